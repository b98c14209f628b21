// Located diagnostics of the FANUC rotation control ROT (SUB 6) and ROTB (SUB 26)
// (frontends/fanuc/DataFunctional.cpp; docs/fanuc-pmc.md "Rules"): one test per rule.
#include "tests/frontend/FanucDiags.h"

#include <gtest/gtest.h>

#include <string>

namespace lj {
namespace {

std::string diags(const std::string &text) { return test::fanucDiags(text); }

constexpr const char *kEnd = "END1\nEND2\nEND\n";
// RN0, BYT, DIR, POS, INC, ACT (ROT: lines 1-6, the instruction on line 7).
constexpr const char *kSix = "RD X0.5\nRD.STK X0.4\nRD.STK X0.3\nRD.STK X0.2\nRD.STK X0.1\n"
                             "RD.STK X0.0\n";
// RN0, DIR, POS, INC, ACT (ROTB: lines 1-5, the instruction on line 6).
constexpr const char *kFive = "RD X0.5\nRD.STK X0.3\nRD.STK X0.2\nRD.STK X0.1\nRD.STK X0.0\n";

TEST(FanucRotDiagnostics, AcceptsEachForm) {
  EXPECT_EQ(diags(std::string(kSix) + "ROT 12 R10 R12 R14\nWRT R0.0\n" + kSix +
                  "SUB 6\n(PRM) 2\n(PRM) D0\n(PRM) X0\n(PRM) D9998\n" + kSix +
                  "ROT 9999 F0 R7998 R9000\n" + kFive + "ROTB 1 X0 F0 R0 R1\nWRT R0.1\n" + kFive +
                  "ROTB 2 D0 D2 D4 D9998\n" + kFive + "SUB 26 4 D0 D4 D8 D9996\n" + kFive +
                  "SUB 26\n(PRM) 4\n(PRM) R0\n(PRM) R0\n(PRM) R0\n(PRM) R0\n" + kEnd),
            "");
}

TEST(FanucRotDiagnostics, ControlInputs) {
  EXPECT_EQ(diags("RD X0.4\nRD.STK X0.3\nRD.STK X0.2\nRD.STK X0.1\nRD.STK X0.0\n"
                  "ROT 12 R10 R12 R14\n" +
                  std::string(kEnd)),
            "t.pmc:6:1: error: ROT needs its inputs RN0, BYT, DIR, POS, INC, ACT in ST5..ST0 (RD, "
            "then RD.STK for each further input), found 5 [LJ4076]\n");
  EXPECT_EQ(diags("RD X0.0\nSUB 6 12 R10 R12 R14\n" + std::string(kEnd)),
            "t.pmc:2:1: error: SUB 6 (ROT) needs its inputs RN0, BYT, DIR, POS, INC, ACT in "
            "ST5..ST0 (RD, then RD.STK for each further input), found 1 [LJ4076]\n");
  EXPECT_EQ(diags("RD X0.3\nRD.STK X0.2\nRD.STK X0.1\nRD.STK X0.0\nROTB 1 R0 R1 R2 R3\n" +
                  std::string(kEnd)),
            "t.pmc:5:1: error: ROTB needs its inputs RN0, DIR, POS, INC, ACT in ST4..ST0 (RD, "
            "then RD.STK for each further input), found 4 [LJ4076]\n");
}

TEST(FanucRotDiagnostics, ParameterCounts) {
  EXPECT_EQ(diags(std::string(kSix) + "ROT 12 R10 R12\n" + kEnd),
            "t.pmc:7:1: error: ROT takes 4 parameters (rotor index count n (constant 2..9999), "
            "current position address, goal position address, result address), got 3 [LJ4068]\n");
  EXPECT_EQ(diags(std::string(kFive) + "SUB 26\n(PRM) 1\n(PRM) R0\n(PRM) R1\n(PRM) R2\n" + kEnd),
            "t.pmc:6:1: error: SUB 26 (ROTB) takes 5 parameters (format 1/2/4, rotor index count "
            "address, current position address, goal position address, result address), got "
            "4 [LJ4068]\n");
  EXPECT_EQ(diags(std::string(kFive) + "ROTB 1 R0 R1 R2 R3 R4\n" + kEnd),
            "t.pmc:6:1: error: ROTB takes 5 parameters (format 1/2/4, rotor index count address, "
            "current position address, goal position address, result address), got 6 [LJ4068]\n");
}

TEST(FanucRotDiagnostics, RotorIndexCountOutOfRange) {
  EXPECT_EQ(diags(std::string(kSix) + "ROT 1 R10 R12 R14\n" + kEnd),
            "t.pmc:7:5: error: rotor index count '1' out of range (2..9999) [LJ4022]\n");
  EXPECT_EQ(diags(std::string(kSix) + "ROT 10000 R10 R12 R14\n" + kEnd),
            "t.pmc:7:5: error: rotor index count '10000' out of range (2..9999) [LJ4022]\n");
  EXPECT_EQ(diags(std::string(kSix) + "ROT R0 R10 R12 R14\n" + kEnd),
            "t.pmc:7:5: error: expected a number as rotor index count, got 'R0' [LJ4021]\n");
}

TEST(FanucRotDiagnostics, BadRotbFormat) {
  EXPECT_EQ(diags(std::string(kFive) + "ROTB 3 R0 R1 R2 R3\n" + kEnd),
            "t.pmc:6:6: error: format '3': expected 1, 2 or 4 [LJ4067]\n");
  EXPECT_EQ(diags(std::string(kFive) + "ROTB 0 R0 R1 R2 R3\n" + kEnd),
            "t.pmc:6:6: error: format '0' out of range (1..4) [LJ4022]\n");
  EXPECT_EQ(diags(std::string(kFive) + "ROTB 1002 R0 R1 R2 R3\n" + kEnd),
            "t.pmc:6:6: error: format '1002' out of range (1..4) [LJ4022]\n");
}

TEST(FanucRotDiagnostics, ConstantWhereAnAddressIsNeeded) {
  EXPECT_EQ(diags(std::string(kSix) + "ROT 12 5 R12 R14\n" + kEnd),
            "t.pmc:7:8: error: expected an address, got constant '5' [LJ4023]\n");
  EXPECT_EQ(diags(std::string(kSix) + "ROT 12 R10 R12 0\n" + kEnd),
            "t.pmc:7:16: error: expected an address, got constant '0' [LJ4023]\n");
  EXPECT_EQ(diags(std::string(kFive) + "ROTB 2 12 D2 D4 D6\n" + kEnd),
            "t.pmc:6:8: error: expected an address, got constant '12' [LJ4023]\n");
  EXPECT_EQ(diags(std::string(kFive) + "ROTB 2 D0 D2 7 D6\n" + kEnd),
            "t.pmc:6:14: error: expected an address, got constant '7' [LJ4023]\n");
}

TEST(FanucRotDiagnostics, AddressOutOfItsArea) {
  EXPECT_EQ(diags(std::string(kSix) + "ROT 12 R8000 R12 R14\n" + kEnd),
            "t.pmc:7:8: error: address 'R8000' out of range (R0..R7999, R9000..R9499) [LJ4017]\n");
  EXPECT_EQ(diags(std::string(kFive) + "ROTB 1 R0 R1 R2 D10000\n" + kEnd),
            "t.pmc:6:17: error: address 'D10000' out of range (D0..D9999) [LJ4017]\n");
}

TEST(FanucRotDiagnostics, ReadOnlyResult) {
  EXPECT_EQ(
      diags(std::string(kSix) + "ROT 12 R10 R12 X0\n" + kEnd),
      "t.pmc:7:16: error: 'X0' is read-only (X is written by the machine or the CNC) [LJ4001]\n");
  EXPECT_EQ(
      diags(std::string(kFive) + "ROTB 4 D0 D4 D8 F0\n" + kEnd),
      "t.pmc:6:17: error: 'F0' is read-only (F is written by the machine or the CNC) [LJ4001]\n");
}

// ROT's addresses are checked as 2 bytes whatever BYT will be at run time (as XMOV's); ROTB's as
// the format's bytes.
TEST(FanucRotDiagnostics, SpanPastItsRange) {
  EXPECT_EQ(diags(std::string(kSix) + "ROT 12 R10 D9999 R14\n" + kEnd),
            "t.pmc:7:12: error: 'D9999' as 2 bytes runs past the end of D0..D9999 [LJ4025]\n");
  EXPECT_EQ(diags(std::string(kSix) + "ROT 12 R10 R12 R7999\n" + kEnd),
            "t.pmc:7:16: error: 'R7999' as 2 bytes runs past the end of R0..R7999, "
            "R9000..R9499 [LJ4025]\n");
  EXPECT_EQ(diags(std::string(kFive) + "ROTB 4 D9997 D0 D4 D8\n" + kEnd),
            "t.pmc:6:8: error: 'D9997' as 4 bytes runs past the end of D0..D9999 [LJ4025]\n");
}

} // namespace
} // namespace lj

// Located diagnostics of the FANUC arithmetic and constant instructions (frontends/fanuc/
// ArithFunctional.cpp; docs/fanuc-pmc.md "Rules"): one test per rule.
#include "tests/frontend/FanucDiags.h"

#include <gtest/gtest.h>

#include <string>

namespace lj {
namespace {

std::string diags(const std::string &text) { return test::fanucDiags(text); }

constexpr const char *kEnd = "END1\nEND2\nEND\n";
constexpr const char *kTwo = "RD X0.0\nRD.STK X0.1\n";                // RST, ACT
constexpr const char *kThree = "RD X0.0\nRD.STK X0.1\nRD.STK X0.2\n"; // BYT, RST, ACT

TEST(FanucArithDiagnostics, AcceptsEachInstruction) {
  EXPECT_EQ(diags(std::string(kTwo) + "ADDB 1002 D0 D2 D4\nWRT R0.0\n" + kTwo +
                  "SUBB 0001 R0 -128 R1\n" + kTwo + "MULB 0004 D0 2147483647 D4\n" + kTwo +
                  "SUB 39\n(PRM) 1004\n(PRM) D0\n(PRM) D4\n(PRM) D8\n" + kThree +
                  "ADD 0 D0 9999 D2\n" + kThree + "SUB 20 1 D0 D2 D4\n" + kThree +
                  "MUL 1 X0 D2 R9000\n" + kThree + "DIV 0 D0 0 D2\n" +
                  "RD X0.0\nNUMEB 1 -128 R0\nNUMEB 2 32767 R0\nNUMEB 4 -2147483648 D9996\n" + kTwo +
                  "NUME 9999 D0\n" + kTwo + "SUB 23\n(PRM) 0\n(PRM) D2\n" + kEnd),
            "");
}

TEST(FanucArithDiagnostics, ParameterCounts) {
  EXPECT_EQ(diags(std::string(kTwo) + "DIVB 0002 R0 R2\n" + kEnd),
            "t.pmc:3:1: error: DIVB takes 4 parameters (format, operand 1 address, operand 2 "
            "(constant or address), result address), got 3 [LJ4063]\n");
  EXPECT_EQ(diags(std::string(kThree) + "SUB 21\n(PRM) 0\n(PRM) D0\n(PRM) 1\n" + kEnd),
            "t.pmc:4:1: error: SUB 21 (MUL) takes 4 parameters (operand 2 format (0 constant, 1 "
            "address), operand 1 address, operand 2, result address), got 3 [LJ4063]\n");
  EXPECT_EQ(diags(std::string("RD X0.0\nNUMEB 2 5\n") + kEnd),
            "t.pmc:2:1: error: NUMEB takes 3 parameters (format 1/2/4, constant, output "
            "address), got 2 [LJ4063]\n");
  EXPECT_EQ(diags(std::string(kTwo) + "NUME 12 R0 R1\n" + kEnd),
            "t.pmc:3:1: error: NUME takes 2 parameters (BCD constant 0..9999, output address), "
            "got 3 [LJ4063]\n");
}

TEST(FanucArithDiagnostics, ControlInputs) {
  EXPECT_EQ(diags(std::string("RD X0.0\nADDB 0002 R0 1 R2\n") + kEnd),
            "t.pmc:2:1: error: ADDB needs its inputs RST, ACT in ST1..ST0 (RD, then RD.STK for "
            "each further input), found 1 [LJ4065]\n");
  EXPECT_EQ(diags(std::string(kTwo) + "ADD 0 D0 1 D2\n" + kEnd),
            "t.pmc:3:1: error: ADD needs its inputs BYT, RST, ACT in ST2..ST0 (RD, then RD.STK "
            "for each further input), found 2 [LJ4065]\n");
  EXPECT_EQ(diags(std::string("NUMEB 4 1 R0\n") + kEnd),
            "t.pmc:1:1: error: NUMEB needs its ACT input in ST0 (an RD before it) [LJ4064]\n");
  EXPECT_EQ(diags(std::string("RD X0.0\nNUME 1 R0\n") + kEnd),
            "t.pmc:2:1: error: NUME needs its inputs BYT, ACT in ST1..ST0 (RD, then RD.STK for "
            "each further input), found 1 [LJ4065]\n");
}

TEST(FanucArithDiagnostics, BadFormat) {
  EXPECT_EQ(diags(std::string(kTwo) + "ADDB 0003 R0 1 R2\n" + kEnd),
            "t.pmc:3:6: error: format '0003': expected 0001/0002/0004 (operand 2 a constant) or "
            "1001/1002/1004 (an address) [LJ4059]\n");
  EXPECT_EQ(diags(std::string(kTwo) + "SUBB 2002 R0 1 R2\n" + kEnd),
            "t.pmc:3:6: error: format '2002': expected 0001/0002/0004 (operand 2 a constant) or "
            "1001/1002/1004 (an address) [LJ4059]\n");
  EXPECT_EQ(diags(std::string(kTwo) + "MULB 0102 R0 1 R2\n" + kEnd),
            "t.pmc:3:6: error: format '0102': expected 0001/0002/0004 (operand 2 a constant) or "
            "1001/1002/1004 (an address) [LJ4059]\n");
  EXPECT_EQ(diags(std::string(kThree) + "ADD 2 D0 1 D2\n" + kEnd),
            "t.pmc:4:5: error: operand 2 format (0 constant, 1 address) '2' out of range "
            "(0..1) [LJ4022]\n");
  EXPECT_EQ(diags(std::string("RD X0.0\nNUMEB 3 1 R0\n") + kEnd),
            "t.pmc:2:7: error: format '3': expected 1, 2 or 4 [LJ4061]\n");
  EXPECT_EQ(diags(std::string("RD X0.0\nNUMEB 8 1 R0\n") + kEnd),
            "t.pmc:2:7: error: format (data length) '8' out of range (1..4) [LJ4022]\n");
}

TEST(FanucArithDiagnostics, ConstantWhereAnAddressIsNeeded) {
  EXPECT_EQ(diags(std::string(kTwo) + "ADDB 1002 R0 5 R2\n" + kEnd),
            "t.pmc:3:14: error: expected an address, got constant '5' [LJ4023]\n");
  EXPECT_EQ(diags(std::string(kTwo) + "ADDB 0002 5 5 R2\n" + kEnd),
            "t.pmc:3:11: error: expected an address, got constant '5' [LJ4023]\n");
  EXPECT_EQ(diags(std::string(kTwo) + "DIVB 0002 R0 5 7\n" + kEnd),
            "t.pmc:3:16: error: expected an address, got constant '7' [LJ4023]\n");
  EXPECT_EQ(diags(std::string(kThree) + "MUL 1 D0 7 D2\n" + kEnd),
            "t.pmc:4:10: error: expected an address, got constant '7' [LJ4023]\n");
  EXPECT_EQ(diags(std::string(kThree) + "DIV 1 5 D4 D2\n" + kEnd),
            "t.pmc:4:7: error: expected an address, got constant '5' [LJ4023]\n");
  EXPECT_EQ(diags(std::string(kTwo) + "NUME 12 34\n" + kEnd),
            "t.pmc:3:9: error: expected an address, got constant '34' [LJ4023]\n");
}

TEST(FanucArithDiagnostics, AddressWhereAConstantIsNeeded) {
  EXPECT_EQ(diags(std::string(kTwo) + "ADDB 0002 R0 R4 R2\n" + kEnd),
            "t.pmc:3:14: error: format 0002 says operand 2 is a constant, got 'R4' [LJ4060]\n");
  EXPECT_EQ(diags(std::string(kThree) + "ADD 0 D0 D4 D2\n" + kEnd),
            "t.pmc:4:10: error: expected a number as operand 2 (decimal constant, format 0), got "
            "'D4' [LJ4021]\n");
  EXPECT_EQ(diags(std::string("RD X0.0\nNUMEB 2 R4 R0\n") + kEnd),
            "t.pmc:2:9: error: NUMEB writes a constant, got 'R4' [LJ4062]\n");
  EXPECT_EQ(diags(std::string(kTwo) + "NUME R1 R0\n" + kEnd),
            "t.pmc:3:6: error: expected a number as BCD constant (at most 4 digits), got 'R1' "
            "[LJ4021]\n");
}

TEST(FanucArithDiagnostics, ConstantsOutOfRange) {
  EXPECT_EQ(diags(std::string(kTwo) + "ADDB 0001 R0 300 R2\n" + kEnd),
            "t.pmc:3:14: error: constant '300' out of range (-128..255) [LJ4022]\n");
  EXPECT_EQ(diags(std::string(kThree) + "ADD 0 D0 10000 D2\n" + kEnd),
            "t.pmc:4:10: error: operand 2 (decimal constant, format 0) '10000' out of range "
            "(0..9999) [LJ4022]\n");
  EXPECT_EQ(diags(std::string("RD X0.0\nNUMEB 1 128 R0\n") + kEnd),
            "t.pmc:2:9: error: constant for 1 byte '128' out of range (-128..127) [LJ4022]\n");
  EXPECT_EQ(
      diags(std::string("RD X0.0\nNUMEB 2 -32769 R0\n") + kEnd),
      "t.pmc:2:9: error: constant for 2 bytes '-32769' out of range (-32768..32767) [LJ4022]\n");
  EXPECT_EQ(diags(std::string(kTwo) + "NUME 10000 R0\n" + kEnd),
            "t.pmc:3:6: error: BCD constant (at most 4 digits) '10000' out of range (0..9999) "
            "[LJ4022]\n");
}

TEST(FanucArithDiagnostics, WritesAndSpans) {
  EXPECT_EQ(
      diags(std::string(kTwo) + "SUBB 0004 R0 1 X0\n" + kEnd),
      "t.pmc:3:16: error: 'X0' is read-only (X is written by the machine or the CNC) [LJ4001]\n");
  EXPECT_EQ(diags(std::string(kTwo) + "MULB 1004 R0 D9998 R4\n" + kEnd),
            "t.pmc:3:14: error: 'D9998' as 4 bytes runs past the end of D0..D9999 [LJ4025]\n");
  EXPECT_EQ(diags(std::string(kThree) + "ADD 1 D0 D2 D9999\n" + kEnd),
            "t.pmc:4:13: error: 'D9999' as 2 bytes runs past the end of D0..D9999 [LJ4025]\n");
  EXPECT_EQ(
      diags(std::string(kTwo) + "NUME 12 X0\n" + kEnd),
      "t.pmc:3:9: error: 'X0' is read-only (X is written by the machine or the CNC) [LJ4001]\n");
}

// `SUB` followed by a number is always the functional-instruction syntax, so the BCD subtract is
// written `SUB 20` and the name SUB cannot start it (docs/fanuc-pmc.md "Program text").
TEST(FanucArithDiagnostics, TheBcdSubtractIsSub20) {
  EXPECT_EQ(diags(std::string(kThree) + "SUB 20 0 D0 1 D2\nWRT R0.0\n" + kEnd), "");
  EXPECT_EQ(diags(std::string(kTwo) + "SUB 20 0 D0 1 D2\n" + kEnd),
            "t.pmc:3:1: error: SUB 20 (SUB) needs its inputs BYT, RST, ACT in ST2..ST0 (RD, then "
            "RD.STK for each further input), found 2 [LJ4065]\n");
  EXPECT_EQ(diags(std::string(kThree) + "SUB 0 D0 1 D2\n" + kEnd),
            "t.pmc:4:5: error: unknown functional instruction SUB 0 [LJ4051]\n");
  EXPECT_EQ(diags(std::string(kThree) + "SUB D0 0 D0 1 D2\n" + kEnd),
            "t.pmc:4:5: error: expected a number as SUB number, got 'D0' [LJ4021]\n");
}

} // namespace
} // namespace lj

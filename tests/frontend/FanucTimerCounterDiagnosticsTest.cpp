// Located diagnostics of the FANUC timers, counters and compares (frontends/fanuc/
// TimerCounter.cpp; docs/fanuc-pmc.md "Rules").
#include "tests/frontend/FanucDiags.h"

#include <gtest/gtest.h>

#include <string>

namespace lj {
namespace {

std::string diags(const std::string &text) { return test::fanucDiags(text); }

constexpr const char *kEnd = "END1\nEND2\nEND\n";
constexpr const char *kFour = "RD X0.0\nRD.STK X0.1\nRD.STK X0.2\nRD.STK X0.3\n";

TEST(FanucTimerCounterDiagnostics, AcceptsEachInstruction) {
  EXPECT_EQ(diags(std::string("RD X0.0\nTMR 250\nWRT R0.0\nRD X0.0\nTMRC 7 D0 R0\n") + kFour +
                  "CTR 100\n" + kFour + "CTRB 100 32767\n" + kFour + "CTRC D0 R4\n" +
                  "RD X0.0\nCOMPB 1004 D0 R0\nRD X0.0\nRD.STK X0.1\nCOMP 0 9999 D0\n" +
                  "RD X0.0\nNED D0 -1\nRD X0.0\nRNGB 1 2 R0\n" + kEnd),
            "");
}

TEST(FanucTimerCounterDiagnostics, NumbersAndCounts) {
  EXPECT_EQ(diags(std::string("RD X0.0\nTMR 251\n") + kEnd),
            "t.pmc:2:5: error: timer number '251' out of range (1..250) [LJ4022]\n");
  EXPECT_EQ(diags(std::string(kFour) + "CTR 101\n" + kEnd),
            "t.pmc:5:5: error: counter number '101' out of range (1..100) [LJ4022]\n");
  EXPECT_EQ(diags(std::string(kFour) + "CTR 1\n" + kFour + "SUB 5\n(PRM) 1\n" + kEnd),
            "t.pmc:11:7: error: counter number 1 is already used on line 5 [LJ4029]\n");
  EXPECT_EQ(diags(std::string("RD X0.0\nTMR 3\nRD X0.0\nTMR 3\n") + kEnd),
            "t.pmc:4:5: error: timer number 3 is already used on line 2 [LJ4029]\n");
  // TMR and TMRB number their timers separately (reference 6.2).
  EXPECT_EQ(diags(std::string("RD X0.0\nTMR 3\nRD X0.0\nTMRB 3 100\n") + kEnd), "");
  EXPECT_EQ(diags(std::string(kFour) + "CTRB 1 32768\n" + kEnd),
            "t.pmc:5:8: error: preset '32768' out of range (0..32767) [LJ4022]\n");
}

TEST(FanucTimerCounterDiagnostics, InputsAndParameters) {
  EXPECT_EQ(diags(std::string("RD X0.0\nRD.STK X0.1\nCTR 1\n") + kEnd),
            "t.pmc:3:1: error: CTR needs CN0, UPDOWN, RST and ACT in ST3..ST0, found 2 ST "
            "entries [LJ4058]\n");
  EXPECT_EQ(diags(std::string("RD X0.0\nCOIN 0 1 D0\n") + kEnd),
            "t.pmc:2:1: error: COIN needs BYT and ACT in ST1, ST0, found 1 ST entries [LJ4058]\n");
  EXPECT_EQ(diags(std::string("TMR 1\n") + kEnd),
            "t.pmc:1:1: error: TMR needs its ACT input in ST0 (an RD before it), found 0 ST "
            "entries [LJ4058]\n");
  EXPECT_EQ(diags(std::string("RD X0.0\nSUB 54\n(PRM) 0\n(PRM) D0\n") + kEnd),
            "t.pmc:2:1: error: SUB 54 (TMRC) takes 3 parameters (precision, set-time address, "
            "timer register address), got 2 [LJ4057]\n");
  EXPECT_EQ(diags(std::string("RD X0.0\nTMRC 8 D0 R0\n") + kEnd),
            "t.pmc:2:6: error: precision '8' out of range (0..7) [LJ4022]\n");
  EXPECT_EQ(diags(std::string("RD X0.0\nTMRC 0 D0 R7997\n") + kEnd),
            "t.pmc:2:11: error: 'R7997' as 4 bytes runs past the end of R0..R7999, "
            "R9000..R9499 [LJ4025]\n");
  EXPECT_EQ(
      diags(std::string(kFour) + "CTRC D0 X0\n" + kEnd),
      "t.pmc:5:9: error: 'X0' is read-only (X is written by the machine or the CNC) [LJ4001]\n");
  EXPECT_EQ(diags(std::string("RD X0.0\nCOMPB 0003 1 D0\n") + kEnd),
            "t.pmc:2:7: error: format '0003': expected 0001/0002/0004 (constant) or "
            "1001/1002/1004 (address) [LJ4056]\n");
  EXPECT_EQ(diags(std::string("RD X0.0\nCOMPB 1001 5 D0\n") + kEnd),
            "t.pmc:2:12: error: expected an address, got constant '5' [LJ4023]\n");
  EXPECT_EQ(
      diags(std::string("RD X0.0\nRD.STK X0.1\nCOMP 0 10000 D0\n") + kEnd),
      "t.pmc:3:8: error: input data (decimal constant) '10000' out of range (0..9999) [LJ4022]\n");
  EXPECT_EQ(diags(std::string("RD X0.0\nNEB 300 R0\n") + kEnd),
            "t.pmc:2:5: error: constant '300' out of range (-128..255) [LJ4022]\n");
}

} // namespace
} // namespace lj

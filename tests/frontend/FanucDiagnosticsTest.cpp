// The FANUC front end's located diagnostics: one test per rule (docs/fanuc-pmc.md "Rules").
#include "tests/frontend/FanucDiags.h"

#include <gtest/gtest.h>

#include <string>

namespace lj {
namespace {

std::string diags(const std::string &text) { return test::fanucDiags(text); }

constexpr const char *kEnd = "END1\nEND2\nEND\n";

TEST(FanucDiagnostics, AcceptsAMinimalProgram) { EXPECT_EQ(diags(kEnd), ""); }

TEST(FanucDiagnostics, StackRulesOfSt0ToSt7) {
  EXPECT_EQ(diags(std::string("RD X0.0\nAND.STK\n") + kEnd),
            "t.pmc:2:1: error: AND.STK needs two logic lines (ST1 and ST0), found 1 [LJ4034]\n");
  EXPECT_EQ(diags(std::string("AND X0.0\n") + kEnd),
            "t.pmc:1:1: error: AND without a logic line (start it with RD) [LJ4031]\n");
  EXPECT_EQ(diags(std::string("WRT Y0.0\n") + kEnd),
            "t.pmc:1:1: error: WRT without a logic line (start it with RD) [LJ4031]\n");
  std::string nine = "RD X0.0\n";
  for (int i = 1; i <= 8; ++i) nine += "RD.STK X0." + std::to_string(i % 8) + "\n";
  EXPECT_EQ(diags(nine + kEnd), "t.pmc:9:1: error: RD.STK pushes a ninth operation result: the PMC "
                                "has only ST0..ST7 [LJ4033]\n");
}

TEST(FanucDiagnostics, Addresses) {
  EXPECT_EQ(
      diags(std::string("RD X0.0\nWRT X0.1\n") + kEnd),
      "t.pmc:2:5: error: 'X0.1' is read-only (X is written by the machine or the CNC) [LJ4001]\n");
  EXPECT_EQ(
      diags(std::string("RD R8000.0\n") + kEnd),
      "t.pmc:1:4: error: address 'R8000.0' out of range (R0..R7999, R9000..R9499) [LJ4017]\n");
  EXPECT_EQ(diags(std::string("RD X0.8\n") + kEnd),
            "t.pmc:1:4: error: bit number 8 out of range in 'X0.8' (bits 0..7) [LJ4020]\n");
  EXPECT_EQ(diags(std::string("RD Q0.0\n") + kEnd),
            "t.pmc:1:4: error: unknown address 'Q0.0' (areas: X Y F G R E A T C K D; labels L, "
            "subroutines P) [LJ4017]\n");
  EXPECT_EQ(diags(std::string("RD X0.0\nMOVW R0 D9999\n") + kEnd),
            "t.pmc:2:9: error: 'D9999' as 2 bytes runs past the end of D0..D9999 [LJ4025]\n");
  EXPECT_EQ(diags(std::string("RD X0.0\nMOVD R7998 R0\n") + kEnd),
            "t.pmc:2:6: error: 'R7998' as 4 bytes runs past the end of R0..R7999, R9000..R9499 "
            "[LJ4025]\n");
}

TEST(FanucDiagnostics, LevelsAndEnds) {
  EXPECT_EQ(diags("RD X0.0\nWRT Y0.0\n"),
            "t.pmc:2:1: error: program has no END1 (END1 is required, reference 4.1) [LJ4013]\n");
  EXPECT_EQ(diags("END1\nEND2\n"),
            "t.pmc:2:1: error: program has no END (the last instruction) [LJ4015]\n");
  EXPECT_EQ(diags("END1\nEND2\nEND\nRD X0.0\n"),
            "t.pmc:4:1: error: statement after END (END ends the program) [LJ4010]\n");
  EXPECT_EQ(diags("END1\nEND2\nRD X0.0\nWRT Y0.0\nEND3\nEND\n"),
            "t.pmc:5:1: error: level 3 (END2..END3) is not supported: it must be empty "
            "(docs/fanuc-pmc.md, [EXT] levels) [LJ4040]\n");
  EXPECT_EQ(diags("END1\nEND2\nEND3\nEND\n"), "");
  EXPECT_EQ(
      diags("RD X0.0\nCALL P1\nEND1\nEND2\nSP P1\nSPE\nEND\n"),
      "t.pmc:2:1: error: CALL: level 1 cannot call subroutines (reference 4.2, L877) [LJ4054]\n");
  EXPECT_EQ(diags("SP P1\nSPE\nEND1\nEND2\nEND\n"),
            "t.pmc:1:1: error: SP before END2: subroutines follow END2 (or END3) [LJ4043]\n");
}

TEST(FanucDiagnostics, FunctionalInstructions) {
  EXPECT_EQ(
      diags(std::string("SUB 24\n(PRM) 1\n(PRM) 100\n") + kEnd),
      "t.pmc:1:1: error: SUB 24 (TMRB) needs its ACT input in ST0 (an RD before it) [LJ4053]\n");
  EXPECT_EQ(diags(std::string("RD X0.0\nSUB 24\n(PRM) 1\n") + kEnd),
            "t.pmc:2:1: error: SUB 24 (TMRB) takes 2 parameters (timer number, set time (ms)), "
            "got 1 [LJ4052]\n");
  EXPECT_EQ(diags(std::string("RD X0.0\nSUB 999\n") + kEnd),
            "t.pmc:2:5: error: unknown functional instruction SUB 999 [LJ4051]\n");
  EXPECT_EQ(diags(std::string("RD X0.0\nSUB 26\n(PRM) 1\n") + kEnd),
            "t.pmc:2:1: error: SUB 26 (ROTB) needs its inputs RN0, DIR, POS, INC, ACT in ST4..ST0 "
            "(RD, then RD.STK for each further input), found 1 [LJ4076]\n");
  EXPECT_EQ(
      diags(std::string("(PRM) 1\n") + kEnd),
      "t.pmc:1:1: error: parameter line without a functional instruction before it [LJ4008]\n");
  EXPECT_EQ(diags(std::string("RD X0.0\nDIFU 3\nRD X0.0\nDIFD 3\n") + kEnd),
            "t.pmc:4:6: error: edge number 3 is already used on line 2 [LJ4029]\n");
  EXPECT_EQ(diags(std::string("RD X0.0\nTMRB 501 100\n") + kEnd),
            "t.pmc:2:6: error: timer number '501' out of range (1..500) [LJ4022]\n");
  EXPECT_EQ(diags(std::string("RD X0.0\nAND 1 2\n") + kEnd),
            "t.pmc:2:1: error: AND takes one bit address, got 2 [LJ4030]\n");
  EXPECT_EQ(diags(std::string("RD X0.0\nSUB 60\n(PRM) 0003\n(PRM) R0\n(PRM) 1\n(PRM) R1\n") + kEnd),
            "t.pmc:3:7: error: format '0003': expected 0001/0002/0004 (constant) or "
            "1001/1002/1004 (address) [LJ4046]\n");
  EXPECT_EQ(
      diags(std::string("RD X0.0\nMOVE 0001 2111 X10 R100\n") + kEnd),
      "t.pmc:2:11: error: a MOVE mask half is 4 binary digits (like 0001), got '2111' [LJ4002]\n");
}

// The 0i-D resource counts (reference 1, 4.2 [L869], 6.3 [L1715], 6.8 [L3149-L3159]): TMRB /
// TMRBF 1..500, DIFU / DIFD 1..1000, subroutines P1..P5000; one past each is a located error.
TEST(FanucDiagnostics, ResourceLimits) {
  EXPECT_EQ(diags(std::string("RD X0.0\nTMRB 500 100\nRD X0.0\nTMRBF 499 100\n") + kEnd), "");
  EXPECT_EQ(diags(std::string("RD X0.0\nTMRBF 501 100\n") + kEnd),
            "t.pmc:2:7: error: timer number '501' out of range (1..500) [LJ4022]\n");
  EXPECT_EQ(diags(std::string("RD X0.0\nDIFU 1000\nRD X0.0\nDIFD 999\n") + kEnd), "");
  EXPECT_EQ(diags(std::string("RD X0.0\nDIFU 1001\n") + kEnd),
            "t.pmc:2:6: error: edge number '1001' out of range (1..1000) [LJ4022]\n");
  EXPECT_EQ(diags(std::string("RD X0.0\nSUB 58\n(PRM) 1001\n") + kEnd),
            "t.pmc:3:7: error: edge number '1001' out of range (1..1000) [LJ4022]\n");
  EXPECT_EQ(diags("END1\nRD X0.0\nCALL P5000\nEND2\nSP P5000\nSPE\nEND\n"), "");
  EXPECT_EQ(diags("END1\nRD X0.0\nCALL P5001\nEND2\nEND\n"),
            "t.pmc:3:6: error: address 'P5001' out of range (P0..P5000) [LJ4017]\n");
  EXPECT_EQ(diags("END1\nEND2\nSP P5001\nSPE\nEND\n"),
            "t.pmc:3:4: error: address 'P5001' out of range (P0..P5000) [LJ4017]\n");
}

TEST(FanucDiagnostics, UnknownInstruction) {
  EXPECT_EQ(diags(std::string("LD X0.0\n") + kEnd),
            "t.pmc:1:1: error: unknown instruction 'LD' [LJ4012]\n");
}

// JMPC (SUB 73): from a subroutine to a label of level 2 (docs/fanuc-pmc.md "JMPC").
TEST(FanucDiagnostics, JmpcRules) {
  const std::string call = "END1\nRD X0.0\nCALL P1\n";
  EXPECT_EQ(diags(call + "LBL L1\nEND2\nSP P1\nRD X0.1\nJMPC L1\nSPE\nEND\n"), "");
  EXPECT_EQ(diags(call + "LBL L1\nEND2\nSP P1\nRD X0.1\nSUB 73\n(PRM) L1\nSPE\nEND\n"), "");
  EXPECT_EQ(diags("END1\nRD X0.0\nJMPC L1\nLBL L1\nEND2\nEND\n"),
            "t.pmc:3:1: error: JMPC L1 outside a subroutine: it leaves a subroutine for a label "
            "before END2 [LJ1004]\n");
  EXPECT_EQ(diags("RD X0.0\nJMPC L1\nLBL L1\nEND1\nEND2\nEND\n"),
            "t.pmc:2:1: error: JMPC L1 outside a subroutine: it leaves a subroutine for a label "
            "before END2 [LJ1004]\n");
  // The label must be level 2's: not missing, not level 1's, not the subroutine's own.
  const char *missing = "error: missing label L5 before END2: JMPC L5 goes on at a label of the "
                        "part that ends with END2 [LJ1005]\n";
  EXPECT_EQ(diags(call + "END2\nSP P1\nRD X0.1\nJMPC L5\nSPE\nEND\n"),
            std::string("t.pmc:7:6: ") + missing);
  EXPECT_EQ(diags("LBL L5\nEND1\nRD X0.0\nCALL P1\nEND2\nSP P1\nRD X0.1\nJMPC L5\nSPE\nEND\n"),
            std::string("t.pmc:8:6: ") + missing);
  EXPECT_EQ(diags(call + "END2\nSP P1\nRD X0.1\nJMPC L5\nLBL L5\nSPE\nEND\n"),
            std::string("t.pmc:7:6: ") + missing);
  EXPECT_EQ(diags(call + "LBL L1\nEND2\nSP P1\nJMPC L1\nSPE\nEND\n"),
            "t.pmc:7:1: error: JMPC needs its ACT input in ST0 (an RD before it) [LJ4053]\n");
  EXPECT_EQ(diags(call + "LBL L1\nEND2\nSP P1\nRD X0.1\nJMPC L1 L2\nSPE\nEND\n"),
            "t.pmc:8:1: error: JMPC takes 1 parameters (label), got 2 [LJ4052]\n");
  EXPECT_EQ(diags(call + "LBL L1\nEND2\nSP P1\nRD X0.1\nJMPC P1\nSPE\nEND\n"),
            "t.pmc:8:6: error: expected a label (L1), got 'P1' [LJ4027]\n");
}

} // namespace
} // namespace lj

namespace lj {
namespace {

// fanuc-e: the CS / CM / CE select-call rules (docs/fanuc-pmc.md [EXT] select-call).
TEST(FanucDiagnostics, SelectCallRules) {
  const std::string subs = "SP P1\nSPE\nEND\n";
  EXPECT_EQ(
      diags("RD X0.0\nCS R100\nCM P1\nCE\nEND1\nEND2\n" + subs),
      "t.pmc:2:1: error: CS: level 1 cannot call subroutines (reference 4.2, L877) [LJ4054]\n");
  EXPECT_EQ(diags("END1\nRD X0.0\nCS R100\nCM P1\nEND2\n" + subs),
            "t.pmc:5:1: error: CS on line 3 has no CE before END2 [LJ4049]\n");
  EXPECT_EQ(
      diags("END1\nRD X0.0\nCS R100\nCM P1\nRD X0.1\nCE\nEND2\n" + subs),
      "t.pmc:5:1: error: only CM lines may stand between CS (line 3) and CE, got RD [LJ4050]\n");
  EXPECT_EQ(diags("END1\nRD X0.0\nCS R100\nCS R102\nCE\nEND2\n" + subs),
            "t.pmc:4:1: error: CS inside the CS list opened on line 3 (CS..CE lists do not "
            "nest; close it with CE first) [LJ4047]\n");
  EXPECT_EQ(diags("END1\nCM P1\nEND2\n" + subs),
            "t.pmc:2:1: error: CM outside a CS..CE list (it must follow a CS) [LJ4048]\n");
  EXPECT_EQ(diags("END1\nSUB 76\nEND2\n" + subs),
            "t.pmc:2:1: error: SUB 76 (CE) outside a CS..CE list (it must follow a CS) [LJ4048]\n");
  EXPECT_EQ(diags("END1\nCS R100\nCE\nEND2\n" + subs),
            "t.pmc:2:1: error: CS needs its ACT input in ST0 (an RD before it) [LJ4053]\n");
  EXPECT_EQ(diags("END1\nRD X0.0\nCS\nCE\nEND2\n" + subs),
            "t.pmc:3:1: error: CS takes 1 parameters (index address), got 0 [LJ4052]\n");
  EXPECT_EQ(diags("END1\nRD X0.0\nCS R100\nCM P2\nCE\nEND2\n" + subs),
            // the verifier's rule for CALL, in the dialect's spelling
            "t.pmc:4:4: error: undefined subroutine P2 [LJ1012]\n"
            "t.pmc:7:1: warning: subroutine P1 is never called [LJ1003]\n");
}

} // namespace
} // namespace lj

namespace lj {
namespace {

// DIALECT.md 6: a double coil is the same bit written by two output instructions. E4096.0 and
// A0.0 are different bits (reference 2: E0..E9999, A0..A249); the verifier's key once folded an
// element number of 4096 into the next area's element 0 and warned about A0.0.
TEST(FanucDiagnostics, DoubleCoilOnlyForTheSameBit) {
  EXPECT_EQ(test::fanucDiags("RD X0.0\nWRT E4096.0\nRD X0.1\nWRT A0.0\nEND1\nEND2\nEND\n"), "");
  EXPECT_EQ(test::fanucDiags("RD X0.0\nWRT E9999.7\nRD X0.1\nWRT E9999.7\nEND1\nEND2\nEND\n"),
            "t.pmc:4:5: warning: double coil: E9999.7 is also written on line 2 [LJ1015]\n"
            "t.pmc:2:5: note: first write of E9999.7 is here\n");
}

} // namespace
} // namespace lj

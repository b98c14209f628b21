// Golden diagnostics: one test per error class of DIALECT.md 6 (exact `file:line:col: error:`
// line), the warnings of DIALECT.md 6 / dialect-notes, rendering order, and the ten-mistakes file.
#include "FrontEndTestUtil.h"
#include "pipeline/Compile.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

namespace lj {
namespace {

using test::compile;

std::string diags(std::string_view text, VerifyOptions o = {}) { return compile(text, o).diags; }

// --- errors, DIALECT.md 6, in the order listed there ---

TEST(GoldenErrors, UnknownMnemonic) {
  EXPECT_EQ(diags("LDX X1.0\n"), "t.stl:1:1: error: unknown mnemonic 'LDX' [LJ3001]\n");
}

TEST(GoldenErrors, WrongOperandCount) {
  EXPECT_EQ(diags("LD X1.0\nOUT\n"),
            "t.stl:2:1: error: OUT takes 1 operand (coil), got 0 [LJ3003]\n");
}

TEST(GoldenErrors, WrongOperandKind) {
  EXPECT_EQ(diags("LD X1.0\nOUT 5\n"),
            "t.stl:2:5: error: OUT expects a bit address (like X1.0) as coil, got constant "
            "'5' [LJ3013]\n");
}

TEST(GoldenErrors, BadAddress) {
  EXPECT_EQ(diags("LD X513.0\nOUT Y0.0\n"),
            "t.stl:1:4: error: address 'X513.0' out of range (X0..X512) [LJ3012]\n");
}

TEST(GoldenErrors, BadBit) {
  EXPECT_EQ(diags("LD X2.8\nOUT Y0.0\n"),
            "t.stl:1:4: error: bit number 8 out of range in 'X2.8' (X has bits 0..7) [LJ3014]\n");
}

TEST(GoldenErrors, ConstantRange) {
  EXPECT_EQ(diags("LD X0.0\nTMRB 1 4 100\n"),
            "t.stl:2:8: error: constant '4' out of range for time unit of TMRB (0..3) [LJ3016]\n");
}

TEST(GoldenErrors, AreaNotAllowed) {
  EXPECT_EQ(diags("LDT\nMOV T3 D0\n"),
            "t.stl:2:5: error: area T is not allowed as source of MOV (allowed: X, Y, F, G, R, "
            "W, D, B or P) [LJ3011]\n");
}

TEST(GoldenErrors, ReadOnlyArea) {
  EXPECT_EQ(diags("LD X1.0\nOUT F3.0\n"),
            "t.stl:2:5: error: F3.0 is read-only; OUT cannot write its coil (writable: Y, G, R, "
            "W, D or B) [LJ3010]\n");
}

TEST(GoldenErrors, StackUnderflowBlockPop) {
  EXPECT_EQ(diags("LD X1.0\nORB\nOUT Y0.0\n"),
            "t.stl:2:1: error: stack underflow: ORB needs 2 entries on ST, found 1 [LJ1013]\n");
}

TEST(GoldenErrors, StackUnderflowCoil) {
  EXPECT_EQ(diags("OUT Y0.0\n"),
            "t.stl:1:1: error: stack underflow: OUT with an empty ST [LJ1013]\n");
}

TEST(GoldenErrors, StackUnderflowCombine) {
  EXPECT_EQ(diags("AND X1.0\nOUT Y0.0\n"),
            "t.stl:1:1: error: stack underflow: AND with an empty ST [LJ1013]\n");
}

TEST(GoldenErrors, StackUnderflowMultiInputBlock) {
  EXPECT_EQ(diags("LD X1.0\nLD X1.1\nCTUD 0 5\nOUT Y0.0\n"),
            "t.stl:3:1: error: stack underflow: CTUD needs 4 inputs on ST, found 2 [LJ1013]\n");
}

TEST(GoldenErrors, StackUnderflowMs) {
  EXPECT_EQ(diags("LD X1.0\nMPP\nOUT Y0.0\n"),
            "t.stl:2:1: error: stack underflow: MPP with an empty MS [LJ1013]\n");
}

TEST(GoldenErrors, UnclosedMpsAtLabel) {
  EXPECT_EQ(diags("LD X1.0\nMPS\nOUT Y0.0\nLBL L1\n"),
            "t.stl:2:1: error: unclosed MPS: MS is not empty at LBL (line 4) [LJ1014]\n");
}

TEST(GoldenErrors, UnclosedMpsAtEndOfPart) {
  EXPECT_EQ(diags("LD X1.0\nMPS\nOUT Y0.0\n1END\n"),
            "t.stl:2:1: error: unclosed MPS: MS is not empty at the end of PLC1 [LJ1014]\n");
}

TEST(GoldenErrors, MissingLabel) {
  EXPECT_EQ(diags("LD X1.0\nJMP L5\n"), "t.stl:2:5: error: missing label L5 [LJ1010]\n");
}

TEST(GoldenErrors, DuplicateLabel) {
  EXPECT_EQ(diags("LBL L5\nLBL L5\n"),
            "t.stl:2:5: error: duplicate label L5 (first on line 1) [LJ1008]\n");
}

TEST(GoldenErrors, MissingSubroutine) {
  EXPECT_EQ(diags("LDT\nCALL S9\n"), "t.stl:2:6: error: undefined subroutine S9 [LJ1012]\n");
}

TEST(GoldenErrors, DuplicateSubroutine) {
  EXPECT_EQ(diags("CALL S1\n2END\nSP S1\nSPE\nSP S1\nSPE\n"),
            "t.stl:5:4: error: duplicate subroutine S1 (first on line 3) [LJ1030]\n");
}

// DIALECT.md 2: each loop body is a scope; JMP/LBL never cross scopes.
TEST(GoldenErrors, JmpAcrossScopes) {
  EXPECT_EQ(diags("LD X1.0\nJMP L1\nLOOP 2\nLBL L1\nNEXT\n"),
            "t.stl:2:5: error: JMP L1 crosses a scope boundary (LBL L1 on line 4 is not in the "
            "same loop body) [LJ1011]\n");
  // Out of a loop body into the enclosing part, and between two sibling bodies.
  EXPECT_EQ(diags("LOOP 2\nLD X1.0\nJMP L1\nNEXT\nLBL L1\n"),
            "t.stl:3:5: error: JMP L1 crosses a scope boundary (LBL L1 on line 5 is not in the "
            "same loop body) [LJ1011]\n");
  EXPECT_EQ(diags("LOOP 2\nLD X1.0\nJMP L1\nNEXT\nLOOP 2\nLBL L1\nNEXT\n"),
            "t.stl:3:5: error: JMP L1 crosses a scope boundary (LBL L1 on line 6 is not in the "
            "same loop body) [LJ1011]\n");
  // Within one loop body a jump is fine.
  EXPECT_EQ(diags("LOOP 2\nLD X1.0\nJMP L1\nLBL L1\nNEXT\n"), "");
}

TEST(GoldenErrors, RetnOutsideSubroutine) {
  EXPECT_EQ(diags("LD X1.0\nRETN\n"), "t.stl:2:1: error: RETN outside a subroutine [LJ1017]\n");
}

TEST(GoldenErrors, SpBeforeEndOfMainParts) {
  EXPECT_EQ(diags("LDT\nOUT Y0.0\nSP S1\nSPE\n1END\n"),
            "t.stl:3:1: warning: subroutine S1 is never called [LJ1003]\n"
            "t.stl:5:1: error: 1END after a subroutine: SP before the end of the main parts "
            "(first SP on line 3) [LJ1033]\n");
}

// dialect-notes "Program parts": a statement outside a subroutine after them.
TEST(GoldenErrors, StatementAfterSubroutines) {
  EXPECT_EQ(diags("CALL S1\n2END\nSP S1\nSPE\nLDT\nOUT Y0.0\n"),
            "t.stl:5:1: error: statement after the subroutines [LJ1034]\n");
}

TEST(GoldenErrors, NestedSp) {
  EXPECT_EQ(diags("CALL S1\nCALL S2\n2END\nSP S1\nSP S2\nSPE\n"),
            "t.stl:5:1: error: nested SP: S1 (line 4) has no SPE before it [LJ1031]\n");
}

TEST(GoldenErrors, MissingSpe) {
  EXPECT_EQ(diags("CALL S1\n2END\nSP S1\nLDT\nOUT Y0.0\n"),
            "t.stl:3:1: error: SP S1 has no SPE [LJ1035]\n");
}

TEST(GoldenErrors, Recursion) {
  EXPECT_EQ(diags("CALL S1\n2END\nSP S1\nCALL S2\nSPE\nSP S2\nCALL S1\nSPE\n"),
            "t.stl:7:1: error: recursion: S1 -> S2 -> S1 [LJ1001]\n");
}

TEST(GoldenErrors, CallDepth) {
  std::string text = "CALL S1\n2END\n";
  for (int s = 1; s <= 33; ++s) {
    text += "SP S" + std::to_string(s) + "\n";
    if (s < 33) text += "CALL S" + std::to_string(s + 1) + "\n";
    text += "SPE\n";
  }
  EXPECT_EQ(diags(text),
            "t.stl:1:1: error: call nesting depth 33 exceeds the limit of 32 [LJ1002]\n");
  VerifyOptions o;
  o.maxCallDepth = 33;
  EXPECT_EQ(diags(text, o), "");
}

TEST(GoldenErrors, LoopWithoutNext) {
  EXPECT_EQ(diags("LOOP 3\nLDT\nOUT Y0.0\n"), "t.stl:1:1: error: LOOP without NEXT [LJ1009]\n");
}

TEST(GoldenErrors, NextWithoutLoop) {
  EXPECT_EQ(diags("LDT\nOUT Y0.0\nNEXT\n"), "t.stl:3:1: error: NEXT without LOOP [LJ1007]\n");
}

// dialect-notes "Function blocks": one timer number with both TMRB and STMR.
TEST(GoldenErrors, TimerTwoKinds) {
  EXPECT_EQ(diags("LD X0.0\nTMRB 5 0 100\nLD X0.1\nSTMR 5 0 100\n"),
            "t.stl:4:6: error: timer T5 is used by both TMRB (line 2) and STMR [LJ1020]\n"
            "t.stl:2:6: note: T5 is first used here\n");
}

TEST(GoldenErrors, CounterTwoKinds) {
  EXPECT_EQ(diags("LD X0.0\nLD X0.1\nCTRC 300 5\nLD X0.2\nLD X0.3\nLD X0.4\nLD X0.5\n"
                  "CTUD 300 5\n"),
            "t.stl:8:6: error: counter C300 is used by both CTRC (line 3) and CTUD [LJ1020]\n"
            "t.stl:3:6: note: C300 is first used here\n");
}

// DIALECT.md 1: T0..T127 and T300..T427; the gap is an error.
TEST(GoldenErrors, TimerNumberInGap) {
  EXPECT_EQ(diags("LD X0.0\nTMRB 200 0 100\n"),
            "t.stl:2:6: error: timer number 200 is not valid (T0..T127, T300..T427) [LJ1019]\n");
}

TEST(GoldenErrors, ProgramTooLarge) {
  std::string text;
  for (int i = 0; i < 5001; ++i) text += "LDT\nOUT Y0.0\n";
  auto c = compile(text);
  EXPECT_FALSE(c.prog.has_value());
  EXPECT_EQ(c.errors, 1);
  EXPECT_NE(c.diags.find("t.stl:10001:1: error: program has 10002 statements, more than the "
                         "limit of 10000 [LJ3019]\n"),
            std::string::npos)
      << c.diags.substr(0, 300);
  VerifyOptions raised;
  raised.maxStatements = 20000;
  EXPECT_EQ(compile(text, raised).errors, 0);
}

// LJ_EDGE_SLOTS edge bits: one more edge instruction is an error (limit raised so the
// program-size rule does not fire first).
TEST(GoldenErrors, TooManyEdgeSlots) {
  std::string text;
  for (int i = 0; i < 16385; ++i) text += "LDP X0.0\n";
  VerifyOptions o;
  o.maxStatements = 20000;
  EXPECT_EQ(diags(text, o), "t.stl:16385:1: error: too many edge instructions (more than 16384 "
                            "LDP/LDF/ANDP/ANDF/ORP/ORF/CTR) [LJ1022]\n");
  text.resize(text.size() - 9);
  auto c = compile(text, o);
  ASSERT_TRUE(c.prog.has_value()) << c.diags.substr(0, 200);
  EXPECT_EQ(c.prog->edgeSlots, 16384);
}

TEST(GoldenErrors, MarkerOrder) {
  EXPECT_EQ(diags("1END\nIEND\n"), "t.stl:2:1: error: IEND after 1END: markers must come in the "
                                   "order IEND, 1END, 2END [LJ1029]\n");
  EXPECT_EQ(diags("1END\n1END\n"), "t.stl:2:1: error: duplicate 1END (first on line 1) [LJ1028]\n");
}

// --- warnings (DIALECT.md 6, dialect-notes) ---

TEST(GoldenWarnings, DoubleCoilWithNote) {
  EXPECT_EQ(diags("LD X0.0\nOUT Y0.0\nLD X0.1\nOUT Y0.0\n"),
            "t.stl:4:5: warning: double coil: Y0.0 is also written on line 2 [LJ1015]\n"
            "t.stl:2:5: note: first write of Y0.0 is here\n");
  // SET/RST pairs are not double coils.
  EXPECT_EQ(diags("LD X0.0\nSET Y0.0\nLD X0.1\nRST Y0.0\n"), "");
}

TEST(GoldenWarnings, UnreachableAfterLdtJmp) {
  EXPECT_EQ(diags("LDT\nJMP L1\nLD X0.0\nOUT Y0.0\nLBL L1\n"),
            "t.stl:3:1: warning: unreachable code [LJ1018]\n");
}

TEST(GoldenWarnings, UnreachableAfterRetn) {
  EXPECT_EQ(diags("CALL S1\n2END\nSP S1\nRETN\nLDT\nOUT Y0.0\nSPE\n"),
            "t.stl:5:1: warning: unreachable code [LJ1018]\n");
}

TEST(GoldenWarnings, BlockNeedsInput) {
  EXPECT_EQ(diags("ADD D0 1 D0\n"),
            "t.stl:1:1: warning: ADD: block needs an input; ST is empty, input is 1 [LJ1016]\n");
}

TEST(GoldenWarnings, SubroutineNeverCalled) {
  EXPECT_EQ(diags("2END\nSP S4\nSPE\n"),
            "t.stl:2:1: warning: subroutine S4 is never called [LJ1003]\n");
}

TEST(GoldenWarnings, SharedTimer) {
  EXPECT_EQ(diags("LD X0.0\nTMRB 5 0 100\nLD X0.1\nTMRB 5 1 2\n"),
            "t.stl:4:6: warning: timer T5 is also used on line 2; both instructions share its "
            "state [LJ1021]\n");
}

TEST(GoldenWarnings, SharedPlsBlock) {
  EXPECT_EQ(diags("LD X0.0\nPLS 3\nLD X0.1\nPLS 3\n"),
            "t.stl:4:5: warning: PLS block 3 is also used on line 2; both instructions share its "
            "state [LJ1025]\n");
}

// Diagnostics::render: sorted by line and column, notes stay with their diagnostic.
TEST(Render, SortedStable) {
  Diagnostics d("f.stl");
  d.error({3, 1}, "c");
  d.warning({1, 5}, "b");
  d.note({9, 9}, "note of b");
  d.error({1, 5}, "b2");
  d.error({1, 2}, "a");
  EXPECT_EQ(d.render(), "f.stl:1:2: error: a\n"
                        "f.stl:1:5: warning: b\n"
                        "f.stl:9:9: note: note of b\n"
                        "f.stl:1:5: error: b2\n"
                        "f.stl:3:1: error: c\n");
  EXPECT_EQ(d.errorCount(), 3);
}

// The CLI tests use this file: ten different mistakes, ten located errors.
TEST(TenMistakes, TenLocatedErrors) {
  std::ifstream f(LJ_FRONTEND_DATA_DIR "/ten_mistakes.stl", std::ios::binary);
  ASSERT_TRUE(f) << "missing data file";
  std::stringstream ss;
  ss << f.rdbuf();
  Diagnostics d("ten_mistakes.stl");
  auto prog = pipeline::compileStl(ss.str(), "ten_mistakes.stl", {}, d);
  EXPECT_FALSE(prog.has_value());
  EXPECT_EQ(d.errorCount(), 10);
  EXPECT_EQ(
      d.render(),
      "ten_mistakes.stl:3:1: error: unknown mnemonic 'OUTT' [LJ3001]\n"
      "ten_mistakes.stl:4:1: error: stack underflow: ANB needs 2 entries on ST, found 1 [LJ1013]\n"
      "ten_mistakes.stl:5:5: error: X3.0 is read-only; OUT cannot write its coil "
      "(writable: Y, G, R, W, D or B) [LJ3010]\n"
      "ten_mistakes.stl:6:1: error: ADD takes 3 operands (augend, addend, destination), "
      "got 2 [LJ3003]\n"
      "ten_mistakes.stl:7:4: error: bit number 9 out of range in 'X1.9' (X has bits 0..7) "
      "[LJ3014]\n"
      "ten_mistakes.stl:10:5: error: missing label L7 [LJ1010]\n"
      "ten_mistakes.stl:12:1: error: unclosed MPS: MS is not empty at the end of PLC1 [LJ1014]\n"
      "ten_mistakes.stl:19:6: error: timer T5 is used by both TMRB (line 16) and STMR [LJ1020]\n"
      "ten_mistakes.stl:16:6: note: T5 is first used here\n"
      "ten_mistakes.stl:22:1: error: RETN outside a subroutine [LJ1017]\n"
      "ten_mistakes.stl:24:6: error: undefined subroutine S9 [LJ1012]\n");
}

} // namespace
} // namespace lj

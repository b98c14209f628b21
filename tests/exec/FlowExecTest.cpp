// Flow control: IEND, JMP/LBL, CALL/SP/SPE/RETN, LOOP/NEXT (hnc8-functions-1.md 3.5 test values)
// and the stack and edge rules of DIALECT.md 3 / docs/dialect-notes.md "Flow".
#include "tests/exec/ExecTest.h"

namespace lj::test {
namespace {

class FlowExec : public ExecTest {};
LJ_EXEC_SUITE(FlowExec);

// 3.5 IEND: `LDT / INC D0 / IEND / ...` -> D0 = 1 after any number of scans.
TEST_P(FlowExec, IendRunsInitOnce) {
  auto m = load("LDT\nINC D0\nIEND\nLDT\nINC D1\n");
  ASSERT_TRUE(m);
  EXPECT_EQ(m->get("D0"), 1); // after init
  m->ticks(7);
  EXPECT_EQ(m->get("D0"), 1);
  EXPECT_EQ(m->get("D1"), 7);
}

// 3.5 JMP: X35.5=1 -> Y0.0 unchanged, Y0.1=1; X35.5=0 -> both 1.
TEST_P(FlowExec, JmpExample) {
  const char *prog = "LD X35.5\nJMP L1111\nLDT\nOUT Y0.0\nLBL L1111\nLDT\nOUT Y0.1\n";
  auto taken = load(prog);
  ASSERT_TRUE(taken);
  taken->set("X35.5", 1);
  taken->tick();
  EXPECT_EQ(taken->get("Y0.0"), 0);
  EXPECT_EQ(taken->get("Y0.1"), 1);
  auto fallThrough = load(prog);
  ASSERT_TRUE(fallThrough);
  fallThrough->tick();
  EXPECT_EQ(fallThrough->get("Y0.0"), 1);
  EXPECT_EQ(fallThrough->get("Y0.1"), 1);
}

// A backward JMP used as a bounded loop (each taken backward jump is one watchdog step).
TEST_P(FlowExec, BackwardJmpLoop) {
  auto m = load("LBL L1\nLDT\nINC D0\nLDT\nCMP D0 4\nJMP L1\nLDT\nINC D1\n");
  ASSERT_TRUE(m);
  m->tick(); // D0 = 1..5: the jump back is taken while D0 <= 4
  EXPECT_EQ(m->get("D0"), 5);
  EXPECT_EQ(m->get("D1"), 1);
  EXPECT_EQ(m->state().steps, 4u);
}

// 3.5 RETN test: `SP S1 / LDI R100.0 / RETN / LDT / OUT Y0.0 / SPE`, called with R100.0=0 ->
// Y0.0 not written; with R100.0=1 -> Y0.0=1.
TEST_P(FlowExec, RetnExample) {
  const char *prog = "LDT\nCALL S1\n1END\n2END\nSP S1\nLDI R100.0\nRETN\nLDT\nOUT Y0.0\nSPE\n";
  auto m = load(prog);
  ASSERT_TRUE(m);
  m->tick();
  EXPECT_EQ(m->get("Y0.0"), 0);
  m->set("R100.0", 1);
  m->tick();
  EXPECT_EQ(m->get("Y0.0"), 1);
}

// 3.5 CALL: runs only when its input is 1; without input it always runs.
TEST_P(FlowExec, ConditionalAndUnconditionalCall) {
  auto m = load("LD X12.2\nCALL S123\nLBL L0\nCALL S7\n1END\n2END\n"
                "SP S123\nLDT\nINC D0\nSPE\nSP S7\nLDT\nINC D1\nSPE\n");
  ASSERT_TRUE(m);
  m->ticks(2);
  m->set("X12.2", 1);
  m->ticks(3);
  EXPECT_EQ(m->get("D0"), 3);
  EXPECT_EQ(m->get("D1"), 5);
}

// DIALECT.md 3: a called subroutine starts with empty stacks of its own and the caller's ST and
// MS are intact after the CALL, also when the callee returns by RETN with MS non-empty.
TEST_P(FlowExec, SubroutineStacksAreIndependent) {
  auto m = load(R"(
LD  X0.0
MPS
LD  X0.1
CALL S1
ANB
OUT Y0.0
MPP
OUT Y0.1
1END
2END
SP S1
LDI X0.0
MPS
LDI X0.1
MPS
OUT R5.0
LD X0.0
RETN
MPP
MPP
OUT R5.1
SPE
)");
  ASSERT_TRUE(m);
  forAllInputs(*m, {"X0.0", "X0.1"}, [&](const Inputs &v) {
    EXPECT_EQ(m->get("Y0.0"), v("X0.0") && v("X0.1"));
    EXPECT_EQ(m->get("Y0.1"), v("X0.0"));
    if (v("X0.1")) {
      EXPECT_EQ(m->get("R5.0"), 0); // written by the call: not X0.1
      // RETN taken (X0.0 = 1) leaves with MS 2 deep; otherwise R5.1 := the first MPS value.
      if (!v("X0.0")) {
        EXPECT_EQ(m->get("R5.1"), 1);
      }
    }
  });
}

// Nested calls: S1 calls S2; RETN in S2 returns to S1 only.
TEST_P(FlowExec, NestedCalls) {
  auto m = load("CALL S1\nLDT\nINC D9\n1END\n2END\n"
                "SP S1\nCALL S2\nLDT\nINC D1\nSPE\n"
                "SP S2\nLDT\nINC D2\nLDT\nRETN\nSPE\n");
  ASSERT_TRUE(m);
  m->ticks(3);
  EXPECT_EQ(m->get("D1"), 3);
  EXPECT_EQ(m->get("D2"), 3);
  EXPECT_EQ(m->get("D9"), 3);
}

// 3.5 LOOP test: `LOOP 5 / LDT / INC D0 / NEXT` -> D0 increases by 5 per scan.
TEST_P(FlowExec, LoopExample) {
  auto m = load("LOOP 5\nLDT\nINC D0\nNEXT\n");
  ASSERT_TRUE(m);
  m->tick();
  EXPECT_EQ(m->get("D0"), 5);
  m->tick();
  EXPECT_EQ(m->get("D0"), 10);
  EXPECT_EQ(m->state().steps, 5u); // each iteration counts one watchdog step
}

// dialect-notes: the count is read once on entry; n <= 0 skips the body; loops nest.
TEST_P(FlowExec, LoopCountRulesAndNesting) {
  auto m = load("LOOP D5\nLDT\nINC D5\nLDT\nINC D0\nNEXT\n"
                "LOOP W6\nLDT\nINC D1\nNEXT\n"
                "LOOP 3\nLOOP 4\nLDT\nINC D2\nNEXT\nLDT\nINC D3\nNEXT\n");
  ASSERT_TRUE(m);
  m->set("D5", 4);
  m->set("W6", -3);
  m->tick();
  EXPECT_EQ(m->get("D0"), 4);
  EXPECT_EQ(m->get("D5"), 8);
  EXPECT_EQ(m->get("D1"), 0);
  EXPECT_EQ(m->get("D2"), 12);
  EXPECT_EQ(m->get("D3"), 3);
}

// hnc8-functions-1.md 3.5 LOOP: edge instructions in the body update their memory on each
// iteration, so a rising edge is seen by the first iteration only.
TEST_P(FlowExec, EdgeInsideLoopUpdatesPerIteration) {
  auto m = load("LOOP 3\nLDP X0.0\nINC D0\nNEXT\n");
  ASSERT_TRUE(m);
  m->set("X0.0", 1);
  m->tick();
  EXPECT_EQ(m->get("D0"), 1);
  m->tick();
  EXPECT_EQ(m->get("D0"), 1);
}

// DIALECT.md 3: RETN inside a loop body of a subroutine leaves the subroutine.
TEST_P(FlowExec, RetnInsideLoop) {
  auto m = load("CALL S0\n1END\n2END\nSP S0\nLOOP 10\nLDT\nINC D0\nLDT\nCMP 3 D0\nRETN\nNEXT\n"
                "LDT\nINC D1\nSPE\n");
  ASSERT_TRUE(m);
  m->tick();
  EXPECT_EQ(m->get("D0"), 3);
  EXPECT_EQ(m->get("D1"), 0);
}

// DIALECT.md 3: skipped code (JMP) does not update edge memory. The LDP first executes in
// tick 1 and sees X0.1 = 1 against m = 0: a rising edge, although X0.1 was already 1 in tick 0.
TEST_P(FlowExec, EdgeNotUpdatedWhenJumpedOver) {
  auto m = load("LD X0.0\nJMP L1\nLDP X0.1\nOUT Y0.0\nLBL L1\n");
  ASSERT_TRUE(m);
  m->set("X0.0", 1);
  m->set("X0.1", 1);
  m->tick();
  EXPECT_EQ(m->get("Y0.0"), 0);
  m->set("X0.0", 0);
  m->tick();
  EXPECT_EQ(m->get("Y0.0"), 1);
  m->tick();
  EXPECT_EQ(m->get("Y0.0"), 0);
}

// DIALECT.md 3: an uncalled subroutine does not update its edge memory either.
TEST_P(FlowExec, EdgeNotUpdatedInUncalledSubroutine) {
  auto m = load("LD X0.0\nCALL S1\n1END\n2END\nSP S1\nLDP X0.1\nOUT Y0.0\nSPE\n");
  ASSERT_TRUE(m);
  m->set("X0.1", 1);
  m->tick(); // not called
  m->set("X0.0", 1);
  m->tick(); // first execution: rise
  EXPECT_EQ(m->get("Y0.0"), 1);
  m->tick();
  EXPECT_EQ(m->get("Y0.0"), 0);
}

// dialect-notes "Stacks and blocks": LBL empties ST, so a block after it reads input 1.
TEST_P(FlowExec, LabelEmptiesStack) {
  auto m = load("LD X0.0\nLBL L5\nMOV 7 D0\nOUT Y0.0\n");
  ASSERT_TRUE(m);
  m->tick();
  EXPECT_EQ(m->get("D0"), 7);
  EXPECT_EQ(m->get("Y0.0"), 1);
}

} // namespace
} // namespace lj::test

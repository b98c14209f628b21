// The watchdog (DIALECT.md 4, docs/dialect-notes.md "Flow"): `if (++steps > max) abort` before
// each taken backward JMP and each loop iteration; the abort keeps the state written so far,
// propagates out of subroutines, stops the part, and a PLC1 abort skips the tick's PLC2 slice.
#include "tests/exec/ExecTest.h"

namespace lj::test {
namespace {

class WatchdogExec : public ExecTest {};
LJ_EXEC_SUITE(WatchdogExec);

// Backward JMP in PLC1 with max = 10: the body after the label runs once plus once per allowed
// jump (11 times), the 11th jump aborts; code after the loop and the PLC2 slice do not run.
TEST_P(WatchdogExec, BackwardJumpAbortsTick) {
  auto m = load("LDT\nINC D0\nLBL L1\nLDT\nINC D1\nLD X0.0\nJMP L1\nLDT\nINC D3\n1END\n"
                "LDT\nINC D2\n2END\n");
  ASSERT_TRUE(m);
  m->state().max_backward_steps = 10;
  m->set("X0.0", 1);
  EXPECT_EQ(m->tick(), uint32_t{LJ_FAULT_WATCHDOG});
  EXPECT_EQ(m->get("D0"), 1);
  EXPECT_EQ(m->get("D1"), 11);
  EXPECT_EQ(m->get("D3"), 0);
  EXPECT_EQ(m->get("D2"), 0); // slice skipped
  EXPECT_EQ(m->state().steps, 11u);
  EXPECT_EQ(m->state().last_fault, uint32_t{LJ_FAULT_WATCHDOG});
  EXPECT_EQ(m->state().fault_watchdog, 1u);
  EXPECT_EQ(m->state().plc2_next_slice, 0u);
  // The next tick starts a fresh step count; with the loop released it completes.
  m->set("X0.0", 0);
  EXPECT_EQ(m->tick(), uint32_t{LJ_FAULT_NONE});
  EXPECT_EQ(m->get("D1"), 12);
  EXPECT_EQ(m->get("D3"), 1);
  EXPECT_EQ(m->get("D2"), 1);
  EXPECT_EQ(m->state().last_fault, uint32_t{LJ_FAULT_NONE});
  EXPECT_EQ(m->state().fault_watchdog, 1u);
}

// Exactly max steps is allowed: 10 taken backward jumps with max = 10 do not fault.
TEST_P(WatchdogExec, LimitIsInclusive) {
  auto m = load("LBL L1\nLDT\nINC D0\nLDT\nLT D0 11\nJMP L1\n");
  ASSERT_TRUE(m);
  m->state().max_backward_steps = 10;
  EXPECT_EQ(m->tick(), uint32_t{LJ_FAULT_NONE});
  EXPECT_EQ(m->get("D0"), 11);
  EXPECT_EQ(m->state().steps, 10u);
}

// Loop iterations count before their body: LOOP 20 with max = 10 runs the body 10 times.
TEST_P(WatchdogExec, LoopIterationsAbort) {
  auto m = load("LOOP 20\nLDT\nINC D0\nNEXT\nLDT\nINC D1\n");
  ASSERT_TRUE(m);
  m->state().max_backward_steps = 10;
  EXPECT_EQ(m->tick(), uint32_t{LJ_FAULT_WATCHDOG});
  EXPECT_EQ(m->get("D0"), 10);
  EXPECT_EQ(m->get("D1"), 0);
  EXPECT_EQ(m->tick(), uint32_t{LJ_FAULT_WATCHDOG});
  EXPECT_EQ(m->get("D0"), 20);
  EXPECT_EQ(m->state().fault_watchdog, 2u);
}

// The abort propagates out of a subroutine and stops the calling part; PLC2 is skipped.
TEST_P(WatchdogExec, AbortPropagatesOutOfSubroutine) {
  auto m = load("LDT\nCALL S1\nLDT\nINC D1\n1END\nLDT\nINC D2\n2END\n"
                "SP S1\nCALL S2\nLDT\nINC D4\nSPE\n"
                "SP S2\nLOOP 100\nLDT\nINC D0\nNEXT\nSPE\n");
  ASSERT_TRUE(m);
  m->state().max_backward_steps = 10;
  EXPECT_EQ(m->tick(), uint32_t{LJ_FAULT_WATCHDOG});
  EXPECT_EQ(m->get("D0"), 10);
  EXPECT_EQ(m->get("D4"), 0);
  EXPECT_EQ(m->get("D1"), 0);
  EXPECT_EQ(m->get("D2"), 0);
  m->state().max_backward_steps = 1000;
  EXPECT_EQ(m->tick(), uint32_t{LJ_FAULT_NONE});
  EXPECT_EQ(m->get("D0"), 110);
  EXPECT_EQ(m->get("D4"), 1);
  EXPECT_EQ(m->get("D1"), 1);
  EXPECT_EQ(m->get("D2"), 1);
}

// PLC1 and the PLC2 slice share one count per tick; an abort inside a slice still advances the
// slice index (dialect-notes "Flow").
TEST_P(WatchdogExec, SliceAbortAdvancesSlice) {
  auto m = load("LOOP 6\nLDT\nINC D0\nNEXT\n1END\n"
                "LOOP 6\nLDT\nINC D1\nNEXT\nLDT\nINC D5\n"
                "LDT\nINC D2\nLDT\nINC D3\n2END\n",
                optionsWithNvalue(2));
  ASSERT_TRUE(m);
  ASSERT_GE(m->engine().entries().plc2_slice_count, 2u);
  m->state().max_backward_steps = 10;
  EXPECT_EQ(m->tick(), uint32_t{LJ_FAULT_WATCHDOG}); // 6 steps in PLC1, 4 allowed in the slice
  EXPECT_EQ(m->get("D0"), 6);
  EXPECT_EQ(m->get("D1"), 4);
  EXPECT_EQ(m->get("D5"), 0);
  EXPECT_EQ(m->state().plc2_next_slice, 1u);
  EXPECT_EQ(m->state().fault_watchdog, 1u);
}

// Watchdog in the init part: lj_run_init reports it like a tick.
TEST_P(WatchdogExec, InitAbort) {
  auto m = loadNoInit("LOOP 50\nLDT\nINC D0\nNEXT\nIEND\nLDT\nINC D1\n");
  ASSERT_TRUE(m);
  m->state().max_backward_steps = 5;
  EXPECT_EQ(m->init(), uint32_t{LJ_FAULT_WATCHDOG});
  EXPECT_EQ(m->get("D0"), 5);
  EXPECT_EQ(m->state().fault_watchdog, 1u);
}

} // namespace
} // namespace lj::test

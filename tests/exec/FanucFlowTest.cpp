// FANUC select-call CS / CM / CE (fanuc-e) on every engine. The reference (../shared/reference/
// fanuc-pmc.md 4.2, [EXT]) says only "CS takes an index value and calls the CM entry it
// selects; CE closes the list"; the reading (2-byte binary index, 0 selects the first CM, out of
// range or ACT = 0 calls nothing) is docs/fanuc-pmc.md [EXT] "select-call". Expected values are
// derived by hand from that reading.
#include "tests/exec/FanucExec.h"

namespace lj::test {
namespace {

class FanucFlow : public FanucExecTest {};
LJ_EXEC_SUITE(FanucFlow);

// Each subroutine Pn sets R0.(n-1) (SET, so one tick shows every call made); the tick before
// clears R0 so each case starts from 0.
constexpr const char *kSelect =
    "END1\nRD X0.0\nCS R100\nCM P1\nCM P2\nCM P3\nCE\nRD R9091.1\nWRT R1.0\nEND2\n"
    "SP P1\nRD R9091.1\nSET R0.0\nSPE\nSP P2\nRD R9091.1\nSET R0.1\nSPE\n"
    "SP P3\nRD R9091.1\nSET R0.2\nSPE\nEND\n";

TEST_P(FanucFlow, SelectCallCallsTheIndexedEntry) {
  auto m = pmc(kSelect);
  ASSERT_TRUE(m);
  set(*m, "X0.0", 1);
  // index -> R0 bit pattern: 0 -> P1 (bit 0), 1 -> P2 (bit 1), 2 -> P3 (bit 2), 3 and -1 none.
  const int64_t expect[][2] = {{0, 0x1}, {1, 0x2}, {2, 0x4}, {3, 0}, {-1, 0}, {256, 0}};
  for (const auto &e : expect) {
    set(*m, "R0", 0);
    set(*m, "R100:2", e[0]);
    m->tick();
    EXPECT_EQ(get(*m, "R0") & 0xFF, e[1]) << "index " << e[0];
    EXPECT_EQ(get(*m, "R1.0"), 1); // the rung after CE runs
  }
}

TEST_P(FanucFlow, SelectCallWithActZeroCallsNothing) {
  auto m = pmc(kSelect);
  ASSERT_TRUE(m);
  for (int idx = 0; idx < 3; ++idx) {
    set(*m, "R0", 0);
    set(*m, "R100:2", idx);
    m->tick();
    EXPECT_EQ(get(*m, "R0") & 0xFF, 0) << "index " << idx;
  }
}

// The index is two bytes: R101 = 1 with R100 = 0 is index 256, not 0 (3.1 little-endian).
TEST_P(FanucFlow, SelectCallIndexIsTwoBytes) {
  auto m = pmc(kSelect);
  ASSERT_TRUE(m);
  set(*m, "X0.0", 1);
  set(*m, "R100", 0);
  set(*m, "R101", 1);
  m->tick();
  EXPECT_EQ(get(*m, "R0") & 0xFF, 0);
}

// A select-call inside a subroutine, and the same subroutine listed twice: index 1 calls P2
// once (its counter-like SET pattern is one bit), index 2 calls P2 again through the third CM.
TEST_P(FanucFlow, SelectCallFromASubroutine) {
  auto m =
      pmc("END1\nRD X0.0\nCALL P9\nEND2\nSP P9\nRD R9091.1\nCS D10\nCM P1\nCM P2\nCM P2\n"
          "CE\nSPE\nSP P1\nRD R9091.1\nSET R0.0\nSPE\nSP P2\nRD R9091.1\nSET R0.1\nSPE\nEND\n");
  ASSERT_TRUE(m);
  set(*m, "X0.0", 1);
  set(*m, "D10:2", 2);
  m->tick();
  EXPECT_EQ(get(*m, "R0") & 0xFF, 0x2);
  set(*m, "R0", 0);
  set(*m, "D10:2", 0);
  m->tick();
  EXPECT_EQ(get(*m, "R0") & 0xFF, 0x1);
  set(*m, "R0", 0);
  set(*m, "X0.0", 0); // P9 not called: nothing
  m->tick();
  EXPECT_EQ(get(*m, "R0") & 0xFF, 0);
}

// ---- JMPC (SUB 73) -------------------------------------------------------------------------
// The reference (4.2 [EXT]) says "JMPC jumps from a subroutine to a label in level 2"; the
// reading (docs/fanuc-pmc.md "JMPC"): ACT = 1 leaves the subroutine and every subroutine that
// called it, and level 2 goes on at the label; what was skipped keeps its state, like JMPB's
// skipped coils. Expected values follow from that by hand.

// Level 2 calls P1 when X0.0; P1 sets R0.0, takes JMPC L1 when X0.1, else sets R0.3.
constexpr const char *kJmpc = "END1\nRD X0.0\nCALL P1\nRD R9091.1\nWRT R0.1\nLBL L1\n"
                              "RD R9091.1\nWRT R0.2\nEND2\n"
                              "SP P1\nRD R9091.1\nSET R0.0\nRD X0.1\nJMPC L1\n"
                              "RD R9091.1\nSET R0.3\nSPE\nEND\n";

TEST_P(FanucFlow, JmpcLeavesTheSubroutineForALevel2Label) {
  auto m = pmc(kJmpc);
  ASSERT_TRUE(m);
  // Not taken: P1 runs to its end, level 2 runs every rung.
  set(*m, "X0.0", 1);
  ASSERT_EQ(m->tick(), uint32_t{LJ_FAULT_NONE});
  EXPECT_EQ(get(*m, "R0") & 0xF, 0xF);
  // Taken: P1 stops at JMPC (R0.3 not set again), level 2 skips WRT R0.1 (it keeps 0).
  set(*m, "R0", 0);
  set(*m, "X0.1", 1);
  ASSERT_EQ(m->tick(), uint32_t{LJ_FAULT_NONE});
  EXPECT_EQ(get(*m, "R0") & 0xF, 0x5); // R0.0 (P1 ran) and R0.2 (after L1)
  // The skipped coil keeps its state: set it, the jump leaves it 1.
  set(*m, "R0.1", 1);
  ASSERT_EQ(m->tick(), uint32_t{LJ_FAULT_NONE});
  EXPECT_EQ(get(*m, "R0.1"), 1);
  // JMPC's ACT = 0: no jump (X0.1 = 0) and no call (X0.0 = 0) both run the rung after CALL.
  set(*m, "R0", 0);
  set(*m, "X0.0", 0);
  ASSERT_EQ(m->tick(), uint32_t{LJ_FAULT_NONE});
  EXPECT_EQ(get(*m, "R0") & 0xF, 0x6);
}

// Level 2 -> P1 -> P2; P2's JMPC leaves both: the rest of P1 after CALLU P2 does not run.
TEST_P(FanucFlow, JmpcLeavesEveryCallingSubroutine) {
  auto m = pmc("END1\nRD X0.0\nCALL P1\nRD R9091.1\nWRT R0.1\nLBL L7\nRD R9091.1\nWRT R0.2\n"
               "END2\nSP P1\nRD R9091.1\nSET R1.0\nCALLU P2\nRD R9091.1\nSET R1.1\nSPE\n"
               "SP P2\nRD X0.1\nJMPC L7\nRD R9091.1\nSET R1.2\nSPE\nEND\n");
  ASSERT_TRUE(m);
  set(*m, "X0.0", 1);
  set(*m, "X0.1", 1);
  ASSERT_EQ(m->tick(), uint32_t{LJ_FAULT_NONE});
  EXPECT_EQ(get(*m, "R1") & 0x7, 0x1); // P1 up to its CALLU only; P2 up to its JMPC only
  EXPECT_EQ(get(*m, "R0") & 0x6, 0x4); // level 2: WRT R0.1 skipped, WRT R0.2 after L7
  set(*m, "R1", 0);
  set(*m, "X0.1", 0);
  ASSERT_EQ(m->tick(), uint32_t{LJ_FAULT_NONE});
  EXPECT_EQ(get(*m, "R1") & 0x7, 0x7);
  EXPECT_EQ(get(*m, "R0") & 0x6, 0x6);
}

// A JMPC back to a label before the CALL repeats the code in between. R20 is 0 at the start of
// level 2 (NUMEB), P1 adds 1 (ADDB) and jumps back while R20 < 5: P1 runs 5 times, then level
// 2 goes on after the CALL.
constexpr const char *kJmpcBack = "END1\nRD R9091.1\nNUMEB 1 0 R20\nLBL L1\nRD R9091.1\n"
                                  "CALL P1\nRD R9091.1\nWRT R0.0\nEND2\n"
                                  "SP P1\nRD R9091.0\nRD.STK R9091.1\nADDB 0001 R20 1 R20\n"
                                  "RD R9091.1\nLTB R20 5\nJMPC L1\nSPE\nEND\n";

TEST_P(FanucFlow, JmpcBackwardRepeatsLevel2) {
  auto m = pmc(kJmpcBack);
  ASSERT_TRUE(m);
  ASSERT_EQ(m->tick(), uint32_t{LJ_FAULT_NONE});
  EXPECT_EQ(get(*m, "R20"), 5);
  EXPECT_EQ(get(*m, "R0.0"), 1);
  ASSERT_EQ(m->tick(), uint32_t{LJ_FAULT_NONE}); // the next scan starts again from 0
  EXPECT_EQ(get(*m, "R20"), 5);
}

// A backward JMPC counts one watchdog step per jump, as a backward JMPB does (DIALECT.md 4):
// 4 jumps pass a limit of 100; with a limit of 3 the 4th jump ends the tick with the watchdog
// fault.
TEST_P(FanucFlow, JmpcBackwardCountsWatchdogSteps) {
  auto m = pmc(kJmpcBack);
  ASSERT_TRUE(m);
  m->state().max_backward_steps = 100;
  set(*m, "R20", 0);
  ASSERT_EQ(m->tick(), uint32_t{LJ_FAULT_NONE}); // 4 backward jumps, under the limit
  m->state().max_backward_steps = 3;
  EXPECT_EQ(m->tick(), uint32_t{LJ_FAULT_WATCHDOG});
  // Jumps 1..3 pass, the 4th exceeds the limit: P1 ran 4 times (R20 = 4) and the rest of
  // level 2 did not run.
  EXPECT_EQ(get(*m, "R20"), 4);
}

// JMPC from a subroutine a CS..CE list calls: the list's MS entry is dropped at the label.
TEST_P(FanucFlow, JmpcFromASelectCall) {
  auto m = pmc("END1\nRD X0.0\nCS R100\nCM P1\nCM P2\nCE\nRD R9091.1\nWRT R0.1\nLBL L3\n"
               "RD R9091.1\nWRT R0.2\nEND2\nSP P1\nRD R9091.1\nSET R0.0\nSPE\n"
               "SP P2\nRD R9091.1\nJMPC L3\nSPE\nEND\n");
  ASSERT_TRUE(m);
  set(*m, "X0.0", 1);
  set(*m, "R100:2", 1); // P2: jumps
  ASSERT_EQ(m->tick(), uint32_t{LJ_FAULT_NONE});
  EXPECT_EQ(get(*m, "R0") & 0x7, 0x4);
  set(*m, "R100:2", 0); // P1: no jump
  ASSERT_EQ(m->tick(), uint32_t{LJ_FAULT_NONE});
  EXPECT_EQ(get(*m, "R0") & 0x7, 0x7);
}

} // namespace
} // namespace lj::test

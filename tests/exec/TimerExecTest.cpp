// Timers TMRB (on-delay) and STMR (off-delay): the timing tests of hnc8-functions-1.md 3.4 with
// the state rules of docs/dialect-notes.md "Timers" (now_ms = tick * period).
#include "tests/exec/ExecTest.h"

#include <algorithm>

namespace lj::test {
namespace {

class TimerExec : public ExecTest {};
LJ_EXEC_SUITE(TimerExec);

// 3.4 TMRB: X35.5=1 from t=0 -> Y4.2=0 at t=99 and 1 at t>=100; T1 = min(elapsed, preset).
TEST_P(TimerExec, TmrbExample) {
  auto m = load("LD X35.5\nTMRB 1 0 100\nOUT Y4.2\nLD T1.0\nOUT Y5.0\n");
  ASSERT_TRUE(m);
  m->set("X35.5", 1);
  for (int64_t t = 0; t <= 150; ++t) {
    m->tick(); // tick t runs at now_ms = t
    ASSERT_EQ(m->get("Y4.2"), t >= 100) << "t=" << t;
    ASSERT_EQ(m->get("Y5.0"), t >= 100) << "t=" << t; // Tn.0 contact
    ASSERT_EQ(m->get("T1"), std::min<int64_t>(t, 100)) << "t=" << t;
  }
}

// 3.4 TMRB: X35.5=0 at any time -> Y4.2=0, and the next on restarts timing from 0.
TEST_P(TimerExec, TmrbResetsWhenInputDrops) {
  auto m = load("LD X35.5\nTMRB 1 0 100\nOUT Y4.2\n");
  ASSERT_TRUE(m);
  m->set("X35.5", 1);
  m->ticks(60); // t = 0..59
  m->set("X35.5", 0);
  m->tick(); // t = 60
  EXPECT_EQ(m->get("Y4.2"), 0);
  EXPECT_EQ(m->get("T1"), 0);
  m->ticks(9); // t = 61..69
  m->set("X35.5", 1);
  m->ticks(100); // t = 70..169: elapsed 99 at t = 169
  EXPECT_EQ(m->get("Y4.2"), 0);
  EXPECT_EQ(m->get("T1"), 99);
  m->tick(); // t = 170
  EXPECT_EQ(m->get("Y4.2"), 1);
}

// 3.4 units: preset_ms = len * {1, 1000, 60000, 3600000}[unit], computed in 64 bits.
TEST_P(TimerExec, TmrbUnits) {
  struct Case {
    const char *program;
    uint32_t periodMs;
    uint32_t onTick; ///< first tick with output 1: preset / period
  };
  const Case cases[] = {
      {"LDT\nTMRB 2 1 2\nOUT Y0.0\n", 250, 2000 / 250},
      {"LDT\nTMRB 2 2 1\nOUT Y0.0\n", 1000, 60000 / 1000},
      // 1000 h = 3.6e9 ms does not fit in int32 (3.4: "compute them in 64 bits").
      {"LDT\nTMRB 2 3 1000\nOUT Y0.0\n", 3600000, 1000},
  };
  for (const Case &c : cases) {
    SCOPED_TRACE(c.program);
    auto m = load(c.program);
    ASSERT_TRUE(m);
    m->setPeriodMs(c.periodMs);
    m->ticks(c.onTick); // ticks 0 .. onTick-1
    EXPECT_EQ(m->get("Y0.0"), 0);
    m->tick();
    EXPECT_EQ(m->get("Y0.0"), 1);
    EXPECT_EQ(m->get("T2"), int64_t(c.onTick) * c.periodMs);
  }
}

// dialect-notes: len is read on every execution; a negative preset counts as 0; preset 0 turns
// the output on in the same scan.
TEST_P(TimerExec, TmrbRegisterPreset) {
  auto m = load("LD X0.0\nTMRB 4 0 D0\nOUT Y0.0\nLD X0.1\nTMRB 5 0 W1\nOUT Y0.1\n");
  ASSERT_TRUE(m);
  m->set("D0", 100);
  m->set("W1", -5);
  m->set("X0.0", 1);
  m->set("X0.1", 1);
  m->tick(); // t = 0
  EXPECT_EQ(m->get("Y0.0"), 0);
  EXPECT_EQ(m->get("Y0.1"), 1);
  EXPECT_EQ(m->get("T5"), 0);
  m->ticks(19); // t = 1..19
  EXPECT_EQ(m->get("Y0.0"), 0);
  m->set("D0", 20);
  m->tick(); // t = 20: elapsed 20 >= new preset 20
  EXPECT_EQ(m->get("Y0.0"), 1);
  EXPECT_EQ(m->get("T4"), 20);
}

// 3.4 STMR: never on -> 0; X35.5=1 -> Y4.2=1 at once; X35.5 -> 0 at t0 -> Y4.2=1 until
// t0+99 and 0 from t0+100; T1 = elapsed, then the preset.
TEST_P(TimerExec, StmrExample) {
  auto m = load("LD X35.5\nSTMR 1 0 100\nOUT Y4.2\n");
  ASSERT_TRUE(m);
  m->ticks(5); // t = 0..4, input never on
  EXPECT_EQ(m->get("Y4.2"), 0);
  m->set("X35.5", 1);
  m->tick(); // t = 5
  EXPECT_EQ(m->get("Y4.2"), 1);
  m->ticks(4); // t = 6..9
  m->set("X35.5", 0);
  for (int64_t t = 10; t <= 130; ++t) {
    m->tick();
    ASSERT_EQ(m->get("Y4.2"), t < 110) << "t=" << t;
    ASSERT_EQ(m->get("T1"), std::min<int64_t>(t - 10, 100)) << "t=" << t;
  }
}

// 3.4 STMR: the input coming back during the off-delay cancels it; the next off restarts it.
TEST_P(TimerExec, StmrCancelledByInput) {
  auto m = load("LD X35.5\nSTMR 1 0 100\nOUT Y4.2\n");
  ASSERT_TRUE(m);
  m->set("X35.5", 1);
  m->tick(); // t = 0
  m->set("X35.5", 0);
  m->ticks(50); // t = 1..50
  m->set("X35.5", 1);
  m->tick(); // t = 51
  EXPECT_EQ(m->get("Y4.2"), 1);
  EXPECT_EQ(m->get("T1"), 0);
  m->set("X35.5", 0);
  m->ticks(100); // t = 52..151: off since 52, elapsed 99 at 151
  EXPECT_EQ(m->get("Y4.2"), 1);
  m->tick(); // t = 152
  EXPECT_EQ(m->get("Y4.2"), 0);
  EXPECT_EQ(m->get("T1"), 100);
}

// dialect-notes: a skipped timer keeps aging (timestamps); its coil is not written while skipped.
TEST_P(TimerExec, SkippedTimerKeepsAging) {
  auto m = load("LD X0.1\nJMP L1\nLD X0.0\nTMRB 6 0 100\nOUT Y0.0\nLBL L1\n");
  ASSERT_TRUE(m);
  m->set("X0.0", 1);
  m->tick(); // t = 0: timing starts
  m->set("X0.1", 1);
  m->ticks(149); // t = 1..149 skipped
  EXPECT_EQ(m->get("Y0.0"), 0);
  EXPECT_EQ(m->get("T6"), 0);
  m->set("X0.1", 0);
  m->tick(); // t = 150
  EXPECT_EQ(m->get("Y0.0"), 1);
  EXPECT_EQ(m->get("T6"), 100);
}

// Retentive timer numbers use the upper slots (abi.h lj_tc_slot): T300 is independent of T0.
TEST_P(TimerExec, RetentiveNumbersAreSeparateTimers) {
  auto m = load("LD X0.0\nTMRB 0 0 5\nOUT Y0.0\nLD X0.1\nTMRB 300 0 10\nOUT Y0.1\n");
  ASSERT_TRUE(m);
  m->set("X0.0", 1);
  m->set("X0.1", 1);
  m->ticks(6); // t = 0..5
  EXPECT_EQ(m->get("Y0.0"), 1);
  EXPECT_EQ(m->get("Y0.1"), 0);
  EXPECT_EQ(m->get("T300"), 5);
  EXPECT_EQ(m->state().T[128].elapsed_ms, 5);
}

} // namespace
} // namespace lj::test

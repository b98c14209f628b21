// Counters CTR, CTRC, CTUD: the test values of hnc8-functions-1.md 3.3 and the common
// algorithm there (rising edge of input 1, ring counting, reset priority, down counting reloads
// the preset), with the storage rules of docs/dialect-notes.md "Function blocks".
#include "tests/exec/ExecTest.h"

namespace lj::test {
namespace {

class CounterExec : public ExecTest {
protected:
  static void resetPulse(Machine &m, std::string_view rst) {
    m.set(rst, 1);
    m.tick();
    m.set(rst, 0);
    m.tick();
  }
};
LJ_EXEC_SUITE(CounterExec);

constexpr const char *kCtrExample = "LD X2.5\nLD X4.0\nLD X4.1\nLD X4.2\nCTR R0 16\nOUT Y1.4\n";

// hnc8-functions-1.md 3.3 CTR tests 1-4: start 1, count up, output at 16, ring back to 1.
TEST_P(CounterExec, CtrExampleCountUpFromOne) {
  auto m = load(kCtrExample);
  ASSERT_TRUE(m);
  m->set("X4.0", 1);
  m->set("X4.1", 0);
  resetPulse(*m, "X4.2");
  EXPECT_EQ(m->get("R0"), 1);
  pulse(*m, "X2.5", 5);
  EXPECT_EQ(m->get("R0"), 6);
  EXPECT_EQ(m->get("Y1.4"), 0);
  pulse(*m, "X2.5", 10);
  EXPECT_EQ(m->get("R0"), 16);
  EXPECT_EQ(m->get("Y1.4"), 1);
  pulse(*m, "X2.5", 1);
  EXPECT_EQ(m->get("R0"), 1); // ring
  EXPECT_EQ(m->get("Y1.4"), 0);
  pulse(*m, "X2.5", 3);
  m->set("X4.2", 1);
  m->tick();
  EXPECT_EQ(m->get("R0"), 1); // reset to the start value 1
  EXPECT_EQ(m->get("Y1.4"), 0);
}

// 3.3 CTR test 5: X4.0=0, X4.1=0 with reset -> R0=0; 16 pulses -> Y1.4=1.
TEST_P(CounterExec, CtrExampleCountUpFromZero) {
  auto m = load(kCtrExample);
  ASSERT_TRUE(m);
  m->set("R0", 9);
  resetPulse(*m, "X4.2");
  EXPECT_EQ(m->get("R0"), 0);
  pulse(*m, "X2.5", 15);
  EXPECT_EQ(m->get("Y1.4"), 0);
  pulse(*m, "X2.5", 1);
  EXPECT_EQ(m->get("R0"), 16);
  EXPECT_EQ(m->get("Y1.4"), 1);
}

// 3.3 CTR test 6: down (X4.1=1), start 1, reset -> R0=16; 15 pulses -> R0=1 -> Y1.4=1; the next
// pulse reloads the preset.
TEST_P(CounterExec, CtrExampleCountDown) {
  auto m = load(kCtrExample);
  ASSERT_TRUE(m);
  m->set("X4.0", 1);
  m->set("X4.1", 1);
  resetPulse(*m, "X4.2");
  EXPECT_EQ(m->get("R0"), 16);
  EXPECT_EQ(m->get("Y1.4"), 0);
  pulse(*m, "X2.5", 15);
  EXPECT_EQ(m->get("R0"), 1);
  EXPECT_EQ(m->get("Y1.4"), 1);
  pulse(*m, "X2.5", 1);
  EXPECT_EQ(m->get("R0"), 16);
  EXPECT_EQ(m->get("Y1.4"), 0);
}

// 3.3 "Power-up": edge memory starts at 0, so an input already 1 on the first scan counts
// once; holding it counts nothing more (rising edges only).
TEST_P(CounterExec, CountsRisingEdgesOnly) {
  auto m = load(kCtrExample);
  ASSERT_TRUE(m);
  m->set("X2.5", 1);
  m->ticks(5);
  EXPECT_EQ(m->get("R0"), 1);
}

// 3.3: reset is level-sensitive and has priority; the edge memory follows input 1 during reset,
// so releasing reset while input 1 stays on does not count.
TEST_P(CounterExec, ResetHasPriority) {
  auto m = load(kCtrExample);
  ASSERT_TRUE(m);
  m->set("X4.2", 1);
  m->set("X2.5", 1);
  m->tick();
  EXPECT_EQ(m->get("R0"), 0);
  m->set("X4.2", 0);
  m->tick();
  EXPECT_EQ(m->get("R0"), 0);
  m->set("X2.5", 0);
  m->tick();
  m->set("X2.5", 1);
  m->tick();
  EXPECT_EQ(m->get("R0"), 1);
}

// dialect-notes: CTR keeps its value in its register at the register's width (R wraps at 256),
// and the preset is read on every execution.
TEST_P(CounterExec, CtrRegisterWidthAndLivePreset) {
  auto m = load("LD X0.0\nLDI X7.0\nLDI X7.1\nLD X0.1\nCTR R3 D9\nOUT Y0.0\n"
                "LD X0.0\nLDI X7.0\nLDI X7.1\nLD X0.1\nCTR W3 D9\nOUT Y0.1\n");
  ASSERT_TRUE(m);
  m->set("X7.0", 1); // LDI X7.0 -> start value 0
  m->set("X7.1", 1); // LDI X7.1 -> count up
  m->set("D9", 300);
  m->set("R3", 255);
  m->set("W3", 255);
  pulse(*m, "X0.0", 1);
  EXPECT_EQ(m->get("R3"), 0); // 256 truncated to 8 bits
  EXPECT_EQ(m->get("W3"), 256);
  m->set("D9", 256); // W3 has reached the new preset
  m->tick();
  EXPECT_EQ(m->get("Y0.1"), 1);
  EXPECT_EQ(m->get("Y0.0"), 0);
}

// hnc8-functions-1.md 3.3 CTRC tests: 99 pulses -> 0, 100 -> Y1.4=1; X4.0=1 -> Y1.4=0, count 0.
TEST_P(CounterExec, CtrcExample) {
  auto m = load("LD X2.5\nLD X4.0\nCTRC 0 100\nOUT Y1.4\n");
  ASSERT_TRUE(m);
  pulse(*m, "X2.5", 99);
  EXPECT_EQ(m->get("C0"), 99);
  EXPECT_EQ(m->get("Y1.4"), 0);
  EXPECT_EQ(m->get("C0.0"), 0);
  pulse(*m, "X2.5", 1);
  EXPECT_EQ(m->get("C0"), 100);
  EXPECT_EQ(m->get("Y1.4"), 1);
  EXPECT_EQ(m->get("C0.0"), 1);
  m->set("X4.0", 1);
  m->tick();
  EXPECT_EQ(m->get("Y1.4"), 0);
  EXPECT_EQ(m->get("C0"), 0);
  EXPECT_EQ(m->get("C0.0"), 0);
}

// 3.3 ring counting with pv = 3 and start 0: 0 -> 1 -> 2 -> 3 (out) -> 0 -> 1.
TEST_P(CounterExec, CtrcRing) {
  auto m = load("LD X0.0\nLD X0.1\nCTRC 300 3\nOUT Y0.0\nLD C300.0\nOUT Y0.1\n");
  ASSERT_TRUE(m);
  const int expectCount[] = {1, 2, 3, 0, 1};
  for (int i = 0; i < 5; ++i) {
    pulse(*m, "X0.0", 1);
    EXPECT_EQ(m->get("C300"), expectCount[i]) << "pulse " << i + 1;
    EXPECT_EQ(m->get("Y0.0"), expectCount[i] >= 3);
    EXPECT_EQ(m->get("Y0.1"), expectCount[i] >= 3); // Cn.0 contact reads the output
  }
}

constexpr const char *kCtudExample =
    "LD X2.5\nLD X2.6\nLD X2.7\nLD X3.0\nCTUD 0 100\nOUT Y1.4\n"; // X3.0 for the manual's X2.8

// hnc8-functions-1.md 3.3 CTUD test 1: up from 0, reset, 100 pulses -> Y1.4=1.
TEST_P(CounterExec, CtudExampleUp) {
  auto m = load(kCtudExample);
  ASSERT_TRUE(m);
  resetPulse(*m, "X3.0");
  pulse(*m, "X2.5", 99);
  EXPECT_EQ(m->get("Y1.4"), 0);
  pulse(*m, "X2.5", 1);
  EXPECT_EQ(m->get("C0"), 100);
  EXPECT_EQ(m->get("Y1.4"), 1);
}

// 3.3 CTUD test 2: X2.7=1 (down), reset -> cv=100; 100 pulses -> cv=0 -> Y1.4=1; then reload.
TEST_P(CounterExec, CtudExampleDown) {
  auto m = load(kCtudExample);
  ASSERT_TRUE(m);
  m->set("X2.7", 1);
  resetPulse(*m, "X3.0");
  EXPECT_EQ(m->get("C0"), 100);
  pulse(*m, "X2.5", 99);
  EXPECT_EQ(m->get("C0"), 1);
  EXPECT_EQ(m->get("Y1.4"), 0);
  pulse(*m, "X2.5", 1);
  EXPECT_EQ(m->get("C0"), 0);
  EXPECT_EQ(m->get("Y1.4"), 1);
  pulse(*m, "X2.5", 1);
  EXPECT_EQ(m->get("C0"), 100); // down counting reloads the preset
}

// 3.3 / hnc8-core.md 5.2: LDT on input 2 makes the counter restart from 1 after reset.
TEST_P(CounterExec, CtudStartOneWithLdt) {
  auto m = load("LD X2.5\nLDT\nLD X2.7\nLD X3.0\nCTUD 5 3\nOUT Y1.4\n");
  ASSERT_TRUE(m);
  resetPulse(*m, "X3.0");
  EXPECT_EQ(m->get("C5"), 1);
  pulse(*m, "X2.5", 2);
  EXPECT_EQ(m->get("C5"), 3);
  EXPECT_EQ(m->get("Y1.4"), 1);
  pulse(*m, "X2.5", 1);
  EXPECT_EQ(m->get("C5"), 1); // ring back to the start value 1
}

} // namespace
} // namespace lj::test

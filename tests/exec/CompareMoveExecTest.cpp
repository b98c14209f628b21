// Compare blocks CMP LT ACMP COIN and MOV: hnc8-functions-1.md 3.6 / hnc8-functions-2.md 1.x and
// 2.1 test values, plus the empty-ST rule of docs/dialect-notes.md "Stacks and blocks".
#include "tests/exec/ExecTest.h"

#include <utility>
#include <vector>

namespace lj::test {
namespace {

class CompareExec : public ExecTest {};
LJ_EXEC_SUITE(CompareExec);

/// Runs one tick per (R0 value, expected R10.0) pair.
void expectTable(Machine &m, const std::vector<std::pair<int, int>> &rows) {
  for (auto [r0, out] : rows) {
    m.set("R0", r0);
    m.tick();
    EXPECT_EQ(m.get("R10.0"), out) << "R0=" << r0;
  }
}

// hnc8-functions-2.md 1.1: R0=100 -> 1; 99 -> 1; 101 -> 0; 0 -> 1.
TEST_P(CompareExec, CmpTests) {
  auto m = load("LDT\nCMP R0 100\nOUT R10.0\n");
  ASSERT_TRUE(m);
  expectTable(*m, {{100, 1}, {99, 1}, {101, 0}, {0, 1}});
}

// hnc8-functions-2.md 1.2: R0=99 -> 1; 100 -> 0; 150 -> 0.
TEST_P(CompareExec, LtTests) {
  auto m = load("LDT\nLT R0 100\nOUT R10.0\n");
  ASSERT_TRUE(m);
  expectTable(*m, {{99, 1}, {100, 0}, {150, 0}});
}

// hnc8-functions-2.md 1.3: R0=50 -> 1; 0 -> 0; 100 -> 0; 1 -> 1; 99 -> 1 (both bounds strict).
TEST_P(CompareExec, AcmpTests) {
  auto m = load("LDT\nACMP 0 100 R0\nOUT R10.0\n");
  ASSERT_TRUE(m);
  expectTable(*m, {{50, 1}, {0, 0}, {100, 0}, {1, 1}, {99, 1}});
}

// hnc8-functions-2.md 1.3: lo >= hi is always false.
TEST_P(CompareExec, AcmpEmptyRange) {
  auto m = load("LDT\nACMP 100 0 R0\nOUT R10.0\n");
  ASSERT_TRUE(m);
  expectTable(*m, {{50, 0}, {0, 0}, {100, 0}});
}

// hnc8-functions-2.md 1.4: R0=100 -> 1; 99 -> 0.
TEST_P(CompareExec, CoinTests) {
  auto m = load("LDT\nCOIN R0 100\nOUT R10.0\n");
  ASSERT_TRUE(m);
  expectTable(*m, {{100, 1}, {99, 0}});
}

// hnc8-functions-2.md 1.4 series use: with X1.0 = 0, Y1.0 = 0 whatever R0 holds (out = EN and
// condition).
TEST_P(CompareExec, CompareInSeries) {
  auto m = load("LD X1.0\nCOIN R0 100\nOUT Y1.0\n");
  ASSERT_TRUE(m);
  for (int x : {0, 1}) {
    for (int r0 : {100, 99}) {
      m->set("X1.0", x);
      m->set("R0", r0);
      m->tick();
      EXPECT_EQ(m->get("Y1.0"), x && r0 == 100) << "X1.0=" << x << " R0=" << r0;
    }
  }
}

// dialect-notes: with an empty ST a compare's input is 1 and its output is pushed, so
// `CMP R0 100 / OUT R1.0` works without LDT (hnc8-functions-1.md 3.6 CMP test values).
TEST_P(CompareExec, LeftRailCompare) {
  auto m = load("CMP R0 100\nOUT R1.0\n");
  ASSERT_TRUE(m);
  m->set("R0", 100);
  m->tick();
  EXPECT_EQ(m->get("R1.0"), 1);
  m->set("R0", 101);
  m->tick();
  EXPECT_EQ(m->get("R1.0"), 0);
}

// hnc8-functions-2.md 0.2 / 1.4: compares are signed after the read rule. F2616 = 0xFFFF is -1
// (sign-extended); R0 = 200 stays 200 (zero-extended), so CMP R0 100 is false.
TEST_P(CompareExec, SignedAfterReadRule) {
  auto m = load("LDT\nCOIN F2616 -1\nOUT R10.0\nLDT\nCMP R0 100\nOUT R10.1\nLDT\nLT W5 0\n"
                "OUT R10.2\nLDT\nCOIN W5 -1\nOUT R10.3\n");
  ASSERT_TRUE(m);
  m->set("F2616", 0xFFFF);
  m->set("R0", 200);
  m->set("W5", 0xFFFF);
  m->tick();
  EXPECT_EQ(m->get("R10.0"), 1);
  EXPECT_EQ(m->get("R10.1"), 0);
  EXPECT_EQ(m->get("R10.2"), 1);
  EXPECT_EQ(m->get("R10.3"), 1);
}

// hnc8-functions-2.md 2.1: D0=123456 -> D1=123456; ST0 := EN.
TEST_P(CompareExec, MovExample) {
  auto m = load("LDT\nMOV D0 D1\nOUT R4.0\n");
  ASSERT_TRUE(m);
  m->set("D0", 123456);
  m->tick();
  EXPECT_EQ(m->get("D1"), 123456);
  EXPECT_EQ(m->get("R4.0"), 1);
}

// hnc8-functions-2.md 2.1 width tests: MOV 300 R5 -> 44; MOV -1 W3 -> 0xFFFF (reads -1);
// MOV W3 D2 -> -1.
TEST_P(CompareExec, MovWidthTests) {
  auto m = load("LDT\nMOV 300 R5\nLDT\nMOV -1 W3\nLDT\nMOV W3 D2\nLDT\nMOV R5 G7\n");
  ASSERT_TRUE(m);
  m->tick();
  EXPECT_EQ(m->get("R5"), 44);
  EXPECT_EQ(m->get("W3"), -1);
  EXPECT_EQ(m->state().img.W[3], static_cast<int16_t>(0xFFFF));
  EXPECT_EQ(m->get("D2"), -1);
  EXPECT_EQ(m->get("G7"), 44);
}

// dialect-notes: a move with EN = 0 does nothing and outputs 0.
TEST_P(CompareExec, MovDisabled) {
  auto m = load("LD X0.0\nMOV 5 D1\nOUT R4.0\n");
  ASSERT_TRUE(m);
  m->set("D1", 9);
  m->tick();
  EXPECT_EQ(m->get("D1"), 9);
  EXPECT_EQ(m->get("R4.0"), 0);
  m->set("X0.0", 1);
  m->tick();
  EXPECT_EQ(m->get("D1"), 5);
  EXPECT_EQ(m->get("R4.0"), 1);
}

} // namespace
} // namespace lj::test

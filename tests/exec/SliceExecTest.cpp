// PLC2 slicing (DIALECT.md 4, docs/dialect-notes.md "PLC2 slicing"): slices end at the first
// rung boundary after at least plc2_nvalue statements; tick t runs slice t mod n; PLC1 runs
// every tick.
#include "tests/exec/ExecTest.h"

namespace lj::test {
namespace {

class SliceExec : public ExecTest {};
LJ_EXEC_SUITE(SliceExec);

// PLC1 increments D10 every tick; PLC2 is four rungs `LDT / INC Dk`, each 2 statements.
constexpr const char *kFourRungs = "LDT\nINC D10\n1END\n"
                                   "LDT\nINC D0\nLDT\nINC D1\nLDT\nINC D2\nLDT\nINC D3\n2END\n";

/// Times slice k ran in ticks 0..t when tick u runs slice u mod n.
int64_t runsOfSlice(int64_t k, int64_t t, int64_t n) { return t < k ? 0 : (t - k) / n + 1; }

// nvalue = 2: every rung is one slice (the boundary after 2 statements is a rung boundary: the
// INC output left in ST is never read), so each PLC2 counter moves once per 4-tick cycle.
TEST_P(SliceExec, OneRungPerSlice) {
  auto m = load(kFourRungs, optionsWithNvalue(2));
  ASSERT_TRUE(m);
  EXPECT_EQ(m->engine().entries().plc2_slice_count, 4u);
  for (int64_t t = 0; t < 13; ++t) {
    EXPECT_EQ(m->state().plc2_next_slice, uint32_t(t % 4));
    m->tick();
    SCOPED_TRACE("tick " + std::to_string(t));
    EXPECT_EQ(m->get("D10"), t + 1);
    for (int k = 0; k < 4; ++k)
      EXPECT_EQ(m->get("D" + std::to_string(k)), runsOfSlice(k, t, 4)) << "D" << k;
  }
}

// nvalue = 3: after 3 statements the position is inside a rung (the INC reads the LDT), so the
// slice extends to the next boundary: two rungs per slice, two slices.
TEST_P(SliceExec, SliceEndsAtNextRungBoundary) {
  auto m = load(kFourRungs, optionsWithNvalue(3));
  ASSERT_TRUE(m);
  EXPECT_EQ(m->engine().entries().plc2_slice_count, 2u);
  m->ticks(5);
  EXPECT_EQ(m->get("D0"), runsOfSlice(0, 4, 2));
  EXPECT_EQ(m->get("D1"), runsOfSlice(0, 4, 2));
  EXPECT_EQ(m->get("D2"), runsOfSlice(1, 4, 2));
  EXPECT_EQ(m->get("D3"), runsOfSlice(1, 4, 2));
  EXPECT_EQ(m->get("D10"), 5);
}

// nvalue = 0: no slicing, the whole PLC2 runs every tick.
TEST_P(SliceExec, NvalueZeroRunsWholePlc2) {
  auto m = load(kFourRungs, optionsWithNvalue(0));
  ASSERT_TRUE(m);
  EXPECT_EQ(m->engine().entries().plc2_slice_count, 1u);
  m->ticks(3);
  for (int k = 0; k < 4; ++k) EXPECT_EQ(m->get("D" + std::to_string(k)), 3);
}

// A PLC2 block sees PLC1's signals only when its slice runs: R0.0 toggles every tick in PLC1;
// the CTRC in slice 0 of 3 samples it on ticks 0, 3, 6, ... and counts the rising edges of
// those samples (expected value from a model of that sampling).
TEST_P(SliceExec, Plc2CounterSamplesOncePerCycle) {
  auto m = load("LDI R0.0\nOUT R0.0\n1END\n"
                "LD R0.0\nLD X0.0\nCTRC 2 1000\nOUT Y0.0\nLDT\nINC D2\nLDT\nINC D3\n2END\n",
                optionsWithNvalue(2));
  ASSERT_TRUE(m);
  ASSERT_EQ(m->engine().entries().plc2_slice_count, 3u);
  int64_t count = 0;
  bool prev = false;
  for (int64_t t = 0; t < 20; ++t) {
    m->tick();
    bool r00 = t % 2 == 0; // after PLC1 of tick t (R0.0 starts at 0 and flips every tick)
    EXPECT_EQ(m->get("R0.0"), r00);
    if (t % 3 == 0) {
      if (r00 && !prev) ++count;
      prev = r00;
    }
    EXPECT_EQ(m->get("C2"), count) << "tick " << t;
  }
  EXPECT_EQ(m->get("D2"), runsOfSlice(1, 19, 3));
  EXPECT_EQ(m->get("D3"), runsOfSlice(2, 19, 3));
}

// A slice that starts after a rung leaving a dead entry on ST still computes correctly, and a
// rung with MPS is never split (no boundary while MS is non-empty).
TEST_P(SliceExec, MpsRungIsNotSplit) {
  auto m = load("1END\nLD X0.0\nMPS\nAND X0.1\nOUT Y0.0\nMPP\nAND X0.2\nOUT Y0.1\n"
                "LD X0.3\nOUT Y0.2\n2END\n",
                optionsWithNvalue(1));
  ASSERT_TRUE(m);
  uint32_t n = m->engine().entries().plc2_slice_count;
  EXPECT_EQ(n, 2u);
  m->set("X0.0", 1);
  m->set("X0.2", 1);
  m->set("X0.3", 1);
  m->ticks(n);
  EXPECT_EQ(m->get("Y0.0"), 0);
  EXPECT_EQ(m->get("Y0.1"), 1);
  EXPECT_EQ(m->get("Y0.2"), 1);
}

} // namespace
} // namespace lj::test

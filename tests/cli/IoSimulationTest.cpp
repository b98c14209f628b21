// Unit tests of the simulation driver with a hand-written engine (plain C entry functions), so
// the order of power-up, init, stimulus, now_ms and watch rows is checked without any real
// engine (CLI.md `run` options; DIALECT.md 4 scan model; README "Simulation order").
#include "hosts/Simulation.h"

#include <gtest/gtest.h>

#include <memory>

namespace lj::hosts {
namespace {

// init records what it saw at power-up; PLC1 copies X0 to Y0, records now_ms and counts ticks,
// and reports a watchdog fault while X5 is nonzero; the PLC2 slice records its index.
uint32_t fakeInit(void *, lj_state *s) {
  s->img.D[10] = s->img.X[1]; // a --set input is visible to init
  s->img.D[11] = s->img.P[3]; // so is a parameter
  s->img.D[12] = static_cast<int32_t>(s->now_ms);
  return LJ_FAULT_NONE;
}
uint32_t fakePlc1(void *, lj_state *s) {
  s->img.Y[0] = s->img.X[0];
  s->img.D[1] = static_cast<int32_t>(s->now_ms);
  s->img.D[2]++;
  return s->img.X[5] ? LJ_FAULT_WATCHDOG : LJ_FAULT_NONE;
}
uint32_t fakeSlice(void *, lj_state *s, uint32_t k) {
  s->img.W[0] = static_cast<int16_t>(k);
  return LJ_FAULT_NONE;
}
const lj_entries kFake = {nullptr, fakeInit, fakePlc1, fakeSlice, 3};

formats::Assignment assign(const char *text) {
  std::string e;
  std::optional<formats::Assignment> a = formats::parseAssignment(text, e);
  EXPECT_TRUE(a) << e;
  return a.value_or(formats::Assignment{});
}

formats::CliAddress watchOf(const char *text) {
  std::string e;
  return formats::parseAddress(text, e).value();
}

TEST(Simulation, PowerUpOrderAndTicks) {
  SimOptions o;
  o.ticks = 6;
  o.periodMs = 10;
  o.params = {assign("P3=77"), assign("X1=5")}; // params first ...
  o.sets = {assign("X1=9")};                    // ... --set after them wins
  std::string e;
  o.stimulus =
      *formats::parseStimulus("@2 X0=1\n@2 X0=3\n@4 X0=0 X5=1\n@5 X5=0\n@9 X0=7\n", "t", e);
  o.watch = {watchOf("Y0"), watchOf("D1"), watchOf("D2"), watchOf("W0")};
  auto s = std::make_unique<lj_state>();
  std::vector<WatchRow> rows;
  SimResult r = simulate(kFake, *s, o, [&](const WatchRow &row) { rows.push_back(row); });

  EXPECT_EQ(r.initFault, LJ_FAULT_NONE);
  EXPECT_EQ(s->img.D[10], 9);  // init saw --set
  EXPECT_EQ(s->img.D[11], 77); // and the parameter
  EXPECT_EQ(s->img.D[12], 0);  // init runs at now_ms = 0
  ASSERT_EQ(rows.size(), 6u);
  // The slice each tick's W0 shows: slices in turn (abi.h lj_tick); tick 4's PLC1 fault skips
  // its slice and does not advance the index (docs/dialect-notes.md "Flow"), so W0 keeps 0
  // and tick 5 runs slice 1.
  const int64_t slice[6] = {0, 1, 2, 0, 0, 1};
  for (uint64_t t = 0; t < 6; ++t) {
    EXPECT_EQ(rows[t].tick, t);
    EXPECT_EQ(rows[t].values[1], static_cast<int64_t>(t * 10)) << "now_ms = tick * period";
    EXPECT_EQ(rows[t].values[2], static_cast<int64_t>(t + 1)) << "one PLC1 run per tick";
    EXPECT_EQ(rows[t].values[3], slice[t]) << "tick " << t;
  }
  // Stimulus before the scan of its tick; two events of one tick in file order (3 wins).
  EXPECT_EQ(rows[1].values[0], 0);
  EXPECT_EQ(rows[2].values[0], 3);
  EXPECT_EQ(rows[3].values[0], 3);
  EXPECT_EQ(rows[4].values[0], 0);
  // Tick 4 faulted (X5 = 1): reported, counted, and the run went on.
  EXPECT_EQ(rows[4].fault, static_cast<uint32_t>(LJ_FAULT_WATCHDOG));
  EXPECT_EQ(rows[5].fault, static_cast<uint32_t>(LJ_FAULT_NONE));
  EXPECT_EQ(r.faultTicks, 1u);
  EXPECT_EQ(s->fault_watchdog, 1u);
  EXPECT_EQ(s->now_ms, 50u);
}

TEST(Simulation, ZeroTicksRunsOnlyInit) {
  SimOptions o;
  o.ticks = 0;
  o.sets = {assign("X1=4")};
  o.maxBackwardSteps = 17;
  auto s = std::make_unique<lj_state>();
  int rows = 0;
  simulate(kFake, *s, o, [&](const WatchRow &) { ++rows; });
  EXPECT_EQ(rows, 0);
  EXPECT_EQ(s->img.D[10], 4);
  EXPECT_EQ(s->img.D[2], 0);
  EXPECT_EQ(s->max_backward_steps, 17u);
}

TEST(Simulation, StepwiseEqualsWhole) {
  SimOptions o;
  o.ticks = 3;
  o.watch = {watchOf("D2")};
  auto s = std::make_unique<lj_state>();
  Simulation sim(kFake, *s, o);
  EXPECT_EQ(sim.powerUp(), static_cast<uint32_t>(LJ_FAULT_NONE));
  WatchRow row;
  int n = 0;
  while (!sim.done()) {
    sim.step(row);
    EXPECT_EQ(row.values[0], ++n);
  }
  EXPECT_EQ(n, 3);
  EXPECT_STREQ(faultName(LJ_FAULT_WATCHDOG), "watchdog");
}

} // namespace
} // namespace lj::hosts

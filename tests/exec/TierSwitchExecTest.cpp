// Interpreter-first tiering (docs/serve.md "Tiering"): the engine of a running program switches
// at a tick boundary with the same lj_state, and the program cannot tell. Each test runs the
// reference's worked example with switches at chosen ticks (interp -> jit-opt, interp ->
// jit-fast -> jit-opt, jit-opt -> interp) and checks the values the manual and DIALECT.md give
// for an unswitched run: a running timer keeps timing, edge memories keep their last level, the
// PLC2 slice cycle goes on with its next slice, a counter keeps its count and input edge.
#include "engines/EngineSpec.h"
#include "tests/support/Machine.h"
#include "tests/support/TestAddress.h"
#include "verify/Verify.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

namespace lj::test {
namespace {

enum class Code { Interp, JitFast, JitOpt };

const char *codeName(Code c) {
  return c == Code::Interp ? "interp" : c == Code::JitFast ? "jit-fast" : "jit-opt";
}

/// One switch: from tick `tick` on, `code` runs.
struct Switch {
  uint32_t tick;
  Code code;
};

/// A schedule: init and the first ticks on `first`, then the switches.
struct Schedule {
  Code first;
  std::vector<Switch> switches;
  std::string describe() const {
    std::string s = std::string("init on ") + codeName(first);
    for (const Switch &w : switches)
      s += ", " + std::string(codeName(w.code)) + " from tick " + std::to_string(w.tick);
    return s;
  }
};

/// One program, one lj_state, three engines; tick t runs the code the schedule names for t.
class SwitchedRun {
public:
  bool load(std::string_view text, const VerifyOptions &opts, Schedule sched) {
    std::optional<VerifiedProgram> p = compileOrFail(text, opts);
    if (!p) return false;
    prog_ = std::make_unique<VerifiedProgram>(std::move(*p));
    for (Code c : {Code::Interp, Code::JitFast, Code::JitOpt}) {
      engines::EngineOptions eo;
      eo.fastTier = c == Code::JitFast;
      Result<std::unique_ptr<Engine>> e = engines::makeEngine(
          {c == Code::Interp ? engines::EngineKind::Interp : engines::EngineKind::Jit, {}}, *prog_,
          eo);
      if (!e) {
        ADD_FAILURE() << codeName(c) << ": " << e.status().message();
        return false;
      }
      engines_[static_cast<int>(c)] = std::move(e).value();
    }
    sched_ = std::move(sched);
    s_ = std::make_unique<lj_state>();
    lj_state_reset(s_.get());
    s_->now_ms = 0;
    EXPECT_EQ(lj_run_init(s_.get(), &entriesFor(UINT32_MAX)), uint32_t{LJ_FAULT_NONE});
    return true;
  }
  /// Tick `tick_` at now_ms = tick * period, on the code the schedule says.
  void tick() {
    s_->now_ms = uint64_t{tick_} * periodMs_;
    EXPECT_EQ(lj_tick(s_.get(), &entriesFor(tick_)), uint32_t{LJ_FAULT_NONE});
    ++tick_;
  }
  int64_t get(std::string_view a) const { return readAddr(*s_, parseTestAddr(a)); }
  void set(std::string_view a, int64_t v) { writeAddr(*s_, parseTestAddr(a), v); }
  const lj_state &state() const { return *s_; }
  uint32_t slices() const { return engines_[0]->entries().plc2_slice_count; }
  void setPeriodMs(uint32_t ms) { periodMs_ = ms; }

private:
  const lj_entries &entriesFor(uint32_t t) const {
    Code c = sched_.first;
    if (t != UINT32_MAX)
      for (const Switch &w : sched_.switches)
        if (w.tick <= t) c = w.code;
    return engines_[static_cast<int>(c)]->entries();
  }
  std::unique_ptr<VerifiedProgram> prog_;
  std::unique_ptr<Engine> engines_[3];
  Schedule sched_;
  std::unique_ptr<lj_state> s_;
  uint32_t tick_ = 0, periodMs_ = 1;
};

/// The schedules every test runs, all switching at tick `at` (and the second one a few ticks
/// later): tiering's two plans and the way back.
std::vector<Schedule> schedulesAt(uint32_t at) {
  return {
      {Code::Interp, {{at, Code::JitOpt}}},
      {Code::Interp, {{at, Code::JitFast}, {at + 3, Code::JitOpt}}},
      {Code::JitOpt, {{at, Code::Interp}}},
      {Code::JitFast, {{at, Code::Interp}, {at + 1, Code::JitOpt}}},
  };
}

// hnc8-functions-1.md 3.4 TMRB: X35.5=1 from t=0 -> Y4.2=0 up to t=99 and 1 at t>=100;
// T1 = min(elapsed, preset). The switch lands before, in the middle of and at the end of the
// timing: the timer's start time and running flag are lj_state, so timing goes on.
TEST(TierSwitchExec, RunningTimerKeepsTiming) {
  for (uint32_t at : {1u, 50u, 99u, 100u}) {
    for (const Schedule &sc : schedulesAt(at)) {
      SCOPED_TRACE(sc.describe());
      SwitchedRun r;
      ASSERT_TRUE(r.load("LD X35.5\nTMRB 1 0 100\nOUT Y4.2\nLD T1.0\nOUT Y5.0\n", {}, sc));
      r.set("X35.5", 1);
      for (int64_t t = 0; t <= 130; ++t) {
        r.tick();
        ASSERT_EQ(r.get("Y4.2"), t >= 100) << "t=" << t;
        ASSERT_EQ(r.get("Y5.0"), t >= 100) << "t=" << t;
        ASSERT_EQ(r.get("T1"), std::min<int64_t>(t, 100)) << "t=" << t;
      }
    }
  }
}

// DIALECT.md 3: each edge instance owns m, `rise = cur & !m`, `fall = !cur & m`, then m = cur.
// X1.0 is 1 on ticks 0..4 and 0 from tick 5: LDP gives 1 on tick 0 only, LDF on tick 5 only.
// A switch at tick 1 (m = 1 set by the other code: no second rise) or at tick 5 (the fall is
// seen against the m the other code left) must not add or lose an edge. ANDP and ORF likewise.
TEST(TierSwitchExec, EdgeMemoriesCarryOver) {
  const char *prog = "LDP X1.0\nOUT Y1.0\nLDF X1.0\nOUT Y1.1\n"
                     "LDT\nANDP X1.0\nOUT Y1.2\nLDI X2.0\nORF X1.0\nOUT Y1.3\n";
  for (uint32_t at : {1u, 5u}) {
    for (const Schedule &sc : schedulesAt(at)) {
      SCOPED_TRACE(sc.describe());
      SwitchedRun r;
      ASSERT_TRUE(r.load(prog, {}, sc));
      r.set("X2.0", 1); // LDI X2.0 = 0: Y1.3 is the ORF alone
      for (int64_t t = 0; t < 12; ++t) {
        r.set("X1.0", t < 5);
        r.tick();
        ASSERT_EQ(r.get("Y1.0"), t == 0) << "LDP, t=" << t;
        ASSERT_EQ(r.get("Y1.1"), t == 5) << "LDF, t=" << t;
        ASSERT_EQ(r.get("Y1.2"), t == 0) << "ANDP, t=" << t;
        ASSERT_EQ(r.get("Y1.3"), t == 5) << "ORF, t=" << t;
      }
    }
  }
}

// DIALECT.md 4: tick t runs slice t mod n. PLC1 increments D10 every tick; PLC2 is four rungs
// `LDT / INC Dk`, one slice each with nvalue 2 (tests/exec/SliceExecTest.cpp). A switch in the
// middle of the cycle (ticks 1, 2, 3, 6) continues with the next slice, not slice 0.
TEST(TierSwitchExec, Plc2SliceCycleContinues) {
  constexpr const char *kFourRungs = "LDT\nINC D10\n1END\n"
                                     "LDT\nINC D0\nLDT\nINC D1\nLDT\nINC D2\nLDT\nINC D3\n2END\n";
  auto runsOfSlice = [](int64_t k, int64_t t, int64_t n) { return t < k ? 0 : (t - k) / n + 1; };
  for (uint32_t at : {1u, 2u, 3u, 6u}) {
    for (const Schedule &sc : schedulesAt(at)) {
      SCOPED_TRACE(sc.describe());
      SwitchedRun r;
      ASSERT_TRUE(r.load(kFourRungs, optionsWithNvalue(2), sc));
      ASSERT_EQ(r.slices(), 4u);
      for (int64_t t = 0; t < 14; ++t) {
        ASSERT_EQ(r.state().plc2_next_slice, uint32_t(t % 4)) << "before tick " << t;
        r.tick();
        ASSERT_EQ(r.get("D10"), t + 1) << "t=" << t;
        for (int k = 0; k < 4; ++k)
          ASSERT_EQ(r.get("D" + std::to_string(k)), runsOfSlice(k, t, 4)) << "D" << k << " t=" << t;
      }
    }
  }
}

// hnc8-functions-1.md 3.3 CTRC: counts rising edges of input 1 (R0.0, toggled every tick by
// PLC1), sampled by the slice it sits in (slice 0 of 3: ticks 0, 3, 6, ...); the count and the
// last input level (lj_counter.prev) carry across a switch in the middle of the slice cycle.
TEST(TierSwitchExec, CounterInSliceKeepsCountAndEdge) {
  const char *prog = "LDI R0.0\nOUT R0.0\n1END\n"
                     "LD R0.0\nLD X0.0\nCTRC 2 1000\nOUT Y0.0\nLDT\nINC D2\nLDT\nINC D3\n2END\n";
  for (uint32_t at : {3u, 4u, 8u}) {
    for (const Schedule &sc : schedulesAt(at)) {
      SCOPED_TRACE(sc.describe());
      SwitchedRun r;
      ASSERT_TRUE(r.load(prog, optionsWithNvalue(2), sc));
      ASSERT_EQ(r.slices(), 3u);
      int64_t count = 0;
      bool prev = false;
      for (int64_t t = 0; t < 20; ++t) {
        r.tick();
        bool r00 = t % 2 == 0; // after PLC1 of tick t
        ASSERT_EQ(r.get("R0.0"), r00);
        if (t % 3 == 0) {
          if (r00 && !prev) ++count;
          prev = r00;
        }
        ASSERT_EQ(r.get("C2"), count) << "tick " << t;
      }
    }
  }
}

} // namespace
} // namespace lj::test

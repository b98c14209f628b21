// The differential harness itself, without the JIT: the interpreter against itself never
// mismatches, an engine with an injected bug is caught and minimized to a tiny replayable case,
// and a differing field is named the way the CLI names addresses.
#include "frontends/hnc8/FrontEnd.h"
#include "fuzz/Differential.h"
#include "fuzz/Fuzz.h"

#include <gtest/gtest.h>

#include <sstream>

namespace lj::fuzz {
namespace {

EngineFactory interpreterFactory() {
  return [](const VerifiedProgram &p, bool, std::string &) { return makeInterpreterEngine(p); };
}

/// The interpreter plus one deliberate bug: after PLC1, whenever bit 0 of one of R0..R15 is on,
/// G3119.0 flips (random programs write these relays often).
class BuggyEngine final : public Engine {
public:
  explicit BuggyEngine(const VerifiedProgram &p) : inner_(makeInterpreterEngine(p)) {
    entries_ = inner_->entries();
    entries_.ctx = this;
    entries_.plc1 = &BuggyEngine::plc1;
    entries_.init = [](void *ctx, lj_state *s) {
      const lj_entries &in = static_cast<BuggyEngine *>(ctx)->inner_->entries();
      return in.init(in.ctx, s);
    };
    entries_.plc2_slice = [](void *ctx, lj_state *s, uint32_t k) {
      const lj_entries &in = static_cast<BuggyEngine *>(ctx)->inner_->entries();
      return in.plc2_slice(in.ctx, s, k);
    };
  }
  const lj_entries &entries() const override { return entries_; }
  const char *name() const override { return "buggy"; }

private:
  static uint32_t plc1(void *ctx, lj_state *s) {
    const lj_entries &in = static_cast<BuggyEngine *>(ctx)->inner_->entries();
    uint32_t f = in.plc1(in.ctx, s);
    bool odd = false;
    for (int i = 0; i < 16; ++i) odd = odd || (s->img.R[i] & 1);
    if (odd) s->img.G[3119] ^= 1;
    return f;
  }
  std::unique_ptr<Engine> inner_;
  lj_entries entries_{};
};

/// The interpreter, except that it keeps the PLC2 slice position to itself (its own counter
/// instead of the index lj_tick passes from lj_state.plc2_next_slice): right when it runs every
/// tick from power-up, wrong when it takes over a running state. An engine switch (tiering)
/// must catch exactly this kind of private state.
class PrivateSliceEngine final : public Engine {
public:
  explicit PrivateSliceEngine(const VerifiedProgram &p) : inner_(makeInterpreterEngine(p)) {
    entries_ = inner_->entries();
    entries_.ctx = this;
    entries_.init = [](void *ctx, lj_state *s) {
      const lj_entries &in = static_cast<PrivateSliceEngine *>(ctx)->inner_->entries();
      return in.init(in.ctx, s);
    };
    entries_.plc1 = [](void *ctx, lj_state *s) {
      const lj_entries &in = static_cast<PrivateSliceEngine *>(ctx)->inner_->entries();
      return in.plc1(in.ctx, s);
    };
    entries_.plc2_slice = [](void *ctx, lj_state *s, uint32_t) {
      auto *self = static_cast<PrivateSliceEngine *>(ctx);
      const lj_entries &in = self->inner_->entries();
      uint32_t k = self->next_;
      self->next_ = (k + 1) % in.plc2_slice_count;
      return in.plc2_slice(in.ctx, s, k);
    };
  }
  const lj_entries &entries() const override { return entries_; }
  const char *name() const override { return "private-slice"; }

private:
  std::unique_ptr<Engine> inner_;
  lj_entries entries_{};
  uint32_t next_ = 0;
};

TEST(Harness, SwitchModeCatchesAnEngineWithPrivateState) {
  EngineFactory privateSlice = [](const VerifiedProgram &p, bool, std::string &) {
    return std::unique_ptr<Engine>(new PrivateSliceEngine(p));
  };
  FuzzOptions o;
  o.seed = 9;
  o.programs = 150;
  o.ticks = 20;
  o.minimize = false;
  std::ostringstream plain, switched;
  // Run from power-up on every tick, the private counter stays in step with lj_state.
  FuzzStats st = runWith(o, plain, privateSlice);
  EXPECT_EQ(st.failures(), 0u) << plain.str();
  ASSERT_GT(st.multiSlice, 0u) << "no program had more than one PLC2 slice";
  // Taking over a running state (or handing it back), it runs the wrong slice.
  o.switches = true;
  st = runWith(o, switched, privateSlice);
  EXPECT_GT(st.mismatches, 0u) << switched.str();
  EXPECT_GT(st.interpToJit, 0u);
  EXPECT_GT(st.jitToInterp, 0u);
  EXPECT_GT(st.fastToOpt, 0u);
  EXPECT_NE(switched.str().find("engine switches: init on"), std::string::npos) << switched.str();
}

TEST(Harness, SwitchModeInterpreterAgainstItselfNeverMismatches) {
  FuzzOptions o;
  o.seed = 21;
  o.programs = 200;
  o.ticks = 20;
  o.switches = true;
  std::ostringstream out;
  FuzzStats st = runWith(o, out, interpreterFactory());
  EXPECT_EQ(st.failures(), 0u) << out.str();
  EXPECT_GT(st.interpToJit + st.jitToInterp, 0u);
}

TEST(Harness, InterpreterAgainstItselfNeverMismatches) {
  FuzzOptions o;
  o.seed = 5;
  o.programs = 300;
  o.ticks = 25;
  std::ostringstream out;
  FuzzStats st = runWith(o, out, interpreterFactory());
  EXPECT_EQ(st.failures(), 0u) << out.str();
  EXPECT_EQ(st.programs, 300u);
  EXPECT_GT(st.statements, 0u);
  EXPECT_GT(st.watchdogTicks, 0u) << "no generated program ever reached the watchdog";
  EXPECT_NE(out.str().find("PASS"), std::string::npos);
}

TEST(Harness, SameSeedSameCampaign) {
  FuzzOptions o;
  o.seed = 11;
  o.programs = 40;
  o.ticks = 10;
  std::ostringstream a, b;
  FuzzStats sa = runWith(o, a, interpreterFactory());
  FuzzStats sb = runWith(o, b, interpreterFactory());
  EXPECT_EQ(sa.statements, sb.statements);
  EXPECT_EQ(sa.watchdogTicks, sb.watchdogTicks);
  EXPECT_EQ(sa.fastPrograms, sb.fastPrograms);
}

TEST(Harness, InjectedBugIsFoundAndMinimized) {
  FuzzOptions o;
  o.seed = 3;
  o.programs = 100;
  o.ticks = 20;
  o.maxReports = 1;
  std::ostringstream out;
  EngineFactory buggy = [](const VerifiedProgram &p, bool, std::string &) {
    return std::unique_ptr<Engine>(new BuggyEngine(p));
  };
  FuzzStats st = runWith(o, out, buggy);
  const std::string text = out.str();
  ASSERT_GT(st.mismatches, 0u) << text;
  EXPECT_NE(text.find("first difference: G3119: interp="), std::string::npos) << text;
  // The smallest program that turns such a bit on is a push and a coil (plus markers it may
  // need), a single move, or a block with its power-flow inputs (ROT: five pushes + the block).
  size_t p = text.find("--- program (");
  ASSERT_NE(p, std::string::npos);
  int lines = std::stoi(text.substr(p + 13));
  EXPECT_LE(lines, 6) << text;
  EXPECT_NE(text.find("FAIL"), std::string::npos);
}

TEST(Harness, MinimizedCaseStillFails) {
  Case c;
  c.lines = {"LD X1.0", "AND X1.1", "OUT R3.0", "IEND", "LD X2.0",  "OUT R5.0",
             "LDT",     "INC D1",   "1END",     "LDT",  "MOV 5 W3", "2END"};
  c.stim.nowMs = {1, 2, 3, 4, 5};
  c.stim.writes = {{}, {}, {{Area::Input, 2, -1, 1}}, {}, {}};
  EngineFactory buggy = [](const VerifiedProgram &p, bool, std::string &) {
    return std::unique_ptr<Engine>(new BuggyEngine(p));
  };
  Outcome before = runCase(c, buggy);
  ASSERT_EQ(before.kind, Outcome::Kind::Mismatch);
  EXPECT_EQ(before.tick, 2u); // X2.0 arrives before tick 2's scan
  Case m = minimize(c, Outcome::Kind::Mismatch, buggy, 500);
  Outcome after = runCase(m, buggy);
  EXPECT_EQ(after.kind, Outcome::Kind::Mismatch);
  EXPECT_LT(m.lines.size(), c.lines.size());
  EXPECT_LE(m.stim.ticks(), 3u);
}

TEST(Harness, FirstDifferenceNamesTheField) {
  auto a = std::make_unique<lj_state>(), b = std::make_unique<lj_state>();
  lj_state_reset(a.get());
  lj_state_reset(b.get());
  EXPECT_EQ(firstDifference(*a, *b, "jit"), "");
  b->T[lj_tc_slot(301)].out = 1;
  b->edge[9] = 1;
  EXPECT_EQ(firstDifference(*a, *b, "jit"), "T301.0 (out): interp=0 jit=1");
  b->img.D[5] = -4;
  EXPECT_EQ(firstDifference(*a, *b, "jit"), "D5: interp=0 jit=-4");
  lj_state_reset(b.get());
  b->edge[9] = 1;
  EXPECT_EQ(firstDifference(*a, *b, "jit"), "edge[9]: interp=0 jit=1");
}

} // namespace
} // namespace lj::fuzz

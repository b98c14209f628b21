// Whole-state differential runs: mixed programs and scenarios run in lock-step on every
// registered engine (complete lj_state compared after every tick), with expected values checked
// on the reference; plus tests of the comparison helper itself.
#include "tests/exec/ExecTest.h"
#include "tests/support/StateDiff.h"
#include "verify/Verify.h"

#include <cstring>

namespace lj::test {
namespace {

// A program touching every state kind: edges, counters, timers, PLS/PLF/ALT, math with faults,
// subroutine, loop and PLC2 slices.
constexpr const char *kMixed = R"(
LDT
MOV 3 D20
IEND
LDP X0.0
ORF X0.1
OUT Y0.0
LD X0.0
LD X0.2
LDI X0.3
LD X0.4
CTUD 7 5
OUT Y0.1
LD X0.0
TMRB 3 0 4
OUT Y0.2
LD X0.1
STMR 300 0 3
OUT Y0.3
LD X0.0
PLS 9
OUT Y1.0
LD X0.0
PLF 9
OUT Y1.1
LD X0.1
ALT 9
OUT Y1.2
LD X0.2
DIV D20 W1 D21
OUT Y1.3
LD X0.3
CALL S4
1END
LOOP D20
LDT
ADD D22 1000000000 D22
NEXT
LD X0.0
LDT
LDI X0.1
LD X0.3
CTR W9 2
OUT Y2.0
LDT
MUL D22 7 B3
2END
SP S4
LD X0.4
INC R7
LDT
NEG G11
SPE
)";

Scenario mixedScenario() {
  Scenario sc;
  sc.ticks = 40;
  sc.periodMs = 1;
  for (uint32_t t = 0; t < sc.ticks; ++t) {
    sc.at(t, "X0.0", (t / 3) % 2);
    sc.at(t, "X0.1", (t / 5) % 2);
    sc.at(t, "X0.2", (t / 7) % 2);
    sc.at(t, "X0.3", (t % 4) == 1);
    sc.at(t, "X0.4", (t / 11) % 2);
  }
  sc.at(20, "W1", 2); // divisions by zero before tick 20, by 2 afterwards
  return sc;
}

TEST(CrossEngine, MixedProgramSameStateEverywhere) {
  int64_t divzeroTicks = 0;
  auto check = [&](int64_t t, const Machine &ref, uint32_t fault) {
    EXPECT_EQ(fault, uint32_t{LJ_FAULT_NONE});
    if (t < 0) {
      EXPECT_EQ(ref.get("D20"), 3); // init ran
      return;
    }
    // DIV with X0.2 = 1 and W1 = 0 counts a fault (dialect-notes); X0.2 = (t / 7) % 2.
    if ((t / 7) % 2 && t < 20) ++divzeroTicks;
    EXPECT_EQ(int64_t(ref.state().fault_divzero), divzeroTicks) << "tick " << t;
    EXPECT_EQ(ref.get("Y1.3"), (t / 7) % 2 && t >= 20) << "tick " << t;
  };
  EXPECT_TRUE(sameStateOnAllEngines(kMixed, mixedScenario(), optionsWithNvalue(3), check));
}

// The LDP table of hnc8-core.md 4.8 as a scenario, checked per tick on the reference.
TEST(CrossEngine, LdpTableScenario) {
  Scenario sc;
  sc.ticks = 5;
  const int r10[] = {0, 1, 1, 1, 1}, x50[] = {0, 0, 0, 1, 0}, r20[] = {0, 1, 1, 0, 1},
            r40[] = {1, 0, 0, 1, 0}, out[] = {0, 1, 0, 0, 1};
  for (uint32_t t = 0; t < 5; ++t) {
    sc.at(t, "R1.0", r10[t]).at(t, "X5.0", x50[t]).at(t, "R2.0", r20[t]).at(t, "R4.0", r40[t]);
  }
  auto check = [&](int64_t t, const Machine &ref, uint32_t) {
    if (t >= 0) {
      EXPECT_EQ(ref.get("R10.1"), out[t]) << "scan " << t;
    }
  };
  EXPECT_TRUE(sameStateOnAllEngines("LDP R1.0\nORF X5.0\nANDP R2.0\nANDF R4.0\nOUT R10.1\n", sc,
                                    VerifyOptions{}, check));
}

// Watchdog aborts compared across engines: same fault code and same partial state.
TEST(CrossEngine, WatchdogScenario) {
  Scenario sc;
  sc.ticks = 4;
  sc.maxBackwardSteps = 7;
  sc.at(2, "X0.0", 1);
  auto check = [&](int64_t t, const Machine &ref, uint32_t fault) {
    if (t < 0) return;
    EXPECT_EQ(ref.get("D1"), t < 2 ? t + 1 : 2); // PLC2 is skipped after an aborted PLC1
    EXPECT_EQ(fault, t >= 2 ? uint32_t{LJ_FAULT_WATCHDOG} : uint32_t{LJ_FAULT_NONE});
  };
  EXPECT_TRUE(sameStateOnAllEngines("LBL L1\nLDT\nINC D0\nLD X0.0\nJMP L1\n1END\nLDT\nINC D1\n", sc,
                                    VerifyOptions{}, check));
}

// The comparison helper names fields precisely (it is what a JIT mismatch report shows).
TEST(StateDiffTest, NamesFirstDifferingField) {
  auto a = std::make_unique<lj_state>(), b = std::make_unique<lj_state>();
  lj_state_reset(a.get());
  lj_state_reset(b.get());
  EXPECT_FALSE(firstDifference(*a, *b).has_value());
  EXPECT_EQ(describeDifference(*a, *b, "x", "y"), "");
  b->img.W[7] = 0x100;
  b->T[130].elapsed_ms = 5;
  std::optional<size_t> off = firstDifference(*a, *b);
  ASSERT_TRUE(off.has_value());
  EXPECT_EQ(*off, offsetof(lj_state, img.W) + 7 * 2 + 1);
  EXPECT_EQ(fieldAt(*off), "img.W[7] (byte 1)");
  EXPECT_EQ(fieldAt(offsetof(lj_state, T) + 130 * sizeof(lj_timer) + 8), "T[130].elapsed_ms");
  EXPECT_EQ(fieldAt(offsetof(lj_state, C) + 3 * sizeof(lj_counter) + 5), "C[3].prev");
  EXPECT_EQ(fieldAt(offsetof(lj_state, edge) + 17), "edge[17]");
  EXPECT_EQ(fieldAt(offsetof(lj_state, fault_divzero)), "fault_divzero");
  std::string d = describeDifference(*a, *b, "interp", "jit");
  EXPECT_NE(d.find("img.W[7]"), std::string::npos) << d;
  EXPECT_NE(d.find("2 differing bytes"), std::string::npos) << d;
}

/// A deliberately wrong engine: the interpreter, plus a flipped Y3.2 after every PLC1 run.
class FlippingEngine final : public Engine {
public:
  explicit FlippingEngine(const VerifiedProgram &p) : inner_(makeInterpreterEngine(p)) {
    entries_ = inner_->entries();
    entries_.ctx = this;
    entries_.init = [](void *ctx, lj_state *s) {
      const lj_entries &in = static_cast<FlippingEngine *>(ctx)->inner_->entries();
      return in.init(in.ctx, s);
    };
    entries_.plc1 = [](void *ctx, lj_state *s) {
      const lj_entries &in = static_cast<FlippingEngine *>(ctx)->inner_->entries();
      uint32_t f = in.plc1(in.ctx, s);
      s->img.Y[3] ^= 4;
      return f;
    };
    entries_.plc2_slice = [](void *ctx, lj_state *s, uint32_t k) {
      const lj_entries &in = static_cast<FlippingEngine *>(ctx)->inner_->entries();
      return in.plc2_slice(in.ctx, s, k);
    };
  }
  const lj_entries &entries() const override { return entries_; }
  const char *name() const override { return "flipping"; }

private:
  std::unique_ptr<Engine> inner_;
  lj_entries entries_{};
};

// The lock-step runner must catch a differing engine and name the step and the field.
TEST(StateDiffTest, LockstepDetectsWrongEngine) {
  std::optional<VerifiedProgram> prog = compileOrFail("LDT\nOUT Y0.0\n");
  ASSERT_TRUE(prog);
  std::vector<EngineFactory> engines = {
      registeredEngines()[0],
      {"flipping", [](const VerifiedProgram &p, std::string &) -> std::unique_ptr<Engine> {
         return std::make_unique<FlippingEngine>(p);
       }}};
  Scenario sc;
  sc.ticks = 3;
  ::testing::AssertionResult r = sameStateOnEngines(engines, *prog, sc);
  ASSERT_FALSE(r);
  std::string msg = r.message();
  EXPECT_NE(msg.find("after tick 0"), std::string::npos) << msg;
  EXPECT_NE(msg.find("img.Y[3]"), std::string::npos) << msg;
  // Against itself the reference agrees.
  EXPECT_TRUE(sameStateOnEngines({registeredEngines()[0], registeredEngines()[0]}, *prog, sc));
}

} // namespace
} // namespace lj::test

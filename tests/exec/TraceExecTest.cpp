// The power-flow trace of a traced build (ir/Trace.h, docs/ladder-view.md "Live view"): the
// words the rules of ir/Trace.h give for a small program, tick by tick, on the interpreter and
// the JIT, and the two traces byte-identical. Expected values come from DIALECT.md 3: a contact
// records what it conducts (LDI of a 0 conducts), an edge contact its own pulse (1 only on the
// tick the bit rises, though the bit stays 1), a coil its ST0, CMP (out := EN and a <= b) its
// EN, output and operand values.
#include "engines/EngineSpec.h"
#include "ir/Trace.h"
#include "tests/support/Machine.h"

#include <gtest/gtest.h>

namespace lj::test {
namespace {

constexpr const char *kProgram = "LD X0.0\n"  // 0: contact
                                 "ANI X0.1\n" // 1: contact NC
                                 "OUT Y0.0\n" // 2: coil
                                 "LDP X0.2\n" // 3: edge contact
                                 "OUT Y0.1\n" // 4: coil
                                 "LD X0.3\n"  // 5: contact
                                 "CMP D0 7\n" // 6: box: EN, out, D0, 7
                                 "OUT Y0.2\n" // 7: coil
                                 "1END\n"
                                 "2END\n";

struct Traced {
  std::unique_ptr<Engine> engine;
  std::vector<int32_t> words;
  std::unique_ptr<lj_state> s = std::make_unique<lj_state>();
};

Traced build(const char *name, const VerifiedProgram &prog, int32_t words) {
  Traced t;
  t.words.assign(static_cast<size_t>(words), -1); // -1: shows a word nobody wrote
  engines::EngineOptions o;
  o.trace = t.words.data();
  Result<engines::EngineSpec> spec = engines::parseEngineSpec(name);
  EXPECT_TRUE(spec);
  Result<std::unique_ptr<Engine>> e = engines::makeEngine(*spec, prog, o);
  EXPECT_TRUE(e) << (e ? "" : e.status().message());
  if (e) t.engine = std::move(e).value();
  lj_state_reset(t.s.get());
  return t;
}

void setBit(lj_state &s, int byte, int bit, bool v) {
  uint8_t &b = s.img.X[byte];
  b = static_cast<uint8_t>(v ? (b | (1u << bit)) : (b & ~(1u << bit)));
}

TEST(TraceExec, WordsFollowTheRulesAndEnginesAgree) {
  std::optional<VerifiedProgram> prog = compileOrFail(kProgram);
  ASSERT_TRUE(prog);
  const TraceLayout tl = traceLayout(*prog);
  // Layout: 1 word per contact and coil, CMP 2 + its two operands.
  ASSERT_EQ(tl.words, 1 + 1 + 1 + 1 + 1 + 1 + 4 + 1);
  EXPECT_EQ(tl.kind[6], TraceKind::Box);
  Traced a = build("interp", *prog, tl.words), b = build("jit", *prog, tl.words);
  ASSERT_TRUE(a.engine && b.engine);
  struct Tick {
    bool x0, x1, x2, x3;
    int32_t d0;
    std::vector<int32_t> want;
  };
  // at: 0 LD, 1 ANI, 2 OUT, 3 LDP, 4 OUT, 5 LD, 6..9 CMP (EN, out, D0, 7), 10 OUT
  const std::vector<Tick> ticks = {
      {true, false, true, true, 3, {1, 1, 1, 1, 1, 1, 1, 1, 3, 7, 1}},
      // X0.2 stays 1: the edge contact records 0 (its own result, not the operand's level);
      // X0.0 = 0: ANI still records what it conducts (X0.1 = 0 -> 1), the coil 0.
      {false, false, true, true, 9, {0, 1, 0, 0, 0, 1, 1, 0, 9, 7, 0}},
      {true, true, false, false, 7, {1, 0, 0, 0, 0, 0, 0, 0, 7, 7, 0}},
  };
  for (Traced *t : {&a, &b}) ASSERT_EQ(lj_run_init(t->s.get(), &t->engine->entries()), 0u);
  for (size_t k = 0; k < ticks.size(); ++k) {
    for (Traced *t : {&a, &b}) {
      setBit(*t->s, 0, 0, ticks[k].x0);
      setBit(*t->s, 0, 1, ticks[k].x1);
      setBit(*t->s, 0, 2, ticks[k].x2);
      setBit(*t->s, 0, 3, ticks[k].x3);
      t->s->img.D[0] = ticks[k].d0;
      ASSERT_EQ(lj_tick(t->s.get(), &t->engine->entries()), 0u);
    }
    EXPECT_EQ(a.words, ticks[k].want) << "interp, tick " << k;
    EXPECT_EQ(b.words, a.words) << "jit differs from interp, tick " << k;
  }
}

TEST(TraceExec, AotIsNeverTraced) {
  std::optional<VerifiedProgram> prog = compileOrFail(kProgram);
  ASSERT_TRUE(prog);
  std::vector<int32_t> w(16);
  engines::EngineOptions o;
  o.trace = w.data();
  Result<std::unique_ptr<Engine>> e =
      engines::makeEngine({engines::EngineKind::Aot, "x.so"}, *prog, o);
  ASSERT_FALSE(e);
  EXPECT_NE(e.status().message().find("never traced"), std::string::npos);
}

} // namespace
} // namespace lj::test

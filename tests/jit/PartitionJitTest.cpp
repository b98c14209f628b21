// Parallel compilation (JitOptions::compileThreads): a program lowered into several modules,
// compiled on several threads and linked into one JITDylib must behave exactly like the
// interpreter (full-state equality after init and every tick), on both tiers, whatever the
// number of partitions and wherever the cross-module calls (slices, subroutines) fall.
#include "lowering/Lower.h"
#include "tests/jit/JitHarness.h"
#include "tests/jit/RandomPrograms.h"

namespace lj::test {
namespace {

struct PartitionCase {
  uint64_t seed;
  jit::Tier tier;
};

class PartitionJit : public ::testing::TestWithParam<PartitionCase> {};

// Lock-step run of the interpreter and a JIT built with `opts` (the harness builds its JIT with
// default options, which do not partition programs this small).
::testing::AssertionResult matches(const VerifiedProgram &prog, const jit::JitOptions &opts,
                                   uint64_t seed) {
  std::string error;
  std::unique_ptr<Engine> ref = makeInterpreterEngine(prog);
  std::unique_ptr<Engine> jit = jit::compile(prog, opts, error);
  if (!jit) return ::testing::AssertionFailure() << "JIT compile failed: " << error;
  auto a = std::make_unique<lj_state>(), b = std::make_unique<lj_state>();
  lj_state_reset(a.get());
  lj_state_reset(b.get());
  a->max_backward_steps = b->max_backward_steps = 3000;
  uint32_t fa = lj_run_init(a.get(), &ref->entries());
  uint32_t fb = lj_run_init(b.get(), &jit->entries());
  if (fa != fb) return ::testing::AssertionFailure() << "init fault " << fa << " vs " << fb;
  if (auto r = sameState(*a, *b); !r) return r << " after init";
  for (uint32_t t = 0; t < 30; ++t) {
    a->now_ms = b->now_ms = t * (1 + seed % 23);
    randomInputs(seed, t, *a);
    randomInputs(seed, t, *b);
    fa = lj_tick(a.get(), &ref->entries());
    fb = lj_tick(b.get(), &jit->entries());
    if (fa != fb)
      return ::testing::AssertionFailure() << "tick " << t << " fault " << fa << " vs " << fb;
    if (auto r = sameState(*a, *b); !r) return r << " after tick " << t;
  }
  return ::testing::AssertionSuccess();
}

TEST_P(PartitionJit, PartitionedProgramMatchesInterpreter) {
  const PartitionCase c = GetParam();
  static const int32_t kNvalues[] = {0, 7, 30, 200};
  std::string text = randomProgram(c.seed, 60);
  auto prog = verifyOrFail(text, kNvalues[c.seed % 4]);
  ASSERT_TRUE(prog) << text;
  for (int32_t threads : {2, 3, 5}) {
    jit::JitOptions o;
    o.tier = c.tier;
    o.compileThreads = threads;
    o.minStatementsPerThread = 1; // partition even this small program
    o.chunkStatements = c.seed % 2 ? 150 : 8;
    ::testing::AssertionResult same = matches(*prog, o, c.seed);
    EXPECT_TRUE(same) << "seed " << c.seed << ", " << threads << " threads\n" << text;
    if (!same) break;
  }
}

std::vector<PartitionCase> cases() {
  std::vector<PartitionCase> v;
  for (uint64_t seed = 101; seed <= 112; ++seed) {
    v.push_back({seed, jit::Tier::Fast});
    v.push_back({seed, jit::Tier::Optimizing});
  }
  return v;
}

INSTANTIATE_TEST_SUITE_P(Seeds, PartitionJit, ::testing::ValuesIn(cases()),
                         [](const ::testing::TestParamInfo<PartitionCase> &i) {
                           return std::string(i.param.tier == jit::Tier::Fast ? "Fast" : "Opt") +
                                  "_" + std::to_string(i.param.seed);
                         });

// The partition plan: contiguous, starting at 0, every partition used when there are enough
// bodies, and a single partition when asked for one.
TEST(PartitionPlan, ContiguousAndBalanced) {
  auto prog = verifyOrFail(randomProgram(7, 80), 20);
  ASSERT_TRUE(prog);
  std::vector<uint32_t> one = lower::planPartitions(*prog, 1);
  for (uint32_t p : one) EXPECT_EQ(p, 0u);
  std::vector<uint32_t> two = lower::planPartitions(*prog, 2);
  ASSERT_FALSE(two.empty());
  EXPECT_EQ(two.front(), 0u);
  EXPECT_EQ(two.back(), 1u);
  for (size_t k = 1; k < two.size(); ++k) EXPECT_LE(two[k - 1], two[k]);
}

} // namespace
} // namespace lj::test

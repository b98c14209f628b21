// Parallel compilation (JitOptions::compileThreads): a program lowered into several modules,
// compiled on several threads and linked into one JITDylib must behave exactly like the
// interpreter (full-state equality after init and every tick), on both tiers, whatever the
// number of partitions and wherever the cross-module calls (slices, subroutines) fall.
#include "lowering/Lower.h"
#include "tests/jit/JitHarness.h"

namespace lj::test {
namespace {

struct PartitionCase {
  uint64_t seed;
  jit::Tier tier;
};

class PartitionJit : public ::testing::TestWithParam<PartitionCase> {};

TEST_P(PartitionJit, PartitionedProgramMatchesInterpreter) {
  const PartitionCase c = GetParam();
  std::string text;
  auto prog = randomProgramOrFail(c.seed, 1500, &text);
  ASSERT_TRUE(prog) << text;
  Scenario sc = randomScenario(c.seed, 30, static_cast<uint32_t>(1 + c.seed % 23), 3000);
  for (int32_t threads : {2, 3, 5}) {
    jit::JitOptions o;
    o.tier = c.tier;
    o.compileThreads = threads;
    o.minStatementsPerThread = 1; // partition even a small program
    o.chunkStatements = c.seed % 2 ? 150 : 8;
    ::testing::AssertionResult same = jitMatchesInterpreter(*prog, o, sc);
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
  auto prog = randomProgramOrFail(7, 2000, nullptr, 20);
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

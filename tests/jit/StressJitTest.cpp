// Random programs using every instruction (RandomPrograms.h), both tiers, with and without
// cutting bodies into small functions: the JIT's state must equal the interpreter's after init
// and after every tick, whatever the inputs, faults and slice plan.
#include "tests/jit/JitHarness.h"
#include "tests/jit/RandomPrograms.h"

namespace lj::test {
namespace {

struct StressCase {
  uint64_t seed;
  jit::Tier tier;
};

class StressJit : public ::testing::TestWithParam<StressCase> {};

TEST_P(StressJit, RandomProgramMatchesInterpreter) {
  const StressCase c = GetParam();
  static const int32_t kNvalues[] = {0, 5, 20, 200};
  std::string text = randomProgram(c.seed, 25);
  auto prog = verifyOrFail(text, kNvalues[c.seed % 4]);
  ASSERT_TRUE(prog) << text;
  Drive d;
  d.ticks = 40;
  d.periodMs = 1 + c.seed % 37;
  d.maxSteps = 3000;
  d.before = [seed = c.seed](lj_state &s) {
    Rng r(seed);
    for (int i = 0; i < 4; ++i) s.img.P[i] = static_cast<int32_t>(r.next());
    for (int i = 0; i < 10; ++i) s.img.B[i] = static_cast<int32_t>(r.below(20)) - 5;
  };
  d.inputs = [seed = c.seed](uint32_t t, lj_state &s) { randomInputs(seed, t, s); };
  for (int32_t chunk : {150, 4}) {
    ::testing::AssertionResult same = jitMatchesInterpreter(*prog, c.tier, d, {}, chunk);
    EXPECT_TRUE(same) << "seed " << c.seed << ", chunkStatements " << chunk << "\n" << text;
    if (!same) break;
  }
}

std::vector<StressCase> cases() {
  std::vector<StressCase> v;
  for (uint64_t seed = 1; seed <= 24; ++seed) {
    v.push_back({seed, jit::Tier::Fast});
    v.push_back({seed, jit::Tier::Optimizing});
  }
  return v;
}

INSTANTIATE_TEST_SUITE_P(Seeds, StressJit, ::testing::ValuesIn(cases()),
                         [](const ::testing::TestParamInfo<StressCase> &i) {
                           return std::string(i.param.tier == jit::Tier::Fast ? "Fast" : "Opt") +
                                  "_" + std::to_string(i.param.seed);
                         });

} // namespace
} // namespace lj::test

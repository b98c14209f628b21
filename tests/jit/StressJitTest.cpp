// The differential fuzzer's random programs (gen/ProgramGenerator.h: every instruction of the
// table) on both tiers, with and without cutting bodies into small functions: the JIT's state
// must equal the interpreter's after init and after every tick, whatever the inputs, faults and
// slice plan. Also checks that the seeds used here and in PartitionJitTest cover every row.
#include "frontends/hnc8/Mnemonics.h"
#include "ir/OpTable.h"
#include "tests/jit/JitHarness.h"

#include <algorithm>
#include <set>

namespace lj::test {
namespace {

// About the size the suite's programs always had (~700 statements), so chunking and slicing
// have plenty of cut points.
constexpr int32_t kStressStatements = 700;
constexpr uint64_t kFirstSeed = 1, kLastSeed = 24;

struct StressCase {
  uint64_t seed;
  jit::Tier tier;
};

class StressJit : public ::testing::TestWithParam<StressCase> {};

TEST_P(StressJit, RandomProgramMatchesInterpreter) {
  const StressCase c = GetParam();
  std::string text;
  auto prog = randomProgramOrFail(c.seed, kStressStatements, &text);
  ASSERT_TRUE(prog) << text;
  Scenario sc = randomScenario(c.seed, 40, static_cast<uint32_t>(1 + c.seed % 37), 3000);
  for (int32_t chunk : {150, 4}) {
    ::testing::AssertionResult same = jitMatchesInterpreter(*prog, c.tier, sc, {}, chunk);
    EXPECT_TRUE(same) << "seed " << c.seed << ", chunkStatements " << chunk << "\n" << text;
    if (!same) break;
  }
}

std::vector<StressCase> cases() {
  std::vector<StressCase> v;
  for (uint64_t seed = kFirstSeed; seed <= kLastSeed; ++seed) {
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

// The programs StressJit runs (and PartitionJit's, seeds 101..112 at 1,500 statements) use every
// row of the instruction table and the structures the lowering must get right: deep ST and MS
// nesting, nested loops, subroutine calls, RETN, backward jumps and several PLC2 slices.
TEST(StressJitPrograms, CoverEveryRowAndStructure) {
  std::set<Op> seen;
  int32_t maxDepth = 0, maxMs = 0, maxLoopNest = 0;
  size_t maxSlices = 0, maxSubs = 0;
  auto scan = [&](uint64_t seed, int32_t statements) {
    auto prog = randomProgramOrFail(seed, statements);
    ASSERT_TRUE(prog);
    int32_t loops = 0;
    for (size_t i = 0; i < prog->stmts.size(); ++i) {
      const Op op = prog->stmts[i].op;
      seen.insert(op);
      maxDepth = std::max(maxDepth, prog->info[i].depth);
      maxMs = std::max(maxMs, prog->info[i].msDepth);
      loops += op == Op::LoopBegin ? 1 : op == Op::LoopEnd ? -1 : 0;
      maxLoopNest = std::max(maxLoopNest, loops);
    }
    maxSlices = std::max(maxSlices, prog->slices.size());
    maxSubs = std::max(maxSubs, prog->subs.size());
  };
  for (uint64_t seed = kFirstSeed; seed <= kLastSeed; ++seed) scan(seed, kStressStatements);
  for (uint64_t seed = 101; seed <= 112; ++seed) scan(seed, 1500);
  for (const InstrInfo &in : instrTable())
    if (hnc8::spells(in.op)) { // the HNC-8 generator: rows HNC-8 spells
      EXPECT_TRUE(seen.count(in.op)) << hnc8::mnemonicOf(in.op) << " never generated";
    }
  EXPECT_GE(maxDepth, 8);
  EXPECT_GE(maxMs, 3);
  EXPECT_GE(maxLoopNest, 2);
  EXPECT_GE(maxSlices, 3u);
  EXPECT_GE(maxSubs, 3u);
}

} // namespace
} // namespace lj::test

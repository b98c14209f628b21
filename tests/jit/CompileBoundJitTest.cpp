// Compile time stays linear in the program size for every instruction mix (issue 11 finding 5),
// checked without timing: for the worst-case program of every table row and flow shape
// (gen/WorstPrograms.h) the largest lowered function has a bounded IR size that does not grow
// with the program, and the IR per statement stays constant. The same programs, cut into many
// carried chunks and outlined loop bodies, still run exactly as the interpreter does.
#include "gen/ShapeCorpus.h"
#include "gen/WorstPrograms.h"
#include "jit/Jit.h"
#include "lowering/Lower.h"
#include "tests/jit/JitHarness.h"

#include <llvm/IR/Instructions.h>
#include <llvm/IR/LLVMContext.h>
#include <llvm/IR/Module.h>

namespace lj::test {
namespace {

const char *kDataLayout = "e-m:e-p270:32:32-p271:32:32-p272:64:64-i64:64-i128:128-f80:128-n8:16:"
                          "32:64-S128";

/// Largest function of a program's default lowering, in IR instructions (codegen and the
/// optimizer work per function, and both are super-linear in a function's size), and the total.
/// A body cut into chunks has a driver (`f` calling `f.c0`, `f.c1`...): a few instructions per
/// chunk, counted apart as `driverPerChunk`.
/// `longestName`: the longest function name; names that grew with the nesting (an outlined
/// loop named after all its enclosing ones) made a nest of n loops cost O(n^2) in the symbol
/// tables, the object file and the linker.
/// `functions`, `mostStores`: the number of functions and the most stores one of them has.
struct LoweredSize {
  size_t largest = 0, total = 0, longestName = 0, functions = 0, mostStores = 0;
  double driverPerChunk = 0;
};

LoweredSize loweredSize(const VerifiedProgram &p, const lower::LowerOptions &lo = {}) {
  llvm::LLVMContext ctx;
  auto m =
      lower::lowerProgram(p, ctx, llvm::DataLayout(kDataLayout), "x86_64-unknown-linux-gnu", lo);
  LoweredSize s;
  if (!m) {
    ADD_FAILURE() << llvm::toString(m.takeError());
    return s;
  }
  for (const llvm::Function &f : **m) {
    const size_t n = f.getInstructionCount();
    s.total += n;
    ++s.functions;
    size_t stores = 0;
    for (const llvm::BasicBlock &bb : f)
      for (const llvm::Instruction &inst : bb) stores += llvm::isa<llvm::StoreInst>(inst);
    s.mostStores = std::max(s.mostStores, stores);
    s.longestName = std::max(s.longestName, f.getName().size());
    size_t chunks = 0;
    while ((*m)->getFunction((f.getName() + ".c" + std::to_string(chunks)).str())) ++chunks;
    if (chunks == 0)
      s.largest = std::max(s.largest, n);
    else
      s.driverPerChunk = std::max(s.driverPerChunk, static_cast<double>(n) / chunks);
  }
  return s;
}

// The heaviest row (SPDLBUS1, ~90 IR instructions a statement) fills a 150-weight chunk with
// ~2,000 instructions; an ordinary chunk of 150 statements has ~300-800.
constexpr size_t kMaxFunction = 3000;

class CompileBound : public ::testing::TestWithParam<std::string> {};

TEST_P(CompileBound, LargestFunctionDoesNotGrowWithTheProgram) {
  LoweredSize at[2];
  int32_t sizes[2] = {2000, 4000};
  for (int k = 0; k < 2; ++k) {
    gen::GenProgram g = gen::generateWorst(GetParam(), sizes[k]);
    ASSERT_FALSE(g.lines.empty());
    auto prog = compileOrFail(g.text());
    ASSERT_TRUE(prog) << GetParam() << " at " << sizes[k] << " statements";
    at[k] = loweredSize(*prog);
  }
  // Before the fix one long rung (or a loop nest) was one function: 4,000 x BMOV = 68,000.
  EXPECT_LE(at[1].largest, kMaxFunction) << "2,000 statements: " << at[0].largest;
  EXPECT_LE(at[1].largest, at[0].largest + 64) << "the largest function grows with the program";
  // A driver calls and dispatches: a few instructions per chunk, whatever the program.
  EXPECT_LE(at[1].driverPerChunk, 8.0);
  // Symbol names of bounded length: the body's name, a statement index and a chunk number.
  EXPECT_LE(at[1].longestName, 40u) << "2,000 statements: " << at[0].longestName;
  // Linear total: twice the statements, about twice the IR.
  EXPECT_LE(at[1].total, 2 * at[0].total + at[0].total / 5 + 500);
}

// A whole optimizing build merges consecutive chunks (LowerOptions::mergeIr / mergeStores /
// mergeIndexed, jit/Jit.h): a function closes once it reaches any bound, so it exceeds one by
// at most the chunk that crossed it (kMaxFunction instructions). The worst cases keep that too.
lower::LowerOptions optimizingBuild() {
  lower::LowerOptions lo;
  lo.mergeIr = jit::kOptMergeIr;
  lo.mergeStores = jit::kOptMergeStores;
  lo.mergeIndexed = jit::kOptMergeIndexed;
  return lo;
}

TEST_P(CompileBound, MergedFunctionsStayWithinTheMergeBounds) {
  gen::GenProgram g = gen::generateWorst(GetParam(), 4000);
  auto prog = compileOrFail(g.text());
  ASSERT_TRUE(prog);
  const LoweredSize merged = loweredSize(*prog, optimizingBuild());
  EXPECT_LE(merged.largest, static_cast<size_t>(jit::kOptMergeIr) + kMaxFunction);
}

// Rung-structured programs (clean cuts at every rung) do get merged: on the 10,000-statement
// corpus shapes at most a third of the functions remain, none above the instruction bound, and
// no function has more stores than the store bound plus one chunk's.
TEST(CompileBoundMerge, RungStructuredProgramsMergeWithinTheBounds) {
  for (const char *shape : {"plc1-mixed", "edge-heavy", "deep-nesting"}) {
    SCOPED_TRACE(shape);
    gen::GenProgram g = gen::generateShape(shape, 20330000, 10000);
    auto prog = compileOrFail(g.text());
    ASSERT_TRUE(prog);
    const LoweredSize chunked = loweredSize(*prog), merged = loweredSize(*prog, optimizingBuild());
    EXPECT_LE(merged.functions * 3, chunked.functions)
        << chunked.functions << " functions chunked, " << merged.functions << " merged";
    EXPECT_LE(merged.largest, static_cast<size_t>(jit::kOptMergeIr) + kMaxFunction);
    EXPECT_LE(merged.mostStores, static_cast<size_t>(jit::kOptMergeStores) + chunked.mostStores);
    EXPECT_GT(merged.mostStores, chunked.mostStores);
  }
}

// Rungs of contacts that all write one output byte: the image cache stores that byte once per
// function, so only the instruction bound can close a function. 1,100 rungs of 8 contacts
// (~28,000 IR instructions) need at least three functions, none above the bound.
TEST(CompileBoundMerge, FewStoresCloseOnTheInstructionBound) {
  std::string text;
  for (int r = 0; r < 1100; ++r) {
    text += "LD X0." + std::to_string(r % 8) + "\n";
    for (int c = 1; c < 8; ++c)
      text += "AND X" + std::to_string(c) + "." + std::to_string(r % 8) + "\n";
    text += "OUT Y0." + std::to_string(r % 8) + "\n";
  }
  auto prog = compileOrFail(text);
  ASSERT_TRUE(prog);
  const LoweredSize merged = loweredSize(*prog, optimizingBuild());
  EXPECT_LE(merged.largest, static_cast<size_t>(jit::kOptMergeIr) + kMaxFunction);
  EXPECT_LE(merged.mostStores, 8u);
  const size_t driversAndEntries = 4; // lj_init, lj_plc1 (the driver), lj_plc2 and its slice
  EXPECT_GE(merged.functions, driversAndEntries + 3)
      << merged.functions << " functions, largest " << merged.largest << ", total " << merged.total;
}

INSTANTIATE_TEST_SUITE_P(Worst, CompileBound, ::testing::ValuesIn(gen::worstCaseNames()),
                         [](const ::testing::TestParamInfo<std::string> &i) { return i.param; });

// Every worst case with its rung fed from inputs (LD X1.n instead of LDT, so carried entries are
// not constants), lowered at chunk size 4: carried cuts everywhere, loops outlined. Interpreter
// and JIT must agree on every byte of the state after every tick.
TEST(CompileBoundRuns, CarriedChunksAndOutlinedLoopsMatchInterpreter) {
  for (const std::string &name : gen::worstCaseNames()) {
    SCOPED_TRACE(name);
    gen::GenProgram g = gen::generateWorst(name, 120);
    int n = 0;
    for (std::string &l : g.lines)
      if (l == "LDT") l = "LD X1." + std::to_string(n++ % 8);
    auto prog = compileOrFail(g.text());
    ASSERT_TRUE(prog);
    Scenario sc;
    sc.ticks = 4;
    sc.maxBackwardSteps = 5000; // the nested loops end in the watchdog: both engines alike
    sc.hostInputs = [](uint32_t t, lj_state &s) {
      s.img.X[0] = static_cast<uint8_t>(t * 0x5b + 1);
      s.img.X[1] = static_cast<uint8_t>(t % 2 ? 0xff : 0x3c + t);
    };
    EXPECT_TRUE(jitMatchesInterpreter(*prog, jit::Tier::Fast, sc, {}, 4));
  }
}

} // namespace
} // namespace lj::test

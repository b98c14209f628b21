// JIT compile latency per program size and tier, with the lower / optimize / codegen phase
// times (targets: optimizing < 1 s, fast < 150 ms for 10k statements), and compiles served by
// the object cache (in memory, and from disk as in a new `ladderjit run` process), and the
// worst-case program of every instruction (gen/WorstPrograms.h) at two sizes, whose ratio
// shows the compile time is linear for every mix (BM_CompileWorst/<row>/<statements>).
#include "bench/BenchPrograms.h"
#include "gen/WorstPrograms.h"
#include "jit/Jit.h"
#include "jit/ObjectCache.h"
#include "pipeline/Compile.h"

#include <filesystem>
#include <unistd.h>

namespace lj::bench {
namespace {

void BM_Compile(benchmark::State &state, jit::Tier tier) {
  const int n = static_cast<int>(state.range(0));
  const VerifiedProgram &p = verifiedProgram(n);
  jit::JitOptions o;
  o.tier = tier;
  jit::CompileTimes sum;
  Stopwatch sw(CLOCK_PROCESS_CPUTIME_ID);
  for (auto _ : state) {
    std::string err;
    jit::CompileTimes t;
    std::unique_ptr<Engine> e = jit::compile(p, o, err, &t);
    if (!e) {
      state.SkipWithError(("JIT compile failed: " + err).c_str());
      break;
    }
    benchmark::DoNotOptimize(e.get());
    sum.lowerUs += t.lowerUs;
    sum.optimizeUs += t.optimizeUs;
    sum.codegenUs += t.codegenUs;
  }
  const double it = static_cast<double>(std::max<int64_t>(state.iterations(), 1));
  state.counters["lower_ms"] = sum.lowerUs / it / 1000;
  state.counters["optimize_ms"] = sum.optimizeUs / it / 1000;
  state.counters["codegen_ms"] = sum.codegenUs / it / 1000;
  setStatementCounters(state, n, sw.ns());
}

// Each compile of a 10k program takes long enough that a handful of iterations is plenty.
// The optimizing tier compiles partitions on worker threads, so the CPU column must count the
// whole process (not only the calling thread) and the quoted latency is wall time.
BENCHMARK_CAPTURE(BM_Compile, fast, jit::Tier::Fast)
    ->Apply(programSizes)
    ->MeasureProcessCPUTime()
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Compile, optimizing, jit::Tier::Optimizing)
    ->Apply(programSizes)
    ->MeasureProcessCPUTime()
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

enum class CacheTier { Memory, Disk };

/// An optimizing compile that hits the cache: every iteration is a hit (asserted by counter).
/// Disk: a new ObjectCache per iteration on a warm directory, like a new process.
void BM_CompileCached(benchmark::State &state, CacheTier tier) {
  const int n = static_cast<int>(state.range(0));
  const VerifiedProgram &p = verifiedProgram(n);
  const std::string dir = "/tmp/ladderjit-bench-cache-" + std::to_string(getpid());
  jit::JitOptions o;
  o.cache = std::make_shared<jit::ObjectCache>(dir);
  std::string err;
  if (!jit::compile(p, o, err)) { // warm the cache
    state.SkipWithError(("JIT compile failed: " + err).c_str());
    return;
  }
  uint64_t hits = 0;
  Stopwatch sw(CLOCK_PROCESS_CPUTIME_ID);
  for (auto _ : state) {
    if (tier == CacheTier::Disk) o.cache = std::make_shared<jit::ObjectCache>(dir);
    const uint64_t before = o.cache->stats().hits;
    std::unique_ptr<Engine> e = jit::compile(p, o, err);
    benchmark::DoNotOptimize(e.get());
    hits += o.cache->stats().hits - before;
  }
  const double ns = sw.ns();
  std::error_code ec;
  std::filesystem::remove_all(dir, ec);
  if (hits != static_cast<uint64_t>(state.iterations()))
    state.SkipWithError("a compile missed the cache");
  setStatementCounters(state, n, ns);
}

BENCHMARK_CAPTURE(BM_CompileCached, memory, CacheTier::Memory)
    ->Apply(programSizes)
    ->MeasureProcessCPUTime()
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_CompileCached, disk, CacheTier::Disk)
    ->Apply(programSizes)
    ->MeasureProcessCPUTime()
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

/// The optimizing-tier compile of the worst case `name` of `n` statements (as `ladderjit run`).
void BM_CompileWorst(benchmark::State &state, const std::string &name) {
  const int n = static_cast<int>(state.range(0));
  Diagnostics d("worst.stl");
  std::optional<VerifiedProgram> p =
      pipeline::compileStl(gen::generateWorst(name, n).text(), "worst.stl", {}, d);
  if (!p) {
    state.SkipWithError(("worst case does not verify: " + d.render()).c_str());
    return;
  }
  jit::JitOptions o;
  jit::CompileTimes sum;
  Stopwatch sw(CLOCK_PROCESS_CPUTIME_ID);
  for (auto _ : state) {
    std::string err;
    jit::CompileTimes t;
    std::unique_ptr<Engine> e = jit::compile(*p, o, err, &t);
    if (!e) {
      state.SkipWithError(("JIT compile failed: " + err).c_str());
      break;
    }
    benchmark::DoNotOptimize(e.get());
    sum.lowerUs += t.lowerUs;
    sum.optimizeUs += t.optimizeUs;
    sum.codegenUs += t.codegenUs;
  }
  const double it = static_cast<double>(std::max<int64_t>(state.iterations(), 1));
  state.counters["lower_ms"] = sum.lowerUs / it / 1000;
  state.counters["optimize_ms"] = sum.optimizeUs / it / 1000;
  state.counters["codegen_ms"] = sum.codegenUs / it / 1000;
  setStatementCounters(state, static_cast<int64_t>(p->stmts.size()), sw.ns());
}

} // namespace
} // namespace lj::bench

int main(int argc, char **argv) {
  for (const std::string &name : lj::gen::worstCaseNames())
    benchmark::RegisterBenchmark(("BM_CompileWorst/" + name).c_str(), lj::bench::BM_CompileWorst,
                                 name)
        ->Arg(1000)
        ->Arg(2000)
        ->Arg(4000)
        ->Arg(8000)
        ->Iterations(1)
        ->MeasureProcessCPUTime()
        ->UseRealTime()
        ->Unit(benchmark::kMillisecond);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

// JIT compile latency per program size and tier, with the lower / optimize / codegen phase
// times (targets: optimizing < 1 s, fast < 150 ms for 10k statements).
#include "bench/BenchPrograms.h"
#include "jit/Jit.h"

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

} // namespace
} // namespace lj::bench

BENCHMARK_MAIN();

// Front-end latency: parse, verify, and parse+verify of realistic 1k/5k/10k-statement programs
// (target: parse+verify of 10k statements < 50 ms).
#include "bench/BenchPrograms.h"
#include "pipeline/Compile.h"
#include "pipeline/Dialects.h"

namespace lj::bench {
namespace {

void BM_Parse(benchmark::State &state) {
  const int n = static_cast<int>(state.range(0));
  const std::string &text = programText(n);
  Stopwatch sw;
  for (auto _ : state) {
    Diagnostics d("bench.stl");
    ParsedProgram p = pipeline::parse(pipeline::defaultDialect(), text, "bench.stl", d);
    benchmark::DoNotOptimize(p.stmts.data());
    benchmark::ClobberMemory();
  }
  setStatementCounters(state, n, sw.ns());
}

void BM_Verify(benchmark::State &state) {
  const int n = static_cast<int>(state.range(0));
  Diagnostics pd("bench.stl");
  const ParsedProgram parsed =
      pipeline::parse(pipeline::defaultDialect(), programText(n), "bench.stl", pd);
  Stopwatch sw;
  for (auto _ : state) {
    Diagnostics d("bench.stl");
    std::optional<VerifiedProgram> v = verify(parsed, {}, d);
    if (!v) {
      state.SkipWithError("generated program does not verify");
      break;
    }
    benchmark::DoNotOptimize(v->info.data());
    benchmark::ClobberMemory();
  }
  setStatementCounters(state, n, sw.ns());
}

void BM_ParseVerify(benchmark::State &state) {
  const int n = static_cast<int>(state.range(0));
  const std::string &text = programText(n);
  Stopwatch sw;
  for (auto _ : state) {
    Diagnostics d("bench.stl");
    std::optional<VerifiedProgram> v = pipeline::compileStl(text, "bench.stl", {}, d);
    if (!v) {
      state.SkipWithError("generated program does not verify");
      break;
    }
    benchmark::DoNotOptimize(v->info.data());
    benchmark::ClobberMemory();
  }
  setStatementCounters(state, n, sw.ns());
}

BENCHMARK(BM_Parse)->Apply(programSizes)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Verify)->Apply(programSizes)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ParseVerify)->Apply(programSizes)->Unit(benchmark::kMillisecond);

} // namespace
} // namespace lj::bench

BENCHMARK_MAIN();

// Scan speed: one full scan (PLC1 + every PLC2 slice, entries called directly) of realistic
// 1k/5k/10k programs on the interpreter and the JIT tiers, plus a same-run JIT/interpreter ratio
// (targets: JIT full scan of 10k < 10 us and >= 30x the interpreter), and AOT shared objects
// (`ladderjit compile`) against the optimizing JIT in the same run.
#include "bench/BenchPrograms.h"
#include "engines/EngineSpec.h"
#include "ir/Engine.h"

namespace lj::bench {
namespace {

enum class Kind { Interp, JitFast, JitOpt, Aot };

/// Engines are built once per (size, kind): Google Benchmark calls a benchmark function several
/// times, and a 10k optimizing compile should not be repeated for each call.
const Engine &engineFor(int n, Kind k) {
  static std::map<std::pair<int, Kind>, std::unique_ptr<Engine>> cache;
  auto key = std::make_pair(n, k);
  auto it = cache.find(key);
  if (it != cache.end()) return *it->second;
  const VerifiedProgram &p = verifiedProgram(n);
  // AOT: `ladderjit compile` (host CPU) into a temp .so, loaded like `run --engine aot:` does.
  engines::EngineSpec spec{k == Kind::Interp ? engines::EngineKind::Interp
                           : k == Kind::Aot  ? engines::EngineKind::Aot
                                             : engines::EngineKind::Jit,
                           {}};
  engines::EngineOptions o;
  o.fastTier = k == Kind::JitFast;
  Result<std::unique_ptr<Engine>> e = engines::makeEngine(spec, p, o);
  if (!e) {
    std::fprintf(stderr, "%s build of the %d-statement program failed: %s\n",
                 engines::engineKindName(spec.kind), n, e.status().message().c_str());
    std::abort();
  }
  return *cache.emplace(key, std::move(e).value()).first->second;
}

/// A state after init, with a fixed input pattern.
std::unique_ptr<lj_state> preparedState(const Engine &e) {
  auto s = std::make_unique<lj_state>();
  lj_state_reset(s.get());
  for (int i = 0; i < 64; ++i) s->img.X[i] = static_cast<uint8_t>(i * 37 + 11);
  for (int i = 0; i < 100; ++i) s->img.F[i] = static_cast<int16_t>(i * 997);
  lj_run_init(s.get(), &e.entries());
  return s;
}

/// One full scan; an input byte toggles each scan so edges, counters and timers see changes.
inline void fullScan(const lj_entries &e, lj_state *s, uint64_t i) {
  s->now_ms += 1;
  s->steps = 0;
  s->img.X[i & 63] ^= 0x5A;
  e.plc1(e.ctx, s);
  for (uint32_t k = 0; k < e.plc2_slice_count; ++k) e.plc2_slice(e.ctx, s, k);
}

void BM_Scan(benchmark::State &state, Kind kind) {
  const int n = static_cast<int>(state.range(0));
  const Engine &eng = engineFor(n, kind);
  auto s = preparedState(eng);
  const lj_entries &e = eng.entries();
  uint64_t i = 0;
  Stopwatch sw;
  for (auto _ : state) {
    fullScan(e, s.get(), i++);
    benchmark::DoNotOptimize(s.get());
    benchmark::ClobberMemory();
  }
  setStatementCounters(state, scanStatements(verifiedProgram(n)), sw.ns());
  state.counters["slices"] = e.plc2_slice_count;
}

BENCHMARK_CAPTURE(BM_Scan, interp, Kind::Interp)
    ->Apply(programSizes)
    ->Unit(benchmark::kMicrosecond);

BENCHMARK_CAPTURE(BM_Scan, jit_fast, Kind::JitFast)
    ->Apply(programSizes)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_Scan, jit_opt, Kind::JitOpt)
    ->Apply(programSizes)
    ->Unit(benchmark::kMicrosecond);

/// Interpreter and JIT timed in the same iterations (blocks of scans, alternating), so the
/// ratio is not skewed by the machine's load changing between two benchmark runs.
void BM_ScanRatio(benchmark::State &state, Kind jitKind) {
  const int n = static_cast<int>(state.range(0));
  // Blocks of scans long enough that reading the CPU clock costs well under 1%.
  const int kBlock = std::max(8, 100000 / n);
  const Engine &ie = engineFor(n, Kind::Interp);
  const Engine &je = engineFor(n, jitKind);
  auto si = preparedState(ie);
  auto sj = preparedState(je);
  double interpNs = 0, jitNs = 0;
  uint64_t i = 0;
  for (auto _ : state) {
    Stopwatch a;
    for (int k = 0; k < kBlock; ++k) fullScan(ie.entries(), si.get(), i + k);
    benchmark::ClobberMemory();
    interpNs += a.ns();
    Stopwatch b;
    for (int k = 0; k < kBlock; ++k) fullScan(je.entries(), sj.get(), i + k);
    benchmark::ClobberMemory();
    jitNs += b.ns();
    i += kBlock;
    benchmark::DoNotOptimize(si.get());
    benchmark::DoNotOptimize(sj.get());
  }
  const double scans = static_cast<double>(state.iterations()) * kBlock;
  const double stmts = static_cast<double>(scanStatements(verifiedProgram(n)));
  state.counters["interp_us_per_scan"] = interpNs / scans / 1000;
  state.counters["jit_us_per_scan"] = jitNs / scans / 1000;
  state.counters["interp_ns_per_stmt"] = interpNs / scans / stmts;
  state.counters["jit_ns_per_stmt"] = jitNs / scans / stmts;
  state.counters["speedup"] = jitNs > 0 ? interpNs / jitNs : 0;
}

BENCHMARK_CAPTURE(BM_Scan, aot, Kind::Aot)->Apply(programSizes)->Unit(benchmark::kMicrosecond);

/// The optimizing JIT and the AOT .so of the same program timed in alternating blocks of the
/// same run: same lowering and pipeline, so the ratio should be 1 within noise.
void BM_ScanAotVsJit(benchmark::State &state) {
  const int n = static_cast<int>(state.range(0));
  const int kBlock = std::max(8, 100000 / n);
  const Engine &je = engineFor(n, Kind::JitOpt);
  const Engine &ae = engineFor(n, Kind::Aot);
  auto sj = preparedState(je);
  auto sa = preparedState(ae);
  double jitNs = 0, aotNs = 0;
  uint64_t i = 0;
  for (auto _ : state) {
    Stopwatch a;
    for (int k = 0; k < kBlock; ++k) fullScan(je.entries(), sj.get(), i + k);
    benchmark::ClobberMemory();
    jitNs += a.ns();
    Stopwatch b;
    for (int k = 0; k < kBlock; ++k) fullScan(ae.entries(), sa.get(), i + k);
    benchmark::ClobberMemory();
    aotNs += b.ns();
    i += kBlock;
    benchmark::DoNotOptimize(sj.get());
    benchmark::DoNotOptimize(sa.get());
  }
  const double scans = static_cast<double>(state.iterations()) * kBlock;
  state.counters["jit_us_per_scan"] = jitNs / scans / 1000;
  state.counters["aot_us_per_scan"] = aotNs / scans / 1000;
  state.counters["aot_over_jit"] = jitNs > 0 ? aotNs / jitNs : 0;
}
BENCHMARK(BM_ScanAotVsJit)->Apply(programSizes)->Unit(benchmark::kMicrosecond);

BENCHMARK_CAPTURE(BM_ScanRatio, jit_fast, Kind::JitFast)
    ->Apply(programSizes)
    ->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_ScanRatio, jit_opt, Kind::JitOpt)
    ->Apply(programSizes)
    ->Unit(benchmark::kMicrosecond);

} // namespace
} // namespace lj::bench

BENCHMARK_MAIN();

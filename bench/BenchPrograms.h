// The benchmark inputs every bench binary shares: realistic programs of 1k/5k/10k statements
// (fixed seeds, so runs compare), verified once and cached, plus explicit per-statement counters.
#pragma once

#include "gen/ProgramGenerator.h"
#include "pipeline/Compile.h"

#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <map>
#include <memory>
#include <string>

namespace lj::bench {

/// Program sizes of every family (statements, markers included).
inline void programSizes(benchmark::internal::Benchmark *b) {
  for (int n : {1000, 5000, 10000}) b->Arg(n);
}

/// The text of the `n`-statement realistic program.
inline const std::string &programText(int n) {
  static std::map<int, std::string> cache;
  auto it = cache.find(n);
  if (it == cache.end()) {
    gen::RealisticOptions o;
    o.seed = 20240000u + static_cast<uint64_t>(n);
    o.statements = n;
    it = cache.emplace(n, gen::generateRealistic(o).text()).first;
  }
  return it->second;
}

/// The verified `n`-statement program (default plc2_nvalue 200); aborts if it does not verify,
/// since every number measured on it would be meaningless.
inline const VerifiedProgram &verifiedProgram(int n) {
  static std::map<int, std::unique_ptr<VerifiedProgram>> cache;
  auto it = cache.find(n);
  if (it == cache.end()) {
    Diagnostics d("bench.stl");
    std::optional<VerifiedProgram> p = pipeline::compileStl(programText(n), "bench.stl", {}, d);
    if (!p) {
      std::fprintf(stderr, "benchmark program of %d statements does not verify:\n%s", n,
                   d.render().c_str());
      std::abort();
    }
    it = cache.emplace(n, std::make_unique<VerifiedProgram>(std::move(*p))).first;
  }
  return *it->second;
}

/// Statements one full scan executes: PLC1 + all of PLC2 (subroutine bodies not counted).
inline int64_t scanStatements(const VerifiedProgram &p) {
  return (p.plc1.end - p.plc1.begin) + (p.plc2.end - p.plc2.begin);
}

/// CPU-time stopwatch for the explicit ns/statement counters. CPU time, like Google Benchmark's
/// "CPU" column, because the 2 cores are shared and wall time counts other work. Scans run on
/// the calling thread; compiles use worker threads and pass CLOCK_PROCESS_CPUTIME_ID.
class Stopwatch {
public:
  explicit Stopwatch(clockid_t clock = CLOCK_THREAD_CPUTIME_ID) : clock_(clock), t0_(now()) {}
  double ns() const { return now() - t0_; }

private:
  double now() const {
    timespec ts{};
    clock_gettime(clock_, &ts);
    return static_cast<double>(ts.tv_sec) * 1e9 + static_cast<double>(ts.tv_nsec);
  }
  clockid_t clock_;
  double t0_;
};

/// Explicit counters (STYLE.md 13): statements per iteration, statements/s and ns per statement
/// (both from CPU time).
inline void setStatementCounters(benchmark::State &state, int64_t stmtsPerIter, double loopNs) {
  const double total = static_cast<double>(stmtsPerIter) * static_cast<double>(state.iterations());
  state.counters["stmts"] = static_cast<double>(stmtsPerIter);
  state.counters["stmts_per_s"] = benchmark::Counter(static_cast<double>(stmtsPerIter),
                                                     benchmark::Counter::kIsIterationInvariantRate);
  state.counters["ns_per_stmt"] = total > 0 ? loopNs / total : 0;
}

} // namespace lj::bench

// The signal trace's cost per tick (issue 32, docs/BENCHMARKS.md "Signal trace"):
//   BM_TraceOff          what the executive's scan thread does per tick while no trace is armed
//                        (Executive::tickOnce: one acquire load of a flag, one branch not taken);
//   BM_TraceSample/N     SignalTrace::sample with N addresses (1, 8, 64) while waiting for a
//                        rising-edge trigger that never fires: copy the row into the pre-trigger
//                        ring, read the trigger bit, compare with the previous tick;
//   BM_TraceRecord/N     the same after the trigger (post-trigger rows), repeated captures
//                        handed off through the triple buffer whenever one completes.
// The addresses mix bits, bytes, words and double words of the HNC-8 image and timers.
#include "runtime/SignalTrace.h"

#include <benchmark/benchmark.h>

#include <atomic>
#include <cstdio>
#include <cstring>
#include <memory>

namespace {

using namespace lj;

std::optional<formats::CliAddress> hnc8(std::string_view text, std::string &error) {
  return formats::parseAddress(text, error);
}

std::string signalList(int n) {
  static const char *kinds[] = {"X%d.3", "Y%d", "F%d", "G%d.1", "R%d", "D%d", "B%d", "T%d"};
  std::string out;
  for (int i = 0; i < n; ++i) {
    char buf[32];
    std::snprintf(buf, sizeof buf, kinds[i % 8], 1 + i / 8);
    out += (i ? ", " : "") + std::string(buf);
  }
  return out;
}

std::unique_ptr<rt::SignalTrace> make(int n, const char *trigger, const char *mode) {
  std::string def = "signal " + signalList(n) + "\ntrigger " + trigger +
                    "\npre 1000\npost 1000\nmode " + mode + "\n";
  std::string err;
  std::optional<rt::TraceDefinition> d = rt::parseTraceDefinition(def, "bench", err);
  if (!d) return nullptr;
  return rt::SignalTrace::make(*d, hnc8, 1000000, err);
}

void BM_TraceOff(benchmark::State &state) {
  auto s = std::make_unique<lj_state>();
  std::memset(s.get(), 0, sizeof(lj_state));
  std::atomic<bool> wanted{false};
  auto t = make(8, "rising X1.0", "single");
  uint64_t tick = 0;
  for (auto _ : state) {
    if (wanted.load(std::memory_order_acquire)) [[unlikely]]
      t->sample(*s, tick);
    benchmark::ClobberMemory();
    ++tick;
  }
}
BENCHMARK(BM_TraceOff);

// Sample ticks on a trace of state.range(0) addresses armed with `trigger` and `mode`.
void sampleTicks(benchmark::State &state, const char *trigger, const char *mode) {
  auto s = std::make_unique<lj_state>();
  std::memset(s.get(), 0, sizeof(lj_state));
  auto t = make(static_cast<int>(state.range(0)), trigger, mode);
  if (!t) {
    state.SkipWithError("trace definition refused");
    return;
  }
  uint64_t tick = 0;
  for (auto _ : state) {
    t->sample(*s, tick++);
    benchmark::ClobberMemory();
  }
}

// Armed and waiting: the trigger never fires (X1.0 stays 0).
void BM_TraceSample(benchmark::State &state) { sampleTicks(state, "rising X1.0", "single"); }
BENCHMARK(BM_TraceSample)->Arg(1)->Arg(8)->Arg(64);

// Armed and recording every tick.
void BM_TraceRecord(benchmark::State &state) { sampleTicks(state, "immediate", "repeat"); }
BENCHMARK(BM_TraceRecord)->Arg(1)->Arg(8)->Arg(64);

} // namespace

BENCHMARK_MAIN();

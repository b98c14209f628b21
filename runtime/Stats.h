// Per-tick timing statistics of the cyclic executive: fixed-size histograms (no allocation on
// the scan thread), percentiles, overruns and missed deadlines, printed and written as JSON.
#pragma once

#include <nlohmann/json.hpp>

#include <array>
#include <cstdint>
#include <string>

namespace lj::rt {

/// A distribution of durations in nanoseconds: exact min/max/mean, percentiles from 1 us
/// buckets up to 10 ms (one overflow bucket above; its percentile reports the max).
class Histogram {
public:
  static constexpr uint32_t kBuckets = 10000; ///< 1 us each
  void add(int64_t ns);
  uint64_t count() const { return n_; }
  int64_t minNs() const { return n_ ? min_ : 0; }
  int64_t maxNs() const { return n_ ? max_ : 0; }
  double meanNs() const { return n_ ? static_cast<double>(sum_) / static_cast<double>(n_) : 0; }
  /// Upper edge (ns) of the bucket holding the q-quantile (0 < q <= 1), capped at max.
  int64_t percentileNs(double q) const;
  /// Ticks in 1 us bucket `i` (i == kBuckets: the overflow bucket).
  uint32_t bucket(uint32_t i) const { return i <= kBuckets ? b_[i] : 0; }
  /// {"count", "min_us", "mean_us", "p99_us", "p99_9_us", "max_us"}.
  nlohmann::json toJson() const;
  void clear();

private:
  std::array<uint32_t, kBuckets + 1> b_{};
  uint64_t n_ = 0;
  int64_t min_ = 0, max_ = 0;
  long double sum_ = 0;
};

/// Which code runs a program version (docs/serve.md "Tiering").
/// JitQuick: an online change's build, the optimizing tier's code except for the rung groups
/// the change touched, which are compiled at the fast tier until the optimized build replaces
/// it (docs/serve.md "Online change latency").
enum class EngineTier : uint8_t { Interp, JitFast, JitOpt, Aot, JitQuick };
/// "interp", "jit-fast", "jit-opt", "aot" (the lane names of `ladderjit bench`), "jit-quick".
const char *engineTierName(EngineTier t);

/// One engine switch of the running program at a tick boundary (interpreter-first tiering): the
/// same program and the same lj_state, only the code changed.
struct TierSwitch {
  uint64_t tick = 0; ///< the first tick the new code ran
  EngineTier from = EngineTier::Interp, to = EngineTier::Interp;
  int64_t buildNs = 0; ///< how long the background build of the new code took
  int64_t endNs = 0;   ///< CLOCK_MONOTONIC at the end of that tick
};

/// One online change (docs/serve.md "Online change latency"): from the request (after any wait
/// for a file still being written, which is not counted) to the new code running at a tick
/// boundary. CLOCK_MONOTONIC ns; durations in ns.
struct ChangeRecord {
  uint64_t version = 0; ///< the new version's id
  uint64_t tick = 0;    ///< the first tick it ran
  int64_t requestedNs = 0, runningNs = 0;
  int64_t optimizedNs = 0; ///< its optimized build switched in (JitQuick only; 0 = not yet / never)
  int64_t settleNs = 0;    ///< the wait for the file to settle before the request (not counted)
  int64_t frontendNs = 0;  ///< read, parse and verify
  int64_t buildNs = 0;     ///< the engine build (compile + link)
  int64_t buildCpuNs = 0;  ///< its CPU time over all compile threads (JIT; 0 = not measured)
  uint32_t groups = 0, groupsCompiled = 0, groupsQuick = 0; ///< incremental JIT rung groups
  EngineTier tier = EngineTier::Interp;
};

/// Everything the executive counts.
struct TickStats {
  uint64_t periodNs = 0;
  uint64_t ticks = 0;           ///< ticks executed (init excluded)
  uint64_t overruns = 0;        ///< ticks whose work ended past the next deadline
  uint64_t missedDeadlines = 0; ///< deadlines skipped without a tick (see docs/serve.md)
  uint64_t faultTicks = 0;      ///< ticks that ended with a fault (watchdog)
  uint64_t swaps = 0;           ///< online changes applied
  uint64_t rebuilds = 0;        ///< same-program rebuilds switched in (forces, live view; no init)
  uint64_t swapTickMaxNs = 0;   ///< longest scan of a tick that swapped (init + tick)
  uint64_t swapOverruns = 0;    ///< overruns of ticks that swapped
  uint64_t missedAfterSwap = 0; ///< deadlines missed right after a swap tick
  // Start-up and tiering (docs/serve.md "Time to first tick" and "Tiering"). Times are
  // CLOCK_MONOTONIC ns; 0 = not (yet) known.
  const char *tierMode = "direct"; ///< ExecutiveOptions::tierMode (a static string)
  int64_t startNs = 0;             ///< ExecutiveOptions::startNs (serve: the start of main)
  int64_t readyNs = 0;             ///< ExecutiveOptions::readyNs (program read and verified)
  int64_t firstTickEndNs = 0;      ///< the end of the first tick's scan (step 9)
  int64_t firstTickEndUnixNs = 0;  ///< the same moment on CLOCK_REALTIME (for outside clocks)
  EngineTier firstTier = EngineTier::Interp; ///< the code init and the first tick ran on
  EngineTier tier = EngineTier::Interp;      ///< the code running now
  static constexpr uint32_t kMaxSwitches = 8;
  uint32_t tierSwitches = 0;                       ///< engine switches taken (all of them counted)
  std::array<TierSwitch, kMaxSwitches> switches{}; ///< the first kMaxSwitches of them
  uint64_t tierRefusals = 0; ///< faster code discarded: an online change came first
  // Online change latency: the last kMaxChanges records, and the latencies of the last
  // kLatencies changes for the median (changeCount counts them all).
  static constexpr uint32_t kMaxChanges = 32, kLatencies = 256;
  uint64_t changeCount = 0;
  std::array<ChangeRecord, kMaxChanges> changes{}; ///< ring: change n at n % kMaxChanges
  std::array<int64_t, kLatencies> latencyNs{};     ///< ring likewise
  Histogram scan;   ///< work per tick: apply, I/O, lj_tick, publish, hooks
  Histogram jitter; ///< wake-up minus deadline

  nlohmann::json toJson() const;
  /// The "startup" object of toJson: ready_ms, first_tick_ms, first_tick_unix_ns and "tiering"
  /// (mode, first_engine, engine, switches [{tick, from, to, build_ms, at_ms}], switch_count,
  /// refused, time_to_jit_ms); times in ms since startNs, -1 = not known.
  nlohmann::json startupJson() const;
  /// The "online_changes" object of toJson: count, latency_ms {min, median, max} over the last
  /// kLatencies changes, and "recent" (the last kMaxChanges records, oldest first).
  nlohmann::json changesJson() const;
  /// Median / min / max latency (ms) over the recorded changes; -1 when none.
  double changeLatencyMs(double q) const;
  /// Human-readable summary (several lines).
  std::string summary() const;
};

} // namespace lj::rt

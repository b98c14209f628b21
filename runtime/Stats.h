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

/// Everything the executive counts.
struct TickStats {
  uint64_t periodNs = 0;
  uint64_t ticks = 0;           ///< ticks executed (init excluded)
  uint64_t overruns = 0;        ///< ticks whose work ended past the next deadline
  uint64_t missedDeadlines = 0; ///< deadlines skipped without a tick (see docs/serve.md)
  uint64_t faultTicks = 0;      ///< ticks that ended with a fault (watchdog)
  uint64_t swaps = 0;           ///< online changes applied
  uint64_t swapTickMaxNs = 0;   ///< longest scan of a tick that swapped (init + tick)
  uint64_t swapOverruns = 0;    ///< overruns of ticks that swapped
  uint64_t missedAfterSwap = 0; ///< deadlines missed right after a swap tick
  Histogram scan;               ///< work per tick: apply, I/O, lj_tick, publish, hooks
  Histogram jitter;             ///< wake-up minus deadline

  nlohmann::json toJson() const;
  /// Human-readable summary (several lines).
  std::string summary() const;
};

} // namespace lj::rt

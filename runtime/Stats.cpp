// Histogram percentiles and the JSON / text forms of the executive's statistics.
#include "runtime/Stats.h"

#include <algorithm>
#include <cstdio>
#include <vector>

namespace lj::rt {

void Histogram::add(int64_t ns) {
  if (ns < 0) ns = 0;
  uint64_t us = static_cast<uint64_t>(ns) / 1000;
  b_[std::min<uint64_t>(us, kBuckets)]++;
  if (n_ == 0 || ns < min_) min_ = ns;
  if (n_ == 0 || ns > max_) max_ = ns;
  sum_ += ns;
  ++n_;
}

int64_t Histogram::percentileNs(double q) const {
  if (n_ == 0) return 0;
  // The smallest bucket whose cumulative count reaches ceil(q * n).
  uint64_t need = static_cast<uint64_t>(q * static_cast<double>(n_));
  if (static_cast<double>(need) < q * static_cast<double>(n_)) ++need;
  need = std::clamp<uint64_t>(need, 1, n_);
  uint64_t cum = 0;
  for (uint32_t i = 0; i <= kBuckets; ++i) {
    cum += b_[i];
    if (cum >= need) {
      if (i == kBuckets) return max_;
      return std::min<int64_t>(static_cast<int64_t>(i + 1) * 1000, max_);
    }
  }
  return max_;
}

void Histogram::clear() { *this = Histogram(); }

static double us(int64_t ns) { return static_cast<double>(ns) / 1000.0; }

nlohmann::json Histogram::toJson() const {
  return {{"count", n_},
          {"min_us", us(minNs())},
          {"mean_us", meanNs() / 1000.0},
          {"p99_us", us(percentileNs(0.99))},
          {"p99_9_us", us(percentileNs(0.999))},
          {"max_us", us(maxNs())}};
}

const char *engineTierName(EngineTier t) {
  switch (t) {
  case EngineTier::Interp:
    return "interp";
  case EngineTier::JitFast:
    return "jit-fast";
  case EngineTier::JitOpt:
    return "jit-opt";
  case EngineTier::Aot:
    return "aot";
  case EngineTier::JitQuick:
    return "jit-quick";
  }
  return "interp";
}

namespace {
double msSince(int64_t from, int64_t to) {
  return from && to ? static_cast<double>(to - from) / 1e6 : -1.0;
}
} // namespace

nlohmann::json TickStats::startupJson() const {
  nlohmann::json sw = nlohmann::json::array();
  double toJit = -1;
  for (uint32_t i = 0; i < std::min(tierSwitches, kMaxSwitches); ++i) {
    const TierSwitch &w = switches[i];
    double at = msSince(startNs, w.endNs);
    sw.push_back({{"tick", w.tick},
                  {"from", engineTierName(w.from)},
                  {"to", engineTierName(w.to)},
                  {"build_ms", static_cast<double>(w.buildNs) / 1e6},
                  {"at_ms", at}});
    if (toJit < 0 && w.to != EngineTier::Interp) toJit = at;
  }
  if (firstTier != EngineTier::Interp && toJit < 0) toJit = msSince(startNs, firstTickEndNs);
  return {{"ready_ms", msSince(startNs, readyNs)},
          {"first_tick_ms", msSince(startNs, firstTickEndNs)},
          {"first_tick_unix_ns", firstTickEndUnixNs},
          {"tiering",
           {{"mode", tierMode},
            {"first_engine", engineTierName(firstTier)},
            {"engine", engineTierName(tier)},
            {"switches", sw},
            {"switch_count", tierSwitches},
            {"refused", tierRefusals},
            {"time_to_jit_ms", toJit}}}};
}

double TickStats::changeLatencyMs(double q) const {
  const size_t n = static_cast<size_t>(std::min<uint64_t>(changeCount, kLatencies));
  if (n == 0) return -1;
  std::vector<int64_t> v(latencyNs.begin(), latencyNs.begin() + static_cast<ptrdiff_t>(n));
  std::sort(v.begin(), v.end());
  size_t k = static_cast<size_t>(q * static_cast<double>(n - 1) + 0.5);
  return static_cast<double>(v[std::min(k, n - 1)]) / 1e6;
}

nlohmann::json TickStats::changesJson() const {
  nlohmann::json recent = nlohmann::json::array();
  const uint64_t first = changeCount > kMaxChanges ? changeCount - kMaxChanges : 0;
  auto ms = [](int64_t ns) { return static_cast<double>(ns) / 1e6; };
  for (uint64_t n = first; n < changeCount; ++n) {
    const ChangeRecord &c = changes[n % kMaxChanges];
    const int64_t latency = c.runningNs - c.requestedNs;
    recent.push_back({{"version", c.version},
                      {"tick", c.tick},
                      {"engine", engineTierName(c.tier)},
                      {"latency_ms", ms(latency)},
                      {"settle_ms", ms(c.settleNs)},
                      {"frontend_ms", ms(c.frontendNs)},
                      {"build_ms", ms(c.buildNs)},
                      {"build_cpu_ms", ms(c.buildCpuNs)},
                      {"swap_wait_ms", ms(latency - c.frontendNs - c.buildNs)},
                      {"groups", c.groups},
                      {"groups_compiled", c.groupsCompiled},
                      {"groups_quick", c.groupsQuick},
                      {"optimized_ms", c.optimizedNs ? ms(c.optimizedNs - c.requestedNs) : -1.0}});
  }
  return {{"count", changeCount},
          {"latency_ms",
           {{"min", changeLatencyMs(0)},
            {"median", changeLatencyMs(0.5)},
            {"max", changeLatencyMs(1)},
            {"of_last", std::min<uint64_t>(changeCount, kLatencies)}}},
          {"recent", recent}};
}

nlohmann::json TickStats::toJson() const {
  return {{"period_us", static_cast<double>(periodNs) / 1000.0},
          {"ticks", ticks},
          {"overruns", overruns},
          {"missed_deadlines", missedDeadlines},
          {"fault_ticks", faultTicks},
          {"swaps", swaps},
          {"rebuilds", rebuilds},
          {"swap_tick_max_us", static_cast<double>(swapTickMaxNs) / 1000.0},
          {"swap_overruns", swapOverruns},
          {"missed_after_swap", missedAfterSwap},
          {"scan", scan.toJson()},
          {"jitter", jitter.toJson()},
          {"startup", startupJson()},
          {"online_changes", changesJson()}};
}

std::string TickStats::summary() const {
  char buf[1024];
  auto line = [](const char *name, const Histogram &h) {
    char l[256];
    std::snprintf(l, sizeof l,
                  "  %-7s min %.1f us  mean %.1f us  p99 %.1f us  p99.9 %.1f us  max %.1f us\n",
                  name, us(h.minNs()), h.meanNs() / 1000.0, us(h.percentileNs(0.99)),
                  us(h.percentileNs(0.999)), us(h.maxNs()));
    return std::string(l);
  };
  std::snprintf(
      buf, sizeof buf,
      "ticks %llu at %.3f ms: overruns %llu, missed deadlines %llu, fault ticks %llu, "
      "online changes %llu\n",
      static_cast<unsigned long long>(ticks), static_cast<double>(periodNs) / 1e6,
      static_cast<unsigned long long>(overruns), static_cast<unsigned long long>(missedDeadlines),
      static_cast<unsigned long long>(faultTicks), static_cast<unsigned long long>(swaps));
  std::string out = buf;
  if (swaps) {
    std::snprintf(buf, sizeof buf,
                  "  swap ticks: longest %.1f us, overruns %llu, deadlines missed right after "
                  "%llu\n",
                  static_cast<double>(swapTickMaxNs) / 1000.0,
                  static_cast<unsigned long long>(swapOverruns),
                  static_cast<unsigned long long>(missedAfterSwap));
    out += buf;
  }
  if (changeCount) {
    std::snprintf(buf, sizeof buf,
                  "  online change latency (requested -> new code running), last %llu: median "
                  "%.1f ms, min %.1f ms, max %.1f ms\n",
                  static_cast<unsigned long long>(std::min<uint64_t>(changeCount, kLatencies)),
                  changeLatencyMs(0.5), changeLatencyMs(0), changeLatencyMs(1));
    out += buf;
  }
  if (firstTickEndNs) {
    std::snprintf(buf, sizeof buf, "  first tick %.1f ms after start (program ready at %.1f ms)\n",
                  msSince(startNs, firstTickEndNs), msSince(startNs, readyNs));
    out += buf;
  }
  for (uint32_t i = 0; i < std::min(tierSwitches, kMaxSwitches); ++i) {
    const TierSwitch &w = switches[i];
    std::snprintf(buf, sizeof buf,
                  "  engine switch %s -> %s at tick %llu, %.1f ms after start (built in %.1f ms)\n",
                  engineTierName(w.from), engineTierName(w.to),
                  static_cast<unsigned long long>(w.tick), msSince(startNs, w.endNs),
                  static_cast<double>(w.buildNs) / 1e6);
    out += buf;
  }
  return out + line("scan", scan) + line("jitter", jitter);
}

} // namespace lj::rt

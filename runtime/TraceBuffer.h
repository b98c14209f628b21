// The power-flow trace of one traced program version (ir/Trace.h) and its hand-off from the
// scan thread to readers: the engine writes `live()` during the scan; at a tick boundary the
// scan thread copies it into a triple buffer (no lock, no allocation, never waits); a reader
// takes the newest complete copy, so no reader ever sees a half-written tick.
#pragma once

#include <atomic>
#include <climits>
#include <cstdint>
#include <mutex>
#include <vector>

namespace lj::rt {

class TraceBuffer {
public:
  explicit TraceBuffer(int32_t words);
  TraceBuffer(const TraceBuffer &) = delete;
  TraceBuffer &operator=(const TraceBuffer &) = delete;

  /// The buffer the engine records into (traceLayout(prog).words words).
  int32_t *live() { return live_.data(); }
  int32_t words() const { return static_cast<int32_t>(live_.size()); }

  /// Set in every word before a tick: a statement whose first word (always a 0/1 flag: the
  /// contact's conduction, the coil's input, a box's EN, a jump's EN) still holds it after the
  /// tick was not scanned in that tick. (A value word may hold it legitimately.)
  static constexpr int32_t kNotScanned = INT32_MIN;
  /// Scan thread, between ticks: every live word to kNotScanned. No allocation.
  void markNotScanned();
  /// Scan thread, at a tick boundary: publish the words of tick `tick`. Wait-free.
  void publish(uint64_t tick);
  /// Any thread: the newest published copy into `out` (and its tick). False when nothing was
  /// published yet. Readers serialize among themselves, never with the scan thread.
  bool take(std::vector<int32_t> &out, uint64_t &tick);
  /// Ticks published so far.
  uint64_t published() const { return published_.load(std::memory_order_acquire); }

private:
  struct Slot {
    std::vector<int32_t> w;
    uint64_t tick = 0;
  };
  static constexpr uint32_t kFresh = 4;
  std::vector<int32_t> live_;
  Slot slots_[3];
  std::atomic<uint32_t> middle_{1}; ///< slot index | kFresh when written since the last take
  uint32_t back_ = 0;               ///< scan thread's slot
  uint32_t front_ = 2;              ///< readers' slot (under readMu_)
  bool any_ = false;                ///< under readMu_: front_ holds a published tick
  std::mutex readMu_;
  std::atomic<uint64_t> published_{0};
};

} // namespace lj::rt

// Triple buffer of the power-flow trace (runtime/TraceBuffer.h).
#include "runtime/TraceBuffer.h"

#include <algorithm>
#include <cstring>

namespace lj::rt {

TraceBuffer::TraceBuffer(int32_t words) : live_(static_cast<size_t>(std::max(words, 0)), 0) {
  for (Slot &s : slots_) s.w.assign(live_.size(), 0);
}

void TraceBuffer::publish(uint64_t tick) {
  Slot &b = slots_[back_];
  if (!live_.empty()) std::memcpy(b.w.data(), live_.data(), live_.size() * sizeof(int32_t));
  b.tick = tick;
  // Hand the written slot over and take the middle one back (the reader's is never touched).
  back_ = middle_.exchange(back_ | kFresh, std::memory_order_acq_rel) & 3u;
  published_.fetch_add(1, std::memory_order_release);
}

void TraceBuffer::markNotScanned() { std::fill(live_.begin(), live_.end(), kNotScanned); }

bool TraceBuffer::take(std::vector<int32_t> &out, uint64_t &tick) {
  std::lock_guard<std::mutex> g(readMu_);
  if (middle_.load(std::memory_order_acquire) & kFresh) {
    front_ = middle_.exchange(front_, std::memory_order_acq_rel) & 3u;
    any_ = true;
  }
  if (!any_) return false;
  out = slots_[front_].w;
  tick = slots_[front_].tick;
  return true;
}

} // namespace lj::rt

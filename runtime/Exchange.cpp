// Exchange: seqlocked double-buffered snapshots, posted writes and the lock list.
#include "runtime/Exchange.h"

#include <cstring>
#include <thread>

namespace lj::rt {

struct Exchange::Buffer {
  std::atomic<uint64_t> seq{0}; // odd while the scan thread writes this buffer
  uint64_t tick = 0;
  lj_state state;
};

Exchange::Exchange() {
  for (auto &b : buf_) {
    b = std::make_unique<Buffer>();
    lj_state_reset(&b->state);
  }
}

Exchange::~Exchange() = default;

void Exchange::applyPending(lj_state &s) {
  std::unique_lock<std::mutex> g(postMu_, std::try_to_lock);
  if (g.owns_lock() && !pending_.empty()) {
    uint64_t last = 0;
    for (const auto &[seq, writes] : pending_) {
      for (const formats::Assignment &w : writes) formats::writeAddress(s, w.addr, w.value);
      last = seq;
    }
    pending_.clear();      // keeps its capacity: no allocation on the scan thread next time
    appliedInTick_ = last; // announced by publish(), once a snapshot shows the writes
  }
  g = {};
  applyLocks(s);
}

void Exchange::applyLocks(lj_state &s) {
  uint64_t v = locksVersion_.load(std::memory_order_acquire);
  if (v != scanLocksVersion_) {
    std::unique_lock<std::mutex> g(lockMu_, std::try_to_lock);
    if (g.owns_lock()) {
      scanLocks_ = locks_; // only when the list changed: a rare allocation
      scanLocksVersion_ = locksVersion_.load(std::memory_order_relaxed);
    }
  }
  for (const formats::Assignment &a : scanLocks_) formats::writeAddress(s, a.addr, a.value);
}

void Exchange::publish(const lj_state &s, uint64_t tick) {
  // Write the buffer readers are not directed to, then flip version_ to it.
  uint64_t v = version_.load(std::memory_order_relaxed) + 1;
  Buffer &b = *buf_[v & 1];
  uint64_t q = b.seq.load(std::memory_order_relaxed);
  b.seq.store(q + 1, std::memory_order_relaxed);
  std::atomic_thread_fence(std::memory_order_release);
  std::memcpy(&b.state, &s, sizeof s);
  b.tick = tick;
  b.seq.store(q + 2, std::memory_order_release);
  version_.store(v, std::memory_order_release);
  if (appliedInTick_) applied_.store(appliedInTick_, std::memory_order_release);
}

bool Exchange::snapshot(lj_state &out, uint64_t *tick) const {
  for (int attempt = 0;; ++attempt) {
    uint64_t v = version_.load(std::memory_order_acquire);
    if (v == 0) return false;
    const Buffer &b = *buf_[v & 1];
    uint64_t q1 = b.seq.load(std::memory_order_acquire);
    if ((q1 & 1) == 0) {
      std::memcpy(&out, &b.state, sizeof out);
      uint64_t t = b.tick;
      std::atomic_thread_fence(std::memory_order_acquire);
      if (b.seq.load(std::memory_order_relaxed) == q1) {
        if (tick) *tick = t;
        return true;
      }
    }
    // The scan thread overtook us (two publishes during one copy): try the newest again.
    if (attempt > 8) std::this_thread::yield();
  }
}

uint64_t Exchange::lastTick() const {
  lj_state tmp; // rare use (tests, stats): the full copy keeps the seqlock logic in one place
  uint64_t t = 0;
  snapshot(tmp, &t);
  return t;
}

uint64_t Exchange::post(std::vector<formats::Assignment> writes) {
  std::lock_guard<std::mutex> g(postMu_);
  uint64_t seq = nextSeq_++;
  pending_.emplace_back(seq, std::move(writes));
  return seq;
}

bool Exchange::waitApplied(uint64_t seq, std::chrono::milliseconds timeout) const {
  // Polling keeps the scan thread free of any notification work; 200 us is well below a tick.
  auto until = std::chrono::steady_clock::now() + timeout;
  while (applied_.load(std::memory_order_acquire) < seq) {
    if (std::chrono::steady_clock::now() >= until) return false;
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  return true;
}

namespace {
bool sameAddress(const formats::CliAddress &a, const formats::CliAddress &b) {
  return a.area == b.area && a.index == b.index && a.bit == b.bit;
}
} // namespace

void Exchange::lock(const formats::Assignment &a) {
  std::lock_guard<std::mutex> g(lockMu_);
  bool replaced = false;
  for (formats::Assignment &l : locks_)
    if (sameAddress(l.addr, a.addr)) {
      l = a;
      replaced = true;
    }
  if (!replaced) locks_.push_back(a);
  locksVersion_.fetch_add(1, std::memory_order_release);
}

bool Exchange::unlock(const formats::CliAddress &addr) {
  std::lock_guard<std::mutex> g(lockMu_);
  size_t before = locks_.size();
  std::erase_if(locks_, [&](const formats::Assignment &l) { return sameAddress(l.addr, addr); });
  if (locks_.size() == before) return false;
  locksVersion_.fetch_add(1, std::memory_order_release);
  return true;
}

std::vector<formats::Assignment> Exchange::locks() const {
  std::lock_guard<std::mutex> g(lockMu_);
  return locks_;
}

} // namespace lj::rt

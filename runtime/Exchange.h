// Thread-safe exchange between the scan thread and every other thread of `ladderjit serve`:
// consistent snapshots of the state, writes applied at tick boundaries, and the lock list.
#pragma once

#include "formats/Address.h"
#include "ladderjit/abi.h"

#include <array>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <mutex>
#include <vector>

namespace lj::rt {

/// The scan thread never waits for a client: snapshots are seqlocked double buffers, and the
/// queues clients append to are drained with try_lock (a busy queue is drained next tick).
class Exchange {
public:
  Exchange();
  ~Exchange();
  Exchange(const Exchange &) = delete;
  Exchange &operator=(const Exchange &) = delete;

  // ---- scan thread -------------------------------------------------------------------------

  /// Start of a tick: apply the writes posted so far (in post order), then the lock list.
  /// Marks the applied writes so waitApplied() returns for them.
  void applyPending(lj_state &s);
  /// Write every locked value into `s` (before and after each scan, hnc8-core.md 6.1 (b)).
  void applyLocks(lj_state &s);
  /// After a tick: make `s` (as of the end of tick `tick`) the state snapshot() returns.
  void publish(const lj_state &s, uint64_t tick);

  // ---- any thread --------------------------------------------------------------------------

  /// Copy of the last published state (never torn). Returns false (and leaves `out` alone)
  /// while nothing has been published yet. `tick`, when given, receives its tick number.
  bool snapshot(lj_state &out, uint64_t *tick = nullptr) const;
  /// Queue writes to be applied together at the start of the next tick; returns their sequence
  /// number (> 0) for waitApplied. Callers check the addresses (formats::checkWritable) first.
  uint64_t post(std::vector<formats::Assignment> writes);
  /// Wait until the writes of `seq` have been applied and the tick that applied them has been
  /// published (a snapshot() now shows them), true; false when `timeout` passed first.
  bool waitApplied(uint64_t seq, std::chrono::milliseconds timeout) const;
  /// Sequence number of the last applied and published post (0 = none yet).
  uint64_t appliedSeq() const { return applied_.load(std::memory_order_acquire); }
  /// Tick number of the last publish (valid when published() is true).
  uint64_t lastTick() const;
  bool published() const { return version_.load(std::memory_order_acquire) != 0; }

  /// Lock `a.addr` at `a.value` (replaces an existing lock on the same address). The lock is
  /// in force from the next tick on.
  void lock(const formats::Assignment &a);
  /// Remove the lock on `addr`; false when there was none.
  bool unlock(const formats::CliAddress &addr);
  /// The current lock list, in the order the locks were set.
  std::vector<formats::Assignment> locks() const;

private:
  struct Buffer; // one seqlocked copy of the state

  // Seqlock: version_ counts publishes; buffer (version_ & 1) holds the newest one.
  std::array<std::unique_ptr<Buffer>, 2> buf_;
  std::atomic<uint64_t> version_{0};

  mutable std::mutex postMu_; // clients only; the scan thread try_locks
  std::vector<std::pair<uint64_t, std::vector<formats::Assignment>>> pending_;
  uint64_t nextSeq_ = 1;
  std::atomic<uint64_t> applied_{0};
  uint64_t appliedInTick_ = 0; // scan thread: last seq applied, not yet published

  mutable std::mutex lockMu_; // clients only; the scan thread try_locks
  std::vector<formats::Assignment> locks_;
  std::atomic<uint64_t> locksVersion_{0};
  std::vector<formats::Assignment> scanLocks_; // the scan thread's copy
  uint64_t scanLocksVersion_ = 0;
};

} // namespace lj::rt

// The retentive store of `ladderjit serve` and the HAL component: the retentive part of a
// target's state (HNC-8: B0..B49, timers T300..T427, counters C300..C427; FANUC: K, T, C, D;
// IEC: %M0..%M63) persisted crash-safely to one file (format and guarantees: docs/retain.md).
#pragma once

#include "ir/Profile.h"
#include "ladderjit/abi.h"

#include <array>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace lj::services {

/// Number of retained timer / counter slots: T300..T427 and C300..C427 (slots 128..255).
inline constexpr int kRetainedTcFirstSlot = 128;
inline constexpr int kRetainedTcCount = 128;

/// One retained byte range of lj_state.
struct RetainSpan {
  uint32_t offset = 0; ///< byte offset inside lj_state
  uint32_t bytes = 0;
  bool operator==(const RetainSpan &) const = default;
};

/// What a target retains: byte ranges of lj_state in offset order (adjacent ranges merged),
/// taken from its profile (retentiveAreas, retentiveTimers, retentiveCounters).
struct RetainLayout {
  std::string profile;           ///< the profile's name ("hnc8", "fanuc", "iec")
  std::vector<RetainSpan> spans; ///< the payload, in this order
  int timerSpan = -1;            ///< index of the span holding retained lj_timer slots, or -1
  bool format1 = false;          ///< HNC-8: the file is format 1 (docs/retain.md)
  uint32_t payloadBytes() const;
};

/// The layout of `tp` (HNC-8: B, T300..T427, C300..C427, written as format 1).
RetainLayout retainLayoutOf(const TargetProfile &tp);

/// The retained part of an lj_state, as captured at the end of one tick.
struct RetainImage {
  uint64_t tick = 0;                ///< tick whose end state this is
  uint64_t nowMs = 0;               ///< now_ms of that tick (timer timestamps are relative to it)
  uint64_t index = 0;               ///< capture number, 1, 2, ... (0 = nothing captured)
  std::vector<unsigned char> bytes; ///< the spans of the layout, concatenated
};

/// Copy the retained fields of `layout` from `from` into `to`.
void copyRetained(const RetainLayout &layout, const lj_state &from, lj_state &to);

/// What restore() found.
enum class RestoreStatus {
  Restored,       ///< the main file was good and is loaded
  RestoredPrev,   ///< the main file was bad; FILE.prev was good and is loaded
  NoFile,         ///< neither file exists (first start): zeros
  BothBad,        ///< both files unusable: zeros
  LayoutMismatch, ///< a file of another layout: refused (nothing loaded)
  LayoutForced,   ///< a file of another layout, --retain-force: zeros, the file is replaced
  DamagedNotKept, ///< a damaged file could not be moved aside: refused (nothing is written)
};

/// restore() result: the status and the log lines explaining it (already passed to the log).
struct RestoreReport {
  RestoreStatus status = RestoreStatus::NoFile;
  std::string message;
  uint64_t saveSeq = 0; ///< save number of the loaded file (0 when nothing was loaded)
};

/// Configuration of one store.
struct RetainConfig {
  std::string path;                             ///< the file; FILE.prev and FILE.tmp beside it
  std::chrono::milliseconds period{100};        ///< minimum gap between periodic saves
  bool force = false;                           ///< --retain-force (see RestoreStatus)
  std::string programHash;                      ///< "sha256:..." when known, else empty
  const TargetProfile *profile = nullptr;       ///< what is retained; nullptr: HNC-8
  std::function<void(const std::string &)> log; ///< one line per event; default: stderr
};

/// Save statistics (for `serve` at exit and the tests).
struct RetainStats {
  uint64_t saves = 0;       ///< files written durably
  uint64_t failures = 0;    ///< writes that failed (each logged)
  uint64_t captures = 0;    ///< end-of-tick copies taken by the scan thread
  uint64_t lastSaveSeq = 0; ///< save number of the newest durable file
};

/// The store. Threads: restore() before the scan starts; afterTick()/requestSave() on the scan
/// thread (no locks, no syscalls: a copy into a triple buffer); commit() on any other thread;
/// a background writer thread does every file operation.
class RetainStore {
public:
  explicit RetainStore(RetainConfig config);
  ~RetainStore(); ///< stops the writer (without a final save: call stop() for that)
  RetainStore(const RetainStore &) = delete;
  RetainStore &operator=(const RetainStore &) = delete;

  /// Before restore() in a server: check the location and hold the store for this process.
  /// False (with `error`) when the directory is missing, FILE or FILE.prev exists and is not a
  /// regular file (a FIFO, a symlink, a device), or another process holds FILE.lock (an
  /// exclusive flock kept until the store is destroyed). Removes temp files a crash left.
  bool prepare(std::string &error);

  /// Load the retained fields into `s` (call after lj_state_reset, before init). Timers are
  /// rebased to `nowMs` so a retained timer keeps the age it had at the save (docs/retain.md).
  /// Falls back to FILE.prev, then to zeros, logging why.
  RestoreReport restore(lj_state &s, uint64_t nowMs);

  /// Start the background writer. Call once, after restore().
  void start();

  /// Scan thread, after every tick: copy the retained fields when they changed (or a save was
  /// requested). Cheap: a compare and a 4 KiB copy, no locks or syscalls.
  void afterTick(const lj_state &s, uint64_t tick);

  /// Ask for a save of the state at the end of the current tick, outside the rate limit (the
  /// SAVEDATA block's host call). Any thread, including the scan thread inside a tick.
  void requestSave();

  /// Any thread except the scan thread: block until a save containing every write applied to
  /// the state before this call is durable (group commit), or `timeout`. True when durable.
  bool commit(std::chrono::milliseconds timeout);

  /// Clean shutdown: capture `finalState`, write it, stop the writer. Call once, after the
  /// scan thread stopped (or from its stop hook).
  void stop(const lj_state &finalState, uint64_t tick);

  RetainStats stats() const;
  const RetainLayout &layout() const { return layout_; }
  /// Copy the retained fields of this store's layout from `from` into `to`.
  void copyRetained(const lj_state &from, lj_state &to) const {
    services::copyRetained(layout_, from, to);
  }

  /// Outcome of reading one file.
  enum class ReadResult { Ok, Missing, Corrupt, Layout };
  /// Read and check one store file (no fallback): the image, its save number and the program
  /// hash it was saved with, or `error` naming the problem. Used by restore() and the tests.
  static ReadResult readFile(const RetainLayout &layout, const std::string &path, RetainImage &out,
                             uint64_t &saveSeq, std::string &savedHash, std::string &error);

private:
  void writerLoop();
  bool takeLatest(); ///< writer: make slots_[front_] the newest capture; false if none is new
  bool writeFile(const RetainImage &img, std::string &error);
  void logLine(const std::string &line) const;
  /// Whether the retained spans of `s` equal `img`'s bytes.
  bool sameAs(const RetainImage &img, const lj_state &s) const;
  void capture(RetainImage &img, const lj_state &s) const;

  RetainConfig cfg_;
  RetainLayout layout_;
  // Triple buffer: the scan thread fills slots_[back_], then swaps it with middle_; the writer
  // swaps front_ with middle_ when the fresh bit is set. Neither side ever waits.
  std::array<RetainImage, 3> slots_;
  int back_ = 0;               // scan thread only
  int front_ = 2;              // writer only
  std::atomic<int> middle_{1}; // slot index | kFresh
  RetainImage last_;           // scan thread: last capture (change detection)
  bool haveLast_ = false;      // scan thread
  std::atomic<uint64_t> captures_{0};
  std::atomic<bool> forceCapture_{false};
  std::atomic<uint64_t> wantIndex_{0}; // writer must make a capture >= this durable at once
  std::atomic<bool> refused_{false};   // layout mismatch without force: never write

  mutable std::mutex mu_; // guards the fields below and the condition variables
  std::condition_variable writerCv_;
  std::condition_variable doneCv_;
  uint64_t durableIndex_ = 0; // capture index of the newest durable file
  bool stopping_ = false;
  bool started_ = false;
  RetainStats stats_;
  uint64_t saveSeq_ = 0;   // save number of the newest file on disk
  bool mainIsGood_ = true; // false: do not rotate the current FILE into FILE.prev
  std::thread writer_;
  int lockFd_ = -1; // FILE.lock, flocked by prepare()
};

} // namespace lj::services

// The background half of a quick online change (docs/serve.md "Online change latency"): an
// online change runs the rung groups it touched at the fast tier (EngineTier::JitQuick) so the
// new code runs within milliseconds; this thread then builds the same program with every group
// optimized (the untouched ones come from the session's cache) and switches it in at a tick
// boundary like interpreter-first tiering (Executive::tierUp: same lj_state, no init, nothing
// cleared). A newer change supersedes the version waiting to be optimized.
#pragma once

#include "runtime/Executive.h"
#include "runtime/ProgramLoader.h"

#include <atomic>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <thread>

namespace lj::rt {

class ChangeOptimizer {
public:
  ChangeOptimizer(Executive &exec, ProgramLoader &loader, Executive::Log log);
  /// Stops and joins the thread (a compile in progress, one group or a few, ends first).
  ~ChangeOptimizer();
  ChangeOptimizer(const ChangeOptimizer &) = delete;
  ChangeOptimizer &operator=(const ChangeOptimizer &) = delete;

  /// Optimize `v` (just swapped in, tier JitQuick) next; replaces a version not yet started.
  void offer(std::shared_ptr<ProgramVersion> v);
  /// No further switch; the thread ends after the compile in progress.
  void stop();
  /// Whether a build is in progress or waiting.
  bool busy() const { return busy_.load(std::memory_order_acquire); }

private:
  void run();

  Executive &exec_;
  ProgramLoader &loader_;
  Executive::Log log_;
  std::mutex mu_;
  std::condition_variable cv_;
  std::shared_ptr<ProgramVersion> next_; // guarded by mu_
  bool stop_ = false;                    // guarded by mu_
  std::atomic<bool> busy_{false};
  std::thread thread_;
};

} // namespace lj::rt

// The background optimized build after a quick online change (runtime/ChangeOptimizer.h).
#include "runtime/ChangeOptimizer.h"

#include <chrono>

#include <sys/resource.h>
#include <unistd.h>

namespace lj::rt {

ChangeOptimizer::ChangeOptimizer(Executive &exec, ProgramLoader &loader, Executive::Log log)
    : exec_(exec), loader_(loader), log_(std::move(log)) {}

ChangeOptimizer::~ChangeOptimizer() {
  stop();
  if (thread_.joinable()) thread_.join();
}

void ChangeOptimizer::stop() {
  {
    std::lock_guard<std::mutex> g(mu_);
    stop_ = true;
    next_.reset();
  }
  cv_.notify_all();
}

void ChangeOptimizer::offer(std::shared_ptr<ProgramVersion> v) {
  if (!v || v->tier != EngineTier::JitQuick) return;
  {
    std::lock_guard<std::mutex> g(mu_);
    if (stop_) return;
    next_ = std::move(v);
    busy_.store(true, std::memory_order_release);
    if (!thread_.joinable()) thread_ = std::thread([this] { run(); });
  }
  cv_.notify_all();
}

void ChangeOptimizer::run() {
  // Never in the way of a tick or of the next change: the lowest CPU weight, as tiering's.
  (void)::setpriority(PRIO_PROCESS, static_cast<id_t>(::gettid()), 19);
  for (;;) {
    std::shared_ptr<ProgramVersion> v;
    {
      std::unique_lock<std::mutex> g(mu_);
      busy_.store(next_ != nullptr, std::memory_order_release);
      cv_.wait(g, [&] { return stop_ || next_; });
      if (stop_) {
        busy_.store(false, std::memory_order_release);
        return;
      }
      v = std::move(next_);
    }
    std::string error;
    std::shared_ptr<ProgramVersion> opt = loader_.buildTier(*v, EngineTier::JitOpt, error);
    {
      std::lock_guard<std::mutex> g(mu_);
      if (stop_ || next_) continue; // stopping, or a newer change to optimize instead
    }
    if (!opt) {
      if (log_)
        log_("optimizer: the optimized build of version " + std::to_string(v->id) +
             " failed, it keeps running as " + engineTierName(v->tier) + ": " + error);
      continue;
    }
    // Refused when another change came first (counted as a tiering refusal).
    if (!exec_.tierUp(opt, std::chrono::seconds(5), error) && log_ && exec_.running())
      log_("optimizer: the optimized build of version " + std::to_string(v->id) +
           " not switched in: " + error);
  }
}

} // namespace lj::rt

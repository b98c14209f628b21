// The background compile of interpreter-first tiering in serve (runtime/TierUp.h).
#include "runtime/TierUp.h"

#include <chrono>

#include <sys/resource.h>
#include <unistd.h>

namespace lj::rt {

const char *tierPlanName(TierPlan p) {
  switch (p) {
  case TierPlan::Direct:
    return "direct";
  case TierPlan::InterpFirst:
    return "interp-first";
  case TierPlan::InterpFastOpt:
    return "interp-fast-opt";
  }
  return "direct";
}

std::optional<TierPlan> parseTierPlan(std::string_view text, std::string &error) {
  for (TierPlan p : {TierPlan::Direct, TierPlan::InterpFirst, TierPlan::InterpFastOpt})
    if (text == tierPlanName(p)) return p;
  error =
      "--tier: expected direct, interp-first or interp-fast-opt, got '" + std::string(text) + "'";
  return std::nullopt;
}

std::vector<EngineTier> backgroundTiers(TierPlan p) {
  switch (p) {
  case TierPlan::Direct:
    return {};
  case TierPlan::InterpFirst:
    return {EngineTier::JitOpt};
  case TierPlan::InterpFastOpt:
    return {EngineTier::JitFast, EngineTier::JitOpt};
  }
  return {};
}

TierUp::TierUp(Executive &exec, ProgramLoader &loader, Executive::Log log)
    : exec_(exec), loader_(loader), log_(std::move(log)) {}

TierUp::~TierUp() {
  stop();
  if (thread_.joinable()) thread_.join();
}

void TierUp::detach() {
  if (thread_.joinable()) thread_.detach();
}

void TierUp::start(std::shared_ptr<ProgramVersion> v, std::vector<EngineTier> tiers) {
  if (thread_.joinable() || tiers.empty() || !v) return;
  busy_.store(true, std::memory_order_release);
  thread_ = std::thread([this, v = std::move(v), tiers = std::move(tiers)]() mutable {
    // The compile must never delay a tick: this thread (and the compile threads it starts,
    // which inherit it) runs at the lowest CPU weight, so a scan thread at normal priority on a
    // busy core keeps its deadlines. Failing to lower it only costs that margin.
    (void)::setpriority(PRIO_PROCESS, static_cast<id_t>(::gettid()), 19);
    run(std::move(v), std::move(tiers));
    busy_.store(false, std::memory_order_release);
  });
}

void TierUp::run(std::shared_ptr<ProgramVersion> v, std::vector<EngineTier> tiers) {
  for (EngineTier t : tiers) {
    if (stop_.load(std::memory_order_acquire)) return;
    std::string error;
    std::shared_ptr<ProgramVersion> next = loader_.buildTier(*v, t, error);
    if (!next) {
      if (log_)
        log_(std::string("tiering: building ") + engineTierName(t) + " failed, the program " +
             "keeps running on " + engineTierName(v->tier) + ": " + error);
      return;
    }
    if (stop_.load(std::memory_order_acquire)) return;
    // The scan thread takes it at its next tick boundary (5 s cover any period, at most 1 s).
    if (!exec_.tierUp(next, std::chrono::seconds(5), error)) {
      if (log_ && exec_.running())
        log_(std::string("tiering: ") + engineTierName(t) + " not switched in: " + error);
      return;
    }
    v = std::move(next);
  }
}

} // namespace lj::rt

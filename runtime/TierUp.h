// Interpreter-first tiering (docs/serve.md "Tiering", issue 13 scope 3): the first tick runs on
// the interpreter at once; the JIT code of the same program is compiled on a background thread
// and switched in at a tick boundary with the same lj_state (Executive::tierUp). Every engine
// keeps all program state in lj_state (the interpreter only keeps scratch stacks that each part
// starts afresh, interp/Interpreter.h; compiled code has no globals), so the switch carries
// everything by construction; `ladderjit fuzz --switch` checks it.
#pragma once

#include "runtime/Executive.h"
#include "runtime/ProgramLoader.h"

#include <atomic>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

namespace lj::rt {

/// `--tier` of `run` and `serve`.
enum class TierPlan : uint8_t {
  Direct,        ///< the engine is built before the first tick (no switch)
  InterpFirst,   ///< interpreter, then the optimizing JIT
  InterpFastOpt, ///< interpreter, then the fast JIT, then the optimizing JIT
};

/// "direct", "interp-first", "interp-fast-opt".
const char *tierPlanName(TierPlan p);
/// Parse the `--tier` value; InvalidArgument-style message in `error` when it is none of them.
std::optional<TierPlan> parseTierPlan(std::string_view text, std::string &error);
/// The JIT tiers a plan builds in the background, in switch order (Direct: none).
std::vector<EngineTier> backgroundTiers(TierPlan p);

/// The background compile of serve: builds each tier of the plan for the running version, one
/// after another, and hands each to the executive at a tick boundary. A tier that cannot be
/// built, or an online change that came first, ends it (logged); the program keeps running on
/// what it runs.
class TierUp {
public:
  TierUp(Executive &exec, ProgramLoader &loader, Executive::Log log);
  /// Joins the thread (which may wait for a compile to end): call stop() and check busy() first
  /// when that must not block.
  ~TierUp();
  TierUp(const TierUp &) = delete;
  TierUp &operator=(const TierUp &) = delete;

  /// Start building `tiers` for `v` (the version the executive runs). Once only.
  void start(std::shared_ptr<ProgramVersion> v, std::vector<EngineTier> tiers);
  /// No further switch after the compile in progress (which LLVM cannot interrupt).
  void stop() { stop_.store(true, std::memory_order_release); }
  /// Whether the thread is still compiling or switching.
  bool busy() const { return busy_.load(std::memory_order_acquire); }
  /// Let the thread end with the process (serve's fast exit) instead of joining it.
  void detach();

private:
  void run(std::shared_ptr<ProgramVersion> v, std::vector<EngineTier> tiers);

  Executive &exec_;
  ProgramLoader &loader_;
  Executive::Log log_;
  std::atomic<bool> stop_{false}, busy_{false};
  std::thread thread_;
};

} // namespace lj::rt

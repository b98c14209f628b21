// One program running on one engine, driven like a host would: reset, init, ticks with
// now_ms = tick * period, inputs written between ticks. The building block of every exec test.
#pragma once

#include "frontends/hnc8/FrontEnd.h"
#include "ir/Engine.h"
#include "ir/Program.h"
#include "ladderjit/abi.h"
#include "tests/support/EngineRegistry.h"
#include "verify/Verify.h"

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lj::test {

/// Front-end options for tests with a smaller PLC2 slice when wanted.
VerifyOptions optionsWithNvalue(int32_t plc2Nvalue);

/// parseStl + verify. On an error, records a GoogleTest failure carrying the rendered
/// diagnostics and returns nothing.
std::optional<VerifiedProgram> compileOrFail(std::string_view text,
                                             const VerifyOptions &opts = VerifyOptions{});

/// A write applied by the host before tick `tick` runs (tick 0 is the first tick after init).
struct Stimulus {
  uint32_t tick = 0;
  std::string addr;
  int64_t value = 0;
};

/// Inputs over time, for runs that are compared across engines.
struct Scenario {
  uint32_t ticks = 1;
  uint32_t periodMs = 1;
  uint64_t maxBackwardSteps = 1000000;
  std::vector<Stimulus> before; ///< applied after reset, before init
  std::vector<Stimulus> inputs; ///< applied before their tick
  /// Host writes that address text cannot express compactly (computed from the tick number,
  /// whole arrays, generated stimuli). `hostBefore` runs after `before`; `hostInputs(tick, s)`
  /// runs before every tick, after that tick's `inputs`.
  std::function<void(lj_state &)> hostBefore;
  std::function<void(uint32_t tick, lj_state &)> hostInputs;

  Scenario &preset(std::string addr, int64_t v) {
    before.push_back({0, std::move(addr), v});
    return *this;
  }
  Scenario &at(uint32_t tick, std::string addr, int64_t v) {
    inputs.push_back({tick, std::move(addr), v});
    return *this;
  }
};

/// A verified program bound to one engine and one lj_state (reset to power-up on creation).
class Machine {
public:
  /// Compile `text` and build the engine; records a failure and returns null on any error.
  static std::unique_ptr<Machine> load(std::string_view text, const EngineFactory &engine,
                                       const VerifyOptions &opts = VerifyOptions{});
  /// Build the engine for an already verified program (copied, so it outlives the engine).
  static std::unique_ptr<Machine> create(const VerifiedProgram &prog, const EngineFactory &engine);

  /// Run the init part at now_ms = 0 (lj_run_init). Returns its fault code.
  uint32_t init();
  /// One tick: now_ms = tickIndex() * period, then lj_tick. Returns the tick's fault code.
  uint32_t tick();
  /// `n` ticks; returns the fault code of the last one.
  uint32_t ticks(uint32_t n);
  /// Apply the scenario writes meant for the next tick (`inputs`, then `hostInputs`), then run it.
  uint32_t tick(const Scenario &sc);

  /// Read a bit, element, timer or counter (TestAddress.h forms).
  int64_t get(std::string_view addr) const;
  /// Host-side write (inputs, presets).
  void set(std::string_view addr, int64_t value);

  lj_state &state() { return *state_; }
  const lj_state &state() const { return *state_; }
  const VerifiedProgram &program() const { return *prog_; }
  const Engine &engine() const { return *engine_; }
  /// Index of the next tick to run.
  uint32_t tickIndex() const { return tick_; }
  void setPeriodMs(uint32_t ms) { periodMs_ = ms; }

private:
  Machine() = default;
  std::unique_ptr<VerifiedProgram> prog_;
  std::unique_ptr<Engine> engine_;
  std::unique_ptr<lj_state> state_;
  uint32_t tick_ = 0;
  uint32_t periodMs_ = 1;
};

} // namespace lj::test

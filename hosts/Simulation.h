// The simulation driver behind `ladderjit run`: power-up inputs, init, then ticks with stimulus,
// now_ms = tick * period and a watch row after every tick. Engine-agnostic: it only needs the
// lj_entries of an Engine (interpreter, JIT or AOT).
#pragma once

#include "formats/Address.h"
#include "formats/InputFiles.h"
#include "hosts/SimNc.h"
#include "ladderjit/abi.h"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace lj::hosts {

/// What to simulate.
struct SimOptions {
  uint64_t ticks = 1;                      ///< ticks to run, numbered 0..ticks-1
  uint64_t periodMs = 1;                   ///< PLC1 period; now_ms = tick * periodMs
  uint64_t maxBackwardSteps = 1000000;     ///< watchdog limit per tick (DIALECT.md 4)
  std::vector<formats::Assignment> params; ///< `--params` file, applied first (P is configuration)
  std::vector<formats::Assignment> sets;   ///< `--set`, applied after params, before init
  formats::Stimulus stimulus;              ///< applied before the scan of each event's tick
  std::vector<formats::CliAddress> watch;  ///< read after every tick
  const TargetProfile *profile = nullptr;  ///< whose system bits are written before each tick
};

/// One watch row: the tick number, the fault of that tick and the watched values in order.
struct WatchRow {
  uint64_t tick = 0;
  uint32_t fault = LJ_FAULT_NONE;
  std::vector<int64_t> values;
};

/// Receives every tick's row as soon as it is computed (so long runs stream).
using RowSink = std::function<void(const WatchRow &)>;

/// Result of a whole run.
struct SimResult {
  uint32_t initFault = LJ_FAULT_NONE;
  uint64_t faultTicks = 0; ///< ticks that ended with a fault
};

/// A run in steps, for callers that report between init and the ticks. Order (README
/// "Simulation order"): powerUp() = lj_state_reset, watchdog limit, the NC's power-up, params,
/// --set, now_ms = 0, lj_run_init; then each step() = the stimulus assignments of tick t (file
/// order), the tick's NC commands, the NC's beforeTick, now_ms = t * period, lj_tick, the NC's
/// afterTick, the watch list read into the row (docs/simulated-nc.md). Faults never stop the
/// run. Without an NC (nullptr) the NC steps are skipped and NC commands are ignored.
class Simulation {
public:
  /// `entries`, `s`, `opts` and `nc` must outlive the simulation.
  Simulation(const lj_entries &entries, lj_state &s, const SimOptions &opts, SimNc *nc = nullptr)
      : entries_(&entries), s_(s), opts_(opts), nc_(nc) {}
  /// Run the following ticks on other code for the same program (interpreter-first tiering,
  /// docs/serve.md "Tiering"): only the entry table changes, the state goes on as it is.
  /// `entries` must outlive the simulation. Call between steps.
  void setEntries(const lj_entries &entries) { entries_ = &entries; }
  /// The number of the next tick step() runs.
  uint64_t nextTick() const { return tick_; }
  /// Reset to power-up and run init; returns init's fault code.
  uint32_t powerUp();
  /// Whether all `opts.ticks` ticks have run.
  bool done() const { return tick_ >= opts_.ticks; }
  /// Run the next tick and fill `row`; returns the tick's fault code.
  uint32_t step(WatchRow &row);

private:
  const lj_entries *entries_;
  lj_state &s_;
  const SimOptions &opts_;
  SimNc *nc_;
  uint64_t tick_ = 0;
  size_t nextEvent_ = 0;
};

/// powerUp, then every tick, calling `sink` after each one (with the simulated NC `nc`, if any).
SimResult simulate(const lj_entries &entries, lj_state &s, const SimOptions &opts,
                   const RowSink &sink, SimNc *nc = nullptr);

/// Name of a fault code for messages ("watchdog").
const char *faultName(uint32_t fault);

} // namespace lj::hosts

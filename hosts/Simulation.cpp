// The simulation loop of `ladderjit run` (DIALECT.md 4: inputs between ticks, now_ms per tick).
#include "hosts/Simulation.h"
#include "hosts/SystemBits.h"

namespace lj::hosts {

namespace {

void apply(lj_state &s, const std::vector<formats::Assignment> &list) {
  for (const formats::Assignment &a : list) writeAddress(s, a.addr, a.value);
}

// F/G words the user drives: the NC leaves them alone, so stimulus files written before the
// simulated NC existed (they play the NC by writing F) keep their meaning.
void leaveUserWords(SimNc &nc, const SimOptions &opts) {
  auto leave = [&](const std::vector<formats::Assignment> &list) {
    for (const formats::Assignment &a : list)
      if (a.addr.area == Area::NcStatus || a.addr.area == Area::NcControl)
        nc.leaveWord(a.addr.area == Area::NcStatus, a.addr.index);
  };
  leave(opts.params);
  leave(opts.sets);
  for (const formats::StimulusEvent &ev : opts.stimulus.events) leave(ev.sets);
}

} // namespace

uint32_t Simulation::powerUp() {
  lj_state_reset(&s_);
  s_.max_backward_steps = opts_.maxBackwardSteps;
  if (nc_) {
    leaveUserWords(*nc_, opts_);
    nc_->powerUp(s_); // idle F values first, so --set can still override them
  }
  // Power-up: P comes from the parameter file (DIALECT.md 1); --set then acts like inputs that
  // are already present at power-up, so init sees them.
  apply(s_, opts_.params);
  apply(s_, opts_.sets);
  s_.now_ms = 0;
  tick_ = 0;
  nextEvent_ = 0;
  return lj_run_init(&s_, entries_);
}

uint32_t Simulation::step(WatchRow &row) {
  const std::vector<formats::StimulusEvent> &events = opts_.stimulus.events;
  // Events are sorted by tick (parseStimulus enforces it); all of this tick's, in file order:
  // first every assignment, then every NC command.
  size_t first = nextEvent_;
  while (nextEvent_ < events.size() && events[nextEvent_].tick <= tick_)
    apply(s_, events[nextEvent_++].sets);
  if (nc_) {
    for (size_t i = first; i < nextEvent_; ++i)
      for (const formats::NcCommand &c : events[i].nc) nc_->apply(c);
    nc_->beforeTick(s_, tick_);
  }
  s_.now_ms = tick_ * opts_.periodMs;
  if (opts_.profile) writeSystemBits(*opts_.profile, s_, tick_);
  uint32_t fault = lj_tick(&s_, entries_);
  if (nc_) nc_->afterTick(s_, tick_);
  row.tick = tick_;
  row.fault = fault;
  row.values.resize(opts_.watch.size());
  for (size_t i = 0; i < opts_.watch.size(); ++i)
    row.values[i] = formats::readAddress(s_, opts_.watch[i]);
  ++tick_;
  return fault;
}

SimResult simulate(const lj_entries &entries, lj_state &s, const SimOptions &opts,
                   const RowSink &sink, SimNc *nc) {
  SimResult result;
  Simulation sim(entries, s, opts, nc);
  result.initFault = sim.powerUp();
  WatchRow row;
  while (!sim.done()) {
    if (sim.step(row) != LJ_FAULT_NONE) ++result.faultTicks;
    if (sink) sink(row);
  }
  return result;
}

const char *faultName(uint32_t fault) {
  switch (fault) {
  case LJ_FAULT_NONE:
    return "none";
  case LJ_FAULT_WATCHDOG:
    return "watchdog";
  default:
    return "unknown fault";
  }
}

} // namespace lj::hosts

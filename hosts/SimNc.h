// The simulated NC behind `ladderjit run`: a deterministic, tick-driven model of channels, axes
// and spindles that reads the PLC's G words and writes F words between ticks, and implements
// every lj_host callback (hnc8-cnc-interface.md sections 1 and 3; docs/simulated-nc.md).
#pragma once

#include "formats/NcCommand.h"
#include "ladderjit/abi.h"

#include <nlohmann/json_fwd.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace lj::hosts {

/// Sizes, timing (in ticks) and the fixed machine layout of the simulated NC.
struct SimNcConfig {
  int channels = 4; ///< 1..4 (channel words F/G 2560 + 80*C)
  int axes = 32;    ///< 1..32 (axis words F/G 80*A)
  int tools = 100;  ///< tool objects of variable type 9 (offset = 200*t + item)
  int pockets = 24; ///< magazine pockets 1..pockets for TOOL
  /// Logical axis numbers of each channel's 9 axes (FC[21..29]), -1 = none. Default: channel 0
  /// has axes 0, 1, 2.
  std::array<std::array<int16_t, 9>, 4> channelAxes{};
  /// Logical axis of each channel's 4 spindles (FC[30..33]), -1 = none. Default: channel 0
  /// spindle 0 is axis 5 (hnc8-cnc-interface.md 6.2 SPDLBUS example).
  std::array<std::array<int16_t, 4>, 4> channelSpindles{};
  uint32_t enableDelay = 2;  ///< GA[0].7 / GA[3].0 -> FA[2].8 / FA[3].0, ticks
  uint32_t homeZDelay = 3;   ///< ticks of phase 2 (Z search) unless `nc.zpulse` ends it
  uint32_t orientDelay = 4;  ///< GA[2].12 -> FA[3].8, ticks
  int32_t jogStep = 1000;    ///< position units (0.001 mm) per jogging tick
  int32_t rapidStep = 5000;  ///< position units per tick at jog speed 2 (rapid)
  int32_t spindleJog = 100;  ///< spindle speed of the feed-spindle keys GA[1].6/7
  int32_t pmcStep = 1000;    ///< position units per tick of a PMC move
  int32_t spindleRamp = 500; ///< spindle speed change per tick (units of GC[10+2sp])
  /// Host calls and events kept: 0 = all of them (`run`, whose dump shows them); N = the last N
  /// of each, a ring overwritten in place (a long-running `serve`, docs/simulated-nc.md).
  size_t logLimit = 0;
  SimNcConfig();
};

/// One recorded happening, in order: a G-area bit change (alarm/event/prompt) or a host call.
struct NcEvent {
  int64_t tick = 0; ///< tick number; -1 = power-up / init
  std::string what; ///< e.g. "alarm 3 on", "event 116 on", "mcode ch0 m3 done"
  bool operator==(const NcEvent &) const = default;
};

/// One lj_host callback invocation: name, value arguments in ABI order, values written through
/// pointer arguments, result (0 for void calls).
struct NcCall {
  int64_t tick = 0; ///< tick number; -1 = the init part
  std::string name; ///< the lj_host member name, e.g. "var_get"
  std::vector<int64_t> args;
  std::vector<int64_t> out; ///< *value of var_get; *pocket, *error of tool_select
  int64_t result = 0;
  bool operator==(const NcCall &) const = default;
};

/// An append-only log, or with a limit the last `limit` entries: a ring whose slots are
/// overwritten in place, so entries that fit their slot's capacity cost no allocation.
template <typename T> class NcLog {
public:
  /// 0 = unlimited. Clears the log.
  void setLimit(size_t limit) {
    limit_ = limit;
    clear();
    items_.reserve(limit);
  }
  /// The slot of the next entry (oldest one overwritten when full); the caller fills it.
  T &next() {
    if (limit_ == 0 || items_.size() < limit_) return items_.emplace_back();
    T &slot = items_[head_];
    head_ = head_ + 1 == limit_ ? 0 : head_ + 1;
    ++dropped_;
    return slot;
  }
  void clear() {
    items_.clear();
    head_ = 0;
    dropped_ = 0;
  }
  /// The entries kept, oldest first.
  std::vector<T> ordered() const {
    std::vector<T> out(items_.begin() + static_cast<std::ptrdiff_t>(head_), items_.end());
    out.insert(out.end(), items_.begin(), items_.begin() + static_cast<std::ptrdiff_t>(head_));
    return out;
  }
  /// f(entry) for the entries kept, oldest first.
  template <typename F> void forEach(F &&f) const {
    for (size_t i = head_; i < items_.size(); ++i) f(items_[i]);
    for (size_t i = 0; i < head_; ++i) f(items_[i]);
  }
  size_t size() const { return items_.size(); }
  /// Entries overwritten since the last clear.
  uint64_t dropped() const { return dropped_; }
  bool operator==(const NcLog &o) const {
    return dropped_ == o.dropped_ && ordered() == o.ordered();
  }

private:
  std::vector<T> items_;
  size_t limit_ = 0, head_ = 0;
  uint64_t dropped_ = 0;
};

/// A CNC variable's stored value: int32/int64 types keep `i`, float types keep `f`.
struct NcVar {
  bool isFloat = false;
  int64_t i = 0;
  double f = 0;
  bool operator==(const NcVar &) const = default;
};

/// The simulated NC. Per tick the host calls beforeTick, runs the scan, then afterTick; nothing
/// here runs inside a scan except the lj_host callbacks, which only touch the model.
class SimNc {
public:
  /// A model with `cfg` (channels/axes clamped to 1..4 / 1..32).
  explicit SimNc(const SimNcConfig &cfg = {});
  SimNc(const SimNc &) = delete; // host() points at this object
  SimNc &operator=(const SimNc &) = delete;

  /// Power-up after lj_state_reset: idle F values (FC[48..56] = -1, axis tables) and
  /// s.host = host(); G is left zero (the response words get -1 when a code is posted). Clears
  /// the model.
  void powerUp(lj_state &s);
  /// Publish F (and the NC-written G words: M/T responses, temperatures) for tick `tick`.
  void beforeTick(lj_state &s, uint64_t tick);
  /// Consume the G words the PLC wrote during tick `tick`; record alarm/event/prompt changes.
  void afterTick(lj_state &s, uint64_t tick);
  /// The callback table bound to this NC (ctx = this).
  const lj_host *host() const { return &host_; }
  /// Apply a scripted command (before beforeTick of the tick it belongs to). Commands outside
  /// the configured sizes are ignored and logged as "ignored ..." events.
  void apply(const formats::NcCommand &c);
  /// Leave F or G word `word` to the host: the NC never writes it (a stimulus file or --set
  /// drives it, so older stimulus files that play the NC keep working). Survives powerUp.
  void leaveWord(bool isF, int word);

  // ---- inspection (tests, `run --dump`, the differential fuzzer) ----
  /// The variable (type, offset), or nullptr if it was never written (reads as 0).
  const NcVar *var(int type, int offset) const;
  /// Whether (type, offset) exists with the configured sizes (hnc8-functions-2.md section 3).
  bool varExists(int type, int offset) const;
  /// Preset a variable directly (same rules as `nc.var`); false if it does not exist.
  bool setVar(int type, int offset, const NcVar &v);
  /// The events and host calls kept (all, or the last SimNcConfig::logLimit), oldest first.
  std::vector<NcEvent> events() const { return events_.ordered(); }
  std::vector<NcCall> calls() const { return calls_.ordered(); }
  /// How many older events / calls the limit dropped (0 without a limit).
  uint64_t eventsDropped() const { return events_.dropped(); }
  uint64_t callsDropped() const { return calls_.dropped(); }
  /// Tool held by magazine pocket p (0 = empty or no such pocket).
  int32_t pocketTool(int p) const;
  /// Tool shown in use by channel ch (TOOLUSE), tool-vector flag (TOOLSET/TOOLCLR).
  int32_t toolInUse(int ch) const;
  bool toolVector(int ch) const;
  /// Part count the NC read from G[2579+80*ch] after the last tick.
  int32_t partCount(int ch) const;
  /// Machine position of axis a (integrator of jog/PMC moves), current spindle speed of axis a.
  int64_t axisPosition(int a) const;
  int32_t spindleSpeed(int a) const;
  /// Converted temperature of sensor (0..19) as published in G3080+sensor.
  int32_t temperature(int sensor) const;
  /// Everything above as JSON (the "nc" object of `run --dump`).
  nlohmann::ordered_json toJson() const;
  /// A 64-bit FNV-1a digest of the whole model state and logs (differential fuzzing).
  uint64_t digest() const;
  /// Same model state and the same logs.
  bool operator==(const SimNc &o) const;

  /// The model state (channels, axes, spindles, tools, ...), defined in hosts/SimNcModel.h.
  struct Model;

private:
  friend struct SimNcHost; // the lj_host trampolines (SimNcHost.cpp)
  void bindHost();
  void putF(lj_state &s, int word, int16_t v) const; // unless the word is left to the host
  void putG(lj_state &s, int word, int16_t v) const;
  void log(const std::string &what);
  void publish(lj_state &s);
  void resetChannel(int c, const char *why);
  void channelAfterTick(const lj_state &s, int c);
  static bool varIsFloat(int type);
  int32_t scaledGet(int type, int offset, int exp, int32_t &out) const; // VARGET rule
  int32_t scaledSet(int type, int offset, int exp, int32_t value);      // VARSET rule
  int32_t daValue(int32_t rpm, int32_t gear, int32_t pbase) const;      // SPDA scaling

  SimNcConfig cfg_;
  lj_host host_{};
  int64_t tick_ = -1;         // tick being run; -1 during power-up and init
  lj_state *state_ = nullptr; // the state being run (SPDA reads its P block)
  NcLog<NcEvent> events_;
  NcLog<NcCall> calls_;
  std::map<std::pair<int, int>, NcVar> vars_;
  std::unique_ptr<Model> m_;

public:
  ~SimNc();
};

} // namespace lj::hosts

// One running program of the HAL component, without the HAL headers: loading (trusted AOT
// loader, program source for the pins and the identity check, map, P values, retain store) and
// the tick the real-time function calls. HalComponent.cpp is the HAL glue around it.
#pragma once

#include "hosts/linuxcnc/HalPlan.h"
#include "ir/Engine.h"
#include "ladderjit/abi.h"

#include <atomic>
#include <cmath>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <thread>
#include <vector>

namespace lj::services {
class RetainStore;
}

namespace lj::hal {

/// The module parameters (HalComponent.cpp, docs/linuxcnc.md).
struct Options {
  std::string program;               ///< the AOT .so
  std::string source;                ///< the program it was built from; empty: beside `program`
  std::string map;                   ///< map file, empty: default pins only
  std::string trust;                 ///< comma-separated public key files; empty: the default key
  std::string params;                ///< P values file
  std::string retain;                ///< retentive store file
  int32_t plc2Nvalue = kNvalueUnset; ///< plc2_nvalue=N (0..2^31-1), or unset
  ClassicSizes classic;              ///< a ClassicLadder source: classicladder_rt's pin sizes
  /// A ClassicLadder source: the prefix of its pins and function (names=); empty:
  /// classicladder_rt's own, kClassicPrefix.
  std::string classicName;
  static constexpr int32_t kNvalueUnset = INT32_MIN;
  std::function<void(const std::string &)> log; ///< RTAPI log (one line per call)
};

/// One loaded program: its engine (an AOT .so), entries, pin plan, target and identity.
struct Loaded {
  std::unique_ptr<Engine> engine;
  lj_entries entries{};
  std::vector<PinSpec> pins;
  const TargetProfile *profile = nullptr;
  std::string hash; ///< "sha256:..." of the program source
  /// A ClassicLadder source: the pins are classicladder_rt's (prefix classicPrefix(opt)).
  bool classic = false;
};

/// The prefix of a ClassicLadder source's pins and function: `names=`, else classicladder_rt's
/// `classicladder.0`.
std::string classicPrefix(const Options &opt);

/// Read and verify `sourcePath`, load `opt.program` through the trusted AOT loader, and plan
/// the pins (with `prefix`). False with `error` naming the file and the problem.
bool loadProgram(const Options &opt, const std::string &sourcePath, const std::string &prefix,
                 Loaded &out, std::string &error);

/// Whether two pin plans are the same pins (name, type, direction, address, scale, in order).
bool samePins(const std::vector<PinSpec> &a, const std::vector<PinSpec> &b);

/// The source beside an AOT .so: PATH without `.so` plus `.dit`, `.stl`, `.json`, `.pmc` or
/// `.il` or `.clp`, the first that exists; empty when none does.
std::string sourceBeside(const std::string &soPath);

class Instance {
public:
  /// Load everything `opt` names. Null with `error` (one line, naming the file and the problem)
  /// when anything is refused; nothing is left running then.
  static Instance *create(const Options &opt, const std::string &prefix, std::string &error);
  ~Instance();
  Instance(const Instance &) = delete;
  Instance &operator=(const Instance &) = delete;

  const std::vector<PinSpec> &pins() const { return pins_; }
  lj_state &state() { return *state_; }
  uint64_t ticks() const { return ticks_; }

  /// Real-time: one tick with inputs already written. The first call runs init first (so init
  /// sees the inputs present at start, as `ladderjit run --set` does). now_ms follows the
  /// thread period: tick n (from 0) runs at floor(n * period_ns / 1e6) ms.
  uint32_t tick(uint64_t periodNs);

  /// Whether the pins are classicladder_rt's (a ClassicLadder source: the drop-in).
  bool classicLadder() const { return classic_; }
  /// Float input pin `i` as the element value: lround(pin / scale), or truncated toward zero
  /// (PinSpec::truncate), saturated to int32.
  int64_t fromFloat(size_t i, double v) const {
    double x = pins_[i].truncate ? std::trunc(v) : v / pins_[i].scale;
    if (!(x == x)) return 0;
    if (x > 2147483647.0) return 2147483647;
    if (x < -2147483648.0) return -2147483648LL;
    return std::lround(x);
  }

  /// Online change (docs/linuxcnc.md "Online change"). Real-time: ask the loader thread to
  /// load program= and its source again (an atomic flag, nothing else).
  void requestReload();
  /// Not real-time: start / stop the loader thread (after hal_ready / before unloading).
  void startLoader();
  void stopLoader();
  uint32_t reloads() const { return reloads_.load(std::memory_order_relaxed); }
  uint32_t reloadFailures() const { return reloadFailures_.load(std::memory_order_relaxed); }

  void startRetain();
  /// The final save of the retentive fields (after HAL stopped calling tick).
  void stopRetain();
  std::string summary() const;

private:
  Instance() = default;
  /// Real-time: swap in a prepared program (pointer and entries only). True when swapped.
  bool takePending();
  void loaderLoop();
  std::unique_ptr<Engine> engine_;
  lj_entries entries_{};
  lj_state *state_ = nullptr;
  std::vector<PinSpec> pins_;
  const TargetProfile *profile_ = nullptr; ///< the program's target (system bits)
  bool classic_ = false;
  std::unique_ptr<services::RetainStore> retain_;
  std::string soPath_, sourcePath_, programHash_;
  uint64_t ticks_ = 0;
  uint64_t elapsedNs_ = 0;
  bool inited_ = false;
  bool retainStarted_ = false;
  // Online change: the loader thread fills pending_, refresh swaps it in and leaves the old
  // engine in retired_ for the loader thread to free.
  Options opt_;
  std::string prefix_;
  std::thread loader_;
  std::atomic<bool> stopLoader_{false};
  std::atomic<bool> reloadRequested_{false};
  std::atomic<Loaded *> pending_{nullptr};
  std::atomic<Loaded *> retired_{nullptr};
  std::atomic<uint32_t> reloads_{0};
  std::atomic<uint32_t> reloadFailures_{0};
};

} // namespace lj::hal

// One running program of the HAL component, without the HAL headers: loading (trusted AOT
// loader, program source for the pins and the identity check, map, P values, retain store) and
// the tick the real-time function calls. HalComponent.cpp is the HAL glue around it.
#pragma once

#include "hosts/linuxcnc/HalPlan.h"
#include "ir/Engine.h"
#include "ladderjit/abi.h"

#include <cmath>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace lj::io {
class RetainStore;
}

namespace lj::hal {

/// The module parameters (HalComponent.cpp, docs/linuxcnc.md).
struct Options {
  std::string program; ///< the AOT .so
  std::string source;  ///< the program it was built from; empty: beside `program`
  std::string map;     ///< map file, empty: default pins only
  std::string trust;   ///< comma-separated public key files; empty: the default key
  std::string params;  ///< P values file
  std::string retain;  ///< retentive store file
  int32_t plc2Nvalue = -1;
  std::function<void(const std::string &)> log; ///< RTAPI log (one line per call)
};

/// The source beside an AOT .so: PATH without `.so` plus `.dit`, `.stl`, `.json`, `.pmc` or
/// `.il`, the first that exists; empty when none does.
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

  /// Float input pin `i` as the element value: lround(pin / scale), saturated to int32.
  int64_t fromFloat(size_t i, double v) const {
    double x = v / pins_[i].scale;
    if (!(x == x)) return 0;
    if (x > 2147483647.0) return 2147483647;
    if (x < -2147483648.0) return -2147483648LL;
    return std::lround(x);
  }

  void startRetain();
  /// The final save of the retentive fields (after HAL stopped calling tick).
  void stopRetain();
  std::string summary() const;

private:
  Instance() = default;
  std::unique_ptr<Engine> engine_;
  lj_entries entries_{};
  lj_state *state_ = nullptr;
  std::vector<PinSpec> pins_;
  const TargetProfile *profile_ = nullptr; ///< the program's target (system bits)
  std::unique_ptr<io::RetainStore> retain_;
  std::string soPath_, sourcePath_, programHash_;
  uint64_t ticks_ = 0;
  uint64_t elapsedNs_ = 0;
  bool inited_ = false;
  bool retainStarted_ = false;
};

} // namespace lj::hal

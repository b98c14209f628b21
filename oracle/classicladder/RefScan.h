// A reference model of ClassicLadder's scan (LinuxCNC 2.9 `calc.c`, `calc_sequential.c`,
// `arithm_eval.c`, `module_hal.c`) over the project model of frontends/classicladder: the
// statement of what the engines must match, checked against classicladder_rt itself by the
// oracle harness (docs/classicladder.md "The reference scan"). It is not an engine: it keeps
// ClassicLadder's data layout and evaluation order literally, for checking only.
#pragma once

#include "frontends/classicladder/Project.h"

#include <cstdint>
#include <map>
#include <vector>

namespace lj::oracle {

/// The sizes classicladder_rt was loaded with (its loadrt parameters).
struct ClSizes {
  int32_t bits = 20, words = 20, timers = 10, monostables = 10, counters = 10, timersIec = 10,
          inputs = 15, outputs = 15, s32in = 10, s32out = 10, floatIn = 10, floatOut = 10;
};

/// One ClassicLadder instance: the state after load, then one `refresh` per call.
class ClReferenceScan {
public:
  ClReferenceScan(const classicladder::Project &p, const ClSizes &sizes);

  /// Input pins (copied in before the sections run).
  std::vector<uint8_t> in;
  std::vector<int32_t> s32in;
  std::vector<double> floatIn;
  /// Output pins (copied out after all sections ran).
  std::vector<uint8_t> out;
  std::vector<int32_t> s32out;
  std::vector<double> floatOut;

  /// One scan of `ms` milliseconds (module_hal.c: the nominal thread period).
  void refresh(int32_t ms);
  /// False once more than 99,999 jumps in one section pass stopped the ladder (state STOP).
  bool running() const { return running_; }

private:
  struct Dyn {
    uint8_t out = 0; ///< DynamicOutput: the power leaving the cell's right edge
    uint8_t bak = 0; ///< DynamicVarBak of an edge contact
  };
  struct OldTimer {
    int32_t baseMs = 1000, presetMs = 0, value = 0;
    uint8_t done = 0, running = 0;
  };
  struct Mono {
    int32_t baseMs = 1000, presetMs = 0, value = 0;
    uint8_t running = 0, inputBak = 0;
  };
  struct Counter {
    int32_t preset = 0, value = 0, valueBak = 0;
    uint8_t upBak = 0, downBak = 0, empty = 0, done = 0, full = 0;
  };
  struct IecTimer {
    int32_t baseMs = 1000, preset = 0, value = 0, acc = 0;
    classicladder::IecMode mode = classicladder::IecMode::Ton;
    uint8_t q = 0, inputBak = 0, started = 0;
  };

  int32_t readVar(int32_t type, int32_t num) const;
  void writeVar(int32_t type, int32_t num, int32_t value);
  int32_t readRef(const classicladder::VarRef &v) const;
  bool stateOnLeft(const classicladder::Rung &r, int x, int y) const;
  int32_t refreshRung(int32_t rung);
  void refreshSection(const classicladder::Section &s);
  void refreshSequentialPage(int32_t page);
  void refreshStepsVars();

  const classicladder::Project &p_;
  ClSizes sz_;
  int32_t ms_ = 1;
  bool running_ = true;
  int64_t jumps_ = 0;
  std::vector<uint8_t> bits_, sys_, err_, steps_;
  std::vector<int32_t> words_, sysWords_, stepSeconds_;
  std::vector<OldTimer> timers_;
  std::vector<Mono> monos_;
  std::vector<Counter> counters_;
  std::vector<IecTimer> iec_;
  std::map<int32_t, std::vector<std::vector<Dyn>>> dyn_; ///< per rung, [x][y]
  std::vector<uint8_t> stepActive_;
  std::vector<int32_t> stepTime_;
};

} // namespace lj::oracle

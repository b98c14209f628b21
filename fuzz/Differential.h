// One differential case (program lines + stimulus) run on the interpreter and an engine under
// test, the state comparison, and the delta-debugging minimizer. Internal to the fuzzer and its
// tests.
#pragma once

#include "fuzz/Fuzz.h"
#include "gen/ProgramGenerator.h"
#include "hosts/TestHost.h"
#include "ir/Engine.h"
#include "ir/Trace.h"
#include "ladderjit/abi.h"

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

namespace lj::fuzz {

/// The code one side runs in switch mode (`ladderjit fuzz --switch`).
enum class SwitchEngine : uint8_t { Interp, JitFast, JitOpt };
/// "interp", "jit-fast", "jit-opt".
const char *switchEngineName(SwitchEngine e);

/// From tick `tick` on (before its scan), the engine under test runs `engine`'s code on the same
/// lj_state: nothing is reset, init does not run again.
struct SwitchPoint {
  uint32_t tick = 0;
  SwitchEngine engine = SwitchEngine::Interp;
};

/// A reproducible case: what the minimizer shrinks.
struct Case {
  std::vector<std::string> lines;
  int32_t plc2Nvalue = 200;
  gen::Stimulus stim;
  bool fastTier = true;
  /// Content seed of the recording NC host (hosts/TestHost.h) each engine gets a copy
  /// of; 0 = empty content.
  uint64_t hostSeed = 0;
  /// Switch mode: the candidate side runs init and the first ticks on `first`, then switches at
  /// every point (ticks not decreasing), and is compared with an unswitched interpreter run.
  /// Empty = the plain differential case (the factory's engine throughout).
  bool switched = false;
  SwitchEngine first = SwitchEngine::Interp;
  std::vector<SwitchPoint> switches;
  /// Build both engines traced (ir/Trace.h) and compare their traces too; the candidate is then
  /// the traced JIT (tracedJit), whatever the factory.
  bool trace = false;
  /// The lines are FANUC PMC text (gen/FanucProgram.h) and the stimulus names FANUC areas.
  bool fanuc = false;
  /// The program's dialect: false HNC-8 STL, true IEC IL (frontends/iec, gen/IlGenerator.h).
  bool iec = false;
};

/// The JIT built traced into `trace` (ir/Trace.h), for Case::trace.
std::unique_ptr<Engine> tracedJit(const VerifiedProgram &prog, bool fastTier, int32_t *trace,
                                  std::string &error);

/// What running a case on both engines gave.
struct Outcome {
  enum class Kind : uint8_t { Same, Mismatch, NotVerified, EngineError } kind = Kind::Same;
  /// Tick of the first difference; kInitTick when it was after init.
  uint32_t tick = 0;
  static constexpr uint32_t kInitTick = UINT32_MAX;
  std::string detail;      ///< first differing field, diagnostics or the engine's error
  uint64_t statements = 0; ///< PLC1 + slice statements of the ticks run (static count)
  uint32_t watchdogTicks = 0;
  uint32_t divZero = 0; ///< fault_divzero at the end (interpreter)
  uint32_t slices = 0;
};

/// Parse + verify `c.lines`, build the interpreter and `factory`'s engine (switch mode: a second
/// interpreter and the factory's fast and optimizing builds, switched as `c.switches` says),
/// give each its own
/// TestHost with the same content, run init and every tick of the stimulus on both, and compare
/// the program state (LJ_STATE_COMPARED_BYTES), the fault codes and the two hosts' call logs
/// after init and after every tick. Stops at the first difference.
Outcome runCase(const Case &c, const EngineFactory &factory);

/// The first field (in struct order) where two states differ, as `D5: interp=3 jit=4`; empty when
/// the states are byte-identical.
std::string firstDifference(const lj_state &ref, const lj_state &cand, const char *candName);

/// The first trace word where two traces of `prog` differ, with its statement.
std::string firstTraceDifference(const VerifiedProgram &prog, const TraceLayout &tl,
                                 const std::vector<int32_t> &a, const std::vector<int32_t> &b,
                                 const char *candName);

/// The first host call where two call logs differ, as `host call 3: interp=event(5) -> 0
/// jit=(no call)`.
std::string firstCallDifference(const std::vector<hosts::HostCall> &ref,
                                const std::vector<hosts::HostCall> &cand, const char *candName);

/// Delta-debug a failing case: drop chunks of lines (ddmin) while the program still verifies and
/// the engines still disagree, then single lines, then cut ticks after the first difference,
/// drop stimulus writes, and try a linear clock and the default watchdog so the result replays
/// with `ladderjit run`. At most `budget` runs.
Case minimize(const Case &failing, Outcome::Kind kind, const EngineFactory &factory,
              uint32_t budget);

} // namespace lj::fuzz

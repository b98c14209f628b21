// Differential fuzzing: random valid programs + stimulus, interpreter against JIT, state
// compared after every tick; a mismatch is minimized and printed.
#pragma once

#include <cstdint>
#include <functional>
#include <iosfwd>
#include <memory>
#include <string>

namespace lj {
class Engine;
struct VerifiedProgram;
} // namespace lj

namespace lj::fuzz {

/// Which JIT tier each program is compiled with.
enum class TierMode : uint8_t { Mixed, Fast, Optimizing };

struct FuzzStats;

struct FuzzOptions {
  uint64_t seed = 1;
  uint64_t programs = 1000;
  uint32_t ticks = 50;
  // Additive extensions (defaults keep the CLI contract `--seed/--programs/--ticks`).
  TierMode tiers = TierMode::Mixed; ///< Mixed: chosen per program from the seed
  int32_t statements = 60;          ///< approximate size of each generated program
  bool minimize = true;             ///< delta-debug mismatches before printing them
  uint32_t minimizeBudget = 1500;   ///< engine runs per minimization
  uint32_t maxReports = 3;          ///< mismatches printed in full; later ones are only counted
  /// Engine under test: the interpreter on the program's ladder round trip instead of the JIT
  /// (fuzz/RoundTrip.h).
  bool roundTrip = false;
  /// Switch mode (`ladderjit fuzz --switch`, docs/serve.md "Tiering"): the side under test
  /// switches between the interpreter, the fast and the optimizing JIT at random ticks (1 to 4
  /// switches, init on a random one of them) on one lj_state, compared tick by tick with an
  /// unswitched interpreter run.
  bool switches = false;
  /// Build both engines traced and compare the power-flow traces (ir/Trace.h) after init and
  /// every tick as well as the states (the JIT is the engine under test).
  bool trace = false;
  /// Generate FANUC PMC programs (gen/FanucProgram.h) instead of HNC-8 STL.
  bool fanuc = false;
  /// Generate IEC IL programs (gen/IlGenerator.h) instead of HNC-8 STL (`fuzz --dialect iec`).
  bool iec = false;
  /// Generate ClassicLadder projects (gen/ClpGenerator.h, fuzz/ClpFuzz.h) instead
  /// (`fuzz --dialect classicladder`).
  bool classicladder = false;
  /// Called after every program with the counters so far and the programs done, and once more
  /// with `done` == 0 just before the summary (`ladderjit fuzz`'s progress line; null = none).
  std::function<void(const FuzzStats &, uint64_t done)> progress;
};

/// Campaign counters, also printed as the summary.
struct FuzzStats {
  uint64_t programs = 0;
  uint64_t notVerified = 0;  ///< generated programs the verifier rejected (generator/verifier bug)
  uint64_t mismatches = 0;   ///< programs whose states or fault codes differed
  uint64_t engineErrors = 0; ///< programs the engine under test failed to build
  uint64_t ticks = 0;
  uint64_t statements = 0; ///< PLC1 + PLC2-slice statements of all ticks run (static count)
  uint64_t watchdogTicks = 0;
  uint64_t divZero = 0;    ///< division-by-zero faults counted by the programs
  uint64_t multiSlice = 0; ///< programs whose PLC2 ran in more than one slice
  uint64_t fastPrograms = 0, optimizingPrograms = 0;
  /// Switch mode: switches scheduled within the ticks run, by kind.
  uint64_t interpToJit = 0, jitToInterp = 0, fastToOpt = 0, optToFast = 0;
  double seconds = 0;
  /// Mismatches + engine errors + programs that did not verify.
  uint64_t failures() const { return notVerified + mismatches + engineErrors; }
};

/// Builds the engine under test for one verified program (which outlives it). `fastTier` selects
/// the JIT tier. Returns null and sets `error` on failure.
using EngineFactory = std::function<std::unique_ptr<Engine>(const VerifiedProgram &, bool fastTier,
                                                            std::string &error)>;

/// The JIT as the engine under test.
EngineFactory jitFactory();

/// Run the campaign, printing a summary (and any minimized mismatch) to `out`.
/// Returns the number of mismatching programs (0 = pass); programs that did not verify and
/// engine build failures count as mismatches here.
uint64_t run(const FuzzOptions &opts, std::ostream &out);

/// The campaign against any engine (tests inject faulty engines to check the harness).
/// `minimizing`, if set, is called with true before a failing program is minimized and with
/// false after (the round trip leaves the minimizer's runs out of its counts).
FuzzStats runWith(const FuzzOptions &opts, std::ostream &out, const EngineFactory &candidate,
                  const std::function<void(bool)> &minimizing = nullptr);

} // namespace lj::fuzz

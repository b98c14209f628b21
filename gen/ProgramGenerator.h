// Seeded STL program generators: `realistic` machine-builder programs for benchmarks and
// table-driven random valid programs (plus input stimulus) for differential fuzzing.
#pragma once

#include "ir/Area.h"
#include "ir/OpTable.h"
#include "ir/Profile.h"
#include "ladderjit/abi.h"

#include <cstdint>
#include <string>
#include <vector>

namespace lj::gen {

/// A generated program: one STL statement per line (no comments), plus the slicing parameter
/// it is meant to be verified with.
struct GenProgram {
  std::vector<std::string> lines;
  int32_t plc2Nvalue = 200;
  /// The whole text, lines joined with '\n'.
  std::string text() const;
};

/// Options of the benchmark generator.
struct RealisticOptions {
  uint64_t seed = 1;
  int32_t statements = 1000; ///< exact statement count, markers and SP/SPE included
  int32_t subroutines = 4;
  /// Only what the C baseline of `ladderjit bench --c-baseline` expresses (gen/CTranslate.h):
  /// the same bit-logic rungs, ~20% compare / math / move rungs, no subroutines, jumps, timers,
  /// counters or PLS/PLF/ALT. Off (the default) leaves the generated programs unchanged.
  bool coreSubset = false;
};

/// A program as a machine builder would write it: ~70% bit-logic rungs (contacts, ANB/ORB
/// blocks, MPS branches, edges, OUT/SET/RST on Y/G/R), ~30% function-block rungs (timers,
/// counters, compares, math, moves, PLS/PLF/ALT), split into init / PLC1 (~10%) / PLC2 (~90%)
/// with a few subroutines called from PLC2. No loops or backward jumps. Always verifies.
GenProgram generateRealistic(const RealisticOptions &opts);

/// Options of the differential-fuzzing generator.
struct RandomOptions {
  uint64_t seed = 1;
  int32_t statements = 60; ///< approximate size (the structure may add a few)
  int32_t maxDepth = 12;   ///< cap on the ST depth the generator builds up
  int32_t maxMsDepth = 4;
  int32_t maxSubs = 4;
  int32_t maxNest = 3; ///< nesting of jump regions and loops
  /// Keep backward jumps and loops short (counted guards with small bounds, constant LOOP
  /// counts), so a tick rarely ends in the watchdog and all of a long program runs; for tests
  /// that compare whole programs. Off (the default) leaves the generated programs unchanged.
  bool avoidWatchdog = false;
};

/// A random program that must verify without errors. Instructions are chosen by iterating the
/// instruction table (operand specs, areas, constant ranges, stack rules, input counts), so a new
/// row is generated without touching this file; only flow instructions (JMP/LBL, LOOP/NEXT,
/// CALL/SP/SPE/RETN, the part markers) are placed by a structural planner. Covers deep ANB/ORB
/// and MPS nesting, edges, timers, counters, forward and guarded backward jumps (some of which
/// run into the watchdog), nested loops with register counts, nested subroutine calls with
/// conditional RETN, faults (DIV by zero, INT32_MIN / -1) and small PLC2 slices. Now and then a
/// range of 33..100 elements (BMOV overlapping within one area in either direction, FMOV, ZRST
/// word and bit forms, COD/SER tables), which the lowering turns into loops, and index registers
/// (XMOV/XCH formats 1/2, runtime axes) loaded with the edges of their range just before use.
GenProgram generateRandom(const RandomOptions &opts);

/// A small complete program that executes `op` on every tick with EN = 1 (LDT feeds each of
/// its inputs), its operands chosen by the random generator's own operand rules; flow
/// instructions come in a minimal valid frame (a label for JMP, a subroutine for CALL...).
/// Used by the catalogue completeness test: it proves the generator can emit every row.
GenProgram generateSnippet(Op op, uint64_t seed);

/// One host write: a whole element (`bit` < 0) or one bit.
struct HostWrite {
  Area area = Area::Input;
  int32_t index = 0;
  int8_t bit = -1;
  int32_t value = 0;
  /// The target whose layout (area, index) is in (nullptr: HNC-8's lj_image).
  const TargetProfile *profile = nullptr;
};

/// What the host does around a run: initial P/B (parameters and the retain store) and X/F
/// writes before init, then per tick the X/F writes and now_ms.
struct Stimulus {
  std::vector<HostWrite> beforeInit;
  uint64_t initNowMs = 0;
  std::vector<std::vector<HostWrite>> writes; ///< per tick, applied before that tick's scan
  std::vector<uint64_t> nowMs;                ///< per tick
  uint64_t maxBackwardSteps = 1000000;
  /// FANUC: the counter data type system parameter at power-up (TargetProfile::kCounterBinary
  /// or kCounterBcd), written before init like --params does.
  uint8_t counterFormat = 0;
  uint32_t ticks() const { return static_cast<uint32_t>(nowMs.size()); }
};

/// Random stimulus for `ticks` ticks on the address pools the random generator reads: X bytes and
/// bits, F words and bits, now_ms mostly +1 per tick with occasional jumps (up to hours and past
/// 2^32 ms) so minute/hour timers fire, and a random watchdog limit.
Stimulus generateStimulus(uint64_t seed, uint32_t ticks);

/// Apply writes to a state (bit writes change only that bit; element writes truncate).
void applyWrites(lj_state &s, const std::vector<HostWrite> &writes);

/// `X3.1`, `F7`, ... as on the command line.
std::string formatAddress(const HostWrite &w);

/// The stimulus in the CLI stimulus-file format (`@TICK ADDR=VALUE ...`), with the pre-init
/// writes, the time stream and the watchdog limit as `#` comments where the format has no field.
std::string formatStimulus(const Stimulus &st);

} // namespace lj::gen

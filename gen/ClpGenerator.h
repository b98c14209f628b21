// Random ClassicLadder projects (`.clp` text) that LinuxCNC 2.9's `classicladder --nogui`
// loads: contacts NO/NC/rising/falling on %I %Q %B, coils, negated, set and reset coils, parallel
// branches closed by vertical links, old timers %T, IEC timers %TM (TON/TOF/TP), monostables
// %M, counters %C, compare and operate blocks with expressions on %W %IW %QW %IF %QF and block
// values, several main sections whose rungs are chained out of file order (docs/classicladder.md
// "Generator"). Used by the oracle harness (tests/classicladder/clharness.py).
#pragma once

#include <cstdint>
#include <string>

namespace lj::gen {

/// The sizes a generated project declares in its general.txt (and the harness loads
/// classicladder_rt with).
struct ClpGenSizes {
  int32_t bits = 16, words = 8, timers = 4, monostables = 4, counters = 4, timersIec = 4,
          inputs = 12, outputs = 12, arithmExpr = 64, sections = 4, s32in = 4, s32out = 4,
          floatIn = 2, floatOut = 2;
};

/// Which elements a generated project uses (the classicladder front end maps all of them,
/// docs/classicladder.md): All = everything above; Logic = contacts NO/NC/rising/falling on
/// %I %Q %B, coils, negated, set and reset coils, connections and vertical links; Expressions =
/// Logic plus compare and operate blocks on %W %IW %QW %IF %QF %I %B.
enum class ClpElements : uint8_t { All, Logic, Expressions };

/// A random project for `seed` with about `rungs` rungs (at least 1), as `.clp` text.
std::string generateClp(uint64_t seed, int32_t rungs = 8, const ClpGenSizes &sizes = {},
                        ClpElements elements = ClpElements::All);

} // namespace lj::gen

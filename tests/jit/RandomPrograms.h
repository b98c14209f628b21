// Random valid STL programs that use every instruction of the table, for JIT-vs-interpreter
// stress tests (nested expressions, MPS branches, blocks, loops, jumps, calls, RETN, slices).
#pragma once

#include "ladderjit/abi.h"

#include <cstdint>
#include <string>

namespace lj::test {

/// Deterministic generator (splitmix64).
struct Rng {
  uint64_t s;
  explicit Rng(uint64_t seed) : s(seed) {}
  uint64_t next() {
    uint64_t z = (s += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  /// Uniform in [0, n).
  uint32_t below(uint32_t n) { return static_cast<uint32_t>(next() % n); }
  bool chance(uint32_t percent) { return below(100) < percent; }
};

/// A random program of roughly `rungs` rungs per part, with subroutines, loops and jumps.
/// Registers R50..R59 hold loop counts (never written by the program) and D90..D99 bound the
/// backward jumps, so a tick terminates without the watchdog unless the program is unlucky.
std::string randomProgram(uint64_t seed, int rungs);

/// Random host inputs for tick `tick`: X, F and the loop-count registers.
void randomInputs(uint64_t seed, uint32_t tick, lj_state &s);

} // namespace lj::test

// Differential fuzzing: random valid programs + stimulus, interpreter against JIT, state
// compared after every tick; a mismatch is minimized and printed.
#pragma once

#include <cstdint>
#include <iosfwd>

namespace lj::fuzz {

struct FuzzOptions {
  uint64_t seed = 1;
  uint64_t programs = 1000;
  uint32_t ticks = 50;
};

/// Run the campaign, printing a summary (and any minimized mismatch) to `out`.
/// Returns the number of mismatching programs (0 = pass).
uint64_t run(const FuzzOptions &opts, std::ostream &out);

} // namespace lj::fuzz

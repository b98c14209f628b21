// Random valid IEC IL (Neza) programs and their stimulus for `ladderjit fuzz --dialect iec`
// (docs/iec-il.md "Fuzzing"): every instruction of the front end, parentheses to the seed's
// depth 8, MPS to depth 8, edges on %I and %M0-31, comparisons and operation blocks, forward
// jumps, ENDC, subroutines; inputs are %I bits and %KW words.
#pragma once

#include "gen/ProgramGenerator.h"

#include <cstdint>

namespace lj::gen {

/// A random IL program of about `statements` instructions that compiles without errors.
GenProgram generateIl(uint64_t seed, int32_t statements);

/// Random %I bits and %KW words for `ticks` ticks (now_ms + 1 per tick).
Stimulus generateIlStimulus(uint64_t seed, uint32_t ticks);

} // namespace lj::gen

// Differential fuzzing of ClassicLadder projects (`ladderjit fuzz --dialect classicladder`):
// random `.clp` projects of gen/ClpGenerator (every element: contacts, coils, compare and
// operate blocks, old timers, monostables, counters, IEC timers), compiled through pipeline/,
// run on the interpreter and the engine under test (the JIT) in lock step with random HAL
// inputs and a random period; the whole state is compared after init and every tick.
#pragma once

#include "fuzz/Fuzz.h"

#include <iosfwd>

namespace lj::fuzz {

/// The campaign over generated `.clp` projects (opts.seed, programs, ticks; the tier mode as
/// for the other dialects). A mismatch prints the seed and rung count that regenerate the
/// project (`clp_tool gen SEED OUT.clp RUNGS`), the tick and the first state difference.
FuzzStats runClp(const FuzzOptions &opts, std::ostream &out, const EngineFactory &candidate);

} // namespace lj::fuzz

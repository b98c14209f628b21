// The FANUC generator's rungs for family PmcTc (TMR, TMRC, CTR, CTRB, CTRC, COMPB, COMP, COIN,
// NEx, RNGx), hooked into gen/FanucProgram.cpp's rung choice.
#pragma once

#include "gen/Rng.h"

#include <string>
#include <vector>

namespace lj::gen {

/// Append one rung's instruction after a logic line that left ST0 (depth 1) to `lines`. Timer
/// and counter numbers are the next unused ones (counted in `lines`); presets come from the
/// R/D data pools by a MOVW into the T / C area, so they vary with the program's own writes.
void fanucTimerCounterRung(Rng &r, std::vector<std::string> &lines);

} // namespace lj::gen

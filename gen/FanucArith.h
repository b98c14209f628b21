// Random rungs of the FANUC arithmetic and constant instructions (fanuc-c) for
// gen/FanucProgram.cpp.
#pragma once

#include "gen/Rng.h"

#include <string>
#include <vector>

namespace lj::gen {

/// Append one rung to `out` after the caller's logic line (ST depth 1, its value the first
/// input); the rung verifies on its own (ST depth at most 4).
void fanucArithRung(Rng &r, std::vector<std::string> &out);

} // namespace lj::gen

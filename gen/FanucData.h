// Random rungs of the FANUC transfer, search, conversion and flow instructions (fanuc-b) for
// gen/FanucProgram.cpp.
#pragma once

#include "gen/Rng.h"

#include <string>
#include <vector>

namespace lj::gen {

/// Append one rung to `out` after the caller's logic line (ST depth 1, its value the first
/// input); the rung verifies on its own (ST depth at most 4, regions closed).
void fanucDataRung(Rng &r, std::vector<std::string> &out);

} // namespace lj::gen

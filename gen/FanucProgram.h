// Random valid FANUC PMC programs (docs/fanuc-pmc.md) and their stimulus, for the differential
// fuzzer (`ladderjit fuzz --dialect fanuc`): basic instructions with ST0..ST7, and every
// functional instruction of this build, over small overlapping byte pools so multi-byte and
// bit accesses of the same bytes meet in one rung.
#pragma once

#include "gen/ProgramGenerator.h"
#include "ir/Profile.h"

#include <cstdint>
#include <string>
#include <vector>

namespace lj::gen {

/// A random program (one instruction per line) with about `statements` lines.
std::vector<std::string> generateFanuc(uint64_t seed, int32_t statements);

/// Random X and F inputs (bytes X0..X3 and F0..F3, bits), changing on any tick, and now_ms for
/// `ticks` ticks; writes name FANUC areas (apply them with applyFanucWrites).
Stimulus generateFanucStimulus(uint64_t seed, uint32_t ticks);

/// Apply writes whose areas are FANUC's (byte elements at profile offsets).
void applyFanucWrites(const TargetProfile &tp, lj_state &s, const std::vector<HostWrite> &w);

} // namespace lj::gen

// The FANUC 0i-D PMC target profile (profiles/fanuc/Areas.cpp; FANUC PMC manual ref
// sections 1, 2, 4; the [EXT] choices are rows of docs/fanuc-pmc.md). Only the FANUC front end,
// the FANUC generator and the profile registry name it.
#pragma once

#include "ir/Profile.h"

#include <cstdint>

namespace lj::fanuc {

/// 0i-D PMC resource counts (reference 1, 4.2, 6.3, 6.8, 7 "Resource counts"): TMRB/TMRBF
/// timer numbers 1..500, DIFU/DIFD edge numbers 1..1000, subroutines P1..P5000.
constexpr int32_t kTmrbTimers = 500, kDifEdges = 1000, kSubroutines = 5000;

/// The FANUC 0i-D PMC profile: byte-addressed areas laid out in lj_state.mem.
const TargetProfile &profile();

/// Byte offsets inside lj_state of the system relays the engines write (reference section 2).
uint32_t systemRelayOffset(int32_t rByte);

} // namespace lj::fanuc

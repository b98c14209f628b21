// The FANUC 0i-D PMC target profile (profiles/fanuc/Areas.cpp; ../shared/reference/fanuc-pmc.md
// sections 1, 2, 4; the [EXT] choices are rows of docs/fanuc-pmc.md). Only the FANUC front end,
// the FANUC generator and the profile registry name it.
#pragma once

#include "ir/Profile.h"

#include <cstdint>

namespace lj::fanuc {

/// The FANUC 0i-D PMC profile: byte-addressed areas laid out in lj_state.mem.
const TargetProfile &profile();

/// Byte offsets inside lj_state of the system relays the engines write (reference section 2).
uint32_t systemRelayOffset(int32_t rByte);

} // namespace lj::fanuc

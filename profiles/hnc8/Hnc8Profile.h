// The HNC-8 target profile (profiles/hnc8/Areas.cpp). Only the HNC-8 front end, the generators
// that write HNC-8 text and the profile registry (profiles/Profiles.h) name it; the core reads
// the profile a program carries.
#pragma once

#include "ir/Profile.h"

namespace lj::hnc8 {

/// The HNC-8 profile (DIALECT.md 1, 2, 4, 6; hnc8-cnc-interface.md 0-1).
const TargetProfile &profile();

} // namespace lj::hnc8

// The registry of target profiles: every profile this build knows, by name. A dialect
// (pipeline/Dialects.h) names its profile; tools and tests that need a profile by name ask here.
#pragma once

#include "ir/Profile.h"

#include <span>
#include <string_view>

namespace lj {

/// Every profile of this build, in a stable order ("hnc8" first).
std::span<const TargetProfile *const> allProfiles();

/// The profile called `name` (TargetProfile::name), or nullptr.
const TargetProfile *profileNamed(std::string_view name);

} // namespace lj

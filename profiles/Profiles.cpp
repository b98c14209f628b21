// The profiles of this build (profiles/Profiles.h). A new target adds its profile here.
#include "profiles/Profiles.h"

#include "profiles/classicladder/ClassicLadderProfile.h"
#include "profiles/fanuc/FanucProfile.h"
#include "profiles/hnc8/Hnc8Profile.h"
#include "profiles/iec/IecProfile.h"

namespace lj {

std::span<const TargetProfile *const> allProfiles() {
  static const TargetProfile *const kAll[] = {&hnc8::profile(), &fanuc::profile(), &iec::profile(),
                                              &classicladder::profile()};
  return kAll;
}

const TargetProfile *profileNamed(std::string_view name) {
  for (const TargetProfile *p : allProfiles())
    if (name == p->name) return p;
  return nullptr;
}

} // namespace lj

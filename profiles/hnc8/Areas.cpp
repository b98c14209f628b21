// Area facts from DIALECT.md section 1, in one table.
#include "ir/Area.h"

#include "ladderjit/abi.h"

#include <cstddef>

namespace lj {

namespace {
constexpr AreaInfo kAreas[] = {
    {'X', LJ_X_COUNT, 1, false, false}, {'Y', LJ_Y_COUNT, 1, false, true},
    {'F', LJ_F_COUNT, 2, true, false},  {'G', LJ_G_COUNT, 2, true, true},
    {'R', LJ_R_COUNT, 1, false, true},  {'W', LJ_W_COUNT, 2, true, true},
    {'D', LJ_D_COUNT, 4, true, true},   {'B', LJ_B_COUNT, 4, true, true},
    {'P', LJ_P_COUNT, 4, true, false},  {'T', 428, 0, false, false},
    {'C', 428, 0, false, false},        {'L', 10000, 0, false, false},
    {'S', 512, 0, false, false},        {'?', 0, 0, false, false},
};
} // namespace

const AreaInfo &areaInfo(Area a) { return kAreas[static_cast<int>(a)]; }

std::optional<Area> areaFromLetter(char c) {
  if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
  for (int i = 0; i < kAreaCount; ++i)
    if (kAreas[i].letter == c) return static_cast<Area>(i);
  return std::nullopt;
}

bool validIndex(Area a, int64_t n) {
  if (n < 0) return false;
  if (a == Area::Timer || a == Area::Counter)
    return lj_tc_slot(static_cast<int32_t>(n > 100000 ? -1 : n)) >= 0;
  return n < areaInfo(a).count;
}

int bitWidth(Area a) {
  if (a == Area::Timer || a == Area::Counter) return 1;
  return areaInfo(a).bytes * 8;
}

uint32_t stateOffset(Area a) {
  switch (a) {
  case Area::Input:
    return offsetof(lj_state, img.X);
  case Area::Output:
    return offsetof(lj_state, img.Y);
  case Area::NcStatus:
    return offsetof(lj_state, img.F);
  case Area::NcControl:
    return offsetof(lj_state, img.G);
  case Area::Relay:
    return offsetof(lj_state, img.R);
  case Area::Word:
    return offsetof(lj_state, img.W);
  case Area::DWord:
    return offsetof(lj_state, img.D);
  case Area::Retained:
    return offsetof(lj_state, img.B);
  case Area::Param:
    return offsetof(lj_state, img.P);
  default:
    return 0;
  }
}

} // namespace lj

// The HNC-8 target profile (DIALECT.md 1, 2, 4, 6; hnc8-cnc-interface.md 0-1), checked against the
// process image of runtime_abi/include/ladderjit/abi.h: every area's count, width and offset.
#include "profiles/hnc8/Hnc8Profile.h"

#include "profiles/hnc8/CncTable.h"

#include "ladderjit/abi.h"

#include <cstddef>
#include <iterator>

namespace lj {

namespace {

#define LJ_AREA(letter, field, sign, write)                                                        \
  AreaInfo {                                                                                       \
    letter, static_cast<int32_t>(sizeof(lj_image::field) / sizeof(lj_image::field[0])),            \
        static_cast<uint8_t>(sizeof(lj_image::field[0])), sign, write, true,                       \
        static_cast<uint32_t>(offsetof(lj_state, img.field))                                       \
  }

constexpr const char *kHostServices[] = {"var_get",     "var_set",     "mpg_input",  "mpg_delta",
                                         "temp_input",  "event",       "save_data",  "tool_select",
                                         "tool_in_use", "tool_vector", "slave_home", "spindle_da",
                                         "nixie_encode"};

constexpr TargetProfile kHnc8{
    "hnc8",
    {{
        LJ_AREA("X", X, false, false),
        LJ_AREA("Y", Y, false, true),
        LJ_AREA("F", F, true, false),
        LJ_AREA("G", G, true, true),
        LJ_AREA("R", R, false, true),
        LJ_AREA("W", W, true, true),
        LJ_AREA("D", D, true, true),
        LJ_AREA("B", B, true, true),
        LJ_AREA("P", P, true, false),
        {"T", 428, 0, false, false, true, 0}, // only Tn.0, the output bit (contacts)
        {"C", 428, 0, false, false, true, 0},
        {"L", 10000, 0, false, false, false, 0},
        {"S", 512, 0, false, false, false, 0},
        // roles HNC-8 does not have
        {"", 0, 0, false, false},
        {"", 0, 0, false, false},
        {"", 0, 0, false, false},
        {"", 0, 0, false, false},
        {"", 0, 0, false, false},
        {"", 0, 0, false, false},
        {"", 0, 0, false, false},
        {"", 0, 0, false, false},
        {"", 0, 0, false, false},
        {"?", 0, 0, false, false, false, 0},
    }},
    {{{0, 127}, {300, 427}}},
    {{{0, 127}, {300, 427}}},
    {1, 1000, 60000, 3600000},
    areas(Area::Retained),
    {300, 427},
    {300, 427},
    {{{"init", Op::EndInit, PartSpec::Schedule::Once},
      {"cyclic", Op::EndCyclic, PartSpec::Schedule::EveryTick},
      {"sliced", Op::EndSliced, PartSpec::Schedule::Sliced}}},
    10000,
    32,
    200,
    0,
    0,
    EdgePolicy::PerInstance,
    {80, 2560, 32, 4, 48, 8, 56, 19},
    kHostServices,
    cnc::kRows,
    {1, 7, 2, 3, 5, 4, 6},
    {},
};

#undef LJ_AREA

// The profile and the ABI agree (abi.h is the process image; the profile must describe it).
static_assert(kHnc8.areas[static_cast<int>(Area::Input)].count == LJ_X_COUNT);
static_assert(kHnc8.areas[static_cast<int>(Area::Output)].count == LJ_Y_COUNT);
static_assert(kHnc8.areas[static_cast<int>(Area::NcStatus)].count == LJ_F_COUNT);
static_assert(kHnc8.areas[static_cast<int>(Area::NcControl)].count == LJ_G_COUNT);
static_assert(kHnc8.areas[static_cast<int>(Area::Relay)].count == LJ_R_COUNT);
static_assert(kHnc8.areas[static_cast<int>(Area::Word)].count == LJ_W_COUNT);
static_assert(kHnc8.areas[static_cast<int>(Area::DWord)].count == LJ_D_COUNT);
static_assert(kHnc8.areas[static_cast<int>(Area::Retained)].count == LJ_B_COUNT);
static_assert(kHnc8.areas[static_cast<int>(Area::Param)].count == LJ_P_COUNT);
constexpr bool numberSpacesFillSlots() {
  int32_t n = 0;
  for (const NumberRange &r : kHnc8.timerNumbers) n += r.hi - r.lo + 1;
  return n == LJ_TC_SLOTS;
}
static_assert(numberSpacesFillSlots(), "timer numbers map one to one onto lj_state.T slots");
constexpr bool slotsAreAbiSlots() {
  for (int32_t n = -1; n < 500; ++n)
    // abi.h lj_tc_slot, spelled out (C inline functions are not constexpr)
    if (const int abi = n >= 0 && n < 128 ? n : n >= 300 && n < 428 ? n - 300 + 128 : -1;
        kHnc8.tcSlot(Area::Timer, n) != abi || kHnc8.tcSlot(Area::Counter, n) != abi)
      return false;
  return true;
}
static_assert(slotsAreAbiSlots(), "the profile's slot mapping is abi.h's lj_tc_slot");
static_assert(kHnc8.cnc.channelBase + kHnc8.cnc.channels * kHnc8.cnc.blockWords <= LJ_F_COUNT);

static_assert(kHnc8.cnc.blockWords == cnc::kBlockWords &&
                  kHnc8.cnc.channelBase == cnc::kChannelBase && kHnc8.cnc.axes == cnc::kAxes,
              "the CNC table and the profile use one layout");

static_assert(std::size(cnc::kModeCode) == kHnc8.modeCode.size());
constexpr bool modeCodesAgree() {
  for (size_t i = 0; i < kHnc8.modeCode.size(); ++i)
    if (kHnc8.modeCode[i] != cnc::kModeCode[i]) return false;
  return true;
}
static_assert(modeCodesAgree(), "the CNC table and the profile use one mode code list");

} // namespace

const TargetProfile &hnc8::profile() { return kHnc8; }

} // namespace lj

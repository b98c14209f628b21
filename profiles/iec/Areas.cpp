// The IEC IL (Neza) target profile: the Neza objects of modicon-neza.md 1 laid on the existing
// lj_image areas (an interim layout until the ABI has a profile-laid byte region; docs/iec-il.md
// "Process image"), checked against runtime_abi/include/ladderjit/abi.h at compile time.
#include "profiles/iec/IecProfile.h"

#include "ladderjit/abi.h"

#include <cstddef>

namespace lj {

namespace {

#define LJ_IEC_AREA(letter, field, count, sign, write)                                             \
  AreaInfo {                                                                                       \
    letter, count, static_cast<uint8_t>(sizeof(lj_image::field[0])), sign, write, true,            \
        static_cast<uint32_t>(offsetof(lj_state, img.field))                                       \
  }

using namespace iec;

constexpr TargetProfile kIec{
    "iec",
    {{
        LJ_IEC_AREA('I', X, kUnits *kPointsPerUnit / 8, false, false),       // %Ii.j
        LJ_IEC_AREA('Q', Y, kUnits *kPointsPerUnit / 8, false, true),        // %Qi.j
        LJ_IEC_AREA('K', F, kConstWords, true, false),                       // %KWi
        LJ_IEC_AREA('Z', G, kSystemWords, true, true),                       // %SWi
        LJ_IEC_AREA('M', R, kScratchFirstByte + kScratchBytes, false, true), // %M64.. + scratch
        LJ_IEC_AREA('W', W, kWords, true, true),                             // %MWi
        LJ_IEC_AREA('S', D, kSystemBits / 32, true, true),                   // %Si
        LJ_IEC_AREA('N', B, kRetainedBits / 32, true, true),                 // %M0..%M63
        {'P', 0, 4, true, false, false, 0},
        {'T', 32, 0, false, false, true, 0},
        {'C', 16, 0, false, false, true, 0},
        {'L', kLabels + 1, 0, false, false, false, 0},
        {'R', kSubroutines, 0, false, false, false, 0},
        {'?', 0, 0, false, false, false, 0},
    }},
    {{{0, 31}, {0, -1}}},
    {{{0, 15}, {0, -1}}},
    {1, 10, 100, 1000},
    areas(Area::Retained),
    {0, -1},
    {0, -1},
    {{{"init", Op::EndInit, PartSpec::Schedule::Once},
      {"cyclic", Op::EndCyclic, PartSpec::Schedule::EveryTick},
      {"sliced", Op::EndSliced, PartSpec::Schedule::Sliced}}},
    10000,
    8,
    200,
    0,
    kMpsDepth,
    EdgePolicy::PerObject,
    {0, 0, 0, 0, 0, 0, 0, 0},
    {},
    {},
    {0, 0, 0, 0, 0, 0, 0},
};

#undef LJ_IEC_AREA

static_assert(kUnits * kPointsPerUnit / 8 <= LJ_X_COUNT &&
              kUnits * kPointsPerUnit / 8 <= LJ_Y_COUNT);
static_assert(kConstWords <= LJ_F_COUNT && kSystemWords <= LJ_G_COUNT && kWords <= LJ_W_COUNT);
static_assert(kScratchFirstByte + kScratchBytes <= LJ_R_COUNT, "%M64.. and the scratch bits");
static_assert(kSystemBits / 32 <= LJ_D_COUNT && kRetainedBits / 32 <= LJ_B_COUNT);

} // namespace

const TargetProfile &iec::profile() { return kIec; }

} // namespace lj

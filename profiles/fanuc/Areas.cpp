// The FANUC 0i-D PMC profile (FANUC PMC manual ref 1.1, 2, 4): every area is bytes,
// little-endian, in lj_state.mem (abi.h ABI v3), the second range of T/C/K/A/R/X/Y right after
// the first (TargetProfile::elementOffset). Ranges the seed lacks are [EXT] rows of
// docs/fanuc-pmc.md.
#include "profiles/fanuc/FanucProfile.h"

#include "ladderjit/abi.h"

#include <cstddef>

namespace lj {

namespace {

constexpr uint32_t kMem = static_cast<uint32_t>(offsetof(lj_state, mem));

// Layout inside mem: [name, first range count, upper range lo, upper count] in this order.
constexpr uint32_t kX = 0, kY = 256, kF = 512, kG = 1280, kR = 2048, kE = 10548, kA = 20548,
                   kC = 21048, kK = 21648, kT = 21848, kD = 22848, kEnd = 32848;
// Hidden state after the areas (TargetProfile::BlockState): the lj_timer records of TMRB /
// TMRBF 1..500 (slots 0..499), then the previous-ACT bytes of DIFU and DIFD edge numbers
// 0..1000 (slot = number). abi.h's own arrays have 256 timer and 512 PLS/PLF slots.
constexpr int32_t kTimers = fanuc::kTmrbTimers, kEdges = fanuc::kDifEdges + 1;
constexpr uint32_t kTmrbState = kEnd, kDifu = kTmrbState + kTimers * sizeof(lj_timer),
                   kDifd = kDifu + kEdges, kStateEnd = kDifd + kEdges;
// Then the synchronized input memory of level 2 (ref 4.1, TargetProfile::SyncInputs): a copy of
// the bytes from X to the end of F, latched before the first slice of each level-2 scan (Y lies
// between X and F: it is copied too, one memcpy, but never read from the copy). Then the system
// parameters the host writes at power-up: the counter data type (ref 6.4).
constexpr uint32_t kSync = (kStateEnd + 15) / 16 * 16, kSyncBytes = kG - kX,
                   kCounterFormat = kSync + kSyncBytes, kHiddenEnd = kCounterFormat + 1;
static_assert((kMem + kTmrbState) % alignof(lj_timer) == 0, "lj_timer records are aligned");
static_assert(kHiddenEnd <= LJ_MEM_BYTES, "the FANUC hidden state fits lj_state.mem");
static_assert(kEnd <= LJ_MEM_BYTES, "the FANUC areas fit lj_state.mem");
static_assert(kX < kF && kF + 768 == kG, "X and F lie in the bytes the synchronized memory copies");

constexpr AreaInfo byteArea(const char *name, int32_t count, bool writable, uint32_t at,
                            int32_t upperLo = 0, int32_t upperCount = 0) {
  return AreaInfo{name, count, 1, true, writable, true, kMem + at, upperLo, upperCount};
}

constexpr AreaInfo none() { return AreaInfo{"", 0, 0, false, false}; }

constexpr uint32_t relayByte(int32_t r) {
  return kMem + kR + static_cast<uint32_t>(8000 + (r - 9000));
}
using K = SystemBit::Kind;
// Reference 2 [L115-L211]: R9091.0 OFF, .1 ON, .2 RUN, .5 FL2 (0.2 s, 1:1), .6 FL (1 s, 1:1);
// R9015.0 RUNR (first scan after start, [EXT]). Written by the runtime before every tick.
constexpr SystemBit kSystemBits[] = {
    {relayByte(9091), 0, K::Zero},       {relayByte(9091), 1, K::One},
    {relayByte(9091), 2, K::One},        {relayByte(9091), 5, K::Clock, 100},
    {relayByte(9091), 6, K::Clock, 500}, {relayByte(9015), 0, K::FirstScan},
};

constexpr TargetProfile kFanuc{
    "fanuc",
    {{
        byteArea("X", 128, false, kX, 200, 128),  // Input
        byteArea("Y", 128, true, kY, 200, 128),   // Output
        byteArea("F", 768, false, kF),            // NcStatus
        byteArea("G", 768, true, kG),             // NcControl
        byteArea("R", 8000, true, kR, 9000, 500), // Relay (R9000.. system relays)
        none(),                                   // Word
        none(),                                   // DWord
        none(),                                   // Retained
        none(),                                   // Param
        {"T", 0, 0, false, false, false, 0},      // Timer: TMRB/TMRBF numbers (timerNumbers)
        none(),                                   // Counter
        {"L", 10000, 0, false, false, false, 0, 0, 0, 1},                   // Label L1..L9999
        {"P", fanuc::kSubroutines + 1, 0, false, false, false, 0, 0, 0, 1}, // Subroutine P1..P5000
        byteArea("K", 100, true, kK, 900, 100),                             // KeepRelay
        byteArea("E", 10000, true, kE),                                     // ExtraRelay
        byteArea("A", 250, true, kA, 9000, 250),                            // MessageBits
        byteArea("T", 500, true, kT, 9000, 500),                            // TimerData
        byteArea("C", 400, true, kC, 5000, 200),                            // CounterData
        byteArea("D", 10000, true, kD),                                     // DataTable
        none(),                                                             // SystemBits
        none(),                                                             // SystemWords
        none(),                                                             // ConstWords
        {"?", 0, 0, false, false, false, 0},
    }},
    // TMRB/TMRBF timer numbers 1..500 (ref 1 specification table, 6.3), in blockState.
    {{{1, kTimers}, {0, -1}}},
    {{{0, -1}, {0, -1}}},
    {1, 8, 48, 100},
    areas(Area::KeepRelay, Area::TimerData, Area::CounterData, Area::DataTable),
    {0, -1},
    {0, -1},
    {{{"init", Op::EndInit, PartSpec::Schedule::Once},
      {"level1", Op::EndCyclic, PartSpec::Schedule::EveryTick},
      {"level2", Op::EndSliced, PartSpec::Schedule::Sliced}}},
    24000,
    8,
    200,
    8,
    0,
    EdgePolicy::PerInstance,
    {0, 0, 0, 0, 0, 0, 0, 0},
    {},
    {},
    {0, 0, 0, 0, 0, 0, 0},
    kSystemBits,
    {kMem + kTmrbState, kTimers, kMem + kDifu, kMem + kDifd, kEdges},
    // Level 2 reads X and F through the synchronized input memory (ref 4.1 L841-L843).
    {areas(Area::Input, Area::NcStatus), kMem + kX, kMem + kSync, kSyncBytes},
    {kMem + kCounterFormat},
};

static_assert(kFanuc.elementOffset(Area::Relay, 9091) == relayByte(9091), "R9091 layout");

} // namespace

const TargetProfile &fanuc::profile() { return kFanuc; }

uint32_t fanuc::systemRelayOffset(int32_t rByte) {
  return kFanuc.elementOffset(Area::Relay, rByte);
}

} // namespace lj

// The IEC IL (Neza) target profile: the Neza objects of modicon-neza.md 1 laid in the
// profile-laid byte region lj_state.mem (runtime_abi/include/ladderjit/abi.h v3; docs/iec-il.md
// "Process image"), checked against it at compile time.
#include "profiles/iec/IecProfile.h"

#include "ladderjit/abi.h"

#include <cstddef>

namespace lj {

namespace {

using namespace iec;

// Byte offsets inside lj_state.mem, in layout order; words on even offsets.
constexpr uint32_t kInOff = 0;                                              // %Ii.j
constexpr uint32_t kOutOff = kInOff + kUnits * kPointsPerUnit / 8;          // %Qi.j
constexpr uint32_t kKeepOff = kOutOff + kUnits * kPointsPerUnit / 8;        // %M0..%M63
constexpr uint32_t kRelayOff = kKeepOff + kRetainedBits / 8;                // %M64..%M127
constexpr uint32_t kSysOff = kRelayOff + (kMemoryBits - kRetainedBits) / 8; // %S0..%S127
constexpr uint32_t kScratchOff = kSysOff + kSystemBits / 8;
constexpr uint32_t kWordOff = (kScratchOff + kScratchBytes + 1) / 2 * 2; // %MWi
constexpr uint32_t kConstOff = kWordOff + 2 * kWords;                    // %KWi
constexpr uint32_t kSysWordOff = kConstOff + 2 * kConstWords;            // %SWi
constexpr uint32_t kEnd = kSysWordOff + 2 * kSystemWords;

constexpr uint32_t mem(uint32_t off) {
  return static_cast<uint32_t>(offsetof(lj_state, mem)) + off;
}

constexpr AreaInfo bits(const char *name, int32_t bytes, bool writable, uint32_t off) {
  return {name, bytes, 1, false, writable, true, mem(off)};
}
constexpr AreaInfo words(const char *name, int32_t count, bool writable, uint32_t off) {
  return {name, count, 2, true, writable, true, mem(off)};
}
constexpr AreaInfo none() { return {"", 0, 0, false, false}; }

constexpr TargetProfile kIec{
    "iec",
    {{
        bits("%I", kUnits *kPointsPerUnit / 8, false, kInOff),            // Input
        bits("%Q", kUnits *kPointsPerUnit / 8, true, kOutOff),            // Output
        none(),                                                           // NcStatus
        none(),                                                           // NcControl
        bits("%M64", (kMemoryBits - kRetainedBits) / 8, true, kRelayOff), // Relay: %M64..%M127
        words("%MW", kWords, true, kWordOff),                             // Word
        none(),                                                           // DWord
        none(),                                                           // Retained
        none(),                                                           // Param
        {"%TM", 32, 0, false, false, true, 0},                            // Timer (L1269)
        {"%C", 16, 0, false, false, true, 0},                             // Counter (L1104-1168)
        {"%L", kLabels + 1, 0, false, false, false, 0},                   // Label (+ the end label)
        {"SR", kSubroutines, 0, false, false, false, 0},                  // Subroutine
        bits("%M", kRetainedBits / 8, true, kKeepOff),                    // KeepRelay: %M0..%M63
        bits("%~", kScratchBytes, true, kScratchOff),                     // ExtraRelay: scratch
        none(),                                                           // MessageBits
        none(),                                                           // TimerData
        none(),                                                           // CounterData
        none(),                                                           // DataTable
        bits("%S", kSystemBits / 8, true, kSysOff),                       // SystemBits
        words("%SW", kSystemWords, true, kSysWordOff),                    // SystemWords
        words("%KW", kConstWords, false, kConstOff),                      // ConstWords
        {"?", 0, 0, false, false, false, 0},
    }},
    {{{0, 31}, {0, -1}}},
    {{{0, 15}, {0, -1}}},
    {1, 10, 100, 1000},
    areas(Area::KeepRelay), // the first 64 %M survive a power failure (L542)
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
    {}, // %S1 is set by the program's own init part (frontends/iec), so every host agrees
};

static_assert(kEnd <= LJ_MEM_BYTES, "the IEC objects fit lj_state.mem");
static_assert(kWordOff % 2 == 0 && kConstOff % 2 == 0 && kSysWordOff % 2 == 0);

} // namespace

const TargetProfile &iec::profile() { return kIec; }

} // namespace lj

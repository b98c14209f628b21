// The IEC IL (Neza) target profile: the Neza objects of modicon-neza.md 1 laid in the
// profile-laid byte region lj_state.mem (runtime_abi/include/ladderjit/abi.h v3; docs/iec-il.md
// "Process image"), checked against it at compile time.
#include "profiles/iec/IecProfile.h"

#include "ir/IecBlocks.h"
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
constexpr uint32_t kTimerOff = kSysWordOff + 2 * kSystemWords;           // %TMi words
constexpr uint32_t kCounterOff = kTimerOff + 2 * kTimers * kTimerWords;  // %Ci words
constexpr uint32_t kEnd = kCounterOff + 2 * kCounters * kCounterWords;

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

constexpr uint32_t sysByte(int32_t n) { return mem(kSysOff + static_cast<uint32_t>(n / 8)); }
constexpr uint8_t sysBit(int32_t n) { return static_cast<uint8_t>(n % 8); }
using K = SystemBit::Kind;
/// The system bits the runtime writes before every tick (docs/iec-il.md "System bits"): %S0 /
/// %S1 cold / warm start and %S13 first scan (every start of ladderjit is both: the seed's
/// `LD %S1 / ENDC`, L581-582, suppresses the start edges after either), %S4..%S7 the 10 ms,
/// 100 ms, 1 s and 1 min square waves (modicon-neza.md 11).
constexpr SystemBit kSystemBitTable[] = {
    {sysByte(0), sysBit(0), K::FirstScan},   {sysByte(1), sysBit(1), K::FirstScan},
    {sysByte(4), sysBit(4), K::Clock, 5},    {sysByte(5), sysBit(5), K::Clock, 50},
    {sysByte(6), sysBit(6), K::Clock, 500},  {sysByte(7), sysBit(7), K::Clock, 30000},
    {sysByte(13), sysBit(13), K::FirstScan},
};

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
        none(),                                                           // Timer
        none(),                                                           // Counter
        {"%L", kLabels + 1, 0, false, false, false, 0},                   // Label (+ the end label)
        {"SR", kSubroutines, 0, false, false, false, 0},                  // Subroutine
        bits("%M", kRetainedBits / 8, true, kKeepOff),                    // KeepRelay: %M0..%M63
        bits("%~", kScratchBytes, true, kScratchOff),                     // ExtraRelay: scratch
        none(),                                                           // MessageBits
        words("%TM", kTimers *kTimerWords, true, kTimerOff),              // TimerData: %TMi
        words("%C", kCounters *kCounterWords, true, kCounterOff),         // CounterData: %Ci
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
    kSystemBitTable,
};

static_assert(kEnd <= LJ_MEM_BYTES, "the IEC objects fit lj_state.mem");
static_assert(kWordOff % 2 == 0 && kConstOff % 2 == 0 && kSysWordOff % 2 == 0);

} // namespace

const TargetProfile &iec::profile() { return kIec; }

} // namespace lj

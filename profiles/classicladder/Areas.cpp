// The ClassicLadder target profile: %I %Q %B %W, the rung cells' state and the blocks' words laid
// in the profile-laid byte region lj_state.mem (runtime_abi/include/ladderjit/abi.h), checked
// against it at compile time. Bit variable n of an area is bit n % 8 of its byte n / 8.
#include "profiles/classicladder/ClassicLadderProfile.h"

#include "ladderjit/abi.h"

#include <cstddef>

namespace lj {

namespace {

using namespace classicladder;

constexpr uint32_t kInOff = 0;                       // %I
constexpr uint32_t kOutOff = kInOff + kInputs / 8;   // %Q
constexpr uint32_t kBitOff = kOutOff + kOutputs / 8; // %B
constexpr uint32_t kSysOff = kBitOff + kBits / 8;    // %S
constexpr uint32_t kWordOff =
    (kSysOff + (kSystemBits + 7) / 8 + 3) / 4 * 4;                    // %W, then the scratch words
constexpr uint32_t kWordInOff = kWordOff + 4 * (kWords + kTempWords); // %IW
constexpr uint32_t kWordOutOff = kWordInOff + 4 * kWordInputs;        // %QW
constexpr uint32_t kFloatInOff = kWordOutOff + 4 * kWordOutputs;      // %IF
constexpr uint32_t kFloatOutOff = kFloatInOff + 4 * kFloatInputs;     // %QF
constexpr uint32_t kCellOff = kFloatOutOff + 4 * kFloatOutputs;       // cell states
constexpr uint32_t kBlockOff = (kCellOff + kCellBytes + 3) / 4 * 4;   // the blocks' words
constexpr uint32_t kEnd = kBlockOff + 4 * kBlockWords;

constexpr uint32_t mem(uint32_t off) {
  return static_cast<uint32_t>(offsetof(lj_state, mem)) + off;
}

constexpr AreaInfo bits(const char *name, int32_t bytes, bool writable, uint32_t off) {
  return {name, bytes, 1, false, writable, true, mem(off)};
}
constexpr AreaInfo none() { return {"", 0, 0, false, false}; }

constexpr TargetProfile kClassicLadder{
    "classicladder",
    {{
        bits("%I", kInputs / 8, false, kInOff),  // Input: HAL in-NN
        bits("%Q", kOutputs / 8, true, kOutOff), // Output: HAL out-NN
        none(),                                  // NcStatus
        {"%QF", kFloatOutputs, 4, true, true, false,
         mem(kFloatOutOff)},                                         // NcControl: %QF (floatout)
        bits("%B", kBits / 8, true, kBitOff),                        // Relay
        {"%IW", kWordInputs, 4, true, true, false, mem(kWordInOff)}, // Word: %IW (s32in)
        {"%W", kWords + kTempWords, 4, true, true, false, mem(kWordOff)}, // DWord: %W, scratch
        {"%QW", kWordOutputs, 4, true, true, false, mem(kWordOutOff)},    // Retained: %QW (s32out)
        {"%IF", kFloatInputs, 4, true, false, false,
         mem(kFloatInOff)},                               // Param: %IF (floatin, read-only)
        none(),                                           // Timer
        none(),                                           // Counter
        {"%L", 4096, 0, false, false, false, 0},          // Label: one per rung placed
        {"SR", 64, 0, false, false, false, 0},            // Subroutine: SR0..SR63
        bits("%S", (kSystemBits + 7) / 8, true, kSysOff), // KeepRelay: %S (never retained)
        bits("%~", kCellBytes, true, kCellOff),           // ExtraRelay: cell states
        none(),                                           // MessageBits
        {"%~T", kBlockWords, 4, true, true, true, mem(kBlockOff)}, // TimerData: the blocks
        none(),                                                    // CounterData
        none(),                                                    // DataTable
        none(),                                                    // SystemBits
        none(),                                                    // SystemWords
        none(),                                                    // ConstWords
        {"?", 0, 0, false, false, false, 0},
    }},
    {{{0, -1}, {0, -1}}},
    {{{0, -1}, {0, -1}}},
    {1, 10, 100, 1000},
    0, // nothing survives a restart: classicladder_rt starts from zero
    {0, -1},
    {0, -1},
    {{{"init", Op::EndInit, PartSpec::Schedule::Once},
      {"cyclic", Op::EndCyclic, PartSpec::Schedule::EveryTick},
      {"sliced", Op::EndSliced, PartSpec::Schedule::Sliced}}},
    2000000,
    8,
    200,
    0,
    0,
    EdgePolicy::PerInstance,
    {0, 0, 0, 0, 0, 0, 0, 0},
    {},
    {},
    {0, 0, 0, 0, 0, 0, 0},
    {},
};

static_assert(kEnd <= LJ_MEM_BYTES, "the ClassicLadder variables fit lj_state.mem");

} // namespace

const TargetProfile &classicladder::profile() { return kClassicLadder; }

} // namespace lj

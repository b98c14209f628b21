// The ClassicLadder target profile (LinuxCNC's classicladder_rt, docs/classicladder.md "The
// classicladder profile"; layout: profiles/classicladder/Areas.cpp). Only the ClassicLadder front
// end, the profile registry (profiles/Profiles.h) and the dialect registry name it; the core
// reads the profile a program carries.
#pragma once

#include "ir/ClBlocks.h"
#include "ir/Profile.h"

#include <cstdint>

namespace lj::classicladder {

/// The ClassicLadder profile.
const TargetProfile &profile();

/// How many of each variable the profile holds. classicladder_rt sizes them at `loadrt` time
/// (defaults: 15 %I, 15 %Q, 20 %B, 20 %W); the profile holds the largest project ladderjit
/// accepts, and the front end refuses a variable number beyond these with a located error.
constexpr int32_t kInputs = 512;  ///< %I0..%I511 (HAL in-NN)
constexpr int32_t kOutputs = 512; ///< %Q0..%Q511 (HAL out-NN)
constexpr int32_t kBits = 2048;   ///< %B0..%B2047
/// %S0..%S19: ClassicLadder's system bits. LinuxCNC 2.9's RT module never writes them (they
/// start at 0 and only coils change them), so they are plain bits here; 20 as in classicladder.h.
constexpr int32_t kSystemBits = 20;
constexpr int32_t kWords = 1024;      ///< %W0..%W1023, 32-bit signed (ClassicLadder's int)
constexpr int32_t kWordInputs = 256;  ///< %IW0..%IW255 (HAL s32in-NN), 32-bit signed
constexpr int32_t kWordOutputs = 256; ///< %QW0..%QW255 (HAL s32out-NN), 32-bit signed
/// %IF0..%IF63 (HAL floatin-NN, which 2.9 reads as int: the host writes the truncated value)
/// and %QF0..%QF63 (HAL floatout-NN: expressions write whole numbers), 32-bit signed.
constexpr int32_t kFloatInputs = 64, kFloatOutputs = 64;
/// Scratch words after %W1023 for the operate and compare blocks' expressions (one per level of
/// an expression tree), never named by a program.
constexpr int32_t kTempWords = 64;
/// The cell state bytes: one bit per grid cell for the power leaving its right edge
/// (DynamicOutput) and one per edge contact for its previous value (DynamicVarBak), never
/// named by a program (docs/classicladder.md "Rungs on the IR").
constexpr int32_t kCellBytes = 40000;
/// The blocks the profile holds (classicladder_rt's defaults are 10 of each): old timers %T,
/// monostables %M, counters %C, IEC timers %TM. Their words (ir/ClBlocks.h) are the 32-bit
/// elements of the block area (Area::TimerData): the scan clock first, then each kind's blocks.
constexpr int32_t kOldTimers = 128, kMonostables = 128, kCounters = 128, kIecTimers = 128;
constexpr int32_t kClockAt = 0;
constexpr int32_t kTimerAt = kClockAt + clblocks::kClockWords;
constexpr int32_t kMonoAt = kTimerAt + clblocks::kTimerWords * kOldTimers;
constexpr int32_t kCounterAt = kMonoAt + clblocks::kMonoWords * kMonostables;
constexpr int32_t kIecAt = kCounterAt + clblocks::kCounterWords * kCounters;
/// The jumps of the current section pass and the stop flag (calc.c MadLoopBreak: more than
/// 99,999 jumps in one section pass stop the ladder for good), then the end of the area.
constexpr int32_t kJumpsAt = kIecAt + clblocks::kIecWords * kIecTimers;
constexpr int32_t kStoppedAt = kJumpsAt + 1;
constexpr int32_t kBlockWords = kStoppedAt + 1;
/// More jumps than this in one section pass stop the ladder (calc.c).
constexpr int32_t kMaxJumps = 99999;

} // namespace lj::classicladder

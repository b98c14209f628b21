// The Neza function blocks %TMi and %Ci (Op::IecTimer, Op::IecCounter; modicon-neza.md 3,
// docs/iec-il.md "Function blocks"): the layout of their words and the constants both engines
// (interp/InterpIec.cpp, lowering/EmitIec.cpp) and the IEC front end share.
#pragma once

#include <cstdint>

namespace lj::iec {

/// Words of one timer in the TimerData area: %TMi.V, %TMi.P, the status word, and the
/// now_ms (low 32 bits) at which the current timing started, low half first.
enum TimerWord : int32_t { kTimerV, kTimerP, kTimerStatus, kTimerStartLo, kTimerStartHi };
constexpr int32_t kTimerWords = 5;
/// Status word bits of a timer: %TMi.Q, timing in progress, IN at the last execution (TP).
constexpr int32_t kTimerQ = 0, kTimerRun = 1, kTimerPrevIn = 2;

/// Words of one counter in the CounterData area: %Ci.V, %Ci.P, the status word.
enum CounterWord : int32_t { kCounterV, kCounterP, kCounterStatus };
constexpr int32_t kCounterWords = 3;
/// Status word bits of a counter: %Ci.E, %Ci.D, %Ci.F, CU and CD at their last execution.
constexpr int32_t kCounterE = 0, kCounterD = 1, kCounterF = 2, kCounterPrevUp = 3,
                  kCounterPrevDown = 4;
/// The inputs a counter execution drives (Op::IecCounter operand 1): the BLK form drives all
/// four, the instruction form (`CU %Ci`) one.
constexpr int32_t kPinR = 1, kPinS = 2, kPinCu = 4, kPinCd = 8, kPinsAll = 15;

/// Timer types (Op::IecTimer operand 1; L1249-1265).
enum class TimerType : int32_t { Ton, Tof, Tp };
/// Time bases by code (Op::IecTimer operand 2; L1274-1275): 1 min (the default), 1 s, 100 ms,
/// 10 ms, 1 ms (1 ms only for %TM0 and %TM1).
constexpr uint32_t kTimeBaseMs[5] = {60000, 1000, 100, 10, 1};
/// The highest counter value: counting up from it gives 0 and F, down from 0 gives it and E.
constexpr int32_t kCounterMax = 9999;
/// The preset range the seed gives for both blocks (L1276-1278) and the default preset.
constexpr int32_t kPresetMax = 9999;

} // namespace lj::iec

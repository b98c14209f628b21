// The ClassicLadder function blocks (Op::ClClock, ClTimer, ClMonostable, ClCounter, ClIecTimer;
// LinuxCNC 2.9 `calc.c`, docs/classicladder.md "Timers, monostables and counters"): the layout
// of their words and the constants the interpreter (interp/InterpClassicLadder.cpp), the
// lowering (lowering/EmitClassicLadder.cpp) and the classicladder front end share. Every word
// is a 32-bit element of the block area; a flag is a word holding 0 or 1, so a contact reads
// it as bit 0 of the word.
#pragma once

#include <cstdint>

namespace lj::clblocks {

/// The scan clock (Op::ClClock): the milliseconds this scan advances every timer
/// (ClassicLadder's nominal period) and the now_ms of the previous scan.
enum ClockWord : int32_t { kClockDt, kClockPrev };
constexpr int32_t kClockWords = 2;
/// Op::ClClock modes: at the start of each scan (dt := now - prev, prev := now), and in the
/// init part (prev := now - kFirstPeriodMs, so the first scan advances by that much).
constexpr int32_t kClockScan = 0, kClockPowerUp = 1;
/// The first scan's period: LinuxCNC's servo thread of 1 ms (classicladder_rt accumulates the
/// thread period before every scan, so its first scan already counts one period).
constexpr int32_t kFirstPeriodMs = 1;

/// Old timer %Tn (element 10): preset and remaining value in ms (both Preset/Value of
/// calc.c, V counts down), the D and R outputs.
enum TimerWord : int32_t { kTimerPresetMs, kTimerValueMs, kTimerDone, kTimerRunning };
constexpr int32_t kTimerWords = 4;

/// Monostable %Mn (element 11): preset and remaining value in ms, R, the input's last value.
enum MonoWord : int32_t { kMonoPresetMs, kMonoValueMs, kMonoRunning, kMonoInputBak };
constexpr int32_t kMonoWords = 4;

/// Counter %Cn (element 12): P, V, V before its last change, U and D at the last scan, E, D, F.
enum CounterWord : int32_t {
  kCounterPreset,
  kCounterValue,
  kCounterValueBak,
  kCounterUpBak,
  kCounterDownBak,
  kCounterEmpty,
  kCounterDone,
  kCounterFull
};
constexpr int32_t kCounterWords = 8;
/// A counter wraps from 9999 up to 0 (F) and from 0 down to 9999 (E).
constexpr int32_t kCounterMax = 9999;

/// IEC timer %TMn (element 13): P and V in base units (V counts up), the ms accumulated
/// towards the next base unit (kept across resets, as calc.c keeps it), Q, the input's last
/// value, and whether a TOF/TP is timing.
enum IecWord : int32_t { kIecPreset, kIecValue, kIecAcc, kIecQ, kIecInputBak, kIecStarted };
constexpr int32_t kIecWords = 6;
/// IEC timer modes (Op::ClIecTimer operand 2; timers_iec.csv).
constexpr int32_t kIecTon = 0, kIecTof = 1, kIecTp = 2;

} // namespace lj::clblocks

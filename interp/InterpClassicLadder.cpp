// Interpreter semantics of family ClassicLadder: the scan clock and the old timer, monostable,
// counter and IEC timer of LinuxCNC 2.9's classicladder_rt (`calc.c`; the statement checked
// against classicladder_rt is oracle/classicladder/RefScan.cpp, docs/classicladder.md "Timers,
// monostables and counters"). The lowering is lowering/EmitClassicLadder.cpp; both share the
// word layout of ir/ClBlocks.h. Values wrap like 32-bit ints.
#include "interp/InterpreterInternal.h"
#include "ir/ClBlocks.h"

namespace lj::interp {

namespace {

using namespace clblocks;

/// Word k of the block whose first word is `base` (a 32-bit element of the block area).
Ref word(const Ref &base, int32_t k) {
  Ref r = base;
  r.off += static_cast<uint32_t>(4 * k);
  return r;
}

/// The words of one block, read on entry and written back on exit.
struct Words {
  lj_state *s;
  const Ref &base;
  int32_t get(int32_t k) const { return readValue(s, word(base, k)); }
  void set(int32_t k, int32_t v) const { writeValue(s, word(base, k), v); }
};

void clock(lj_state *s, const Ref *o) {
  const Words w{s, o[0]};
  const auto now = static_cast<uint32_t>(s->now_ms);
  if (o[1].value == kClockPowerUp) {
    w.set(kClockDt, 0);
    w.set(kClockPrev, wrap(now - static_cast<uint32_t>(kFirstPeriodMs)));
    return;
  }
  w.set(kClockDt, wrap(now - static_cast<uint32_t>(w.get(kClockPrev))));
  w.set(kClockPrev, wrap(now));
}

/// calc.c CalcTypeTimer: E low reloads V; E and C count V down; V at or below 0 is done.
bool oldTimer(lj_state *s, const Ref *o, bool e, bool c) {
  const Words w{s, o[0]};
  const int32_t dt = Words{s, o[1]}.get(kClockDt);
  if (!e) {
    w.set(kTimerRunning, 0);
    w.set(kTimerDone, 0);
    w.set(kTimerValueMs, w.get(kTimerPresetMs));
  } else if (w.get(kTimerValueMs) > 0) {
    if (c) {
      w.set(kTimerValueMs, subWrap(w.get(kTimerValueMs), dt));
      w.set(kTimerRunning, 1);
      w.set(kTimerDone, 0);
    }
  } else {
    w.set(kTimerRunning, 0);
    w.set(kTimerDone, 1);
  }
  return w.get(kTimerDone) != 0;
}

/// calc.c CalcTypeMonostable: a rising input starts it only when V is exactly 0.
bool monostable(lj_state *s, const Ref *o, bool in) {
  const Words w{s, o[0]};
  const int32_t dt = Words{s, o[1]}.get(kClockDt);
  if (in && !w.get(kMonoInputBak) && w.get(kMonoValueMs) == 0) {
    w.set(kMonoRunning, 1);
    w.set(kMonoValueMs, w.get(kMonoPresetMs));
  }
  if (w.get(kMonoValueMs) > 0)
    w.set(kMonoValueMs, subWrap(w.get(kMonoValueMs), dt));
  else
    w.set(kMonoRunning, 0);
  w.set(kMonoInputBak, in);
  return w.get(kMonoRunning) != 0;
}

/// calc.c CalcTypeCounter: up and down on rising edges, then preset, then reset (reset wins);
/// D = (V == P), E and F flag a wrap through 0 / 9999 in the last change.
bool counter(lj_state *s, const Ref *o, bool reset, bool preset, bool up, bool down) {
  const Words w{s, o[0]};
  int32_t v = w.get(kCounterValue), bak = w.get(kCounterValueBak);
  if (up && !w.get(kCounterUpBak)) {
    bak = v;
    v = addWrap(v, 1);
    if (v > kCounterMax) v = 0;
  }
  if (down && !w.get(kCounterDownBak)) {
    bak = v;
    v = subWrap(v, 1);
    if (v < 0) v = kCounterMax;
  }
  w.set(kCounterUpBak, up);
  w.set(kCounterDownBak, down);
  if (preset) {
    bak = v;
    v = w.get(kCounterPreset);
  }
  if (reset) {
    bak = v;
    v = 0;
  }
  w.set(kCounterValue, v);
  w.set(kCounterValueBak, bak);
  w.set(kCounterDone, v == w.get(kCounterPreset));
  w.set(kCounterEmpty, v == kCounterMax && bak == 0);
  w.set(kCounterFull, v == 0 && bak == kCounterMax);
  return w.get(kCounterEmpty) != 0;
}

/// calc.c CalcTypeTimerIEC: Q changes when V has reached P at the start of a scan (one scan
/// late); V counts whole base units of accumulated ms, the partial unit kept across resets.
bool iecTimer(lj_state *s, const Ref *o, bool in) {
  const Words w{s, o[0]};
  const int32_t dt = Words{s, o[1]}.get(kClockDt);
  const int32_t mode = o[2].value, baseMs = o[3].value;
  int32_t q = w.get(kIecQ), v = w.get(kIecValue), started = w.get(kIecStarted);
  const int32_t p = w.get(kIecPreset), bak = w.get(kIecInputBak);
  bool inc = false;
  auto timeOut = [&] {
    if (v < p) {
      inc = true;
    } else {
      q = 0;
      v = 0;
      started = 0;
    }
  };
  switch (mode) {
  case kIecTon:
    if (!in)
      q = 0, v = 0;
    else if (v < p)
      inc = true;
    else
      q = 1;
    break;
  case kIecTof:
    if (in)
      q = 1, v = 0, started = 0;
    else if (bak)
      started = 1;
    if (started) timeOut();
    break;
  default: // kIecTp
    if (in && !bak && !started) q = 1, v = 0, started = 1;
    if (started) timeOut();
    break;
  }
  if (inc) {
    int32_t acc = addWrap(w.get(kIecAcc), dt);
    if (acc >= baseMs) {
      v = addWrap(v, 1);
      acc -= baseMs;
    }
    w.set(kIecAcc, acc);
  }
  w.set(kIecQ, q);
  w.set(kIecValue, v);
  w.set(kIecStarted, started);
  w.set(kIecInputBak, in);
  return q != 0;
}

} // namespace

bool runClassicLadder(const BlockCall &b) {
  lj_state *s = b.s;
  const Ref *o = b.ops;
  switch (b.c.op) {
  case Op::ClClock:
    clock(s, o);
    return true;
  case Op::ClTimer: {
    const bool c = b.f.pop(), e = b.f.pop();
    b.f.push(oldTimer(s, o, e, c));
    return true;
  }
  case Op::ClMonostable:
    b.f.output(monostable(s, o, b.f.input()));
    return true;
  case Op::ClCounter: {
    const bool down = b.f.pop(), up = b.f.pop(), preset = b.f.pop(), reset = b.f.pop();
    b.f.push(counter(s, o, reset, preset, up, down));
    return true;
  }
  case Op::ClIecTimer:
    b.f.output(iecTimer(s, o, b.f.input()));
    return true;
  default:
    return false;
  }
}

} // namespace lj::interp

// The Neza function blocks of the reference interpreter (twin of lowering/EmitIec.cpp;
// semantics in docs/iec-il.md "Function blocks"): the whole state of a block is in its words.
#include "interp/Interpreter.h"
#include "interp/InterpreterInternal.h"
#include "ir/IecBlocks.h"

#include <algorithm>

namespace lj::interp {

namespace {

/// Word k of the block whose first word is `base` (a 16-bit element of lj_state.mem).
Ref word(const Ref &base, int32_t k) {
  Ref r = base;
  r.off += static_cast<uint32_t>(2 * k);
  return r;
}

bool bit(int32_t w, int32_t b) { return ((w >> b) & 1) != 0; }
int32_t bitv(bool v, int32_t b) { return v ? (1 << b) : 0; }

} // namespace

void iecTimer(lj_state *s, Frame &f, const Code &c) {
  using namespace iec;
  const bool in = f.input();
  const int32_t p = std::max(readValue(s, word(c.a, kTimerP)), 0);
  const int32_t status = readValue(s, word(c.a, kTimerStatus));
  bool q = bit(status, kTimerQ), run = bit(status, kTimerRun);
  const bool prev = bit(status, kTimerPrevIn);
  int32_t v = readValue(s, word(c.a, kTimerV));
  uint32_t start = (static_cast<uint32_t>(readValue(s, word(c.a, kTimerStartLo))) & 0xFFFFu) |
                   (static_cast<uint32_t>(readValue(s, word(c.a, kTimerStartHi))) << 16);
  const uint32_t now = static_cast<uint32_t>(s->now_ms);
  const uint32_t tb = kTimeBaseMs[c.c.value];
  const uint32_t presetMs = static_cast<uint32_t>(p) * tb; // <= 32767 * 60000 < 2^32
  // Timing from `start` (set now when not running): V in time-base units, `done` at the preset.
  auto timing = [&](bool &out, bool endValue) {
    if (!run) {
      run = true;
      start = now;
    }
    const uint32_t el = now - start; // modulo 2^32: exact below 49 days
    if (el >= presetMs) {
      out = endValue;
      run = false;
      v = p;
    } else {
      v = static_cast<int32_t>(el / tb);
    }
  };
  switch (static_cast<TimerType>(c.b.value)) {
  case TimerType::Ton:
    if (!in) {
      run = q = false;
      v = 0;
    } else if (!q) {
      timing(q, true);
    }
    break;
  case TimerType::Tof:
    if (in) {
      run = false;
      q = true;
      v = 0;
    } else if (q) {
      timing(q, false);
    }
    break;
  case TimerType::Tp:
    if (!q && in && !prev) {
      q = run = true;
      start = now;
    }
    if (q) timing(q, false);
    if (!q && !in) v = 0;
    break;
  }
  writeValue(s, word(c.a, kTimerV), v);
  writeValue(s, word(c.a, kTimerStatus),
             bitv(q, kTimerQ) | bitv(run, kTimerRun) | bitv(in, kTimerPrevIn));
  writeValue(s, word(c.a, kTimerStartLo), static_cast<int32_t>(start & 0xFFFFu));
  writeValue(s, word(c.a, kTimerStartHi), static_cast<int32_t>(start >> 16));
  f.output(in);
}

void iecCounter(lj_state *s, Frame &f, const Code &c) {
  using namespace iec;
  const bool cd = f.pop(), cu = f.pop(), preset = f.pop(), reset = f.pop();
  const int32_t pins = c.b.value;
  const int32_t status = readValue(s, word(c.a, kCounterStatus));
  bool e = bit(status, kCounterE), d = bit(status, kCounterD), full = bit(status, kCounterF);
  bool prevUp = bit(status, kCounterPrevUp), prevDown = bit(status, kCounterPrevDown);
  const bool up = (pins & kPinCu) && cu && !prevUp;
  const bool down = (pins & kPinCd) && cd && !prevDown;
  if (pins & kPinCu) prevUp = cu;
  if (pins & kPinCd) prevDown = cd;
  int32_t v = readValue(s, word(c.a, kCounterV));
  const int32_t p = readValue(s, word(c.a, kCounterP));
  if ((pins & kPinR) && reset) {
    v = 0;
    e = d = full = false;
  } else if ((pins & kPinS) && preset) {
    v = p;
    e = full = false;
    d = true;
  } else {
    if (up && !down) {
      full = v >= kCounterMax;
      v = full ? 0 : v + 1;
    } else if (down && !up) {
      e = v <= 0;
      v = e ? kCounterMax : v - 1;
    }
    d = v == p;
  }
  writeValue(s, word(c.a, kCounterV), v);
  writeValue(s, word(c.a, kCounterStatus),
             bitv(e, kCounterE) | bitv(d, kCounterD) | bitv(full, kCounterF) |
                 bitv(prevUp, kCounterPrevUp) | bitv(prevDown, kCounterPrevDown));
  f.push(d);
}

} // namespace lj::interp

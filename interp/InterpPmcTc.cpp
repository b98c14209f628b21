// Interpreter semantics of family PmcTc: the FANUC PMC timers TMR/TMRC, the counters
// CTR/CTRB/CTRC, COMPB (R9000 flags), COMP/COIN (BCD), NEx and RNGx
// (FANUC PMC manual ref 6.3, 6.4, 6.6; choices in docs/fanuc-pmc.md). The lowering
// is lowering/EmitPmcTc.cpp; both share ir/PmcTc.h for the unit tables and the BCD reading.
#include "interp/InterpreterInternal.h"
#include "ir/Bcd.h"
#include "ir/PmcTc.h"

namespace lj::interp {

namespace {

/// On-delay timing on the instance's two words ([0] start, low 32 bits of now_ms; [1] 0 idle,
/// 1 timing, 2 done). Returns W1.
bool onDelay(lj_state *s, int32_t slot, bool act, uint32_t presetMs) {
  int32_t *w = &s->inst_word[slot];
  if (!act) {
    w[1] = 0;
    return false;
  }
  const auto now = static_cast<uint32_t>(s->now_ms);
  if (w[1] == 0) {
    w[1] = 1;
    w[0] = static_cast<int32_t>(now);
  }
  if (w[1] == 1 && now - static_cast<uint32_t>(w[0]) >= presetMs) w[1] = 2;
  return w[1] == 2;
}

/// The 4 BCD digits of `v` (>= 0; digits above the fourth dropped).
int32_t bcdDigits(int32_t v) {
  return static_cast<int32_t>(bcd::encode(static_cast<uint32_t>(v), 4));
}

uint32_t elapsedMs(const lj_state *s, int32_t slot, uint32_t presetMs) {
  const int32_t *w = &s->inst_word[slot];
  if (w[1] == 0) return 0;
  if (w[1] == 2) return presetMs;
  return static_cast<uint32_t>(s->now_ms) - static_cast<uint32_t>(w[0]);
}

} // namespace

bool runPmcTc(const BlockCall &b) {
  lj_state *s = b.s;
  const Ref *o = b.ops;
  switch (b.c.op) {
  case Op::PmcTimer: {
    const uint32_t unit = pmc::tmrUnitMs(readValue(s, o[2]), o[0].value);
    const uint32_t preset = pmc::presetMs(readValue(s, o[1]), unit);
    b.f.output(onDelay(s, b.c.slot, b.f.input(), preset));
    return true;
  }
  case Op::PmcTimerAddr: {
    const uint32_t unit = pmc::tmrcUnitMs(o[0].value);
    const uint32_t preset = pmc::presetMs(readValue(s, o[1]), unit);
    const bool out = onDelay(s, b.c.slot, b.f.input(), preset);
    writeValue(s, o[2], static_cast<int32_t>(elapsedMs(s, b.c.slot, preset)));
    b.f.output(out);
    return true;
  }
  case Op::PmcCounter: {
    // ST3..ST0 = CN0, UPDOWN, RST, ACT (reference 5: ACT is the last loaded).
    const bool act = b.f.pop(), rst = b.f.pop(), down = b.f.pop(), cn0 = b.f.pop();
    // CTR follows the counter data type of the system parameter (reference 6.4): in BCD the
    // preset and the count are 4 BCD digits (a digit above 9 counts its binary value, as
    // COMP/COIN read it) and the new count is written as the 4 digits of its value.
    const uint32_t typeAt = b.tp.systemParams.counterFormat;
    const bool bcd = o[2].kind == Ref::Kind::Const && o[2].value == pmc::kCounterSystemType &&
                     typeAt != 0 && bytes(s)[typeAt] == TargetProfile::kCounterBcd;
    auto value = [&](const Ref &r) {
      return bcd ? pmc::bcdValue(readValue(s, r), 2) : readValue(s, r);
    };
    const int32_t pv = value(o[0]), cv = value(o[1]);
    const int32_t init = cn0 ? 1 : 0;
    const bool rise = act && s->edge[b.c.slot] == 0;
    int32_t next = cv;
    if (rst)
      next = down ? pv : init;
    else if (rise && down)
      next = cv <= init ? pv : subWrap(cv, 1);
    else if (rise)
      next = cv >= pv ? init : addWrap(cv, 1);
    s->edge[b.c.slot] = act;
    writeValue(s, o[1], bcd ? bcdDigits(next) : next);
    const int32_t stored = value(o[1]); // as the register holds it (2 bytes)
    const bool reached = down ? stored <= init : stored >= pv;
    b.f.push(!rst && reached);
    return true;
  }
  case Op::PmcCompareFlags: {
    if (!b.f.input()) return true;
    const int32_t in = readValue(s, o[0]), ref = readValue(s, o[1]);
    int32_t flags = readValue(s, o[2]) & ~(pmc::kFlagZ | pmc::kFlagN);
    if (in == ref) flags |= pmc::kFlagZ;
    if (in < ref) flags |= pmc::kFlagN;
    writeValue(s, o[2], flags);
    return true;
  }
  case Op::BcdCompare: {
    // ST1 = BYT (0: 2 digits in the first byte, 1: 4 digits in 2 bytes), ST0 = ACT.
    const bool act = b.f.pop(), byt = b.f.pop();
    const int width = byt ? 2 : 1;
    const int32_t in =
        o[1].kind == Ref::Kind::Const ? o[1].value : pmc::bcdValue(readValue(s, o[1]), width);
    const int32_t ref = pmc::bcdValue(readValue(s, o[2]), width);
    const bool cond = o[0].value == pmc::kBcdEqual ? in == ref : in <= ref;
    b.f.push(act && cond);
    return true;
  }
  case Op::CompareNe:
    b.f.output(b.f.input() && readValue(s, o[0]) != readValue(s, o[1]));
    return true;
  case Op::CompareBetween: {
    const int32_t d1 = readValue(s, o[0]), d2 = readValue(s, o[1]), x = readValue(s, o[2]);
    const bool in = (d1 <= x && x <= d2) || (d2 <= x && x <= d1);
    b.f.output(b.f.input() && in);
    return true;
  }
  default:
    return runFanucArith(b); // fanuc-c's arithmetic (InterpFanucArith.cpp), else false
  }
}

} // namespace lj::interp

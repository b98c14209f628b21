// The FANUC timers, counters and compares of family PmcTc (reference 6.3, 6.4, 6.6;
// docs/fanuc-pmc.md): TMR, TMRC, CTR, CTRB, CTRC, COMPB, COMP, COIN, NEB/NEW/NED, RNGB/RNGW/RNGD.
// Functional.cpp resolves `SUB n` or the name and hands the instruction here first.
#include "frontends/fanuc/ParserInternal.h"
#include "ir/PmcTc.h"
#include "profiles/fanuc/FanucProfile.h"

namespace lj::fanuc::detail {

namespace {

/// Resource counts of the 0i-D PMC (reference 7 "Resource counts", 6.3, 6.4).
constexpr int64_t kTmrTimers = 250, kCtrCounters = 100, kCtrbCounters = 100;

struct Spec {
  int sub;
  const char *name;
  int params;
  const char *roles;
  int inputs; ///< control inputs including ACT (ST entries the instruction needs)
  int width;  ///< data width of NEx / RNGx
};

constexpr Spec kSpecs[] = {
    {3, "TMR", 1, "timer number", 1, 0},
    {54, "TMRC", 3, "precision, set-time address, timer register address", 1, 0},
    {5, "CTR", 1, "counter number", 4, 0},
    {56, "CTRB", 2, "counter number, preset", 4, 0},
    {55, "CTRC", 2, "preset address, counter register address", 4, 0},
    {32, "COMPB", 3, "format, input data, comparison data address", 1, 0},
    {15, "COMP", 3, "input format, input data, comparison data address", 2, 0},
    {16, "COIN", 3, "input format, input data, comparison data address", 2, 0},
    {203, "NEB", 2, "data 1, data 2", 1, 1},
    {204, "NEW", 2, "data 1, data 2", 1, 2},
    {205, "NED", 2, "data 1, data 2", 1, 4},
    {218, "RNGB", 3, "data 1, data 2, input data", 1, 1},
    {219, "RNGW", 3, "data 1, data 2, input data", 1, 2},
    {220, "RNGD", 3, "data 1, data 2, input data", 1, 4},
};

const char *inputNames(int sub) {
  switch (sub) {
  case 5:
  case 55:
  case 56:
    return "CN0, UPDOWN, RST and ACT in ST3..ST0";
  case 15:
  case 16:
    return "BYT and ACT in ST1, ST0";
  default:
    return "its ACT input in ST0 (an RD before it)";
  }
}

/// The `□00△` format of COMPB: operand kind (thousands digit) and length (units digit).
bool compbFormat(Emitter &e, const Token &t, bool &isAddr, int &width) {
  int64_t v;
  if (!e.constant(t, 0, 9999, "format", v)) return false;
  width = static_cast<int>(v % 10);
  if ((width != 1 && width != 2 && width != 4) || (v / 10) % 100 != 0 || v / 1000 > 1) {
    e.error(t.loc, "LJ4056",
            "format '" + std::string(t.text) +
                "': expected 0001/0002/0004 (constant) or 1001/1002/1004 (address)");
    return false;
  }
  isAddr = v >= 1000;
  return true;
}

void emitSpec(Emitter &e, const Spec &sp, const Functional &f) {
  const SourceLoc at = f.head.loc;
  const auto &p = f.params;
  Operand a, b, c;
  switch (sp.sub) {
  case 3: { // TMR: preset T(2(n-1)), precision T9000 + 2(n-1) (reference 6.3, 1.1)
    int64_t n;
    if (!e.constant(p[0], 1, kTmrTimers, "timer number", n) || !e.claimNumber('M', n, p[0].loc))
      return;
    const auto k = static_cast<int32_t>(2 * (n - 1));
    e.emit(Op::PmcTimer, at,
           {konst(n, p[0].loc), implied(Area::TimerData, k, 2, p[0].loc),
            implied(Area::TimerData, 9000 + k, 2, p[0].loc)});
    return;
  }
  case 54: { // TMRC: precision code, 2-byte set time, 4-byte timer register
    int64_t code;
    if (!e.constant(p[0], 0, 7, "precision", code) || !e.dataOperand(p[1], 2, false, false, b) ||
        !e.dataOperand(p[2], 4, false, true, c))
      return;
    e.emit(Op::PmcTimerAddr, at, {konst(code, p[0].loc), b, c});
    return;
  }
  case 5: { // CTR: counter n at C(4(n-1)): preset +0..+1, current +2..+3 (reference 6.4)
    int64_t n;
    if (!e.constant(p[0], 1, kCtrCounters, "counter number", n) || !e.claimNumber('C', n, p[0].loc))
      return;
    const auto k = static_cast<int32_t>(4 * (n - 1));
    // The data type is the system parameter's (ref 6.4 "chosen globally": --params).
    e.emit(Op::PmcCounter, at,
           {implied(Area::CounterData, k, 2, p[0].loc),
            implied(Area::CounterData, k + 2, 2, p[0].loc), konst(pmc::kCounterSystemType, at)});
    break;
  }
  case 56: { // CTRB: constant preset, count value at C5000 + 2(n-1)
    int64_t n, pv;
    if (!e.constant(p[0], 1, kCtrbCounters, "counter number", n) ||
        !e.constant(p[1], 0, 32767, "preset", pv) || !e.claimNumber('B', n, p[0].loc))
      return;
    e.emit(Op::PmcCounter, at, // binary (ref 6.4 [L2073])
           {konst(pv, p[1].loc),
            implied(Area::CounterData, static_cast<int32_t>(5000 + 2 * (n - 1)), 2, p[0].loc),
            konst(pmc::kCounterBinary, at)});
    break;
  }
  case 55: { // CTRC: 2-byte preset, 4-byte register holding the count in its first 2 bytes
    if (!e.dataOperand(p[0], 2, false, false, a) || !e.dataOperand(p[1], 4, false, true, b)) return;
    b.width = 2;
    e.emit(Op::PmcCounter, at, {a, b, konst(pmc::kCounterBinary, at)});
    break;
  }
  case 32: { // COMPB: result in R9000 (reference 2, 6.6)
    bool isAddr;
    int w;
    if (!compbFormat(e, p[0], isAddr, w) || !e.dataOperand(p[1], w, !isAddr, false, a) ||
        !e.dataOperand(p[2], w, false, false, b))
      return;
    e.emit(Op::PmcCompareFlags, at, {a, b, implied(Area::Relay, 9000, 1, p[0].loc)});
    return;
  }
  case 15:
  case 16: { // COMP / COIN: BCD, 2 bytes read, BYT selects 2 or 4 digits at run time
    int64_t fmt, v;
    if (!e.constant(p[0], 0, 1, "input format (0 constant, 1 address)", fmt)) return;
    if (fmt == 0) {
      if (!e.constant(p[1], 0, 9999, "input data (decimal constant)", v)) return;
      a = konst(v, p[1].loc);
    } else if (!e.dataOperand(p[1], 2, false, false, a)) {
      return;
    }
    if (!e.dataOperand(p[2], 2, false, false, b)) return;
    e.emit(Op::BcdCompare, at, {konst(sp.sub == 16 ? 1 : 0, at), a, b});
    e.setDepth(e.depth() - 1);
    return;
  }
  case 203:
  case 204:
  case 205:
    if (!e.dataOperand(p[0], sp.width, true, false, a) ||
        !e.dataOperand(p[1], sp.width, true, false, b))
      return;
    e.emit(Op::CompareNe, at, {a, b});
    return;
  default: // RNGx
    if (!e.dataOperand(p[0], sp.width, true, false, a) ||
        !e.dataOperand(p[1], sp.width, true, false, b) ||
        !e.dataOperand(p[2], sp.width, true, false, c))
      return;
    e.emit(Op::CompareBetween, at, {a, b, c});
    return;
  }
  e.setDepth(e.depth() - 3); // a counter: four inputs, W1
}

} // namespace

bool emitTimerCounter(Emitter &e, const Functional &f, int sub, const std::string &what) {
  const Spec *sp = nullptr;
  for (const Spec &s : kSpecs)
    if (s.sub == sub) sp = &s;
  if (!sp) return false;
  if (static_cast<int>(f.params.size()) != sp->params) {
    e.error(f.head.loc, "LJ4057",
            what + " takes " + std::to_string(sp->params) + " parameters (" + sp->roles +
                "), got " + std::to_string(f.params.size()));
    return true;
  }
  if (e.depth() < sp->inputs) {
    e.error(f.head.loc, "LJ4058",
            what + " needs " + inputNames(sub) + ", found " + std::to_string(e.depth()) +
                " ST entries");
    return true;
  }
  emitSpec(e, *sp, f);
  return true;
}

} // namespace lj::fanuc::detail

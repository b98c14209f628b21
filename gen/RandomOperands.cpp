// Operand choice of the random program generator: register and bit addresses from the hot
// pools, constants, and the catalogue constraints the OperandSpecs cannot express (ranges that
// must fit their area, long ranges for the lowering's loops, ZRST zones, XMOV/XCH indirection,
// runtime-checked indices loaded with their edge values; hnc8-functions-2.md 0.5/0.6).
#include "gen/GenPools.h"
#include "gen/RandomGen.h"
#include "profiles/hnc8/Hnc8Profile.h"

#include <algorithm>
#include <cassert>
#include <iterator>

namespace lj::gen::detail {

namespace {

/// Consecutive elements register operand `i` of `op` uses: the table's span column, which the
/// verifier checks (verify/Verify{Data,Nc,Cnc}.cpp).
int32_t spanOf(Op op, int i) { return instrInfo(op).operands[i].span; }

/// Elements a written range may use: D88.. are the planner's guards.
int32_t rangeLimit(Area a, bool writes) {
  return writes && a == Area::DWord ? kGuardFirst : hnc8::profile().area(a).count;
}

} // namespace

int32_t RandomGen::tcFor(const InstrInfo &in) {
  auto &owner = tcOwner_[in.state == StateKind::Timer ? 0 : 1];
  for (int attempt = 0; attempt < 16; ++attempt) {
    int32_t n = tcNumber(rng_);
    auto it = owner.find(n);
    if (it == owner.end() || it->second == in.op) {
      owner[n] = in.op;
      return n;
    }
  }
  for (int32_t n = 0; n < 428; ++n) {
    if (lj_tc_slot(n) < 0) continue;
    auto it = owner.find(n);
    if (it == owner.end() || it->second == in.op) {
      owner[n] = in.op;
      return n;
    }
  }
  assert(false && "more timer/counter kinds than numbers");
  return 0;
}

int32_t RandomGen::constFor(const InstrInfo &in, int i) {
  const OperandSpec &sp = in.operands[i];
  int64_t lo = sp.cmin, hi = sp.cmax;
  // Catalogue constants whose useful values the range alone does not tell.
  switch (in.op) {
  case Op::MCodeGet:
  case Op::MCodeAck:
    if (i == 1 && rng_.chance(85)) return kMCodes[rng_.below(std::size(kMCodes))];
    break;
  case Op::TCodeGet:
    // A constant destination is a compare against the pending T code (functions-1 3.1 TGET).
    if (i == 1) return kTCodes[rng_.below(std::size(kTCodes))];
    break;
  case Op::PointToNumber:
  case Op::NumberToPoint:
    // Point numbers the hot registers actually hold, so a point matches now and then.
    if (rng_.chance(80)) return static_cast<int32_t>(rng_.range(-1, 5));
    break;
  case Op::ChannelModeSet:
    // A constant mode is one of the one-hot codes 1..64 (cnc-interface 6.1 MDST).
    if (i == 1) return 1 << rng_.below(7);
    break;
  case Op::ToolLife:
    if (i == 1 && rng_.chance(85)) return static_cast<int32_t>(rng_.range(1, 4));
    break;
  case Op::MagazineRotate:
    if (i == 0 && rng_.chance(85)) return static_cast<int32_t>(rng_.range(1, 16));
    break;
  case Op::Alarm: {
    // PLC alarms and prompts: the table's two value ranges; the gap between is rejected.
    const std::span<const ValueRange> v = in.operands[i].values;
    assert(v.size() == 2);
    const int32_t edges[] = {v[0].lo, 16, 17, v[0].hi, v[1].lo, v[1].lo + 1, v[1].hi};
    if (rng_.chance(50)) return static_cast<int32_t>(rng_.range(1, 20));
    if (rng_.chance(50)) return edges[rng_.below(std::size(edges))];
    return static_cast<int32_t>(rng_.chance(50) ? rng_.range(v[0].lo, v[0].hi)
                                                : rng_.range(v[1].lo, v[1].hi));
  }
  case Op::VarGet:
  case Op::VarSet:
  case Op::UserInput:
  case Op::SkipG31:
    if (hi - lo > 1024 && rng_.chance(70))
      return static_cast<int32_t>(rng_.range(std::max<int64_t>(lo, -1), 10));
    break;
  default:
    break;
  }
  if (hi - lo <= 1024) {
    // Small ranges (time units, block numbers): mostly the low end, so blocks share state and
    // timers run in milliseconds, but every value of the range shows up.
    if (rng_.chance(60)) return static_cast<int32_t>(rng_.range(lo, std::min(hi, lo + 3)));
    return static_cast<int32_t>(rng_.range(lo, hi));
  }
  bool timing = in.state == StateKind::Timer || in.state == StateKind::Counter;
  // Presets near the counters' boundaries (start value 0/1, reload, ring wrap) and near-zero
  // timer lengths come up within a few ticks only when they are tiny, so a good share is 0..3.
  if (timing && rng_.chance(35)) return static_cast<int32_t>(rng_.range(-1, 3));
  if (timing && rng_.chance(60)) return static_cast<int32_t>(rng_.range(-2, 30));
  // The two division faults (DIALECT.md 1, dialect-notes DIV): x / 0 and INT32_MIN / -1.
  if (in.op == Op::Divide && i == 1 && rng_.chance(30)) return rng_.chance(50) ? 0 : -1;
  if (in.op == Op::Divide && i == 0 && rng_.chance(20)) return INT32_MIN;
  int32_t v = interestingConst(rng_);
  if (v < lo || v > hi) v = static_cast<int32_t>(rng_.range(lo, hi));
  return v;
}

std::string RandomGen::regAddress(AreaMask mask, bool writes) {
  Area a = pickArea(mask);
  int32_t idx = pickIndex(rng_, a);
  if (writes && a == Area::DWord && idx >= kGuardFirst) idx %= poolSize(Area::DWord);
  return std::string(hnc8::profile().area(a).name) + std::to_string(idx);
}

std::string RandomGen::bitAddress(AreaMask mask, bool writes) {
  static constexpr Area kBits[] = {Area::Input, Area::Output, Area::NcStatus, Area::NcControl,
                                   Area::Relay, Area::Word,   Area::DWord,    Area::Retained,
                                   Area::Param, Area::Timer,  Area::Counter};
  static constexpr int kWeight[] = {6, 3, 3, 3, 6, 2, 2, 1, 1, 2, 2};
  std::array<int, 11> w{};
  for (int i = 0; i < 11; ++i) w[i] = hasArea(mask, kBits[i]) ? kWeight[i] : 0;
  Area a = kBits[rng_.weighted(w)];
  std::string s(hnc8::profile().area(a).name);
  if (a == Area::Timer || a == Area::Counter) return s + std::to_string(tcNumber(rng_)) + ".0";
  int32_t idx = pickIndex(rng_, a);
  if (writes && a == Area::DWord && idx >= kGuardFirst) idx %= poolSize(Area::DWord);
  int bitNo = static_cast<int>(rng_.below(static_cast<uint64_t>(hnc8::profile().bitWidth(a))));
  return s + std::to_string(idx) + "." + std::to_string(bitNo);
}

std::string RandomGen::operand(const InstrInfo &in, int i) {
  const OperandSpec &sp = in.operands[i];
  bool tcNo =
      (in.state == StateKind::Timer || in.state == StateKind::Counter) && i == 0 && sp.areas == 0;
  if (tcNo) return std::to_string(tcFor(in));
  if (sp.isBit) return bitAddress(sp.areas, sp.writes);
  // Register operands that start several consecutive elements must fit in their area.
  if (int32_t n = spanOf(in.op, i); n > 1 && !sp.constOk) return range(sp.areas, sp.writes, n);
  if (sp.constOk && (sp.areas == 0 || rng_.chance(40))) return std::to_string(constFor(in, i));
  if (sp.constOk && sp.cmax - sp.cmin <= 1024) return checkedRegister(in, i);
  return regAddress(sp.areas, sp.writes);
}

/// A register operand whose value the block range-checks at run time (the runtime axis of the
/// CNC blocks, MPGSET: 0..31, DIALECT.md 4). Often loaded first with a value at the edges of
/// the range, so an off-by-one bound check in an engine is caught; else whatever it holds.
std::string RandomGen::checkedRegister(const InstrInfo &in, int i) {
  const OperandSpec &sp = in.operands[i];
  const AreaMask writable = sp.areas & kDstAreas;
  if (!writable || in.inputs > 1 || depth_ + 2 > prof_.depthCap || !rng_.chance(60))
    return regAddress(sp.areas, sp.writes);
  std::string addr = regAddress(writable, true);
  static constexpr int32_t kBad[] = {-1, 255, 1000, INT32_MIN, 80};
  static constexpr int kKinds[] = {40, 15, 15, 10, 20};
  int64_t k = 0;
  switch (rng_.weighted(kKinds)) {
  case 0:
    k = sp.cmin + static_cast<int64_t>(rng_.below(4));
    break;
  case 1:
    k = sp.cmax;
    break;
  case 2:
    k = sp.cmax + 1;
    break;
  case 3:
    k = rng_.range(sp.cmin, sp.cmax);
    break;
  default:
    k = kBad[rng_.below(std::size(kBad))];
    break;
  }
  emit("LDT");
  emit("MOV " + std::to_string(k) + " " + addr);
  ++depth_; // LDT pushes 1, MOV passes it through: the block runs with EN = 1
  return addr;
}

// ---- Catalogue constraints the OperandSpecs cannot express (hnc8-functions-2.md 0.5/0.6) ----

Area RandomGen::pickArea(AreaMask mask) {
  static constexpr Area kRegs[] = {Area::Input,     Area::Output,   Area::NcStatus,
                                   Area::NcControl, Area::Relay,    Area::Word,
                                   Area::DWord,     Area::Retained, Area::Param};
  Area cand[9];
  int n = 0;
  for (Area a : kRegs)
    if (hasArea(mask, a)) cand[n++] = a;
  assert(n > 0);
  return cand[rng_.below(static_cast<uint64_t>(n))];
}

/// A random area of `mask` in which `n` consecutive elements fit (B has only 50 elements and a
/// written D range must stay below the guards).
Area RandomGen::pickFitting(AreaMask mask, bool writes, int32_t n) {
  static constexpr Area kRegs[] = {Area::Input,     Area::Output,   Area::NcStatus,
                                   Area::NcControl, Area::Relay,    Area::Word,
                                   Area::DWord,     Area::Retained, Area::Param};
  Area cand[9];
  int c = 0;
  for (Area a : kRegs)
    if (hasArea(mask, a) && rangeLimit(a, writes) >= n) cand[c++] = a;
  assert(c > 0);
  return cand[rng_.below(static_cast<uint64_t>(c))];
}

/// A long element count, 33..100 but at most `limit`, mostly just past the unroll limit.
int32_t RandomGen::longCount(int32_t limit) {
  const int32_t hi = std::min<int32_t>(100, limit);
  assert(hi >= 33);
  return static_cast<int32_t>(rng_.chance(40) ? rng_.range(33, std::min(hi, 36))
                                              : rng_.range(33, hi));
}

/// The start register of `n` consecutive elements of an area in `mask` that fit in the area
/// (a range past the end is a compile error): a hot element, or a range ending at the last one.
std::string RandomGen::range(AreaMask mask, bool writes, int32_t n) {
  Area a = pickFitting(mask, writes, n);
  int32_t limit = rangeLimit(a, writes);
  int32_t idx = pickIndex(rng_, a);
  if (idx + n > limit) idx = limit - n;
  return std::string(hnc8::profile().area(a).name) + std::to_string(idx);
}

/// Operands of a long BMOV (functions-2 2.3, memmove semantics): mostly source and destination
/// in one area overlapping by all but 1..n-1 elements, the destination above the source (the
/// lowering must copy backward) or below it (forward); otherwise two independent ranges.
std::string RandomGen::longBmov(const InstrInfo &in) {
  const AreaMask srcMask = in.operands[0].areas, dstMask = in.operands[1].areas;
  if (rng_.chance(80)) {
    Area a = pickFitting(srcMask & dstMask, true, 34);
    const int32_t limit = rangeLimit(a, true);
    const int32_t n = longCount(limit - 1);
    int32_t shift = static_cast<int32_t>(rng_.range(1, std::min(n - 1, limit - n)));
    if (rng_.chance(50)) shift = std::min<int32_t>(shift, static_cast<int32_t>(rng_.range(1, 3)));
    // Over the hot elements (which hold the program's varied values) nearly always: a copy in
    // the wrong direction only shows when the elements differ.
    const int32_t room = limit - n - shift;
    const int32_t lo = rng_.chance(70)   ? 0
                       : rng_.chance(70) ? std::min<int32_t>(pickIndex(rng_, a) % poolSize(a), room)
                                         : static_cast<int32_t>(rng_.range(0, room));
    const bool up = rng_.chance(50);
    const std::string l(hnc8::profile().area(a).name);
    return l + std::to_string(up ? lo : lo + shift) + " " + l +
           std::to_string(up ? lo + shift : lo) + " " + std::to_string(n);
  }
  const int32_t n = longCount(100);
  return range(srcMask, false, n) + " " + range(dstMask, true, n) + " " + std::to_string(n);
}

/// Long FMOV / ZRST bounds: 33..100 whole registers, or (ZRST `bits`) a bit range whose whole
/// elements between a partial first and a partial last element number 33..100.
std::string RandomGen::longZone(bool bits) {
  Area a = pickFitting(kDstAreas, true, bits ? 35 : 33);
  const int32_t limit = rangeLimit(a, true);
  const std::string l(hnc8::profile().area(a).name);
  if (!bits) {
    const int32_t n = longCount(limit);
    const int32_t idx = rng_.chance(60) ? 0 : static_cast<int32_t>(rng_.range(0, limit - n));
    return l + std::to_string(idx) + " " + l + std::to_string(idx + n - 1);
  }
  const int32_t n = longCount(limit - 2), w = hnc8::profile().bitWidth(a);
  const int32_t first = rng_.chance(60) ? 0 : static_cast<int32_t>(rng_.range(0, limit - n - 2));
  const int32_t last = first + n + 1;
  const auto b0 = rng_.below(static_cast<uint64_t>(w)), b1 = rng_.below(static_cast<uint64_t>(w));
  return l + std::to_string(first) + "." + std::to_string(b0) + " " + l + std::to_string(last) +
         "." + std::to_string(b1);
}

/// ZRST bounds: same area and same form, start <= end; word form (the manual's example) or bit
/// form, where bits are ordered as index * width + bit (functions-2 2.6).
std::string RandomGen::zone() {
  if (longRange()) return longZone(rng_.chance(50));
  Area a = pickArea(kDstAreas);
  int32_t limit = rangeLimit(a, true);
  std::string l(hnc8::profile().area(a).name);
  if (rng_.chance(50)) {
    int32_t n = static_cast<int32_t>(rng_.range(1, 4));
    int32_t idx = pickIndex(rng_, a);
    if (idx + n > limit) idx = limit - n;
    return l + std::to_string(idx) + " " + l + std::to_string(idx + n - 1);
  }
  const int32_t w = hnc8::profile().bitWidth(a);
  int32_t first =
      pickIndex(rng_, a) * w + static_cast<int32_t>(rng_.below(static_cast<uint64_t>(w)));
  int32_t last =
      std::min<int32_t>(first + static_cast<int32_t>(rng_.range(0, 2 * w)), limit * w - 1);
  first = std::min(first, last);
  auto bit = [&](int32_t b) { return l + std::to_string(b / w) + "." + std::to_string(b % w); };
  return bit(first) + " " + bit(last);
}

/// One (format, address) pair of XMOV / XCH (functions-2 0.6). For a B or P format the address
/// register is often loaded first with a valid index, sometimes with an out-of-range one (the
/// runtime fault path, DIALECT.md 4); otherwise it holds whatever the program left there.
std::string RandomGen::indirect(const InstrInfo &in, int i) {
  const int32_t fmt = static_cast<int32_t>(rng_.below(3));
  // Always a writable register (no guard D), so the index load below may write it.
  std::string addr = regAddress(in.operands[i + 1].areas, true);
  if (fmt != 0 && rng_.chance(75) && depth_ + 2 <= prof_.depthCap) {
    const int32_t count = fmt == 1 ? LJ_B_COUNT : LJ_P_COUNT;
    static constexpr int32_t kBad[] = {-1, LJ_B_COUNT, LJ_P_COUNT, 255, 1000, INT32_MIN};
    // The bound check matters most: the last element and the first one past it come up as
    // often as the hot elements' neighbours, so an off-by-one bound is caught.
    static constexpr int kKinds[] = {45, 15, 15, 10, 15};
    int32_t k = 0;
    switch (rng_.weighted(kKinds)) {
    case 0:
      k = static_cast<int32_t>(rng_.below(4));
      break;
    case 1:
      k = count - 1;
      break;
    case 2:
      k = count;
      break;
    case 3:
      k = static_cast<int32_t>(rng_.below(static_cast<uint64_t>(count)));
      break;
    default:
      k = kBad[rng_.below(std::size(kBad))];
      break;
    }
    emit("LDT");
    emit("MOV " + std::to_string(k) + " " + addr);
    ++depth_; // LDT pushes 1, MOV passes it through: the block below runs with EN = 1
  }
  return std::to_string(fmt) + " " + addr;
}

bool RandomGen::specialOperands(const InstrInfo &in, std::string &s) {
  auto small = [&](int32_t hi) {
    return static_cast<int32_t>(rng_.chance(85) ? rng_.range(1, std::min(hi, 6))
                                                : rng_.range(1, hi));
  };
  switch (in.op) {
  case Op::IndexedMove:
  case Op::Exchange: {
    std::string a = indirect(in, 0);
    std::string b = indirect(in, 2);
    s += " " + a + " " + b;
    return true;
  }
  case Op::BlockMove: {
    if (longRange()) {
      s += " " + longBmov(in);
      return true;
    }
    int32_t n = small(20);
    s += " " + range(in.operands[0].areas, false, n) + " " + range(in.operands[1].areas, true, n) +
         " " + std::to_string(n);
    return true;
  }
  case Op::Fill: {
    if (longRange()) {
      s += " " + longZone(false) + " " + operand(in, 2);
      return true;
    }
    Area a = pickArea(in.operands[0].areas);
    int32_t limit = rangeLimit(a, true);
    int32_t n = small(8);
    int32_t idx = pickIndex(rng_, a);
    if (idx + n > limit) idx = limit - n;
    std::string l(hnc8::profile().area(a).name);
    s += " " + l + std::to_string(idx) + " " + l + std::to_string(idx + n - 1) + " " +
         operand(in, 2);
    return true;
  }
  case Op::ZoneReset:
    s += " " + zone();
    return true;
  case Op::TableEncode:
  case Op::TableDecode:
  case Op::TableLookup:
  case Op::TableSearch: {
    // A table of n entries that fits in its area; ENCO/DECO map entries to the bits of a word.
    // COD / SER tables are sometimes long (the SER loop); a long COD then mostly gets a
    // constant index around the table's end (the last entries and the fault just past them).
    const bool wide = in.op == Op::TableLookup || in.op == Op::TableSearch;
    const bool long_ = wide && longRange();
    int32_t n = long_ ? longCount(100) : small(wide ? 40 : 32);
    std::string x = long_ && in.op == Op::TableLookup && rng_.chance(60)
                        ? std::to_string(rng_.range(std::max(0, n - 3), n))
                        : operand(in, 2);
    s += " " + range(in.operands[0].areas, false, n) + " " + std::to_string(n) + " " + x + " " +
         operand(in, 3);
    return true;
  }
  case Op::Pack: {
    int32_t n = small(8);
    s += " " + range(in.operands[0].areas, false, n) + " " + std::to_string(n) + " " +
         operand(in, 2);
    return true;
  }
  case Op::Unpack: {
    int32_t n = small(8);
    s +=
        " " + operand(in, 0) + " " + std::to_string(n) + " " + range(in.operands[2].areas, true, n);
    return true;
  }
  case Op::HeadSensors: {
    // count temperatures stored from a D register on; enable 0 = acquire (functions-2 2.21).
    int32_t n = small(20);
    int32_t start = static_cast<int32_t>(rng_.below(static_cast<uint64_t>(kGuardFirst - n + 1)));
    if (rng_.chance(70)) start = std::min<int32_t>(start % 8, kGuardFirst - n);
    s += " " + std::to_string(n) + " " +
         std::to_string(rng_.chance(70) ? 0 : interestingConst(rng_)) + " D" +
         std::to_string(start);
    return true;
  }
  default:
    return false;
  }
}

} // namespace lj::gen::detail

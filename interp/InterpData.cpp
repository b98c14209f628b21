// Interpreter semantics of family Data: data operations (hnc8-functions-2.md 2.2-2.13, 2.17-2.18,
// resolutions in its section 6; decisions in docs/dialect-notes.md "Data operations").
//
// Written as the oracle: element by element, every read before any write where the reference
// says so, no shortcuts. The verifier (VerifyData.cpp) has checked every constant range, so only
// the indices computed at run time (XMOV/XCH formats 1 and 2, the COD index) are checked here.
#include "interp/InterpreterInternal.h"

#include <vector>

namespace lj::interp {

namespace {

/// Element `index` of area `a` as an operand reference (read rule and width of the area).
Ref element(const TargetProfile &tp, Area a, int32_t index) {
  Operand o;
  o.kind = Operand::Kind::Reg;
  o.area = a;
  o.index = index;
  return decode(tp, o);
}

int32_t readAt(const BlockCall &b, Area a, int32_t index) {
  return readValue(b.s, element(b.tp, a, index));
}
void writeAt(const BlockCall &b, Area a, int32_t index, int32_t v) {
  writeValue(b.s, element(b.tp, a, index), v);
}

/// The raw bit pattern of an element, zero-extended (ASSEM/DISAS, functions-2 0.2).
uint32_t rawAt(const BlockCall &b, Area a, int32_t index) {
  uint32_t v = static_cast<uint32_t>(readAt(b, a, index));
  int w = b.tp.bitWidth(a);
  return w == 32 ? v : v & ((1u << w) - 1u);
}

/// Effective operand of XMOV/XCH (functions-2 0.6): format 0 is the register itself, 1 is
/// B[value of the register], 2 is P[value of the register]. False when the index is out of range.
bool resolve(const BlockCall &b, const Operand &format, const Operand &addr, Ref &out) {
  if (format.value == 0) {
    out = element(b.tp, addr.area, addr.index);
    return true;
  }
  Area target = format.value == 1 ? Area::Retained : Area::Param;
  int32_t k = readAt(b, addr.area, addr.index);
  if (!b.tp.validIndex(target, k)) return false;
  out = element(b.tp, target, k);
  return true;
}

/// A runtime index out of range (DIALECT.md 4): nothing written, fault_index counts it, and the
/// block's output is 0 -- for a block without an output, ST0 := 0 when ST is not empty.
void indexFault(const BlockCall &b) {
  ++b.s->fault_index;
  if (b.f.sp > 0) b.f.setTop(false);
}

void xmov(const BlockCall &b) {
  const auto &o = b.stmt.ops;
  bool en = b.f.input(), ok = true;
  if (en) {
    Ref src, dst;
    ok = resolve(b, o[0], o[1], src) && resolve(b, o[2], o[3], dst);
    if (ok)
      writeValue(b.s, dst, readValue(b.s, src));
    else
      ++b.s->fault_index;
  }
  b.f.output(en && ok);
}

void xch(const BlockCall &b) {
  if (!b.f.input()) return;
  const auto &o = b.stmt.ops;
  // Both operands are resolved before anything is written (an index register may be the other
  // operand); then both are read, then operand 1 and operand 2 are written in that order.
  Ref r1, r2;
  if (!resolve(b, o[0], o[1], r1) || !resolve(b, o[2], o[3], r2)) {
    indexFault(b);
    return;
  }
  int32_t v1 = readValue(b.s, r1), v2 = readValue(b.s, r2);
  writeValue(b.s, r1, v2);
  writeValue(b.s, r2, v1);
}

void bmov(const BlockCall &b) {
  const auto &o = b.stmt.ops;
  bool en = b.f.input();
  if (en) {
    // memmove semantics (functions-2 2.3): read all n values first, then write them.
    std::vector<int32_t> v(static_cast<size_t>(o[2].value));
    for (int32_t i = 0; i < o[2].value; ++i) v[i] = readAt(b, o[0].area, o[0].index + i);
    for (int32_t i = 0; i < o[2].value; ++i) writeAt(b, o[1].area, o[1].index + i, v[i]);
  }
  b.f.output(en);
}

void fmov(const BlockCall &b) {
  if (!b.f.input()) return;
  const auto &o = b.stmt.ops;
  int32_t v = readValue(b.s, b.ops[2]); // read once, before any write (functions-2 2.4)
  for (int32_t k = o[0].index; k <= o[1].index; ++k) writeAt(b, o[0].area, k, v);
}

void zrst(const BlockCall &b) {
  const auto &o = b.stmt.ops;
  bool en = b.f.input();
  if (en && o[0].kind == Operand::Kind::Reg) {
    for (int32_t k = o[0].index; k <= o[1].index; ++k) writeAt(b, o[0].area, k, 0);
  } else if (en) {
    // Bit form: bits ordered linearly as index * width + bit (functions-2 2.6).
    const int w = b.tp.bitWidth(o[0].area);
    for (int32_t p = o[0].index * w + o[0].bit; p <= o[1].index * w + o[1].bit; ++p) {
      Operand bitOp;
      bitOp.kind = Operand::Kind::Bit;
      bitOp.area = o[0].area;
      bitOp.index = p / w;
      bitOp.bit = static_cast<int8_t>(p % w);
      writeBit(b.s, decode(b.tp, bitOp), false);
    }
  }
  b.f.output(en);
}

/// ENCO / DECO / COD / SER: table T[i] = area[start + i], i = 0..n-1.
void table(const BlockCall &b) {
  if (!b.f.input()) {
    if (b.c.op == Op::TableSearch) b.f.output(false); // compare-like: output EN and found
    return;
  }
  const auto &o = b.stmt.ops;
  const Area area = o[0].area;
  const int32_t start = o[0].index, n = o[1].value;
  const int32_t x = readValue(b.s, b.ops[2]);
  auto t = [&](int32_t i) { return readAt(b, area, start + i); };
  switch (b.c.op) {
  case Op::TableEncode: { // first entry equal to x -> its one-hot bit; not found -> 0 (2.7)
    uint32_t r = 0;
    for (int32_t i = 0; i < n; ++i) {
      if (t(i) == x) {
        r = 1u << i; // n <= 32 (table row)
        break;
      }
    }
    writeValue(b.s, b.ops[3], static_cast<int32_t>(r));
    return;
  }
  case Op::TableDecode: { // lowest set bit i < n of x -> T[i]; none -> 0 (2.8)
    int32_t r = 0;
    for (int32_t i = 0; i < n; ++i) {
      if ((static_cast<uint32_t>(x) >> i) & 1u) {
        r = t(i);
        break;
      }
    }
    writeValue(b.s, b.ops[3], r);
    return;
  }
  case Op::TableLookup: // T[x] for 0 <= x < n; else an index fault (2.9, DIALECT.md 4)
    if (x >= 0 && x < n)
      writeValue(b.s, b.ops[3], t(x));
    else
      indexFault(b);
    return;
  default: { // SER: first i with T[i] == x -> dst := i, output 1; else dst kept, output 0
    for (int32_t i = 0; i < n; ++i) {
      if (t(i) == x) {
        writeValue(b.s, b.ops[3], i);
        b.f.output(true);
        return;
      }
    }
    b.f.output(false);
    return;
  }
  }
}

void assem(const BlockCall &b) {
  if (!b.f.input()) return;
  const auto &o = b.stmt.ops;
  const int w = b.tp.bitWidth(o[0].area);
  // First source in the least-significant bits; pieces at or beyond bit 32 are lost (2.11).
  uint32_t acc = 0;
  for (int32_t i = 0; i < o[1].value; ++i)
    if (i * w < 32) acc |= rawAt(b, o[0].area, o[0].index + i) << (i * w);
  writeValue(b.s, b.ops[2], static_cast<int32_t>(acc));
}

void disas(const BlockCall &b) {
  if (!b.f.input()) return;
  const auto &o = b.stmt.ops;
  const int w = b.tp.bitWidth(o[2].area);
  const uint32_t mask = (1u << w) - 1u;                 // destinations are 8 or 16 bits wide
  const uint32_t raw = rawAt(b, o[0].area, o[0].index); // read once, before any write
  for (int32_t i = 0; i < o[1].value; ++i) {
    uint32_t piece = i * w < 32 ? (raw >> (i * w)) & mask : 0; // logical, never shift >= 32
    writeAt(b, o[2].area, o[2].index + i, static_cast<int32_t>(piece));
  }
}

void acvt(const BlockCall &b) {
  if (!b.f.input()) return;
  const auto &o = b.stmt.ops;
  const int32_t k = o[0].index;
  // dst := (src - P[k]) * (P[k+3] - P[k+2]) / (P[k+1] - P[k]) + P[k+2] (the "+P2" fix, 2.13).
  // int64 intermediates: the differences are exact; the product wraps modulo 2^64 (only when
  // both ranges are wider than 2^31); the quotient truncates toward zero; the sum wraps.
  int64_t smin = readAt(b, Area::Param, k), smax = readAt(b, Area::Param, k + 1);
  int64_t dmin = readAt(b, Area::Param, k + 2), dmax = readAt(b, Area::Param, k + 3);
  int64_t x = readValue(b.s, b.ops[1]);
  int64_t den = smax - smin;
  if (den == 0) { // division by zero (DIALECT.md 4): nothing written, output 0, counted
    ++b.s->fault_divzero;
    if (b.f.sp > 0) b.f.setTop(false);
    return;
  }
  int64_t num =
      static_cast<int64_t>(static_cast<uint64_t>(x - smin) * static_cast<uint64_t>(dmax - dmin));
  int64_t q = (num == INT64_MIN && den == -1) ? INT64_MIN : num / den;
  uint64_t r = static_cast<uint64_t>(q) + static_cast<uint64_t>(dmin);
  writeValue(b.s, b.ops[2], static_cast<int32_t>(static_cast<uint32_t>(r)));
}

void ptn(const BlockCall &b) {
  if (!b.f.input()) return;
  // Pairs (point, number) at operands 1/2, 3/4, 5/6, 7/8; the first active point wins (2.17).
  for (int p = 1; p < kMaxOperands; p += 2) {
    if (readBit(b.s, b.ops[p])) {
      writeValue(b.s, b.ops[0], b.ops[p + 1].value);
      return;
    }
  }
}

void ntp(const BlockCall &b) {
  if (!b.f.input()) return;
  // Pairs (number, point) at operands 1/2 ... 7/8: point := (source == number), in pair order,
  // with the source read once before any point is written (2.18).
  const int32_t x = readValue(b.s, b.ops[0]);
  for (int p = 1; p < kMaxOperands; p += 2) writeBit(b.s, b.ops[p + 1], x == b.ops[p].value);
}

} // namespace

bool runData(const BlockCall &b) {
  switch (b.c.op) {
  case Op::IndexedMove:
    xmov(b);
    return true;
  case Op::Exchange:
    xch(b);
    return true;
  case Op::BlockMove:
    bmov(b);
    return true;
  case Op::Fill:
    fmov(b);
    return true;
  case Op::ZoneReset:
    zrst(b);
    return true;
  case Op::TableEncode:
  case Op::TableDecode:
  case Op::TableLookup:
  case Op::TableSearch:
    table(b);
    return true;
  case Op::Pack:
    assem(b);
    return true;
  case Op::Unpack:
    disas(b);
    return true;
  case Op::RangeConvert:
    acvt(b);
    return true;
  case Op::PointToNumber:
    ptn(b);
    return true;
  case Op::NumberToPoint:
    ntp(b);
    return true;
  default:
    return runFanucData(b); // fanuc-b's operations (InterpFanucData.cpp), else false
  }
}

} // namespace lj::interp

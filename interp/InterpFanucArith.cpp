// Interpreter semantics of the FANUC arithmetic (fanuc-c rows of ir/OpTable.h: BinaryArith,
// BcdArith, BcdConstant; FANUC PMC manual ref 6.10 [EXT], 6.2, 3.1, 3.2; the
// readings are rows of docs/fanuc-pmc.md). Twin of lowering/EmitFanucArith.cpp; the operation
// codes, flag bits and ranges are ir/PmcArith.h's.
//
// Control inputs are ST entries: ACT = ST0, RST = ST1, BYT = ST2 (reference 5). W1 is held in the
// instance's edge slot: ACT = 1 sets it to this execution's error, ACT = 0 keeps it, RST = 1
// clears it (after the execution, which still runs), as for fanuc-b's RST family. On an error
// the BCD instructions and a division by zero write nothing; a binary overflow writes the
// result wrapped to its bytes.
#include "interp/InterpFanucCommon.h"
#include "interp/InterpreterInternal.h"
#include "ir/PmcArith.h"

namespace lj::interp {

namespace {

using fanuc::at;
using fanuc::fromBcd;
using fanuc::Inputs;
using fanuc::take;
using fanuc::w1;

/// `v` wrapped to `width` bytes and sign-extended (reference 3.1).
int64_t wrapTo(int64_t v, int width) {
  const int shift = 64 - 8 * width;
  return static_cast<int64_t>(static_cast<uint64_t>(v) << shift) >> shift;
}

void binaryArith(const BlockCall &b) {
  const Inputs in = take(b, 2); // ACT, RST
  bool err = false;
  if (in.v[0]) {
    const auto &o = b.stmt.ops;
    const int width = o[1].width;
    const int64_t x = readValue(b.s, b.ops[1]), y = readValue(b.s, b.ops[2]);
    const int32_t op = o[0].value;
    if (op == pmc::kArithDiv && y == 0) {
      err = true; // division by zero: nothing written, R9000 kept
    } else {
      int64_t r = 0, rem = 0;
      switch (op) {
      case pmc::kArithAdd:
        r = x + y;
        break;
      case pmc::kArithSub:
        r = x - y;
        break;
      case pmc::kArithMul:
        r = x * y; // |x|, |y| <= 2^31: fits
        break;
      default:
        r = x / y; // truncated; the remainder takes the dividend's sign
        rem = x % y;
        break;
      }
      const bool overflow = r < pmc::minOf(width) || r > pmc::maxOf(width);
      const int64_t stored = wrapTo(r, width);
      writeValue(b.s, b.ops[3], static_cast<int32_t>(stored));
      if (op == pmc::kArithDiv) writeValue(b.s, b.ops[5], static_cast<int32_t>(rem));
      // R9000: Z (#0), N (#1) of the stored result, V (#5) overflow; other bits kept.
      unsigned char &flags = at(b, b.ops[4].off)[0];
      flags = static_cast<unsigned char>(
          (flags & ~(pmc::kArithFlagZ | pmc::kArithFlagN | pmc::kArithFlagV)) |
          (stored == 0 ? pmc::kArithFlagZ : 0) | (stored < 0 ? pmc::kArithFlagN : 0) |
          (overflow ? pmc::kArithFlagV : 0));
      err = overflow;
    }
  }
  w1(b, in.v[0], in.v[1], err);
}

/// The value of `n` (1, 2) bytes of BCD at `off`, little-endian; false on a digit above 9.
bool bcdAt(const BlockCall &b, uint32_t off, int n, int64_t &v) {
  uint32_t raw = 0;
  for (int k = 0; k < n; ++k) raw |= static_cast<uint32_t>(at(b, off)[k]) << (8 * k);
  return fromBcd(raw, 2 * n, v);
}

void bcdArith(const BlockCall &b) {
  const Inputs in = take(b, 3); // ACT, RST, BYT
  bool err = false;
  if (in.v[0]) {
    const auto &o = b.stmt.ops;
    const int n = in.v[2] ? 2 : 1; // bytes; 2 n digits
    const int64_t limit = pmc::bcdLimit(2 * n);
    int64_t x = 0, y = 0;
    err = !bcdAt(b, b.ops[1].off, n, x);
    if (o[2].kind == Operand::Kind::Const) {
      y = o[2].value; // a decimal constant: too many digits for BYT is an invalid operand
      err = err || y >= limit;
    } else {
      err = err || !bcdAt(b, b.ops[2].off, n, y);
    }
    int64_t r = 0;
    if (!err) {
      switch (o[0].value) {
      case pmc::kArithAdd:
        r = x + y;
        break;
      case pmc::kArithSub:
        r = x - y; // negative: an error (BCD has no sign, reference 3.2)
        break;
      case pmc::kArithMul:
        r = x * y;
        break;
      default:
        if (y == 0)
          err = true;
        else
          r = x / y; // the remainder is dropped
        break;
      }
      err = err || r < 0 || r >= limit;
    }
    if (!err) {
      const uint64_t digits = bcd::encode(static_cast<uint64_t>(r), 2 * n);
      for (int k = 0; k < n; ++k)
        at(b, b.ops[3].off)[k] = static_cast<unsigned char>(digits >> (8 * k));
    }
  }
  w1(b, in.v[0], in.v[1], err);
}

void bcdConstant(const BlockCall &b) {
  const Inputs in = take(b, 2); // ACT, BYT
  if (in.v[0]) {
    const auto pattern = static_cast<uint32_t>(b.stmt.ops[0].value);
    at(b, b.ops[1].off)[0] = static_cast<unsigned char>(pattern);
    if (in.v[1]) at(b, b.ops[1].off)[1] = static_cast<unsigned char>(pattern >> 8);
  }
  b.f.setTop(in.v[0]); // no W1: ACT stays in ST0
}

} // namespace

bool runFanucArith(const BlockCall &b) {
  switch (b.c.op) {
  case Op::BinaryArith:
    binaryArith(b);
    return true;
  case Op::BcdArith:
    bcdArith(b);
    return true;
  case Op::BcdConstant:
    bcdConstant(b);
    return true;
  default:
    return false;
  }
}

} // namespace lj::interp

// The one BCD codec (FANUC PMC reference 3.2: a decimal digit per nibble, the lowest digit in
// the lowest nibble): the front end's constants, the interpreter, the generator and the hosts'
// nixie encoding use it; lowering/EmitBcd.h emits the same arithmetic as LLVM IR.
#pragma once

#include <cstdint>

namespace lj::bcd {

/// Bits a digit takes.
inline constexpr int kDigitBits = 4;

/// 10^digits: the first value that does not fit `digits` BCD digits.
constexpr int64_t limit(int digits) {
  int64_t v = 1;
  for (int k = 0; k < digits; ++k) v *= 10;
  return v;
}

/// The low `digits` decimal digits of `v` (digits above them dropped) as BCD.
constexpr uint64_t encode(uint64_t v, int digits) {
  uint64_t r = 0;
  for (int k = 0; k < digits; ++k, v /= 10) r |= (v % 10) << (kDigitBits * k);
  return r;
}

/// The value of the low `digits` nibbles of `raw`; false when one of them is above 9.
constexpr bool decode(uint64_t raw, int digits, int64_t &out) {
  out = 0;
  for (int k = digits - 1; k >= 0; --k) {
    const auto d = static_cast<int64_t>((raw >> (kDigitBits * k)) & 0xFu);
    if (d > 9) return false;
    out = out * 10 + d;
  }
  return true;
}

/// The value of the low `digits` nibbles of `raw`, a nibble above 9 taken at its binary value
/// (what a counter of BCD type reads, docs/fanuc-pmc.md [EXT] row).
constexpr int64_t decodeLoose(uint64_t raw, int digits) {
  int64_t v = 0;
  for (int k = digits - 1; k >= 0; --k)
    v = v * 10 + static_cast<int64_t>((raw >> (kDigitBits * k)) & 0xFu);
  return v;
}

static_assert(encode(1234, 4) == 0x1234 && encode(12345, 4) == 0x2345);
static_assert(limit(4) == 10000 && decodeLoose(0x1A, 2) == 20);

} // namespace lj::bcd

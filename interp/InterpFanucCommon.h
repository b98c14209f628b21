// Helpers shared by the interpreter's FANUC functional-instruction files (InterpFanucData.cpp,
// InterpFanucArith.cpp): control inputs taken from ST, the held W1 of the RST family, and byte
// access to the state's `mem` region.
//
// Control inputs are ST entries: ACT = ST0, the next input ST1, ... (reference 5). An instruction
// with k inputs pops k - 1 of them and leaves W1 in ST0. The RST family keeps W1 in its edge
// slot: ACT = 1 sets it to this execution's error, ACT = 0 keeps it, RST = 1 clears it (after the
// execution).
#pragma once

#include "interp/InterpreterInternal.h"
#include "ir/Bcd.h"

namespace lj::interp::fanuc {

/// The top `k` (at most 6: ROT) ST entries, ST0 first.
struct Inputs {
  bool v[6] = {};
};
/// Takes the top `k` ST entries and pops all but one (which W1 then replaces).
inline Inputs take(const BlockCall &b, int k) {
  Inputs in;
  for (int j = 0; j < k; ++j) in.v[j] = b.f.st[b.f.sp - 1 - j] != 0;
  b.f.sp -= k - 1;
  return in;
}

/// W1 of the RST family (file comment), stored and left in ST0.
inline void w1(const BlockCall &b, bool act, bool rst, bool err) {
  uint8_t &held = b.s->edge[b.info.slot];
  if (act) held = err;
  if (rst) held = 0;
  b.f.setTop(held != 0);
}

/// The state's byte at offset `off` of its profile-laid memory.
inline unsigned char *at(const BlockCall &b, uint32_t off) { return bytes(b.s) + off; }

/// Binary value of `digits` BCD digits in `raw`; false on a digit above 9.
inline bool fromBcd(uint32_t raw, int digits, int64_t &out) {
  return bcd::decode(raw, digits, out);
}

} // namespace lj::interp::fanuc

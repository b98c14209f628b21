// Resolving one CNC table action for a statement (ir/CncTable.h).
#include "ir/CncTable.h"

namespace lj::cnc {

namespace {

int32_t constOf(const Stmt &s, int8_t op) { return op >= 0 ? s.ops[op].value : 0; }

} // namespace

Resolved resolve(const Action &a, const Stmt &s) {
  Resolved r;
  int32_t word = a.word + constOf(s, a.wordOp);
  int32_t index = a.bit, auxIndex = a.auxBit;
  if (a.bitOp >= 0) {
    int32_t v = constOf(s, a.bitOp);
    if (v < a.lo || v > a.hi) {
      r.applies = false;
      return r;
    }
    index += v - a.lo;
    auxIndex += v - a.lo;
  }
  r.word = word + index / 16;
  r.bit = index % 16;
  r.auxWord = a.aux + auxIndex / 16;
  r.auxBit = auxIndex % 16;
  r.aux2Word = a.aux2;
  if (a.spOp >= 0) {
    int32_t sp = constOf(s, a.spOp);
    r.word = a.word + 2 * sp;
    r.auxWord = a.aux + 2 * sp;
    r.aux2Word = a.aux2 + sp;
  }
  return r;
}

} // namespace lj::cnc

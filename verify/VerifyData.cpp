// Verifier checks of family Data (hnc8-functions-2.md 0.5, 2.2-2.18): constant ranges that must
// lie inside their area (BMOV, tables, ASSEM/DISAS, the ACVT P block) and the start/end pairs of
// FMOV and ZRST. Errors point at the offending operand (DIALECT.md 6).
#include "verify/VerifierInternal.h"

#include <string>

namespace lj::verifier {

namespace {

std::string addr(const Context &cx, Area a, int64_t index) {
  return std::string(cx.tp.area(a).name) + std::to_string(index);
}

std::string addr(const Context &cx, const Operand &o) {
  std::string s = addr(cx, o.area, o.index);
  if (o.kind == Operand::Kind::Bit) {
    s += '.';
    s += std::to_string(o.bit);
  }
  return s;
}

/// `count` elements from register operand `start` must exist in its area.
void checkRange(Context &cx, const Stmt &s, const Operand &start, int64_t count, const char *what) {
  const int64_t last = int64_t{start.index} + count - 1;
  if (cx.tp.validIndex(start.area, last)) return;
  cx.error(start.loc, "LJ1045",
           std::string(cx.spell(s.op)) + " " + what + " " + addr(cx, start) + ".." +
               addr(cx, start.area, last) + " runs past the end of " + cx.tp.area(start.area).name +
               " (" + addr(cx, start.area, 0) + ".." +
               addr(cx, start.area, cx.tp.area(start.area).count - 1) + ")");
}

/// FMOV / ZRST: start and end in the same form and area, start <= end (bits: index*width+bit).
void checkZone(Context &cx, const Stmt &s) {
  const Operand &a = s.ops[0], &b = s.ops[1];
  const std::string mn = cx.spell(s.op);
  if (a.kind != b.kind) {
    cx.error(b.loc, "LJ1046",
             mn + " start " + addr(cx, a) + " and end " + addr(cx, b) +
                 " must both be registers or both be bit addresses");
    return;
  }
  if (a.area != b.area) {
    cx.error(b.loc, "LJ1047",
             mn + " start " + addr(cx, a) + " and end " + addr(cx, b) + " are in different areas");
    return;
  }
  const int w = cx.tp.bitWidth(a.area);
  auto pos = [w](const Operand &o) {
    return o.kind == Operand::Kind::Bit ? int64_t{o.index} * w + o.bit : int64_t{o.index};
  };
  if (pos(b) < pos(a))
    cx.error(b.loc, "LJ1048", mn + " end " + addr(cx, b) + " comes before start " + addr(cx, a));
}

} // namespace

void checkData(Context &cx) {
  for (const Stmt &s : cx.prog.stmts) {
    if (opFamily(s.op) != Family::Data) continue;
    const auto &o = s.ops;
    switch (s.op) {
    case Op::BlockMove: // functions-2 0.5: `BMOV D98 D0 5` is an error
      checkRange(cx, s, o[0], o[2].value, "source range");
      checkRange(cx, s, o[1], o[2].value, "destination range");
      break;
    case Op::Fill:
    case Op::ZoneReset:
      checkZone(cx, s);
      break;
    case Op::TableEncode:
    case Op::TableDecode:
    case Op::TableLookup:
    case Op::TableSearch:
      checkRange(cx, s, o[0], o[1].value, "table");
      break;
    case Op::Pack:
      checkRange(cx, s, o[0], o[1].value, "source range");
      break;
    case Op::Unpack:
      checkRange(cx, s, o[2], o[1].value, "destination range");
      break;
    case Op::RangeConvert: // P[k] .. P[k+3] (functions-2 2.13)
      checkRange(cx, s, o[0], instrInfo(s.op).operands[0].span, "parameter block");
      break;
    default: // XMOV XCH PTN NTP: the table's operand checks are enough
      break;
    }
  }
}

} // namespace lj::verifier

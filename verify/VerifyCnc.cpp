// Verifier checks of family Cnc (hnc8-cnc-interface.md 2, docs/cnc-blocks.md) that an operand
// spec cannot express: ALARM's number gap, USEROUT's four bytes, SPDLBUS1's P block, constant
// MDST modes, and REFPT 5 (no status bit). Diagnostics point at the operand (DIALECT.md 6).
#include "verify/VerifierInternal.h"

#include <string>

namespace lj::verifier {

namespace {

std::string addr(const Context &cx, Area a, int64_t index) {
  return std::string(cx.tp.area(a).name) + std::to_string(index);
}

std::string range(const ValueRange &r) {
  return std::to_string(r.lo) + ".." + std::to_string(r.hi);
}
std::string lastOf(const Context &cx, Area a) { return addr(cx, a, cx.tp.area(a).count - 1); }

void checkStmt(Context &cx, const Stmt &s) {
  const std::string mn = cx.spell(s.op);
  switch (s.op) {
  case Op::Alarm: {
    // Alarms 1..256 (G3010-3025) and prompts 501..884 (G3056-3079); nothing in between.
    const Operand &n = s.ops[0];
    const std::span<const ValueRange> v = instrInfo(s.op).operands[0].values;
    if (!inValueSet(instrInfo(s.op).operands[0], n.value))
      cx.error(n.loc, "LJ1040",
               mn + " number " + std::to_string(n.value) + " is neither an alarm (" + range(v[0]) +
                   ") nor a prompt (" + range(v[1]) + ")");
    break;
  }
  case Op::UserOutput: {
    // 32 user outputs go to four consecutive bytes from the start operand.
    const Operand &o = s.ops[2];
    const int64_t last = int64_t{o.index} + instrInfo(s.op).operands[2].span - 1;
    if (!cx.tp.validIndex(o.area, last))
      cx.error(o.loc, "LJ1041",
               mn + " output bytes " + addr(cx, o.area, o.index) + ".." + addr(cx, o.area, last) +
                   " run past the end of " + cx.tp.area(o.area).name + " (" + addr(cx, o.area, 0) +
                   ".." + lastOf(cx, o.area) + ")");
    break;
  }
  case Op::BusSpindleGeared: {
    // Gear g uses P[base + 5(g-1) .. + 4]; at least gear 1's block must exist.
    const Operand &p = s.ops[3];
    const int64_t last = int64_t{p.index} + instrInfo(s.op).operands[3].span - 1;
    if (!cx.tp.validIndex(Area::Param, last))
      cx.error(p.loc, "LJ1042",
               mn + " parameter block " + addr(cx, Area::Param, p.index) + ".." +
                   addr(cx, Area::Param, last) + " runs past the end of " +
                   cx.tp.area(Area::Param).name + " (" + addr(cx, Area::Param, 0) + ".." +
                   lastOf(cx, Area::Param) + ")");
    break;
  }
  case Op::ChannelModeSet: {
    const Operand &m = s.ops[1];
    if (m.kind == Operand::Kind::Const &&
        (m.value <= 0 || m.value > 64 || (m.value & (m.value - 1)) != 0))
      cx.error(m.loc, "LJ1043",
               mn + " mode " + std::to_string(m.value) +
                   " is not one of 1, 2, 4, 8, 16, 32, 64 (auto, single block, manual, "
                   "increment, home, MPG, PMC)");
    break;
  }
  case Op::ReferencePoint:
    if (s.ops[1].value == 5)
      cx.warning(s.ops[1].loc, "LJ1044",
                 mn + " 5: the 5th reference point has no status bit; the output is always 0");
    break;
  default:
    break;
  }
}

} // namespace

void checkCnc(Context &cx) {
  for (const Stmt &s : cx.prog.stmts)
    if (opFamily(s.op) == Family::Cnc) checkStmt(cx, s);
}

} // namespace lj::verifier

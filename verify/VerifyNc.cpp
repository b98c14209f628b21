// Verifier checks of family Nc that the operand table cannot express: register blocks that must
// fit in their area (TEMPSEN X word and P block, HEADSEN D range, SPDA P block, NIXIE's second
// display byte). Errors point at the operand (DIALECT.md 6, docs/dialect-notes.md "NC services").
#include "verify/VerifierInternal.h"

#include <string>

namespace lj::verifier {

namespace {

/// `op` (a register) starts `count` consecutive elements; error unless the last one exists.
void mustFit(Context &cx, const Stmt &s, int k, int32_t count, const char *what) {
  const Operand &op = s.ops[k];
  if (op.kind != Operand::Kind::Reg || count <= 0) return;
  const AreaInfo &a = cx.tp.area(op.area);
  int64_t last = int64_t{op.index} + count - 1;
  if (last < a.count) return;
  std::string l(a.name);
  cx.error(op.loc, "LJ1049",
           std::string(cx.spell(s.op)) + " " + what + " " + l + std::to_string(op.index) + ".." +
               l + std::to_string(last) + " runs past the end of area " + l + " (" + l + "0.." + l +
               std::to_string(a.count - 1) + ")");
}

/// Elements operand `k` of `s` touches (the table's span column).
int32_t spanOf(const Stmt &s, int k) { return instrInfo(s.op).operands[k].span; }

} // namespace

void checkNc(Context &cx) {
  for (const Stmt &s : cx.prog.stmts) {
    switch (s.op) {
    case Op::TempSensor:
      mustFit(cx, s, 1, spanOf(s, 1), "AD word"); // low byte X[n], high byte X[n+1]
      mustFit(cx, s, 3, spanOf(s, 3), "parameter block");
      break;
    case Op::HeadSensors:
      if (s.ops[0].kind == Operand::Kind::Const) mustFit(cx, s, 2, s.ops[0].value, "storage range");
      break;
    case Op::SpindleAnalog:
      mustFit(cx, s, 4, spanOf(s, 4), "parameter block");
      break;
    case Op::PanelDisplay:
      // Width 1 into a byte area writes two bytes; W/D/B elements hold both.
      if (s.ops[1].kind == Operand::Kind::Const && s.ops[1].value == 1 &&
          s.ops[2].kind == Operand::Kind::Reg && cx.tp.area(s.ops[2].area).bytes == 1)
        mustFit(cx, s, 2, spanOf(s, 2), "two-byte display");
      break;
    default:
      break;
    }
  }
}

} // namespace lj::verifier

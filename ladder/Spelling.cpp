// The instruction as the ladder view draws it, in the program's dialect (docs/ladder-view.md
// "Dialects"): HNC-8 programs with the HNC-8 mnemonics, FANUC PMC programs with the PMC ones
// (RD/WRT, the functional instructions by name with their width: MOVW, EQB, TMRB...), IEC IL
// programs with the IL ones (LD/ST/S/R, the operation and comparison blocks' operators). The
// IR keeps no trace of a few source distinctions; those are drawn by meaning: a FANUC GTx/GEx
// is the IR's LTx/LEx with the operands swapped and is drawn so, MOVE (SUB 8, a masked move)
// as AND with its mask, MOVN as MOVB. Block joins that a dialect has no word for (the IR's ORB/ANB
// in an IEC listing) keep the HNC-8 word.
#include "ladder/Network.h"

namespace lj::ladder {

namespace {

/// B, W or D from the first register operand's width (0: the area's element, one byte on FANUC).
std::string fanucWidth(const Stmt &s) {
  for (int k = 0; k < s.operandCount; ++k) {
    const Operand &o = s.ops[static_cast<size_t>(k)];
    if (o.kind != Operand::Kind::Reg) continue;
    return o.width == 4 ? "D" : o.width == 2 ? "W" : "B";
  }
  return "B";
}

std::string fanuc(const VerifiedProgram &p, const Stmt &s) {
  switch (s.op) {
  case Op::Move:
    return "MOV" + fanucWidth(s);
  case Op::CompareEq:
    return "EQ" + fanucWidth(s);
  case Op::CompareLt:
    return "LT" + fanucWidth(s);
  case Op::CompareLe:
    return "LE" + fanucWidth(s);
  case Op::BitXor: // NOT (SUB 62) is x ^ all ones
    return s.operandCount >= 2 && s.ops[1].kind == Operand::Kind::Const && s.ops[1].value == -1
               ? "NOT"
               : "EOR";
  case Op::BitAnd:
    return "AND";
  case Op::BitOr:
    return "OR";
  default:
    // The front end's own table (RD, RD.NOT, WRT, AND.STK, END1, TMRB, DIFU...): it names
    // the ops above by all their source forms ("EQB/EQW/EQD"), which a drawing cannot use.
    return spelling(p.dialect, s.op);
  }
}

std::string iec(const VerifiedProgram &p, const Stmt &s) {
  switch (s.op) {
  case Op::AndBlock:
  case Op::OrBlock:
    return hnc8Mnemonic(s.op); // the IR's block joins: IL has only its parentheses
  case Op::LoadTrue:
    return "LD 1";
  case Op::SubEnd:
    return "RET"; // the end of a subroutine in IL
  default:
    return spelling(p.dialect, s.op);
  }
}

} // namespace

std::string drawnMnemonic(const VerifiedProgram &p, const Stmt &s) {
  const std::string d = p.dialect ? p.dialect->name : "hnc8";
  if (d == "fanuc") return fanuc(p, s);
  if (d == "iec") return iec(p, s);
  return hnc8Mnemonic(s.op);
}

} // namespace lj::ladder

// The IL -> IR expansions (Emitter.h), the IL wording of messages, and parse + verify.
#include "frontends/iec/Emitter.h"
#include "frontends/iec/FrontEnd.h"
#include "frontends/iec/Objects.h"

#include "profiles/iec/IecProfile.h"

namespace lj::iec {

namespace detail { // NetworkText.cpp
std::string spellStatement(const Stmt &s);
bool lookupWord(std::string_view w, Op &op);
bool printStatements(std::span<const StmtText> stmts, std::string &out, std::string &error);
bool drawStatements(std::span<const Stmt> stmts, size_t i, DrawnInstr &out);
} // namespace detail

void Emitter::emit(Op op, SourceLoc loc, std::initializer_list<Operand> operands) {
  Stmt s;
  s.op = op;
  s.loc = loc;
  s.id = static_cast<StmtId>(prog_.stmts.size());
  for (Operand o : operands) {
    if (o.loc.line == 0) o.loc = loc;
    s.ops[s.operandCount++] = o;
  }
  prog_.stmts.push_back(s);
}

Operand Emitter::scratch(SourceLoc loc) {
  Operand o;
  o.kind = Operand::Kind::Bit;
  o.area = Area::ExtraRelay;
  if (scratchUsed_ >= kScratchBytes * 8) {
    if (scratchUsed_ == kScratchBytes * 8)
      diags_.error(loc, "LJ2021",
                   "too many N / XOR / OPEN / SHORT instructions (more than " +
                       std::to_string(kScratchBytes * 8) + " scratch bits)");
    ++scratchUsed_;
    o.index = 0;
    o.bit = 0;
    return o;
  }
  o.index = scratchUsed_ / 8;
  o.bit = static_cast<int8_t>(scratchUsed_ % 8);
  ++scratchUsed_;
  o.loc = loc;
  return o;
}

void Emitter::negate(SourceLoc loc) {
  // t := acc; acc := (acc AND NOT t) OR NOT t = NOT acc.
  const Operand t = scratch(loc);
  emit(Op::Coil, loc, {t});
  emit(Op::AndNot, loc, {t});
  emit(Op::OrNot, loc, {t});
}

void Emitter::exclusiveOr(Op push, const Operand &x, SourceLoc loc) {
  // a := acc; push e; b := e; acc := (a OR e) AND (NOT a OR NOT b) = a XOR e. Each contact of
  // x is read once, so an edge form samples its object once.
  const Operand a = scratch(loc), b = scratch(loc);
  emit(Op::Coil, loc, {a});
  emit(push, loc, {x});
  emit(Op::Coil, loc, {b});
  emit(Op::OrBlock, loc);
  emit(Op::LoadNot, loc, {a});
  emit(Op::OrNot, loc, {b});
  emit(Op::AndBlock, loc);
}

void Emitter::constant(bool value, SourceLoc loc) {
  const Operand t = scratch(loc);
  emit(Op::Coil, loc, {t});
  emit(value ? Op::OrNot : Op::AndNot, loc, {t});
}

namespace {

const char *spell(Op op) {
  switch (op) {
  case Op::Load:
    return "LD";
  case Op::LoadNot:
    return "LDN";
  case Op::LoadTrue:
    return "LD 1";
  case Op::LoadRise:
    return "LDR";
  case Op::LoadFall:
    return "LDF";
  case Op::And:
    return "AND";
  case Op::AndNot:
    return "ANDN";
  case Op::AndRise:
    return "ANDR";
  case Op::AndFall:
    return "ANDF";
  case Op::Or:
    return "OR";
  case Op::OrNot:
    return "ORN";
  case Op::OrRise:
    return "ORR";
  case Op::OrFall:
    return "ORF";
  case Op::AndBlock:
    return ") of AND(";
  case Op::OrBlock:
    return ") of OR(";
  case Op::BranchPush:
    return "MPS";
  case Op::BranchRead:
    return "MRD";
  case Op::BranchPop:
    return "MPP";
  case Op::Coil:
    return "ST";
  case Op::CoilNot:
    return "STN";
  case Op::Set:
    return "S";
  case Op::Reset:
    return "R";
  case Op::EndInit:
  case Op::EndCyclic:
  case Op::EndSliced:
    return "END";
  case Op::Jump:
    return "JMPC";
  case Op::Label:
    return "%L:";
  case Op::Call:
    return "SR";
  case Op::SubBegin:
    return "SR:";
  case Op::SubEnd:
    return "end of subroutine";
  case Op::Return:
    return "RETC";
  case Op::Move:
    return ":=";
  case Op::Add:
    return "+";
  case Op::Subtract:
    return "-";
  case Op::Multiply:
    return "*";
  case Op::Divide:
    return "/";
  case Op::CompareLt:
    return "<";
  case Op::CompareLe:
    return "<=";
  case Op::CompareEq:
    return "=";
  case Op::IecTimer:
    return "BLK %TMi";
  case Op::IecCounter:
    return "BLK %Ci";
  default:
    return nullptr; // not spelled in this dialect: spelling() prints the neutral name
  }
}

const DialectText kText{"iec",
                        spell,
                        formatOperand,
                        nullptr,
                        detail::spellStatement,
                        detail::lookupWord,
                        detail::printStatements,
                        nullptr,
                        detail::drawStatements,
                        "(*",
                        "*)"};

} // namespace

const DialectText &dialectText() { return kText; }

} // namespace lj::iec

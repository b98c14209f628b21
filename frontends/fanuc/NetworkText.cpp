// FANUC PMC mnemonics as networks name and print them (docs/ladder-json.md "Other dialects",
// docs/ladder-view.md "Dialects"): the instruction of a statement as the user writes it (RD/WRT,
// the functional instructions by name with their width: MOVW, EQB, TMRB...), the reverse
// lookup the network JSON is read back with, and statements as mnemonic lines. The IR keeps no
// trace of a few source distinctions; those are named by meaning: a GTx/GEx is the IR's LTx/LEx
// with the operands swapped and is named so, MOVE (SUB 8, a masked move) AND with its mask,
// MOVN MOVB.
#include "frontends/fanuc/FrontEnd.h"
#include "frontends/fanuc/ParserInternal.h"

#include "ir/StackEffect.h"

namespace lj::fanuc::detail {

namespace {

/// B, W or D from the first register operand's width (0: the area's element, one byte).
std::string width(const Stmt &s) {
  for (int k = 0; k < s.operandCount; ++k) {
    const Operand &o = s.ops[static_cast<size_t>(k)];
    if (o.kind != Operand::Kind::Reg) continue;
    return o.width == 4 ? "D" : o.width == 2 ? "W" : "B";
  }
  return "B";
}

/// The operation of a width-suffixed name (MOVW, EQB, LTD, NEW, RNGB), false if none.
bool widthNamed(std::string_view w, Op &op) {
  if (w.empty() || (w.back() != 'B' && w.back() != 'W' && w.back() != 'D')) return false;
  const std::string_view stem = w.substr(0, w.size() - 1);
  static constexpr std::pair<std::string_view, Op> kStems[] = {
      {"MOV", Op::Move},     {"EQ", Op::CompareEq}, {"LT", Op::CompareLt},
      {"LE", Op::CompareLe}, {"NE", Op::CompareNe}, {"RNG", Op::CompareBetween},
  };
  for (const auto &[name, o] : kStems)
    if (stem == name) {
      op = o;
      return true;
    }
  return false;
}

} // namespace

std::string spellStatement(const Stmt &s) {
  switch (s.op) {
  case Op::Move:
    return "MOV" + width(s);
  case Op::CompareEq:
    return "EQ" + width(s);
  case Op::CompareLt:
    return "LT" + width(s);
  case Op::CompareLe:
    return "LE" + width(s);
  case Op::CompareNe:
    return "NE" + width(s);
  case Op::CompareBetween:
    return "RNG" + width(s);
  case Op::BitXor: // NOT (SUB 62) is x ^ all ones
    return s.operandCount >= 2 && s.ops[1].kind == Operand::Kind::Const && s.ops[1].value == -1
               ? "NOT"
               : "EOR";
  case Op::BitAnd:
    return "AND";
  case Op::BitOr:
    return "OR";
  default:
    // The front end's own table (RD, RD.NOT, WRT, AND.STK, END1, TMRB, DIFU...): it names the
    // ops above by all their source forms ("EQB/EQW/EQD"), which one statement cannot use.
    return spelling(&dialectText(), s.op);
  }
}

bool lookupWord(std::string_view w, Op &op) {
  if (w == "RD.STK" || w == "RD.NOT.STK") { // the pushing forms of RD and RD.NOT
    op = w == "RD.STK" ? Op::Load : Op::LoadNot;
    return true;
  }
  if (widthNamed(w, op)) return true;
  if (w == "EOR") { // NOT is spelled by the table row of BitXor's other form below
    op = Op::BitXor;
    return true;
  }
  for (int k = 0; k < kOpCount; ++k) {
    const char *s = dialectText().spell(static_cast<Op>(k));
    if (s && w == s) {
      op = static_cast<Op>(k);
      return true;
    }
  }
  if (w == "NOT") {
    op = Op::BitXor;
    return true;
  }
  return false;
}

bool drawStatements(std::span<const Stmt> s, size_t i, DrawnInstr &out) {
  if (i >= s.size()) return false;
  const Stmt &st = s[i];
  // JMP .. JMPE (SUB 10 / SUB 30, fanuc-pmc.md 6.11): the front end jumps to a label of its own
  // (L10000 and up) where JMPE stands; drawn as the JMP and the JMPE the user wrote.
  const bool ownLabel = st.operandCount == 1 && st.ops[0].area == Area::Label &&
                        st.ops[0].index >= FlowRegions{}.nextLabel;
  out.count = 1;
  out.main = 0;
  out.op = st.op;
  if (st.op == Op::Label && ownLabel) {
    out.as = DrawAs::Marker;
    out.text = "JMPE";
    return true;
  }
  if (st.op == Op::Jump || st.op == Op::JumpOut || st.op == Op::Call) {
    out.as = st.op == Op::Call ? DrawAs::Call : DrawAs::Jump;
    out.text = spellStatement(st);
    if (!ownLabel && st.operandCount == 1) {
      out.operand = formatOperand(st.ops[0]);
      out.text += " " + out.operand;
    } else if (ownLabel) {
      out.text = "JMP";
    }
    return true;
  }
  return false;
}

bool printStatements(std::span<const StmtText> stmts, std::string &out, std::string &error) {
  int32_t depth = 0;
  for (size_t i = 0; i < stmts.size(); ++i) {
    const StmtText &s = stmts[i];
    if (s.role != WrittenRole::None) {
      // An instruction as written (ir/Program.h WrittenInstr): its text stands for this
      // statement and the Part ones after it (a Part alone: its First printed it).
      size_t last = i;
      while (s.role == WrittenRole::First && last + 1 < stmts.size() &&
             stmts[last + 1].role == WrittenRole::Part)
        ++last;
      std::string comment;
      bool hasComment = false;
      for (size_t k = i; k <= last; ++k) {
        for (const std::string &c : stmts[k].before) out += ";" + (c.empty() ? c : " " + c) + "\n";
        if (stmts[k].hasComment) {
          comment += (hasComment ? " " : "") + stmts[k].comment;
          hasComment = true;
        }
        depth = stackEffect(instrInfo(stmts[k].op), depth).after(depth);
      }
      if (s.role == WrittenRole::First && !s.written.empty())
        out += s.written + (hasComment ? " ;" + (comment.empty() ? comment : " " + comment) : "") +
               "\n";
      i = last;
      continue;
    }
    for (const std::string &c : s.before) out += ";" + (c.empty() ? c : " " + c) + "\n";
    // CALLU Pn: the front end made it an always-true load and a CALL (Functional.cpp); FANUC
    // has no word for the load alone (an edited CALLU rung, a renamed subprogram's call).
    if (s.op == Op::LoadTrue && i + 1 < stmts.size() && stmts[i + 1].op == Op::Call &&
        stmts[i + 1].role == WrittenRole::None && stmts[i + 1].operands.size() == 1 &&
        stmts[i + 1].before.empty()) {
      const StmtText &call = stmts[i + 1];
      std::string line = "CALLU " + call.operands[0];
      if (s.hasComment || call.hasComment)
        line += " ;" + std::string(s.hasComment && !s.comment.empty() ? " " + s.comment : "") +
                (call.hasComment && !call.comment.empty() ? " " + call.comment : "");
      out += line + "\n";
      depth = stackEffect(instrInfo(s.op), depth).after(depth);
      depth = stackEffect(instrInfo(call.op), depth).after(depth);
      ++i;
      continue;
    }
    std::string word = s.instr.empty() ? spelling(&dialectText(), s.op) : s.instr;
    switch (s.op) {
    case Op::Load: // RD starts a logic line, RD.STK pushes onto a live one (reference 5)
      word = depth > 0 ? "RD.STK" : "RD";
      break;
    case Op::LoadNot:
      word = depth > 0 ? "RD.NOT.STK" : "RD.NOT";
      break;
    default:
      break;
    }
    Op named = Op::LoadTrue;
    if (word.empty() || !lookupWord(word, named) ||
        (named != s.op && !(s.op == Op::BitXor && word == "NOT"))) {
      error = "statement " + std::to_string(i + 1) + ": " + instrInfo(s.op).name +
              " has no FANUC mnemonic form" + (word.empty() ? "" : " ('" + word + "')");
      return false;
    }
    std::string line = word;
    for (size_t k = 0; k < s.operands.size(); ++k) {
      if (k < 32 && (s.implied >> k & 1u)) continue;
      if (s.op == Op::BitXor && word == "NOT" && k == 1) continue; // the all-ones mask
      line += " " + s.operands[k];
    }
    if (s.hasComment) line += " ;" + (s.comment.empty() ? s.comment : " " + s.comment);
    out += line + "\n";
    depth = stackEffect(instrInfo(s.op), depth).after(depth);
  }
  return true;
}

} // namespace lj::fanuc::detail

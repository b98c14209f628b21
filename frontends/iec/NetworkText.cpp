// IEC IL as networks name and print it (docs/ladder-json.md "Other dialects", docs/ladder-view.md
// "Dialects"): the instruction of a statement as the Neza writes it, the reverse lookup the
// network JSON is read back with, and statements as IL lines: a chain that starts while a value
// is live is a parenthesis (`AND(` / `OR(` by the block that closes it, `)`), a comparison block
// is the bracketed operand of its LD / AND, an arithmetic block is `[dst := a + b]`, comments are
// `(* ... *)`. Statements the front end makes from other IL (N, XOR, END and their scratch bits,
// a BLK block's) are printed as the lines they were made from (ir/Program.h WrittenInstr).
#include "frontends/iec/FrontEnd.h"
#include "frontends/iec/Objects.h"
#include "profiles/iec/IecProfile.h"

#include "ir/StackEffect.h"

#include <algorithm>

namespace lj::iec::detail {

namespace {

bool isLoad(Op op) {
  return op == Op::Load || op == Op::LoadNot || op == Op::LoadRise || op == Op::LoadFall ||
         op == Op::LoadTrue;
}

bool isCompare(Op op) { return op == Op::CompareLt || op == Op::CompareLe || op == Op::CompareEq; }

const char *relation(Op op) { return op == Op::CompareLt ? "<" : op == Op::CompareLe ? "<=" : "="; }

const char *arith(Op op) {
  switch (op) {
  case Op::Add:
    return "+";
  case Op::Subtract:
    return "-";
  case Op::Multiply:
    return "*";
  case Op::Divide:
    return "/";
  default:
    return nullptr;
  }
}

/// A comment's text that cannot end the comment early.
std::string commentText(const std::string &c) {
  std::string t = c;
  for (size_t p; (p = t.find("*)")) != std::string::npos;) t.replace(p, 2, "* )");
  return t;
}

/// The modifier letter of a load / contact form: "", N, R, F.
const char *modifier(Op op) {
  switch (op) {
  case Op::LoadNot:
  case Op::AndNot:
  case Op::OrNot:
    return "N";
  case Op::LoadRise:
  case Op::AndRise:
  case Op::OrRise:
    return "R";
  case Op::LoadFall:
  case Op::AndFall:
  case Op::OrFall:
    return "F";
  default:
    return "";
  }
}

} // namespace

std::string spellStatement(const Stmt &s) {
  switch (s.op) {
  case Op::AndBlock:
  case Op::OrBlock:
    // The IR's block joins, which IL writes only as parentheses: drawn with the words of the
    // stack machine (an IL listing's ANB / ORB rung shows where a `)` closed).
    return s.op == Op::AndBlock ? "ANB" : "ORB";
  case Op::SubEnd:
    return "RET"; // the end of a subroutine in IL
  case Op::Label:
  case Op::SubBegin: // IL writes `%L64:` and `SR0:`: the operand with a colon
    return s.operandCount == 1 ? formatOperand(s.ops[0]) + ":" : spelling(&dialectText(), s.op);
  default:
    return spelling(&dialectText(), s.op);
  }
}

bool lookupWord(std::string_view w, Op &op) {
  static constexpr std::pair<std::string_view, Op> kExtra[] = {
      {"ANB", Op::AndBlock}, {"ORB", Op::OrBlock}, {"RET", Op::SubEnd}};
  for (const auto &[name, o] : kExtra)
    if (w == name) {
      op = o;
      return true;
    }
  if (w.size() > 1 && w.back() == ':') { // a label or subroutine header written whole
    std::string why;
    std::optional<Object> obj = parseObject(w.substr(0, w.size() - 1), why);
    if (obj && obj->op.area == Area::Label) op = Op::Label;
    if (obj && obj->op.area == Area::Subroutine) op = Op::SubBegin;
    if (obj && (obj->op.area == Area::Label || obj->op.area == Area::Subroutine)) return true;
  }
  for (int k = 0; k < kOpCount; ++k) {
    const char *s = dialectText().spell(static_cast<Op>(k));
    if (s && w == s) {
      op = static_cast<Op>(k);
      return true;
    }
  }
  return false;
}

namespace {

bool isScratch(const Operand &o) {
  return o.kind == Operand::Kind::Bit && o.area == Area::ExtraRelay;
}

bool sameBit(const Operand &a, const Operand &b) {
  return a.kind == b.kind && a.area == b.area && a.index == b.index && a.bit == b.bit;
}

bool is(std::span<const Stmt> s, size_t i, Op op) { return i < s.size() && s[i].op == op; }

/// Statement `i` and on is the front end's N (Emitter::negate): `ST t; ANDN t; ORN t`.
bool negation(std::span<const Stmt> s, size_t i) {
  return is(s, i, Op::Coil) && is(s, i + 1, Op::AndNot) && is(s, i + 2, Op::OrNot) &&
         isScratch(s[i].ops[0]) && sameBit(s[i].ops[0], s[i + 1].ops[0]) &&
         sameBit(s[i].ops[0], s[i + 2].ops[0]);
}

/// Statement `i` and on is the front end's XOR (Emitter::exclusiveOr): `ST a; LD x; ST b; ORB;
/// LDN a; ORN b; ANB`.
bool exclusiveOr(std::span<const Stmt> s, size_t i) {
  if (!is(s, i, Op::Coil) || !isScratch(s[i].ops[0]) || i + 6 >= s.size()) return false;
  const Op push = s[i + 1].op;
  const Operand &a = s[i].ops[0], &b = s[i + 2].ops[0];
  return (push == Op::Load || push == Op::LoadNot || push == Op::LoadRise ||
          push == Op::LoadFall) &&
         is(s, i + 2, Op::Coil) && isScratch(b) && is(s, i + 3, Op::OrBlock) &&
         is(s, i + 4, Op::LoadNot) && sameBit(s[i + 4].ops[0], a) && is(s, i + 5, Op::OrNot) &&
         sameBit(s[i + 5].ops[0], b) && is(s, i + 6, Op::AndBlock);
}

/// Statement `i` and on is the front end's constant (Emitter::constant): `ST t; ANDN t` (acc :=
/// 0, AND 0) or `ST t; ORN t` (acc := 1, OR 1); not the start of an N.
bool constantAt(std::span<const Stmt> s, size_t i, bool &value) {
  if (!is(s, i, Op::Coil) || !isScratch(s[i].ops[0]) || negation(s, i)) return false;
  if (!(is(s, i + 1, Op::AndNot) || is(s, i + 1, Op::OrNot)) ||
      !sameBit(s[i].ops[0], s[i + 1].ops[0]))
    return false;
  value = s[i + 1].op == Op::OrNot;
  return true;
}

bool isEndLabel(const Operand &o) { return o.area == Area::Label && o.index == kEndLabel; }

/// A comparison as written: the IR keeps `a > b` as `b < a`. The sides in the order the source
/// has them (their columns, ParserSequence.cpp); without a source (an edited network), the
/// object first when one side is a constant (`%MW0 > 5`, not `5 < %MW0`). `negated`: `<>` (an
/// `=` and an N).
std::string comparisonText(const Stmt &c, bool negated) {
  std::string a = formatOperand(c.ops[0]), b = formatOperand(c.ops[1]);
  const SourceLoc &la = c.ops[0].loc, &lb = c.ops[1].loc;
  const bool located =
      la.line > 0 && la.line == lb.line && la.col > 0 && lb.col > 0 && la.col != lb.col;
  const bool swap =
      located ? la.col > lb.col
              : c.ops[0].kind == Operand::Kind::Const && c.ops[1].kind != Operand::Kind::Const;
  std::string rel = negated ? "<>" : relation(c.op);
  if (swap && !negated) rel = c.op == Op::CompareLt ? ">" : c.op == Op::CompareLe ? ">=" : "=";
  return swap ? b + " " + rel + " " + a : a + " " + rel + " " + b;
}

/// `out` for statements [i, i + count) drawn `as` with `text`, standing for one statement `op`.
bool form(DrawnInstr &out, DrawAs as, int32_t count, int32_t main, Op op, std::string text,
          std::string operand = {}, bool fromRail = false) {
  out.as = as;
  out.count = count;
  out.main = main;
  out.op = op;
  out.text = std::move(text);
  out.operand = std::move(operand);
  out.fromRail = fromRail;
  return true;
}

} // namespace

bool drawStatements(std::span<const Stmt> s, size_t i, DrawnInstr &out) {
  if (i >= s.size()) return false;
  const Stmt &st = s[i];
  // What the front end adds on its own: the label END jumps to, the end of a subroutine (the
  // user wrote RET or nothing), the end of the init part IL does not have.
  if ((st.op == Op::Label && isEndLabel(st.ops[0])) || st.op == Op::SubEnd || st.op == Op::EndInit)
    return form(out, DrawAs::Hidden, 1, 0, st.op, {});
  auto flow = [&](const Stmt &f, const char *cond) {
    const bool end = f.op == Op::Jump && isEndLabel(f.ops[0]);
    const std::string label = f.op == Op::Jump && !end ? formatOperand(f.ops[0]) : std::string();
    const DrawAs as = f.op == Op::Return ? DrawAs::Return : end ? DrawAs::End : DrawAs::Jump;
    const char *word = as == DrawAs::Return ? "RET" : as == DrawAs::End ? "END" : "JMP";
    return std::make_pair(as, std::string(word) + cond + (label.empty() ? "" : " " + label));
  };
  auto isFlow = [&](size_t k) { return is(s, k, Op::Jump) || is(s, k, Op::Return); };
  const auto label = [&](size_t k) {
    return is(s, k, Op::Jump) && !isEndLabel(s[k].ops[0]) ? formatOperand(s[k].ops[0])
                                                          : std::string();
  };
  // JMP / END / RET: `LD 1` and the jump, drawn from the rail.
  if (st.op == Op::LoadTrue && isFlow(i + 1)) {
    auto [as, text] = flow(s[i + 1], "");
    return form(out, as, 2, 1, s[i + 1].op, text, label(i + 1), true);
  }
  // JMPCN / ENDCN / RETCN: N, the conditional form, N.
  if (negation(s, i) && isFlow(i + 3) && negation(s, i + 4)) {
    auto [as, text] = flow(s[i + 3], "CN");
    return form(out, as, 7, 3, s[i + 3].op, text, label(i + 3));
  }
  if (isFlow(i)) { // JMPC / ENDC / RETC
    auto [as, text] = flow(st, "C");
    return form(out, as, 1, 0, st.op, text, label(i));
  }
  if (st.op == Op::Call) // SRi: the call as written
    return form(out, DrawAs::Call, 1, 0, st.op, formatOperand(st.ops[0]), formatOperand(st.ops[0]));
  // Comparisons: `LD [a < b]` (LD 1 and the block), `AND [a < b]` (the block), `<>` with an N.
  if (st.op == Op::LoadTrue && i + 1 < s.size() && isCompare(s[i + 1].op)) {
    const bool neg = negation(s, i + 2);
    if (neg && is(s, i + 5, Op::AndBlock)) // AND [a <> b]
      return form(out, DrawAs::Compare, 6, 1, Op::And, comparisonText(s[i + 1], true));
    return form(out, DrawAs::Compare, neg ? 5 : 2, 1, Op::Load, comparisonText(s[i + 1], neg));
  }
  if (isCompare(st.op) && st.operandCount == 2)
    return form(out, DrawAs::Compare, 1, 0, Op::And, comparisonText(st, false));
  // Operation blocks: `[dst := a]`, `[dst := a + b]`.
  if (st.op == Op::Move && st.operandCount == 2)
    return form(out, DrawAs::Operate, 1, 0, st.op,
                formatOperand(st.ops[1]) + " := " + formatOperand(st.ops[0]));
  if (const char *a = arith(st.op); a && st.operandCount == 3)
    return form(out, DrawAs::Operate, 1, 0, st.op,
                formatOperand(st.ops[2]) + " := " + formatOperand(st.ops[0]) + " " + a + " " +
                    formatOperand(st.ops[1]));
  // XOR x (XORN, XORR, XORF by the contact form of x): one element in the series.
  if (exclusiveOr(s, i)) {
    const std::string x = formatOperand(s[i + 1].ops[0]);
    return form(out, DrawAs::Contact, 7, 1, Op::And,
                std::string("XOR") + modifier(s[i + 1].op) + " " + x, x);
  }
  if (negation(s, i)) return form(out, DrawAs::Contact, 3, 0, Op::And, "N");
  // LD 0 (LD 1 and AND 0), AND 0 / OPEN, OR 1 / SHORT.
  bool value = false;
  if (st.op == Op::LoadTrue && constantAt(s, i + 1, value) && !value)
    return form(out, DrawAs::Contact, 3, 0, Op::Load, "LD 0");
  if (constantAt(s, i, value))
    return form(out, DrawAs::Contact, 2, 0, value ? Op::Or : Op::And, value ? "OR 1" : "AND 0");
  return false;
}

bool printStatements(std::span<const StmtText> stmts, std::string &out, std::string &error) {
  const size_t n = stmts.size();
  // Which parenthesis each load on a live value opens: the block statement that closes it.
  std::vector<Op> opens(n, Op::LoadTrue);
  {
    std::vector<size_t> open;
    int32_t depth = 0;
    for (size_t i = 0; i < n; ++i) {
      const Op op = stmts[i].op;
      if (isLoad(op) && depth > 0) open.push_back(i);
      if ((op == Op::AndBlock || op == Op::OrBlock) && !open.empty()) {
        opens[open.back()] = op;
        open.pop_back();
      }
      depth = stackEffect(instrInfo(op), depth).after(depth);
    }
  }
  auto fail = [&](size_t i, const std::string &why) {
    error = "statement " + std::to_string(i + 1) + ": " + instrInfo(stmts[i].op).name +
            " has no IL form" + (why.empty() ? "" : " (" + why + ")");
    return false;
  };
  auto operand = [&](size_t i, size_t k) -> const std::string * {
    return k < stmts[i].operands.size() ? &stmts[i].operands[k] : nullptr;
  };
  int32_t depth = 0;
  for (size_t i = 0; i < n; ++i) {
    const StmtText &s = stmts[i];
    if (s.role != WrittenRole::None) {
      // Lines as written (ir/Program.h WrittenInstr: an N / XOR / END expansion, a BLK block's
      // lines): they stand for this statement and the Part ones after it (a Part alone: its
      // First printed it); empty: statements the front end makes on its own (block presets).
      size_t last = i;
      while (s.role == WrittenRole::First && last + 1 < n &&
             stmts[last + 1].role == WrittenRole::Part)
        ++last;
      std::string comments;
      for (size_t k = i; k <= last; ++k) {
        for (const std::string &c : stmts[k].before) out += "(* " + commentText(c) + " *)\n";
        if (stmts[k].hasComment) comments += " (* " + commentText(stmts[k].comment) + " *)";
        depth = stackEffect(instrInfo(stmts[k].op), depth).after(depth);
      }
      if (s.role == WrittenRole::First && !s.written.empty()) out += s.written + comments + "\n";
      i = last;
      continue;
    }
    for (const std::string &c : s.before) out += "(* " + commentText(c) + " *)\n";
    std::string line;
    size_t last = i; // the last statement this line writes
    const Op op = s.op;
    // What the front end adds on its own: the init part's end (IL has no init part), a
    // subroutine's end (at the next SRi : or the end of the text; IL's RET is a Return) and the
    // label END jumps to (after the main program). Not written; the front end adds them again.
    if (op == Op::EndInit || op == Op::SubEnd ||
        (op == Op::Label && s.operands.size() == 1 &&
         s.operands[0] ==
             formatOperand(
                 Operand{Operand::Kind::Reg, Area::Label, 0, false, kEndLabel, -1, -1, 0, {}}))) {
      depth = 0;
      continue;
    }
    const bool nextCompare =
        i + 1 < n && isCompare(stmts[i + 1].op) && stmts[i + 1].role == WrittenRole::None;
    if (isLoad(op)) {
      std::string head;
      if (depth == 0) {
        head = std::string("LD") + modifier(op);
      } else {
        if (opens[i] == Op::LoadTrue) return fail(i, "a chain no ')' closes");
        head = std::string(opens[i] == Op::AndBlock ? "AND(" : "OR(") + modifier(op);
      }
      if (op == Op::LoadTrue && nextCompare) {
        const StmtText &c = stmts[i + 1];
        if (c.operands.size() != 2 || !c.before.empty() || s.hasComment)
          return fail(i + 1, "a comparison with two operands");
        line = head + (depth == 0 ? " [" : "[") + c.operands[0] + " " + relation(c.op) + " " +
               c.operands[1] + "]";
        last = i + 1;
      } else if (op == Op::LoadTrue && i + 1 < n && depth == 0 &&
                 (stmts[i + 1].op == Op::Jump ||
                  // RET ends the sequence; LD 1 RETC leaves it open for what follows
                  (stmts[i + 1].op == Op::Return && (i + 2 == n || isLoad(stmts[i + 2].op)))) &&
                 !s.hasComment && stmts[i + 1].before.empty() &&
                 stmts[i + 1].role == WrittenRole::None) {
        const StmtText &j = stmts[i + 1];
        line = j.op == Op::Jump ? "JMP " + (j.operands.empty() ? "" : j.operands[0]) : "RET";
        last = i + 1;
      } else if (op == Op::LoadTrue) {
        line = depth == 0 ? "LD 1" : head + " 1";
      } else {
        const std::string *x = operand(i, 0);
        if (!x) return fail(i, "no operand");
        line = head + " " + *x;
      }
    } else {
      switch (op) {
      case Op::And:
      case Op::AndNot:
      case Op::AndRise:
      case Op::AndFall:
      case Op::Or:
      case Op::OrNot:
      case Op::OrRise:
      case Op::OrFall: {
        const std::string *x = operand(i, 0);
        if (!x) return fail(i, "no operand");
        const bool isAnd =
            op == Op::And || op == Op::AndNot || op == Op::AndRise || op == Op::AndFall;
        line = std::string(isAnd ? "AND" : "OR") + modifier(op) + " " + *x;
        break;
      }
      case Op::CompareLt:
      case Op::CompareLe:
      case Op::CompareEq:
        if (s.operands.size() != 2) return fail(i, "a comparison with two operands");
        line = "AND [" + s.operands[0] + " " + relation(op) + " " + s.operands[1] + "]";
        break;
      case Op::AndBlock:
      case Op::OrBlock:
        line = ")";
        break;
      case Op::BranchPush:
      case Op::BranchRead:
      case Op::BranchPop:
      case Op::Coil:
      case Op::CoilNot:
      case Op::Set:
      case Op::Reset:
      case Op::Jump: {
        line = spelling(&dialectText(), op);
        if (const std::string *x = operand(i, 0)) line += " " + *x;
        break;
      }
      case Op::Return:
        line = "RETC";
        break;
      case Op::Call:
        if (!operand(i, 0)) return fail(i, "no subroutine");
        line = *operand(i, 0);
        break;
      case Op::Label:
      case Op::SubBegin:
        if (!operand(i, 0)) return fail(i, "no operand");
        line = *operand(i, 0) + ":";
        break;
      case Op::EndCyclic:
      case Op::EndSliced:
        line = "END";
        break;
      case Op::Move:
        if (s.operands.size() != 2) return fail(i, "an operation block [dst := src]");
        line = "[" + s.operands[1] + " := " + s.operands[0] + "]";
        break;
      default:
        if (const char *a = arith(op); a && s.operands.size() == 3) {
          line = "[" + s.operands[2] + " := " + s.operands[0] + " " + a + " " + s.operands[1] + "]";
          break;
        }
        return fail(i, "");
      }
    }
    for (size_t k = i; k <= last; ++k) {
      if (stmts[k].hasComment) line += " (* " + commentText(stmts[k].comment) + " *)";
      depth = stackEffect(instrInfo(stmts[k].op), depth).after(depth);
    }
    out += line + "\n";
    i = last;
  }
  return true;
}

} // namespace lj::iec::detail

// The IEC IL parser, the sequence: operands and comparisons, the load / AND / OR / XOR
// families, AND( / OR( parentheses, coils (ST STN S R) and the MPS stack (modicon-neza.md
// 2.1-2.9).
#include "frontends/iec/ParserInternal.h"

#include "ir/IecBlocks.h"
#include "profiles/iec/IecProfile.h"

namespace lj::iec::detail {

bool IlParser::needSequence(SourceLoc loc, const std::string &what) {
  if (seq_) return true;
  error(loc, "LJ2053",
        what + " without a value to work on: a sequence starts with LD, LDN, LDR or LDF");
  seq_ = true; // one error per sequence
  return false;
}

bool IlParser::outsideParens(SourceLoc loc, const std::string &what) {
  if (parens_.empty()) return true;
  error(loc, "LJ2054",
        what + " inside parentheses (the " + parenName(parens_.back()) + " on " +
            lineText(parens_.back().loc) +
            " is open): not allowed (modicon-neza.md 2.8, L973-976)");
  return false;
}

void IlParser::closeSequence(SourceLoc loc, const std::string &where) {
  for (const Paren &p : parens_)
    error(p.loc, "LJ2055",
          parenName(p) + " is not closed by ')' before " + where + " (" + lineText(loc) + ")");
  parens_.clear();
  if (!mps_.empty())
    error(mps_.front(), "LJ2056", "MPS has no MPP before " + where + " (" + lineText(loc) + ")");
  mps_.clear();
}

void IlParser::startSequence(SourceLoc loc, const std::string &mnem) {
  if (!parens_.empty()) {
    outsideParens(loc, mnem);
    parens_.clear();
  }
  closeSequence(loc, mnem);
  seq_ = true;
  afterMain(loc);
}

std::optional<Object> IlParser::object(std::string_view text, SourceLoc loc,
                                       const std::string &mnem) {
  if (text.empty()) {
    error(loc, "LJ2057", mnem + " needs an operand");
    return std::nullopt;
  }
  bool isBare = false;
  std::optional<Object> obj = blocks_.bare(text, loc, isBare);
  if (isBare) {
    if (obj) obj->op.loc = loc;
    return obj;
  }
  std::string err;
  obj = parseObject(text, err);
  if (!obj) {
    error(loc, "LJ2058", mnem + ": " + err);
    return std::nullopt;
  }
  blocks_.use(*obj);
  obj->op.loc = loc;
  return obj;
}

bool IlParser::isBitObject(ObjClass c) {
  return c == ObjClass::InputBit || c == ObjClass::OutputBit || c == ObjClass::MemoryBit ||
         c == ObjClass::SystemBit || c == ObjClass::WordBit || c == ObjClass::BlockBit;
}

std::optional<Object> IlParser::testOperand(std::string_view text, SourceLoc loc,
                                            const std::string &mnem, Mod mod, bool immediate) {
  std::optional<Object> obj = object(text, loc, mnem);
  if (!obj) return std::nullopt;
  if (obj->cls == ObjClass::Immediate) {
    if (!immediate || mod != Mod::Plain) {
      error(loc, "LJ2059",
            mnem + " takes no immediate value (modicon-neza.md 2.2-2.6, L614-617, L739-742, "
                   "L784-787, L829-832)");
      return std::nullopt;
    }
    if (obj->number != 0 && obj->number != 1) {
      error(loc, "LJ2060", mnem + ": an immediate bit value is 0 or 1");
      return std::nullopt;
    }
    return obj;
  }
  if (!isBitObject(obj->cls)) {
    error(loc, "LJ2061",
          mnem + " needs a bit object (%I, %Q, %M, %S, %MWi:Xk, %TMi.Q, %Ci.E/D/F), found '" +
              std::string(text) + "'");
    return std::nullopt;
  }
  if ((mod == Mod::Rise || mod == Mod::Fall) &&
      !(obj->cls == ObjClass::InputBit ||
        (obj->cls == ObjClass::MemoryBit && obj->number < kEdgeMemoryBits))) {
    error(loc, "LJ2062",
          mnem +
              ": edge instructions take only %I and %M0..%M31 (modicon-neza.md 2.1, "
              "L574-575), found '" +
              std::string(text) + "'");
    return std::nullopt;
  }
  return obj;
}

std::optional<Relation> IlParser::comparison(std::string_view text, SourceLoc loc,
                                             const std::string &mnem) {
  if (text.size() < 2 || text.front() != '[' || text.back() != ']') {
    error(loc, "LJ2063", mnem + ": expected a comparison [a < b]");
    return std::nullopt;
  }
  std::string_view in = text.substr(1, text.size() - 2);
  static const char *const kRels[] = {"<=", ">=", "<>", "<", ">", "="};
  for (const char *r : kRels) {
    size_t p = in.find(r);
    if (p == std::string_view::npos || p == 0) continue;
    Relation out;
    out.rel = r;
    std::optional<Operand> a = wordOperand(in.substr(0, p), loc, mnem, false);
    std::optional<Operand> b = wordOperand(in.substr(p + out.rel.size()), loc, mnem, false);
    if (!a || !b) return std::nullopt;
    out.a = *a;
    out.b = *b;
    // Each side where it is written (the right one after the operator): the IR keeps `a > b` as
    // `b < a`, and drawings tell the written order from these columns (NetworkText.cpp).
    out.a.loc = {loc.line, loc.col + 1};
    out.b.loc = {loc.line, loc.col + 1 + static_cast<int32_t>(p + out.rel.size())};
    return out;
  }
  error(loc, "LJ2064",
        mnem + ": expected a comparison operator (<, <=, >, >=, =, <>) in '" +
            std::string(text.substr(0, 40)) + "'");
  return std::nullopt;
}

std::optional<Operand> IlParser::wordOperand(std::string_view t, SourceLoc loc,
                                             const std::string &mnem, bool dest) {
  while (!t.empty() && blank(t.front())) t.remove_prefix(1);
  while (!t.empty() && blank(t.back())) t.remove_suffix(1);
  std::optional<Object> obj = object(t, loc, mnem);
  if (!obj) return std::nullopt;
  const bool word = obj->cls == ObjClass::Word || obj->cls == ObjClass::ConstWord ||
                    obj->cls == ObjClass::BlockWord;
  const bool writable =
      obj->cls == ObjClass::Word || (obj->cls == ObjClass::BlockWord && obj->writable);
  if (dest ? !writable : !(word || obj->cls == ObjClass::Immediate)) {
    error(loc, "LJ2065",
          mnem + ": '" + std::string(t) + "' is not " +
              (dest ? "a writable word (%MWi, %SWi, %TMi.P, %Ci.P)" +
                          std::string(obj->cls == ObjClass::BlockWord
                                          ? " (the current value .V is read-only, "
                                            "modicon-neza.md 1.2)"
                                          : "")
                    : "a word (%MWi, %KWi, %SWi, %TMi.V/.P, %Ci.V/.P) or a number"));
    return std::nullopt;
  }
  return obj->op;
}

void IlParser::emitComparison(const Relation &r, bool negated, bool push, SourceLoc loc) {
  std::string rel = r.rel;
  if (negated)
    rel = rel == "<"    ? ">="
          : rel == ">=" ? "<"
          : rel == ">"  ? "<="
          : rel == "<=" ? ">"
          : rel == "="  ? "<>"
                        : "=";
  const bool swap = rel == ">" || rel == ">=";
  const bool neg = rel == "<>";
  const Op op = rel == "<" || rel == ">"     ? Op::CompareLt
                : rel == "<=" || rel == ">=" ? Op::CompareLe
                                             : Op::CompareEq;
  const Operand a = swap ? r.b : r.a, b = swap ? r.a : r.b;
  if (push || neg) em_.emit(Op::LoadTrue, loc);
  em_.emit(op, loc, {a, b});
  if (neg) em_.negate(loc);
  if (!push && neg) em_.emit(Op::AndBlock, loc);
}

void IlParser::closeParen(SourceLoc loc) {
  if (parens_.empty()) {
    error(loc, "LJ2066", "')' without AND( or OR(");
    return;
  }
  em_.emit(parens_.back().close, loc);
  parens_.pop_back();
}

void IlParser::pushTest(const std::string &mnem, Mod mod, std::string_view text, SourceLoc loc,
                        SourceLoc opLoc, bool comparisonOk) {
  if (!text.empty() && text.front() == '[') {
    if (!comparisonOk || mod == Mod::Rise || mod == Mod::Fall) {
      error(opLoc, "LJ2067", mnem + " takes no comparison");
      return;
    }
    if (std::optional<Relation> r = comparison(text, opLoc, mnem))
      emitComparison(*r, mod == Mod::Not, true, loc);
    return;
  }
  std::optional<Object> obj = testOperand(text, opLoc, mnem, mod, true);
  if (!obj) return;
  if (obj->cls == ObjClass::Immediate) {
    em_.emit(Op::LoadTrue, loc);
    if (obj->number == 0) em_.constant(false, loc);
    return;
  }
  em_.emit(loadOp(mod), loc, {obj->op});
}

void IlParser::nonReversible(SourceLoc loc, const std::string &mnem) {
  diags_.warning(loc, "LJ2068",
                 mnem + " is not reversible: the Neza cannot edit it as ladder; the ladder view "
                        "draws it as written (modicon-neza.md 9 rule 3, L462-473)");
}

void IlParser::combine(const std::string &fam, Mod mod, const std::string &mnem,
                       std::string_view text, SourceLoc loc, SourceLoc opLoc) {
  if (!needSequence(loc, mnem)) return;
  const bool isXor = fam == "XOR";
  if (!text.empty() && text.front() == '[') {
    if (fam != "AND" || mod == Mod::Rise || mod == Mod::Fall) {
      error(opLoc, "LJ2069",
            mnem +
                " takes no comparison (modicon-neza.md 2.5-2.6, L784-787, L829-832; "
                "write " +
                fam + "( [...] ) instead)");
      return;
    }
    if (std::optional<Relation> r = comparison(text, opLoc, mnem))
      emitComparison(*r, mod == Mod::Not, false, loc);
    return;
  }
  std::optional<Object> obj = testOperand(text, opLoc, mnem, mod, !isXor);
  if (!obj) return;
  if (isXor) {
    if (mod == Mod::Not) nonReversible(loc, mnem);
    if (!parens_.empty())
      diags_.warning(loc, "LJ2070",
                     mnem + " inside parentheses is not reversible: ladder cannot place XOR "
                            "in a parallel branch (modicon-neza.md 2.6, L833-837)");
    em_.exclusiveOr(loadOp(mod), obj->op, loc);
    return;
  }
  if (obj->cls == ObjClass::Immediate) {
    // OPEN = AND 0, SHORT = OR 1 (L1053); AND 1 and OR 0 change nothing.
    if ((fam == "AND") == (obj->number == 0)) em_.constant(fam == "OR", loc);
    return;
  }
  static const Op kAnd[] = {Op::And, Op::AndNot, Op::AndRise, Op::AndFall};
  static const Op kOr[] = {Op::Or, Op::OrNot, Op::OrRise, Op::OrFall};
  em_.emit((fam == "AND" ? kAnd : kOr)[static_cast<int>(mod)], loc, {obj->op});
}

void IlParser::coil(const std::string &mnem, std::string_view text, SourceLoc loc,
                    SourceLoc opLoc) {
  if (!needSequence(loc, mnem) || !outsideParens(loc, mnem)) return;
  std::optional<Object> obj = object(text, opLoc, mnem);
  if (!obj) return;
  if (FunctionBlocks::isBlock(*obj) && (mnem == "R" || mnem == "S")) {
    directBlock(mnem, *obj, loc, opLoc);
    return;
  }
  if (obj->cls == ObjClass::SystemBit && runtimeBit(obj->number)) {
    error(opLoc, "LJ2071",
          mnem + " %S" + std::to_string(obj->number) +
              ": the runtime writes this system bit before every scan; the program may "
              "only read it (docs/iec-il.md \"System bits\")");
    return;
  }
  if (obj->cls == ObjClass::BlockBit) {
    error(opLoc, "LJ2072",
          mnem + " " + std::string(text) +
              ": function-block outputs are read-only (modicon-neza.md 1.2, L1133-1159)");
    return;
  }
  const bool ok = obj->cls == ObjClass::OutputBit || obj->cls == ObjClass::MemoryBit ||
                  obj->cls == ObjClass::SystemBit ||
                  (obj->cls == ObjClass::WordBit && obj->op.area != Area::ConstWords);
  if (!ok) {
    error(opLoc, "LJ2073",
          mnem + " needs a writable bit (%Q, %M, %S, %MWi:Xk), found '" + std::string(text) + "'" +
              (obj->cls == ObjClass::InputBit ? " (inputs are read-only)" : ""));
    return;
  }
  const Op op = mnem == "ST"    ? Op::Coil
                : mnem == "STN" ? Op::CoilNot
                : mnem == "S"   ? Op::Set
                                : Op::Reset;
  em_.emit(op, loc, {obj->op});
}

void IlParser::branch(const std::string &mnem, std::string_view text, SourceLoc loc) {
  if (!text.empty()) error(loc, "LJ2074", mnem + " takes no operand");
  if (!needSequence(loc, mnem)) return;
  if (!parens_.empty()) {
    error(loc, "LJ2075",
          mnem + " inside parentheses (the " + parenName(parens_.back()) + " on " +
              lineText(parens_.back().loc) + " is open): not allowed (modicon-neza.md 2.9, L1046)");
    return;
  }
  if (mnem == "MPS") {
    if (static_cast<int32_t>(mps_.size()) >= kMpsDepth) {
      error(loc, "LJ2076",
            "MPS stack deeper than " + std::to_string(kMpsDepth) +
                " entries (modicon-neza.md 2.9, L979)");
      return;
    }
    mps_.push_back(loc);
    em_.emit(Op::BranchPush, loc);
    return;
  }
  if (mps_.empty()) {
    error(loc, "LJ2077", mnem + " without MPS (the MPS stack is empty)");
    return;
  }
  if (mnem == "MPP") mps_.pop_back();
  em_.emit(mnem == "MRD" ? Op::BranchRead : Op::BranchPop, loc);
}

bool IlParser::runtimeBit(int32_t n) {
  const TargetProfile &tp = profile();
  for (const SystemBit &b : tp.systemBits)
    if (b.offset == tp.elementOffset(Area::SystemBits, n / 8) && b.bit == n % 8) return true;
  return false;
}

} // namespace lj::iec::detail

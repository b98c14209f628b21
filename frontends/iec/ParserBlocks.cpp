// The IEC IL parser, blocks: operation blocks `[%MWi := a + b]` (modicon-neza.md 9 rule 4)
// and the BLK / OUT_BLK / END_BLK structure of function blocks with their inputs (3.1;
// FunctionBlocks in Blocks.h does the blocks themselves).
#include "frontends/iec/ParserInternal.h"

#include "ir/IecBlocks.h"
#include "profiles/iec/IecProfile.h"

namespace lj::iec::detail {

bool IlParser::isPreset(const Operand &o) {
  return o.area == Area::TimerData || o.area == Area::CounterData; // only .P is writable
}

void IlParser::operationBlock(std::string_view text, SourceLoc loc) {
  afterMain(loc);
  if (blocks_.section() == FunctionBlocks::Section::Inputs) {
    inputSection(loc, "an operation block");
    return;
  }
  if (text.back() != ']') {
    error(loc, "LJ2033", "operation block: expected ']' at the end");
    return;
  }
  std::string_view in = text.substr(1, text.size() - 2);
  size_t assign = in.find(":=");
  if (assign == std::string_view::npos) {
    error(loc, "LJ2034",
          "operation block: expected [%MWi := expression]; a comparison [a < b] is the "
          "operand of LD, LDN, AND, ANDN, AND( or OR(");
    return;
  }
  if (!seq_) {
    error(loc, "LJ2035",
          "an operation block needs a condition: write LD 1 before an unconditional one "
          "(modicon-neza.md 9 rule 4, L474-489)");
    seq_ = true;
    return;
  }
  if (!outsideParens(loc, "an operation block")) return;
  std::optional<Operand> dst = wordOperand(in.substr(0, assign), loc, ":=", true);
  std::string_view expr = in.substr(assign + 2);
  while (!expr.empty() && blank(expr.front())) expr.remove_prefix(1);
  // a OP b, OP one of + - * / (not a leading sign).
  size_t p = std::string_view::npos;
  for (size_t k = 1; k < expr.size(); ++k)
    if (std::string_view("+-*/").find(expr[k]) != std::string_view::npos) {
      p = k;
      break;
    }
  if (p == std::string_view::npos) {
    std::optional<Operand> src = wordOperand(expr, loc, ":=", false);
    if (dst && src && isPreset(*dst) && src->kind == Operand::Kind::Const &&
        (src->value < 0 || src->value > kPresetMax)) {
      error(loc, "LJ2036",
            ":=: preset " + std::to_string(src->value) +
                " out of range (0 <= P <= 9999; modicon-neza.md 3.3, L1276-1278)");
      return;
    }
    if (dst && src) em_.emit(Op::Move, loc, {*src, *dst});
    return;
  }
  std::optional<Operand> a = wordOperand(expr.substr(0, p), loc, ":=", false);
  std::optional<Operand> b = wordOperand(expr.substr(p + 1), loc, ":=", false);
  if (!dst || !a || !b) return;
  const Op op = expr[p] == '+'   ? Op::Add
                : expr[p] == '-' ? Op::Subtract
                : expr[p] == '*' ? Op::Multiply
                                 : Op::Divide;
  em_.emit(op, loc, {*a, *b, *dst});
}

bool IlParser::testInstruction(const std::string &m) {
  for (const char *fam : {"LD", "AND", "OR", "XOR"})
    for (const char *suffix : {"", "N", "R", "F"})
      if (m == std::string(fam) + suffix) return true;
  return m == "N" || m == "NOP";
}

void IlParser::inputSection(SourceLoc loc, const std::string &what) {
  error(loc, "LJ2037",
        what + " between BLK and OUT_BLK (" + blocks_.openBlock() +
            "): only test instructions and the block's inputs are allowed there "
            "(modicon-neza.md 3.1, L1244-1246)");
}

bool IlParser::outsideBlock(SourceLoc loc, const std::string &what) {
  if (blocks_.section() == FunctionBlocks::Section::None) return true;
  error(loc, "LJ2038",
        what + " inside " + blocks_.openBlock() + " (before its END_BLK): not allowed");
  return false;
}

bool IlParser::blockInstruction(const std::string &mnem, std::string_view text, SourceLoc loc,
                                SourceLoc opLoc) {
  if (mnem == "CONFIG") {
    if (stmtCount_ - 1 != configLines_)
      error(loc, "LJ2039", "CONFIG lines come before the first instruction of the program");
    ++configLines_;
    blocks_.config(text, loc);
    return true;
  }
  if (mnem == "BLK") {
    afterMain(loc);
    if (blocks_.section() == FunctionBlocks::Section::None) {
      closeSequence(loc, "BLK");
      seq_ = false;
    }
    blocks_.begin(text, loc, opLoc);
    return true;
  }
  if (mnem == "OUT_BLK" || mnem == "END_BLK") {
    if (!text.empty()) error(opLoc, "LJ2040", mnem + " takes no operand");
    closeSequence(loc, mnem);
    seq_ = false;
    if (mnem == "OUT_BLK")
      blocks_.outputs(loc);
    else
      blocks_.end(loc);
    return true;
  }
  const bool input = mnem == "IN" || mnem == "CU" || mnem == "CD";
  if (!input && !((mnem == "R" || mnem == "S") && text.empty())) return false;
  if (text.empty()) {
    if (blocks_.section() != FunctionBlocks::Section::Inputs) {
      error(loc, "LJ2041",
            mnem +
                " without an operand is a function-block input: it stands between "
                "BLK and OUT_BLK (or END_BLK); elsewhere write " +
                mnem + " %TMi / %Ci");
      return true;
    }
    if (needSequence(loc, mnem) && outsideParens(loc, mnem)) blocks_.pin(mnem, loc);
    return true;
  }
  std::optional<Object> blk = object(text, opLoc, mnem);
  if (!blk) return true;
  if (!FunctionBlocks::isBlock(*blk)) {
    error(opLoc, "LJ2042",
          mnem + " needs a function block (%TMi, %Ci), found '" + std::string(text) + "'");
    return true;
  }
  directBlock(mnem, *blk, loc, opLoc);
  return true;
}

void IlParser::directBlock(const std::string &mnem, const Object &blk, SourceLoc loc,
                           SourceLoc opLoc) {
  afterMain(loc);
  const std::string name = (blk.cls == ObjClass::Timer ? "%TM" : "%C") + std::to_string(blk.number);
  if (!outsideBlock(loc, mnem + " " + name) || !needSequence(loc, mnem) ||
      !outsideParens(loc, mnem))
    return;
  blocks_.direct(mnem, blk, loc, opLoc);
}

} // namespace lj::iec::detail

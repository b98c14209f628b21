// The IEC IL (Neza) parser: lines `[NNN] MNEMONIC [operand]`, `%Li :` labels, `SRi :`
// subroutine entries, `[ ... ]` operation blocks, `(* ... *)` comments (modicon-neza.md 1.3, 7),
// with every restriction the seed states as a located error (2.8, 2.9, 9) and the
// non-reversible forms (9 rule 3, rule 8) as warnings. The IR mapping is Emitter.h's.
#include "frontends/iec/Blocks.h"
#include "frontends/iec/Emitter.h"
#include "frontends/iec/FrontEnd.h"
#include "frontends/iec/Objects.h"

#include "ir/IecBlocks.h"
#include "profiles/iec/IecProfile.h"

#include <cctype>
#include <vector>

namespace lj::iec {

namespace {

std::string upper(std::string_view s) {
  std::string out(s);
  for (char &c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

bool blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

std::string lineText(SourceLoc l) { return "line " + std::to_string(l.line); }

/// Contact forms by modifier: plain, N (negated), R (rising edge), F (falling edge).
enum class Mod : uint8_t { Plain, Not, Rise, Fall };

Op loadOp(Mod m) {
  switch (m) {
  case Mod::Not:
    return Op::LoadNot;
  case Mod::Rise:
    return Op::LoadRise;
  case Mod::Fall:
    return Op::LoadFall;
  default:
    return Op::Load;
  }
}

class Parser {
public:
  Parser(ParsedProgram &prog, Diagnostics &diags)
      : prog_(prog), diags_(diags), em_(prog, diags), blocks_(em_, diags) {}

  void run(std::string_view text) {
    if (text.size() >= 3 && text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
    // The init part: the block presets go before its end marker once the program is read (the
    // runtime writes %S0 / %S1 and the clocks: profiles/iec/Areas.cpp).
    em_.emit(Op::EndInit, {1, 1});
    int32_t lineNo = 0;
    size_t pos = 0;
    while (pos <= text.size() && diags_.errorCount() < kMaxErrors) {
      size_t nl = text.find('\n', pos);
      std::string_view line =
          text.substr(pos, nl == std::string_view::npos ? text.size() - pos : nl - pos);
      ++lineNo;
      handleLine(line, lineNo);
      if (nl == std::string_view::npos) break;
      pos = nl + 1;
    }
    const SourceLoc end{lineNo, 1};
    if (inComment_) diags_.error(commentLoc_, "comment '(*' is not closed by '*)'");
    blocks_.mustBeClosed(end, "the end of the program");
    closeSequence(end, "the end of the program");
    if (!mainDone_) finishMain(end);
    if (sub_ >= 0) em_.emit(Op::SubEnd, end);
    insertPresets();
  }

private:
  static constexpr int kMaxErrors = 100;

  /// The block presets (FunctionBlocks::presets) at the start of the init part; statement ids
  /// and comment positions move with them.
  void insertPresets() {
    std::vector<Stmt> pre = blocks_.presets({1, 1});
    if (pre.empty()) return;
    prog_.stmts.insert(prog_.stmts.begin(), pre.begin(), pre.end());
    for (size_t i = 0; i < prog_.stmts.size(); ++i) prog_.stmts[i].id = static_cast<StmtId>(i);
    for (Comment &c : prog_.comments) c.stmt += static_cast<int32_t>(pre.size());
  }

  void error(SourceLoc loc, const std::string &msg) { diags_.error(loc, msg); }

  // ---- lines and comments ------------------------------------------------------------------

  void handleLine(std::string_view line, int32_t lineNo) {
    // Remove (* ... *) comments (they may span lines), keep their text.
    std::string code(line.size(), ' ');
    std::string comment;
    bool hadComment = false;
    for (size_t i = 0; i < line.size(); ++i) {
      if (inComment_) {
        if (line.compare(i, 2, "*)") == 0) {
          inComment_ = false;
          ++i;
        } else {
          comment += line[i];
        }
        continue;
      }
      if (line.compare(i, 2, "(*") == 0) {
        inComment_ = true;
        hadComment = true;
        commentLoc_ = {lineNo, static_cast<int32_t>(i) + 1};
        ++i;
        continue;
      }
      code[i] = line[i];
    }
    if (!comment.empty()) hadComment = true; // the middle and last lines of a long (* ... *)
    const size_t before = prog_.stmts.size();
    bool hasCode = false;
    for (char c : code)
      if (!blank(c)) hasCode = true;
    if (hasCode) statement(code, lineNo);
    if (hadComment) {
      while (!comment.empty() && blank(comment.back())) comment.pop_back();
      size_t b = 0;
      while (b < comment.size() && blank(comment[b])) ++b;
      prog_.comments.push_back({lineNo, static_cast<int32_t>(hasCode ? before : prog_.stmts.size()),
                                hasCode, comment.substr(b)});
    }
  }

  void statement(const std::string &code, int32_t lineNo) {
    size_t i = 0;
    auto skip = [&] {
      while (i < code.size() && blank(code[i])) ++i;
    };
    auto at = [&](size_t k) { return SourceLoc{lineNo, static_cast<int32_t>(k) + 1}; };
    skip();
    // The auto-generated statement number `003` (L308-315).
    size_t d = i;
    while (d < code.size() && std::isdigit(static_cast<unsigned char>(code[d]))) ++d;
    if (d > i && d < code.size() && blank(code[d])) {
      i = d;
      skip();
    }
    size_t endCode = code.size();
    while (endCode > i && blank(code[endCode - 1])) --endCode;
    std::string_view rest(code.data() + i, endCode - i);
    const SourceLoc loc = at(i);
    if (rest.empty()) return;
    const std::string up = upper(rest);
    if (stmtCount_++ >= kStatementLimit) {
      if (stmtCount_ == kStatementLimit + 1)
        error(loc, "program has more than " + std::to_string(kStatementLimit) + " instructions");
      return;
    }
    // `%Li :` and `SRi :` headers.
    if (size_t colon = rest.find(':'); colon != std::string_view::npos &&
                                       (up.rfind("%L", 0) == 0 || up.rfind("SR", 0) == 0) &&
                                       rest.find(":=") == std::string_view::npos) {
      std::string_view name = rest.substr(0, colon);
      while (!name.empty() && blank(name.back())) name.remove_suffix(1);
      std::string_view after = rest.substr(colon + 1);
      while (!after.empty() && blank(after.front())) after.remove_prefix(1);
      if (!after.empty() && upper(after).rfind("X", 0) != 0) {
        error(at(i + colon + 1), "a label or subroutine header stands on its own line");
        return;
      }
      if (after.empty()) {
        header(name, loc);
        return;
      }
    }
    if (rest.front() == '[') {
      operationBlock(rest, loc);
      return;
    }
    if (rest.front() == ')') {
      if (rest.size() > 1) {
        error(at(i + 1), "unexpected text after ')'");
        return;
      }
      closeParen(loc);
      return;
    }
    size_t m = 0;
    while (m < rest.size() && (std::isalnum(static_cast<unsigned char>(rest[m])) || rest[m] == '_'))
      ++m;
    if (m == 0) {
      error(loc, "expected an instruction, found '" + std::string(rest.substr(0, 20)) + "'");
      return;
    }
    std::string mnem = upper(rest.substr(0, m));
    std::optional<char> paren; // AND( / OR( and their modifier ('\0' none, N R F or '[')
    size_t k = m;
    if (k < rest.size() && rest[k] == '(') {
      ++k;
      char mod = '\0';
      if (k < rest.size()) {
        const char c = static_cast<char>(std::toupper(static_cast<unsigned char>(rest[k])));
        if (c == 'N' || c == 'R' || c == 'F') {
          mod = c;
          ++k;
        } else if (c == '[') {
          mod = '[';
        }
      }
      paren = mod;
    }
    while (k < rest.size() && blank(rest[k])) ++k;
    const SourceLoc opLoc = at(i + k);
    instruction(mnem, paren, rest.substr(k), loc, opLoc);
  }

  // ---- sequence state ------------------------------------------------------------------------

  /// A statement that needs an open sequence (an accumulator value).
  bool needSequence(SourceLoc loc, const std::string &what) {
    if (seq_) return true;
    error(loc, what + " without a value to work on: a sequence starts with LD, LDN, LDR or LDF");
    seq_ = true; // one error per sequence
    return false;
  }

  /// A statement the seed forbids inside parentheses (L973-976, L1046).
  bool outsideParens(SourceLoc loc, const std::string &what) {
    if (parens_.empty()) return true;
    error(loc, what + " inside parentheses (the " + parenName(parens_.back()) + " on " +
                   lineText(parens_.back().loc) +
                   " is open): not allowed (modicon-neza.md 2.8, L973-976)");
    return false;
  }

  struct Paren {
    Op close;
    SourceLoc loc;
  };
  static std::string parenName(const Paren &p) { return p.close == Op::AndBlock ? "AND(" : "OR("; }

  /// The end of a sequence (a new LD, a label, a header, the end): everything must be closed.
  void closeSequence(SourceLoc loc, const std::string &where) {
    for (const Paren &p : parens_)
      error(p.loc,
            parenName(p) + " is not closed by ')' before " + where + " (" + lineText(loc) + ")");
    parens_.clear();
    if (!mps_.empty())
      error(mps_.front(), "MPS has no MPP before " + where + " (" + lineText(loc) + ")");
    mps_.clear();
  }

  void startSequence(SourceLoc loc, const std::string &mnem) {
    if (!parens_.empty()) {
      outsideParens(loc, mnem);
      parens_.clear();
    }
    closeSequence(loc, mnem);
    seq_ = true;
    afterMain(loc);
  }

  /// Code after END outside a subroutine.
  void afterMain(SourceLoc loc) {
    if (mainEnded_ && sub_ < 0 && !afterEndReported_) {
      error(loc, "instruction after END outside a subroutine (after END only SRi : blocks follow)");
      afterEndReported_ = true;
    }
  }

  void finishMain(SourceLoc loc) {
    // END / ENDC / ENDCN jump here.
    Operand end;
    end.kind = Operand::Kind::Reg;
    end.area = Area::Label;
    end.index = kEndLabel;
    em_.emit(Op::Label, loc, {end});
    mainDone_ = true;
  }

  void header(std::string_view name, SourceLoc loc) {
    std::string err;
    std::optional<Object> obj = parseObject(name, err);
    if (!obj || (obj->cls != ObjClass::Label && obj->cls != ObjClass::Sub)) {
      error(loc, obj ? "expected %Li : or SRi :" : err);
      return;
    }
    blocks_.mustBeClosed(loc, obj->cls == ObjClass::Label ? "a label" : "a subroutine");
    closeSequence(loc, obj->cls == ObjClass::Label ? "a label" : "a subroutine");
    seq_ = false;
    Operand op = obj->op;
    op.loc = loc;
    if (obj->cls == ObjClass::Label) {
      afterMain(loc);
      em_.emit(Op::Label, loc, {op});
      return;
    }
    if (!mainDone_) finishMain(loc);
    mainEnded_ = true;
    if (sub_ >= 0) em_.emit(Op::SubEnd, loc);
    em_.emit(Op::SubBegin, loc, {op});
    sub_ = obj->number;
  }

  // ---- operands ------------------------------------------------------------------------------

  std::optional<Object> object(std::string_view text, SourceLoc loc, const std::string &mnem) {
    if (text.empty()) {
      error(loc, mnem + " needs an operand");
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
      error(loc, mnem + ": " + err);
      return std::nullopt;
    }
    blocks_.use(*obj);
    obj->op.loc = loc;
    return obj;
  }

  static bool isBitObject(ObjClass c) {
    return c == ObjClass::InputBit || c == ObjClass::OutputBit || c == ObjClass::MemoryBit ||
           c == ObjClass::SystemBit || c == ObjClass::WordBit || c == ObjClass::BlockBit;
  }

  /// A test operand of `mnem` with modifier `mod`; `immediate`: 0/1 accepted.
  std::optional<Object> testOperand(std::string_view text, SourceLoc loc, const std::string &mnem,
                                    Mod mod, bool immediate) {
    std::optional<Object> obj = object(text, loc, mnem);
    if (!obj) return std::nullopt;
    if (obj->cls == ObjClass::Immediate) {
      if (!immediate || mod != Mod::Plain) {
        error(loc, mnem + " takes no immediate value (modicon-neza.md 2.2-2.6, L614-617, L739-742, "
                          "L784-787, L829-832)");
        return std::nullopt;
      }
      if (obj->number != 0 && obj->number != 1) {
        error(loc, mnem + ": an immediate bit value is 0 or 1");
        return std::nullopt;
      }
      return obj;
    }
    if (!isBitObject(obj->cls)) {
      error(loc, mnem +
                     " needs a bit object (%I, %Q, %M, %S, %MWi:Xk, %TMi.Q, %Ci.E/D/F), found '" +
                     std::string(text) + "'");
      return std::nullopt;
    }
    if ((mod == Mod::Rise || mod == Mod::Fall) &&
        !(obj->cls == ObjClass::InputBit ||
          (obj->cls == ObjClass::MemoryBit && obj->number < kEdgeMemoryBits))) {
      error(loc, mnem +
                     ": edge instructions take only %I and %M0..%M31 (modicon-neza.md 2.1, "
                     "L574-575), found '" +
                     std::string(text) + "'");
      return std::nullopt;
    }
    return obj;
  }

  // ---- comparisons and operation blocks -------------------------------------------------------

  struct Relation {
    Operand a, b;
    std::string rel; // < <= > >= = <>
  };

  /// `[a REL b]`, for LD/LDN/AND/ANDN and AND([ / OR([.
  std::optional<Relation> comparison(std::string_view text, SourceLoc loc,
                                     const std::string &mnem) {
    if (text.size() < 2 || text.front() != '[' || text.back() != ']') {
      error(loc, mnem + ": expected a comparison [a < b]");
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
      return out;
    }
    error(loc, mnem + ": expected a comparison operator (<, <=, >, >=, =, <>) in '" +
                   std::string(text.substr(0, 40)) + "'");
    return std::nullopt;
  }

  /// A word operand or constant; `dest`: must be a writable word.
  std::optional<Operand> wordOperand(std::string_view t, SourceLoc loc, const std::string &mnem,
                                     bool dest) {
    while (!t.empty() && blank(t.front())) t.remove_prefix(1);
    while (!t.empty() && blank(t.back())) t.remove_suffix(1);
    std::optional<Object> obj = object(t, loc, mnem);
    if (!obj) return std::nullopt;
    const bool word = obj->cls == ObjClass::Word || obj->cls == ObjClass::ConstWord ||
                      obj->cls == ObjClass::BlockWord;
    const bool writable =
        obj->cls == ObjClass::Word || (obj->cls == ObjClass::BlockWord && obj->writable);
    if (dest ? !writable : !(word || obj->cls == ObjClass::Immediate)) {
      error(loc, mnem + ": '" + std::string(t) + "' is not " +
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

  /// Push (LD) or combine with AND (AND) the comparison, negated for LDN / ANDN.
  void emitComparison(const Relation &r, bool negated, bool push, SourceLoc loc) {
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

  static bool isPreset(const Operand &o) {
    return o.area == Area::TimerData || o.area == Area::CounterData; // only .P is writable
  }

  void operationBlock(std::string_view text, SourceLoc loc) {
    afterMain(loc);
    if (blocks_.section() == FunctionBlocks::Section::Inputs) {
      inputSection(loc, "an operation block");
      return;
    }
    if (text.back() != ']') {
      error(loc, "operation block: expected ']' at the end");
      return;
    }
    std::string_view in = text.substr(1, text.size() - 2);
    size_t assign = in.find(":=");
    if (assign == std::string_view::npos) {
      error(loc, "operation block: expected [%MWi := expression]; a comparison [a < b] is the "
                 "operand of LD, LDN, AND, ANDN, AND( or OR(");
      return;
    }
    if (!seq_) {
      error(loc, "an operation block needs a condition: write LD 1 before an unconditional one "
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
        error(loc, ":=: preset " + std::to_string(src->value) +
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

  // ---- instructions --------------------------------------------------------------------------

  void closeParen(SourceLoc loc) {
    if (parens_.empty()) {
      error(loc, "')' without AND( or OR(");
      return;
    }
    em_.emit(parens_.back().close, loc);
    parens_.pop_back();
  }

  /// Push the first operand of a sequence or a parenthesis: `mnem` with modifier `mod`.
  void pushTest(const std::string &mnem, Mod mod, std::string_view text, SourceLoc loc,
                SourceLoc opLoc, bool comparisonOk) {
    if (!text.empty() && text.front() == '[') {
      if (!comparisonOk || mod == Mod::Rise || mod == Mod::Fall) {
        error(opLoc, mnem + " takes no comparison");
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

  void instruction(const std::string &mnem, std::optional<char> paren, std::string_view text,
                   SourceLoc loc, SourceLoc opLoc) {
    // The load family: LD LDN LDR LDF.
    static const std::pair<const char *, Mod> kLoads[] = {
        {"LD", Mod::Plain}, {"LDN", Mod::Not}, {"LDR", Mod::Rise}, {"LDF", Mod::Fall}};
    static const std::pair<const char *, Mod> kMods[] = {
        {"", Mod::Plain}, {"N", Mod::Not}, {"R", Mod::Rise}, {"F", Mod::Fall}};
    if (!paren && blockInstruction(mnem, text, loc, opLoc)) return;
    if (blocks_.section() == FunctionBlocks::Section::Inputs && !paren && !testInstruction(mnem)) {
      inputSection(loc, mnem);
      return;
    }
    if (paren) {
      if (mnem != "AND" && mnem != "OR") {
        error(loc, "only AND( and OR( open a parenthesis, found '" + mnem + "('");
        return;
      }
      if (!needSequence(loc, mnem + "(")) return;
      if (static_cast<int32_t>(parens_.size()) >= kParenDepth) {
        error(loc, mnem + "( nests parentheses deeper than " + std::to_string(kParenDepth) +
                       " levels (modicon-neza.md 2.8, L924-925)");
        return;
      }
      if (!mps_.empty() && parens_.empty()) {
        // MPS entries stay outside; nothing to check here.
      }
      const Mod mod = *paren == 'N'   ? Mod::Not
                      : *paren == 'R' ? Mod::Rise
                      : *paren == 'F' ? Mod::Fall
                                      : Mod::Plain;
      parens_.push_back({mnem == "AND" ? Op::AndBlock : Op::OrBlock, loc});
      pushTest(mnem + "(" + (*paren && *paren != '[' ? std::string(1, *paren) : ""), mod, text, loc,
               opLoc, true);
      return;
    }
    for (const auto &[name, mod] : kLoads)
      if (mnem == name) {
        startSequence(loc, mnem);
        pushTest(mnem, mod, text, loc, opLoc, mod == Mod::Plain || mod == Mod::Not);
        return;
      }
    // AND / OR / XOR families.
    for (const char *fam : {"AND", "OR", "XOR"})
      for (const auto &[suffix, mod] : kMods) {
        if (mnem != std::string(fam) + suffix) continue;
        combine(fam, mod, mnem, text, loc, opLoc);
        return;
      }
    if (mnem == "ST" || mnem == "STN" || mnem == "S" || mnem == "R") {
      coil(mnem, text, loc, opLoc);
      return;
    }
    if (mnem == "N") {
      if (!needSequence(loc, mnem)) return;
      if (!text.empty()) error(opLoc, "N takes no operand");
      nonReversible(loc, "N");
      em_.negate(loc);
      return;
    }
    if (mnem == "MPS" || mnem == "MRD" || mnem == "MPP") {
      branch(mnem, text, loc);
      return;
    }
    if (mnem == "JMP" || mnem == "JMPC" || mnem == "JMPCN") {
      jump(mnem, text, loc, opLoc);
      return;
    }
    if (mnem == "END" || mnem == "ENDC" || mnem == "ENDCN") {
      end(mnem, text, loc, opLoc);
      return;
    }
    if (mnem == "RET" || mnem == "RETC" || mnem == "RETCN") {
      ret(mnem, text, loc, opLoc);
      return;
    }
    if (mnem.size() > 2 && mnem.rfind("SR", 0) == 0 &&
        mnem.find_first_not_of("0123456789", 2) == std::string::npos) {
      call(mnem, text, loc, opLoc);
      return;
    }
    if (mnem == "NOP") {
      if (!text.empty()) error(opLoc, "NOP takes no operand");
      return;
    }
    static const char *const kBlocks[] = {"I", "O", "DS", "RET_BLK"};
    for (const char *b : kBlocks)
      if (mnem == b) {
        error(loc, mnem + ": an input of the %Ri / %DRi / %SBRi / %SCi blocks, which are not "
                          "supported (their pages are missing from the seed; docs/iec-il.md)");
        return;
      }
    error(loc, "unknown instruction '" + mnem + "'");
  }

  // ---- function blocks (Blocks.h) -----------------------------------------------------------

  /// The instructions allowed between BLK and OUT_BLK besides the block's inputs: tests only
  /// (modicon-neza.md 3.1, L1244-1246).
  static bool testInstruction(const std::string &m) {
    for (const char *fam : {"LD", "AND", "OR", "XOR"})
      for (const char *suffix : {"", "N", "R", "F"})
        if (m == std::string(fam) + suffix) return true;
    return m == "N" || m == "NOP";
  }

  void inputSection(SourceLoc loc, const std::string &what) {
    error(loc, what + " between BLK and OUT_BLK (" + blocks_.openBlock() +
                   "): only test instructions and the block's inputs are allowed there "
                   "(modicon-neza.md 3.1, L1244-1246)");
  }

  /// Not inside a BLK structure at all (jumps, calls, END, other blocks).
  bool outsideBlock(SourceLoc loc, const std::string &what) {
    if (blocks_.section() == FunctionBlocks::Section::None) return true;
    error(loc, what + " inside " + blocks_.openBlock() + " (before its END_BLK): not allowed");
    return false;
  }

  /// CONFIG, BLK, OUT_BLK, END_BLK, the inputs IN / CU / CD / R / S; false when `mnem` is none.
  bool blockInstruction(const std::string &mnem, std::string_view text, SourceLoc loc,
                        SourceLoc opLoc) {
    if (mnem == "CONFIG") {
      if (stmtCount_ - 1 != configLines_)
        error(loc, "CONFIG lines come before the first instruction of the program");
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
      if (!text.empty()) error(opLoc, mnem + " takes no operand");
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
        error(loc, mnem +
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
      error(opLoc, mnem + " needs a function block (%TMi, %Ci), found '" + std::string(text) + "'");
      return true;
    }
    directBlock(mnem, *blk, loc, opLoc);
    return true;
  }

  /// The instruction form `IN %TMi`, `CU %Ci`, `R %Ci`... (not reversible, modicon-neza.md 9 rule
  /// 2).
  void directBlock(const std::string &mnem, const Object &blk, SourceLoc loc, SourceLoc opLoc) {
    afterMain(loc);
    const std::string name =
        (blk.cls == ObjClass::Timer ? "%TM" : "%C") + std::to_string(blk.number);
    if (!outsideBlock(loc, mnem + " " + name) || !needSequence(loc, mnem) ||
        !outsideParens(loc, mnem))
      return;
    blocks_.direct(mnem, blk, loc, opLoc);
  }

  void nonReversible(SourceLoc loc, const std::string &mnem) {
    diags_.warning(loc, mnem + " is not reversible: the ladder view shows it as IL expanded into "
                               "contacts (modicon-neza.md 9 rule 3, L462-473)");
  }

  void combine(const std::string &fam, Mod mod, const std::string &mnem, std::string_view text,
               SourceLoc loc, SourceLoc opLoc) {
    if (!needSequence(loc, mnem)) return;
    const bool isXor = fam == "XOR";
    if (!text.empty() && text.front() == '[') {
      if (fam != "AND" || mod == Mod::Rise || mod == Mod::Fall) {
        error(opLoc, mnem +
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
        diags_.warning(loc, mnem + " inside parentheses is not reversible: ladder cannot place XOR "
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

  void coil(const std::string &mnem, std::string_view text, SourceLoc loc, SourceLoc opLoc) {
    if (!needSequence(loc, mnem) || !outsideParens(loc, mnem)) return;
    std::optional<Object> obj = object(text, opLoc, mnem);
    if (!obj) return;
    if (FunctionBlocks::isBlock(*obj) && (mnem == "R" || mnem == "S")) {
      directBlock(mnem, *obj, loc, opLoc);
      return;
    }
    if (obj->cls == ObjClass::SystemBit && runtimeBit(obj->number)) {
      error(opLoc, mnem + " %S" + std::to_string(obj->number) +
                       ": the runtime writes this system bit before every scan; the program may "
                       "only read it (docs/iec-il.md \"System bits\")");
      return;
    }
    if (obj->cls == ObjClass::BlockBit) {
      error(opLoc, mnem + " " + std::string(text) +
                       ": function-block outputs are read-only (modicon-neza.md 1.2, L1133-1159)");
      return;
    }
    const bool ok = obj->cls == ObjClass::OutputBit || obj->cls == ObjClass::MemoryBit ||
                    obj->cls == ObjClass::SystemBit ||
                    (obj->cls == ObjClass::WordBit && obj->op.area != Area::ConstWords);
    if (!ok) {
      error(opLoc, mnem + " needs a writable bit (%Q, %M, %S, %MWi:Xk), found '" +
                       std::string(text) + "'" +
                       (obj->cls == ObjClass::InputBit ? " (inputs are read-only)" : ""));
      return;
    }
    const Op op = mnem == "ST"    ? Op::Coil
                  : mnem == "STN" ? Op::CoilNot
                  : mnem == "S"   ? Op::Set
                                  : Op::Reset;
    em_.emit(op, loc, {obj->op});
  }

  void branch(const std::string &mnem, std::string_view text, SourceLoc loc) {
    if (!text.empty()) error(loc, mnem + " takes no operand");
    if (!needSequence(loc, mnem)) return;
    if (!parens_.empty()) {
      error(loc, mnem + " inside parentheses (the " + parenName(parens_.back()) + " on " +
                     lineText(parens_.back().loc) +
                     " is open): not allowed (modicon-neza.md 2.9, L1046)");
      return;
    }
    if (mnem == "MPS") {
      if (static_cast<int32_t>(mps_.size()) >= kMpsDepth) {
        error(loc, "MPS stack deeper than " + std::to_string(kMpsDepth) +
                       " entries (modicon-neza.md 2.9, L979)");
        return;
      }
      mps_.push_back(loc);
      em_.emit(Op::BranchPush, loc);
      return;
    }
    if (mps_.empty()) {
      error(loc, mnem + " without MPS (the MPS stack is empty)");
      return;
    }
    if (mnem == "MPP") mps_.pop_back();
    em_.emit(mnem == "MRD" ? Op::BranchRead : Op::BranchPop, loc);
  }

  std::optional<Operand> label(std::string_view text, SourceLoc opLoc, const std::string &mnem) {
    std::optional<Object> obj = object(text, opLoc, mnem);
    if (!obj) return std::nullopt;
    if (obj->cls != ObjClass::Label) {
      error(opLoc, mnem + " needs a label %Li, found '" + std::string(text) + "'");
      return std::nullopt;
    }
    return obj->op;
  }

  void jump(const std::string &mnem, std::string_view text, SourceLoc loc, SourceLoc opLoc) {
    afterMain(loc);
    if (!outsideBlock(loc, mnem)) return;
    if (mnem != "JMP" && !needSequence(loc, mnem)) return;
    if (!outsideParens(loc, mnem)) return;
    std::optional<Operand> l = label(text, opLoc, mnem);
    if (!l) return;
    if (mnem == "JMP") {
      em_.emit(Op::LoadTrue, loc); // unconditional: needs no LD 1 (L481-489)
      em_.emit(Op::Jump, loc, {*l});
      seq_ = true;
    } else if (mnem == "JMPC") {
      em_.emit(Op::Jump, loc, {*l});
    } else {
      nonReversible(loc, mnem);
      em_.negate(loc);
      em_.emit(Op::Jump, loc, {*l});
      em_.negate(loc);
    }
  }

  void end(const std::string &mnem, std::string_view text, SourceLoc loc, SourceLoc opLoc) {
    if (!text.empty()) error(opLoc, mnem + " takes no operand");
    if (!outsideBlock(loc, mnem)) return;
    if (sub_ >= 0) {
      error(loc, mnem + " inside a subroutine is not supported (the scan ends after the main "
                        "program; use RET)");
      return;
    }
    afterMain(loc);
    if (mnem != "END" && !needSequence(loc, mnem)) return;
    if (!outsideParens(loc, mnem)) return;
    Operand end;
    end.kind = Operand::Kind::Reg;
    end.area = Area::Label;
    end.index = kEndLabel;
    end.loc = loc;
    if (mnem == "END") {
      closeSequence(loc, "END");
      em_.emit(Op::LoadTrue, loc);
      em_.emit(Op::Jump, loc, {end});
      mainEnded_ = true;
      seq_ = false;
    } else if (mnem == "ENDC") {
      em_.emit(Op::Jump, loc, {end});
    } else {
      nonReversible(loc, mnem);
      em_.negate(loc);
      em_.emit(Op::Jump, loc, {end});
      em_.negate(loc);
    }
  }

  void ret(const std::string &mnem, std::string_view text, SourceLoc loc, SourceLoc opLoc) {
    if (!text.empty()) error(opLoc, mnem + " takes no operand");
    if (!outsideBlock(loc, mnem)) return;
    if (sub_ < 0) {
      error(loc, mnem + " outside a subroutine");
      return;
    }
    if (mnem != "RET" && !needSequence(loc, mnem)) return;
    if (!outsideParens(loc, mnem)) return;
    if (mnem == "RET") {
      closeSequence(loc, "RET");
      em_.emit(Op::LoadTrue, loc);
      em_.emit(Op::Return, loc);
      seq_ = false;
    } else if (mnem == "RETC") {
      em_.emit(Op::Return, loc);
    } else {
      em_.negate(loc);
      em_.emit(Op::Return, loc);
      em_.negate(loc);
    }
  }

  void call(const std::string &mnem, std::string_view text, SourceLoc loc, SourceLoc opLoc) {
    if (!text.empty()) error(opLoc, mnem + " takes no operand");
    if (!outsideBlock(loc, mnem)) return;
    afterMain(loc);
    if (!needSequence(loc, mnem) || !outsideParens(loc, mnem)) return;
    std::string err;
    std::optional<Object> obj = parseObject(mnem, err);
    if (!obj) {
      error(loc, err);
      return;
    }
    obj->op.loc = loc;
    em_.emit(Op::Call, loc, {obj->op});
  }

  /// The system bits of the profile's table (%S0, %S1, %S4..%S7, %S13).
  static bool runtimeBit(int32_t n) {
    const TargetProfile &tp = profile();
    for (const SystemBit &b : tp.systemBits)
      if (b.offset == tp.elementOffset(Area::SystemBits, n / 8) && b.bit == n % 8) return true;
    return false;
  }

  static constexpr int32_t kStatementLimit = 10000;

  ParsedProgram &prog_;
  Diagnostics &diags_;
  Emitter em_;
  FunctionBlocks blocks_;
  int32_t configLines_ = 0;
  std::vector<Paren> parens_;
  std::vector<SourceLoc> mps_;
  bool seq_ = false;
  bool mainDone_ = false, mainEnded_ = false, afterEndReported_ = false;
  int32_t sub_ = -1;
  int32_t stmtCount_ = 0;
  bool inComment_ = false;
  SourceLoc commentLoc_;
};

} // namespace

ParsedProgram parseIl(std::string_view text, std::string file, Diagnostics &diags) {
  ParsedProgram prog;
  prog.file = std::move(file);
  prog.dialect = &dialectText();
  prog.profile = &profile();
  Parser(prog, diags).run(text);
  return prog;
}

} // namespace lj::iec

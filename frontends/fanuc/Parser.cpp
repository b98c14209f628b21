// Lexer and parser of FANUC PMC mnemonic text (reference 5: basic instructions; 4: levels,
// END1/END2/END3/END, SP/SPE; docs/fanuc-pmc.md). One instruction per line; a functional
// instruction's parameters follow it on its line or on `(PRM) value` lines. The parser tracks the
// operation-result register ST0..ST7 itself: RD starts a new logic line (depth 1), RD.STK
// pushes, AND.STK/OR.STK pop; more than eight results is an error, as on the PMC.
#include "frontends/common/LineTokens.h"
#include "frontends/common/OperandText.h"
#include "frontends/common/ProfileAddress.h"
#include "frontends/fanuc/FrontEnd.h"
#include "frontends/fanuc/ParserInternal.h"
#include "profiles/fanuc/FanucProfile.h"

#include <algorithm>
#include <array>
#include <map>
#include <set>

namespace lj::fanuc {

namespace detail {
std::string upper(std::string_view s) {
  std::string out(s);
  for (char &c : out)
    if (c >= 'a' && c <= 'z') c = static_cast<char>(c - 'a' + 'A');
  return out;
}
} // namespace detail

namespace {

using detail::Token;

bool isDigit(char c) { return c >= '0' && c <= '9'; }
std::string quote(std::string_view t) {
  return "'" + std::string(t.substr(0, 40)) + (t.size() > 40 ? "...'" : "'");
}

const TargetProfile &tp() { return profile(); }

} // namespace

namespace detail {

std::string ranges(Area a) {
  const AreaInfo &i = profile().area(a);
  std::string n(i.name);
  std::string r = n + "0.." + n + std::to_string(i.count - 1);
  if (i.upperCount > 0)
    r += ", " + n + std::to_string(i.upperLo) + ".." + n +
         std::to_string(i.upperLo + i.upperCount - 1);
  return r;
}

bool readAddress(std::string_view s, bool labels, Operand &out, int64_t &bit, std::string &error) {
  const frontend::ProfileAddressText lexed = frontend::lexProfileAddress(profile(), s);
  if (lexed.lex == frontend::ProfileAddressText::Lex::NoArea) {
    error = "unknown address " + quote(s) + " (areas: X Y F G R E A T C K D" +
            (labels ? "; labels L, subroutines P)" : ")");
    return false;
  }
  // A width (`:2`) is command-line syntax; the instruction gives an operand's width.
  if (lexed.lex != frontend::ProfileAddressText::Lex::Ok || lexed.sep == ':') {
    error = "malformed address " + quote(s);
    return false;
  }
  const int64_t idx = lexed.index;
  bit = std::min<int64_t>(lexed.bit, 99);
  out = Operand{};
  out.area = lexed.area;
  out.index = static_cast<int32_t>(std::min<int64_t>(idx, INT32_MAX));
  if (!profile().validIndex(lexed.area, idx)) {
    error = "address " + quote(s) + " out of range (" + ranges(lexed.area) + ")";
    return false;
  }
  return true;
}
} // namespace detail

bool implied(Op op, int k); // below: the dialect's implied operands

namespace {

/// The basic instructions (reference 5) and how each changes ST.
struct Basic {
  const char *name;
  Op op;
  enum Kind : uint8_t { Read, ReadStk, Combine, Write, Block, Marker } kind;
};
constexpr Basic kBasic[] = {
    {"RD", Op::Load, Basic::Read},           {"RD.NOT", Op::LoadNot, Basic::Read},
    {"RD.STK", Op::Load, Basic::ReadStk},    {"RD.NOT.STK", Op::LoadNot, Basic::ReadStk},
    {"AND", Op::And, Basic::Combine},        {"AND.NOT", Op::AndNot, Basic::Combine},
    {"OR", Op::Or, Basic::Combine},          {"OR.NOT", Op::OrNot, Basic::Combine},
    {"WRT", Op::Coil, Basic::Write},         {"WRT.NOT", Op::CoilNot, Basic::Write},
    {"SET", Op::Set, Basic::Write},          {"RST", Op::Reset, Basic::Write},
    {"AND.STK", Op::AndBlock, Basic::Block}, {"OR.STK", Op::OrBlock, Basic::Block},
};

const Basic *basicNamed(std::string_view n) {
  for (const Basic &b : kBasic)
    if (n == b.name) return &b;
  return nullptr;
}

/// The SUB number written `digits` (1 to 4 decimal digits, as the SUB number table has them),
/// or -1: not such a number.
int64_t subNumber(std::string_view digits) {
  if (digits.empty() || digits.size() > 4 ||
      digits.find_first_not_of("0123456789") != std::string_view::npos)
    return -1;
  return std::stoll(std::string(digits));
}

/// The words of `line` (frontend::splitLine), its comment left out.
std::vector<frontend::Word> wordsOf(std::string_view line) {
  std::vector<frontend::Word> w;
  std::string_view comment;
  bool hasComment = false;
  frontend::splitLine(line, w, comment, hasComment);
  return w;
}

bool isMarkerName(std::string_view n) {
  return n == "END1" || n == "END2" || n == "END3" || n == "END" || n == "SP" || n == "SPE";
}

/// The words of one line (frontend::splitLine) located on line `lineNo`.
void tokenize(std::string_view line, int32_t lineNo, std::vector<Token> &toks,
              std::string_view &comment, bool &hasComment) {
  thread_local std::vector<frontend::Word> words;
  frontend::splitLine(line, words, comment, hasComment);
  toks.clear();
  for (const frontend::Word &w : words) toks.push_back({w.text, {lineNo, w.col}});
}

class Parser final : public detail::Emitter {
public:
  /// `symbols`: the program's symbol table (null: none, names are not resolved); `rejected`:
  /// the names (upper case) of symbol definitions that had errors, and their lines.
  Parser(ParsedProgram &p, Diagnostics &d, const SymbolTable *symbols,
         const std::map<std::string, int32_t> &rejected)
      : prog_(p), diags_(d), symbols_(symbols), rejected_(rejected) {}

  void line(const std::vector<Token> &toks, bool hasComment, std::string_view comment) {
    const std::string head = detail::upper(toks[0].text);
    if (!toks[0].text.empty() && toks[0].text[0] == '%') {
      error(toks[0].loc, "LJ4007",
            quote(toks[0].text) +
                " among mnemonic lines: a mnemonic file starts with %@A or a section "
                "header (%@3 the ladder, %@2-E the symbols), docs/fanuc-pmc.md");
      return;
    }
    if (symbols_)
      for (size_t k = 1; k < toks.size(); ++k)
        if (const Symbol *sym =
                SymbolTable::isNameShaped(toks[k].text) ? symbols_->find(toks[k].text) : nullptr)
          symbolAt_.emplace(std::make_pair(toks[k].loc.line, toks[k].loc.col), sym);
    if (head == "(PRM)" || head == "PRM") {
      if (!pending_) {
        error(toks[0].loc, "LJ4008", "parameter line without a functional instruction before it");
        return;
      }
      if (toks.size() != 2) {
        error(toks[0].loc, "LJ4009",
              "a parameter line holds one value, got " + std::to_string(toks.size() - 1));
        return;
      }
      pending_->params.push_back(toks[1]);
      return;
    }
    flush();
    const auto next = static_cast<int32_t>(prog_.stmts.size());
    if (afterEnd_) {
      error(toks[0].loc, "LJ4010", "statement after END (END ends the program)");
      return;
    }
    if (!isMarkerName(head)) {
      const int64_t sub = head == "SUB" && toks.size() >= 2 ? subNumber(toks[1].text) : -1;
      if (detail::insideSelect(*this, head, sub, toks[0].loc)) return;
    }
    if (const Basic *b = basicNamed(head)) {
      basic(*b, toks);
      // A WRT inside COM..COME is the IR's CommonCoil: printed back as written.
      const int32_t n = stmtCount() - next;
      record(next, joined(toks), n > 1 || (n == 1 && prog_.stmts.back().op != b->op),
             toks[0].loc.line);
    } else if (isMarkerName(head)) {
      marker(head, toks);
      record(next, joined(toks), false, toks[0].loc.line);
    } else if (head == "SUB" || detail::isFunctionalName(head)) {
      detail::Functional f;
      f.head = toks[0];
      size_t first = 1;
      if (head == "SUB") {
        if (toks.size() < 2) {
          error(toks[0].loc, "LJ4011", "SUB needs its instruction number (SUB 24)");
          return;
        }
        f.number = toks[1];
        first = 2;
      }
      for (size_t k = first; k < toks.size(); ++k) f.params.push_back(toks[k]);
      pending_ = f;
      pendingComment_ = hasComment ? std::optional<std::string>(comment) : std::nullopt;
      pendingFirst_ = next;
      return;
    } else {
      error(toks[0].loc, "LJ4012", "unknown instruction " + quote(toks[0].text));
      return;
    }
    if (hasComment && static_cast<int32_t>(prog_.stmts.size()) > next)
      prog_.comments.push_back({toks[0].loc.line, next, true, std::string(comment)});
  }

  void flush() {
    if (!pending_) return;
    detail::Functional f = std::move(*pending_);
    pending_.reset();
    detail::emitFunctional(*this, f);
    std::string text(f.head.text);
    if (!f.number.text.empty()) text += " " + std::string(f.number.text);
    for (const Token &t : f.params) text += " " + std::string(t.text);
    record(pendingFirst_, std::move(text), !printsAsWritten(f, pendingFirst_), f.head.loc.line);
    if (pendingComment_ && static_cast<int32_t>(prog_.stmts.size()) > pendingFirst_)
      prog_.comments.push_back({f.head.loc.line, pendingFirst_, true, *pendingComment_});
    pendingComment_.reset();
  }

  /// The words of a line as written, one blank between them.
  static std::string joined(const std::vector<Token> &toks) {
    std::string t;
    for (const Token &k : toks) t += (t.empty() ? "" : " ") + std::string(k.text);
    return t;
  }

  /// Whether the statements from `first` on, of functional instruction `f`, are one statement
  /// the dialect's printer (NetworkText.cpp) gives back as `f` is written: its name (a `SUB n`
  /// by the name of SUB n) and its parameters as written. Otherwise the instruction is
  /// recorded as written (ir/Program.h WrittenInstr): DEC's packed specification, GTB's
  /// swapped operands, CALLU's (ON), CS/CM/CE's branch statements.
  bool printsAsWritten(const detail::Functional &f, int32_t first) const {
    if (stmtCount() - first != 1) return false;
    std::string want(f.head.text);
    if (!f.number.text.empty()) {
      const char *name = detail::functionalName(subNumber(f.number.text));
      if (!name) return false;
      want = name;
    }
    for (const Token &t : f.params) want += " " + std::string(t.text);
    const Stmt &s = prog_.stmts[static_cast<size_t>(first)];
    StmtText t;
    t.op = s.op;
    t.instr = detail::spellStatement(s);
    for (int k = 0; k < s.operandCount; ++k) {
      const Operand &o = s.ops[static_cast<size_t>(k)];
      t.operands.push_back(o.symbol >= 0 && static_cast<size_t>(o.symbol) < prog_.symbols.size()
                               ? prog_.symbols[static_cast<size_t>(o.symbol)].name
                               : formatOperand(o));
      if (implied(s.op, k)) t.implied |= 1u << k;
    }
    std::string out, err;
    return detail::printStatements({&t, 1}, out, err) &&
           detail::upper(out) == detail::upper(want) + "\n";
  }

  /// The statements from `first` on came from the instruction written `text`: recorded as
  /// written when `need`. An instruction with no statement of its own (COME, NOP) goes with
  /// the next one that has statements, which is then recorded as written.
  void record(int32_t first, std::string text, bool need, int32_t line) {
    const int32_t n = stmtCount() - first;
    if (n <= 0) {
      if (pendingWritten_.empty()) pendingLine_ = line;
      pendingWritten_ += (pendingWritten_.empty() ? "" : "\n") + text;
      return;
    }
    int32_t from = 0;
    if (!pendingWritten_.empty()) {
      text = pendingWritten_ + "\n" + text;
      pendingWritten_.clear();
      need = true;
      from = pendingLine_;
    }
    if (need) prog_.written.push_back({first, n, std::move(text), from});
  }

  void finish(int32_t lastLine) {
    flush();
    if (!sawEnd1_)
      error({lastLine, 1}, "LJ4013", "program has no END1 (END1 is required, reference 4.1)");
    else if (!sawEnd2_)
      error({lastLine, 1}, "LJ4014", "program has no END2 (level 2 ends with END2)");
    else if (!afterEnd_)
      error({lastLine, 1}, "LJ4015", "program has no END (the last instruction)");
  }

  // ---- Emitter ----
  // An error at an operand written as a symbol says what the symbol stands for.
  void error(SourceLoc at, const char *code, std::string msg) override {
    if (auto it = symbolAt_.find({at.line, at.col}); it != symbolAt_.end())
      msg += " (symbol " + SymbolTable::quote(it->second->name) + " = " + it->second->address + ")";
    diags_.error(at, code, std::move(msg));
  }

  std::string unknownSymbol(std::string_view name) const {
    auto it = rejected_.find(detail::upper(name));
    return "unknown symbol " + SymbolTable::quote(name) +
           (it == rejected_.end()
                ? std::string()
                : " (its definition on line " + std::to_string(it->second) + " has an error)");
  }

  /// Token `t` as an address (`R100`, `X0.0`; with a symbol table a name stands for its
  /// symbol's address): area and index in range, `bit` -1 or the number after the dot.
  bool address(const Token &t, Operand &out, int64_t &bit) {
    std::string_view s = t.text;
    int16_t symbol = -1;
    if (symbols_ && SymbolTable::isNameShaped(s)) {
      const Symbol *sym = symbols_->find(s);
      if (!sym) {
        error(t.loc, "LJ4016", unknownSymbol(s));
        return false;
      }
      // The table holds canonical addresses: the checks that follow are exactly those of the
      // address written out, and their messages name the symbol (error()).
      s = sym->address;
      symbol = static_cast<int16_t>(sym - symbols_->symbols().data());
    }
    std::string why;
    if (!detail::readAddress(s, true, out, bit, why)) {
      error(t.loc, "LJ4017", why);
      return false;
    }
    out.loc = t.loc;
    out.symbol = symbol;
    return true;
  }

  bool bitOperand(const Token &t, bool writes, Operand &out) override {
    int64_t bit;
    if (!address(t, out, bit)) return false;
    if (tp().area(out.area).bytes == 0) {
      error(t.loc, "LJ4018", "expected a bit address (like R0.0), got " + quote(t.text));
      return false;
    }
    if (bit < 0) {
      error(t.loc, "LJ4019", "expected a bit address (like R0.0), got byte " + quote(t.text));
      return false;
    }
    if (bit > 7) {
      // The digits saturate at 2^40: a longer number is not shown as that value.
      error(t.loc, "LJ4020",
            "bit number " +
                (bit >= (int64_t{1} << 40) ? std::string() : std::to_string(bit) + " ") +
                "out of range in " + quote(t.text) + " (bits 0..7)");
      return false;
    }
    if (writes && !tp().area(out.area).writable) return readOnly(t, out.area);
    out.kind = Operand::Kind::Bit;
    out.bit = static_cast<int8_t>(bit);
    return true;
  }

  bool constant(const Token &t, int64_t lo, int64_t hi, const char *role, int64_t &v) override {
    std::string_view s = t.text;
    size_t pos = 0;
    bool neg = false;
    if (!s.empty() && (s[0] == '-' || s[0] == '+')) {
      neg = s[0] == '-';
      pos = 1;
    }
    size_t start = pos;
    v = 0;
    while (pos < s.size() && isDigit(s[pos]))
      v = std::min<int64_t>(v * 10 + (s[pos++] - '0'), int64_t{1} << 40);
    if (pos == start || pos != s.size()) {
      error(t.loc, "LJ4021", std::string("expected a number as ") + role + ", got " + quote(s));
      return false;
    }
    if (neg) v = -v;
    if (v < lo || v > hi) {
      error(t.loc, "LJ4022",
            std::string(role) + " " + quote(s) + " out of range (" + std::to_string(lo) + ".." +
                std::to_string(hi) + ")");
      return false;
    }
    return true;
  }

  bool dataOperand(const Token &t, int width, bool constOk, bool writes, Operand &out) override {
    std::string_view s = t.text;
    if (!s.empty() && (isDigit(s[0]) || s[0] == '-' || s[0] == '+')) {
      if (!constOk) {
        error(t.loc, "LJ4023", "expected an address, got constant " + quote(s));
        return false;
      }
      const int64_t lo = width == 1 ? -128 : width == 2 ? -32768 : INT32_MIN;
      const int64_t hi = width == 1 ? 255 : width == 2 ? 65535 : INT32_MAX;
      int64_t v;
      if (!constant(t, lo, hi, "constant", v)) return false;
      out = Operand{};
      out.kind = Operand::Kind::Const;
      // The constant as the signed value of its `width` bytes (reference 3.1).
      out.value = width == 1   ? static_cast<int8_t>(v)
                  : width == 2 ? static_cast<int16_t>(v)
                               : static_cast<int32_t>(v);
      out.loc = t.loc;
      return true;
    }
    int64_t bit;
    if (!address(t, out, bit)) return false;
    if (bit >= 0 || tp().area(out.area).bytes == 0) {
      error(t.loc, "LJ4024", "expected a byte address (like D100), got " + quote(s));
      return false;
    }
    if (!tp().validSpan(out.area, out.index, width)) {
      error(t.loc, "LJ4025",
            quote(s) + " as " + std::to_string(width) + " bytes runs past the end of " +
                detail::ranges(out.area));
      return false;
    }
    if (writes && !tp().area(out.area).writable) return readOnly(t, out.area);
    out.kind = Operand::Kind::Reg;
    out.width = static_cast<uint8_t>(width);
    return true;
  }

  bool labelOperand(const Token &t, Area a, Operand &out) override {
    if (symbols_ && SymbolTable::isNameShaped(t.text)) {
      error(t.loc, "LJ4026",
            std::string("expected ") + (a == Area::Label ? "a label (L1)" : "a subroutine (P1)") +
                ", got " + quote(t.text) + ": labels and subroutines are not symbols");
      return false;
    }
    int64_t bit;
    if (!address(t, out, bit) || out.area != a || bit >= 0) {
      if (out.area != a || bit >= 0)
        error(t.loc, "LJ4027",
              std::string("expected ") + (a == Area::Label ? "a label (L1)" : "a subroutine (P1)") +
                  ", got " + quote(t.text));
      return false;
    }
    if (out.index < 1) {
      error(t.loc, "LJ4028", quote(t.text) + ": numbers start at 1");
      return false;
    }
    out.kind = Operand::Kind::Reg;
    return true;
  }

  void emit(Op op, SourceLoc loc, std::initializer_list<Operand> ops) override {
    Stmt s;
    s.op = op;
    s.loc = loc;
    s.operandCount = static_cast<uint8_t>(ops.size());
    size_t k = 0;
    for (const Operand &o : ops) s.ops[k++] = o;
    s.id = static_cast<StmtId>(prog_.stmts.size());
    prog_.stmts.push_back(s);
  }
  int depth() const override { return depth_; }
  void setDepth(int d) override { depth_ = d; }
  int level() const override { return level_; }
  bool claimNumber(char space, int64_t n, SourceLoc at) override {
    auto [it, fresh] = numbers_.emplace(std::make_pair(space, n), at);
    if (!fresh)
      error(at, "LJ4029",
            std::string(space == 'E'                   ? "edge"
                        : space == 'C' || space == 'B' ? "counter"
                                                       : "timer") +
                " number " + std::to_string(n) + " is already used on line " +
                std::to_string(it->second.line));
    return fresh;
  }
  int32_t stmtCount() const override { return static_cast<int32_t>(prog_.stmts.size()); }
  detail::FlowRegions &regions() override { return regions_; }

private:
  /// A written operand `t` in area `a`, which only the machine or the CNC writes: false.
  bool readOnly(const Token &t, Area a) {
    error(t.loc, "LJ4001",
          quote(t.text) + " is read-only (" + tp().area(a).name +
              " is written by the machine or the CNC)");
    return false;
  }

  void basic(const Basic &b, const std::vector<Token> &toks) {
    const bool operand = b.kind != Basic::Block;
    if (toks.size() != (operand ? 2u : 1u)) {
      error(toks[0].loc, "LJ4030",
            std::string(b.name) + (operand ? " takes one bit address" : " takes no operand") +
                ", got " + std::to_string(toks.size() - 1));
      return;
    }
    switch (b.kind) {
    case Basic::Combine:
    case Basic::Write:
      if (depth_ < 1) {
        error(toks[0].loc, "LJ4031",
              std::string(b.name) + " without a logic line (start it with RD)");
        return;
      }
      break;
    case Basic::ReadStk:
      if (depth_ < 1) {
        error(toks[0].loc, "LJ4032", std::string(b.name) + " with no logic line to push (use RD)");
        return;
      }
      if (depth_ >= 8) {
        error(toks[0].loc, "LJ4033",
              std::string(b.name) + " pushes a ninth operation result: the PMC has only ST0..ST7");
        return;
      }
      break;
    case Basic::Block:
      if (depth_ < 2) {
        error(toks[0].loc, "LJ4034",
              std::string(b.name) + " needs two logic lines (ST1 and ST0), found " +
                  std::to_string(depth_));
        return;
      }
      break;
    default:
      break;
    }
    if (operand) {
      Operand o;
      if (!bitOperand(toks[1], b.kind == Basic::Write, o)) return;
      if (b.kind != Basic::Write || !detail::emitCommonCoil(*this, b.op, o, toks[0].loc))
        emit(b.op, toks[0].loc, {o});
    } else {
      emit(b.op, toks[0].loc, {});
    }
    switch (b.kind) {
    case Basic::Read:
      depth_ = 1;
      break;
    case Basic::ReadStk:
      ++depth_;
      break;
    case Basic::Block:
      --depth_;
      break;
    default:
      break;
    }
  }

  void marker(const std::string &head, const std::vector<Token> &toks) {
    const SourceLoc at = toks[0].loc;
    const bool takesOperand = head == "SP";
    if (toks.size() != (takesOperand ? 2u : 1u)) {
      error(at, "LJ4035",
            head + (takesOperand ? " takes one subroutine (SP P1)" : " takes no operand") +
                ", got " + std::to_string(toks.size() - 1));
      return;
    }
    depth_ = 0;
    detail::closeRegions(*this, head, at);
    detail::closeSelect(*this, head, at);
    if (head == "END1") {
      if (sawEnd1_) return error(at, "LJ4036", "duplicate END1");
      sawEnd1_ = true;
      level_ = 2;
      emit(Op::EndCyclic, at, {});
    } else if (head == "END2") {
      if (!sawEnd1_) return error(at, "LJ4037", "END2 before END1");
      if (sawEnd2_) return error(at, "LJ4038", "duplicate END2");
      sawEnd2_ = true;
      level_ = 3;
      level3Start_ = static_cast<int32_t>(prog_.stmts.size());
      emit(Op::EndSliced, at, {});
    } else if (head == "END3") {
      if (!sawEnd2_ || level_ != 3)
        return error(at, "LJ4039", "END3 must follow END2 (level 3 is END2..END3)");
      if (static_cast<int32_t>(prog_.stmts.size()) != level3Start_ + 1)
        return error(at, "LJ4040",
                     "level 3 (END2..END3) is not supported: it must be empty "
                     "(docs/fanuc-pmc.md, [EXT] levels)");
      level_ = 4;
    } else if (head == "END") {
      if (!sawEnd2_) return error(at, "LJ4041", "END before END2");
      if (inSub_) return error(at, "LJ4042", "END inside a subroutine (SP without SPE)");
      afterEnd_ = true;
    } else if (head == "SP") {
      if (!sawEnd2_)
        return error(at, "LJ4043", "SP before END2: subroutines follow END2 (or END3)");
      if (level_ == 3) level_ = 4;
      Operand o;
      if (!labelOperand(toks[1], Area::Subroutine, o)) return;
      inSub_ = true;
      emit(Op::SubBegin, at, {o});
    } else if (head == "SPE") {
      inSub_ = false;
      emit(Op::SubEnd, at, {});
    }
  }

  ParsedProgram &prog_;
  Diagnostics &diags_;
  const SymbolTable *symbols_;
  const std::map<std::string, int32_t> &rejected_;
  /// (line, column) of each operand token written as a symbol name.
  std::map<std::pair<int32_t, int32_t>, const Symbol *> symbolAt_;
  int depth_ = 0, level_ = 1;
  int32_t level3Start_ = -1;
  bool sawEnd1_ = false, sawEnd2_ = false, afterEnd_ = false, inSub_ = false;
  std::optional<detail::Functional> pending_;
  std::optional<std::string> pendingComment_;
  std::string pendingWritten_; ///< instructions without statements so far (record())
  int32_t pendingLine_ = 0;    ///< the line of the first of them
  int32_t pendingFirst_ = 0;
  std::map<std::pair<char, int64_t>, SourceLoc> numbers_;
  detail::FlowRegions regions_;
};

const char *spell(Op op) {
  switch (op) {
  case Op::Load:
    return "RD";
  case Op::LoadNot:
    return "RD.NOT";
  case Op::LoadTrue:
    return "(ON)";
  case Op::And:
    return "AND";
  case Op::AndNot:
    return "AND.NOT";
  case Op::Or:
    return "OR";
  case Op::OrNot:
    return "OR.NOT";
  case Op::AndBlock:
    return "AND.STK";
  case Op::OrBlock:
    return "OR.STK";
  case Op::Coil:
    return "WRT";
  case Op::CoilNot:
    return "WRT.NOT";
  case Op::Set:
    return "SET";
  case Op::Reset:
    return "RST";
  case Op::EndInit:
    return "(INIT)";
  case Op::EndCyclic:
    return "END1";
  case Op::EndSliced:
    return "END2";
  case Op::Jump:
    return "JMPB";
  case Op::JumpOut:
    return "JMPC";
  case Op::Label:
    return "LBL";
  case Op::Call:
    return "CALL";
  case Op::SubBegin:
    return "SP";
  case Op::SubEnd:
    return "SPE";
  case Op::Move:
    return "MOVB/MOVW/MOVD/MOVN/NUMEB";
  case Op::BitAnd:
    return "AND(SUB60)/MOVE";
  case Op::BitOr:
    return "OR(SUB61)/MOVOR";
  case Op::BitXor:
    return "EOR/NOT";
  case Op::CompareEq:
    return "EQB/EQW/EQD";
  case Op::CompareLt:
    return "LTx/GTx";
  case Op::CompareLe:
    return "LEx/GEx";
  case Op::OnDelayTimer:
    return "TMRB";
  case Op::OffDelayTimer:
    return "TMRBF";
  case Op::RisePulse:
    return "DIFU";
  case Op::FallPulse:
    return "DIFD";
  case Op::PmcTimer: // fanuc-a: frontends/fanuc/TimerCounter.cpp
    return "TMR";
  case Op::PmcTimerAddr:
    return "TMRC";
  case Op::PmcCounter:
    return "CTR/CTRB/CTRC";
  case Op::PmcCompareFlags:
    return "COMPB";
  case Op::BcdCompare:
    return "COMP/COIN";
  case Op::CompareNe:
    return "NEB/NEW/NED";
  case Op::CompareBetween:
    return "RNGB/RNGW/RNGD";
  case Op::BinaryArith: // fanuc-c: frontends/fanuc/ArithFunctional.cpp
  case Op::BcdArith:
  case Op::BcdConstant:
    return detail::spellArith(op);
  default:
    return detail::spellData(op); // nullptr: not spelled in this dialect (fanuc-b ops spelled)
  }
}

} // namespace

std::string formatOperand(const Operand &op) { return frontend::operandText(tp(), op); }

// TMRB and TMRBF have two parameters, the timer number and the set time in ms (ref 6.3: "[SUB24
// TMRB | timer number | set time (ms)]", SUB77 alike); the IR's time-unit operand between them is
// implied (Functional.cpp emits 0 = ms).
// A counter's data-type operand (CTR: the system parameter, CTRB/CTRC: binary) is implied too.
bool implied(Op op, int k) {
  return ((op == Op::OnDelayTimer || op == Op::OffDelayTimer) && k == 1) ||
         (op == Op::PmcCounter && k == 2);
}

namespace detail { // NetworkText.cpp: how a statement is drawn
bool drawStatements(std::span<const Stmt> stmts, size_t i, DrawnInstr &out);
} // namespace detail

/// `SUB n ...` as a FANUC ladder names the box: by the name of SUB n (reference 6, the SUB
/// number table), unless the name is a basic instruction's (SUB 60 AND, SUB 61 OR), which the
/// text form must keep apart from the bit logic and the drawing keeps as written.
std::string drawWritten(std::string_view written) {
  const std::vector<frontend::Word> w = written.find('\n') == std::string_view::npos
                                            ? wordsOf(written)
                                            : std::vector<frontend::Word>{};
  if (w.size() < 2 || detail::upper(std::string(w[0].text)) != "SUB") return std::string(written);
  const char *name = detail::functionalName(subNumber(w[1].text));
  if (!name || basicNamed(name) || isMarkerName(name)) return std::string(written);
  std::string out = name;
  for (size_t k = 2; k < w.size(); ++k) out += " " + std::string(w[k].text);
  return out;
}

/// COME and NOP make no statement (reference 6.1): a FANUC ladder draws them between the rungs.
bool markerLine(std::string_view line) {
  const std::vector<frontend::Word> w = wordsOf(line);
  if (w.empty()) return false;
  const std::string head = detail::upper(std::string(w[0].text));
  return head == "COME" || head == "NOP";
}

const DialectText &dialectText() {
  static constexpr DialectText kText{"fanuc",
                                     &spell,
                                     &formatOperand,
                                     &implied,
                                     &detail::spellStatement,
                                     &detail::lookupWord,
                                     &detail::printStatements,
                                     &symbolRules,
                                     &detail::drawStatements,
                                     nullptr,
                                     nullptr,
                                     &drawWritten,
                                     &markerLine};
  return kText;
}

ParsedProgram parsePmc(std::string_view text, std::string file, Diagnostics &diags) {
  return parsePmc(text, std::move(file), diags, nullptr);
}

ParsedProgram parsePmc(std::string_view text, std::string file, Diagnostics &diags,
                       const SymbolTable *symbols) {
  ParsedProgram prog;
  prog.file = std::move(file);
  prog.dialect = &dialectText();
  prog.profile = &profile();
  if (text.size() >= 3 && text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  SymbolTable table(symbolRules());
  const detail::PmcSource src = detail::readPmcSource(text, symbols, table, diags);
  if (!src.hasLadder) return prog;
  if (src.hasTable) prog.symbols = table.symbols();
  Parser p(prog, diags, src.hasTable ? &table : nullptr, src.rejected);
  std::vector<Token> toks;
  std::string_view comment;
  bool hasComment = false;
  int32_t line = src.firstLine - 1;
  size_t pos = 0;
  text = src.ladder;
  while (pos < text.size()) {
    size_t nl = text.find('\n', pos);
    if (nl == std::string_view::npos) nl = text.size();
    if (line < INT32_MAX) ++line;
    tokenize(text.substr(pos, nl - pos), line, toks, comment, hasComment);
    pos = nl + 1;
    if (toks.empty()) {
      if (hasComment)
        prog.comments.push_back(
            {line, static_cast<int32_t>(prog.stmts.size()), false, std::string(comment)});
      continue;
    }
    p.line(toks, hasComment, comment);
    if (diags.errorCount() >= 100) {
      diags.error({line, 1}, "LJ4044", "too many errors (100); the rest is not checked");
      break;
    }
    if (prog.stmts.size() > static_cast<size_t>(profile().maxStatements)) {
      diags.error({line, 1}, "LJ4045",
                  "program has more than " + std::to_string(profile().maxStatements) +
                      " statements");
      break;
    }
  }
  p.finish(std::max(line, 1));
  return prog;
}

} // namespace lj::fanuc

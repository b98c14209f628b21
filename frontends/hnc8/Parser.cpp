// Lexer and parser for STL text (DIALECT.md 2, docs/dialect-notes.md "Text"): one statement per
// line, every operand (or the symbol standing for one) checked against the instruction table;
// bad lines become located diagnostics and are dropped, parsing always continues.
#include "frontends/common/LineTokens.h"
#include "frontends/hnc8/Address.h"
#include "frontends/hnc8/FrontEnd.h"
#include "frontends/hnc8/Mnemonics.h"
#include "profiles/hnc8/Hnc8Profile.h"

#include <algorithm>
#include <climits>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace lj {

namespace {

using hnc8::kSaturated;
using hnc8::readDecimal;

bool isDigit(char c) { return c >= '0' && c <= '9'; }
bool isLetter(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z'); }

int hexValue(char c) {
  if (isDigit(c)) return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

/// The token as it may appear in a message (40 bytes at most).
std::string quote(std::string_view t) { return quoteToken(t, 40); }

/// A line that starts with no known mnemonic: one check wherever the parser meets it.
void unknownMnemonic(Diagnostics &diags, SourceLoc at, std::string_view t) {
  diags.error(at, "LJ3001", "unknown mnemonic " + quote(t));
}

/// "Y, G, R, W, D or B" for the areas of a mask.
std::string areaList(AreaMask m) {
  std::string out;
  int n = 0, total = 0;
  auto has = [&](int a) {
    return hasArea(m, static_cast<Area>(a)) && hnc8::profile().area(static_cast<Area>(a)).count > 0;
  };
  for (int a = 0; a < kAreaCount; ++a) total += has(a) ? 1 : 0;
  for (int a = 0; a < kAreaCount; ++a) {
    if (!has(a)) continue;
    if (n > 0) out += (n == total - 1) ? " or " : ", ";
    out += hnc8::profile().area(static_cast<Area>(a)).name;
    ++n;
  }
  return out;
}

/// "X0..X512", or the two ranges of T/C.
std::string indexRange(Area a) {
  std::string l(hnc8::profile().area(a).name);
  if (a == Area::Timer || a == Area::Counter)
    return l + "0.." + l + "127, " + l + "300.." + l + "427";
  return l + "0.." + l + std::to_string(hnc8::profile().area(a).count - 1);
}

/// Syntactic shape of one operand token, before it is checked against an OperandSpec.
struct RawOperand {
  enum class Shape : uint8_t { Const, Addr } shape = Shape::Const;
  int64_t value = 0; // Const
  Area area = Area::None;
  int64_t index = 0;
  int64_t bit = -1; // -1: no bit number
};

using Token = frontend::Word;

/// Parses the statements of one line; reports every problem it finds on that line.
class LineParser {
public:
  LineParser(Diagnostics &diags, int32_t line, const SymbolTable *symbols)
      : diags_(diags), line_(line), symbols_(symbols) {}

  /// Returns true and fills `stmt` when the line holds one valid statement.
  bool parse(const std::vector<Token> &toks, Stmt &stmt) {
    Op op;
    if (!hnc8::lookupMnemonic(toks[0].text, op)) {
      unknownMnemonic(diags_, {line_, toks[0].col}, toks[0].text);
      return false;
    }
    const InstrInfo &info = instrInfo(op);
    stmt.op = op;
    stmt.loc = {line_, toks[0].col};
    size_t given = toks.size() - 1;
    if (given != info.operandCount) {
      countError(info, toks, given);
      return false;
    }
    bool ok = true;
    stmt.operandCount = info.operandCount;
    for (size_t i = 0; i < given; ++i)
      ok = operand(info, info.operands[i], toks[i + 1], stmt.ops[i]) && ok;
    return ok;
  }

private:
  // While an operand written as a symbol is checked, every message says what it stands for.
  void error(const Token &t, const char *code, std::string msg) {
    if (symbol_)
      msg += " (symbol " + SymbolTable::quote(symbol_->name) + " = " + symbol_->address + ")";
    diags_.error({line_, t.col}, code, std::move(msg));
  }

  void countError(const InstrInfo &info, const std::vector<Token> &toks, size_t given) {
    std::string want;
    if (info.operandCount == 0) {
      want = std::string(hnc8::mnemonicOf(info.op)) + " takes no operands";
    } else {
      want = std::string(hnc8::mnemonicOf(info.op)) + " takes " +
             std::to_string(info.operandCount) +
             (info.operandCount == 1 ? " operand (" : " operands (");
      for (int i = 0; i < info.operandCount; ++i)
        want += std::string(i ? ", " : "") + info.operands[i].role;
      want += ")";
    }
    want += ", got " + std::to_string(given);
    // Too many: point at the first extra operand; too few: at the mnemonic.
    const Token &at = given > info.operandCount ? toks[info.operandCount + 1] : toks[0];
    error(at, "LJ3003", want);
  }

  bool lex(const Token &t, RawOperand &raw) {
    std::string_view s = t.text;
    symbol_ = nullptr;
    symbolIndex_ = -1;
    if (symbols_ && SymbolTable::isNameShaped(s)) {
      const Symbol *sym = symbols_->find(s);
      if (!sym) {
        error(t, "LJ3004", "unknown symbol " + SymbolTable::quote(s));
        return false;
      }
      symbol_ = sym;
      symbolIndex_ = static_cast<int16_t>(sym - symbols_->symbols().data());
      // The table holds canonical addresses, so this lexes; the checks that follow are exactly
      // those of the address written out.
      return lexAddress({sym->address, t.col}, raw);
    }
    if (isLetter(s[0])) return lexAddress(t, raw);
    if (isDigit(s[0]) || s[0] == '+' || s[0] == '-') return lexConstant(t, raw);
    error(t, "LJ3005", "malformed operand " + quote(s));
    return false;
  }

  bool lexAddress(const Token &t, RawOperand &raw) {
    std::string_view s = t.text;
    const hnc8::AddressText a = hnc8::lexAddress(s);
    if (a.lex == hnc8::AddressText::Lex::NoArea) {
      error(t, "LJ3006", "unknown area letter " + quote(s.substr(0, 1)) + " in " + quote(s));
      return false;
    }
    if (a.lex != hnc8::AddressText::Lex::Ok) {
      error(t, "LJ3007", "malformed address " + quote(s));
      return false;
    }
    raw.shape = RawOperand::Shape::Addr;
    raw.area = a.area;
    raw.index = a.index;
    raw.bit = a.bit;
    return true;
  }

  bool lexConstant(const Token &t, RawOperand &raw) {
    std::string_view s = t.text;
    raw.shape = RawOperand::Shape::Const;
    auto malformed = [&] {
      error(t, "LJ3002", "malformed constant " + quote(s));
      return false;
    };
    if (s.size() > 2 && s[0] == '0' && (s[1] == 'x' || s[1] == 'X')) {
      // Hex is a 32-bit pattern: 0xFFFFFFFF is -1 (dialect-notes "Text").
      uint64_t v = 0;
      int digits = 0;
      for (size_t i = 2; i < s.size(); ++i) {
        int h = hexValue(s[i]);
        if (h < 0) return malformed();
        if (v != 0 || h != 0) ++digits;
        v = (v << 4 | static_cast<uint64_t>(h)) & 0xFFFFFFFFFull;
      }
      if (digits > 8) {
        error(t, "LJ3008", "hex constant " + quote(s) + " has more than 32 bits");
        return false;
      }
      raw.value = static_cast<int32_t>(static_cast<uint32_t>(v));
      return true;
    }
    size_t pos = 0;
    bool neg = false;
    if (s[0] == '+' || s[0] == '-') {
      neg = s[0] == '-';
      pos = 1;
    }
    int64_t mag = 0;
    if (!readDecimal(s, pos, mag) || pos != s.size()) return malformed();
    int64_t v = neg ? -mag : mag;
    if (v < INT32_MIN || v > INT32_MAX) {
      error(t, "LJ3009", "constant " + quote(s) + " is outside the int32 range");
      return false;
    }
    raw.value = v;
    return true;
  }

  static std::string addrText(const RawOperand &r) {
    std::string s(hnc8::profile().area(r.area).name);
    s += std::to_string(r.index);
    if (r.bit >= 0) {
      s += '.'; // appended separately: GCC 12 -O3 warns (-Wrestrict) on "." + std::string
      s += std::to_string(r.bit);
    }
    return s;
  }

  /// Area allowed and writable where needed; reports and returns false otherwise.
  bool checkArea(const InstrInfo &info, const OperandSpec &spec, const Token &t,
                 const RawOperand &r) {
    if (spec.writes && !hnc8::profile().area(r.area).writable) {
      error(t, "LJ3010",
            addrText(r) + " is read-only; " + hnc8::mnemonicOf(info.op) + " cannot write its " +
                spec.role + " (writable: " + areaList(spec.areas) + ")");
      return false;
    }
    if (!hasArea(spec.areas, r.area)) {
      error(t, "LJ3011",
            std::string("area ") + hnc8::profile().area(r.area).name + " is not allowed as " +
                spec.role + " of " + hnc8::mnemonicOf(info.op) +
                " (allowed: " + areaList(spec.areas) + ")");
      return false;
    }
    if (!hnc8::profile().validIndex(r.area, r.index)) {
      error(t, "LJ3012", "address " + quote(t.text) + " out of range (" + indexRange(r.area) + ")");
      return false;
    }
    return true;
  }

  bool operand(const InstrInfo &info, const OperandSpec &spec, const Token &t, Operand &out) {
    RawOperand r;
    if (!lex(t, r)) return false;
    out.loc = {line_, t.col};
    out.symbol = symbolIndex_;
    std::string what = std::string(hnc8::mnemonicOf(info.op)) + " expects ";
    bool isConst = r.shape == RawOperand::Shape::Const;
    if (spec.isBit && spec.wordOk && !isConst && r.bit < 0) {
      // Word form of a bit-or-word position (ZRST): a whole register.
      if (!checkArea(info, spec, t, r)) return false;
      out.kind = Operand::Kind::Reg;
      out.area = r.area;
      out.index = static_cast<int32_t>(r.index);
      return true;
    }
    if (spec.isBit) {
      if (isConst || r.bit < 0) {
        error(t, "LJ3013",
              what + "a bit address (like X1.0) as " + spec.role + ", got " +
                  (isConst ? "constant " : "register ") + quote(t.text));
        return false;
      }
      if (!checkArea(info, spec, t, r)) return false;
      if (r.bit >= hnc8::profile().bitWidth(r.area)) {
        std::string l(hnc8::profile().area(r.area).name);
        error(t, "LJ3014",
              // A saturated number (more digits than any index) is not shown as 2^40.
              "bit number " + (r.bit >= kSaturated ? std::string() : std::to_string(r.bit) + " ") +
                  "out of range in " + quote(t.text) + " (" + l +
                  (hnc8::profile().bitWidth(r.area) == 1
                       ? std::string(" has only bit .0")
                       : " has bits 0.." + std::to_string(hnc8::profile().bitWidth(r.area) - 1)) +
                  ")");
        return false;
      }
      out.kind = Operand::Kind::Bit;
      out.area = r.area;
      out.index = static_cast<int32_t>(r.index);
      out.bit = static_cast<int8_t>(r.bit);
      return true;
    }
    const char *accepts = spec.areas == 0 ? "a constant"
                          : spec.constOk  ? "a register or constant"
                                          : "a register";
    if (hasArea(spec.areas, Area::Label)) accepts = "a label (L0..L9999)";
    if (hasArea(spec.areas, Area::Subroutine)) accepts = "a subroutine (S0..S511)";
    if (isConst) {
      if (!spec.constOk) {
        error(t, "LJ3015", what + accepts + " as " + spec.role + ", got constant " + quote(t.text));
        return false;
      }
      if (r.value < spec.cmin || r.value > spec.cmax) {
        error(t, "LJ3016",
              "constant " + quote(t.text) + " out of range for " + spec.role + " of " +
                  hnc8::mnemonicOf(info.op) + " (" + std::to_string(spec.cmin) + ".." +
                  std::to_string(spec.cmax) + ")");
        return false;
      }
      out.kind = Operand::Kind::Const;
      out.value = static_cast<int32_t>(r.value);
      return true;
    }
    if (r.bit >= 0 || spec.areas == 0) {
      error(t, "LJ3017",
            what + accepts + " as " + spec.role + ", got " +
                (r.bit >= 0 ? "bit address " : "register ") + quote(t.text));
      return false;
    }
    if (!checkArea(info, spec, t, r)) return false;
    out.kind = Operand::Kind::Reg;
    out.area = r.area;
    out.index = static_cast<int32_t>(r.index);
    return true;
  }

  Diagnostics &diags_;
  int32_t line_;
  const SymbolTable *symbols_;
  const Symbol *symbol_ = nullptr; ///< the symbol of the operand being checked, if any
  int16_t symbolIndex_ = -1;       ///< its position in the table
};

} // namespace

/// A statement with a constant written other than in decimal (`WAND R0 0xE0 R0`) is recorded
/// as written (ir/Program.h WrittenInstr), so drawings show `0xE0` where the IR holds 224.
static void recordIfRadix(ParsedProgram &prog, const std::vector<Token> &toks, const Stmt &s) {
  if (toks.size() != static_cast<size_t>(s.operandCount) + 1) return;
  bool other = false;
  for (int k = 0; k < s.operandCount && !other; ++k) {
    const Operand &o = s.ops[static_cast<size_t>(k)];
    other = o.kind == Operand::Kind::Const && o.symbol < 0 &&
            toks[static_cast<size_t>(k) + 1].text != std::to_string(o.value);
  }
  if (!other) return;
  std::string text(toks[0].text);
  for (size_t k = 1; k < toks.size(); ++k) text += " " + std::string(toks[k].text);
  prog.written.push_back({s.id, 1, std::move(text)});
}

ParsedProgram parseStl(std::string_view text, std::string file, Diagnostics &diags) {
  return parseStl(text, std::move(file), diags, nullptr);
}

ParsedProgram parseStl(std::string_view text, std::string file, Diagnostics &diags,
                       const SymbolTable *symbols, int32_t maxStatements) {
  // Bounds (issue 11 item 4): parsing stops at the statement limit, after kMaxErrors errors,
  // and after kNotStlLines lines that start with no mnemonic before any that does, so a file
  // that is not a program costs little and its lines are not echoed back one by one.
  constexpr int kMaxErrors = 100;
  constexpr int kNotStlLines = 3;
  ParsedProgram prog;
  prog.file = std::move(file);
  prog.dialect = &hnc8::dialectText();
  prog.profile = &hnc8::profile();
  // A UTF-8 byte-order mark from a Windows editor is not part of the first statement.
  if (text.size() >= 3 && text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  if (symbols) prog.symbols = symbols->symbols();
  std::vector<Token> toks;
  std::string_view comment;
  bool hasComment = false;
  int32_t line = 0;
  size_t pos = 0;
  std::vector<std::pair<int32_t, Token>> leading; // lines before the first mnemonic
  bool sawMnemonic = false;
  const size_t limit = static_cast<size_t>(std::max(maxStatements, 0));
  while (pos < text.size()) {
    size_t nl = text.find('\n', pos);
    if (nl == std::string_view::npos) nl = text.size();
    if (line < INT32_MAX) ++line;
    frontend::splitLine(text.substr(pos, nl - pos), toks, comment, hasComment);
    pos = nl + 1;
    auto next = static_cast<int32_t>(prog.stmts.size());
    if (toks.empty()) {
      if (hasComment) prog.comments.push_back({line, next, false, std::string(comment)});
      continue;
    }
    Op known;
    bool mnemonic = hnc8::lookupMnemonic(toks[0].text, known);
    if (!sawMnemonic && !mnemonic) {
      // Held back until a line starts with a mnemonic: a file that is no program at all gets
      // one error, and none of its lines is echoed.
      leading.push_back({line, toks[0]});
      if (static_cast<int>(leading.size()) < kNotStlLines) continue;
      diags.error({leading[0].first, 1}, "LJ3018",
                  "not an STL program: none of its first " + std::to_string(kNotStlLines) +
                      " lines starts with an instruction; the rest is not read");
      leading.clear();
      break;
    }
    if (!sawMnemonic) {
      sawMnemonic = true;
      for (const auto &[l, t] : leading) unknownMnemonic(diags, {l, t.col}, t.text);
      leading.clear();
    }
    Stmt stmt;
    LineParser lp(diags, line, symbols);
    if (lp.parse(toks, stmt)) {
      stmt.id = next;
      prog.stmts.push_back(stmt);
      recordIfRadix(prog, toks, stmt);
      if (hasComment) prog.comments.push_back({line, next, true, std::string(comment)});
    } else if (mnemonic)
      prog.dropped.push_back({static_cast<int32_t>(prog.stmts.size()), known});
    if (prog.stmts.size() > limit) {
      // Stop building statements here (memory stays bounded), but count the rest so the
      // message says how large the program is, as the verifier's limit check does.
      size_t total = prog.stmts.size();
      while (pos < text.size()) {
        size_t end = text.find('\n', pos);
        if (end == std::string_view::npos) end = text.size();
        frontend::splitLine(text.substr(pos, end - pos), toks, comment, hasComment);
        pos = end + 1;
        Op op;
        if (!toks.empty() && hnc8::lookupMnemonic(toks[0].text, op)) ++total;
      }
      diags.error(prog.stmts.back().loc, "LJ3019",
                  "program has " + std::to_string(total) + " statements, more than the limit of " +
                      std::to_string(limit));
      break;
    }
    if (diags.errorCount() >= kMaxErrors) {
      diags.error({line, 1}, "LJ3020",
                  "too many errors (" + std::to_string(kMaxErrors) + "); the rest is not checked");
      break;
    }
  }
  for (const auto &[l, t] : leading) unknownMnemonic(diags, {l, t.col}, t.text);
  return prog;
}

} // namespace lj

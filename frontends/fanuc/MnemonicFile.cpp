// FANUC LADDER-III mnemonic files (B-66234EN 6.7; docs/fanuc-pmc.md "Symbols and comments"):
// sections opened by identification codes (%@3 the ladder, %@2-E symbols and comments as CSV,
// optionally inside %@A .. %@E), each closed by a line holding only `%`; and the FANUC rules of
// the symbol table the parser resolves operand names with. A text whose first line is not a
// section line is a plain mnemonic program, read whole as before.
#include "frontends/fanuc/FrontEnd.h"
#include "frontends/fanuc/ParserInternal.h"
#include "profiles/fanuc/FanucProfile.h"

#include <array>
#include <utility>

namespace lj::fanuc {

namespace {

bool isBlank(char c) { return c == ' ' || c == '\t'; }

std::string_view trim(std::string_view s) {
  while (!s.empty() && isBlank(s.front())) s.remove_prefix(1);
  while (!s.empty() && isBlank(s.back())) s.remove_suffix(1);
  return s;
}

/// The symbol table's address check: a FANUC bit or byte address in its area's ranges, bit
/// 0..7, as canonical text (`f0000.0` -> `F0.0`, the way formatOperand writes operands).
std::string canonicalAddress(std::string_view text, std::string &error) {
  Operand op;
  int64_t bit = -1;
  if (!detail::readAddress(text, false, op, bit, error)) return {};
  const std::string shown = SymbolTable::quote(text);
  if (profile().area(op.area).bytes == 0) {
    error = shown + " is a " + (op.area == Area::Label ? "label" : "subroutine") +
            ": a symbol names a bit or byte address (labels and subroutines are not symbols)";
    return {};
  }
  if (bit > 7) {
    error = "bit number " +
            (bit >= (int64_t{1} << 40) ? std::string() : std::to_string(bit) + " ") +
            "out of range in " + shown + " (bits 0..7)"; // the digits saturate at 2^40
    return {};
  }
  op.kind = bit >= 0 ? Operand::Kind::Bit : Operand::Kind::Reg;
  op.bit = static_cast<int8_t>(bit);
  return formatOperand(op);
}

/// One field of a CSV row: its text, blanks around it dropped, and the file column where it
/// starts. FANUC's CSV has no quoting: a comma always separates fields.
struct CsvField {
  std::string_view text;
  int32_t col = 1;
};

void splitCsv(std::string_view line, std::vector<CsvField> &out) {
  out.clear();
  size_t i = 0;
  while (true) {
    size_t end = line.find(',', i);
    if (end == std::string_view::npos) end = line.size();
    const std::string_view f = trim(line.substr(i, end - i));
    out.push_back({f, static_cast<int32_t>((f.empty() ? i : f.data() - line.data()) + 1)});
    if (end >= line.size()) return;
    i = end + 1;
  }
}

/// The columns of a %@2-E section (0: absent).
struct Columns {
  std::array<int, 4> col{1, 2, 3, 4}; ///< SYM, ADR, CM1, CM2
};
constexpr const char *kKeys[] = {"SYM", "ADR", "CM1", "CM2"};
constexpr int kMaxColumn = 99;

/// What a section's identification code (`4`, `2-C`) holds (B-66234EN table 6.7), for the
/// "not read" warning.
std::string sectionContents(const std::string &id) {
  static constexpr const char *kSymbols = "; ladderjit reads symbols from a %@2-E (CSV) section";
  static constexpr std::pair<const char *, const char *> kKnown[] = {
      {"0", "system parameters"},
      {"1", "title data"},
      {"2", "symbol and comment data, FORMAT-A/B"},
      {"2-C", "symbol and comment data, FORMAT-C"},
      {"2-C2", "symbol and comment data, multiple comments"},
      {"2-D", "symbol and comment data, variable symbols"},
      {"3-D", "ladder with variable symbols"},
      {"4", "message data"},
      {"5", "I/O module data"},
  };
  for (const auto &[code, what] : kKnown)
    if (id == code) return std::string(" (") + what + (id[0] == '2' ? kSymbols : "") + ")";
  return "";
}

/// Reads the sections of a mnemonic file: remembers where the ladder is, adds the symbols of
/// each %@2-E section to the table, reports everything else that is wrong with a location.
class SectionReader {
public:
  SectionReader(std::string_view text, SymbolTable &table, std::vector<int32_t> &defined,
                Diagnostics &diags, detail::PmcSource &src)
      : text_(text), table_(table), defined_(defined), diags_(diags), src_(src) {}

  void read() {
    size_t pos = 0;
    int32_t line = 0;
    bool first = true; // no content line yet
    while (pos < text_.size()) {
      size_t nl = text_.find('\n', pos);
      if (nl == std::string_view::npos) nl = text_.size();
      if (line < INT32_MAX) ++line;
      std::string_view raw = text_.substr(pos, nl - pos);
      if (!raw.empty() && raw.back() == '\r') raw.remove_suffix(1);
      const std::string_view t = trim(raw);
      const auto col = static_cast<int32_t>(t.empty() ? 1 : t.data() - raw.data() + 1);
      if (!t.empty() && t[0] == '%') {
        sectionLine(t, line, col, pos, nl, first);
      } else if (in_ == In::Symbols) {
        row(raw, line);
      } else if (in_ == In::Outside || in_ == In::AfterEnd) {
        if (!t.empty() && t[0] != ';' && t.substr(0, 2) != "//" && !reported_) {
          reported_ = true;
          if (in_ == In::AfterEnd)
            afterEnd(line, col);
          else
            diags_.error({line, col}, "LJ4004",
                         "text outside a section: " + SymbolTable::quote(t) +
                             " (mnemonic lines belong in a %@3 section, symbols in a %@2-E "
                             "section)");
        }
      }
      if (!t.empty() && t[0] != ';' && t.substr(0, 2) != "//") first = false;
      lastLine_ = line;
      pos = nl + 1;
    }
    if (in_ != In::Outside && in_ != In::AfterEnd) {
      diags_.error({openLine_, 1}, "LJ4083",
                   "section " + openName_ +
                       " is not closed: the file ends inside it (a line holding "
                       "only '%' ends a section)");
      close(text_.size());
    }
    if (allLine_ > 0 && in_ != In::AfterEnd)
      diags_.error({std::max(lastLine_, 1), 1}, "LJ4084",
                   "%@A (line " + std::to_string(allLine_) +
                       ") without %@E at the end of the file");
    if (ladderLine_ == 0)
      diags_.error({1, 1}, "LJ4085",
                   "this mnemonic file has no ladder section (%@3 holds the mnemonic "
                   "lines, docs/fanuc-pmc.md)");
    src_.hasLadder = ladderLine_ > 0;
  }

private:
  enum class In : uint8_t { Outside, Ladder, Symbols, Skipped, AfterEnd };

  void sectionLine(std::string_view t, int32_t line, int32_t col, size_t lineStart, size_t lineEnd,
                   bool first) {
    reported_ = false;
    if (t == "%") {
      if (in_ == In::Outside || in_ == In::AfterEnd)
        diags_.error({line, col}, "LJ4086",
                     "'%' closes no section (it ends the section a %@ line opens)");
      else
        close(lineStart);
      return;
    }
    if (t.size() < 3 || t[1] != '@') {
      diags_.error({line, col}, "LJ4087",
                   "bad section line " + SymbolTable::quote(t) +
                       ": a section starts with %@ and its code (%@3, %@2-E), a "
                       "line holding only '%' ends it");
      return;
    }
    std::string_view code = t.substr(2);
    const size_t paren = code.find('(');
    const std::string id = detail::upper(trim(code.substr(0, paren)));
    const std::string name = "%@" + std::string(trim(code.substr(0, paren)));
    if (id == "A") {
      if (!first || allLine_ > 0)
        diags_.error({line, col}, "LJ4088",
                     "%@A must be the first line of the file (it opens ALL-format "
                     "data)");
      else
        allLine_ = line;
      return;
    }
    if (in_ == In::AfterEnd) {
      if (!reported_) afterEnd(line, col);
      reported_ = true;
      return;
    }
    // A new section header also ends the open one (the ALL-format sections follow each other).
    if (in_ != In::Outside) close(lineStart);
    if (id == "E") {
      if (allLine_ == 0)
        diags_.error({line, col}, "LJ4089",
                     "%@E without %@A (%@E ends ALL-format data that %@A starts)");
      in_ = In::AfterEnd;
      return;
    }
    openLine_ = line;
    openName_ = name;
    if (id == "3") {
      if (ladderLine_ > 0) {
        diags_.error({line, col}, "LJ4090",
                     "a second ladder section %@3 (the first is on line " +
                         std::to_string(ladderLine_) + ")");
        in_ = In::Skipped;
        return;
      }
      ladderLine_ = line;
      ladderBegin_ = std::min(lineEnd + 1, text_.size());
      in_ = In::Ladder;
    } else if (id == "2-E") {
      in_ = option(paren == std::string_view::npos ? std::string_view() : code.substr(paren), line,
                   col + 2 + static_cast<int32_t>(paren))
                ? In::Symbols
                : In::Skipped;
      nameless_ = 0;
    } else {
      diags_.warning({line, col}, "LJ4091",
                     "section " + name + sectionContents(id) + " is not read by ladderjit");
      in_ = In::Skipped;
    }
  }

  /// The section open before the line starting at byte `lineStart` ends there.
  void close(size_t lineStart) {
    if (in_ == In::Ladder) {
      src_.ladder = text_.substr(ladderBegin_, std::max(lineStart, ladderBegin_) - ladderBegin_);
      src_.firstLine = ladderLine_ + 1;
    }
    if (in_ == In::Symbols && nameless_ > 0)
      diags_.warning(namelessAt_, "LJ4092",
                     std::to_string(nameless_) + " row" + (nameless_ == 1 ? "" : "s") +
                         " of section " + openName_ +
                         " give an address no symbol name: ladderjit keeps only named symbols, "
                         "their comments are not shown");
    in_ = In::Outside;
  }

  /// The option of a %@2-E header, `(SYM=1 ADR=2 CM1=3 CM2=4)` starting at column `col` (empty:
  /// those defaults). False (with an error) when it cannot be read.
  bool option(std::string_view opt, int32_t line, int32_t col) {
    cols_ = Columns{};
    if (opt.empty()) return true;
    const size_t close = opt.find(')');
    if (close == std::string_view::npos) {
      diags_.error({line, col}, "LJ4093", "the %@2-E option has no closing ')'");
      return false;
    }
    if (const std::string_view after = trim(opt.substr(close + 1)); !after.empty()) {
      diags_.error({line, col + static_cast<int32_t>(after.data() - opt.data())}, "LJ4094",
                   "text after the %@2-E option: " + SymbolTable::quote(after));
      return false;
    }
    cols_.col = {0, 0, 0, 0};
    size_t i = 1;
    while (i < close) {
      if (isBlank(opt[i]) || opt[i] == ',') {
        ++i;
        continue;
      }
      size_t end = i;
      while (end < close && !isBlank(opt[end]) && opt[end] != ',') ++end;
      const std::string_view item = opt.substr(i, end - i);
      const int32_t at = col + static_cast<int32_t>(i);
      i = end;
      const size_t eq = item.find('=');
      if (eq == std::string_view::npos) {
        diags_.error({line, at}, "LJ4095",
                     "expected KEY=COLUMN in the %@2-E option, got " + SymbolTable::quote(item));
        return false;
      }
      const std::string key = detail::upper(item.substr(0, eq));
      int k = 0;
      while (k < 4 && key != kKeys[k]) ++k;
      if (k == 4) {
        diags_.error({line, at}, "LJ4096",
                     "unknown key " + SymbolTable::quote(item.substr(0, eq)) +
                         " in the %@2-E option (keys: SYM ADR CM1 CM2)");
        return false;
      }
      const std::string_view num = item.substr(eq + 1);
      int n = 0;
      bool ok = !num.empty() && num.size() <= 2; // at most 2 digits: n cannot overflow
      for (size_t d = 0; ok && d < num.size(); ++d) {
        ok = num[d] >= '0' && num[d] <= '9';
        n = n * 10 + (num[d] - '0');
      }
      if (!ok || n < 1 || n > kMaxColumn) {
        diags_.error({line, at + static_cast<int32_t>(eq) + 1}, "LJ4097",
                     "bad column number " + SymbolTable::quote(num) + " for " + kKeys[k] + " (1.." +
                         std::to_string(kMaxColumn) + ")");
        return false;
      }
      if (cols_.col[static_cast<size_t>(k)] != 0) {
        diags_.error({line, at}, "LJ4098",
                     std::string(kKeys[k]) + " is given twice in the %@2-E option");
        return false;
      }
      for (int o = 0; o < 4; ++o)
        if (cols_.col[static_cast<size_t>(o)] == n) {
          diags_.error({line, at + static_cast<int32_t>(eq) + 1}, "LJ4099",
                       "column " + std::to_string(n) + " is given to both " + kKeys[o] + " and " +
                           kKeys[k]);
          return false;
        }
      cols_.col[static_cast<size_t>(k)] = n;
    }
    for (int k = 0; k < 2; ++k)
      if (cols_.col[static_cast<size_t>(k)] == 0) {
        diags_.error({line, col}, "LJ4100",
                     std::string("the %@2-E option gives no ") + kKeys[k] +
                         " column (a symbol needs SYM and ADR)");
        return false;
      }
    return true;
  }

  /// One CSV row of a %@2-E section: a symbol, its address and comments.
  void row(std::string_view raw, int32_t line) {
    if (trim(raw).empty()) return;
    splitCsv(raw, fields_);
    auto field = [&](int k) -> CsvField {
      const int c = cols_.col[static_cast<size_t>(k)];
      if (c > 0 && static_cast<size_t>(c) <= fields_.size())
        return fields_[static_cast<size_t>(c - 1)];
      return {std::string_view(), static_cast<int32_t>(raw.size() + 1)};
    };
    const CsvField name = field(0), addr = field(1), cm1 = field(2), cm2 = field(3);
    if (name.text.empty()) {
      // FANUC keeps comments of addresses without a symbol; ladderjit keeps named symbols only.
      if (!addr.text.empty() || !cm1.text.empty() || !cm2.text.empty()) {
        if (nameless_++ == 0) namelessAt_ = {line, addr.text.empty() ? 1 : addr.col};
      }
      return;
    }
    const std::string n(name.text);
    if (addr.text.empty()) {
      reject(n, line, name.col,
             "symbol " + SymbolTable::quote(n) +
                 " has no address (column ADR = " + std::to_string(cols_.col[1]) + " is empty)");
      return;
    }
    std::string comment(cm1.text);
    if (!cm2.text.empty()) (comment += comment.empty() ? "" : " / ") += cm2.text;
    if (const Symbol *prev = table_.find(n)) {
      const int32_t at = defined_[static_cast<size_t>(prev - table_.symbols().data())];
      diags_.error({line, name.col}, "LJ4101",
                   "duplicate symbol " + SymbolTable::quote(n) + " (already defined " +
                       (at > 0 ? "on line " + std::to_string(at)
                               : std::string("in the symbols given with the program")) +
                       " as " + SymbolTable::quote(prev->name) + "; names are case-insensitive)");
      return;
    }
    std::string why;
    SymbolTable::Field failed = SymbolTable::Field::Name;
    if (!table_.add(n, addr.text, comment, why, &failed)) {
      const int32_t at = failed == SymbolTable::Field::Address ? addr.col
                         : failed == SymbolTable::Field::Comment
                             ? (cm1.text.empty() ? cm2.col : cm1.col)
                             : name.col;
      reject(n, line, at, why);
      return;
    }
    defined_.push_back(line);
  }

  /// A line after %@E, the end of the file, that is no comment.
  void afterEnd(int32_t line, int32_t col) {
    diags_.error({line, col}, "LJ4005", "text after %@E (the end of the mnemonic file)");
  }

  void reject(const std::string &name, int32_t line, int32_t col, std::string msg) {
    diags_.error({line, col}, "LJ4006", std::move(msg));
    src_.rejected.emplace(detail::upper(name), line);
  }

  std::string_view text_;
  SymbolTable &table_;
  std::vector<int32_t> &defined_; ///< line of each table entry (0: given with the program)
  Diagnostics &diags_;
  detail::PmcSource &src_;
  In in_ = In::Outside;
  bool reported_ = false; ///< a stray line was reported since the last section line
  int32_t lastLine_ = 0, allLine_ = 0, ladderLine_ = 0, openLine_ = 0;
  std::string openName_;
  size_t ladderBegin_ = 0;
  Columns cols_;
  std::vector<CsvField> fields_;
  int nameless_ = 0;
  SourceLoc namelessAt_;
};

} // namespace

const SymbolRules &symbolRules() {
  // Names and comments: the 0i-D extended lengths (reference 1: symbols 16 / 40, comments
  // 30 / 255 characters; bytes here). The count is bounded by Operand::symbol (int16_t).
  static constexpr SymbolRules kRules{32767, 40, 255, "ladderjit limit", &canonicalAddress};
  return kRules;
}

namespace detail {

PmcSource readPmcSource(std::string_view text, const SymbolTable *external, SymbolTable &table,
                        Diagnostics &diags) {
  PmcSource src;
  src.ladder = text;
  std::vector<int32_t> defined;
  if (external) {
    src.hasTable = true;
    for (const Symbol &s : external->symbols()) {
      std::string why;
      if (table.add(s.name, s.address, s.comment, why))
        defined.push_back(0);
      else
        diags.error({}, "LJ4102", "symbols given with the program: " + why);
    }
  }
  // A mnemonic file: its first line that is neither blank nor a comment is a section line.
  size_t pos = 0;
  while (pos < text.size()) {
    size_t nl = text.find('\n', pos);
    if (nl == std::string_view::npos) nl = text.size();
    const std::string_view t = trim(text.substr(pos, nl - pos));
    pos = nl + 1;
    if (t.empty() || t == "\r" || t[0] == ';' || t.substr(0, 2) == "//") continue;
    if (t[0] != '%') return src;
    src.hasTable = true;
    src.ladder = {};
    SectionReader(text, table, defined, diags, src).read();
    return src;
  }
  return src;
}

} // namespace detail

} // namespace lj::fanuc

// plc.dit reader and writer (docs/plc-dit.md): line-oriented, one located error, no exceptions;
// the content hash is SHA-256 (OpenSSL EVP) over a canonical serialization.
#include "formats/PlcDit.h"

#include <openssl/evp.h>

#include <array>

namespace lj::formats {

namespace {

bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\v' || c == '\f'; }

std::string_view trim(std::string_view s) {
  while (!s.empty() && isBlank(s.front())) s.remove_prefix(1);
  while (!s.empty() && isBlank(s.back())) s.remove_suffix(1);
  return s;
}

// Splits at the first run of blanks: `head` is the first word, the rest is returned trimmed.
std::string_view firstWord(std::string_view s, std::string_view &rest) {
  s = trim(s);
  size_t i = 0;
  while (i < s.size() && !isBlank(s[i])) ++i;
  rest = trim(s.substr(i));
  return s.substr(0, i);
}

// Decimal digits only, at most 18 (no overflow), into `v`.
bool decimal(std::string_view s, uint64_t &v) {
  if (s.empty() || s.size() > 18) return false;
  v = 0;
  for (char c : s) {
    if (c < '0' || c > '9') return false;
    v = v * 10 + static_cast<uint64_t>(c - '0');
  }
  return true;
}

const char *const kSections[] = {"params", "symbols", "program", "end"};
constexpr int kSectionCount = 4;

int sectionIndex(std::string_view name) {
  for (int i = 0; i < kSectionCount; ++i)
    if (name == kSections[i]) return i;
  return -1;
}

std::string sectionName(int i) { return std::string("[") + kSections[i] + "]"; }

/// The container split into lines (LF; one CR before it dropped) with located errors.
class Reader {
public:
  Reader(std::string_view text, const std::string &file, std::string &error)
      : file_(file), error_(error) {
    if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
    finalNewline_ = !text.empty() && text.back() == '\n';
    size_t pos = 0;
    while (pos < text.size()) {
      size_t nl = text.find('\n', pos);
      if (nl == std::string_view::npos) nl = text.size();
      std::string_view line = text.substr(pos, nl - pos);
      if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
      lines_.push_back(line);
      pos = nl + 1;
    }
  }

  size_t count() const { return lines_.size(); }
  std::string_view line(size_t i) const { return lines_[i]; }

  /// Sets the error for 0-based line `i`; always returns false.
  bool fail(size_t i, const std::string &problem) {
    error_ = file_ + ":" + std::to_string(i + 1) + ": " + problem;
    if (i + 1 >= lines_.size() && !finalNewline_ && problem.rfind("truncated", 0) != 0)
      error_ += " (the file ends in this line without a newline: truncated?)";
    return false;
  }

private:
  const std::string &file_;
  std::string &error_;
  std::vector<std::string_view> lines_;
  bool finalNewline_ = false;
};

bool parseMagic(Reader &r) {
  if (r.count() == 0)
    return r.fail(0, "empty file: not a plc.dit container (expected '" + std::string(kDitMagic) +
                         " " + std::to_string(kDitVersion) + "' on the first line)");
  std::string_view rest;
  std::string_view word = firstWord(r.line(0), rest);
  if (word != kDitMagic)
    return r.fail(0, "wrong magic " + SymbolTable::quote(word) +
                         ": not a ladderjit plc.dit container (the first line must be '" +
                         std::string(kDitMagic) + " " + std::to_string(kDitVersion) + "')");
  uint64_t version = 0;
  if (!decimal(rest, version))
    return r.fail(0, "bad version " + SymbolTable::quote(rest) + " after '" +
                         std::string(kDitMagic) + "' (expected a number)");
  if (version != static_cast<uint64_t>(kDitVersion))
    return r.fail(0, "unsupported plc.dit version " + std::string(rest) +
                         " (this ladderjit reads version " + std::to_string(kDitVersion) + ")");
  return true;
}

bool parseHashLine(Reader &r, std::string &hash) {
  if (r.count() < 2) return r.fail(0, "truncated file: no 'hash = sha256:...' line");
  std::string_view l = trim(r.line(1));
  size_t eq = l.find('=');
  std::string_view key = trim(l.substr(0, eq));
  std::string_view value = eq == std::string_view::npos ? "" : trim(l.substr(eq + 1));
  bool ok = eq != std::string_view::npos && key == "hash" && value.size() == 7 + 64 &&
            value.substr(0, 7) == "sha256:";
  for (size_t i = 7; ok && i < value.size(); ++i) {
    char c = value[i];
    ok = (c >= '0' && c <= '9') || (c >= 'a' && c <= 'f') || (c >= 'A' && c <= 'F');
  }
  if (!ok)
    return r.fail(1, "bad hash line " + SymbolTable::quote(l) +
                         " (expected 'hash = sha256:' and 64 hex digits)");
  hash = value;
  for (char &c : hash)
    if (c >= 'A' && c <= 'F') c = static_cast<char>(c - 'A' + 'a');
  return true;
}

/// One `[params]` line.
class ParamsParser {
public:
  explicit ParamsParser(Reader &r) : r_(r) {}

  bool line(size_t i, std::string_view text, DitFile &dit) {
    size_t eq = text.find('=');
    if (eq == std::string_view::npos)
      return r_.fail(i, "bad parameter line " + SymbolTable::quote(trim(text)) +
                            " (expected NAME = VALUE)");
    std::string_view key = trim(text.substr(0, eq));
    std::string_view value = trim(text.substr(eq + 1));
    uint64_t v = 0;
    if (key == "plc2_nvalue" || key == "period_ms") {
      bool nv = key == "plc2_nvalue";
      int &seen = nv ? nvalueLine_ : periodLine_;
      if (seen)
        return r_.fail(i, "duplicate parameter " + std::string(key) + " (first on line " +
                              std::to_string(seen) + ")");
      seen = static_cast<int>(i + 1);
      uint64_t max = nv ? uint64_t{INT32_MAX} : uint64_t{1} << 40;
      uint64_t min = nv ? 0 : 1;
      if (!decimal(value, v) || v < min || v > max)
        return r_.fail(i, "bad parameter " + std::string(key) + " = " + SymbolTable::quote(value) +
                              " (expected a decimal number " + std::to_string(min) + ".." +
                              std::to_string(max) + ")");
      if (nv)
        dit.plc2Nvalue = static_cast<int32_t>(v);
      else
        dit.periodMs = v;
      return true;
    }
    std::string compact = std::string(key) + "=" + std::string(value);
    std::string why;
    std::optional<Assignment> a = parseAssignment(compact, why);
    if (!a) {
      if (key.empty() || (key[0] != 'P' && key[0] != 'p'))
        why = "unknown parameter " + SymbolTable::quote(key) +
              " (expected plc2_nvalue, period_ms or Pn)";
      return r_.fail(i, "bad parameter: " + why);
    }
    if (a->addr.area != Area::Param || a->addr.isBit())
      return r_.fail(i, "bad parameter " + SymbolTable::quote(key) +
                            " (expected plc2_nvalue, period_ms or Pn with n in 0..199)");
    for (const Assignment &p : dit.params)
      if (p.addr.index == a->addr.index)
        return r_.fail(i, "duplicate parameter P" + std::to_string(a->addr.index));
    a->addr.text = "P" + std::to_string(a->addr.index);
    dit.params.push_back(std::move(*a));
    return true;
  }

  /// At the end of the section (line `i` = its closing header): both scalars present?
  bool finish(size_t i) {
    if (!nvalueLine_) return r_.fail(i, "missing parameter plc2_nvalue in [params]");
    if (!periodLine_) return r_.fail(i, "missing parameter period_ms in [params]");
    return true;
  }

private:
  Reader &r_;
  int nvalueLine_ = 0, periodLine_ = 0;
};

bool symbolLine(std::string_view text, SymbolTable &table, std::string &why) {
  std::string_view rest, comment;
  std::string_view name = firstWord(text, rest);
  std::string_view addr = firstWord(rest, comment);
  if (addr.empty()) {
    why = "symbol " + SymbolTable::quote(name) + " has no address (expected NAME ADDR [comment])";
    return false;
  }
  // A comment may be marked like the rest of the file (`# ...`) or like STL (`; ...`).
  if (!comment.empty() && (comment[0] == '#' || comment[0] == ';'))
    comment = trim(comment.substr(1));
  return table.add(name, addr, comment, why);
}

/// Everything after the hash line: the sections in their fixed order, then nothing but blank
/// or comment lines after [end].
bool parseSections(Reader &r, DitFile &dit) {
  ParamsParser params(r);
  int section = -1; // index into kSections of the current section
  size_t i = 2;
  for (; i < r.count() && section != 3; ++i) {
    std::string_view l = r.line(i);
    bool header = !l.empty() && l[0] == '[';
    if (section == 2 && !header) { // program lines are verbatim
      dit.program.append(l.data(), l.size());
      dit.program += '\n';
      continue;
    }
    std::string_view t = trim(l);
    if (!header && (t.empty() || t[0] == '#')) continue;
    if (header) {
      std::string_view name = t.size() >= 2 && t.back() == ']' ? t.substr(1, t.size() - 2) : "";
      int next = sectionIndex(name);
      if (next < 0)
        return r.fail(i, "unknown section header " + SymbolTable::quote(t) +
                             " (expected [params], [symbols], [program] or [end]; STL lines "
                             "never start with '[')");
      if (next <= section) return r.fail(i, "duplicate section " + sectionName(next));
      if (next != section + 1)
        return r.fail(i, "missing section " + sectionName(section + 1) + " before " +
                             sectionName(next));
      if (section == 0 && !params.finish(i)) return false;
      section = next;
      if (section == 2) dit.programLine = static_cast<int32_t>(i + 2);
      continue;
    }
    if (section < 0)
      return r.fail(i, "text outside a section: " + SymbolTable::quote(t) +
                           " (expected the [params] header)");
    if (section == 0 && !params.line(i, t, dit)) return false;
    std::string why;
    if (section == 1 && !symbolLine(t, dit.symbols, why)) return r.fail(i, why);
  }
  if (section != 3)
    return r.fail(r.count() - 1, "truncated file: it ends " +
                                     (section < 0 ? std::string("before [params]")
                                                  : "inside " + sectionName(section)) +
                                     ", before the [end] line");
  for (; i < r.count(); ++i) {
    std::string_view t = trim(r.line(i));
    if (!t.empty() && t[0] != '#') return r.fail(i, "text after [end]: " + SymbolTable::quote(t));
  }
  return true;
}

std::string where(const std::string &file, size_t line) {
  return file + ":" + std::to_string(line) + ": ";
}

} // namespace

bool looksLikeDit(std::string_view text) {
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  if (text.substr(0, kDitMagic.size()) != kDitMagic) return false;
  return text.size() == kDitMagic.size() || isBlank(text[kDitMagic.size()]) ||
         text[kDitMagic.size()] == '\n' || text[kDitMagic.size()] == '\r';
}

std::optional<DitFile> parseDit(std::string_view text, const std::string &file,
                                std::string &error) {
  Reader r(text, file, error);
  DitFile dit;
  std::string declared;
  if (!parseMagic(r) || !parseHashLine(r, declared) || !parseSections(r, dit)) return std::nullopt;
  dit.hash = sha256Hash(ditCanonical(dit));
  if (dit.hash != declared) {
    r.fail(1, "content hash does not match: file was modified or truncated (declared " + declared +
                  ", content " + dit.hash + ")");
    return std::nullopt;
  }
  return dit;
}

std::string ditCanonical(const DitFile &dit) {
  std::string out = std::string(kDitMagic) + " " + std::to_string(kDitVersion) + "\n";
  out += "[params]\n";
  out += "plc2_nvalue = " + std::to_string(dit.plc2Nvalue) + "\n";
  out += "period_ms = " + std::to_string(dit.periodMs) + "\n";
  for (const Assignment &p : dit.params)
    out += "P" + std::to_string(p.addr.index) + " = " + std::to_string(p.value) + "\n";
  out += "[symbols]\n";
  for (const Symbol &s : dit.symbols.symbols()) {
    out += s.name + " " + s.address;
    if (!s.comment.empty()) out += " # " + s.comment;
    out += "\n";
  }
  out += "[program]\n";
  out += dit.program;
  out += "[end]\n";
  return out;
}

std::string sha256Hash(std::string_view bytes) {
  std::array<unsigned char, EVP_MAX_MD_SIZE> md{};
  unsigned int len = 0;
  std::string out = "sha256:";
  if (EVP_Digest(bytes.data(), bytes.size(), md.data(), &len, EVP_sha256(), nullptr) != 1)
    return out + "unavailable"; // never equal to a declared hash: the file is rejected
  static constexpr char kHex[] = "0123456789abcdef";
  for (unsigned int i = 0; i < len; ++i) {
    out += kHex[md[i] >> 4];
    out += kHex[md[i] & 15];
  }
  return out;
}

std::string writeDit(const DitFile &dit) {
  std::string canon = ditCanonical(dit);
  std::string hashLine = "hash = " + sha256Hash(canon) + "\n";
  std::string comment = "# ladderjit plc.dit (docs/plc-dit.md). Comment lines are free; any other "
                        "change needs 'ladderjit dit' to rebuild the hash.\n";
  size_t firstLineEnd = canon.find('\n') + 1;
  return canon.substr(0, firstLineEnd) + hashLine + comment + canon.substr(firstLineEnd);
}

bool normalizeProgram(std::string_view stl, const std::string &file, std::string &out,
                      std::string &error) {
  out.clear();
  size_t pos = 0, line = 0;
  while (pos < stl.size()) {
    size_t nl = stl.find('\n', pos);
    if (nl == std::string_view::npos) nl = stl.size();
    std::string_view l = stl.substr(pos, nl - pos);
    ++line;
    if (!l.empty() && l.back() == '\r') l.remove_suffix(1);
    if (!l.empty() && l[0] == '[') {
      error = where(file, line) +
              "a line starting with '[' cannot go into a plc.dit (reserved for section headers; "
              "it is not STL either)";
      return false;
    }
    out.append(l.data(), l.size());
    out += '\n';
    pos = nl + 1;
  }
  return true;
}

std::string programForParser(const DitFile &dit) {
  int32_t pad = dit.programLine > 1 ? dit.programLine - 1 : 0;
  return std::string(static_cast<size_t>(pad), '\n') + dit.program;
}

bool parseSymbols(std::string_view text, const std::string &file, SymbolTable &table,
                  std::string &error) {
  size_t pos = 0, line = 0;
  while (pos < text.size()) {
    size_t nl = text.find('\n', pos);
    if (nl == std::string_view::npos) nl = text.size();
    std::string_view t = trim(text.substr(pos, nl - pos));
    if (!t.empty() && t.back() == '\r') t = trim(t.substr(0, t.size() - 1));
    ++line;
    pos = nl + 1;
    if (t.empty() || t[0] == '#') continue;
    std::string why;
    if (!symbolLine(t, table, why)) {
      error = where(file, line) + why;
      return false;
    }
  }
  return true;
}

} // namespace lj::formats

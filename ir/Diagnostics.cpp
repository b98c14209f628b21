// Rendering of collected diagnostics as `file:line:col: severity: text` lines, sorted by position.
#include "ir/Diagnostics.h"

#include <algorithm>

namespace lj {

namespace {

/// `c` as `\xNN`.
void appendEscaped(std::string &out, unsigned char c) {
  static constexpr char kHex[] = "0123456789ABCDEF";
  out += "\\x";
  out += kHex[c >> 4];
  out += kHex[c & 15];
}

} // namespace

std::string printable(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (unsigned char c : text)
    if (c < 0x20 || c == 0x7f)
      appendEscaped(out, c);
    else
      out += static_cast<char>(c);
  return out;
}

std::string quoteToken(std::string_view text, size_t maxBytes, bool keepNonAscii) {
  std::string out = "'";
  for (size_t i = 0; i < text.size() && i < maxBytes; ++i) {
    auto c = static_cast<unsigned char>(text[i]);
    if ((c >= 0x20 && c < 0x7f && c != '\\') || (keepNonAscii && c >= 0x80)) {
      out += static_cast<char>(c);
    } else {
      appendEscaped(out, c);
    }
  }
  if (text.size() > maxBytes) out += "...";
  out += '\'';
  return out;
}

namespace {

const char *severityName(Diagnostic::Severity s) {
  switch (s) {
  case Diagnostic::Severity::Error:
    return "error";
  case Diagnostic::Severity::Warning:
    return "warning";
  case Diagnostic::Severity::Note:
    return "note";
  }
  return "error";
}

// A primary diagnostic (error or warning) with the notes reported right after it.
struct Group {
  SourceLoc loc;
  size_t first = 0; // index of the primary in the list
  size_t count = 0; // primary + its notes
};

} // namespace

std::string Diagnostics::render() const {
  // Notes belong to the diagnostic before them (the "first write is here" of a double coil sits
  // on an earlier line than its warning), so sort whole groups by the primary's position.
  std::vector<Group> groups;
  for (size_t i = 0; i < list_.size(); ++i) {
    if (list_[i].severity == Diagnostic::Severity::Note && !groups.empty()) {
      ++groups.back().count;
      continue;
    }
    groups.push_back({list_[i].loc, i, 1});
  }
  // Stable by construction: equal positions keep report order (the index breaks ties).
  std::sort(groups.begin(), groups.end(), [](const Group &a, const Group &b) {
    if (a.loc.line != b.loc.line) return a.loc.line < b.loc.line;
    if (a.loc.col != b.loc.col) return a.loc.col < b.loc.col;
    return a.first < b.first;
  });
  const std::string &file = file_.empty() ? std::string("<input>") : file_;
  std::string out;
  for (const Group &g : groups) {
    for (size_t i = g.first; i < g.first + g.count; ++i) {
      const Diagnostic &d = list_[i];
      out += file;
      out += ':';
      out += std::to_string(d.loc.line);
      out += ':';
      out += std::to_string(d.loc.col);
      out += ": ";
      out += severityName(d.severity);
      out += ": ";
      // One line per diagnostic, whatever bytes the program held: a control byte a message
      // quotes (a NUL, a CR) is written as \xNN, so it can neither end the output early nor
      // break the `file:line:col: severity: text` line.
      out += printable(d.message);
      out += '\n';
    }
  }
  return out;
}

} // namespace lj

// Located diagnostics (`file:line:col: error: text`), collected, never thrown.
#pragma once

#include "ir/Program.h"

#include <string>
#include <string_view>
#include <vector>

namespace lj {

/// A token as it may appear in a message, in single quotes: printable ASCII kept, other bytes as
/// \xNN (input may be any bytes; with `keepNonAscii`, bytes >= 0x80 are kept so UTF-8 names stay
/// readable), cut after `maxBytes` with "..." so one bad line cannot produce megabytes of text.
std::string quoteToken(std::string_view text, size_t maxBytes, bool keepNonAscii = false);

/// `text` as one line of a message: a control byte (< 0x20, 0x7f) written as \xNN, everything
/// else kept. What Diagnostics::render does to every message, and the CLI to every error it
/// prints, so a value quoted from input can neither end the output early nor break the line.
std::string printable(std::string_view text);

struct Diagnostic {
  enum class Severity : uint8_t { Error, Warning, Note } severity = Severity::Error;
  SourceLoc loc;
  std::string message; ///< ends in " [CODE]" when the diagnostic has a code
  std::string code;    ///< the stable code (docs/diagnostics.md), "LJ1001"; empty: none
};

/// Collects diagnostics for one file; all of them are reported, not only the first.
class Diagnostics {
public:
  explicit Diagnostics(std::string file = {}) : file_(std::move(file)) {}

  void error(SourceLoc loc, std::string msg) {
    add(Diagnostic::Severity::Error, loc, std::move(msg));
  }
  void warning(SourceLoc loc, std::string msg) {
    add(Diagnostic::Severity::Warning, loc, std::move(msg));
  }
  /// With a stable code (docs/diagnostics.md): the text ends in " [CODE]", after the
  /// `file:line:col: error: ` prefix CLI.md fixes.
  void error(SourceLoc loc, const char *code, std::string msg) {
    add(Diagnostic::Severity::Error, loc, std::move(msg), code);
  }
  void warning(SourceLoc loc, const char *code, std::string msg) {
    add(Diagnostic::Severity::Warning, loc, std::move(msg), code);
  }
  void note(SourceLoc loc, std::string msg) {
    add(Diagnostic::Severity::Note, loc, std::move(msg));
  }

  bool hasErrors() const { return errors_ > 0; }
  int errorCount() const { return errors_; }
  const std::vector<Diagnostic> &all() const { return list_; }
  const std::string &file() const { return file_; }

  /// Sorted by position (stable for equal positions), one `file:line:col: kind: text` per line.
  std::string render() const;

private:
  void add(Diagnostic::Severity s, SourceLoc loc, std::string msg, const char *code = nullptr) {
    if (s == Diagnostic::Severity::Error) ++errors_;
    if (code && *code) msg += std::string(" [") + code + "]";
    list_.push_back({s, loc, std::move(msg), code ? code : ""});
  }
  std::string file_;
  std::vector<Diagnostic> list_;
  int errors_ = 0;
};

} // namespace lj

// Parse + verify for every dialect (pipeline/Compile.h).
#include "pipeline/Compile.h"

#include "frontends/classicladder/FrontEnd.h"
#include "frontends/fanuc/FrontEnd.h"
#include "frontends/hnc8/FrontEnd.h"
#include "frontends/iec/FrontEnd.h"
#include "pipeline/Dialects.h"
#include "profiles/hnc8/Hnc8Profile.h"

#include <algorithm>

namespace lj::pipeline {

namespace {

/// Verify `parsed` unless the front end reported an error.
std::optional<VerifiedProgram> verifyParsed(const ParsedProgram &parsed, const VerifyOptions &opts,
                                            Diagnostics &diags) {
  if (diags.hasErrors()) return std::nullopt;
  std::optional<VerifiedProgram> prog = verify(parsed, opts, diags);
  if (diags.hasErrors()) return std::nullopt;
  return prog;
}

/// Lines end with LF or CRLF. A text whose lines end with a CR alone would reach the front end
/// as one long line ("LD takes 1 operand, got 3"): say what is wrong instead (false).
bool lineEndsOk(std::string_view text, Diagnostics &diags) {
  for (size_t i = 0, line = 1, lineStart = 0; i + 1 < text.size(); ++i) {
    if (text[i] == '\n') {
      ++line;
      lineStart = i + 1;
    } else if (text[i] == '\r' && text[i + 1] != '\n') {
      diags.error({static_cast<int32_t>(line), static_cast<int32_t>(i - lineStart + 1)}, "LJ0001",
                  "a carriage return (CR) without a line feed: lines must end with LF or CRLF, "
                  "not with CR alone");
      return false;
    }
  }
  return true;
}

} // namespace

std::optional<VerifiedProgram> compileStl(std::string_view text, std::string file,
                                          const VerifyOptions &opts, Diagnostics &diags,
                                          const SymbolTable *symbols) {
  if (!lineEndsOk(text, diags)) return std::nullopt;
  const int32_t limit = opts.maxStatements.value_or(hnc8::profile().maxStatements);
  ParsedProgram parsed = parseStl(text, std::move(file), diags, symbols, limit);
  // A program cut short at the statement limit is not verified (its end would look missing).
  if (parsed.stmts.size() > static_cast<size_t>(std::max(limit, 0))) return std::nullopt;
  std::optional<VerifiedProgram> prog = verify(parsed, opts, diags);
  if (diags.hasErrors()) return std::nullopt;
  return prog;
}

std::optional<VerifiedProgram> compilePmc(std::string_view text, std::string file,
                                          const VerifyOptions &opts, Diagnostics &diags,
                                          const SymbolTable *symbols) {
  if (!lineEndsOk(text, diags)) return std::nullopt;
  return verifyParsed(fanuc::parsePmc(text, std::move(file), diags, symbols), opts, diags);
}

std::optional<VerifiedProgram> compileIl(std::string_view text, std::string file,
                                         const VerifyOptions &opts, Diagnostics &diags,
                                         const SymbolTable *symbols) {
  if (symbols && !symbols->empty()) {
    diags.error({}, "LJ0002", "an IEC IL program takes no symbol table");
    return std::nullopt;
  }
  if (!lineEndsOk(text, diags)) return std::nullopt;
  return verifyParsed(iec::parseIl(text, std::move(file), diags), opts, diags);
}

std::optional<VerifiedProgram> compileClp(std::string_view text, std::string file,
                                          const VerifyOptions &opts, Diagnostics &diags,
                                          const SymbolTable *symbols) {
  if (symbols && !symbols->empty()) {
    diags.error({}, "LJ0003",
                "a ClassicLadder project takes no symbol table (its symbols.csv is its own)");
    return std::nullopt;
  }
  if (!lineEndsOk(text, diags)) return std::nullopt;
  return verifyParsed(classicladder::parseClp(text, std::move(file), diags), opts, diags);
}

std::optional<VerifiedProgram> compile(const pipeline::Dialect &dialect, std::string_view text,
                                       std::string file, const VerifyOptions &opts,
                                       Diagnostics &diags, const SymbolTable *symbols) {
  return dialect.compile(text, std::move(file), opts, diags, symbols);
}

ParsedProgram parse(const pipeline::Dialect &dialect, std::string_view text, std::string file,
                    Diagnostics &diags, const SymbolTable *symbols) {
  return dialect.parse(text, std::move(file), diags, symbols);
}

std::string printProgram(const VerifiedProgram &prog) { return lj::printProgram(prog); }

} // namespace lj::pipeline

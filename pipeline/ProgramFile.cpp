// Reading and verifying PROGRAM (pipeline/ProgramFile.h).
#include "pipeline/ProgramFile.h"

#include "formats/InputFiles.h"
#include "ir/Diagnostics.h"
#include "ladder/Json.h"

#include <algorithm>

namespace lj::pipeline {

using formats::DitFile;
using formats::looksLikeDit;
using formats::parseDit;
using formats::programForParser;
using formats::readFile;
using formats::sha256Hash;

namespace {

// At most this many diagnostic lines reach a user (the verifier can report one per statement).
constexpr size_t kMaxDiagnosticLines = 200;

std::string capLines(std::string text, size_t max, const std::string &file) {
  size_t pos = 0, lines = 0;
  while (lines < max && (pos = text.find('\n', pos)) != std::string::npos) {
    ++pos;
    ++lines;
  }
  if (lines < max || pos >= text.size()) return text;
  size_t rest = 0;
  for (size_t i = pos; i < text.size(); ++i) rest += text[i] == '\n';
  text.resize(pos);
  return text + file + ": note: " + std::to_string(rest) + " more diagnostic lines not shown\n";
}

} // namespace

Status readProgramFile(const std::string &path, ProgramSource &src, std::string_view dialect,
                       const std::string *bytes) {
  src.path = path;
  const bool json = path.size() >= 5 && path.compare(path.size() - 5, 5, ".json") == 0;
  Result<const Dialect *> d = !dialect.empty() ? dialectForOption(dialect)
                              : json           ? Result<const Dialect *>(&defaultDialect())
                                               : dialectForPath(path);
  if (!d) return d.status();
  src.dialect = *d;
  // The other libraries this reads with (formats/, ladder/) still report through a message.
  std::string error;
  auto fail = [&](ErrorCode code, std::string message) {
    return Status::error(code, std::move(message), {path});
  };
  std::string text;
  if (bytes)
    text = *bytes;
  else if (!readFile(path, text, error))
    return fail(ErrorCode::NotFound, error);
  src.fileHash = sha256Hash(text);
  if (json) {
    Result<const Dialect *> namedOr = dialectOfJson(text);
    if (!namedOr) return namedOr.status().withContext(path);
    const Dialect *named = *namedOr;
    if (!dialect.empty() && named != *d)
      return fail(ErrorCode::InvalidArgument, path + ": the ladder JSON is dialect '" +
                                                  named->name + "', not '" + (*d)->name + "'");
    src.dialect = named;
    if (named != &defaultDialect()) { // networks -> program text of the dialect
      auto nets = std::make_shared<ladder::Networks>();
      if (!ladder::readJson(text, *nets, error, named->text()))
        return fail(ErrorCode::BadFormat, path + ": " + error);
      if (nets->source.empty())
        return fail(ErrorCode::BadFormat,
                    path + ": a " + std::string(named->name) +
                        " ladder JSON keeps its untouched rungs from the program text it carries "
                        "(\"source\", written by `ladderjit ladder --format json`); this one has "
                        "none");
      // The rungs the networks leave unchanged come from that text byte for byte, the edited
      // ones are printed by the dialect (ladder::programText); the front end and the verifier
      // then check the result as any program file of the dialect.
      Diagnostics diags(path);
      std::optional<VerifiedProgram> made =
          named->compile(nets->source, path, VerifyOptions{}, diags, nullptr);
      if (!made || diags.hasErrors())
        return fail(ErrorCode::Rejected,
                    path + ": the program text the JSON carries (\"source\") does not verify:\n" +
                        capLines(diags.render(), kMaxDiagnosticLines, path));
      if (!ladder::programText(*nets, *made, nets->source, src.text, error))
        return fail(ErrorCode::BadFormat, path + ": " + error);
      src.edited = src.text != nets->source;
      src.carried = std::move(nets);
      return {};
    }
    auto lad = std::make_shared<ladder::StlFromJson>();
    if (!ladder::stlFromJson(text, *lad, error, named->text()))
      return fail(ErrorCode::BadFormat, path + ": " + error);
    src.text = lad->text;
    src.ladder = std::move(lad);
    return {};
  }
  bool named = path.size() >= 4 && path.compare(path.size() - 4, 4, ".dit") == 0;
  if (!looksLikeDit(text) && !named) {
    src.text = std::move(text);
    return {};
  }
  src.dit = parseDit(text, path, error);
  if (!src.dit) return fail(ErrorCode::BadFormat, error);
  src.text = programForParser(*src.dit);
  return {};
}

int32_t effectiveNvalue(const ProgramSource &src, int32_t option, bool optionGiven) {
  if (optionGiven || !src.dit) return option;
  return src.dit->plc2Nvalue;
}

namespace {

/// The program text made from edited networks, numbered, for diagnostics that point into it.
std::string madeText(const ProgramSource &src) {
  std::string out =
      "--- the program text made from the networks (" + std::string(src.dialect->name) + ") ---\n";
  size_t line = 1, pos = 0;
  while (pos < src.text.size() && line <= kMaxDiagnosticLines) {
    size_t nl = src.text.find('\n', pos);
    if (nl == std::string::npos) nl = src.text.size();
    out += std::to_string(line++) + ": " + src.text.substr(pos, nl - pos) + "\n";
    pos = nl + 1;
  }
  return out;
}

/// The symbol table of a FANUC/IEC ladder JSON must be the one of the program text it carries
/// (the text's is the one used): an edit of it alone is refused, never silently ignored.
bool sameSymbols(const std::vector<Symbol> &json, const std::vector<Symbol> &text,
                 std::string &error) {
  auto show = [](const Symbol &s) {
    return s.name + " " + s.address + (s.comment.empty() ? "" : " " + s.comment);
  };
  for (size_t i = 0; i < std::max(json.size(), text.size()); ++i) {
    if (i < json.size() && i < text.size() && json[i].name == text[i].name &&
        json[i].address == text[i].address && json[i].comment == text[i].comment)
      continue;
    error = "symbols[" + std::to_string(i) + "]: the JSON's symbol table says " +
            (i < json.size() ? "'" + show(json[i]) + "'" : "nothing") +
            ", the program text it carries says " +
            (i < text.size() ? "'" + show(text[i]) + "'" : "nothing");
    return false;
  }
  return true;
}

} // namespace

std::optional<VerifiedProgram> verifyProgram(const ProgramSource &src, int32_t plc2Nvalue,
                                             std::string &diagnostics, size_t *warnings) {
  if (warnings) *warnings = 0;
  Diagnostics diags(src.path);
  // (A line ending in a CR alone is refused by every dialect's compile: pipeline/Compile.cpp.)
  VerifyOptions opts;
  opts.plc2Nvalue = plc2Nvalue;
  const SymbolTable *symbols = src.dit      ? &src.dit->symbols
                               : src.ladder ? &src.ladder->symbols
                                            : nullptr;
  std::optional<VerifiedProgram> prog =
      src.dialect->compile(src.text, src.path, opts, diags, symbols);
  if (warnings)
    *warnings = static_cast<size_t>(
        std::count_if(diags.all().begin(), diags.all().end(), [](const Diagnostic &d) {
          return d.severity == Diagnostic::Severity::Warning;
        }));
  diagnostics =
      capLines(src.ladder ? ladder::renderDiagnostics(diags, *src.ladder) : diags.render(),
               kMaxDiagnosticLines, src.path);
  if (prog && src.ladder) ladder::applyOrigins(*prog, *src.ladder);
  if (src.edited && diags.hasErrors()) diagnostics += madeText(src);
  std::string edited;
  if (prog && !diags.hasErrors() && src.carried &&
      (!ladder::sameStatementsAs(*src.carried, ladder::fromProgram(*prog), edited, !src.edited) ||
       !sameSymbols(src.carried->symbols, prog->symbols, edited))) {
    // Unedited: the networks are not those of the text they carry. Edited: the text printed
    // from them does not read back as them (a statement the dialect prints otherwise).
    diagnostics += src.path + ": error: " + edited +
                   (src.edited ? "; the program text made from the networks does not read back "
                                 "as them: edit its program text\n" +
                                     madeText(src)
                               : "; the networks and the program text they carry differ\n");
    return std::nullopt;
  }
  if (prog && !diags.hasErrors()) return prog;
  if (!diags.hasErrors()) // a front-end bug, but the user still deserves a reason
    diagnostics += src.path + ": error: program rejected without a diagnostic\n";
  return std::nullopt;
}

std::string programHash(std::string_view stl, const DitFile *dit, int32_t plc2Nvalue) {
  if (dit && dit->plc2Nvalue == plc2Nvalue) return dit->hash;
  std::string canon = "ladderjit-program 1\nplc2_nvalue = " + std::to_string(plc2Nvalue) + "\n";
  if (dit) return sha256Hash(canon + "container = " + dit->hash + "\n");
  canon += "[program]\n";
  for (size_t i = 0; i < stl.size(); ++i) {
    if (stl[i] == '\r' && i + 1 < stl.size() && stl[i + 1] == '\n') continue;
    canon += stl[i];
  }
  if (!stl.empty() && canon.back() != '\n') canon += '\n';
  return sha256Hash(canon);
}

std::string programHashOf(const ProgramSource &src, int32_t plc2Nvalue) {
  if (src.ladder) { // the names in the generated STL stand for what the JSON's table says
    std::string text = src.text;
    for (const Symbol &s : src.ladder->symbols.symbols())
      text += "\n;symbol " + s.name + " " + s.address;
    return programHash(text, nullptr, plc2Nvalue);
  }
  return programHash(src.text, src.dit ? &*src.dit : nullptr, plc2Nvalue);
}

} // namespace lj::pipeline

// Reading and verifying PROGRAM (io/ProgramFile.h).
#include "io/ProgramFile.h"

#include "frontends/hnc8/FrontEnd.h"
#include "io/AotLoader.h"
#include "io/InputFiles.h"
#include "ir/Diagnostics.h"

namespace lj::io {

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

bool readProgramFile(const std::string &path, ProgramSource &src, std::string &error) {
  src.path = path;
  std::string text;
  if (!readFile(path, text, error)) return false;
  src.fileHash = sha256Hash(text);
  bool named = path.size() >= 4 && path.compare(path.size() - 4, 4, ".dit") == 0;
  if (!looksLikeDit(text) && !named) {
    src.text = std::move(text);
    return true;
  }
  src.dit = parseDit(text, path, error);
  if (!src.dit) return false;
  src.text = programForParser(*src.dit);
  return true;
}

int32_t effectiveNvalue(const ProgramSource &src, int32_t option, bool optionGiven) {
  if (optionGiven || !src.dit) return option;
  return src.dit->plc2Nvalue;
}

std::optional<VerifiedProgram> verifyProgram(const ProgramSource &src, int32_t plc2Nvalue,
                                             std::string &diagnostics) {
  Diagnostics diags(src.path);
  VerifyOptions opts;
  opts.plc2Nvalue = plc2Nvalue;
  const SymbolTable *symbols = src.dit ? &src.dit->symbols : nullptr;
  std::optional<VerifiedProgram> prog = compileFrontEnd(src.text, src.path, opts, diags, symbols);
  diagnostics = capLines(diags.render(), kMaxDiagnosticLines, src.path);
  if (prog && !diags.hasErrors()) return prog;
  if (!diags.hasErrors()) // a front-end bug, but the user still deserves a reason
    diagnostics += src.path + ": error: program rejected without a diagnostic\n";
  return std::nullopt;
}

std::string programHashOf(const ProgramSource &src, int32_t plc2Nvalue) {
  return programHash(src.text, src.dit ? &*src.dit : nullptr, plc2Nvalue);
}

} // namespace lj::io

// Reading and verifying PROGRAM (formats/ProgramFile.h).
#include "formats/ProgramFile.h"

#include "formats/InputFiles.h"
#include "instructions/Diagnostics.h"
#include "instructions/FrontEnd.h"

namespace lj::io {

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
  diagnostics = diags.render();
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
  return programHash(src.text, src.dit ? &*src.dit : nullptr, plc2Nvalue);
}

} // namespace lj::io

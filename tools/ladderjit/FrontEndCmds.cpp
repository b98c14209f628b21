// `check`, `emit-llvm` and `fuzz`: the commands that load a program (STL or plc.dit) without
// simulating it (or, for fuzz, generate their own). JIT and fuzzer paths compile only when those
// libraries exist.
#include "tools/ladderjit/Commands.h"

#include "instructions/FrontEnd.h"
#include "io/InputFiles.h"

#ifdef LADDERJIT_HAVE_JIT
#include "jit/Jit.h"
#endif
#ifdef LADDERJIT_HAVE_FUZZ
#include "fuzz/Fuzz.h"
#endif

#include <cstdio>
#include <iostream>

namespace lj::cli {

int usageError(const std::string &msg) {
  std::fprintf(stderr, "ladderjit: error: %s\n", msg.c_str());
  return kUsage;
}

bool haveJit() {
#ifdef LADDERJIT_HAVE_JIT
  return true;
#else
  return false;
#endif
}

bool haveFuzz() {
#ifdef LADDERJIT_HAVE_FUZZ
  return true;
#else
  return false;
#endif
}

bool readProgram(const std::string &path, ProgramSource &src, int &exitCode) {
  src.path = path;
  std::string text, error;
  if (!io::readFile(path, text, error)) {
    exitCode = usageError(error);
    return false;
  }
  // The magic line decides; a `.dit` name without it is a damaged container, not STL.
  bool named = path.size() >= 4 && path.compare(path.size() - 4, 4, ".dit") == 0;
  if (!io::looksLikeDit(text) && !named) {
    src.text = std::move(text);
    exitCode = kOk;
    return true;
  }
  src.dit = io::parseDit(text, path, error);
  if (!src.dit) {
    exitCode = usageError(error);
    return false;
  }
  src.text = io::programForParser(*src.dit);
  exitCode = kOk;
  return true;
}

int32_t effectiveNvalue(const ProgramSource &src, int32_t option, bool optionGiven) {
  if (optionGiven || !src.dit) return option;
  return src.dit->plc2Nvalue;
}

std::optional<VerifiedProgram> loadProgram(const ProgramSource &src, int32_t plc2Nvalue,
                                           int &exitCode) {
  Diagnostics diags(src.path);
  VerifyOptions opts;
  opts.plc2Nvalue = plc2Nvalue;
  const SymbolTable *symbols = src.dit ? &src.dit->symbols : nullptr;
  std::optional<VerifiedProgram> prog = compileFrontEnd(src.text, src.path, opts, diags, symbols);
  std::string rendered = diags.render();
  if (!rendered.empty()) std::fputs(rendered.c_str(), stderr);
  if (!prog || diags.hasErrors()) {
    if (!diags.hasErrors()) // a front-end bug, but the user still deserves a reason
      std::fprintf(stderr, "%s: error: program rejected without a diagnostic\n", src.path.c_str());
    exitCode = kProgramErrors;
    return std::nullopt;
  }
  exitCode = kOk;
  return prog;
}

int runCheck(const CheckArgs &a) {
  int code = kOk;
  ProgramSource src;
  if (!readProgram(a.program, src, code)) return code;
  std::optional<VerifiedProgram> prog =
      loadProgram(src, effectiveNvalue(src, a.plc2Nvalue, a.plc2NvalueGiven), code);
  if (!prog) return code;
  if (a.print) std::cout << printProgram(*prog) << std::flush;
  return kOk;
}

int runEmitLlvm(const EmitArgs &a) {
#ifdef LADDERJIT_HAVE_JIT
  int code = kOk;
  ProgramSource src;
  if (!readProgram(a.program, src, code)) return code;
  std::optional<VerifiedProgram> prog =
      loadProgram(src, effectiveNvalue(src, a.plc2Nvalue, a.plc2NvalueGiven), code);
  if (!prog) return code;
  std::string ir, error;
  if (!jit::emitLlvm(*prog, a.optLevel, ir, error)) return usageError("emit-llvm failed: " + error);
  std::cout << ir << std::flush;
  return kOk;
#else
  (void)a;
  return usageError("emit-llvm is not built yet (this build has no JIT library)");
#endif
}

int runFuzz(const FuzzArgs &a) {
#ifdef LADDERJIT_HAVE_FUZZ
  fuzz::FuzzOptions opts;
  opts.seed = a.seed;
  opts.programs = a.programs;
  opts.ticks = a.ticks;
  uint64_t mismatches = fuzz::run(opts, std::cout);
  std::cout << std::flush;
  return mismatches == 0 ? kOk : kProgramErrors;
#else
  (void)a;
  return usageError("fuzz is not built yet (this build has no fuzzer library)");
#endif
}

} // namespace lj::cli

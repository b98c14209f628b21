// `ladderjit compile PROGRAM -o OUT.so`: the ahead-of-time build (docs/aot.md), and the AOT
// engine of `run --engine aot:PATH` (load the .so, check it was built from PROGRAM).
#include "tools/ladderjit/Commands.h"

#include "engines/AotLoader.h"

#ifdef LADDERJIT_HAVE_JIT
#include "jit/Aot.h"
#endif

namespace lj::cli {

std::unique_ptr<Engine> loadAotEngine(const std::string &soPath, const ProgramSource &src,
                                      int32_t plc2Nvalue, std::string &error) {
  return io::loadAot(soPath, programHashOf(src, plc2Nvalue), error);
}

int runCompile(const CompileArgs &a) {
#ifdef LADDERJIT_HAVE_JIT
  if (a.cpu != "host" && a.cpu != "generic")
    return usageError("--cpu: expected host or generic, got '" + a.cpu + "'");
  int code = kOk;
  ProgramSource src;
  if (!readProgram(a.program, src, code)) return code;
  int32_t nvalue = effectiveNvalue(src, a.plc2Nvalue, a.plc2NvalueGiven);
  std::optional<VerifiedProgram> prog = loadProgram(src, nvalue, code);
  if (!prog) return code;
  jit::AotOptions o;
  o.output = a.output;
  o.programHash = programHashOf(src, nvalue);
  o.genericCpu = a.cpu == "generic";
  std::string error;
  if (!jit::compileSharedObject(*prog, o, error)) return usageError("compile: " + error);
  return kOk;
#else
  (void)a;
  return usageError("compile is not built yet (this build has no JIT library)");
#endif
}

} // namespace lj::cli

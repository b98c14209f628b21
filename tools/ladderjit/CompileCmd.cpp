// `ladderjit compile PROGRAM -o OUT.so`: the ahead-of-time build (docs/aot.md). Loading it
// (`run --engine aot:PATH`) is engines/EngineSpec.h's.
#include "tools/ladderjit/Commands.h"

#include "jit/Aot.h"

namespace lj::cli {

int runCompile(const CompileArgs &a) {
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
}

} // namespace lj::cli

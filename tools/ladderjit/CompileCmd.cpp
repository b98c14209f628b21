// `ladderjit compile PROGRAM -o OUT.so`: the ahead-of-time build (docs/aot.md), and the AOT
// engine of `run --engine aot:PATH` (load the .so, check who signed it and that it was built from
// PROGRAM).
#include "tools/ladderjit/Commands.h"

#include "io/AotLoader.h"
#include "io/AotTrust.h"

#include <cstdio>

#ifdef LADDERJIT_HAVE_JIT
#include "jit/Aot.h"
#endif

namespace lj::cli {

std::unique_ptr<Engine> loadAotEngine(const std::string &soPath, const ProgramSource &src,
                                      int32_t plc2Nvalue, const std::vector<std::string> &trustKeys,
                                      std::string &error) {
  io::TrustedKeys trust;
  if (!io::loadTrustedKeys(trustKeys, trust, error)) return nullptr;
  return io::loadAot(soPath, io::aotExpectOf(src, plc2Nvalue), trust, error);
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
  std::string error;
  io::SigningKey key;
  if (a.signKey.empty()) {
    std::string keyPath;
    bool created = false;
    if (!io::defaultSigningKey(key, keyPath, created, error))
      return usageError("compile: signing key: " + error);
    if (created)
      std::fprintf(stderr,
                   "ladderjit: created the AOT signing key pair '%s' (private) and its .pub; "
                   "run/serve on this account trust it by default (docs/aot.md \"Trust\")\n",
                   keyPath.c_str());
  } else if (!key.loadFile(a.signKey, error)) {
    return usageError("--sign-key: " + error);
  }
  io::AotExpect id = io::aotExpectOf(src, nvalue);
  jit::AotOptions o;
  o.output = a.output;
  o.programHash = id.program;
  o.sourceHash = id.source;
  o.plc2Nvalue = nvalue;
  o.signingKey = &key;
  o.genericCpu = a.cpu == "generic";
  if (!jit::compileSharedObject(*prog, o, error)) return usageError("compile: " + error);
  return kOk;
#else
  (void)a;
  return usageError("compile is not built yet (this build has no JIT library)");
#endif
}

} // namespace lj::cli

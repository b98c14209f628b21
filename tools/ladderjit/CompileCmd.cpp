// `ladderjit compile PROGRAM -o OUT.so`: the ahead-of-time build (docs/aot.md), and the AOT
// engine of `run --engine aot:PATH` (load the .so, check who signed it and that it was built from
// PROGRAM).
#include "tools/ladderjit/Commands.h"

#include "engines/AotLoader.h"
#include "engines/LlvmBackend.h"
#include "formats/OutputFile.h"
#include "signing/AotTrust.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace lj::cli {

std::unique_ptr<Engine> loadAotEngine(const std::string &soPath, const ProgramSource &src,
                                      int32_t plc2Nvalue, const std::vector<std::string> &trustKeys,
                                      std::string &error) {
  signing::TrustedKeys trust;
  if (!signing::loadTrustedKeys(trustKeys, trust, error)) return nullptr;
  return engines::loadAot(soPath, engines::aotExpectOf(src, plc2Nvalue), trust, error);
}

int runCompile(const CompileArgs &a) {
  // Before any thread starts: SIGINT/SIGTERM/SIGHUP remove the temporary directory beside OUT
  // and kill the C compiler's process group (docs/aot.md "Time bound").
  formats::installSignalCleanup();
  if (a.cpu != "host" && a.cpu != "generic")
    return usageError("--cpu: expected host or generic, got '" + a.cpu + "'");
  unsigned ccTimeoutS = jit::kDefaultCcTimeoutS;
  std::string error;
  if (!a.ccTimeout.empty()) {
    if (!jit::parseCcTimeout(a.ccTimeout, ccTimeoutS, error))
      return usageError("--cc-timeout: " + error);
  } else if (const char *env = std::getenv("LADDERJIT_CC_TIMEOUT"); env && *env) {
    if (!jit::parseCcTimeout(env, ccTimeoutS, error))
      return usageError("LADDERJIT_CC_TIMEOUT: " + error);
  }
  int code = kOk;
  ProgramSource src;
  if (!readProgram(a.program, src, code, a.dialect)) return code;
  int32_t nvalue = effectiveNvalue(src, a.plc2Nvalue, a.plc2NvalueGiven);
  std::optional<VerifiedProgram> prog = loadProgram(src, nvalue, code);
  if (!prog) return code;
  const engines::LlvmBackend *llvm = engines::llvmBackend(error);
  if (!llvm) return usageError("compile: " + error);
  signing::SigningKey key;
  if (a.signKey.empty()) {
    std::string keyPath;
    bool created = false;
    if (!signing::defaultSigningKey(key, keyPath, created, error))
      return usageError("compile: signing key: " + error);
    if (created)
      std::fprintf(stderr,
                   "ladderjit: created the AOT signing key pair '%s' (private) and its .pub; "
                   "run/serve on this account trust it by default (docs/aot.md \"Trust\")\n",
                   keyPath.c_str());
  } else if (!key.loadFile(a.signKey, error)) {
    return usageError("--sign-key: " + error);
  }
  // Built in a private directory OUT.XXXXXX beside OUT (the C compiler's files too), then
  // renamed over OUT; the one output-file function of every command (formats/OutputFile.h).
  formats::OutputFile out;
  if (!out.open(a.output, error)) return usageError("compile: -o: " + error);
  engines::AotExpect id = engines::aotExpectOf(src, nvalue);
  std::atomic<int> ccGroup{0};
  formats::registerProcessGroup(&ccGroup);
  jit::AotOptions o;
  o.output = out.tempPath();
  o.tempDir = o.output.substr(0, o.output.rfind('/'));
  o.ccTimeoutS = ccTimeoutS;
  o.ccProcessGroup = &ccGroup;
  o.programHash = id.program;
  o.sourceHash = id.source;
  o.plc2Nvalue = nvalue;
  o.signingKey = &key;
  o.genericCpu = a.cpu == "generic";
  bool ok = llvm->compileSharedObject(*prog, o, error);
  formats::unregisterProcessGroup(&ccGroup);
  if (ok) ok = out.commit(error);
  if (!ok) return usageError("compile: " + error); // `out` removes the temporary directory
  return kOk;
}

} // namespace lj::cli

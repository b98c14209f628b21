// `ladderjit compile PROGRAM -o OUT.so`: the ahead-of-time build (docs/aot.md), and the AOT
// engine of `run --engine aot:PATH` (load the .so, check who signed it and that it was built from
// PROGRAM).
#include "tools/ladderjit/Commands.h"

#include "engines/AotLoader.h"
#include "engines/AotTrust.h"
#include "engines/LlvmBackend.h"

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
  io::TrustedKeys trust;
  if (!io::loadTrustedKeys(trustKeys, trust, error)) return nullptr;
  return io::loadAot(soPath, io::aotExpectOf(src, plc2Nvalue), trust, error);
}

namespace {

// `-o OUT` may name a new file or a regular file it replaces; never a device, FIFO, directory
// or symlink (`compile -o /dev/full` as root once replaced the device node).
bool outputReplaceable(const std::string &out, std::string &error) {
  struct stat st;
  if (::lstat(out.c_str(), &st) != 0) {
    if (errno == ENOENT) return true;
    error = "cannot write '" + out + "': " + std::strerror(errno);
    return false;
  }
  if (S_ISREG(st.st_mode)) return true;
  error = "-o: '" + out + "' exists and is not a regular file (" +
          (S_ISLNK(st.st_mode)   ? "a symbolic link"
           : S_ISDIR(st.st_mode) ? "a directory"
                                 : "a device, FIFO or socket") +
          "); refusing to replace it";
  return false;
}

} // namespace

int runCompile(const CompileArgs &a) {
  if (a.cpu != "host" && a.cpu != "generic")
    return usageError("--cpu: expected host or generic, got '" + a.cpu + "'");
  int code = kOk;
  ProgramSource src;
  if (!readProgram(a.program, src, code, a.dialect)) return code;
  int32_t nvalue = effectiveNvalue(src, a.plc2Nvalue, a.plc2NvalueGiven);
  std::optional<VerifiedProgram> prog = loadProgram(src, nvalue, code);
  if (!prog) return code;
  std::string error;
  const engines::LlvmBackend *llvm = engines::llvmBackend(error);
  if (!llvm) return usageError("compile: " + error);
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
  if (!outputReplaceable(a.output, error)) return usageError("compile: " + error);
  // Built into a new file of a random name beside OUT (mkostemp: O_CREAT | O_EXCL), then
  // renamed over OUT: nothing planted under a predictable name is written or followed.
  std::string tmp = a.output + ".XXXXXX";
  int fd = ::mkostemp(tmp.data(), O_CLOEXEC);
  if (fd < 0)
    return usageError("compile: cannot write '" + a.output + "': " + std::strerror(errno));
  ::close(fd);
  io::AotExpect id = io::aotExpectOf(src, nvalue);
  jit::AotOptions o;
  o.output = tmp;
  o.programHash = id.program;
  o.sourceHash = id.source;
  o.plc2Nvalue = nvalue;
  o.signingKey = &key;
  o.genericCpu = a.cpu == "generic";
  bool ok = llvm->compileSharedObject(*prog, o, error);
  if (ok && !outputReplaceable(a.output, error)) ok = false;
  if (ok && std::rename(tmp.c_str(), a.output.c_str()) != 0) {
    error = "cannot write '" + a.output + "': " + std::strerror(errno);
    ok = false;
  }
  if (!ok) {
    ::unlink(tmp.c_str());
    return usageError("compile: " + error);
  }
  return kOk;
}

} // namespace lj::cli

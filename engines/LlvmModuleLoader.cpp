// llvmBackend() of `ladderjit::engines_dl` (the `ladderjit` driver): dlopen the module
// libladderjit_llvm.so on first use. It is looked for beside the running executable (the build
// tree) and in LADDERJIT_MODULE_RELDIR relative to the executable's directory (the install
// layout, lib/ladderjit next to bin/); never on a search path, so what loads is what was built
// or installed with this executable.
#include "engines/LlvmBackend.h"

#include <dlfcn.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstring>
#include <mutex>
#include <vector>

#ifndef LADDERJIT_MODULE_RELDIR
#error "LADDERJIT_MODULE_RELDIR must be defined (engines/CMakeLists.txt)"
#endif

namespace lj::engines {

namespace {

std::string executableDir() {
  std::vector<char> buf(4096);
  ssize_t n = ::readlink("/proc/self/exe", buf.data(), buf.size() - 1);
  if (n <= 0) return {};
  std::string exe(buf.data(), static_cast<size_t>(n));
  size_t slash = exe.rfind('/');
  return slash == std::string::npos ? std::string() : exe.substr(0, slash);
}

bool isFile(const std::string &path) {
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0 && S_ISREG(st.st_mode);
}

const LlvmBackend *load(std::string &error) {
  const std::string dir = executableDir();
  if (dir.empty()) {
    error = std::string("cannot find the LLVM module ") + kLlvmModuleFile +
            ": the executable's directory is unknown (/proc/self/exe)";
    return nullptr;
  }
  const std::string candidates[] = {dir + "/" + kLlvmModuleFile,
                                    dir + "/" LADDERJIT_MODULE_RELDIR "/" + kLlvmModuleFile};
  std::string path;
  for (const std::string &c : candidates)
    if (isFile(c)) {
      path = c;
      break;
    }
  if (path.empty()) {
    error = std::string("the LLVM module ") + kLlvmModuleFile + " is missing (looked for " +
            candidates[0] + " and " + candidates[1] + "); the JIT, compile and emit-llvm need it";
    return nullptr;
  }
  void *h = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!h) {
    const char *e = ::dlerror();
    error = "cannot load the LLVM module " + path + ": " + (e ? e : "unknown error");
    return nullptr;
  }
  using Entry = const LlvmModuleInfo *(*)();
  auto entry = reinterpret_cast<Entry>(::dlsym(h, kLlvmModuleSymbol));
  const LlvmModuleInfo *info = entry ? entry() : nullptr;
  if (!info) {
    error = path + " is not a ladderjit LLVM module (no " + kLlvmModuleSymbol + ")";
    ::dlclose(h);
    return nullptr;
  }
  if (info->interfaceVersion != kLlvmInterfaceVersion || !info->buildTag ||
      std::strcmp(info->buildTag, llvmBuildTag()) != 0 || !info->backend) {
    error = "the LLVM module " + path + " belongs to another build of ladderjit (module: '" +
            (info->buildTag ? info->buildTag : "?") + "', interface " +
            std::to_string(info->interfaceVersion) + "; this ladderjit: '" + llvmBuildTag() +
            "', interface " + std::to_string(kLlvmInterfaceVersion) + ")";
    // Not dlclosed: its constructors ran and may have registered exit handlers.
    return nullptr;
  }
  return info->backend; // the module stays loaded for the life of the process
}

} // namespace

const LlvmBackend *llvmBackend(std::string &error) {
  static std::once_flag once;
  static const LlvmBackend *backend = nullptr;
  static std::string loadError;
  std::call_once(once, [] { backend = load(loadError); });
  if (!backend) error = loadError;
  return backend;
}

} // namespace lj::engines

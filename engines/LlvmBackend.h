// Everything that needs LLVM, behind one small interface (docs/architecture.md "The LLVM
// module"): the JIT, its sessions and object cache, the AOT build and emit-llvm. Two providers
// define llvmBackend(): `ladderjit::engines` links jit/ and lowering/ in (tests, benchmarks,
// fuzz binaries); the `ladderjit` driver links `ladderjit::engines_dl` instead, which dlopens
// the module libladderjit_llvm.so on first use, so a command that never compiles (serve's
// interpreter-first start, run --engine interp, check) never loads libLLVM.
#pragma once

#include "ir/Engine.h"
#include "ir/Program.h"
#include "jit/Aot.h"
#include "jit/Jit.h"

#include <cstdint>
#include <memory>
#include <string>

namespace lj::engines {

class LlvmBackend {
public:
  virtual ~LlvmBackend() = default;
  /// jit::compile.
  virtual std::unique_ptr<Engine> compile(const VerifiedProgram &prog, const jit::JitOptions &opts,
                                          std::string &error,
                                          jit::CompileTimes *times = nullptr) const = 0;
  /// jit::Session::create, and Session::enableIncremental when `incremental`.
  virtual std::shared_ptr<jit::Session> createSession(jit::Tier tier, bool incremental,
                                                      std::string &error) const = 0;
  /// jit::Session::compile.
  virtual std::unique_ptr<Engine> compileInSession(jit::Session &session,
                                                   const VerifiedProgram &prog,
                                                   const jit::JitOptions &opts,
                                                   std::string &error) const = 0;
  /// jit::emitLlvm.
  virtual bool emitLlvm(const VerifiedProgram &prog, int optLevel, std::string &out,
                        std::string &error) const = 0;
  /// jit::compileSharedObject.
  virtual bool compileSharedObject(const VerifiedProgram &prog, const jit::AotOptions &opts,
                                   std::string &error) const = 0;
  /// jit::ObjectCache::fromEnvironment.
  virtual std::shared_ptr<jit::ObjectCache> cacheFromEnvironment() const = 0;
  /// jit::programDigest.
  virtual std::string programDigest(const VerifiedProgram &prog) const = 0;
};

/// The backend, loaded on the first call (later calls return the same one, or the same error;
/// safe from several threads). Null with `error` set, naming the module file, when the module
/// is missing, cannot be loaded or belongs to another build of ladderjit.
const LlvmBackend *llvmBackend(std::string &error);

/// The linked-in backend (engines/LlvmBackendImpl.cpp over jit/), what the module exports.
const LlvmBackend &linkedLlvmBackend();

/// The module's file name, and the one symbol it exports: `extern "C" const LlvmModuleInfo
/// *ladderjit_llvm_module(void)`.
inline constexpr const char *kLlvmModuleFile = "libladderjit_llvm.so";
inline constexpr const char *kLlvmModuleSymbol = "ladderjit_llvm_module";
/// Raised whenever LlvmBackend or a type it passes changes shape.
inline constexpr uint32_t kLlvmInterfaceVersion = 1;

/// What the module's entry returns. The loader reads `interfaceVersion` and `buildTag` (plain C
/// data) before it touches `backend`.
struct LlvmModuleInfo {
  uint32_t interfaceVersion;
  /// llvmBuildTag() of the module's build.
  const char *buildTag;
  const LlvmBackend *backend;
};

/// This build's identity (the ladderjit version, a per-build-tree id and the sizes of the types
/// crossing the interface): the module and the driver must say the same.
const char *llvmBuildTag();

} // namespace lj::engines

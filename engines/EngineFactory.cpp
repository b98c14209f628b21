// The one engine factory (engines/EngineSpec.h): the interpreter, the JIT (own or shared
// session) and AOT shared objects (loaded, or built into a temp file and loaded).
#include "engines/AotLoader.h"
#include "engines/EngineSpec.h"
#include "engines/LlvmBackend.h"

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <unistd.h>

namespace lj::engines {

namespace {

Status engineFailed(std::string message) {
  return Status::error(ErrorCode::EngineFailed, std::move(message));
}

/// `ladderjit compile` into the temp directory, then load it like `run --engine aot:` does; the
/// file is unlinked at once (the mapping stays valid).
Result<std::unique_ptr<Engine>> buildAndLoadAot(const VerifiedProgram &prog,
                                                const EngineOptions &opts) {
  std::string error;
  const LlvmBackend *llvm = llvmBackend(error);
  if (!llvm) return engineFailed(error);
  static std::atomic<uint64_t> counter{0};
  const char *tmp = std::getenv("TMPDIR");
  jit::AotOptions o;
  o.output = std::string(tmp && *tmp ? tmp : "/tmp") + "/ladderjit-aot-" +
             std::to_string(getpid()) + "-" + std::to_string(counter++) + ".so";
  o.programHash = "sha256:" + llvm->programDigest(prog);
  signing::SigningKey ownKey;
  signing::TrustedKeys ownTrust;
  const signing::TrustedKeys *trust = opts.aotTrust;
  o.signingKey = opts.aotSigningKey;
  if (!o.signingKey || !trust) {
    if (!ownKey.generate(error)) return engineFailed(error);
    ownTrust.addRaw(ownKey.publicRaw());
    o.signingKey = &ownKey;
    trust = &ownTrust;
  }
  if (!llvm->compileSharedObject(prog, o, error)) return engineFailed(error);
  std::unique_ptr<Engine> e = engines::loadAot(o.output, {o.programHash}, *trust, error);
  std::remove(o.output.c_str());
  if (!e) return engineFailed(error);
  return e;
}

} // namespace

const char *engineKindName(EngineKind kind) {
  switch (kind) {
  case EngineKind::Interp:
    return "interp";
  case EngineKind::Jit:
    return "jit";
  case EngineKind::Aot:
    return "aot";
  }
  return "interp";
}

Result<EngineSpec> parseEngineSpec(std::string_view text) {
  if (text == "interp") return EngineSpec{EngineKind::Interp, {}};
  if (text == "jit") return EngineSpec{EngineKind::Jit, {}};
  if (text.substr(0, 4) == "aot:") {
    if (text.size() == 4)
      return Status::error(ErrorCode::InvalidArgument, "--engine aot: needs a path (aot:PATH.so)");
    return EngineSpec{EngineKind::Aot, std::string(text.substr(4))};
  }
  return Status::error(ErrorCode::InvalidArgument,
                       "--engine: expected interp, jit or aot:PATH.so, got '" + std::string(text) +
                           "'");
}

Result<std::unique_ptr<Engine>> makeEngine(const EngineSpec &spec, const VerifiedProgram &prog,
                                           const EngineOptions &opts) {
  std::string error;
  std::unique_ptr<Engine> e;
  if (spec.kind == EngineKind::Aot && !opts.forces.empty())
    return engineFailed("aot: forcing needs recompilation, which an AOT .so cannot do");
  if (spec.kind == EngineKind::Aot && opts.trace)
    return engineFailed("aot: a .so is never traced; the live view needs --engine jit or interp");
  switch (spec.kind) {
  case EngineKind::Interp:
    return makeInterpreterEngine(prog, opts.forces, opts.trace);
  case EngineKind::Jit: {
    const LlvmBackend *llvm = llvmBackend(error);
    if (!llvm) return engineFailed(error);
    jit::JitOptions jo;
    jo.forces = opts.forces;
    jo.trace = opts.trace;
    jo.quickLeaves = opts.quickLeaves;
    jo.times = opts.times;
    jo.tier = opts.fastTier ? jit::Tier::Fast : jit::Tier::Optimizing;
    if (opts.session) {
      e = llvm->compileInSession(*opts.session, prog, jo, error);
    } else {
      jo.cache = opts.cache;
      if (!jo.cache && opts.cacheFromEnvironment) jo.cache = llvm->cacheFromEnvironment();
      e = llvm->compile(prog, jo, error);
    }
    break;
  }
  case EngineKind::Aot:
    if (spec.soPath.empty()) return buildAndLoadAot(prog, opts);
    if (!opts.aotExpect || !opts.aotTrust)
      return engineFailed("aot: loading " + spec.soPath +
                          " needs the expected program and the trusted keys");
    e = engines::loadAot(spec.soPath, *opts.aotExpect, *opts.aotTrust, error);
    break;
  }
  if (!e) return engineFailed(error);
  return e;
}

} // namespace lj::engines

// The JIT as the fuzzer's engine under test, built by the one engine factory (engines/).
#include "fuzz/Differential.h"
#include "fuzz/Fuzz.h"

#include "engines/EngineSpec.h"
#include "engines/LlvmBackend.h"

#include <array>
#include <memory>

namespace lj::fuzz {

EngineFactory jitFactory() {
  // One JIT session per tier for the whole campaign, as serve keeps one for all versions of a
  // program: each program is still compiled on its own (own JITDylib, own TargetMachine and
  // context per partition, jit/OrcSession.cpp), only the LLJIT, its host detection and its
  // runtime JITDylib are not rebuilt ~2 x 100,000 times. An engine keeps its session alive.
  auto sessions = std::make_shared<std::array<std::shared_ptr<jit::Session>, 2>>();
  return [sessions](const VerifiedProgram &prog, bool fastTier, std::string &error) {
    std::shared_ptr<jit::Session> &session = (*sessions)[fastTier ? 1 : 0];
    if (!session) {
      const engines::LlvmBackend *llvm = engines::llvmBackend(error);
      if (!llvm) return std::unique_ptr<Engine>();
      session =
          llvm->createSession(fastTier ? jit::Tier::Fast : jit::Tier::Optimizing, false, error);
      if (!session) return std::unique_ptr<Engine>();
    }
    engines::EngineOptions o;
    o.fastTier = fastTier;
    o.session = session.get();
    Result<std::unique_ptr<Engine>> e =
        engines::makeEngine({engines::EngineKind::Jit, {}}, prog, o);
    if (!e) {
      error = e.status().message();
      return std::unique_ptr<Engine>();
    }
    return std::move(e).value();
  };
}

std::unique_ptr<Engine> tracedJit(const VerifiedProgram &prog, bool fastTier, int32_t *trace,
                                  std::string &error) {
  engines::EngineOptions o;
  o.fastTier = fastTier;
  o.trace = trace;
  Result<std::unique_ptr<Engine>> e = engines::makeEngine({engines::EngineKind::Jit, {}}, prog, o);
  if (!e) {
    error = e.status().message();
    return nullptr;
  }
  return std::move(e).value();
}

} // namespace lj::fuzz

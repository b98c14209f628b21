// The JIT as the fuzzer's engine under test, built by the one engine factory (engines/).
#include "fuzz/Differential.h"
#include "fuzz/Fuzz.h"

#include "engines/EngineSpec.h"

namespace lj::fuzz {

EngineFactory jitFactory() {
  return [](const VerifiedProgram &prog, bool fastTier, std::string &error) {
    engines::EngineOptions o;
    o.fastTier = fastTier;
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

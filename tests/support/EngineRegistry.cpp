// The one place where engines are registered for the execution tests; each is built by the
// engine factory (engines/EngineSpec.h) exactly as the CLI builds it.
#include "tests/support/EngineRegistry.h"

#include "engines/EngineSpec.h"

namespace lj::test {

namespace {

MakeEngineFn fromFactory(engines::EngineSpec spec) {
  return [spec](const VerifiedProgram &p, std::string &error) -> std::unique_ptr<Engine> {
    Result<std::unique_ptr<Engine>> e = engines::makeEngine(spec, p);
    if (!e) {
      error = e.status().message();
      return nullptr;
    }
    return std::move(e).value();
  };
}

} // namespace

const std::vector<EngineFactory> &registeredEngines() {
  static const std::vector<EngineFactory> kEngines = {
      // The reference interpreter (the oracle); keep it first: cross-engine checks compare every
      // other engine against entry 0.
      {"interp", fromFactory({engines::EngineKind::Interp, {}})},
      {"jit", fromFactory({engines::EngineKind::Jit, {}})},
      // AOT through the whole path of `ladderjit compile` + `run --engine aot:`: a shared object
      // in the temp directory, loaded (checks included) and unlinked at once.
      {"aot", fromFactory({engines::EngineKind::Aot, {}})},
  };
  return kEngines;
}

} // namespace lj::test

// The one place where engines are registered for the execution tests; each is built by the
// engine factory (engines/EngineSpec.h) exactly as the CLI builds it.
#include "tests/support/EngineRegistry.h"

#include "engines/EngineSpec.h"
#include "signing/AotTrust.h"

#include <cstdlib>

namespace lj::test {

namespace {

MakeEngineFn fromFactory(engines::EngineSpec spec, bool signWithTestKey = false) {
  return [spec, signWithTestKey](const VerifiedProgram &p,
                                 std::string &error) -> std::unique_ptr<Engine> {
    engines::EngineOptions o;
    if (signWithTestKey) {
      o.aotSigningKey = &testSigningKey();
      o.aotTrust = &testTrust();
    }
    Result<std::unique_ptr<Engine>> e = engines::makeEngine(spec, p, o);
    if (!e) {
      error = e.status().message();
      return nullptr;
    }
    return std::move(e).value();
  };
}

} // namespace

const signing::SigningKey &testSigningKey() {
  static const signing::SigningKey key = [] {
    signing::SigningKey k;
    std::string error;
    if (!k.generate(error)) std::abort(); // OpenSSL without Ed25519: nothing can be signed
    return k;
  }();
  return key;
}

const signing::TrustedKeys &testTrust() {
  static const signing::TrustedKeys trust = [] {
    signing::TrustedKeys t;
    t.addRaw(testSigningKey().publicRaw());
    return t;
  }();
  return trust;
}

const std::vector<EngineFactory> &registeredEngines() {
  static const std::vector<EngineFactory> kEngines = {
      // The reference interpreter (the oracle); keep it first: cross-engine checks compare every
      // other engine against entry 0.
      {"interp", fromFactory({engines::EngineKind::Interp, {}})},
      {"jit", fromFactory({engines::EngineKind::Jit, {}})},
      // AOT through the whole path of `ladderjit compile` + `run --engine aot:`: a shared object
      // in the temp directory, signed with the test key, loaded (checks included) and unlinked
      // at once.
      {"aot", fromFactory({engines::EngineKind::Aot, {}}, true)},
  };
  return kEngines;
}

} // namespace lj::test

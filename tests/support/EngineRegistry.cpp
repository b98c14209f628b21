// The one place where engines are registered for the execution tests.
#include "tests/support/EngineRegistry.h"

#include "jit/Jit.h"

namespace lj::test {

const std::vector<EngineFactory> &registeredEngines() {
  static const std::vector<EngineFactory> kEngines = {
      // The reference interpreter (the oracle); keep it first: cross-engine checks compare every
      // other engine against entry 0.
      {"interp", [](const VerifiedProgram &p, std::string &) { return makeInterpreterEngine(p); }},
      // REGISTRATION POINT: add one line per engine, e.g. (with #include "jit/Jit.h")
      // {"jit", [](const VerifiedProgram &p, std::string &e) { return jit::compile(p, {}, e); }},
      {"jit", [](const VerifiedProgram &p, std::string &e) { return jit::compile(p, {}, e); }},
  };
  return kEngines;
}

} // namespace lj::test

// The one place where engines are registered for the execution tests.
#include "tests/support/EngineRegistry.h"

#include "engines/AotLoader.h"
#include "jit/Aot.h"
#include "jit/Jit.h"
#include "jit/ObjectCache.h"

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <unistd.h>

namespace lj::test {

namespace {

// AOT through the whole path of `ladderjit compile` + `run --engine aot:`: a shared object in
// the temp directory, loaded (checks included) and unlinked at once (the mapping stays valid).
std::unique_ptr<Engine> makeAotEngine(const VerifiedProgram &p, std::string &error) {
  static std::atomic<uint64_t> counter{0};
  const char *tmp = std::getenv("TMPDIR");
  jit::AotOptions o;
  o.output = std::string(tmp && *tmp ? tmp : "/tmp") + "/ladderjit-test-" +
             std::to_string(getpid()) + "-" + std::to_string(counter++) + ".so";
  o.programHash = "sha256:" + jit::programDigest(p);
  if (!jit::compileSharedObject(p, o, error)) return nullptr;
  std::unique_ptr<Engine> e = io::loadAot(o.output, o.programHash, error);
  std::remove(o.output.c_str());
  return e;
}

} // namespace

const std::vector<EngineFactory> &registeredEngines() {
  static const std::vector<EngineFactory> kEngines = {
      // The reference interpreter (the oracle); keep it first: cross-engine checks compare every
      // other engine against entry 0.
      {"interp", [](const VerifiedProgram &p, std::string &) { return makeInterpreterEngine(p); }},
      // REGISTRATION POINT: add one line per engine, e.g. (with #include "jit/Jit.h")
      // {"jit", [](const VerifiedProgram &p, std::string &e) { return jit::compile(p, {}, e); }},
      {"jit", [](const VerifiedProgram &p, std::string &e) { return jit::compile(p, {}, e); }},
      {"aot", makeAotEngine},
  };
  return kEngines;
}

} // namespace lj::test

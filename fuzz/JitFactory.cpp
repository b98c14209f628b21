// The JIT as the fuzzer's engine under test. Compiled with LADDERJIT_HAVE_JIT only when the
// ladderjit_jit target exists, so the fuzz library (and the CLI) build before the JIT lands.
#include "fuzz/Fuzz.h"

#include "ir/Engine.h"

#ifdef LADDERJIT_HAVE_JIT
#include "jit/Jit.h"
#endif

namespace lj::fuzz {

#ifdef LADDERJIT_HAVE_JIT

bool haveJit() { return true; }

EngineFactory jitFactory() {
  return [](const VerifiedProgram &prog, bool fastTier, std::string &error) {
    jit::JitOptions o;
    o.tier = fastTier ? jit::Tier::Fast : jit::Tier::Optimizing;
    return jit::compile(prog, o, error);
  };
}

#else

bool haveJit() { return false; }

EngineFactory jitFactory() {
  return [](const VerifiedProgram &, bool, std::string &error) -> std::unique_ptr<Engine> {
    error = "this build has no JIT (target ladderjit_jit was missing at configure time)";
    return nullptr;
  };
}

#endif

} // namespace lj::fuzz

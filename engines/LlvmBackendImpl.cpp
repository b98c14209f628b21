// The LLVM backend over jit/ (engines/LlvmBackend.h): linked into `ladderjit::engines` and
// into the module libladderjit_llvm.so, so both providers run the very same code.
#include "engines/LlvmBackend.h"

#include "jit/Aot.h"
#include "jit/Jit.h"
#include "jit/ObjectCache.h"

namespace lj::engines {

namespace {

class JitBackend final : public LlvmBackend {
public:
  std::unique_ptr<Engine> compile(const VerifiedProgram &prog, const jit::JitOptions &opts,
                                  std::string &error, jit::CompileTimes *times) const override {
    return jit::compile(prog, opts, error, times);
  }
  std::shared_ptr<jit::Session> createSession(jit::Tier tier, bool incremental,
                                              std::string &error) const override {
    std::shared_ptr<jit::Session> s = jit::Session::create(tier, error);
    if (s && incremental) s->enableIncremental();
    return s;
  }
  std::unique_ptr<Engine> compileInSession(jit::Session &session, const VerifiedProgram &prog,
                                           const jit::JitOptions &opts,
                                           std::string &error) const override {
    return session.compile(prog, opts, error);
  }
  bool emitLlvm(const VerifiedProgram &prog, int optLevel, std::string &out,
                std::string &error) const override {
    return jit::emitLlvm(prog, optLevel, out, error);
  }
  bool compileSharedObject(const VerifiedProgram &prog, const jit::AotOptions &opts,
                           std::string &error) const override {
    return jit::compileSharedObject(prog, opts, error);
  }
  std::shared_ptr<jit::ObjectCache> cacheFromEnvironment() const override {
    return jit::ObjectCache::fromEnvironment();
  }
  std::string programDigest(const VerifiedProgram &prog) const override {
    return jit::programDigest(prog);
  }
};

} // namespace

const LlvmBackend &linkedLlvmBackend() {
  static const JitBackend backend;
  return backend;
}

} // namespace lj::engines

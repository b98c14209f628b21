// The two free functions of the facade: compile() on a fresh Session, and emitLlvm() for the
// `ladderjit emit-llvm` dump (lowered IR after the -O level's pipeline, names kept; -O2 is exactly
// the optimizing tier's, -O0 the fast tier's).
#include "jit/Jit.h"
#include "jit/Pipeline.h"
#include "lowering/Lower.h"

#include <llvm/IR/LLVMContext.h>
#include <llvm/Support/raw_ostream.h>

namespace lj::jit {

std::unique_ptr<Engine> compile(const VerifiedProgram &prog, const JitOptions &opts,
                                std::string &error, CompileTimes *times) {
  // A session per engine: the engine owns its JIT, and creating one costs about a millisecond.
  std::shared_ptr<Session> session = Session::create(opts.tier, error);
  if (!session) return nullptr;
  return session->compile(prog, opts, error, times);
}

bool emitLlvm(const VerifiedProgram &prog, int optLevel, std::string &out, std::string &error) {
  if (optLevel < 0 || optLevel > 3) {
    error = "optimization level must be 0..3";
    return false;
  }
  auto tm = hostTargetMachine(optLevel == 0 ? llvm::CodeGenOptLevel::None
                                            : llvm::CodeGenOptLevel::Default);
  if (!tm) {
    error = llvm::toString(tm.takeError());
    return false;
  }
  llvm::LLVMContext ctx;
  lower::LowerOptions lo;
  lo.readableNames = true;
  if (optLevel > 0) mergeChunksAsOptimizingBuild(lo); // as a whole optimizing build
  auto mod =
      lower::lowerProgram(prog, ctx, (*tm)->createDataLayout(), (*tm)->getTargetTriple().str(), lo);
  if (!mod) {
    error = llvm::toString(mod.takeError());
    return false;
  }
  optimizeModule(**mod, optLevel, tm->get());
  out.clear();
  llvm::raw_string_ostream os(out);
  (*mod)->print(os, nullptr);
  return true;
}

} // namespace lj::jit

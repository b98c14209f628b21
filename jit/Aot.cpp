// `ladderjit compile`: lower a program exactly as the JIT's optimizing tier does (one module),
// generate a position-independent object for the host or a generic CPU, and hand it to the
// linker half (AotLink.cpp). Every symbol of the object is hidden: only the shim exports.
#include "jit/Aot.h"
#include "jit/AotInternal.h"
#include "jit/Jit.h"
#include "jit/Pipeline.h"
#include "lowering/Lower.h"

#include <llvm/ExecutionEngine/Orc/CompileUtils.h>
#include <llvm/ExecutionEngine/Orc/JITTargetMachineBuilder.h>
#include <llvm/IR/LLVMContext.h>
#include <llvm/TargetParser/SubtargetFeature.h>

namespace lj::jit {

bool isProgramHash(const std::string &hash) {
  if (hash.size() != 71 || hash.compare(0, 7, "sha256:") != 0) return false;
  for (size_t i = 7; i < hash.size(); ++i) {
    char c = hash[i];
    if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'))) return false;
  }
  return true;
}

namespace {

// The optimizing tier's code generator settings (OrcSession.cpp createImpl), PIC for a .so.
llvm::Expected<std::unique_ptr<llvm::TargetMachine>> aotTargetMachine(bool generic) {
  initNativeTarget();
  auto jtmb = llvm::orc::JITTargetMachineBuilder::detectHost();
  if (!jtmb) return jtmb.takeError();
  if (generic) {
    // The architecture's baseline: x86-64 = SSE2, no later extensions.
    jtmb->setCPU(jtmb->getTargetTriple().isX86() ? "x86-64" : "generic");
    jtmb->getFeatures() = llvm::SubtargetFeatures();
  }
  jtmb->setCodeGenOptLevel(llvm::CodeGenOptLevel::Less);
  jtmb->setRelocationModel(llvm::Reloc::PIC_);
  jtmb->setCodeModel(llvm::CodeModel::Small);
  return jtmb->createTargetMachine();
}

} // namespace

bool compileSharedObject(const VerifiedProgram &prog, const AotOptions &opts, std::string &error) {
  if (!isProgramHash(opts.programHash)) {
    error = "bad program hash '" + opts.programHash + "' (expected sha256: and 64 hex digits)";
    return false;
  }
  if (!opts.signingKey) {
    error = "no signing key";
    return false;
  }
  auto tm = aotTargetMachine(opts.genericCpu);
  if (!tm) {
    error = "cannot create the target machine: " + llvm::toString(tm.takeError());
    return false;
  }
  CompileTimes t;
  double t0 = nowUs();
  llvm::LLVMContext ctx;
  ctx.setDiscardValueNames(true);
  lower::LowerOptions lo;
  lo.chunkStatements = opts.chunkStatements;
  mergeChunksAsOptimizingBuild(lo); // AOT is a whole build at the optimizing tier
  lo.readableNames = false;
  auto mod =
      lower::lowerProgram(prog, ctx, (*tm)->createDataLayout(), (*tm)->getTargetTriple().str(), lo);
  if (!mod) {
    error = llvm::toString(mod.takeError());
    return false;
  }
  // Nothing of the program is part of the .so's interface: hidden symbols bind locally in the
  // link and never reach the dynamic symbol table (the version script is the second guard).
  for (llvm::GlobalValue &g : (*mod)->global_values())
    if (!g.isDeclaration() && g.hasExternalLinkage())
      g.setVisibility(llvm::GlobalValue::HiddenVisibility);
  double t1 = nowUs();
  t.lowerUs = t1 - t0;
  optimizeModule(**mod, 2, tm->get());
  double t2 = nowUs();
  t.optimizeUs = t2 - t1;
  llvm::orc::SimpleCompiler compiler(**tm);
  auto obj = compiler(**mod);
  if (!obj) {
    error = "code generation failed: " + llvm::toString(obj.takeError());
    return false;
  }
  double t3 = nowUs();
  t.codegenUs = t3 - t2;
  t.objectBytes = (*obj)->getBufferSize();
  uint32_t slices = prog.slices.empty() ? 1u : static_cast<uint32_t>(prog.slices.size());
  bool ok = detail::linkSharedObject((*obj)->getBuffer(), opts, slices, error);
  t.linkUs = nowUs() - t3;
  if (opts.times) *opts.times = t;
  return ok;
}

} // namespace lj::jit

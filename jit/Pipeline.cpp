// Native target setup, host TargetMachine and the PassBuilder pipelines (llvm19-orc-notes 3, 9).
#include "jit/Pipeline.h"

#include "jit/Jit.h"
#include "lowering/Lower.h"

#include <llvm/Analysis/ValueTracking.h>
#include <llvm/ExecutionEngine/Orc/JITTargetMachineBuilder.h>
#include <llvm/IR/IRBuilder.h>
#include <llvm/IR/PatternMatch.h>
#include <llvm/Passes/PassBuilder.h>
#include <llvm/Support/CommandLine.h>
#include <llvm/Support/TargetSelect.h>
#include <llvm/Transforms/InstCombine/InstCombine.h>
#include <llvm/Transforms/Scalar/SimplifyCFG.h>
#include <llvm/Transforms/Utils/BasicBlockUtils.h>
#include <llvm/Transforms/Utils/Local.h>
#include <llvm/Transforms/Vectorize/SLPVectorizer.h>

#include <chrono>
#include <mutex>

namespace lj::jit {

namespace {

/// The bit a value may carry: `v` is known to be 0 or a single bit M, returned as M (0: no).
uint64_t singleBitOf(llvm::Value *v, const llvm::DataLayout &dl) {
  if (llvm::isa<llvm::Constant>(v)) return 0;
  const llvm::KnownBits kb = llvm::computeKnownBits(v, dl);
  const llvm::APInt maybe = ~kb.Zero;
  return maybe.popcount() == 1 ? maybe.getZExtValue() : 0;
}

/// The i1 that a value holding 0 or a single bit was made from (zext, or shl of a zext, as
/// lowering/EmitBasic.cpp's coils write it); null when it was computed otherwise.
llvm::Value *conditionOf(llvm::Value *y) {
  using namespace llvm::PatternMatch;
  llvm::Value *c = nullptr;
  if (match(y, m_ZExt(m_Value(c))) || match(y, m_Shl(m_ZExt(m_Value(c)), m_ConstantInt())))
    return c->getType()->isIntegerTy(1) ? c : nullptr;
  return nullptr;
}

/// One coil write found by CoilDiamonds: the store, the i1 it depends on, the old element and
/// the two values it stores when the i1 is 1 / 0.
struct CoilWrite {
  llvm::StoreInst *store;
  llvm::Value *cond, *old;
  uint64_t mask;
  enum Kind { Out, Set, Reset } kind;
};

/// Before InstCombine: each coil's write of its element (lowering/EmitBasic.cpp emitCoil) as a
/// diamond on ST0 whose arms store the old element with the bit set / cleared; SimplifyCFG then
/// folds each diamond back into a select between those two values, after InstCombine, which
/// would otherwise have turned the select into (old & ~M) | zext(ST0) << k (docs/BENCHMARKS.md
/// "Shape corpus"). As a select, the stored value depends on the old element only and the
/// cmov waits for ST0 alone: every later reader of the element no longer waits for the rung's
/// logic through a zext/shift/or chain. Matched on stored values, with Y known to be 0 or the
/// single bit M and made from an i1 C:
///   (X & ~M) | Y  -> C ? X | M : X & ~M      (OUT, OUT NOT: C is then the negated ST0)
///   X | Y         -> C ? X | M : X           (SET)
///   X & ~Y        -> C ? X & ~M : X          (RST)
struct CoilDiamonds : llvm::PassInfoMixin<CoilDiamonds> {
  llvm::PreservedAnalyses run(llvm::Function &f, llvm::FunctionAnalysisManager &) {
    using namespace llvm::PatternMatch;
    const llvm::DataLayout &dl = f.getDataLayout();
    std::vector<CoilWrite> found;
    for (llvm::BasicBlock &bb : f)
      for (llvm::Instruction &inst : bb) {
        auto *st = llvm::dyn_cast<llvm::StoreInst>(&inst);
        if (!st || !st->getValueOperand()->getType()->isIntegerTy() || st->isVolatile()) continue;
        llvm::Value *v = st->getValueOperand(), *a = nullptr, *b = nullptr;
        if (!v->hasOneUse() || v->getType()->getIntegerBitWidth() > 32) continue;
        if (match(v, m_Or(m_Value(a), m_Value(b)))) {
          for (int side = 0; side < 2; ++side) {
            llvm::Value *p = side ? b : a, *y = side ? a : b;
            const uint64_t m = singleBitOf(y, dl);
            llvm::Value *c = m ? conditionOf(y) : nullptr;
            if (!c) continue;
            llvm::Value *x = nullptr;
            const llvm::APInt *k = nullptr;
            if (match(p, m_And(m_Value(x), m_APInt(k))) && (~*k).getZExtValue() == m)
              found.push_back({st, c, x, m, CoilWrite::Out});
            else
              found.push_back({st, c, p, m, CoilWrite::Set});
            break;
          }
        } else if (match(v, m_c_And(m_Value(a), m_Not(m_Value(b))))) {
          const uint64_t m = singleBitOf(b, dl);
          if (llvm::Value *c = m ? conditionOf(b) : nullptr)
            found.push_back({st, c, a, m, CoilWrite::Reset});
        }
      }
    for (const CoilWrite &w : found) {
      llvm::Value *v = w.store->getValueOperand();
      llvm::Type *ty = v->getType();
      llvm::Instruction *thenT = nullptr, *elseT = nullptr;
      llvm::SplitBlockAndInsertIfThenElse(w.cond, w.store, &thenT, &elseT);
      llvm::IRBuilder<> ib(thenT);
      llvm::Value *on =
          w.kind == CoilWrite::Reset ? ib.CreateAnd(w.old, ~w.mask) : ib.CreateOr(w.old, w.mask);
      ib.SetInsertPoint(elseT);
      llvm::Value *off = w.kind == CoilWrite::Out ? ib.CreateAnd(w.old, ~w.mask) : w.old;
      ib.SetInsertPoint(w.store);
      llvm::PHINode *phi = ib.CreatePHI(ty, 2);
      phi->addIncoming(on, thenT->getParent());
      phi->addIncoming(off, elseT->getParent());
      w.store->setOperand(0, phi);
      llvm::RecursivelyDeleteTriviallyDeadInstructions(v);
    }
    return found.empty() ? llvm::PreservedAnalyses::all() : llvm::PreservedAnalyses::none();
  }
};

} // namespace

void initNativeTarget() {
  static std::once_flag once;
  std::call_once(once, [] {
    llvm::InitializeNativeTarget();
    llvm::InitializeNativeTargetAsmPrinter();
    llvm::InitializeNativeTargetAsmParser();
  });
}

llvm::Expected<std::unique_ptr<llvm::TargetMachine>>
hostTargetMachine(llvm::CodeGenOptLevel level) {
  initNativeTarget();
  auto jtmb = llvm::orc::JITTargetMachineBuilder::detectHost();
  if (!jtmb) return jtmb.takeError();
  jtmb->setCodeGenOptLevel(level);
  return jtmb->createTargetMachine();
}

/// The SLP vectorizer's scheduling region per block (LLVM's `-slp-schedule-budget`, 100,000 by
/// default) raised once for the process: a whole optimizing build emits many rungs into one
/// function of one block (jit/Jit.h kOptMergeIr), and at the default budget the vectorizer
/// gives up on the later bundles of such a block (deep-nesting shape: 0.87 -> 1.03 of the best
/// C; at 200,000 0.81; docs/BENCHMARKS.md "Shape corpus"). LLVM keeps the budget as a
/// command-line option; nothing else in a ladderjit process parses LLVM's options.
void raiseSlpBudget() {
  static std::once_flag once;
  std::call_once(once, [] {
    const auto &registered = llvm::cl::getRegisteredOptions();
    if (auto it = registered.find("slp-schedule-budget"); it != registered.end())
      (void)it->second->addOccurrence(0, "slp-schedule-budget", "200000");
  });
}

void mergeChunksAsOptimizingBuild(lower::LowerOptions &lo) {
  lo.mergeIr = kOptMergeIr;
  lo.mergeStores = kOptMergeStores;
  lo.mergeIndexed = kOptMergeIndexed;
}

void optimizeModule(llvm::Module &m, int level, llvm::TargetMachine *tm) {
  if (level == 2) raiseSlpBudget();
  llvm::LoopAnalysisManager lam;
  llvm::FunctionAnalysisManager fam;
  llvm::CGSCCAnalysisManager cgam;
  llvm::ModuleAnalysisManager mam;
  // The standard pipelines minus the vectorizers and the unroller: scan code is scalar byte
  // logic with a few counted loops.
  llvm::PipelineTuningOptions pto;
  pto.LoopVectorization = false;
  pto.SLPVectorization = false;
  pto.LoopUnrolling = false;
  llvm::PassBuilder pb(tm, pto);
  pb.registerModuleAnalyses(mam);
  pb.registerCGSCCAnalyses(cgam);
  pb.registerFunctionAnalyses(fam);
  pb.registerLoopAnalyses(lam);
  pb.crossRegisterProxies(lam, fam, cgam, mam);
  llvm::ModulePassManager mpm;
  if (level == 2) {
    // The optimizing tier's own pipeline. The lowering already emits SSA without allocas, one
    // load per field per block and no dead stores (ImageCache), so the one thing left to do is
    // peephole work on the bit logic. Measured on the 10,000-statement benchmark program:
    // default<O2> costs ~1.1 s of CPU and this ~0.14 s, for object code within 1% of O2's
    // size and the same scan time. No fixpoint iteration: a second round changes ~0.1%.
    // CoilDiamonds first, so that SimplifyCFG leaves each coil's write as a select (what that
    // bought per program shape: docs/BENCHMARKS.md "Shape corpus"). Then the SLP vectorizer:
    // it packs the neighbouring byte loads, logic and stores of a block (rungs on adjacent
    // image and edge-memory bytes) into vector operations; on the shape corpus it took the scan
    // below the best C compiler on 7 of 8 shapes for ~50 ms more optimizing of the 10k program
    // (same section). Its budget per block: raiseSlpBudget.
    llvm::FunctionPassManager fpm;
    fpm.addPass(CoilDiamonds());
    fpm.addPass(llvm::InstCombinePass(
        llvm::InstCombineOptions().setMaxIterations(1).setVerifyFixpoint(false)));
    fpm.addPass(llvm::SimplifyCFGPass()); // the JMP / CALL / RETN diamonds; the coils' to selects
    fpm.addPass(llvm::SLPVectorizerPass());
    mpm.addPass(llvm::createModuleToFunctionPassAdaptor(std::move(fpm)));
  } else if (level <= 0) {
    mpm = pb.buildO0DefaultPipeline(llvm::OptimizationLevel::O0);
  } else {
    mpm = pb.buildPerModuleDefaultPipeline(level == 1 ? llvm::OptimizationLevel::O1
                                                      : llvm::OptimizationLevel::O3);
  }
  mpm.run(m, mam);
}

double nowUs() {
  using namespace std::chrono;
  return duration<double, std::micro>(steady_clock::now().time_since_epoch()).count();
}

} // namespace lj::jit

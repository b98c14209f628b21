// Incremental compile (JitOptions::incremental, lowering/Incremental.h): the spine is lowered
// first, naming each leaf by its cache key; the leaves missing from the cache are lowered,
// optimized and compiled to one object each on a pool of threads (each with its own context and
// TargetMachine) while this thread compiles the spine; then everything is linked into a new
// JITDylib. Equal keys are equal code, so a leaf that occurs twice is compiled and linked once.
#include "ir/Profile.h"
#include "jit/OrcInternal.h"
#include "jit/Pipeline.h"
#include "lowering/Incremental.h"

#include <llvm/ExecutionEngine/Orc/CompileUtils.h>
#include <llvm/IR/LLVMContext.h>
#include <llvm/Passes/PassBuilder.h>
#include <llvm/Transforms/IPO/AlwaysInliner.h>

#include <algorithm>
#include <atomic>
#include <system_error>
#include <unordered_map>

namespace lj::jit {

namespace {

struct LeafJob {
  lower::Leaf leaf;
  std::string key, symbol;
  std::unique_ptr<llvm::MemoryBuffer> obj;
  bool fromCache = false;
};

struct Built {
  std::unique_ptr<llvm::MemoryBuffer> obj;
  std::string error;
  double lowerUs = 0, optimizeUs = 0;
};

/// What one compile thread spent.
struct ThreadTotals {
  double cpuUs = 0, lowerUs = 0, optimizeUs = 0;
};

lower::LowerOptions leafLowerOptions(const JitOptions &opts) {
  lower::LowerOptions lo;
  lo.chunkStatements = opts.chunkStatements;
  lo.readableNames = false;
  lo.forces = &opts.forces;
  return lo;
}

/// Optimize and compile `mod` with `tm` (the session's tier).
Built compileModule(llvm::Module &mod, llvm::TargetMachine &tm, Tier tier, Built b) {
  const double t1 = nowUs();
  if (tier == Tier::Optimizing) optimizeModule(mod, 2, &tm);
  b.optimizeUs += nowUs() - t1;
  llvm::orc::SimpleCompiler compiler(tm);
  auto obj = compiler(mod);
  if (!obj) {
    b.error = llvm::toString(obj.takeError());
    return b;
  }
  b.obj = std::move(*obj);
  return b;
}

/// The spine: the slice functions inlined into the lj_plc2 switch, then code generation as the
/// fast tier's (FastISel, no optimization): the spine only calls and dispatches, and code
/// generation costs about a millisecond per function at the optimizing tier's level.
Built compileSpine(llvm::Module &mod, llvm::orc::JITTargetMachineBuilder jtmb) {
  Built b;
  const double t1 = nowUs();
  {
    llvm::LoopAnalysisManager lam;
    llvm::FunctionAnalysisManager fam;
    llvm::CGSCCAnalysisManager cgam;
    llvm::ModuleAnalysisManager mam;
    llvm::PassBuilder pb;
    pb.registerModuleAnalyses(mam);
    pb.registerCGSCCAnalyses(cgam);
    pb.registerFunctionAnalyses(fam);
    pb.registerLoopAnalyses(lam);
    pb.crossRegisterProxies(lam, fam, cgam, mam);
    llvm::ModulePassManager mpm;
    mpm.addPass(llvm::AlwaysInlinerPass(false));
    mpm.run(mod, mam);
  }
  b.optimizeUs = nowUs() - t1;
  jtmb.setCodeGenOptLevel(llvm::CodeGenOptLevel::None);
  jtmb.getOptions().EnableFastISel = true;
  auto tm = jtmb.createTargetMachine();
  if (!tm) {
    b.error = llvm::toString(tm.takeError());
    return b;
  }
  llvm::orc::SimpleCompiler compiler(**tm);
  auto obj = compiler(mod);
  if (!obj) {
    b.error = llvm::toString(obj.takeError());
    return b;
  }
  b.obj = std::move(*obj);
  return b;
}

/// A worker: compiles jobs[todo[k]] for k taken from `next` until none is left.
void compileLeaves(const VerifiedProgram &prog, const JitOptions &opts,
                   llvm::orc::JITTargetMachineBuilder jtmb, Tier tier, std::vector<LeafJob> &jobs,
                   const std::vector<size_t> &todo, std::atomic<size_t> &next,
                   std::vector<Built> &out, ThreadTotals &sum) {
  const double c0 = threadCpuUs();
  auto tm = jtmb.createTargetMachine();
  const lower::LowerOptions lo = leafLowerOptions(opts);
  llvm::LLVMContext ctx;
  ctx.setDiscardValueNames(true);
  for (size_t k = next++; k < todo.size(); k = next++) {
    LeafJob &j = jobs[todo[k]];
    Built b;
    if (!tm) {
      b.error = llvm::toString(tm.takeError());
      out[k] = std::move(b);
      break;
    }
    const double t0 = nowUs();
    auto mod = lower::lowerLeaf(prog, j.leaf, j.symbol, ctx, (*tm)->createDataLayout(),
                                (*tm)->getTargetTriple().str(), lo);
    if (!mod) {
      b.error = llvm::toString(mod.takeError());
      out[k] = std::move(b);
      continue;
    }
    b.lowerUs = nowUs() - t0;
    out[k] = compileModule(**mod, **tm, tier, std::move(b));
    sum.lowerUs += out[k].lowerUs;
    sum.optimizeUs += out[k].optimizeUs;
  }
  sum.cpuUs = threadCpuUs() - c0;
}

} // namespace

std::unique_ptr<Engine> compileIncremental(Session &self, Session::Impl &im,
                                           const VerifiedProgram &prog, const JitOptions &opts,
                                           ObjectCache *cache, std::string &error,
                                           CompileTimes *times) {
  const double t0 = nowUs();
  const double c0 = threadCpuUs();
  CompileTimes t;
  CacheKeyInputs in{im.jtmb->getTargetTriple().str(),
                    im.jtmb->getCPU(),
                    im.jtmb->getFeatures().getString(),
                    static_cast<int>(im.tier),
                    opts.chunkStatements,
                    1,
                    {}};
  const std::string profile = prog.profile && prog.profile->name ? prog.profile->name : "";
  const std::vector<int8_t> forced = forceTable(prog, opts.forces);

  // 1. The spine, naming every leaf by its key (the symbol is the key's first 128 bits).
  std::vector<LeafJob> jobs;
  std::unordered_map<std::string, size_t> byKey;
  auto tm = im.jtmb->createTargetMachine();
  if (!tm) {
    error = llvm::toString(tm.takeError());
    return nullptr;
  }
  llvm::LLVMContext ctx;
  ctx.setDiscardValueNames(true);
  lower::LeafNamer namer = [&](const lower::Leaf &leaf) {
    std::string key = leafCacheKey(in, profile, lower::leafDigestInput(prog, leaf, forced));
    std::string symbol = "lj_g_" + key.substr(0, 32);
    if (byKey.emplace(key, jobs.size()).second) jobs.push_back({leaf, key, symbol, nullptr});
    return symbol;
  };
  lower::LowerOptions lo = leafLowerOptions(opts);
  auto spine = lower::lowerSpine(prog, ctx, (*tm)->createDataLayout(),
                                 (*tm)->getTargetTriple().str(), lo, namer);
  if (!spine) {
    error = llvm::toString(spine.takeError());
    return nullptr;
  }
  (*spine)->setModuleIdentifier("spine");
  t.lowerUs = nowUs() - t0;

  // 2. The cache.
  std::vector<size_t> todo;
  const double tc = nowUs();
  for (size_t k = 0; k < jobs.size(); ++k) {
    std::vector<std::string> objs;
    if (cache && cache->lookup(jobs[k].key, objs) && objs.size() == 1) {
      jobs[k].obj = llvm::MemoryBuffer::getMemBufferCopy(objs[0], jobs[k].symbol);
      jobs[k].fromCache = true;
    } else {
      todo.push_back(k);
    }
  }
  t.cacheUs = nowUs() - tc;

  // 3. The missing leaves on the pool, the spine here.
  std::vector<Built> built(todo.size());
  std::atomic<size_t> next{0};
  // This thread compiles the spine first, so one thread more than leaves pays off.
  const size_t threads = std::min(compileThreadCount(opts), todo.size() + 1);
  std::vector<ThreadTotals> sums(threads);
  std::vector<std::thread> workers;
  for (size_t w = 1; w < threads; ++w) try {
      workers.emplace_back([&, w] {
        compileLeaves(prog, opts, *im.jtmb, im.tier, jobs, todo, next, built, sums[w]);
      });
    } catch (const std::system_error &) {
      break; // no thread to be had: the others (and this one) do its share
    }
  Built sp = compileSpine(**spine, *im.jtmb);
  compileLeaves(prog, opts, *im.jtmb, im.tier, jobs, todo, next, built, sums[0]);
  for (std::thread &w : workers) w.join();
  // Phases: the slowest thread's; CPU: this thread's (spine included) plus the workers'.
  t.cpuUs = threadCpuUs() - c0;
  double lowerMax = 0, optMax = 0;
  for (size_t w = 0; w < threads; ++w) {
    if (w > 0) t.cpuUs += sums[w].cpuUs;
    lowerMax = std::max(lowerMax, sums[w].lowerUs);
    optMax = std::max(optMax, sums[w].optimizeUs + (w == 0 ? sp.optimizeUs : 0));
  }
  for (size_t k = 0; k < todo.size(); ++k) {
    Built &b = built[k];
    if (!b.obj) {
      error = b.error.empty() ? "leaf not compiled" : b.error;
      return nullptr;
    }
    jobs[todo[k]].obj = std::move(b.obj);
  }
  if (!sp.obj) {
    error = sp.error;
    return nullptr;
  }
  t.lowerUs += lowerMax;
  t.optimizeUs = optMax;
  if (cache) {
    const double ts = nowUs();
    for (size_t k : todo)
      cache->store(jobs[k].key,
                   {std::string_view(jobs[k].obj->getBufferStart(), jobs[k].obj->getBufferSize())});
    t.cacheUs += nowUs() - ts;
  }
  t.leaves = static_cast<uint32_t>(jobs.size());
  t.leavesCompiled = static_cast<uint32_t>(todo.size());
  t.cacheHit = todo.empty();
  std::vector<std::unique_ptr<llvm::MemoryBuffer>> objs;
  objs.push_back(std::move(sp.obj));
  for (LeafJob &j : jobs) {
    t.objectBytes += j.obj->getBufferSize();
    objs.push_back(std::move(j.obj));
  }
  t.objectBytes += objs.front()->getBufferSize();
  return linkVersion(self, im, std::move(objs), prog, t0, t, error, times);
}

} // namespace lj::jit

// Incremental compile (JitOptions::incremental, lowering/Incremental.h): the spine is lowered
// first, calling each leaf by its position (positionSymbol) and computing each leaf's cache key;
// the spine's object is looked up under the key of its IR and the leaves under theirs; the
// missing leaves are lowered, optimized and compiled to one object each on a pool of threads
// (each with its own context and TargetMachine) while this thread compiles the spine when it
// was not cached; the spine's object then has each position name replaced by the symbol of its
// leaf (lj_g_<key>, as long), and everything is linked into a new JITDylib. Equal keys are
// equal code, so a leaf that occurs twice is compiled and linked once. docs/incremental.md.
#include "ir/Profile.h"
#include "jit/OrcInternal.h"
#include "jit/Pipeline.h"
#include "lowering/Incremental.h"

#include <llvm/Bitcode/BitcodeWriter.h>
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
  bool quick = false; ///< compiled (or found) at the fast tier
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

/// The fast tier's code generator settings (OrcSession.cpp createImpl).
void fastCodegen(llvm::orc::JITTargetMachineBuilder &jtmb) {
  jtmb.setCodeGenOptLevel(llvm::CodeGenOptLevel::None);
  jtmb.getOptions().EnableFastISel = true;
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
  fastCodegen(jtmb);
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

/// A worker: compiles jobs[todo[k]] for k taken from `next` until none is left, each at the
/// fast tier when its job is quick, else at `tier`.
void compileLeaves(const VerifiedProgram &prog, const JitOptions &opts,
                   const llvm::orc::JITTargetMachineBuilder &jtmb, Tier tier,
                   std::vector<LeafJob> &jobs, const std::vector<size_t> &todo,
                   std::atomic<size_t> &next, std::vector<Built> &out, ThreadTotals &sum) {
  const double c0 = threadCpuUs();
  std::unique_ptr<llvm::TargetMachine> tms[2]; // [quick]: made on first use
  const lower::LowerOptions lo = leafLowerOptions(opts);
  llvm::LLVMContext ctx;
  ctx.setDiscardValueNames(true);
  for (size_t k = next++; k < todo.size(); k = next++) {
    LeafJob &j = jobs[todo[k]];
    Built b;
    std::unique_ptr<llvm::TargetMachine> &tm = tms[j.quick ? 1 : 0];
    if (!tm) {
      llvm::orc::JITTargetMachineBuilder mine = jtmb;
      if (j.quick) fastCodegen(mine);
      auto made = mine.createTargetMachine();
      if (!made) {
        b.error = llvm::toString(made.takeError());
        out[k] = std::move(b);
        continue;
      }
      tm = std::move(*made);
    }
    const double t0 = nowUs();
    auto mod = lower::lowerLeaf(prog, j.leaf, j.symbol, ctx, tm->createDataLayout(),
                                tm->getTargetTriple().str(), lo);
    if (!mod) {
      b.error = llvm::toString(mod.takeError());
      out[k] = std::move(b);
      continue;
    }
    b.lowerUs = nowUs() - t0;
    out[k] = compileModule(**mod, *tm, j.quick ? Tier::Fast : tier, std::move(b));
    sum.lowerUs += out[k].lowerUs;
    sum.optimizeUs += out[k].optimizeUs;
  }
  sum.cpuUs = threadCpuUs() - c0;
}

/// The name the spine calls leaf position `k` by: "lj_l_" and 32 decimal digits, as long as the
/// leaf symbols ("lj_g_" and 32 hex digits) that bindLeaves writes over it.
std::string positionSymbol(size_t k) {
  std::string digits = std::to_string(k);
  return "lj_l_" + std::string(32 - digits.size(), '0') + digits;
}

/// The spine's object with every position name replaced by the symbol of its leaf
/// (`symbolAt[k]`). Both are 37 bytes; they occur only in the symbol string table, as
/// NUL-terminated strings, so the bytes are patched in place (the object is otherwise what the
/// cache holds for every version cut the same way). False when a name is not as expected.
bool bindLeaves(std::string &obj, const std::vector<std::string> &symbolAt, std::string &error) {
  constexpr size_t kLen = 37;
  for (size_t at = obj.find("lj_l_"); at != std::string::npos; at = obj.find("lj_l_", at + kLen)) {
    size_t k = 0;
    bool ok = at > 0 && obj[at - 1] == '\0' && at + kLen < obj.size() && obj[at + kLen] == '\0';
    for (size_t i = at + 5; ok && i < at + kLen; ++i) {
      ok = obj[i] >= '0' && obj[i] <= '9' && k < symbolAt.size();
      k = k * 10 + static_cast<size_t>(obj[i] - '0');
    }
    if (!ok || k >= symbolAt.size() || symbolAt[k].size() != kLen) {
      error = "internal error: the spine's object names leaf position " + std::to_string(k) +
              " in a way it cannot be bound";
      return false;
    }
    obj.replace(at, kLen, symbolAt[k]);
  }
  return true;
}

/// `cache`'s single object under `key`, or null.
std::unique_ptr<llvm::MemoryBuffer> cachedObject(ObjectCache *cache, const std::string &key,
                                                 const std::string &name) {
  std::vector<std::string> objs;
  if (!cache || !cache->lookup(key, objs) || objs.size() != 1) return nullptr;
  return llvm::MemoryBuffer::getMemBufferCopy(objs[0], name);
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
  CacheKeyInputs fastIn = in;
  fastIn.tier = static_cast<int>(Tier::Fast);
  const bool quick = opts.quickLeaves && im.tier != Tier::Fast;
  const std::string profile = prog.profile && prog.profile->name ? prog.profile->name : "";
  const std::vector<int8_t> forced = forceTable(prog, opts.forces);

  // The keys of the last compile, when they were computed for the same profile, tier and chunk
  // size (the digest input holds everything else the key covers).
  const std::string keyContext =
      profile + '\n' + std::to_string(in.tier) + '\n' + std::to_string(in.chunkStatements);
  std::unordered_map<std::string, std::string> oldKeys, newKeys;
  {
    std::lock_guard<std::mutex> g(im.keyMu);
    if (im.keyContext == keyContext) oldKeys = std::move(im.leafKeys);
  }

  // 1. The spine, calling leaf position k by positionSymbol(k); every leaf's key (its symbol:
  // the key's first 128 bits).
  std::vector<LeafJob> jobs;
  std::unordered_map<std::string, size_t> byKey;
  std::vector<size_t> jobOf; // the job of each leaf position
  auto tm = im.jtmb->createTargetMachine();
  if (!tm) {
    error = llvm::toString(tm.takeError());
    return nullptr;
  }
  llvm::LLVMContext ctx;
  ctx.setDiscardValueNames(true);
  double keysUs = 0;
  lower::LeafNamer namer = [&](const lower::Leaf &leaf) {
    const double tk = nowUs();
    std::string digest = lower::leafDigestInput(prog, leaf, forced);
    std::string key;
    if (auto it = oldKeys.find(digest); it != oldKeys.end()) {
      key = it->second;
    } else {
      key = leafCacheKey(in, profile, digest);
    }
    auto [it, fresh] = byKey.emplace(key, jobs.size());
    if (fresh) jobs.push_back({leaf, key, "lj_g_" + key.substr(0, 32), nullptr});
    jobOf.push_back(it->second);
    newKeys.emplace(std::move(digest), std::move(key));
    keysUs += nowUs() - tk;
    return positionSymbol(jobOf.size() - 1);
  };
  lower::LowerOptions lo = leafLowerOptions(opts);
  auto spine = lower::lowerSpine(prog, ctx, (*tm)->createDataLayout(),
                                 (*tm)->getTargetTriple().str(), lo, namer);
  if (!spine) {
    error = llvm::toString(spine.takeError());
    return nullptr;
  }
  {
    std::lock_guard<std::mutex> g(im.keyMu);
    im.keyContext = keyContext;
    im.leafKeys = std::move(newKeys);
  }
  (*spine)->setModuleIdentifier("spine");
  (*spine)->setSourceFileName("spine");
  std::string spineKey;
  {
    // The IR as bitcode (deterministic, and several times cheaper to write than the text).
    llvm::SmallVector<char, 0> bc;
    llvm::raw_svector_ostream os(bc);
    llvm::WriteBitcodeToFile(**spine, os);
    spineKey = spineCacheKey(in, std::string_view(bc.data(), bc.size()));
  }
  t.keysUs = keysUs;
  t.lowerUs = nowUs() - t0;

  // 2. The cache: the spine, then each leaf at the session's tier, or (quick) at the fast tier.
  std::vector<size_t> todo;
  const double tc = nowUs();
  Built sp;
  sp.obj = cachedObject(cache, spineKey, "spine");
  t.spineCached = sp.obj != nullptr;
  for (size_t k = 0; k < jobs.size(); ++k) {
    LeafJob &j = jobs[k];
    j.obj = cachedObject(cache, j.key, j.symbol);
    if (!j.obj && quick) {
      // lowerLeaf names the function after the key: the fast object has a symbol of its own.
      j.quick = true;
      j.key = leafCacheKey(fastIn, profile, lower::leafDigestInput(prog, j.leaf, forced));
      j.symbol = "lj_g_" + j.key.substr(0, 32);
      j.obj = cachedObject(cache, j.key, j.symbol);
    }
    if (!j.obj) todo.push_back(k);
    if (j.quick) ++t.leavesQuick;
  }
  t.cacheUs = nowUs() - tc;

  // 3. The missing leaves on the pool, the spine (when not cached) here first.
  std::vector<Built> built(todo.size());
  std::atomic<size_t> next{0};
  const size_t threads =
      std::max<size_t>(std::min(compileThreadCount(opts), todo.size() + (sp.obj ? 0 : 1)), 1);
  std::vector<ThreadTotals> sums(threads);
  std::vector<std::thread> workers;
  for (size_t w = 1; w < threads; ++w) try {
      workers.emplace_back([&, w] {
        compileLeaves(prog, opts, *im.jtmb, im.tier, jobs, todo, next, built, sums[w]);
      });
    } catch (const std::system_error &) {
      break; // no thread to be had: the others (and this one) do its share
    }
  if (!sp.obj) {
    const double ts = nowUs();
    sp = compileSpine(**spine, *im.jtmb);
    t.spineUs = nowUs() - ts;
  }
  compileLeaves(prog, opts, *im.jtmb, im.tier, jobs, todo, next, built, sums[0]);
  for (std::thread &w : workers) w.join();
  // Phases: the slowest thread's; CPU: this thread's (spine included) plus the workers', plus
  // the link's below.
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
    auto bytes = [](const llvm::MemoryBuffer &b) {
      return std::string_view(b.getBufferStart(), b.getBufferSize());
    };
    if (!t.spineCached) cache->store(spineKey, {bytes(*sp.obj)});
    for (size_t k : todo) cache->store(jobs[k].key, {bytes(*jobs[k].obj)});
    t.cacheUs += nowUs() - ts;
  }
  t.leaves = static_cast<uint32_t>(jobs.size());
  t.leavesCompiled = static_cast<uint32_t>(todo.size());
  t.cacheHit = todo.empty() && t.spineCached;
  std::vector<std::string> symbolAt;
  for (size_t j : jobOf) symbolAt.push_back(jobs[j].symbol);
  std::string spineBytes(sp.obj->getBufferStart(), sp.obj->getBufferSize());
  if (!bindLeaves(spineBytes, symbolAt, error)) return nullptr;
  std::vector<std::unique_ptr<llvm::MemoryBuffer>> objs;
  t.objectBytes += spineBytes.size();
  objs.push_back(llvm::MemoryBuffer::getMemBufferCopy(spineBytes, "spine"));
  for (LeafJob &j : jobs) {
    t.objectBytes += j.obj->getBufferSize();
    objs.push_back(std::move(j.obj));
  }
  const double cl = threadCpuUs();
  std::unique_ptr<Engine> e = linkVersion(self, im, std::move(objs), prog, t0, t, error, times);
  if (times) times->cpuUs += threadCpuUs() - cl; // the link is on the critical path too
  return e;
}

} // namespace lj::jit

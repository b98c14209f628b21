// The only file that talks to ORC (STYLE.md 3, 9, 10): one LLJIT per Session, a runtime
// JITDylib of explicitly bound helpers (no process symbol search), one JITDylib per program
// version, removed when its engine dies. A program is lowered into a few modules compiled to
// objects on parallel threads, then linked by JITLink. llvm::Error stays inside; callers get
// strings.
#include "jit/Jit.h"
#include "jit/ObjectCache.h"
#include "jit/OrcInternal.h"
#include "jit/Pipeline.h"
#include "lowering/Lower.h"

#include <llvm/ExecutionEngine/Orc/CompileUtils.h>
#include <llvm/ExecutionEngine/Orc/Core.h>
#include <llvm/ExecutionEngine/Orc/LLJIT.h>
#include <llvm/ExecutionEngine/Orc/ThreadSafeModule.h>

#include <algorithm>
#include <cstring>
#include <ctime>
#include <mutex>
#include <optional>
#include <system_error>
#include <thread>
#include <vector>

namespace lj::jit {

namespace {

/// A compiled program version: its entry table and the JITDylib holding its code.
class JitEngine final : public Engine {
public:
  JitEngine(std::shared_ptr<Session> owner, Session::Impl *impl, llvm::orc::JITDylib *jd,
            const lj_entries &entries)
      : owner_(std::move(owner)), impl_(impl), jd_(jd), entries_(entries) {}
  ~JitEngine() override {
    // Frees the code; the caller has stopped ticking this version (hot-reload contract).
    llvm::consumeError(impl_->jit->getExecutionSession().removeJITDylib(*jd_));
  }
  const lj_entries &entries() const override { return entries_; }
  const char *name() const override { return "jit"; }

private:
  std::shared_ptr<Session> owner_; // keeps the LLJIT alive as long as the code
  Session::Impl *impl_;
  llvm::orc::JITDylib *jd_;
  lj_entries entries_;
};

// Helpers the code generator may call on its own (it may turn byte loops into libc calls).
// Bound by address so generated code can reach nothing else in the process.
llvm::Error defineRuntime(llvm::orc::LLJIT &j, llvm::orc::JITDylib &rt) {
  using llvm::orc::ExecutorAddr;
  auto flags = llvm::JITSymbolFlags::Exported | llvm::JITSymbolFlags::Callable;
  llvm::orc::SymbolMap syms;
  syms[j.mangleAndIntern("memset")] = {ExecutorAddr::fromPtr(&::memset), flags};
  syms[j.mangleAndIntern("memcpy")] = {ExecutorAddr::fromPtr(&::memcpy), flags};
  syms[j.mangleAndIntern("memmove")] = {ExecutorAddr::fromPtr(&::memmove), flags};
  return rt.define(llvm::orc::absoluteSymbols(std::move(syms)));
}

llvm::Expected<std::unique_ptr<Session::Impl>> createImpl(Tier tier) {
  initNativeTarget();
  auto impl = std::make_unique<Session::Impl>();
  impl->tier = tier;
  auto jtmb = llvm::orc::JITTargetMachineBuilder::detectHost();
  if (!jtmb) return jtmb.takeError();
  if (tier == Tier::Fast) {
    jtmb->setCodeGenOptLevel(llvm::CodeGenOptLevel::None);
    jtmb->getOptions().EnableFastISel = true;
  } else {
    // Less rather than Default: ~8% less codegen time for the same code size on the benchmark
    // program (straight-line byte logic gives the extra Default passes nothing to do).
    jtmb->setCodeGenOptLevel(llvm::CodeGenOptLevel::Less);
  }
  // Objects are compiled outside the LLJIT (one TargetMachine per thread) and linked by JITLink,
  // so use the settings LLJITBuilder picks for JITLink itself: PIC (jump tables are PC-relative,
  // JIT memory is far above 2 GiB) and the small code model (JITLink adds stubs where needed).
  jtmb->setRelocationModel(llvm::Reloc::PIC_);
  jtmb->setCodeModel(llvm::CodeModel::Small);
  impl->jtmb = *jtmb;
  auto jit = llvm::orc::LLJITBuilder()
                 .setJITTargetMachineBuilder(std::move(*jtmb))
                 .setLinkProcessSymbolsByDefault(false)
                 .setPlatformSetUp(llvm::orc::setUpInactivePlatform) // no static ctors to run
                 .create();
  if (!jit) return jit.takeError();
  impl->jit = std::move(*jit);
  auto rt = impl->jit->createJITDylib("ladderjit_runtime");
  if (!rt) return rt.takeError();
  impl->runtime = &*rt;
  if (llvm::Error e = defineRuntime(*impl->jit, *impl->runtime)) return e;
  return impl;
}

template <typename Fn>
llvm::Expected<Fn> lookupEntry(Session::Impl &impl, llvm::orc::JITDylib &jd, const char *name) {
  auto addr = impl.jit->lookup(jd, name);
  if (!addr) return addr.takeError();
  return addr->toPtr<Fn>();
}

/// What one compile thread produced: an object file, or the error that stopped it.
struct PartResult {
  std::unique_ptr<llvm::MemoryBuffer> obj;
  std::string error;
  double lowerUs = 0, optimizeUs = 0;
  double cpuUs = 0; ///< CPU time of the thread that compiled it
};

/// Partitions for `prog`: a thread only pays off for a program of some size (a thread, a
/// context and a TargetMachine cost ~1 ms; codegen runs at ~5-50 us per statement).
uint32_t partitionCount(const VerifiedProgram &prog, const JitOptions &opts) {
  size_t byThreads = compileThreadCount(opts);
  size_t perThread = static_cast<size_t>(std::max(opts.minStatementsPerThread, 1));
  size_t bySize = std::max<size_t>(prog.stmts.size() / perThread, 1);
  return static_cast<uint32_t>(std::min({byThreads, bySize, size_t{16}}));
}

/// Lower, optimize and compile partition `part` of `parts` into an object (runs on any thread).
PartResult compilePart(const VerifiedProgram &prog, const JitOptions &opts,
                       llvm::orc::JITTargetMachineBuilder jtmb, Tier tier, uint32_t parts,
                       uint32_t part) {
  // `jtmb` by value: createTargetMachine is not const, and each thread needs its own copy.
  PartResult r;
  auto fail = [&](llvm::Error e) {
    r.error = llvm::toString(std::move(e));
    return std::move(r);
  };
  double t0 = nowUs();
  const double c0 = threadCpuUs();
  auto tm = jtmb.createTargetMachine();
  if (!tm) return fail(tm.takeError());
  llvm::LLVMContext ctx;
  ctx.setDiscardValueNames(true); // names only matter in emit-llvm dumps
  lower::LowerOptions lo;
  lo.chunkStatements = opts.chunkStatements;
  if (tier == Tier::Optimizing) mergeChunksAsOptimizingBuild(lo);
  lo.readableNames = false;
  lo.partitions = parts;
  lo.partition = part;
  lo.forces = &opts.forces;
  lo.trace = opts.trace;
  auto mod =
      lower::lowerProgram(prog, ctx, (*tm)->createDataLayout(), (*tm)->getTargetTriple().str(), lo);
  if (!mod) return fail(mod.takeError());
  (*mod)->setModuleIdentifier((*mod)->getModuleIdentifier() + "#" + std::to_string(part));
  double t1 = nowUs();
  r.lowerUs = t1 - t0;
  if (tier == Tier::Optimizing) optimizeModule(**mod, 2, tm->get());
  r.optimizeUs = nowUs() - t1;
  llvm::orc::SimpleCompiler compiler(**tm);
  auto obj = compiler(**mod);
  if (!obj) return fail(obj.takeError());
  r.obj = std::move(*obj);
  r.cpuUs = threadCpuUs() - c0;
  return r;
}

} // namespace

Session::Session(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Session::~Session() = default;
Tier Session::tier() const { return impl_->tier; }
void Session::enableIncremental() {
  std::lock_guard<std::mutex> lock(impl_->mu);
  if (!impl_->leafCache) impl_->leafCache = std::make_shared<ObjectCache>(std::string());
}

std::shared_ptr<Session> Session::create(Tier tier, std::string &error) {
  auto impl = createImpl(tier);
  if (!impl) {
    error = "cannot create the JIT: " + llvm::toString(impl.takeError());
    return nullptr;
  }
  return std::shared_ptr<Session>(new Session(std::move(*impl)));
}

std::unique_ptr<Engine> Session::compile(const VerifiedProgram &prog, const JitOptions &opts,
                                         std::string &error, CompileTimes *times) {
  Impl &im = *impl_;
  if (!times) times = opts.times;
  std::shared_ptr<ObjectCache> leafCache;
  {
    std::lock_guard<std::mutex> lock(im.mu);
    leafCache = im.leafCache;
  }
  if ((opts.incremental || leafCache) &&
      !opts.trace) { // a traced build is whole (its buffer address is in the code)
    ObjectCache *cache = opts.cache ? opts.cache.get() : leafCache.get();
    return compileIncremental(*this, im, prog, opts, cache, error, times);
  }
  const double t0 = nowUs();
  const uint32_t parts = partitionCount(prog, opts);
  std::vector<PartResult> res(parts);
  // The object cache is consulted before any IR is built (docs/aot.md "Object cache").
  std::string cacheKey;
  std::vector<std::string> cached;
  double cacheUs = 0;
  if (opts.cache && !opts.trace) { // a traced object holds its buffer's address
    const double tc = nowUs();
    CacheKeyInputs in{im.jtmb->getTargetTriple().str(),
                      im.jtmb->getCPU(),
                      im.jtmb->getFeatures().getString(),
                      static_cast<int>(im.tier),
                      opts.chunkStatements,
                      parts,
                      opts.forces};
    cacheKey = objectCacheKey(prog, in);
    if (opts.cache->lookup(cacheKey, cached) && cached.size() != parts) cached.clear();
    for (uint32_t p = 0; p < parts && !cached.empty(); ++p)
      res[p].obj = llvm::MemoryBuffer::getMemBufferCopy(cached[p], "cached#" + std::to_string(p));
    cacheUs += nowUs() - tc;
  }
  if (!res[0].obj) {
    // Partition 0 on this thread, the others on their own; every partition has its own
    // LLVMContext and TargetMachine (notes 4: one context per concurrently compiled module).
    std::vector<std::thread> workers;
    for (uint32_t p = 1; p < parts; ++p) try {
        workers.emplace_back(
            [&, p] { res[p] = compilePart(prog, opts, *im.jtmb, im.tier, parts, p); });
      } catch (const std::system_error &) { // no thread to be had: compile it here instead
        res[p] = compilePart(prog, opts, *im.jtmb, im.tier, parts, p);
      }
    res[0] = compilePart(prog, opts, *im.jtmb, im.tier, parts, 0);
    for (std::thread &w : workers) w.join();
  }
  CompileTimes t;
  for (const PartResult &r : res) {
    if (!r.obj) {
      error = r.error;
      return nullptr;
    }
    t.lowerUs = std::max(t.lowerUs, r.lowerUs);
    t.optimizeUs = std::max(t.optimizeUs, r.optimizeUs);
    t.objectBytes += r.obj->getBufferSize();
    t.cpuUs += r.cpuUs;
  }
  t.cacheHit = !cached.empty();
  if (opts.cache && !opts.trace && cached.empty()) {
    const double tc = nowUs();
    std::vector<std::string_view> objs;
    for (const PartResult &r : res)
      objs.emplace_back(r.obj->getBufferStart(), r.obj->getBufferSize());
    opts.cache->store(cacheKey, objs);
    cacheUs += nowUs() - tc;
  }
  t.cacheUs = cacheUs;
  std::vector<std::unique_ptr<llvm::MemoryBuffer>> objs;
  for (PartResult &r : res) objs.push_back(std::move(r.obj));
  return linkVersion(*this, im, std::move(objs), prog, t0, t, error, times);
}

std::unique_ptr<Engine> linkVersion(Session &self, Session::Impl &im,
                                    std::vector<std::unique_ptr<llvm::MemoryBuffer>> objs,
                                    const VerifiedProgram &prog, double t0, CompileTimes t,
                                    std::string &error, CompileTimes *times) {
  const double tLink = nowUs();
  std::string name;
  {
    std::lock_guard<std::mutex> lock(im.mu);
    name = "prog_v" + std::to_string(im.nextVersion++);
  }
  auto jd = im.jit->createJITDylib(name);
  if (!jd) {
    error = llvm::toString(jd.takeError());
    return nullptr;
  }
  jd->addToLinkOrder(*im.runtime);
  auto failWith = [&](llvm::Error e) -> std::unique_ptr<Engine> {
    error = llvm::toString(std::move(e));
    llvm::consumeError(im.jit->getExecutionSession().removeJITDylib(*jd));
    return nullptr;
  };
  for (std::unique_ptr<llvm::MemoryBuffer> &o : objs)
    if (llvm::Error e = im.jit->addObjectFile(*jd, std::move(o))) return failWith(std::move(e));
  // The first lookup links the objects (JITLink resolves the calls between them).
  lj_entries entries{};
  auto init = lookupEntry<lj_part_fn>(im, *jd, lower::kInitSymbol);
  if (!init) return failWith(init.takeError());
  auto plc1 = lookupEntry<lj_part_fn>(im, *jd, lower::kPlc1Symbol);
  if (!plc1) return failWith(plc1.takeError());
  auto plc2 = lookupEntry<lj_slice_fn>(im, *jd, lower::kPlc2Symbol);
  if (!plc2) return failWith(plc2.takeError());
  entries.ctx = nullptr;
  entries.init = *init;
  entries.plc1 = *plc1;
  entries.plc2_slice = *plc2;
  entries.plc2_slice_count = prog.slices.empty() ? 1u : static_cast<uint32_t>(prog.slices.size());
  const double tEnd = nowUs();
  t.linkUs = tEnd - tLink;
  t.codegenUs = tEnd - t0 - t.lowerUs - t.optimizeUs;
  if (times) *times = t;
  return std::make_unique<JitEngine>(self.shared_from_this(), &im, &*jd, entries);
}

} // namespace lj::jit

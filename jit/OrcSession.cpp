// The only file that talks to ORC (STYLE.md 3, 9, 10): one LLJIT per Session, a runtime
// JITDylib of explicitly bound helpers (no process symbol search), one JITDylib per program
// version, removed when its engine dies. llvm::Error stays inside; callers get strings.
#include "jit/Jit.h"
#include "jit/Pipeline.h"
#include "lowering/Lower.h"

#include <llvm/ExecutionEngine/Orc/Core.h>
#include <llvm/ExecutionEngine/Orc/LLJIT.h>
#include <llvm/ExecutionEngine/Orc/ThreadSafeModule.h>

#include <cstring>
#include <mutex>

namespace lj::jit {

struct Session::Impl {
  Tier tier = Tier::Optimizing;
  std::unique_ptr<llvm::orc::LLJIT> jit;
  llvm::orc::JITDylib *runtime = nullptr;
  std::unique_ptr<llvm::TargetMachine> optTM; ///< cost model of the IR pipeline
  std::mutex mu;                              ///< guards optTM and nextVersion
  uint64_t nextVersion = 1;
};

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
    jtmb->setCodeGenOptLevel(llvm::CodeGenOptLevel::Default);
    auto tm = jtmb->createTargetMachine();
    if (!tm) return tm.takeError();
    impl->optTM = std::move(*tm);
  }
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

} // namespace

Session::Session(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
Session::~Session() = default;
Tier Session::tier() const { return impl_->tier; }

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
  CompileTimes t;
  double t0 = nowUs();
  auto ctx = std::make_unique<llvm::LLVMContext>(); // one context per version (notes 4)
  ctx->setDiscardValueNames(true);                  // names only matter in emit-llvm dumps
  lower::LowerOptions lo;
  lo.chunkStatements = opts.chunkStatements;
  lo.readableNames = false;
  auto mod =
      lower::lowerProgram(prog, *ctx, im.jit->getDataLayout(), im.jit->getTargetTriple().str(), lo);
  if (!mod) {
    error = llvm::toString(mod.takeError());
    return nullptr;
  }
  double t1 = nowUs();
  t.lowerUs = t1 - t0;
  std::string name;
  {
    std::lock_guard<std::mutex> lock(im.mu);
    if (im.tier == Tier::Optimizing) optimizeModule(**mod, 2, im.optTM.get());
    name = "prog_v" + std::to_string(im.nextVersion++);
  }
  double t2 = nowUs();
  t.optimizeUs = t2 - t1;

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
  if (llvm::Error e =
          im.jit->addIRModule(*jd, llvm::orc::ThreadSafeModule(std::move(*mod), std::move(ctx))))
    return failWith(std::move(e));
  // The first lookup materializes (compiles) the whole module.
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
  t.codegenUs = nowUs() - t2;
  if (times) *times = t;
  return std::make_unique<JitEngine>(shared_from_this(), impl_.get(), &*jd, entries);
}

} // namespace lj::jit

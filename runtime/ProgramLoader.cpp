// Program versions for serve: front end, forces, engine build (one ORC session for every JIT
// version, so each online change is a new JITDylib, STYLE.md 10; or an AOT .so, docs/aot.md).
#include "runtime/ProgramLoader.h"

#include "engines/EngineSpec.h"
#include "engines/LlvmBackend.h"
#include "ir/Trace.h"
#include "pipeline/ProgramFile.h"

#include <algorithm>
#include <chrono>

namespace lj::rt {

const Stmt *stmtById(const VerifiedProgram &prog, StmtId id) {
  for (const Stmt &st : prog.stmts)
    if (st.id == id) return &st;
  return nullptr;
}

std::vector<StmtId> stmtsOnLine(const VerifiedProgram &prog, int32_t line) {
  std::vector<StmtId> ids;
  for (const Stmt &st : prog.stmts)
    if (st.loc.line == line) ids.push_back(st.id);
  return ids;
}

/// The contact instructions as the program's dialect writes them (HNC-8 `LD LDI AND ...`,
/// FANUC `RD RD.NOT AND ...`, IL `LD LDN AND ...`), each word once.
static std::string contactWords(const DialectText *d) {
  std::string out;
  std::vector<std::string_view> seen;
  for (int k = 0; k < kOpCount; ++k) {
    const Op op = static_cast<Op>(k);
    if (!isContact(op) || (d && !spells(*d, op))) continue;
    const std::string_view w = spelling(d, op);
    if (std::find(seen.begin(), seen.end(), w) != seen.end()) continue;
    seen.push_back(w);
    out += (out.empty() ? "" : " ") + std::string(w);
  }
  return out;
}

bool checkForces(const VerifiedProgram &prog, ContactForces &forces, std::string &error,
                 std::vector<std::string> *dropped) {
  for (auto it = forces.begin(); it != forces.end();) {
    const Stmt *st = stmtById(prog, it->first);
    std::string why;
    if (!st) {
      why = prog.file + ": statement id " + std::to_string(it->first) + " does not exist";
    } else if (!isContact(st->op)) {
      why = prog.file + ":" + std::to_string(st->loc.line) + ": statement id " +
            std::to_string(it->first) + " is '" + std::string(spelling(prog.dialect, st->op)) +
            "', not a contact (only " + contactWords(prog.dialect) + " can be forced)";
    }
    if (why.empty()) {
      ++it;
      continue;
    }
    if (!dropped) {
      error = why;
      return false;
    }
    dropped->push_back(why);
    it = forces.erase(it);
  }
  return true;
}

ProgramLoader::ProgramLoader(std::string engine, int32_t plc2Nvalue, std::string dialect)
    : engine_(std::move(engine)), plc2Nvalue_(plc2Nvalue), dialect_(std::move(dialect)) {}

ProgramLoader::~ProgramLoader() = default;

namespace {
int64_t monoNs() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
             std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

// Another build of `v`'s program: the same file, hash, VerifiedProgram and version id (a tier or
// a rebuild switches code only).
std::shared_ptr<ProgramVersion> buildOf(const ProgramVersion &v) {
  auto out = std::make_shared<ProgramVersion>();
  out->path = v.path;
  out->hash = v.hash;
  out->prog = v.prog;
  out->id = v.id;
  return out;
}

// What a JIT build's compile times tell the statistics; a build that compiled groups at the fast
// tier (EngineOptions::quickLeaves) runs as JitQuick until its optimized build replaces it.
void noteJitBuild(ProgramVersion &v, const jit::CompileTimes &times) {
  v.buildCpuNs = static_cast<int64_t>(times.cpuUs * 1000);
  v.groups = times.leaves;
  v.groupsCompiled = times.leavesCompiled;
  v.groupsQuick = times.leavesQuick;
  if (times.leavesQuick) v.tier = EngineTier::JitQuick;
}
} // namespace

std::shared_ptr<ProgramVersion>
ProgramLoader::load(const std::string &path, const ContactForces &forces, std::string &error,
                    std::optional<formats::DitFile> *ditOut, const std::string &so,
                    std::vector<std::string> *dropped, int64_t *readyNs, bool interpreted,
                    const std::string *bytes) {
  return loadAs(interpreted, path, forces, error, ditOut, so, dropped, readyNs, bytes);
}

std::optional<VerifiedProgram>
ProgramLoader::verify(const std::string &path, const std::string &bytes, std::string &diagnostics) {
  pipeline::ProgramSource src;
  if (Status st = pipeline::readProgramFile(path, src, dialect_, &bytes); !st.ok()) {
    diagnostics = st.message();
    return std::nullopt;
  }
  const bool nvalueGiven = plc2Nvalue_ >= 0;
  return pipeline::verifyProgram(
      src, pipeline::effectiveNvalue(src, nvalueGiven ? plc2Nvalue_ : 200, nvalueGiven),
      diagnostics);
}

std::shared_ptr<ProgramVersion>
ProgramLoader::loadInterpreted(const std::string &path, std::string &error,
                               std::optional<formats::DitFile> *ditOut, int64_t *readyNs) {
  return loadAs(true, path, {}, error, ditOut, {}, nullptr, readyNs);
}

jit::Session *ProgramLoader::session(bool fast, std::string &error) {
  std::shared_ptr<jit::Session> &s = fast ? fastSession_ : session_;
  if (!s) {
    // The LLVM module loads here (engines/LlvmBackend.h): on the tiering thread when the
    // program starts on the interpreter, so the first tick never waits for libLLVM.
    const engines::LlvmBackend *llvm = engines::llvmBackend(error);
    if (!llvm) return nullptr;
    // The optimizing session compiles incrementally (docs/incremental.md): its first build
    // fills the per-group cache (the program already runs on the interpreter or the fast
    // JIT meanwhile), so an online change or a force recompiles only the groups it touches.
    s = llvm->createSession(fast ? jit::Tier::Fast : jit::Tier::Optimizing, !fast, error);
  }
  return s.get();
}

std::shared_ptr<ProgramVersion> ProgramLoader::buildTier(const ProgramVersion &v, EngineTier tier,
                                                         std::string &error) {
  if (tier != EngineTier::JitFast && tier != EngineTier::JitOpt) {
    error = "tiering builds JIT code only";
    return nullptr;
  }
  const int64_t t0 = monoNs();
  std::shared_ptr<ProgramVersion> out = buildOf(v);
  out->forces = v.forces;
  out->variant = out->baseVariant = v.variant; // a tier of the same build (forces, tracing)
  out->tier = tier;
  engines::EngineOptions eo;
  eo.forces = v.forces;
  jit::CompileTimes times;
  eo.times = &times;
  {
    std::lock_guard<std::mutex> g(mu_);
    eo.session = session(tier == EngineTier::JitFast, error);
    if (!eo.session) return nullptr;
  }
  // Not under mu_: a session compiles from several threads, and an online change (which holds
  // mu_ for its compile) must not wait for a background build (tiering, ChangeOptimizer).
  Result<std::unique_ptr<Engine>> made =
      engines::makeEngine(engines::EngineSpec{engines::EngineKind::Jit, {}}, *out->prog, eo);
  if (!made) {
    error = "jit: " + made.status().message();
    return nullptr;
  }
  out->engine = std::move(made).value();
  out->buildNs = monoNs() - t0;
  noteJitBuild(*out, times); // no quick groups here: the tier stays `tier`
  if (tier == EngineTier::JitOpt) optimizingWarm_.store(true);
  return out;
}

std::shared_ptr<ProgramVersion> ProgramLoader::rebuild(const ProgramVersion &v,
                                                       const ContactForces &forces, bool traced,
                                                       engines::EngineKind kind,
                                                       std::string &error) {
  if (kind != engines::EngineKind::Interp && kind != engines::EngineKind::Jit) {
    error = "a rebuild runs on the interpreter or the JIT";
    return nullptr;
  }
  const int64_t t0 = monoNs();
  std::shared_ptr<ProgramVersion> out = buildOf(v); // nothing is read, nothing renumbered
  out->baseVariant = v.variant;
  out->variant = nextVariant_.fetch_add(1);
  out->forces = forces;
  if (!checkForces(*out->prog, out->forces, error)) return nullptr;
  engines::EngineOptions eo;
  eo.forces = out->forces;
  if (traced) {
    out->trace = std::make_unique<TraceBuffer>(traceLayout(*out->prog).words);
    eo.trace = out->trace->live();
  }
  jit::CompileTimes times;
  out->tier = EngineTier::Interp;
  if (kind == engines::EngineKind::Jit) {
    out->tier = EngineTier::JitOpt;
    eo.times = &times;
    // As an online change: once the optimizing session's cache is full, only the groups the
    // forces touch are compiled, at the fast tier (ChangeOptimizer builds them optimized). A
    // traced build is never incremental.
    eo.quickLeaves = optimizingWarm_.load() && !eo.trace;
    std::lock_guard<std::mutex> g(mu_);
    eo.session = session(false, error);
    if (!eo.session) return nullptr;
  }
  // Not under mu_ (as buildTier): a session compiles from several threads.
  Result<std::unique_ptr<Engine>> made =
      engines::makeEngine(engines::EngineSpec{kind, {}}, *out->prog, eo);
  if (!made) {
    error = std::string(engines::engineKindName(kind)) + ": " + made.status().message();
    return nullptr;
  }
  out->engine = std::move(made).value();
  out->buildNs = monoNs() - t0;
  if (kind == engines::EngineKind::Jit) {
    noteJitBuild(*out, times);
    if (!eo.trace) optimizingWarm_.store(true);
  }
  return out;
}

std::shared_ptr<ProgramVersion>
ProgramLoader::loadAs(bool interpreted, const std::string &path, const ContactForces &forces,
                      std::string &error, std::optional<formats::DitFile> *ditOut,
                      const std::string &so, std::vector<std::string> *dropped, int64_t *readyNs,
                      const std::string *bytes) {
  const int64_t t0 = monoNs();
  if (interpreted && aot()) {
    error = "an AOT server runs its .so from the first tick (no interpreter-first tiering)";
    return nullptr;
  }
  if (aot() && !forces.empty()) {
    error = "forcing needs recompilation, which an AOT .so cannot do";
    return nullptr;
  }
  if (aot() && so.empty()) {
    error = "the AOT engine needs a .so built from '" + path + "'";
    return nullptr;
  }
  pipeline::ProgramSource src;
  if (Status st = pipeline::readProgramFile(path, src, dialect_, bytes); !st.ok()) {
    error = st.message();
    return nullptr;
  }
  auto v = std::make_shared<ProgramVersion>();
  v->path = path;
  v->hash = src.fileHash;
  const bool nvalueGiven = plc2Nvalue_ >= 0;
  const int32_t nvalue =
      pipeline::effectiveNvalue(src, nvalueGiven ? plc2Nvalue_ : 200, nvalueGiven);
  std::string diagnostics;
  std::optional<VerifiedProgram> prog =
      pipeline::verifyProgram(src, nvalue, diagnostics, &v->warnings);
  if (!prog) {
    error = diagnostics;
    while (!error.empty() && error.back() == '\n') error.pop_back();
    return nullptr;
  }
  v->prog = std::make_shared<VerifiedProgram>(std::move(*prog));
  const int64_t verified = monoNs();
  v->frontendNs = verified - t0;
  if (readyNs) *readyNs = verified;
  v->forces = forces;
  if (!checkForces(*v->prog, v->forces, error, dropped)) return nullptr;
  engines::EngineSpec spec{interpreted || engine_ == "interp" ? engines::EngineKind::Interp
                           : aot()                            ? engines::EngineKind::Aot
                                                              : engines::EngineKind::Jit,
                           so};
  v->tier = spec.kind == engines::EngineKind::Interp ? EngineTier::Interp
            : spec.kind == engines::EngineKind::Aot  ? EngineTier::Aot
                                                     : EngineTier::JitOpt;
  engines::EngineOptions eo;
  eo.forces = v->forces; // an override of this build; the verified program stays as verified
  if (traced()) {        // a traced build records into the version's own buffer (ir/Trace.h)
    v->trace = std::make_unique<TraceBuffer>(traceLayout(*v->prog).words);
    eo.trace = v->trace->live();
  }
  std::unique_lock<std::mutex> jitLock(mu_, std::defer_lock);
  jit::CompileTimes times;
  if (spec.kind == engines::EngineKind::Jit) {
    eo.times = &times;
    // After the session's first build (its cache holds every group), an online change compiles
    // the groups it touched at the fast tier: new code within milliseconds; the controller's
    // ChangeOptimizer then builds the optimized groups in the background (docs/serve.md
    // "Online change latency"). A traced build is never incremental, so never quick.
    eo.quickLeaves = optimizingWarm_.load() && !eo.trace;
    // One session for every version (a JITDylib each), compiling incrementally: an online
    // change or a force recompiles only the rung groups it touches; the others are linked from
    // the session's in-memory leaf cache (jit/Jit.h, docs/incremental.md).
    jitLock.lock();
    eo.session = session(false, error);
    if (!eo.session) return nullptr;
  }
  // AOT: the loader checks the signer, ABI, state size, ELF and that `so` was built from this
  // program with this nvalue; a mismatch leaves the running version alone (the caller reports it).
  if (aot()) {
    eo.aotExpect = engines::aotExpectOf(src, nvalue);
    eo.aotTrust = &aotTrust_;
  }
  Result<std::unique_ptr<Engine>> made = engines::makeEngine(spec, *v->prog, eo);
  if (!made) {
    if (spec.kind != engines::EngineKind::Interp)
      error = std::string(engines::engineKindName(spec.kind)) + ": " + made.status().message();
    return nullptr;
  }
  v->engine = std::move(made).value();
  if (aot()) v->so = so;
  if (jitLock.owns_lock()) jitLock.unlock();
  v->buildNs = monoNs() - t0;
  if (spec.kind == engines::EngineKind::Jit) {
    noteJitBuild(*v, times);
    if (!eo.trace) optimizingWarm_.store(true);
  }
  {
    std::lock_guard<std::mutex> g(mu_);
    v->id = nextId_++;
  }
  v->variant = nextVariant_.fetch_add(1);
  if (ditOut) *ditOut = std::move(src.dit);
  return v;
}

} // namespace lj::rt

// Program versions for serve: front end, forces, engine build (one ORC session for every JIT
// version, so each online change is a new JITDylib, STYLE.md 10; or an AOT .so, docs/aot.md).
#include "runtime/ProgramLoader.h"

#include "engines/EngineSpec.h"
#include "formats/ProgramFile.h"
#include "ir/Trace.h"
#include "jit/Jit.h"

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
            "', not a contact (only LD LDI AND ANI OR ORI LDP LDF ANDP ANDF ORP ORF can be "
            "forced)";
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

std::shared_ptr<ProgramVersion> ProgramLoader::load(const std::string &path,
                                                    const ContactForces &forces, std::string &error,
                                                    std::optional<io::DitFile> *ditOut,
                                                    const std::string &so,
                                                    std::vector<std::string> *dropped) {
  if (aot() && !forces.empty()) {
    error = "forcing needs recompilation, which an AOT .so cannot do";
    return nullptr;
  }
  if (aot() && so.empty()) {
    error = "the AOT engine needs a .so built from '" + path + "'";
    return nullptr;
  }
  io::ProgramSource src;
  if (!io::readProgramFile(path, src, error, dialect_)) return nullptr;
  auto v = std::make_shared<ProgramVersion>();
  v->path = path;
  v->hash = src.fileHash;
  const bool nvalueGiven = plc2Nvalue_ >= 0;
  const int32_t nvalue = io::effectiveNvalue(src, nvalueGiven ? plc2Nvalue_ : 200, nvalueGiven);
  std::string diagnostics;
  std::optional<VerifiedProgram> prog = io::verifyProgram(src, nvalue, diagnostics);
  if (!prog) {
    error = diagnostics;
    while (!error.empty() && error.back() == '\n') error.pop_back();
    return nullptr;
  }
  v->prog = std::make_unique<VerifiedProgram>(std::move(*prog));
  v->forces = forces;
  if (!checkForces(*v->prog, v->forces, error, dropped)) return nullptr;
  engines::EngineSpec spec{engine_ == "interp" ? engines::EngineKind::Interp
                           : aot()             ? engines::EngineKind::Aot
                                               : engines::EngineKind::Jit,
                           so};
  engines::EngineOptions eo;
  eo.forces = v->forces; // an override of this build; the verified program stays as verified
  if (traced()) {        // a traced build records into the version's own buffer (ir/Trace.h)
    v->trace = std::make_unique<TraceBuffer>(traceLayout(*v->prog).words);
    eo.trace = v->trace->live();
  }
  std::unique_lock<std::mutex> jitLock(mu_, std::defer_lock);
  if (spec.kind == engines::EngineKind::Jit) {
    // One session for every version (a JITDylib each). No object cache: each version is
    // compiled once, and a forced copy differs anyway.
    jitLock.lock();
    if (!session_) {
      session_ = jit::Session::create(jit::Tier::Optimizing, error);
      if (!session_) return nullptr;
    }
    eo.session = session_.get();
  }
  // AOT: the loader checks the signer, ABI, state size, ELF and that `so` was built from this
  // program with this nvalue; a mismatch leaves the running version alone (the caller reports it).
  if (aot()) {
    eo.aotExpect = io::aotExpectOf(src, nvalue);
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
  {
    std::lock_guard<std::mutex> g(mu_);
    v->id = nextId_++;
  }
  if (ditOut) *ditOut = std::move(src.dit);
  return v;
}

} // namespace lj::rt

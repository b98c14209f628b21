// Loading a program version for `ladderjit serve`: read PROGRAM (STL or plc.dit), verify,
// apply contact forces, build the engine (JIT in one shared ORC session, the interpreter, or an
// AOT .so checked against PROGRAM). Used at start, for online change and for forcing; runs off
// the scan thread.
#pragma once

#include "engines/EngineSpec.h"
#include "formats/PlcDit.h"
#include "runtime/Executive.h"
#include "signing/AotTrust.h"

#include <atomic>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace lj::jit {
class Session;
}

namespace lj::rt {

/// Check that every id of `forces` names a contact of `prog` (ir/Forces.h). `dropped` null:
/// false with `error` naming the first id that does not. Otherwise (online change carrying the
/// running forces over) such forces are removed from `forces`, one message each appended to
/// `dropped`, and the rest are kept.
bool checkForces(const VerifiedProgram &prog, ContactForces &forces, std::string &error,
                 std::vector<std::string> *dropped = nullptr);

/// The ids of the statements on source line `line` of `prog`, in order (none: empty).
std::vector<StmtId> stmtsOnLine(const VerifiedProgram &prog, int32_t line);

/// The statement with id `id`, or null.
const Stmt *stmtById(const VerifiedProgram &prog, StmtId id);

class ProgramLoader {
public:
  /// `engine` is "jit", "interp" or "aot" (the .so is given per load). `plc2Nvalue` < 0 = the
  /// container's, else 200.
  /// `dialect`: --dialect (pipeline/Dialects.h), empty = by file name.
  ProgramLoader(std::string engine, int32_t plc2Nvalue, std::string dialect = {});
  ~ProgramLoader();

  /// Read, verify and compile `path` with the contacts of `forces` forced (engine "aot": load
  /// `so` instead of compiling, and only when it was built from `path` with this plc2 nvalue;
  /// forces are refused). Null with `error` = the diagnostics or the reason. `dit`, when given,
  /// receives the container (nothing for an STL file). `dropped`: see checkForces (null: a
  /// force whose id is not a contact refuses the load). `readyNs`: see loadInterpreted.
  /// `bytes`: `path`'s content as it will be written (a ladder edit, runtime/EditSession.h),
  /// read instead of the file.
  std::shared_ptr<ProgramVersion>
  load(const std::string &path, const ContactForces &forces, std::string &error,
       std::optional<formats::DitFile> *dit = nullptr, const std::string &so = {},
       std::vector<std::string> *dropped = nullptr, int64_t *readyNs = nullptr,
       bool interpreted = false, const std::string *bytes = nullptr);
  /// Read and verify `bytes` as the content of `path` exactly as load does (the dialect option,
  /// the PLC2 nvalue), building nothing: the check of a ladder edit. Null with `diagnostics`.
  std::optional<VerifiedProgram> verify(const std::string &path, const std::string &bytes,
                                        std::string &diagnostics);
  /// The same as load, but the version runs on the interpreter whatever the loader's engine:
  /// the first version of interpreter-first tiering (docs/serve.md "Tiering"), ready as soon as
  /// the program is verified. `readyNs`, when given, receives CLOCK_MONOTONIC at that moment.
  std::shared_ptr<ProgramVersion> loadInterpreted(const std::string &path, std::string &error,
                                                  std::optional<formats::DitFile> *dit = nullptr,
                                                  int64_t *readyNs = nullptr);
  /// Another build of `v`'s program (the same VerifiedProgram, forces and id) on the JIT tier
  /// `tier` (JitFast or JitOpt), in the loader's session of that tier. For the background
  /// compile of tiering; runs on the calling thread. Null with `error` when the JIT fails.
  std::shared_ptr<ProgramVersion> buildTier(const ProgramVersion &v, EngineTier tier,
                                            std::string &error);
  /// Another build of the running program `v` (the same VerifiedProgram, path, hash and id: no
  /// file is read) with exactly the contact forces `forces` and traced or not: what forcing and
  /// the live view switch in with Executive::switchCode, so that they never run init nor clear
  /// any memory (docs/serve.md "Forcing"). `kind`: Interp builds on the interpreter (ready within
  /// milliseconds), Jit on the optimizing session (incremental: only the groups a force touches
  /// are compiled, at the fast tier once the session is warm, EngineTier::JitQuick). Null with
  /// `error` when a force is not a contact of the program or the build fails.
  std::shared_ptr<ProgramVersion> rebuild(const ProgramVersion &v, const ContactForces &forces,
                                          bool traced, engines::EngineKind kind,
                                          std::string &error);
  const std::string &engine() const { return engine_; }
  /// Whether the next loads build traced versions (ir/Trace.h; the live view while a page
  /// watches). Ignored for AOT, which is never traced.
  void setTraced(bool on) { traced_.store(on); }
  bool traced() const { return traced_.load() && !aot(); }
  /// Whether versions come from AOT .so files (no recompilation: forcing is impossible).
  bool aot() const { return engine_ == "aot"; }
  /// The keys whose .so files engine "aot" accepts (docs/aot.md "Trust"); none = refuse all.
  void setAotTrust(signing::TrustedKeys keys) { aotTrust_ = std::move(keys); }

private:
  std::shared_ptr<ProgramVersion> loadAs(bool interpreted, const std::string &path,
                                         const ContactForces &forces, std::string &error,
                                         std::optional<formats::DitFile> *dit,
                                         const std::string &so, std::vector<std::string> *dropped,
                                         int64_t *readyNs, const std::string *bytes = nullptr);
  /// The session of `tier`, created on first use; call with mu_ held.
  jit::Session *session(bool fast, std::string &error);

  signing::TrustedKeys aotTrust_;
  std::string engine_;
  int32_t plc2Nvalue_;
  std::string dialect_;
  std::atomic<bool> traced_{false};
  /// The optimizing session has built a version (its group cache is full): later loads are
  /// online changes, compiled quick (EngineOptions::quickLeaves).
  std::atomic<bool> optimizingWarm_{false};
  std::mutex mu_;
  std::shared_ptr<jit::Session> session_;     // optimizing tier, created on first use
  std::shared_ptr<jit::Session> fastSession_; // fast tier (tiering only), created on first use
  uint64_t nextId_ = 1;
  std::atomic<uint64_t> nextVariant_{1};
};

} // namespace lj::rt

// Loading a program version for `ladderjit serve`: read PROGRAM (STL or plc.dit), verify,
// apply contact forces, build the engine (JIT in one shared ORC session, the interpreter, or an
// AOT .so checked against PROGRAM). Used at start, for online change and for forcing; runs off
// the scan thread.
#pragma once

#include "engines/AotTrust.h"
#include "formats/PlcDit.h"
#include "runtime/Executive.h"

#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>

namespace lj::jit {
class Session;
}

namespace lj::rt {

/// Set `Stmt::force` on the statement of each forced source line. False (with `error` naming
/// the line) when a line holds no statement or one that is not a contact.
bool applyForces(VerifiedProgram &prog, const std::map<int32_t, int8_t> &forces,
                 std::string &error);

class ProgramLoader {
public:
  /// `engine` is "jit", "interp" or "aot" (the .so is given per load). `plc2Nvalue` < 0 = the
  /// container's, else 200.
  /// `dialect`: --dialect (formats/Dialects.h), empty = by file name.
  ProgramLoader(std::string engine, int32_t plc2Nvalue, std::string dialect = {});
  ~ProgramLoader();

  /// Read, verify, force and compile `path` (engine "aot": load `so` instead of compiling, and
  /// only when it was built from `path` with this plc2 nvalue; forces are refused). Null with
  /// `error` = the diagnostics or the reason. `dit`, when given, receives the container
  /// (nothing for an STL file).
  std::shared_ptr<ProgramVersion> load(const std::string &path,
                                       const std::map<int32_t, int8_t> &forces, std::string &error,
                                       std::optional<io::DitFile> *dit = nullptr,
                                       const std::string &so = {});
  const std::string &engine() const { return engine_; }
  /// Whether versions come from AOT .so files (no recompilation: forcing is impossible).
  bool aot() const { return engine_ == "aot"; }
  /// The keys whose .so files engine "aot" accepts (docs/aot.md "Trust"); none = refuse all.
  void setAotTrust(io::TrustedKeys keys) { aotTrust_ = std::move(keys); }

private:
  io::TrustedKeys aotTrust_;
  std::string engine_;
  int32_t plc2Nvalue_;
  std::string dialect_;
  std::mutex mu_;
  std::shared_ptr<jit::Session> session_; // created on first use
  uint64_t nextId_ = 1;
};

} // namespace lj::rt

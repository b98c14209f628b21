// The serve control logic: online change (command, PROGRAM file change or a ladder edit from the
// live view, runtime/EditSession.h), forcing and the live
// view's traced code (rebuilds of the running program switched in without init), the lock list,
// reads/writes and stats, as JSON requests from the control socket (docs/serve.md "Control").
#pragma once

#include "runtime/ChangeOptimizer.h"
#include "runtime/Exchange.h"
#include "runtime/Executive.h"
#include "runtime/ProgramLoader.h"
#include "runtime/SignalTrace.h"

#include <nlohmann/json.hpp>

namespace lj::formats {
struct Dialect;
}

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <ctime>
#include <functional>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

namespace lj::rt {

/// The guards of online change (docs/serve.md "Online change", issue 11 items 2 and 4).
struct ControllerOptions {
  /// Directories `load` may read from (resolved with realpath, symlinks included); a path
  /// outside all of them is refused. Empty = `load` of any new file is refused.
  std::vector<std::string> loadDirs;
  /// A file is taken only once its size, mtime and content have not changed for this long.
  std::chrono::milliseconds settle{500};
  /// How long to wait for a file that keeps changing before the change is refused.
  std::chrono::milliseconds settleGiveUp{10000};
};

/// A ladder edit going live (更新修改, runtime/EditSession.h): the served PROGRAM's new bytes,
/// swapped in only while the running version is `base`, and written by `write` once the new
/// version runs (under the change lock, so the file watch does not take the file again).
struct EditedProgram {
  std::string bytes;
  std::string base; ///< the hash of the version the edit was made from
  /// Called after the swap; false with its reason when the file could not be written.
  std::function<bool(std::string &error)> write;
  bool stale = false;   ///< out: refused because `base` no longer runs
  bool swapped = false; ///< out: the new version runs
};

/// Refusal counters for `monitor stats` / --stats.
struct ChangeStats {
  uint64_t refused = 0;    ///< online changes refused (each logged with its reason)
  std::string lastRefusal; ///< the reason of the last one
};

/// The parts `cur` has and `next` lacks, by the names the network JSON gives them: "init",
/// "PLC1", "PLC2", a subroutine as its dialect writes it ("S3", FANUC "P3", IL "SR3"). An online
/// change that loses one needs the operator's word (monitor load --allow-shrink, an edit's
/// removeParts).
std::vector<std::string> removedParts(const VerifiedProgram &cur, const VerifiedProgram &next);

class Controller {
public:
  using Log = std::function<void(const std::string &)>;
  /// `program` is the path the running version came from, `so` its AOT .so (empty for jit /
  /// interp); both are watched by pollProgramFile.
  Controller(Exchange &ex, Executive &exec, ProgramLoader &loader, std::string program, Log log,
             std::string so = {}, ControllerOptions opts = {});

  /// Answer one control request (docs/serve.md lists them). Never throws.
  nlohmann::json handle(const nlohmann::json &req);
  /// serve --trace FILE: define the signal trace from FILE and arm it (docs/trace.md).
  bool armTraceFile(const std::string &file, std::string &error);

  /// Compile `path` with `forces` (an AOT server: load `so`, checked against `path`) and swap
  /// it in. `forces` empty (nullopt, `{}`): carry the running version's forces over, by
  /// statement id; a force whose id no longer exists or is no longer a contact is dropped and
  /// logged. Given: exactly these forces, and an id that is not a contact refuses the change. On
  /// failure the old program keeps running and `error` says why (also logged). Refused (logged,
  /// counted) when the file is not stable within the settle interval, or when the new program is
  /// empty or lacks a part (init, PLC1, PLC2, a subroutine) the running one has, unless
  /// `allowShrink`; and once shutdown() was called.
  /// `edit`: the new content of `path` (the served PROGRAM) is `edit->bytes`, not the file's (no
  /// settle wait); refused with `edit->stale` unless the running version is `edit->base`.
  bool change(const std::string &path, const std::optional<ContactForces> &forces,
              std::string &error, const std::string &so = {}, bool allowShrink = false,
              bool interpreted = false, EditedProgram *edit = nullptr);
  /// The served PROGRAM (its path; serving AOT, the .so in `so`).
  std::string programPath(std::string *so = nullptr);
  /// Read and verify `bytes` as the content of `path` as an online change would (no engine is
  /// built, nothing runs): the check of a ladder edit. Null with `diagnostics`.
  std::optional<VerifiedProgram> verifyEdit(const std::string &path, const std::string &bytes,
                                            std::string &diagnostics) {
    return loader_.verify(path, bytes, diagnostics);
  }

  /// Once a second from the main thread: if the PROGRAM file's (or, serving AOT, the .so's)
  /// mtime changed since the last look, reload it (forces carried over by statement id, as for
  /// change without forces).
  void pollProgramFile();

  /// The live view (docs/ladder-view.md "Live view"): rebuild the running program traced (`on`)
  /// or untraced and switch it in at a tick boundary, forces kept. Like a force, this is not an
  /// online change: the same program on the same state, no init, nothing cleared, no file read,
  /// the version unchanged (rebuildRunning). Later loads keep the choice. True at once when the
  /// running version already is so; false with `error` when the rebuild was refused or the
  /// engine is AOT. `interpreterFirst` (the JIT engine, `on`): build the traced version on the
  /// interpreter, ready within milliseconds, so a page is live at once; a later setTraced(true)
  /// without it puts the traced JIT build in (it records the same trace, ir/Trace.h).
  bool setTraced(bool on, std::string &error, bool interpreterFirst = false);

  /// Whether a client asked the server to stop.
  bool stopRequested() const { return stop_.load(); }

  /// Stop wins over a change in progress: nothing is swapped in after this call, a settle wait
  /// ends at once, and a compile that finishes later is discarded.
  void shutdown();
  /// Whether an online change (or force) is being read, compiled or waited for, or the
  /// optimized build of the last one is.
  bool busy() const { return busy_.load() > 0 || optimizer_.busy(); }
  ChangeStats changeStats() const;

private:
  /// The running program's dialect: the syntax of read / write / force / lock addresses.
  const pipeline::Dialect &dialect() const;
  nlohmann::json doRead(const nlohmann::json &req);
  nlohmann::json doWrite(const nlohmann::json &req);
  nlohmann::json doForce(const nlohmann::json &req);
  nlohmann::json doLock(const nlohmann::json &req);
  nlohmann::json doLoad(const nlohmann::json &req);
  bool refuse(const std::string &what, const std::string &why, std::string &error);
  /// Build the running program again with `forces` and traced or not, on the server's engine
  /// (the interpreter when `interpreted`; serving AOT: the JIT while any force is set, the
  /// served .so again once none is), and switch it in with Executive::switchCode: no init, no
  /// memory cleared, no file read, the same version id. Call with changeMu_ held.
  bool rebuildRunning(const ContactForces &forces, bool traced, bool interpreted,
                      std::string &error);
  bool allowed(const std::string &path, std::string &why) const;
  /// `hash`, when given, receives the settled file's sha256Hash (empty when unreadable).
  bool settle(const std::string &path, std::string &why, std::string *hash = nullptr);
  bool sleepUnlessStopping(std::chrono::milliseconds d);

  Exchange &ex_;
  Executive &exec_;
  ProgramLoader &loader_;
  Log log_;
  std::mutex changeMu_; // one online change / force at a time
  std::string program_; // guarded by changeMu_
  std::string so_;      // the AOT .so of program_ (empty for jit / interp), guarded by changeMu_
  timespec mtime_{};    // of program_ when last loaded / looked at
  timespec soMtime_{};  // of so_ likewise
  std::atomic<bool> stop_{false};
  ControllerOptions opts_;
  std::atomic<bool> shutdown_{false};
  std::atomic<int> busy_{0};
  mutable std::mutex statsMu_;
  ChangeStats changeStats_; // guarded by statsMu_
  std::mutex sleepMu_;
  std::condition_variable sleepCv_; // woken by shutdown()
  /// Serving AOT: the build of the served .so (unforced, untraced), kept while forced JIT code
  /// of the same program runs, to switch back to once the last force is restored. Guarded by
  /// changeMu_.
  std::shared_ptr<ProgramVersion> aotBase_;
  TraceControl trace_{exec_}; // the signal trace (`trace` requests, docs/trace.md)
  ChangeOptimizer optimizer_; // last: stopped and joined before the rest goes
};

} // namespace lj::rt

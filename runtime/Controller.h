// The serve control logic: online change (command or PROGRAM file change), forcing (by
// recompiling with Stmt::force), the lock list, reads/writes and stats, as JSON requests from
// the control socket (docs/serve.md "Control").
#pragma once

#include "runtime/Exchange.h"
#include "runtime/Executive.h"
#include "runtime/ProgramLoader.h"

#include <nlohmann/json.hpp>

#include <atomic>
#include <ctime>
#include <functional>
#include <map>
#include <mutex>
#include <string>

namespace lj::rt {

class Controller {
public:
  using Log = std::function<void(const std::string &)>;
  /// `program` is the path the running version came from, `so` its AOT .so (empty for jit /
  /// interp); both are watched by pollProgramFile.
  Controller(Exchange &ex, Executive &exec, ProgramLoader &loader, std::string program, Log log,
             std::string so = {});

  /// Answer one control request (docs/serve.md lists them). Never throws.
  nlohmann::json handle(const nlohmann::json &req);

  /// Compile `path` with `forces` (an AOT server: load `so`, checked against `path`) and swap
  /// it in. On failure the old program keeps running and `error` says why (also logged).
  bool change(const std::string &path, const std::map<int32_t, int8_t> &forces, std::string &error,
              const std::string &so = {});

  /// Once a second from the main thread: if the PROGRAM file's (or, serving AOT, the .so's)
  /// mtime changed since the last look, reload it (forces are dropped: their line numbers refer
  /// to the old text).
  void pollProgramFile();

  /// Whether a client asked the server to stop.
  bool stopRequested() const { return stop_.load(); }

private:
  nlohmann::json doRead(const nlohmann::json &req);
  nlohmann::json doWrite(const nlohmann::json &req);
  nlohmann::json doForce(const nlohmann::json &req);
  nlohmann::json doLock(const nlohmann::json &req);
  nlohmann::json doLoad(const nlohmann::json &req);

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
};

} // namespace lj::rt

// The serve runtime as a library (docs/serve.md): what `ladderjit serve` runs, for any embedder.
// A Server takes its options (the command line's, parsed but not checked), checks every one
// before anything runs, loads the program, binds the I/O (simulated NC and/or shared memory),
// the retentive store, the control socket, the live view (--http, runtime/LiveView.h) and the
// Modbus server, runs the cyclic executive, and shuts all of it down in order. The driver
// (tools/ladderjit/ServeCmd.cpp) only parses options and handles signals.
#pragma once

#include "ir/Status.h"
#include "runtime/Controller.h"
#include "runtime/Exchange.h"
#include "runtime/Executive.h"

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace lj::rt {

/// Everything serve takes (CLI.md "serve"; each field is the option of that name).
struct ServerOptions {
  std::string dialect; ///< --dialect NAME (pipeline/Dialects.h), empty = by file name
  std::string program;
  std::string engine = "jit"; ///< jit | interp | aot:PATH.so
  uint64_t periodMs = 1;
  bool periodMsGiven = false; ///< --period-ms was on the command line (beats a plc.dit)
  int32_t plc2Nvalue = 200;
  bool plc2NvalueGiven = false;
  uint64_t maxBackwardSteps = 1000000;
  std::string modbus;                 ///< [HOST:]PORT, empty = no Modbus server
  std::string modbusMap;              ///< map file (docs/modbus-map.md), empty = the HNC-8 map
  std::string http;                   ///< [HOST:]PORT of the live view, empty = none
  std::string httpTokenFile;          ///< the live view's token, from this file
  std::vector<std::string> httpHosts; ///< Host names the live view answers besides its address
  bool httpReadOnly = false;          ///< the live view changes nothing
  std::string retain;                 ///< retentive store file, empty = none
  bool retainForce = false;           ///< --retain-force: a file of another layout -> zeros
  uint32_t retainPeriodMs = 100;      ///< minimum gap between periodic retain saves
  bool modbusWriteInputs = false;     ///< Modbus may write X and F (simulation only)
  std::string params;                 ///< P values file
  std::vector<std::string> sets;      ///< ADDR=VALUE at power-up
  uint64_t duration = 0;              ///< seconds, 0 = until stopped
  std::string stats;                  ///< JSON statistics file at exit
  std::string control;      ///< control socket path, empty = <runtime dir>/serve-<pid>.sock
  std::string shm;          ///< shared-memory image name, empty = none
  std::string io = "simnc"; ///< simnc | shm: who writes F
  int rtPriority = -1;      ///< SCHED_FIFO priority, -1 = none
  int cpu = -1;             ///< CPU to pin the scan thread to, -1 = none
  std::vector<std::string> trustKeys; ///< --trust-key for aot .so files, empty = the default key
  std::vector<std::string> loadDirs;  ///< where `monitor load` may read; empty = PROGRAM's dir
  bool watchFile = false;             ///< reload PROGRAM (and the .so) when it changes on disk
  std::string tier;   ///< --tier direct | interp-first | interp-fast-opt; empty = the default
  bool quiet = false; ///< --quiet: no verifier-warning count line (the driver's)
  std::string trace;  ///< --trace FILE: a signal trace definition armed at start (docs/trace.md)

  // Client deadlines of the control socket and Modbus (docs/serve.md "Control").
  uint32_t clientIdleS = 30;        ///< connections idle this long are closed
  uint32_t requestTimeoutMs = 2000; ///< a request must be whole this long after its 1st byte

  /// CLOCK_MONOTONIC ns of the process start: the "start" of the time to the first tick
  /// (docs/serve.md "Time to first tick"); 0 = when load() is called.
  int64_t startNs = 0;
  /// Log lines ("ladderjit serve: " + line on stderr unless set); called from several threads.
  std::function<void(const std::string &)> log;
  /// The status lines (running, control socket, live view, Modbus, the summary at the end;
  /// stdout unless set).
  std::function<void(const std::string &)> say;
};

/// A running serve. Use: load() (checks and loads; nothing runs yet), start() (threads),
/// waitForStop(), shutdown(). Errors are Status values: ErrorCode::Rejected carries the
/// program's diagnostics (the CLI's exit 1), any other code a bad option or a file that cannot
/// be used (exit 2). Not copyable; the destructor stops whatever still runs.
class Server {
public:
  explicit Server(ServerOptions opts);
  ~Server();
  Server(const Server &) = delete;
  Server &operator=(const Server &) = delete;

  /// Check every option and load the first program version. Starts no thread of its own.
  Status load();
  /// Start the scan thread, the background tier-up, the control socket, the live view, the
  /// Modbus server and the file watch, and say where each is.
  Status start();
  /// Block until a stop: requestStop(), `monitor stop`, --duration or the scan thread ending.
  /// `wait(seconds)` sleeps at most that long and returns a reason to stop (e.g. a signal's
  /// name) or nullptr; unset, it waits for requestStop(). Returns the reason.
  std::string waitForStop(const std::function<const char *(double seconds)> &wait = {});
  /// Ask waitForStop to return with `why` (any thread).
  void requestStop(const std::string &why);
  /// Stop everything in order (nothing swapped in any more, Modbus before the executive, the
  /// final retain save), say the summary and write --stats. An error only for --stats.
  Status shutdown(const std::string &why);
  /// After shutdown: a compile LLVM cannot interrupt still runs on a detached thread; the
  /// process should end without destructors (std::_Exit), as `ladderjit serve` does.
  bool mustExitFast() const;

  Executive &executive();
  Exchange &exchange();
  Controller &controller();
  const std::string &controlPath() const;
  int httpPort() const;   ///< the live view's bound port, -1 without --http
  int modbusPort() const; ///< the Modbus server's bound port, -1 without --modbus
  /// After load(): how many verifier warnings the first program version had.
  size_t warnings() const;

  struct Impl;

private:
  std::unique_ptr<Impl> impl_;
};

} // namespace lj::rt

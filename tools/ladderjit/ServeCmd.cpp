// `ladderjit serve`: the real-time runtime (docs/serve.md). Validates every input first (usage
// errors exit 2 before anything runs), loads the program, binds the I/O (simulated NC and/or
// shared memory), starts the cyclic executive and the control socket, then waits for SIGINT /
// SIGTERM, `monitor stop` or --duration (with --watch-file, watching PROGRAM for online change).
#include "tools/ladderjit/Commands.h"

#include "formats/OutputFile.h"
#include "tools/ladderjit/ServeHttp.h"

#include "engines/EngineSpec.h"
#include "formats/InputFiles.h"
#include "formats/StateJson.h"
#include "hosts/HostChain.h"
#include "hosts/SimNc.h"
#include "runtime/ControlPath.h"
#include "runtime/ControlSocket.h"
#include "runtime/Controller.h"
#include "runtime/Exchange.h"
#include "runtime/Executive.h"
#include "runtime/ProgramLoader.h"
#include "runtime/ShmImage.h"
#include "runtime/TierUp.h"
#include "services/ModbusServer.h"
#include "services/RetainStore.h"

#include <signal.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <future>
#include <mutex>
#include <thread>

namespace lj::cli {

namespace {

// Log lines go to stderr, one at a time (several threads log).
void logLine(const std::string &msg) {
  static std::mutex mu;
  std::lock_guard<std::mutex> g(mu);
  std::fprintf(stderr, "ladderjit serve: %s\n", msg.c_str());
  std::fflush(stderr);
}

// The simulated NC's log in serve: the last kNcLogLimit host calls and events (a ring filled in
// place, so the scan thread stops allocating once it is warm), not the whole run's history.
constexpr size_t kNcLogLimit = 256;
hosts::SimNcConfig servedNcConfig() {
  hosts::SimNcConfig c;
  c.logLimit = kNcLogLimit;
  return c;
}

// The simulated NC as the executive's default I/O binding (hnc8-cnc-interface.md).
class SimNcBinding : public rt::IoBinding {
public:
  hosts::SimNc nc{servedNcConfig()};
  void beforeTick(lj_state &s, uint64_t tick) override { nc.beforeTick(s, tick); }
  void afterTick(lj_state &s, uint64_t tick) override { nc.afterTick(s, tick); }
};

bool splitHostPort(const std::string &text, std::string &host, int &port, std::string &error,
                   const char *flag = "--modbus") {
  size_t colon = text.rfind(':');
  std::string p = colon == std::string::npos ? text : text.substr(colon + 1);
  host = colon == std::string::npos || colon == 0 ? "127.0.0.1" : text.substr(0, colon);
  char *end = nullptr;
  long v = p.empty() ? -1 : std::strtol(p.c_str(), &end, 10);
  if (p.empty() || *end != '\0' || v < 0 || v > 65535) {
    error = std::string(flag) + ": expected [HOST:]PORT with PORT 0..65535, got '" + text + "'";
    return false;
  }
  port = static_cast<int>(v);
  return true;
}

// SAVEDATA (lj_host.save_data) asks the retentive store for a save. Runs after the simulated
// NC's binding and layers over the table it installed (whose own save_data still runs first).
class RetainSaveBinding : public rt::IoBinding {
public:
  services::RetainStore *store = nullptr;
  void beforeTick(lj_state &s, uint64_t) override { chain_.bindOver(s); }
  void afterTick(lj_state &, uint64_t) override {}

private:
  hosts::HostChain chain_{[this] {
    if (store) store->requestSave();
  }};
};

// HOOK(modbus): the Modbus server's view of the exchange. A write is acknowledged once the tick
// that applied it is published (a following read sees it) and, for B, durably saved.
services::ModbusBackend modbusBackend(rt::Exchange &ex, services::RetainStore *retain) {
  services::ModbusBackend b;
  b.snapshot = [&ex](lj_state &s) { return ex.snapshot(s); };
  b.post = [&ex](std::vector<formats::Assignment> w) { return ex.post(std::move(w)); };
  // waitApplied returns once the tick that applied the writes is published (runtime/Exchange.h).
  b.waitVisible = [&ex](uint64_t seq, std::chrono::milliseconds timeout) {
    return ex.waitApplied(seq, timeout);
  };
  if (retain)
    b.commitRetained = [retain](std::chrono::milliseconds t) { return retain->commit(t); };
  return b;
}

// The directory of `path`, resolved (realpath): the default --load-dir.
std::string realDirOf(const std::string &path) {
  char *r = ::realpath(path.c_str(), nullptr);
  if (!r) return {};
  std::string full = r;
  std::free(r);
  size_t slash = full.rfind('/');
  return slash == 0 ? "/" : full.substr(0, slash);
}

// --load-dir DIR, resolved; empty with `error` when it is not a directory.
std::string realDir(const std::string &dir, std::string &error) {
  char *r = ::realpath(dir.c_str(), nullptr);
  struct stat st;
  if (!r || ::stat(r, &st) != 0 || !S_ISDIR(st.st_mode)) {
    error = "--load-dir: '" + dir + "' is not a directory";
    std::free(r);
    return {};
  }
  std::string out = r;
  std::free(r);
  return out;
}

// The file watch of --watch-file: polls once a second on its own thread, so a compile it
// starts never delays the main thread's signal handling.
class FileWatch {
public:
  explicit FileWatch(rt::Controller &c) : thread_([this, &c] { loop(c); }) {}
  void stop() {
    {
      std::lock_guard<std::mutex> g(mu_);
      stop_ = true;
    }
    cv_.notify_all();
  }
  std::thread &thread() { return thread_; }

private:
  void loop(rt::Controller &c) {
    std::unique_lock<std::mutex> g(mu_);
    while (!cv_.wait_for(g, std::chrono::seconds(1), [&] { return stop_; })) {
      g.unlock();
      c.pollProgramFile();
      g.lock();
    }
  }
  std::mutex mu_;
  std::condition_variable cv_;
  bool stop_ = false;
  std::thread thread_;
};

bool writeStats(const std::string &path, const nlohmann::json &j, std::string &error) {
  // One output-file function for every command (formats/OutputFile.h, docs/security.md).
  if (formats::writeOutputFile(path, formats::dumpJson(j, 2) + "\n", error)) return true;
  error = "--stats: " + error;
  return false;
}

// TIER: --tier (docs/serve.md "Tiering"): interp-fast-opt is the default of --engine jit; the
// interpreter and an AOT .so have nothing to tier up to.
bool serveTierPlan(const ServeArgs &a, const engines::EngineSpec &spec, rt::TierPlan &plan,
                   std::string &error) {
  if (a.tier.empty()) {
    plan =
        spec.kind == engines::EngineKind::Jit ? rt::TierPlan::InterpFastOpt : rt::TierPlan::Direct;
    return true;
  }
  std::optional<rt::TierPlan> p = rt::parseTierPlan(a.tier, error);
  if (!p) return false;
  if (*p != rt::TierPlan::Direct && spec.kind != engines::EngineKind::Jit) {
    error =
        "--tier " + a.tier + " needs --engine jit (it switches from the interpreter to the JIT)";
    return false;
  }
  plan = *p;
  return true;
}

} // namespace

int runServe(const ServeArgs &a) {
  // ---- validate every input before anything runs ----
  if (a.periodMs == 0 || a.periodMs > 1000)
    return usageError("--period-ms: expected 1..1000, got " + std::to_string(a.periodMs));
  // The engine syntax of `run` (CLI.md): jit, interp or aot:PATH.so.
  Result<engines::EngineSpec> spec = engines::parseEngineSpec(a.engine);
  if (!spec) return usageError(spec.status().message());
  const bool aot = spec->kind == engines::EngineKind::Aot;
  const std::string so = spec->soPath;
  rt::TierPlan tierPlan = rt::TierPlan::Direct;
  std::string tierError;
  if (!serveTierPlan(a, *spec, tierPlan, tierError)) return usageError(tierError);
  if (a.io != "simnc" && a.io != "shm")
    return usageError("--io: expected simnc or shm, got '" + a.io + "'");
  if (a.io == "shm" && a.shm.empty()) return usageError("--io shm needs --shm NAME");
  if (a.rtPriority > 99) return usageError("--rt-priority: expected 1..99");
  std::string error;
  std::string modbusHost;
  int modbusPort = -1;
  if (!a.modbus.empty() && !splitHostPort(a.modbus, modbusHost, modbusPort, error))
    return usageError(error);
  if (!a.modbusMap.empty() && a.modbus.empty())
    return usageError("--modbus-map needs --modbus [HOST:]PORT");
  // --http (docs/serve.md "Live view"): loopback unless HOST is given; the token every request
  // needs is read from --http-token-file, else a fresh one written next to the control socket
  // (below, once its path is known). It is never printed: logs keep what serve prints.
  LiveViewConfig live;
  if (!a.http.empty()) {
    if (!splitHostPort(a.http, live.host, live.port, error, "--http")) return usageError(error);
    live.readOnly = a.httpReadOnly;
    live.engine = a.engine;
    live.hosts = a.httpHosts;
  } else if (!a.httpTokenFile.empty() || a.httpReadOnly || !a.httpHosts.empty()) {
    return usageError(
        "--http-token-file, --http-host and --http-read-only need --http [HOST:]PORT");
  }
  // --set addresses and --params in the program's dialect (CLI.md): --dialect, else the
  // extension.
  const formats::Dialect *setDialect = a.dialect.empty()
                                           ? formats::dialectForPath(a.program, error)
                                           : formats::dialectForOption(a.dialect, error);
  if (!setDialect) return usageError(error);
  std::vector<formats::Assignment> powerUp;
  if (!a.params.empty()) {
    std::string text;
    if (!formats::readFile(a.params, text, error)) return usageError(error);
    std::optional<std::vector<formats::Assignment>> ps =
        formats::parseParams(text, a.params, error, setDialect->profile);
    if (!ps) return usageError(error);
    powerUp = std::move(*ps);
  }
  // The Modbus map (docs/modbus-map.md "Map files"): the program's dialect's addresses.
  std::shared_ptr<const services::ModbusMap> modbusMap;
  if (!a.modbusMap.empty()) {
    std::string text;
    if (!formats::readFile(a.modbusMap, text, error)) return usageError("--modbus-map: " + error);
    std::optional<services::ModbusMap> m =
        services::ModbusMap::parse(text, a.modbusMap, *setDialect, error);
    if (!m) return usageError("--modbus-map: " + error);
    modbusMap = std::make_shared<const services::ModbusMap>(std::move(*m));
  } else if (!a.modbus.empty() && std::string_view(setDialect->name) != "hnc8") {
    return usageError(std::string("--modbus: a ") + setDialect->name +
                      " program needs --modbus-map FILE (the built-in map is HNC-8's; "
                      "docs/modbus-map.md \"Map files\")");
  }
  for (const std::string &item : a.sets) {
    std::optional<formats::Assignment> as = setDialect->parseAssignment(item, error);
    if (!as || !formats::checkWritable(as->addr, as->value, error))
      return usageError("--set: " + error);
    powerUp.push_back(*as);
  }
  if (!a.stats.empty()) { // unwritable --stats is a usage error up front, not after an hour
    if (!formats::checkOutputPath(a.stats, error)) return usageError("--stats: " + error);
  }
  // `monitor load` reads only below these (docs/serve.md "Online change"): --load-dir, else the
  // directory of PROGRAM (and of the served .so).
  rt::ControllerOptions copts;
  for (const std::string &d : a.loadDirs) {
    std::string r = realDir(d, error);
    if (r.empty()) return usageError(error);
    copts.loadDirs.push_back(r);
  }
  if (a.loadDirs.empty()) {
    for (const std::string *p : {&a.program, &so})
      if (!p->empty())
        if (std::string d = realDirOf(*p); !d.empty()) copts.loadDirs.push_back(d);
  }
  // The default socket lives in a private runtime directory (runtime/ControlPath.h), never
  // at a predictable /tmp path another user could plant.
  std::string control = a.control;
  if (control.empty() && !rt::defaultControlPath(control, error)) return usageError(error);
  bool tokenCreated = false;
  if (!a.http.empty()) {
    live.tokenFile = a.httpTokenFile;
    if (live.tokenFile.empty()) {
      live.tokenFile = control;
      if (live.tokenFile.size() > 5 &&
          live.tokenFile.compare(live.tokenFile.size() - 5, 5, ".sock") == 0)
        live.tokenFile.resize(live.tokenFile.size() - 5);
      live.tokenFile += ".http-token";
    }
    if (!httpToken(live.tokenFile, live.token, tokenCreated, error))
      return usageError("--http-token-file: " + error);
  }

  // ---- the program ----
  if (!a.dialect.empty() && !formats::dialectForOption(a.dialect, error)) return usageError(error);
  rt::ProgramLoader loader(aot ? "aot" : a.engine, a.plc2NvalueGiven ? a.plc2Nvalue : -1,
                           a.dialect);
  if (aot) { // who may have signed the .so files of start and of `monitor load` (docs/aot.md)
    engines::TrustedKeys trust;
    if (!engines::loadTrustedKeys(a.trustKeys, trust, error))
      return usageError("--trust-key: " + error);
    loader.setAotTrust(std::move(trust));
  }
  std::optional<formats::DitFile> dit;
  int64_t readyNs = 0;
  // TIER: interpreter-first, the first version is the interpreter, ready once verified.
  std::shared_ptr<rt::ProgramVersion> first =
      tierPlan == rt::TierPlan::Direct
          ? loader.load(a.program, {}, error, &dit, so, nullptr, &readyNs)
          : loader.loadInterpreted(a.program, error, &dit, &readyNs);
  if (!first) {
    // Diagnostics of PROGRAM exit 1; an unreadable file or a .so that does not fit exits 2.
    if (error.find(": error:") != std::string::npos) {
      std::fprintf(stderr, "%s\n", error.c_str());
      return kProgramErrors;
    }
    return usageError(aot ? "--engine " + error : error);
  }
  if (!a.quiet) std::fputs(warningSummary(a.program, first->warnings, a.dialect).c_str(), stderr);
  uint64_t periodMs = a.periodMs;
  if (dit) {
    // A container's parameters are defaults (docs/plc-dit.md "run"): --params/--set win.
    powerUp.insert(powerUp.begin(), dit->params.begin(), dit->params.end());
    if (!a.periodMsGiven) periodMs = dit->periodMs;
  }

  // Signals are taken synchronously by the main thread (sigtimedwait): block them before any
  // thread starts so every thread inherits the mask.
  sigset_t sigs;
  sigemptyset(&sigs);
  sigaddset(&sigs, SIGINT);
  sigaddset(&sigs, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &sigs, nullptr);

  rt::Exchange exchange;
  rt::ExecutiveOptions eo;
  eo.periodNs = periodMs * 1000000;
  eo.maxBackwardSteps = a.maxBackwardSteps;
  eo.rtPriority = a.rtPriority;
  eo.cpu = a.cpu;
  eo.powerUp = powerUp;
  eo.startNs = mainStartNs();
  eo.readyNs = readyNs;
  eo.tierMode = rt::tierPlanName(tierPlan);
  rt::Executive exec(exchange, eo, logLine);

  // ---- I/O binding: the simulated NC (default) and/or the shared-memory image ----
  std::unique_ptr<SimNcBinding> simnc;
  if (a.io == "simnc") {
    simnc = std::make_unique<SimNcBinding>();
    exec.addStartHook([nc = &simnc->nc](lj_state &s) { nc->powerUp(s); });
    exec.addIo(simnc.get());
  }
  rt::ShmMapping shmMap;
  std::unique_ptr<rt::ShmImage> shm;
  if (!a.shm.empty()) {
    if (!shmMap.create(a.shm, a.io == "shm", eo.periodNs, error)) return usageError(error);
    shm = std::make_unique<rt::ShmImage>(shmMap, a.io == "shm", first->prog->profile);
    exec.addIo(shm.get());
    exec.addAfterTickHook([s = shm.get()](const lj_state &st, uint64_t t) { s->publish(st, t); });
  }

  // HOOK(retain): create the retentive store for a.retain (when not empty), restore it in a
  // start hook (exec.addStartHook, runs before init), capture in an after-tick hook and save
  // in a stop hook (exec.addStopHook).
  std::unique_ptr<services::RetainStore> retain;
  auto restored = std::make_unique<lj_state>();
  RetainSaveBinding saveBinding;
  if (!a.retain.empty()) {
    services::RetainConfig rc;
    rc.path = a.retain;
    rc.period = std::chrono::milliseconds(a.retainPeriodMs);
    rc.force = a.retainForce;
    rc.programHash = first->hash;
    rc.profile = first->prog->profile; // what the target retains (docs/retain.md)
    rc.log = logLine;
    retain = std::make_unique<services::RetainStore>(rc);
    // Checked at start, once: a missing directory, a FIFO or symlink in the file's place, a
    // second server on the same file (docs/retain.md "Location").
    if (!retain->prepare(error)) return usageError("--retain: " + error);
    // Read the file here, on the main thread, so a file of another layout stops serve before
    // anything runs; the start hook only copies the result (docs/retain.md "Restore").
    lj_state_reset(restored.get());
    services::RestoreReport rep = retain->restore(*restored, 0); // the executive starts at now_ms 0
    if (rep.status == services::RestoreStatus::LayoutMismatch)
      return usageError("--retain: " + a.retain + " belongs to another layout (see above)");
    if (rep.status == services::RestoreStatus::DamagedNotKept)
      return usageError("--retain: " + a.retain +
                        " is damaged and cannot be moved aside (see above)");
    exec.addStartHook(
        [r = restored.get(), st = retain.get()](lj_state &s) { st->copyRetained(*r, s); });
    exec.addAfterTickHook(
        [st = retain.get()](const lj_state &s, uint64_t tick) { st->afterTick(s, tick); });
    exec.addStopHook(
        [st = retain.get(), &exchange](lj_state &s) { st->stop(s, exchange.lastTick()); });
    // SAVEDATA reaches the store through the lj_host table (after the simulated NC set it).
    saveBinding.store = retain.get();
    exec.addIo(&saveBinding);
    retain->start();
  }

  rt::Controller controller(exchange, exec, loader, a.program, logLine, so, copts);
  rt::ControlOptions co;
  co.idleTimeout = std::chrono::seconds(a.clientIdleS);
  co.requestTimeout = std::chrono::milliseconds(a.requestTimeoutMs);
  co.log = logLine;
  rt::ControlSocket socket([&controller](const nlohmann::json &r) { return controller.handle(r); },
                           co);
  std::unique_ptr<LiveView> liveView;
  if (!a.http.empty()) {
    live.periodNs = eo.periodNs;
    liveView = std::make_unique<LiveView>(exec, exchange, controller, logLine, live);
    exec.addAfterTickHook(liveView->hook());
  }
  if (!socket.start(control, error)) return usageError(error);

  if (!exec.start(first, error)) return usageError(error);
  if (!a.trace.empty() && !controller.armTraceFile(a.trace, error))
    return usageError("--trace: " + error);
  // TIER: the JIT code is compiled in the background and switched in at a tick boundary.
  rt::TierUp tierUp(exec, loader, logLine);
  tierUp.start(first, rt::backgroundTiers(tierPlan));
  first.reset();
  std::printf("ladderjit serve: running '%s' (engine %s, tier %s, period %llu ms, %zu PLC2 "
              "slices)\n"
              "ladderjit serve: control socket %s\n",
              a.program.c_str(), a.engine.c_str(), rt::tierPlanName(tierPlan),
              static_cast<unsigned long long>(periodMs), exec.current()->prog->slices.size(),
              control.c_str());
  if (!a.shm.empty())
    std::printf("ladderjit serve: shared-memory image /%s (io %s)\n",
                a.shm[0] == '/' ? a.shm.c_str() + 1 : a.shm.c_str(), a.io.c_str());
  std::fflush(stdout);

  if (liveView) {
    if (!liveView->start(error)) {
      exec.requestStop();
      exec.join();
      return usageError(error);
    }
    const bool v6 = live.host.find(':') != std::string::npos;
    std::printf("ladderjit serve: live view http://%s%s%s:%d/ (token in %s)%s\n", v6 ? "[" : "",
                live.host.c_str(), v6 ? "]" : "", liveView->port(), live.tokenFile.c_str(),
                a.httpReadOnly ? " read-only" : "");
    std::fflush(stdout);
  }

  // HOOK(modbus): start the Modbus TCP server on modbusHost:modbusPort (when modbusPort >= 0)
  // over exchange.snapshot / exchange.post / exchange.waitApplied.
  std::unique_ptr<services::ModbusServer> modbus;
  if (modbusPort >= 0) {
    services::ModbusConfig mc;
    mc.host = modbusHost;
    mc.port = modbusPort;
    mc.writeInputs = a.modbusWriteInputs;
    mc.idleTimeout = std::chrono::seconds(a.clientIdleS);
    mc.requestTimeout = std::chrono::milliseconds(a.requestTimeoutMs);
    mc.log = logLine;
    mc.map = modbusMap;
    modbus = std::make_unique<services::ModbusServer>(mc, modbusBackend(exchange, retain.get()));
    if (!modbus->start(error)) {
      exec.requestStop();
      exec.join();
      return usageError(error);
    }
    std::printf("ladderjit serve: modbus TCP on %s:%d%s\n", modbusHost.c_str(), modbus->port(),
                a.modbusWriteInputs ? " (X and F writable)" : "");
    std::fflush(stdout);
  }

  // ---- wait: signal, `monitor stop`, --duration or the scan thread ending ----
  std::unique_ptr<FileWatch> watch;
  if (a.watchFile) watch = std::make_unique<FileWatch>(controller);
  auto startT = std::chrono::steady_clock::now();
  const char *why = "stopped";
  while (true) {
    // Wake at least once a second (stop requests), and exactly at --duration.
    double wait = 1.0;
    if (a.duration > 0) {
      double left =
          static_cast<double>(a.duration) -
          std::chrono::duration<double>(std::chrono::steady_clock::now() - startT).count();
      wait = std::clamp(left, 0.001, 1.0);
    }
    timespec timeout{
        static_cast<time_t>(wait),
        static_cast<long>((wait - static_cast<double>(static_cast<time_t>(wait))) * 1e9)};
    int sig = sigtimedwait(&sigs, nullptr, &timeout);
    if (sig == SIGINT || sig == SIGTERM) {
      why = sig == SIGINT ? "SIGINT" : "SIGTERM";
      break;
    }
    if (controller.stopRequested()) {
      why = "monitor stop";
      break;
    }
    if (!exec.running()) break;
    double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - startT).count();
    if (a.duration > 0 && elapsed >= static_cast<double>(a.duration)) {
      why = "--duration";
      break;
    }
  }

  // ---- clean shutdown ----
  // A stop wins over an online change in progress (issue 11 item 5): nothing is swapped in
  // from here on, and a compile LLVM cannot interrupt is not waited for.
  controller.shutdown();
  tierUp.stop(); // TIER: nothing is switched in from here on
  bool liveCompiling = liveView && liveView->stop();
  if (watch) watch->stop();
  // HOOK(modbus): stop the Modbus TCP server (before the executive, so no write is lost).
  if (modbus) modbus->stop();
  exec.requestStop();
  exec.join(); // stop hooks (final retain save) run on the scan thread before this returns
  // Control clients end within a moment unless one is compiling; then the process exit ends
  // that compile (`fastExit`) instead of waiting for it.
  bool fastExit = false;
  {
    auto done = std::make_shared<std::promise<void>>();
    std::future<void> stopped = done->get_future();
    std::thread t([&socket, done] {
      socket.stop();
      done->set_value();
    });
    if (stopped.wait_for(std::chrono::milliseconds(300)) == std::future_status::ready) {
      t.join();
    } else {
      t.detach();
      fastExit = true;
      ::unlink(control.c_str());
      logLine("stopping without waiting for a control request in progress");
    }
  }
  if (tierUp.busy()) { // TIER: a background compile LLVM cannot interrupt ends with the process
    tierUp.detach();
    fastExit = true;
    logLine("stopping without waiting for the background JIT compile");
  }
  if (liveCompiling) {
    fastExit = true;
    logLine("stopping without waiting for the live view's traced JIT build");
  }
  if (watch) {
    if (controller.busy()) {
      watch->thread().detach();
      fastExit = true;
      logLine("stopping without waiting for the file watch's online change");
    } else {
      watch->thread().join();
    }
  }
  // HOOK(retain): stop the store's writer after its final save.
  if (retain) {
    services::RetainStats rs = retain->stats();
    logLine("retain: " + std::to_string(rs.saves) + " saves (last #" +
            std::to_string(rs.lastSaveSeq) + "), " + std::to_string(rs.failures) + " failed");
  }
  if (!a.shm.empty()) shmMap.unlinkName();
  if (tokenCreated && a.httpTokenFile.empty()) ::unlink(live.tokenFile.c_str());

  rt::TickStats st = exec.stats();
  rt::ChangeStats cs = controller.changeStats();
  std::printf("ladderjit serve: %s; %s", why, st.summary().c_str());
  if (cs.refused)
    std::printf("online changes refused: %llu\n", static_cast<unsigned long long>(cs.refused));
  std::fflush(stdout);
  int code = kOk;
  if (!a.stats.empty()) {
    nlohmann::json j = st.toJson();
    j["program"] = exec.current()->path;
    j["engine"] = a.engine;
    j["tier"] = rt::tierPlanName(tierPlan);
    j["stop_reason"] = why;
    j["online_change_refusals"] = cs.refused;
    j["last_refusal"] = cs.lastRefusal;
    if (!writeStats(a.stats, j, error)) code = usageError(error);
  }
  if (fastExit) { // threads still compile: end them with the process, run no destructors
    std::fflush(stdout);
    std::fflush(stderr);
    std::_Exit(code);
  }
  return code;
}

} // namespace lj::cli

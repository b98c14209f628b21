// The serve runtime (runtime/Server.h): the composition `ladderjit serve` runs, one step per
// function: check the options, load the program, build the executive, bind the I/O, the
// retentive store, the control path (controller, socket, live view), start, wait, shut down.
#include "runtime/Server.h"

#include "engines/EngineSpec.h"
#include "formats/InputFiles.h"
#include "formats/OutputFile.h"
#include "formats/StateJson.h"
#include "hosts/HostChain.h"
#include "hosts/SimNc.h"
#include "pipeline/Dialects.h"
#include "runtime/ControlPath.h"
#include "runtime/ControlSocket.h"
#include "runtime/LiveView.h"
#include "runtime/ProgramLoader.h"
#include "runtime/ShmImage.h"
#include "runtime/TierUp.h"
#include "services/ModbusMap.h"
#include "services/ModbusServer.h"
#include "services/RetainStore.h"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <future>
#include <mutex>
#include <optional>
#include <thread>

namespace lj::rt {

namespace {

// Log lines go to stderr, one at a time (several threads log).
void stderrLog(const std::string &msg) {
  static std::mutex mu;
  std::lock_guard<std::mutex> g(mu);
  std::fprintf(stderr, "ladderjit serve: %s\n", msg.c_str());
  std::fflush(stderr);
}

void stdoutSay(const std::string &text) {
  std::fputs(text.c_str(), stdout);
  std::fflush(stdout);
}

Status usage(std::string message) {
  return Status::error(ErrorCode::InvalidArgument, std::move(message));
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
class SimNcBinding : public IoBinding {
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
class RetainSaveBinding : public IoBinding {
public:
  services::RetainStore *store = nullptr;
  void beforeTick(lj_state &s, uint64_t) override { chain_.bindOver(s); }
  void afterTick(lj_state &, uint64_t) override {}

private:
  hosts::HostChain chain_{[this] {
    if (store) store->requestSave();
  }};
};

// The Modbus server's view of the exchange. A write is acknowledged once the tick that applied
// it is published (a following read sees it) and, for B, durably saved.
services::ModbusBackend modbusBackend(Exchange &ex, services::RetainStore *retain) {
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
// starts never delays the thread that waits for a stop.
class FileWatch {
public:
  explicit FileWatch(Controller &c) : thread_([this, &c] { loop(c); }) {}
  void stop() {
    {
      std::lock_guard<std::mutex> g(mu_);
      stop_ = true;
    }
    cv_.notify_all();
  }
  std::thread &thread() { return thread_; }

private:
  void loop(Controller &c) {
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

// --tier (docs/serve.md "Tiering"): interp-fast-opt is the default of --engine jit; the
// interpreter and an AOT .so have nothing to tier up to.
bool serveTierPlan(const ServerOptions &a, const engines::EngineSpec &spec, TierPlan &plan,
                   std::string &error) {
  if (a.tier.empty()) {
    plan = spec.kind == engines::EngineKind::Jit ? TierPlan::InterpFastOpt : TierPlan::Direct;
    return true;
  }
  std::optional<TierPlan> p = parseTierPlan(a.tier, error);
  if (!p) return false;
  if (*p != TierPlan::Direct && spec.kind != engines::EngineKind::Jit) {
    error =
        "--tier " + a.tier + " needs --engine jit (it switches from the interpreter to the JIT)";
    return false;
  }
  plan = *p;
  return true;
}

int64_t monotonicNs() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(
             std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

} // namespace

struct Server::Impl {
  ServerOptions a;
  std::function<void(const std::string &)> log, say;

  // What checkOptions() resolves.
  bool aot = false;
  std::string so; ///< the served .so of --engine aot:PATH.so
  TierPlan tierPlan = TierPlan::Direct;
  std::string modbusHost;
  int modbusPort = -1;
  LiveViewConfig live;
  bool tokenCreated = false;
  const pipeline::Dialect *setDialect = nullptr;
  std::vector<formats::Assignment> powerUp;
  std::shared_ptr<const services::ModbusMap> modbusMap;
  ControllerOptions copts;
  std::string control;

  // What load() makes. Members are destroyed in reverse order: the file watch, Modbus, tier-up
  // and live view before the controller, the executive and the loader they use.
  std::unique_ptr<ProgramLoader> loader;
  std::shared_ptr<ProgramVersion> first;
  size_t firstWarnings = 0; // the first version's verifier warnings (first is dropped at start)
  uint64_t periodMs = 1;
  int64_t readyNs = 0;
  Exchange exchange;
  std::unique_ptr<Executive> exec;
  std::unique_ptr<SimNcBinding> simnc;
  ShmMapping shmMap;
  std::unique_ptr<ShmImage> shm;
  std::unique_ptr<services::RetainStore> retain;
  std::unique_ptr<lj_state> restored = std::make_unique<lj_state>();
  RetainSaveBinding saveBinding;
  std::unique_ptr<Controller> controller;
  std::unique_ptr<ControlSocket> socket;
  std::unique_ptr<LiveView> liveView;
  std::unique_ptr<TierUp> tierUp;
  std::unique_ptr<services::ModbusServer> modbus;
  std::unique_ptr<FileWatch> watch;

  bool started = false, stopped = false, fastExit = false;
  std::mutex stopMu;
  std::condition_variable stopCv;
  std::string stopWhy;

  explicit Impl(ServerOptions o) : a(std::move(o)) {
    log = a.log ? a.log : stderrLog;
    say = a.say ? a.say : stdoutSay;
  }

  Status checkOptions();
  Status checkHttp(std::string &error);
  Status readPowerUp(std::string &error);
  Status loadProgram(std::string &error);
  void makeExecutive();
  Status bindIo(std::string &error);
  Status startRetain(std::string &error);
  void makeControl();
  Status startServices(std::string &error);
  bool stopRequested(std::string &why);
  void stopThreads();
  Status finish(const std::string &why);
  // A start that failed after the scan thread started: stop it, nothing else to report.
  void stopEarly() {
    stopped = true;
    exec->requestStop();
    exec->join();
  }
};

// ---- check every option before anything runs ----

Status Server::Impl::checkOptions() {
  if (a.periodMs == 0 || a.periodMs > 1000)
    return usage("--period-ms: expected 1..1000, got " + std::to_string(a.periodMs));
  // The engine syntax of `run` (CLI.md): jit, interp or aot:PATH.so.
  Result<engines::EngineSpec> spec = engines::parseEngineSpec(a.engine);
  if (!spec) return usage(spec.status().message());
  aot = spec->kind == engines::EngineKind::Aot;
  so = spec->soPath;
  std::string error;
  if (!serveTierPlan(a, *spec, tierPlan, error)) return usage(error);
  if (a.io != "simnc" && a.io != "shm")
    return usage("--io: expected simnc or shm, got '" + a.io + "'");
  if (a.io == "shm" && a.shm.empty()) return usage("--io shm needs --shm NAME");
  if (a.rtPriority > 99) return usage("--rt-priority: expected 1..99");
  if (!a.modbus.empty() && !splitHostPort(a.modbus, modbusHost, modbusPort, error))
    return usage(error);
  if (!a.modbusMap.empty() && a.modbus.empty())
    return usage("--modbus-map needs --modbus [HOST:]PORT");
  if (!a.http.empty()) {
    if (!splitHostPort(a.http, live.host, live.port, error, "--http")) return usage(error);
    live.readOnly = a.httpReadOnly;
    live.engine = a.engine;
    live.hosts = a.httpHosts;
  } else if (!a.httpTokenFile.empty() || a.httpReadOnly || !a.httpHosts.empty()) {
    return usage("--http-token-file, --http-host and --http-read-only need --http [HOST:]PORT");
  }
  if (Status s = readPowerUp(error); !s.ok()) return s;
  if (!a.stats.empty()) { // unwritable --stats is a usage error up front, not after an hour
    if (!formats::checkOutputPath(a.stats, error)) return usage("--stats: " + error);
  }
  // `monitor load` reads only below these (docs/serve.md "Online change"): --load-dir, else the
  // directory of PROGRAM (and of the served .so).
  for (const std::string &d : a.loadDirs) {
    std::string r = realDir(d, error);
    if (r.empty()) return usage(error);
    copts.loadDirs.push_back(r);
  }
  if (a.loadDirs.empty()) {
    for (const std::string *p : {&a.program, &so})
      if (!p->empty())
        if (std::string d = realDirOf(*p); !d.empty()) copts.loadDirs.push_back(d);
  }
  // The default socket lives in a private runtime directory (runtime/ControlPath.h), never
  // at a predictable /tmp path another user could plant.
  control = a.control;
  if (control.empty() && !defaultControlPath(control, error)) return usage(error);
  return checkHttp(error);
}

// --params, --set and the Modbus map, in the program's dialect (CLI.md): --dialect, else the
// extension.
Status Server::Impl::readPowerUp(std::string &error) {
  Result<const pipeline::Dialect *> d = a.dialect.empty() ? pipeline::dialectForPath(a.program)
                                                          : pipeline::dialectForOption(a.dialect);
  if (!d) return usage(d.status().message());
  setDialect = *d;
  if (!a.params.empty()) {
    std::string text;
    if (!formats::readFile(a.params, text, error)) return usage(error);
    std::optional<std::vector<formats::Assignment>> ps =
        formats::parseParams(text, a.params, error, setDialect->profile);
    if (!ps) return usage(error);
    powerUp = std::move(*ps);
  }
  // The Modbus map (docs/modbus-map.md "Map files"): the program's dialect's addresses.
  if (!a.modbusMap.empty()) {
    std::string text;
    if (!formats::readFile(a.modbusMap, text, error)) return usage("--modbus-map: " + error);
    std::optional<services::ModbusMap> m =
        services::ModbusMap::parse(text, a.modbusMap, *setDialect, error);
    if (!m) return usage("--modbus-map: " + error);
    modbusMap = std::make_shared<const services::ModbusMap>(std::move(*m));
  } else if (!a.modbus.empty() && std::string_view(setDialect->name) != "hnc8") {
    return usage(std::string("--modbus: a ") + setDialect->name +
                 " program needs --modbus-map FILE (the built-in map is HNC-8's; "
                 "docs/modbus-map.md \"Map files\")");
  }
  for (const std::string &item : a.sets) {
    std::optional<formats::Assignment> as = setDialect->parseAssignment(item, error);
    if (!as || !formats::checkWritable(as->addr, as->value, error)) return usage("--set: " + error);
    powerUp.push_back(*as);
  }
  return {};
}

// --http (docs/serve.md "Live view"): the token every request needs is read from
// --http-token-file, else a fresh one written next to the control socket. It is never printed:
// logs keep what serve prints.
Status Server::Impl::checkHttp(std::string &error) {
  if (a.http.empty()) return {};
  live.tokenFile = a.httpTokenFile;
  if (live.tokenFile.empty()) {
    live.tokenFile = control;
    if (live.tokenFile.size() > 5 &&
        live.tokenFile.compare(live.tokenFile.size() - 5, 5, ".sock") == 0)
      live.tokenFile.resize(live.tokenFile.size() - 5);
    live.tokenFile += ".http-token";
  }
  if (!httpToken(live.tokenFile, live.token, tokenCreated, error))
    return usage("--http-token-file: " + error);
  return {};
}

// ---- the program ----

Status Server::Impl::loadProgram(std::string &error) {
  if (!a.dialect.empty())
    if (Result<const pipeline::Dialect *> d = pipeline::dialectForOption(a.dialect); !d)
      return usage(d.status().message());
  loader = std::make_unique<ProgramLoader>(aot ? "aot" : a.engine,
                                           a.plc2NvalueGiven ? a.plc2Nvalue : -1, a.dialect);
  if (aot) { // who may have signed the .so files of start and of `monitor load` (docs/aot.md)
    signing::TrustedKeys trust;
    if (!signing::loadTrustedKeys(a.trustKeys, trust, error)) return usage("--trust-key: " + error);
    loader->setAotTrust(std::move(trust));
  }
  std::optional<formats::DitFile> dit;
  // TIER: interpreter-first, the first version is the interpreter, ready once verified.
  first = tierPlan == TierPlan::Direct
              ? loader->load(a.program, {}, error, &dit, so, nullptr, &readyNs)
              : loader->loadInterpreted(a.program, error, &dit, &readyNs);
  if (!first) {
    // Diagnostics of PROGRAM are the program's errors; an unreadable file or a .so that does
    // not fit is a usage error.
    if (error.find(": error:") != std::string::npos)
      return Status::error(ErrorCode::Rejected, error);
    return usage(aot ? "--engine " + error : error);
  }
  firstWarnings = first->warnings;
  periodMs = a.periodMs;
  if (dit) {
    // A container's parameters are defaults (docs/plc-dit.md "run"): --params/--set win.
    powerUp.insert(powerUp.begin(), dit->params.begin(), dit->params.end());
    if (!a.periodMsGiven) periodMs = dit->periodMs;
  }
  return {};
}

void Server::Impl::makeExecutive() {
  ExecutiveOptions eo;
  eo.periodNs = periodMs * 1000000;
  eo.maxBackwardSteps = a.maxBackwardSteps;
  eo.rtPriority = a.rtPriority;
  eo.cpu = a.cpu;
  eo.powerUp = powerUp;
  eo.startNs = a.startNs ? a.startNs : monotonicNs();
  eo.readyNs = readyNs;
  eo.tierMode = tierPlanName(tierPlan);
  exec = std::make_unique<Executive>(exchange, eo, log);
}

// ---- I/O binding: the simulated NC (default) and/or the shared-memory image ----

Status Server::Impl::bindIo(std::string &error) {
  if (a.io == "simnc") {
    simnc = std::make_unique<SimNcBinding>();
    exec->addStartHook([nc = &simnc->nc](lj_state &s) { nc->powerUp(s); });
    exec->addIo(simnc.get());
  }
  if (!a.shm.empty()) {
    if (!shmMap.create(a.shm, a.io == "shm", periodMs * 1000000, error)) return usage(error);
    shm = std::make_unique<ShmImage>(shmMap, a.io == "shm", first->prog->profile);
    exec->addIo(shm.get());
    exec->addAfterTickHook([s = shm.get()](const lj_state &st, uint64_t t) { s->publish(st, t); });
  }
  return {};
}

// The retentive store (--retain, docs/retain.md): restored in a start hook (before init),
// captured after each tick, saved in a stop hook; SAVEDATA reaches it through lj_host.
Status Server::Impl::startRetain(std::string &error) {
  if (a.retain.empty()) return {};
  services::RetainConfig rc;
  rc.path = a.retain;
  rc.period = std::chrono::milliseconds(a.retainPeriodMs);
  rc.force = a.retainForce;
  rc.programHash = first->hash;
  rc.profile = first->prog->profile; // what the target retains (docs/retain.md)
  rc.log = log;
  retain = std::make_unique<services::RetainStore>(rc);
  // Checked at start, once: a missing directory, a FIFO or symlink in the file's place, a
  // second server on the same file (docs/retain.md "Location").
  if (!retain->prepare(error)) return usage("--retain: " + error);
  // Read the file here, before any thread runs, so a file of another layout stops serve before
  // anything runs; the start hook only copies the result (docs/retain.md "Restore").
  lj_state_reset(restored.get());
  services::RestoreReport rep = retain->restore(*restored, 0); // the executive starts at now_ms 0
  if (rep.status == services::RestoreStatus::LayoutMismatch)
    return usage("--retain: " + a.retain + " belongs to another layout (see above)");
  if (rep.status == services::RestoreStatus::DamagedNotKept)
    return usage("--retain: " + a.retain + " is damaged and cannot be moved aside (see above)");
  exec->addStartHook(
      [r = restored.get(), st = retain.get()](lj_state &s) { st->copyRetained(*r, s); });
  exec->addAfterTickHook(
      [st = retain.get()](const lj_state &s, uint64_t tick) { st->afterTick(s, tick); });
  exec->addStopHook(
      [st = retain.get(), ex = &exchange](lj_state &s) { st->stop(s, ex->lastTick()); });
  // SAVEDATA reaches the store through the lj_host table (after the simulated NC set it).
  saveBinding.store = retain.get();
  exec->addIo(&saveBinding);
  retain->start();
  return {};
}

// The controller, the control socket and the live view's trace hook (before exec->start).
void Server::Impl::makeControl() {
  controller = std::make_unique<Controller>(exchange, *exec, *loader, a.program, log, so, copts);
  ControlOptions co;
  co.idleTimeout = std::chrono::seconds(a.clientIdleS);
  co.requestTimeout = std::chrono::milliseconds(a.requestTimeoutMs);
  co.log = log;
  socket = std::make_unique<ControlSocket>(
      [c = controller.get()](const nlohmann::json &r) { return c->handle(r); }, co);
  if (!a.http.empty()) {
    live.periodNs = periodMs * 1000000;
    liveView = std::make_unique<LiveView>(*exec, exchange, *controller, log, live);
    exec->addAfterTickHook(liveView->hook());
  }
}

// The control socket, the scan thread, the tier-up, the live view's server, Modbus, the watch.
Status Server::Impl::startServices(std::string &error) {
  if (!socket->start(control, error)) return usage(error);
  if (!exec->start(first, error)) return usage(error);
  started = true;
  if (!a.trace.empty() && !controller->armTraceFile(a.trace, error))
    return usage("--trace: " + error);
  // TIER: the JIT code is compiled in the background and switched in at a tick boundary.
  tierUp = std::make_unique<TierUp>(*exec, *loader, log);
  tierUp->start(first, backgroundTiers(tierPlan));
  first.reset();
  char line[512];
  std::snprintf(line, sizeof line,
                "ladderjit serve: running '%s' (engine %s, tier %s, period %llu ms, %zu PLC2 "
                "slices)\n",
                a.program.c_str(), a.engine.c_str(), tierPlanName(tierPlan),
                static_cast<unsigned long long>(periodMs), exec->current()->prog->slices.size());
  std::string text = line;
  text += "ladderjit serve: control socket " + control + "\n";
  if (!a.shm.empty())
    text += "ladderjit serve: shared-memory image /" +
            std::string(a.shm[0] == '/' ? a.shm.c_str() + 1 : a.shm.c_str()) + " (io " + a.io +
            ")\n";
  say(text);

  if (liveView) {
    if (!liveView->start(error)) {
      stopEarly();
      return usage(error);
    }
    const bool v6 = live.host.find(':') != std::string::npos;
    say("ladderjit serve: live view http://" + std::string(v6 ? "[" : "") + live.host +
        (v6 ? "]" : "") + ":" + std::to_string(liveView->port()) + "/ (token in " + live.tokenFile +
        ")" + (a.httpReadOnly ? " read-only" : "") + "\n");
  }

  // The Modbus TCP server over exchange.snapshot / post / waitApplied.
  if (modbusPort >= 0) {
    services::ModbusConfig mc;
    mc.host = modbusHost;
    mc.port = modbusPort;
    mc.writeInputs = a.modbusWriteInputs;
    mc.idleTimeout = std::chrono::seconds(a.clientIdleS);
    mc.requestTimeout = std::chrono::milliseconds(a.requestTimeoutMs);
    mc.log = log;
    mc.map = modbusMap;
    modbus = std::make_unique<services::ModbusServer>(mc, modbusBackend(exchange, retain.get()));
    if (!modbus->start(error)) {
      stopEarly();
      return usage(error);
    }
    say("ladderjit serve: modbus TCP on " + modbusHost + ":" + std::to_string(modbus->port()) +
        (a.modbusWriteInputs ? " (X and F writable)" : "") + "\n");
  }
  if (a.watchFile) watch = std::make_unique<FileWatch>(*controller);
  return {};
}

// ---- wait ----

bool Server::Impl::stopRequested(std::string &why) {
  {
    std::lock_guard<std::mutex> g(stopMu);
    if (!stopWhy.empty()) {
      why = stopWhy;
      return true;
    }
  }
  if (controller->stopRequested()) {
    why = "monitor stop";
    return true;
  }
  return !exec->running();
}

// ---- clean shutdown ----

// A stop wins over an online change in progress (issue 11 item 5): nothing is swapped in from
// here on, and a compile LLVM cannot interrupt is not waited for (fastExit).
void Server::Impl::stopThreads() {
  controller->shutdown();
  tierUp->stop(); // TIER: nothing is switched in from here on
  bool liveCompiling = liveView && liveView->stop();
  if (watch) watch->stop();
  if (modbus) modbus->stop(); // before the executive, so no write is lost
  exec->requestStop();
  exec->join(); // stop hooks (final retain save) run on the scan thread before this returns
  // Control clients end within a moment unless one is compiling; then the process exit ends
  // that compile instead of waiting for it.
  {
    auto done = std::make_shared<std::promise<void>>();
    std::future<void> stopped = done->get_future();
    std::thread t([s = socket.get(), done] {
      s->stop();
      done->set_value();
    });
    if (stopped.wait_for(std::chrono::milliseconds(300)) == std::future_status::ready) {
      t.join();
    } else {
      t.detach();
      fastExit = true;
      ::unlink(control.c_str());
      log("stopping without waiting for a control request in progress");
    }
  }
  if (tierUp->busy()) { // TIER: a background compile LLVM cannot interrupt ends with the process
    tierUp->detach();
    fastExit = true;
    log("stopping without waiting for the background JIT compile");
  }
  if (liveCompiling) {
    fastExit = true;
    log("stopping without waiting for the live view's traced JIT build");
  }
  if (watch) {
    if (controller->busy()) {
      watch->thread().detach();
      fastExit = true;
      log("stopping without waiting for the file watch's online change");
    } else {
      watch->thread().join();
    }
  }
}

Status Server::Impl::finish(const std::string &why) {
  stopThreads();
  if (retain) {
    services::RetainStats rs = retain->stats();
    log("retain: " + std::to_string(rs.saves) + " saves (last #" + std::to_string(rs.lastSaveSeq) +
        "), " + std::to_string(rs.failures) + " failed");
  }
  if (!a.shm.empty()) shmMap.unlinkName();
  if (tokenCreated && a.httpTokenFile.empty()) ::unlink(live.tokenFile.c_str());

  TickStats st = exec->stats();
  ChangeStats cs = controller->changeStats();
  std::string text = "ladderjit serve: " + why + "; " + st.summary();
  if (cs.refused) text += "online changes refused: " + std::to_string(cs.refused) + "\n";
  say(text);
  if (a.stats.empty()) return {};
  nlohmann::json j = st.toJson();
  j["program"] = exec->current()->path;
  j["engine"] = a.engine;
  j["tier"] = tierPlanName(tierPlan);
  j["stop_reason"] = why;
  j["online_change_refusals"] = cs.refused;
  j["last_refusal"] = cs.lastRefusal;
  // One output-file function for every command (formats/OutputFile.h, docs/security.md).
  std::string error;
  if (!formats::writeOutputFile(a.stats, formats::dumpJson(j, 2) + "\n", error))
    return usage("--stats: " + error);
  return {};
}

// ---- Server ----

Server::Server(ServerOptions opts) : impl_(std::make_unique<Impl>(std::move(opts))) {}

Server::~Server() {
  if (impl_->started && !impl_->stopped) (void)shutdown("stopped");
}

Status Server::load() {
  Impl &m = *impl_;
  if (Status s = m.checkOptions(); !s.ok()) return s;
  std::string error;
  return m.loadProgram(error);
}

Status Server::start() {
  Impl &m = *impl_;
  if (!m.first) return Status::error(ErrorCode::Internal, "Server::start before a load");
  std::string error;
  m.makeExecutive();
  if (Status s = m.bindIo(error); !s.ok()) return s;
  if (Status s = m.startRetain(error); !s.ok()) return s;
  m.makeControl();
  return m.startServices(error);
}

std::string Server::waitForStop(const std::function<const char *(double)> &wait) {
  Impl &m = *impl_;
  const auto startT = std::chrono::steady_clock::now();
  auto elapsed = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - startT).count();
  };
  std::string why = "stopped";
  while (true) {
    // Wake at least once a second (stop requests), and exactly at --duration.
    double w = 1.0;
    if (m.a.duration > 0) w = std::clamp(static_cast<double>(m.a.duration) - elapsed(), 0.001, 1.0);
    if (wait) {
      if (const char *reason = wait(w)) return reason;
    } else {
      std::unique_lock<std::mutex> g(m.stopMu);
      m.stopCv.wait_for(g, std::chrono::duration<double>(w), [&] { return !m.stopWhy.empty(); });
    }
    if (m.stopRequested(why)) return why;
    if (m.a.duration > 0 && elapsed() >= static_cast<double>(m.a.duration)) return "--duration";
  }
}

void Server::requestStop(const std::string &why) {
  {
    std::lock_guard<std::mutex> g(impl_->stopMu);
    impl_->stopWhy = why.empty() ? "stopped" : why;
  }
  impl_->stopCv.notify_all();
}

Status Server::shutdown(const std::string &why) {
  if (!impl_->started || impl_->stopped) return {};
  impl_->stopped = true;
  return impl_->finish(why);
}

bool Server::mustExitFast() const { return impl_->fastExit; }
Executive &Server::executive() { return *impl_->exec; }
Exchange &Server::exchange() { return impl_->exchange; }
Controller &Server::controller() { return *impl_->controller; }
const std::string &Server::controlPath() const { return impl_->control; }
int Server::httpPort() const { return impl_->liveView ? impl_->liveView->port() : -1; }
int Server::modbusPort() const { return impl_->modbus ? impl_->modbus->port() : -1; }
size_t Server::warnings() const { return impl_->firstWarnings; }

} // namespace lj::rt

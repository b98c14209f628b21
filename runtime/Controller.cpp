// Control requests of `ladderjit serve`: each is one JSON object with "cmd"; each answer has
// "ok" and either the result or "error" (docs/serve.md "Control").
#include "runtime/Controller.h"

#include "engines/EngineSpec.h"
#include "pipeline/Dialects.h"

#include "formats/InputFiles.h"
#include "formats/PlcDit.h"

#include <sys/stat.h>
#include <time.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <memory>

namespace lj::rt {

std::vector<std::string> removedParts(const VerifiedProgram &cur, const VerifiedProgram &next) {
  std::vector<std::string> out;
  if (!cur.init.empty() && next.init.empty()) out.push_back("init");
  if (!cur.plc1.empty() && next.plc1.empty()) out.push_back("PLC1");
  if (!cur.plc2.empty() && next.plc2.empty()) out.push_back("PLC2");
  const char *name = cur.profile ? cur.profile->area(Area::Subroutine).name : "S";
  for (const Subroutine &sub : cur.subs)
    if (sub.number >= 0 && (sub.number >= static_cast<int32_t>(next.subByNumber.size()) ||
                            next.subByNumber[static_cast<size_t>(sub.number)] < 0))
      out.push_back(std::string(name ? name : "S") + std::to_string(sub.number));
  return out;
}

namespace {

using nlohmann::json;

json fail(const std::string &msg) { return {{"ok", false}, {"error", msg}}; }

timespec mtimeOf(const std::string &path) {
  struct stat st;
  if (::stat(path.c_str(), &st) != 0) return {};
  return st.st_mtim;
}

bool sameTime(const timespec &a, const timespec &b) {
  return a.tv_sec == b.tv_sec && a.tv_nsec == b.tv_nsec;
}

// `text` with every byte outside printable ASCII as \xNN: safe in a JSON string whatever the
// path bytes were.
std::string printable(const std::string &text) {
  static constexpr char kHex[] = "0123456789ABCDEF";
  std::string out;
  for (unsigned char c : text) {
    if (c >= 0x20 && c < 0x7f && c != '\\') {
      out += static_cast<char>(c);
    } else {
      out += "\\x";
      out += kHex[c >> 4];
      out += kHex[c & 15];
    }
  }
  return out;
}

// Counts a request in progress for Controller::busy().
struct BusyCount {
  std::atomic<int> &n;
  explicit BusyCount(std::atomic<int> &c) : n(c) { ++n; }
  ~BusyCount() { --n; }
  BusyCount(const BusyCount &) = delete;
  BusyCount &operator=(const BusyCount &) = delete;
};

// What a settle interval compares: size, mtime, inode and content.
struct FileMark {
  bool ok = false;
  off_t size = 0;
  ino_t ino = 0;
  timespec mtime{};
  std::chrono::milliseconds age{0}; // since the last modification
  std::string hash;
  bool same(const FileMark &o) const {
    return size == o.size && ino == o.ino && sameTime(mtime, o.mtime) && hash == o.hash;
  }
};

FileMark markOf(const std::string &path) {
  FileMark m;
  struct stat st;
  std::string text, err;
  if (::stat(path.c_str(), &st) != 0 || !formats::readFile(path, text, err)) return m;
  m.ok = true;
  m.size = st.st_size;
  m.ino = st.st_ino;
  m.mtime = st.st_mtim;
  timespec now;
  clock_gettime(CLOCK_REALTIME, &now);
  int64_t ms = (int64_t{now.tv_sec} - st.st_mtim.tv_sec) * 1000 +
               (int64_t{now.tv_nsec} - st.st_mtim.tv_nsec) / 1000000;
  m.age = std::chrono::milliseconds(ms < 0 ? 0 : ms);
  m.hash = formats::sha256Hash(text);
  return m;
}

bool resolvedPath(const std::string &path, std::string &out) {
  char *r = ::realpath(path.c_str(), nullptr);
  if (!r) return false;
  out = r;
  std::free(r);
  return true;
}

std::string joinDirs(const std::vector<std::string> &dirs) {
  std::string out;
  for (const std::string &d : dirs) out += (out.empty() ? "" : ", ") + d;
  return out;
}

// What `next` lacks that `cur` has: empty, or the reason an online change would lose a part.
std::string lostParts(const VerifiedProgram &cur, const VerifiedProgram &next) {
  if (next.stmts.empty()) return "the new program is empty";
  std::string lost;
  for (const std::string &part : removedParts(cur, next))
    lost +=
        (lost.empty() ? "" : ", ") + (part == "init" ? std::string("the init part")
                                      : part == "PLC1" || part == "PLC2" ? part
                                                                         : "subroutine " + part);
  return lost.empty() ? lost : "the new program lacks " + lost + " of the running one";
}

// The string items of `req[key]`, or an error naming the key.
bool strings(const json &req, const char *key, std::vector<std::string> &out, std::string &err) {
  auto it = req.find(key);
  if (it == req.end() || !it->is_array() || it->empty()) {
    err = std::string("'") + key + "' must be a non-empty array of strings";
    return false;
  }
  for (const json &j : *it) {
    if (!j.is_string()) {
      err = std::string("'") + key + "' must be a non-empty array of strings";
      return false;
    }
    out.push_back(j.get<std::string>());
  }
  return true;
}

std::string formatAssignment(const formats::Assignment &a) {
  return a.addr.text + "=" + std::to_string(a.value);
}

// The running program's symbols (none before a program runs).
std::vector<Symbol> symbolsOf(Executive &exec) {
  std::shared_ptr<ProgramVersion> cur = exec.current();
  return cur && cur->prog ? cur->prog->symbols : std::vector<Symbol>{};
}

// An address in the running program's dialect, or one of its symbols (formats/Address.h).
std::optional<formats::CliAddress> address(const pipeline::Dialect &d, Executive &exec,
                                           std::string_view item, std::string &err) {
  return formats::parseAddressIn(d.parseAddress, symbolsOf(exec), item, err);
}

// A write or lock item in the running program's dialect (its address perhaps a symbol of the
// program): parsed and checked for writability (formats/Address.h, pipeline/Dialects.h).
std::optional<formats::Assignment> writable(const pipeline::Dialect &d, Executive &exec,
                                            const std::string &item, std::string &err) {
  std::optional<formats::Assignment> a =
      formats::parseAssignmentIn(d.parseAddress, d.parseAssignment, symbolsOf(exec), item, err);
  if (a && !formats::checkWritable(a->addr, a->value, err)) return std::nullopt;
  return a;
}

} // namespace

namespace {
// The trace's addresses in the running program's syntax (pipeline/Dialects.h).
AddressParser traceParser(const pipeline::Dialect &d) {
  return [&d](std::string_view text, std::string &error) { return d.parseAddress(text, error); };
}
} // namespace

bool Controller::armTraceFile(const std::string &file, std::string &error) {
  std::string text;
  if (!formats::readFile(file, text, error)) return false;
  return trace_.defineAndArm(text, file, traceParser(dialect()), exec_.periodNs(), error);
}

const pipeline::Dialect &Controller::dialect() const {
  std::shared_ptr<ProgramVersion> cur = exec_.current();
  const pipeline::Dialect *d = cur && cur->prog && cur->prog->profile
                                   ? pipeline::dialectNamed(cur->prog->profile->name)
                                   : nullptr;
  return d ? *d : pipeline::defaultDialect();
}

Controller::Controller(Exchange &ex, Executive &exec, ProgramLoader &loader, std::string program,
                       Log log, std::string so, ControllerOptions opts)
    : ex_(ex), exec_(exec), loader_(loader), log_(std::move(log)), program_(std::move(program)),
      so_(std::move(so)), opts_(std::move(opts)), optimizer_(exec, loader, log_) {
  mtime_ = mtimeOf(program_);
  if (!so_.empty()) soMtime_ = mtimeOf(so_);
}

void Controller::shutdown() {
  {
    std::lock_guard<std::mutex> g(sleepMu_);
    shutdown_.store(true);
  }
  sleepCv_.notify_all();
  optimizer_.stop();
}

ChangeStats Controller::changeStats() const {
  std::lock_guard<std::mutex> g(statsMu_);
  return changeStats_;
}

bool Controller::refuse(const std::string &what, const std::string &why, std::string &error) {
  error = why;
  {
    std::lock_guard<std::mutex> g(statsMu_);
    ++changeStats_.refused;
    changeStats_.lastRefusal = printable(what + ": " + why);
  }
  if (log_) log_("online change of " + what + " refused, the old program keeps running: " + why);
  return false;
}

bool Controller::sleepUnlessStopping(std::chrono::milliseconds d) {
  std::unique_lock<std::mutex> g(sleepMu_);
  return !sleepCv_.wait_for(g, d, [&] { return shutdown_.load(); });
}

bool Controller::allowed(const std::string &path, std::string &why) const {
  std::string real;
  if (!resolvedPath(path, real)) {
    why = "cannot read '" + path + "': " + std::strerror(errno);
    return false;
  }
  for (const std::string &dir : opts_.loadDirs)
    if (real.size() > dir.size() && real.compare(0, dir.size(), dir) == 0 &&
        (dir.back() == '/' || real[dir.size()] == '/'))
      return true;
  why = "'" + path + "' is outside the directories this server loads from (" +
        (opts_.loadDirs.empty() ? std::string("none") : joinDirs(opts_.loadDirs)) +
        "; see serve --load-dir)";
  return false;
}

bool Controller::settle(const std::string &path, std::string &why, std::string *hash) {
  // A file is taken once it has not changed for a settle interval: an editor or a copy that
  // is still writing changes size, mtime or content in the meantime.
  FileMark a = markOf(path);
  if (hash) *hash = a.hash;
  if (!a.ok) return true; // the loader reports the read error
  auto giveUp = std::chrono::steady_clock::now() + opts_.settleGiveUp;
  if (a.age >= opts_.settle) return true;
  for (;;) {
    if (!sleepUnlessStopping(opts_.settle)) {
      why = "the server is stopping";
      return false;
    }
    FileMark b = markOf(path);
    if (hash) *hash = b.hash;
    if (b.ok && a.same(b)) return true;
    if (std::chrono::steady_clock::now() >= giveUp) {
      why = "'" + path + "' kept changing for " +
            std::to_string(opts_.settleGiveUp.count() / 1000) + " s (still being written?)";
      return false;
    }
    a = b;
  }
}

bool Controller::change(const std::string &path, const std::optional<ContactForces> &forces,
                        std::string &error, const std::string &so, bool allowShrink,
                        bool interpreted, EditedProgram *edit) {
  BusyCount busy(busy_);
  std::lock_guard<std::mutex> g(changeMu_);
  const std::string what = (so.empty() ? "'" + path + "'" : "'" + path + "' (" + so + ")") +
                           (edit ? " (ladder edit)" : "");
  if (shutdown_.load()) return refuse(what, "the server is stopping", error);
  std::string why, settledHash;
  const auto settleStart = std::chrono::steady_clock::now();
  if (edit) { // the bytes are at hand: nothing is being written
    std::shared_ptr<ProgramVersion> running = exec_.current();
    if (!running || running->hash != edit->base) {
      edit->stale = true;
      return refuse(what,
                    "the edit was made from " + edit->base + ", but " +
                        (running ? running->hash : std::string("nothing")) +
                        " runs now (another client, monitor load or the file watch changed it)",
                    error);
    }
  } else if (!settle(path, why, &settledHash) || (!so.empty() && !settle(so, why)))
    return refuse(what, why, error);
  // The change is requested from here on: the wait for a file still being written is not part
  // of its latency (docs/serve.md "Online change latency").
  auto t0 = std::chrono::steady_clock::now();
  const int64_t settleNs =
      std::chrono::duration_cast<std::chrono::nanoseconds>(t0 - settleStart).count();
  const int64_t requestedNs =
      std::chrono::duration_cast<std::chrono::nanoseconds>(t0.time_since_epoch()).count();
  timespec mt = mtimeOf(path);
  timespec soMt = so.empty() ? timespec{} : mtimeOf(so);
  // Forces are runtime state: read them from the running version under changeMu_, so a force
  // request and an online change never lose each other's work.
  ContactForces want;
  if (forces) {
    want = *forces;
  } else if (std::shared_ptr<ProgramVersion> running = exec_.current()) {
    want = running->forces;
  }
  std::vector<std::string> dropped;
  // An AOT .so cannot be forced: with forces, the served .so is loaded (and kept, aotBase_) and
  // forced JIT code of the same program is swapped in instead (rebuildRunning).
  const bool aotForced = loader_.aot() && !want.empty();
  std::shared_ptr<ProgramVersion> next = loader_.load(
      path, aotForced ? ContactForces{} : want, error, nullptr, so, forces ? nullptr : &dropped,
      nullptr, interpreted, edit ? &edit->bytes : nullptr);
  if (!next) return refuse(what, error, error);
  std::shared_ptr<ProgramVersion> aotBase = loader_.aot() ? next : nullptr;
  if (aotForced) {
    if (!checkForces(*next->prog, want, error, forces ? nullptr : &dropped))
      return refuse(what, error, error);
    if (!want.empty()) {
      std::shared_ptr<ProgramVersion> forced =
          loader_.rebuild(*next, want, false, engines::EngineKind::Jit, error);
      if (!forced) return refuse(what, error, error);
      forced->frontendNs = next->frontendNs;
      forced->so = next->so;
      next = std::move(forced);
    }
  }
  // Stop wins over a compile in progress: a version finished after a stop request is dropped.
  if (shutdown_.load())
    return refuse(what, "the server is stopping; the new version is discarded", error);
  if (!settledHash.empty() && next->hash != settledHash)
    return refuse(what, "'" + path + "' changed while it was read; try again once it is written",
                  error);
  std::shared_ptr<ProgramVersion> cur = exec_.current();
  if (!allowShrink && cur && cur->prog) {
    std::string lost = lostParts(*cur->prog, *next->prog);
    if (!lost.empty())
      return refuse(
          what, lost + " (monitor load --allow-shrink takes it anyway; a file watch never does)",
          error);
  }
  double compileMs =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  next->requestedNs = requestedNs;
  next->settleNs = settleNs;
  std::shared_ptr<ProgramVersion> quick = next->tier == EngineTier::JitQuick ? next : nullptr;
  if (!exec_.swap(std::move(next), std::chrono::milliseconds(5000), error)) {
    if (log_) log_("online change of " + what + " failed: " + error);
    return false;
  }
  // The touched groups run at the fast tier: build the optimized ones in the background.
  if (quick && !shutdown_.load()) optimizer_.offer(std::move(quick));
  aotBase_ = std::move(aotBase);
  program_ = path;
  so_ = so;
  if (edit) {
    // The file is written once the new version runs, so a failed change writes nothing; its new
    // mtime is taken here, under the change lock, so the file watch does not load it again.
    edit->swapped = true;
    std::string werr;
    if (edit->write && !edit->write(werr)) {
      error = "the edited program runs, but '" + path + "' could not be written: " + werr;
      if (log_) log_("online change of " + what + ": " + error);
      mtime_ = mtimeOf(path);
      return false;
    }
    mt = mtimeOf(path);
  }
  mtime_ = mt;
  soMtime_ = soMt;
  if (log_) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.1f", compileMs);
    log_("online change: " + what + (so.empty() ? " compiled" : " loaded") + " in " + buf +
         " ms and swapped in");
    for (const std::string &d : dropped) log_("online change: force dropped: " + d);
    if (!forces && !want.empty()) {
      std::string ids;
      for (const auto &[id, v] : want) ids += (ids.empty() ? "" : ", ") + std::to_string(id);
      log_("online change: forces kept on statement id(s) " + ids);
    }
  }
  return true;
}

bool Controller::rebuildRunning(const ContactForces &forces, bool traced, bool interpreted,
                                std::string &error) {
  std::shared_ptr<ProgramVersion> cur = exec_.current();
  if (!cur) {
    error = "no program is running yet";
    return false;
  }
  if (shutdown_.load()) {
    error = "the server is stopping";
    return false;
  }
  // The served .so's build is kept while forced JIT code runs (the version serve started with,
  // or the last online change's).
  if (loader_.aot() && cur->tier == EngineTier::Aot) aotBase_ = cur;
  std::shared_ptr<ProgramVersion> next;
  if (loader_.aot() && forces.empty() && !traced) {
    // Back to the served .so: the same build object as at its load, now replacing the forced
    // JIT code (variants: rebuild's rule, Executive::switchCode). Nothing else reads it.
    if (!aotBase_ || aotBase_->prog != cur->prog) {
      error = "the served .so of the running program is not at hand";
      return false;
    }
    if (aotBase_.get() == cur.get()) return true;
    aotBase_->baseVariant = cur->variant;
    next = aotBase_;
  } else {
    // (An AOT server is never traced: setTraced refuses it, so `traced` is false here.)
    const bool interp = interpreted || loader_.engine() == "interp";
    next = loader_.rebuild(*cur, forces, traced,
                           interp ? engines::EngineKind::Interp : engines::EngineKind::Jit, error);
    if (!next) return false;
    if (!cur->so.empty()) next->so = cur->so;
  }
  std::shared_ptr<ProgramVersion> quick = next->tier == EngineTier::JitQuick ? next : nullptr;
  if (!exec_.switchCode(std::move(next), std::chrono::milliseconds(5000), error)) return false;
  if (quick && !shutdown_.load()) optimizer_.offer(std::move(quick));
  return true;
}

bool Controller::setTraced(bool on, std::string &error, bool interpreterFirst) {
  if (loader_.aot() && on) {
    error = "an AOT .so is never traced; serve with --engine jit or interp for the live view";
    return false;
  }
  loader_.setTraced(on);
  BusyCount busy(busy_);
  std::lock_guard<std::mutex> g(changeMu_);
  std::shared_ptr<ProgramVersion> cur = exec_.current();
  if (!cur) return true;
  const bool jit = loader_.engine() == "jit";
  interpreterFirst = interpreterFirst && on && jit;
  // Done when the running version is traced as asked, unless it is the interim traced
  // interpreter build and the JIT one is asked for now.
  if ((cur->trace != nullptr) == on &&
      (!on || interpreterFirst || !jit || cur->tier != EngineTier::Interp))
    return true;
  if (log_)
    log_(std::string("live view: switching to the ") + (on ? "traced" : "untraced") +
         " code of version " + std::to_string(cur->id) +
         (interpreterFirst ? " on the interpreter (the traced JIT build follows)" : "") +
         " (no init, nothing cleared)");
  return rebuildRunning(cur->forces, on, interpreterFirst, error);
}

void Controller::pollProgramFile() {
  std::string path, so;
  {
    std::lock_guard<std::mutex> g(changeMu_);
    timespec now = mtimeOf(program_);
    timespec soNow = so_.empty() ? timespec{} : mtimeOf(so_);
    bool changed = now.tv_sec != 0 && !sameTime(now, mtime_);
    // Serving AOT, a rebuilt .so is a change too: edit PROGRAM (refused while the old .so no
    // longer matches it), then `ladderjit compile` swaps the new version in.
    bool soChanged = !so_.empty() && soNow.tv_sec != 0 && !sameTime(soNow, soMtime_);
    if (!changed && !soChanged) return;
    if (changed) mtime_ = now; // a broken file is reported once, not every second
    if (soChanged) soMtime_ = soNow;
    path = program_;
    so = so_;
  }
  if (log_)
    log_("'" + (so.empty() ? path : path + "' / '" + so) + "' changed on disk: online change");
  std::string error;
  change(path, std::nullopt, error, so);
}

std::string Controller::programPath(std::string *so) {
  std::lock_guard<std::mutex> g(changeMu_);
  if (so) *so = so_;
  return program_;
}

json Controller::handle(const json &req) {
  try {
    auto it = req.find("cmd");
    if (it == req.end() || !it->is_string()) return fail("request without a \"cmd\" string");
    const std::string cmd = it->get<std::string>();
    if (cmd == "read") return doRead(req);
    if (cmd == "write") return doWrite(req);
    if (cmd == "force") return doForce(req);
    if (cmd == "lock" || cmd == "unlock" || cmd == "locks") return doLock(req);
    if (cmd == "load") return doLoad(req);
    if (cmd == "trace") return trace_.handle(req, traceParser(dialect()), exec_.periodNs());
    if (cmd == "stats") {
      json j = exec_.stats().toJson();
      ChangeStats cs = changeStats();
      j["online_change_refusals"] = cs.refused;
      j["last_refusal"] = cs.lastRefusal;
      std::shared_ptr<ProgramVersion> cur = exec_.current();
      if (cur) {
        j["program"] = {{"path", cur->path}, {"version", cur->id}, {"hash", cur->hash}};
        if (!cur->so.empty()) j["program"]["so"] = cur->so;
      }
      return {{"ok", true}, {"stats", j}};
    }
    if (cmd == "stop") {
      stop_.store(true);
      return {{"ok", true}};
    }
    return fail("unknown command '" + cmd + "'");
  } catch (const std::exception &e) { // a JSON type error in a malformed request
    return fail(std::string("bad request: ") + e.what());
  } catch (...) {
    return fail("bad request");
  }
}

json Controller::doRead(const json &req) {
  std::vector<std::string> items;
  std::string err;
  if (!strings(req, "addrs", items, err)) return fail(err);
  std::vector<formats::CliAddress> addrs;
  for (const std::string &t : items) {
    std::optional<formats::CliAddress> a = address(dialect(), exec_, t, err);
    if (!a) return fail(err);
    addrs.push_back(*a);
  }
  auto s = std::make_unique<lj_state>();
  uint64_t tick = 0;
  if (!ex_.snapshot(*s, &tick)) return fail("no state published yet");
  json values = json::array(), bits = json::array();
  for (const formats::CliAddress &a : addrs) {
    values.push_back(formats::readAddress(*s, a));
    bits.push_back(formats::addressBits(a));
  }
  return {{"ok", true}, {"tick", tick}, {"values", values}, {"bits", bits}};
}

json Controller::doWrite(const json &req) {
  std::vector<std::string> items;
  std::string err;
  if (!strings(req, "writes", items, err)) return fail(err);
  std::vector<formats::Assignment> writes;
  for (const std::string &t : items) {
    std::optional<formats::Assignment> a = writable(dialect(), exec_, t, err);
    if (!a) return fail(err);
    writes.push_back(*a);
  }
  uint64_t seq = ex_.post(std::move(writes));
  if (!ex_.waitApplied(seq, std::chrono::milliseconds(5000)))
    return fail("the write was not applied within 5 s (is the scan thread running?)");
  return {{"ok", true}};
}

json Controller::doForce(const json &req) {
  const bool byId = req.contains("id");
  const char *key = byId ? "id" : "line";
  if (byId == req.contains("line") || !req[key].is_number_integer() || !req.contains("mode") ||
      !req["mode"].is_string())
    return fail("force needs \"id\" (a statement id, integer) or \"line\" (a source line, "
                "integer), and \"mode\" (on|off|restore)");
  int64_t n = req[key].get<int64_t>();
  std::string mode = req["mode"].get<std::string>();
  if (n < (byId ? 0 : 1) || n > INT32_MAX)
    return fail(std::string("force: ") + (byId ? "statement id " : "line ") + std::to_string(n) +
                " is out of range");
  if (mode != "on" && mode != "off" && mode != "restore")
    return fail("force: mode must be on, off or restore, got '" + mode + "'");
  BusyCount busy(busy_);
  std::lock_guard<std::mutex> g(changeMu_); // one force, view switch or online change at a time
  std::shared_ptr<ProgramVersion> cur = exec_.current();
  if (!cur) return fail("force: no program is running yet");
  // The LINE form is an alias: the statements on that line of the running version, by id.
  const int32_t v32 = static_cast<int32_t>(n);
  std::vector<StmtId> ids{v32};
  if (!byId) {
    ids = stmtsOnLine(*cur->prog, v32);
    if (ids.empty())
      return fail("force: " + cur->prog->file + ":" + std::to_string(v32) +
                  ": no statement on this line");
  }
  ContactForces forces = cur->forces;
  if (mode == "restore") {
    size_t erased = 0;
    for (StmtId id : ids) erased += forces.erase(id);
    if (!erased)
      return fail(std::string("force: ") + (byId ? "statement id " : "line ") +
                  std::to_string(v32) + " is not forced");
  } else {
    std::string err;
    ContactForces asked;
    for (StmtId id : ids) asked[id] = 0;
    if (!checkForces(*cur->prog, asked, err)) return fail("force: " + err);
    for (StmtId id : ids) forces[id] = mode == "on" ? 1 : 0; // 允许 = on, 禁止 = off (6.1)
  }
  // Not an online change (hnc8-core.md 6.1: 禁止/允许/恢复 mask one element of the running
  // ladder): the running program rebuilt with the new forces, switched in at the next tick
  // boundary on the same state, without init.
  std::string err;
  if (!rebuildRunning(forces, cur->trace != nullptr, false, err)) return fail("force: " + err);
  std::shared_ptr<ProgramVersion> now = exec_.current();
  if (log_) {
    // What was forced, as the program writes it: `LD X483.0 (line 10, id 57)`.
    std::string list;
    for (StmtId id : ids) {
      const Stmt *st = stmtById(*now->prog, id);
      std::string what;
      if (st && now->prog->dialect) {
        what = spelling(now->prog->dialect, st->op);
        const DialectText &d = *now->prog->dialect;
        for (uint8_t k = 0; k < st->operandCount; ++k)
          if (!d.implied || !d.implied(st->op, k)) what += " " + d.formatOperand(st->ops[k]);
        what += " (line " + std::to_string(st->loc.line) + ", id " + std::to_string(id) + ")";
      } else {
        what = "statement id " + std::to_string(id);
      }
      list += (list.empty() ? "" : ", ") + what;
    }
    log_("force: " + list + " " + (mode == "restore" ? std::string("restored") : "forced " + mode) +
         " from the next tick (no init, nothing cleared); " + std::to_string(now->forces.size()) +
         " force(s) set");
  }
  json list = json::array();
  for (const auto &[id, v] : now->forces) {
    const Stmt *st = stmtById(*now->prog, id);
    list.push_back({{"id", id}, {"line", st ? st->loc.line : 0}, {"value", v}});
  }
  return {{"ok", true}, {"forces", list}};
}

json Controller::doLock(const json &req) {
  std::string cmd = req["cmd"].get<std::string>();
  std::string err;
  if (cmd == "lock") {
    if (!req.contains("item") || !req["item"].is_string())
      return fail("lock needs \"item\" ADDR=VALUE");
    std::optional<formats::Assignment> a =
        writable(dialect(), exec_, req["item"].get<std::string>(), err);
    if (!a) return fail(err);
    ex_.lock(*a);
  } else if (cmd == "unlock") {
    if (!req.contains("addr") || !req["addr"].is_string()) return fail("unlock needs \"addr\"");
    std::optional<formats::CliAddress> a =
        address(dialect(), exec_, req["addr"].get<std::string>(), err);
    if (!a) return fail(err);
    if (!ex_.unlock(*a)) return fail("'" + a->text + "' is not locked");
  }
  json list = json::array();
  for (const formats::Assignment &a : ex_.locks()) list.push_back(formatAssignment(a));
  return {{"ok", true}, {"locks", list}};
}

json Controller::doLoad(const json &req) {
  auto str = [&](const char *key) {
    auto it = req.find(key);
    return it != req.end() && it->is_string() ? it->get<std::string>() : std::string();
  };
  if ((req.contains("program") && !req["program"].is_string()) ||
      (req.contains("so") && !req["so"].is_string()))
    return fail("load: \"program\" and \"so\" must be strings");
  std::string program = str("program"), so = str("so");
  if (loader_.aot()) {
    // An AOT server swaps in .so files; without PROGRAM the .so must match the served one.
    if (so.empty())
      return fail("load: this server runs AOT .so files; give the .so built from the program "
                  "(monitor load PROGRAM PATH.so, or load PATH.so for the served PROGRAM)");
    if (program.empty()) {
      std::lock_guard<std::mutex> g(changeMu_);
      program = program_;
    }
  } else {
    if (!so.empty())
      return fail("load: this server runs the " + loader_.engine() +
                  " engine and compiles PROGRAM itself; a .so is only served with --engine "
                  "aot:PATH.so");
    if (program.empty()) return fail("load needs \"program\"");
  }
  if (req.contains("allow_shrink") && !req["allow_shrink"].is_boolean())
    return fail("load: \"allow_shrink\" must be true or false");
  const bool allowShrink = req.value("allow_shrink", false);
  std::string err;
  // `load` reads only below the operator's --load-dir directories (realpath, so a symlink
  // cannot lead out of them); the served PROGRAM an AOT `load PATH.so` pairs with is not new.
  const std::string what = so.empty() ? "'" + program + "'" : "'" + program + "' (" + so + ")";
  std::string asked = str("program");
  for (const std::string *p : {&asked, &so})
    if (!p->empty() && !allowed(*p, err)) {
      refuse(what, err, err);
      return fail(err);
    }
  if (!change(program, std::nullopt, err, so, allowShrink)) return fail(err);
  return {{"ok", true}, {"version", exec_.current()->id}};
}

} // namespace lj::rt

// The live view of `serve --http` (runtime/LiveView.h).
#include "runtime/LiveView.h"

#include "formats/Address.h"
#include "ir/Trace.h"
#include "ladder/Layout.h"
#include "ladder/Network.h"
#include "runtime/EditGrid.h"
#include "runtime/EditSession.h"
#include "services/HttpServer.h"

#include <nlohmann/json.hpp>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdlib>
#include <cstring>
#include <map>
#include <mutex>
#include <random>
#include <thread>

namespace lj::rt {

using nlohmann::json;

namespace {

/// Stop watching for this long before the untraced build goes back in.
constexpr auto kUntraceAfter = std::chrono::seconds(10);
constexpr auto kHubPeriod = std::chrono::milliseconds(50); // 20 Hz to every page

json histJson(const Histogram &h) {
  // ~60 bars up to 1.5 x the p99.9 (at least 10 us), from the 1 us buckets.
  const int64_t hiUs = std::max<int64_t>(10, h.percentileNs(0.999) * 3 / 2 / 1000);
  const int64_t binUs = std::max<int64_t>(1, (hiUs + 59) / 60);
  json bins = json::array();
  for (int64_t b = 0; b < 60; ++b) {
    uint64_t n = 0;
    for (int64_t k = b * binUs; k < (b + 1) * binUs && k <= Histogram::kBuckets; ++k)
      n += h.bucket(static_cast<uint32_t>(k));
    bins.push_back(n);
  }
  return {{"binUs", binUs},
          {"bins", bins},
          {"p99_us", h.percentileNs(0.99) / 1000.0},
          {"max_us", h.maxNs() / 1000.0},
          {"mean_us", std::round(h.meanNs() / 100.0) / 10.0}};
}

json statsJson(const TickStats &s) {
  // `tick`: the number of the last tick run (tick numbers follow real time: ticks run + the
  // deadlines missed), the same numbering as the header's tick of the drawn state.
  const uint64_t last = s.ticks + s.missedDeadlines;
  return {{"tick", last > 0 ? last - 1 : 0},
          {"period_ns", s.periodNs},
          {"ticks", s.ticks},
          {"overruns", s.overruns},
          {"missed_deadlines", s.missedDeadlines},
          {"fault_ticks", s.faultTicks},
          {"swaps", s.swaps},
          {"scan", histJson(s.scan)},
          {"jitter", histJson(s.jitter)}};
}

const char *kindName(TraceKind k) {
  switch (k) {
  case TraceKind::Contact:
    return "contact";
  case TraceKind::Coil:
    return "coil";
  case TraceKind::Box:
    return "box";
  case TraceKind::Flow:
    return "flow";
  case TraceKind::None:
    break;
  }
  return "none";
}

/// What a box's value words are (docs/ladder-view.md "Box values"), after its EN and output
/// words: each recorded operand as the dialect spells it (null for a constant: the page does not
/// echo constants), then "elapsed ms" or "count" for a block owning a timer or counter. Empty
/// when the statement records no values.
json valueLabels(const VerifiedProgram &prog, const TraceLayout &tl, size_t i, int32_t words) {
  json labels = json::array();
  const Stmt &st = prog.stmts[i];
  for (int o = 0; o < st.operandCount && o < 8; ++o) {
    if (!(tl.operand[i] & (1u << o))) continue;
    if (st.ops[o].kind == Operand::Kind::Const)
      labels.push_back(nullptr);
    else
      labels.push_back(prog.dialect ? prog.dialect->formatOperand(st.ops[o]) : std::string("?"));
  }
  const InstrInfo &r = instrInfo(st.op);
  if (r.family == Family::Core && r.state == StateKind::Timer) labels.push_back("elapsed ms");
  if (r.family == Family::Core && r.state == StateKind::Counter) labels.push_back("count");
  // The table and this reading of it must agree; a mismatch gives no labels, not wrong ones.
  if (static_cast<int32_t>(labels.size()) != words - 2) return json::array();
  return labels;
}

/// Where each statement's operands are in memory, for a cross-reference that sees overlapping
/// addresses (docs/ladder-view.md "Cross-reference"): per statement id, one entry per register
/// or bit operand of an image area, [the operand as the dialect spells it, its byte offset in
/// lj_state, its bytes, its bit (-1: the element), 1 when the instruction writes it]. Timers,
/// counters, labels and subroutines have no image bytes and no entry.
json memOf(const VerifiedProgram &prog) {
  json mem = json::object();
  const TargetProfile &tp = *prog.profile;
  for (const Stmt &st : prog.stmts) {
    json ops = json::array();
    const InstrInfo &r = instrInfo(st.op);
    for (int o = 0; o < st.operandCount; ++o) {
      const Operand &op = st.ops[o];
      if (op.kind != Operand::Kind::Reg && op.kind != Operand::Kind::Bit) continue;
      const AreaInfo &info = tp.area(op.area);
      if (info.bytes == 0) continue;
      const int bytes = (op.kind == Operand::Kind::Reg && op.width ? op.width : info.bytes) *
                        (op.kind == Operand::Kind::Reg ? std::max<int>(r.operands[o].span, 1) : 1);
      ops.push_back({prog.dialect ? prog.dialect->formatOperand(op) : std::string("?"),
                     tp.elementOffset(op.area, op.index), bytes,
                     op.kind == Operand::Kind::Bit ? op.bit : -1, r.operands[o].writes ? 1 : 0});
    }
    if (!ops.empty()) mem[std::to_string(st.id)] = std::move(ops);
  }
  return mem;
}

} // namespace

std::string newHttpToken() {
  std::random_device rd; // the kernel's entropy (getrandom)
  static constexpr char kHex[] = "0123456789abcdef";
  std::string t;
  for (int i = 0; i < 16; ++i) {
    unsigned v = rd() & 0xFFu;
    t += kHex[v >> 4];
    t += kHex[v & 15];
  }
  return t;
}

bool httpToken(const std::string &file, std::string &token, bool &created, std::string &error) {
  created = false;
  int fd = ::open(file.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
  if (fd < 0 && errno == ENOENT) {
    // A fresh token, 0600 whatever the umask; O_EXCL: never through someone else's file.
    fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0600);
    if (fd < 0) {
      error = "'" + file + "': cannot create: " + std::strerror(errno);
      return false;
    }
    token = newHttpToken();
    const std::string text = token + "\n";
    const bool ok = ::fchmod(fd, 0600) == 0 &&
                    ::write(fd, text.data(), text.size()) == static_cast<ssize_t>(text.size());
    ::close(fd);
    if (!ok) {
      error = "'" + file + "': cannot write: " + std::strerror(errno);
      ::unlink(file.c_str());
      return false;
    }
    created = true;
    return true;
  }
  if (fd < 0) {
    error = "'" + file + "': cannot open: " + std::strerror(errno);
    return false;
  }
  struct stat st {};
  std::string why;
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode))
    why = "not a regular file";
  else if (st.st_uid != ::geteuid())
    why = "owned by uid " + std::to_string(st.st_uid) + ", not by this user (uid " +
          std::to_string(::geteuid()) + ")";
  else if ((st.st_mode & 077) != 0)
    why = "token file is accessible by group or others (chmod 600 it)";
  else if (st.st_size > 4096)
    why = "too large for a token file";
  std::string text(static_cast<size_t>(why.empty() ? st.st_size : 0), '\0');
  if (why.empty() && ::read(fd, text.data(), text.size()) != static_cast<ssize_t>(text.size()))
    why = std::string("cannot read: ") + std::strerror(errno);
  ::close(fd);
  while (!text.empty() && std::isspace(static_cast<unsigned char>(text.back()))) text.pop_back();
  if (why.empty() && (text.size() < 8 || text.find_first_of(" \t\r\n") != std::string::npos))
    why = "must hold one token of at least 8 characters on one line";
  if (!why.empty()) {
    error = "'" + file + "': " + why;
    return false;
  }
  token = text;
  return true;
}

struct LiveView::Impl {
  Executive &exec;
  Exchange &ex;
  Controller &ctl;
  std::function<void(const std::string &)> log;
  LiveViewConfig cfg;
  std::string key = newHttpToken(); // the page's key (services/HttpServer.h HttpConfig::key)
  std::unique_ptr<services::HttpServer> http;
  EditSession edits; // the ladder editor's draft (docs/ladder-edit.md)

  uint64_t publishEvery = 1; // ticks between trace copies (~40 per second)
  uint64_t lastPublished = 0;

  std::thread hub;
  std::thread tracer; // the traced JIT build after the interim traced interpreter one
  std::atomic<bool> tracerBusy{false};
  std::mutex mu;
  std::condition_variable cv;
  bool stopping = false;
  uint64_t seq = 0;
  std::string message; // the newest SSE message
  std::string latest;  // and its JSON text
  std::atomic<int> watchers{0};

  std::mutex cacheMu;
  std::string pageHash, page; // the page of the program with this hash
  uint64_t modelVariant = 0;  // the build (ProgramVersion::variant) `model` describes
  json model;

  Impl(Executive &e, Exchange &x, Controller &c, std::function<void(const std::string &)> l,
       LiveViewConfig cf)
      : exec(e), ex(x), ctl(c), log(std::move(l)), cfg(std::move(cf)), edits(e, c, log) {
    publishEvery = std::max<uint64_t>(1, 25000000 / std::max<uint64_t>(cfg.periodNs, 1));
  }

  std::string pageOf(const ProgramVersion &v) {
    std::lock_guard<std::mutex> g(cacheMu);
    if (pageHash != v.hash) {
      ladder::Layout l = ladder::layout(ladder::fromProgram(*v.prog));
      json h = v.hash;
      json k = key;
      // The editor (docs/ladder-edit.md "The page editor") only where the page may change the
      // program: under --http-read-only its script is not sent at all.
      const bool editor = !cfg.readOnly;
      // The trace panel (docs/trace.md "Page") in every page: under --http-read-only it shows
      // the trace and its captures, and its buttons are refused.
      page = ladder::renderLazyHtml(
          l,
          ladder::liveCss() + ladder::traceCss() + (editor ? ladder::editorCss() : std::string()),
          "window.LJ_HASH=" + h.dump() + ";window.LJ_KEY=" + k.dump() + ";window.LJ_RO=" +
              (cfg.readOnly ? "true" : "false") + ";" + ladder::liveScript() + ";" +
              ladder::traceScript() + (editor ? ";" + ladder::editorScript() : std::string()));
      pageHash = v.hash;
    }
    return page;
  }

  json modelOf(const ProgramVersion &v) {
    std::lock_guard<std::mutex> g(cacheMu);
    if (modelVariant != v.variant) { // a version's traced and untraced builds differ
      json stmts = json::object();
      if (v.trace) {
        TraceLayout tl = traceLayout(*v.prog);
        for (size_t i = 0; i < tl.at.size(); ++i) {
          if (tl.at[i] < 0) continue;
          int32_t end = tl.words;
          for (size_t k = i + 1; k < tl.at.size(); ++k)
            if (tl.at[k] >= 0) {
              end = tl.at[k];
              break;
            }
          json entry = {tl.at[i], kindName(tl.kind[i]), end - tl.at[i]};
          if (tl.kind[i] == TraceKind::Box && end - tl.at[i] > 2)
            entry.push_back(valueLabels(*v.prog, tl, i, end - tl.at[i]));
          stmts[std::to_string(v.prog->stmts[i].id)] = entry;
        }
      }
      model = {{"version", v.id},
               {"mem", memOf(*v.prog)},
               {"hash", v.hash},
               {"file", v.path},
               {"engine", cfg.engine},
               {"traced", v.trace != nullptr},
               {"words", v.trace ? v.trace->words() : 0},
               {"stmts", stmts}};
      modelVariant = v.variant;
    }
    return model;
  }

  void hubLoop() {
    std::vector<int32_t> words;
    auto lastWatched = std::chrono::steady_clock::now();
    bool tracedWanted = false;
    json stats;
    uint64_t round = 0;
    std::string wtext;
    // The page of the running program, drawn now (seconds for 10,000 statements on a loaded
    // machine), not when the first browser asks for it.
    if (std::shared_ptr<ProgramVersion> first = exec.current()) pageOf(*first);
    std::unique_lock<std::mutex> g(mu);
    // On a fixed 50 ms grid (the frame's own work does not stretch the period).
    auto due = std::chrono::steady_clock::now() + kHubPeriod;
    while (!cv.wait_until(g, due, [&] { return stopping; })) {
      g.unlock();
      due = std::max(due + kHubPeriod, std::chrono::steady_clock::now());
      const auto now = std::chrono::steady_clock::now();
      const bool watched = watchers.load() > 0;
      if (watched) lastWatched = now;
      // A page watches: the traced build goes in (a compile, off the scan thread); nobody for
      // kUntraceAfter: the untraced one comes back (full speed).
      if (watched != tracedWanted && (watched || now - lastWatched > kUntraceAfter)) {
        tracedWanted = watched;
        std::string err;
        if (tracer.joinable()) tracer.join(); // a traced JIT build still compiling (rare)
        // Watched: the traced interpreter build first (ready within milliseconds of the verify,
        // so the page is live at once), then the traced JIT build on its own thread, swapped
        // in when compiled; the hub goes on sending frames meanwhile.
        if (!ctl.setTraced(watched, err, watched) && log) log("live view: " + err);
        if (watched) {
          tracerBusy.store(true);
          tracer = std::thread([this] {
            std::string e;
            if (!ctl.setTraced(true, e) && log) log("live view: " + e);
            tracerBusy.store(false);
          });
        }
      }
      std::shared_ptr<ProgramVersion> cur = exec.current();
      // A traced version just swapped in (the traced JIT build after the interpreter one) and not
      // yet published: no frame this round, so pages keep drawing power flow (no frame without it).
      const bool unpublished = cur && cur->trace && cur->trace->published() == 0;
      if (cur && (watched || round % 10 == 0) && !unpublished) {
        json m{{"v", cur->id},
               {"hash", cur->hash},
               {"traced", cur->trace != nullptr},
               {"aot", !cur->so.empty()}};
        uint64_t tick = 0;
        wtext.clear();
        if (cur->trace && cur->trace->take(words, tick)) {
          // Written as text, not through json (10k statements: 15k words, 20 times a second).
          // TraceBuffer::kNotScanned goes as null: a statement whose first word is null
          // was not scanned in that tick (the page draws it so); a null value word is INT32_MIN.
          wtext = ",\"w\":[";
          char buf[16];
          for (size_t i = 0; i < words.size(); ++i) {
            if (i) wtext += ',';
            if (words[i] == TraceBuffer::kNotScanned) {
              wtext += "null";
              continue;
            }
            auto r = std::to_chars(buf, buf + sizeof buf, words[i]);
            wtext.append(buf, r.ptr);
          }
          wtext += ']';
        } else
          tick = ex.lastTick();
        m["tick"] = tick;
        json f = json::object();
        for (const auto &[id, val] : cur->forces) f[std::to_string(id)] = val;
        m["forced"] = f;
        json locks = json::array();
        for (const formats::Assignment &a : ex.locks())
          locks.push_back(a.addr.text + "=" + std::to_string(a.value));
        m["locks"] = locks;
        // Every frame while watched (the header's tick and the panel's agree), else 2 Hz.
        if (watched || round % 10 == 0) stats = statsJson(exec.stats());
        m["stats"] = stats;
        std::string data = m.dump(-1, ' ', false, json::error_handler_t::replace);
        data.insert(data.size() - 1, wtext); // before the closing brace
        std::string text = "event: state\ndata: " + data + "\n\n";
        std::lock_guard<std::mutex> lg(mu);
        message = std::move(text);
        latest = std::move(data);
        ++seq;
        cv.notify_all();
      }
      ++round;
      g.lock();
    }
  }

  bool next(uint64_t &mine, std::string &text, std::chrono::milliseconds timeout) {
    std::unique_lock<std::mutex> g(mu);
    if (!cv.wait_for(g, timeout, [&] { return stopping || seq > mine; }) || stopping) return false;
    mine = seq;
    text = message;
    return true;
  }
};

LiveView::LiveView(Executive &exec, Exchange &ex, Controller &ctl,
                   std::function<void(const std::string &)> log, LiveViewConfig cfg)
    : impl_(std::make_unique<Impl>(exec, ex, ctl, std::move(log), std::move(cfg))) {}

LiveView::~LiveView() { stop(); }

Executive::AfterTickHook LiveView::hook() {
  Impl *im = impl_.get();
  return [im](const lj_state &, uint64_t tick) {
    // Scan thread: a traced version's words of this tick into its triple buffer (no lock).
    const ProgramVersion *v = im->exec.scanVersion();
    if (!v || !v->trace) return;
    if (tick - im->lastPublished >= im->publishEvery) {
      im->lastPublished = tick;
      v->trace->publish(tick);
    }
    // The next tick is published: start it from "not scanned", so a statement it skips (a jump,
    // a PLC2 slice not run, a subroutine not called) shows as such, not with stale words.
    if (tick + 1 - im->lastPublished >= im->publishEvery) v->trace->markNotScanned();
  };
}

bool LiveView::start(std::string &error) {
  Impl *im = impl_.get();
  services::HttpBackend be;
  be.page = [im] {
    std::shared_ptr<ProgramVersion> cur = im->exec.current();
    return cur ? im->pageOf(*cur) : std::string("no program is running\n");
  };
  be.model = [im] {
    std::shared_ptr<ProgramVersion> cur = im->exec.current();
    return cur ? im->modelOf(*cur) : json{{"error", "no program is running"}};
  };
  be.state = [im] {
    std::string text;
    {
      std::lock_guard<std::mutex> g(im->mu);
      text = im->latest;
    }
    return text.empty() ? json{{"error", "no snapshot yet"}} : json::parse(text);
  };
  be.next = [im](uint64_t &seq, std::string &text, std::chrono::milliseconds t) {
    return im->next(seq, text, t);
  };
  be.watchers = [im](int d) { im->watchers.fetch_add(d); };
  be.command = [im](const json &r) { return im->ctl.handle(r); };
  be.edit = [im](const std::string &action, const json &body, const std::string &client) {
    // The page editor's grids (runtime/EditGrid.h) read the running version only.
    EditAnswer a = action == "grid" ? editGrid(im->exec.current().get(), body)
                   : action.empty() ? im->edits.status()
                                    : im->edits.post(action, body, client);
    return std::make_pair(a.status, std::move(a.body));
  };
  services::HttpConfig hc;
  hc.host = im->cfg.host;
  hc.port = im->cfg.port;
  hc.token = im->cfg.token;
  hc.key = im->key;
  hc.hosts = im->cfg.hosts;
  hc.tokenFile = im->cfg.tokenFile;
  hc.readOnly = im->cfg.readOnly;
  // Debian's libjs-dygraphs for the trace panel; elsewhere (or to test its absence) another
  // folder holding dygraph.min.js and dygraph.min.css.
  if (const char *d = std::getenv("LADDERJIT_DYGRAPHS_DIR"); d && *d) hc.dygraphsDir = d;
  hc.log = im->log;
  im->http = std::make_unique<services::HttpServer>(hc, std::move(be));
  if (!im->http->start(error)) return false;
  im->hub = std::thread([im] { im->hubLoop(); });
  return true;
}

bool LiveView::stop() {
  if (!impl_) return false;
  {
    std::lock_guard<std::mutex> g(impl_->mu);
    impl_->stopping = true;
  }
  impl_->cv.notify_all();
  if (impl_->http) impl_->http->stop();
  if (impl_->hub.joinable()) impl_->hub.join();
  if (!impl_->tracer.joinable()) return false;
  if (impl_->tracerBusy.load()) { // a JIT compile LLVM cannot interrupt: ends with the process
    impl_->tracer.detach();
    return true;
  }
  impl_->tracer.join();
  return false;
}

int LiveView::port() const { return impl_->http ? impl_->http->port() : -1; }

} // namespace lj::rt

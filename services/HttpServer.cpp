// libmicrohttpd behind HttpServer.h (docs/security.md "The live view's HTTP port"): one event
// loop thread (epoll) reads every connection within fixed bounds; the checks of a request (Host,
// Origin, token) run when its headers are complete and before any body byte is kept; SSE streams
// are suspended while they have nothing to send and resumed by the pump thread; whatever may
// block (the page, the model, control requests) runs on the worker thread, the connection
// suspended meanwhile, so the loop never waits for the scan, a compile or a slow client.
#include "services/HttpServer.h"

#include <microhttpd.h>

#include <arpa/inet.h>
#include <fcntl.h>
#include <netdb.h>
#include <netinet/in.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <condition_variable>
#include <cstring>
#include <deque>
#include <map>
#include <mutex>
#include <set>

namespace lj::services {

using nlohmann::json;
using Clock = std::chrono::steady_clock;

std::string clientText(const std::string &s, size_t max) {
  static constexpr char kHex[] = "0123456789abcdef";
  std::string out;
  const size_t n = std::min(s.size(), max);
  for (size_t i = 0; i < n; ++i) {
    const auto b = static_cast<unsigned char>(s[i]);
    if (b < 0x20 || b >= 0x7f || b == '\\') {
      out += "\\x";
      out += kHex[b >> 4];
      out += kHex[b & 15];
    } else {
      out += static_cast<char>(b);
    }
  }
  if (s.size() > max) out += "...";
  return out;
}

namespace {

/// One TCP connection (MHD's socket context): the watchdog closes it when the request it is
/// reading is not complete `requestSeconds` after it began.
struct Conn {
  int fd = -1;
  std::string client; // "ADDR:PORT"
  std::string ip;
  Clock::time_point start = Clock::now();
  bool reading = true; // a request's headers or body are being read
  bool shut = false;
};

/// One request (MHD's con_cls).
struct Request {
  std::string method, path, client, origin;
  std::string cmd; // POST: the control command
  std::vector<std::string> keys;
  std::string edit;     // POST /api/edit/ACTION: the action
  bool bigBody = false; // holds Impl::draftReading (a draft's body is being read)
  size_t maxBody = 0;
  std::string body;
  bool answered = false; // a response is queued (refusals, 413)
  bool deferred = false; // on the worker
};

/// One SSE stream: the message it sends, where it is in it, and whether it sleeps.
struct Stream {
  MHD_Connection *c = nullptr;
  struct HttpServer::Impl *im = nullptr;
  std::string ip;
  uint64_t seq = 0, ping = 0;
  std::string pending;
  size_t off = 0;
  bool suspended = false;
};

/// Blocking work for the worker thread.
struct Job {
  enum Kind { Page, Model, Locks, Command, Edit, Asset } kind = Page;
  MHD_Connection *c = nullptr;
  json req;
  std::string line;        // for the log: "POST /api/force {..} from ADDR"
  std::string action = {}; // Edit: "" for GET /api/edit, else the POST's action
  std::string client = {}; // Edit: the client, "ADDR:PORT"; Asset: the file's name
};

struct Reply {
  unsigned status = 200;
  std::string body;
  std::string type = "application/json";
  std::vector<std::pair<std::string, std::string>> headers;
  bool close = false;
};

constexpr size_t kMaxJobs = 16;
constexpr int kSummarySeconds = 10;

bool sameToken(const std::string &a, const std::string &b) {
  if (a.size() != b.size() || b.empty()) return false;
  unsigned char d = 0;
  for (size_t i = 0; i < a.size(); ++i) d |= static_cast<unsigned char>(a[i] ^ b[i]);
  return d == 0;
}

std::string lower(std::string s) {
  for (char &c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::string jsonText(const json &j) {
  return j.dump(-1, ' ', false, json::error_handler_t::replace) + "\n";
}

Reply error(unsigned status, const std::string &why, bool close = false) {
  Reply r;
  r.status = status;
  r.body = jsonText({{"ok", false}, {"error", why}});
  r.close = close;
  return r;
}

/// The whole of a regular file of at most `max` bytes; false when it is missing or other.
bool readSmallFile(const std::string &path, size_t max, std::string &out) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return false;
  struct stat st {};
  bool ok = ::fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && static_cast<size_t>(st.st_size) <= max;
  if (ok) {
    out.resize(static_cast<size_t>(st.st_size));
    size_t got = 0;
    while (got < out.size()) {
      const ssize_t n = ::read(fd, out.data() + got, out.size() - got);
      if (n <= 0) break;
      got += static_cast<size_t>(n);
    }
    ok = got == out.size();
  }
  ::close(fd);
  return ok;
}

void addrOf(const sockaddr *sa, std::string &ip, std::string &client) {
  char buf[INET6_ADDRSTRLEN] = "?";
  int port = 0;
  if (sa && sa->sa_family == AF_INET) {
    auto *in = reinterpret_cast<const sockaddr_in *>(sa);
    inet_ntop(AF_INET, &in->sin_addr, buf, sizeof buf);
    port = ntohs(in->sin_port);
    ip = buf;
    client = ip + ":" + std::to_string(port);
  } else if (sa && sa->sa_family == AF_INET6) {
    auto *in = reinterpret_cast<const sockaddr_in6 *>(sa);
    inet_ntop(AF_INET6, &in->sin6_addr, buf, sizeof buf);
    port = ntohs(in->sin6_port);
    ip = buf;
    client = "[" + ip + "]:" + std::to_string(port);
  } else {
    ip = client = "?";
  }
}

} // namespace

struct HttpServer::Impl {
  HttpConfig cfg;
  HttpBackend be;
  MHD_Daemon *daemon = nullptr;
  int port = -1;
  std::string cookieName;
  std::vector<std::string> hostNames; // accepted Host values (lower case)
  std::atomic<bool> stopping{false};
  /// A draft body (up to maxEditBody) is being read: one at a time, so many connections cannot
  /// make the server hold many large bodies.
  std::atomic<bool> draftReading{false};

  std::mutex connMu;
  std::set<Conn *> conns;

  std::mutex streamMu;
  std::set<Stream *> streams;
  std::map<std::string, int> streamsOf; // per client address
  std::string msg;
  uint64_t msgSeq = 0, pingGen = 0;

  std::mutex jobMu;
  std::condition_variable jobCv;
  std::deque<Job> jobs;

  std::mutex refMu;
  std::condition_variable refCv; // the watchdog's sleep (stop wakes it)
  std::map<std::string, uint64_t> refused;
  uint64_t refusedTotal = 0;
  Clock::time_point refStart;
  bool refOpen = false;

  std::thread pump, worker, watchdog;

  void log(const std::string &m) const {
    if (cfg.log) cfg.log("http: " + m);
  }

  // ---- refusals: the first of a 10 s window in full, the others counted and summarised ----
  void refusal(const std::string &reason, const std::string &line) {
    std::lock_guard<std::mutex> g(refMu);
    const auto now = Clock::now();
    if (refOpen && now - refStart < std::chrono::seconds(kSummarySeconds)) {
      ++refused[reason];
      ++refusedTotal;
      return;
    }
    flushRefusals(now);
    refOpen = true;
    refStart = now;
    log(line);
  }
  /// Under refMu: the summary of the window that ended.
  void flushRefusals(Clock::time_point now) {
    if (!refOpen || now - refStart < std::chrono::seconds(kSummarySeconds)) return;
    refOpen = false;
    if (refusedTotal == 0) return;
    std::string s = "refused " + std::to_string(refusedTotal) + " more request(s) in the last " +
                    std::to_string(kSummarySeconds) + " s:";
    bool first = true;
    for (const auto &[why, n] : refused) {
      s += (first ? " " : ", ") + std::to_string(n) + " " + why;
      first = false;
    }
    log(s);
    refused.clear();
    refusedTotal = 0;
  }

  // ---- checks -----------------------------------------------------------------------------
  bool hostAllowed(const std::string &h) const {
    const std::string l = lower(h);
    return std::find(hostNames.begin(), hostNames.end(), l) != hostNames.end();
  }
  void buildHostNames() {
    std::vector<std::string> names = {"127.0.0.1", "localhost", "[::1]"};
    std::string bound = cfg.host;
    if (bound.find(':') != std::string::npos && bound.front() != '[') bound = "[" + bound + "]";
    if (bound != "0.0.0.0" && bound != "[::]" && !bound.empty()) names.push_back(bound);
    const std::string p = std::to_string(port);
    for (const std::string &n : cfg.hosts) {
      // NAME:PORT as given; NAME alone means NAME on this port ([V6] or [V6]:PORT for IPv6).
      const size_t colon = n.rfind(':');
      const bool hasPort = colon != std::string::npos &&
                           (n.front() == '[' ? colon > n.find(']') : n.find(':') == colon);
      if (hasPort)
        hostNames.push_back(lower(n));
      else
        names.push_back(n);
    }
    for (const std::string &n : names) {
      hostNames.push_back(lower(n) + ":" + p);
      if (port == 80) hostNames.push_back(lower(n));
    }
  }

  static const char *header(MHD_Connection *c, const char *name) {
    return MHD_lookup_connection_value(c, MHD_HEADER_KIND, name);
  }

  /// The token of the request: 0 none, 1 right, -1 wrong. `viaCookie`: it came as the page's
  /// cookie (which also needs the page's key).
  int credential(MHD_Connection *c, bool api) const {
    std::string given;
    if (const char *a = header(c, "Authorization")) {
      std::string auth = a;
      if (auth.rfind("Bearer ", 0) == 0) given = auth.substr(7);
    }
    if (given.empty())
      if (const char *t = header(c, "X-Ladderjit-Token")) given = t;
    if (!given.empty()) return sameToken(given, cfg.token) ? 1 : -1;
    const char *ck = MHD_lookup_connection_value(c, MHD_COOKIE_KIND, cookieName.c_str());
    if (!ck) return 0;
    if (!sameToken(ck, cfg.token)) return -1;
    if (!api) return 1;
    const char *k = header(c, "X-Ladderjit-Key");
    if (!k) k = MHD_lookup_connection_value(c, MHD_GET_ARGUMENT_KIND, "k");
    return k && sameToken(k, cfg.key) ? 1 : -1;
  }

  // ---- answers ----------------------------------------------------------------------------
  MHD_Result queue(MHD_Connection *c, Reply r) {
    auto *s = new std::string(std::move(r.body));
    MHD_Response *res = MHD_create_response_from_buffer_with_free_callback_cls(
        s->size(), s->data(), [](void *p) { delete static_cast<std::string *>(p); }, s);
    if (!res) {
      delete s;
      return MHD_NO;
    }
    decorate(res, r.type);
    for (const auto &[k, v] : r.headers) MHD_add_response_header(res, k.c_str(), v.c_str());
    if (r.close) MHD_add_response_header(res, MHD_HTTP_HEADER_CONNECTION, "close");
    MHD_Result ok = MHD_queue_response(c, r.status, res);
    MHD_destroy_response(res);
    return ok;
  }
  static void decorate(MHD_Response *res, const std::string &type) {
    MHD_add_response_header(res, MHD_HTTP_HEADER_CONTENT_TYPE, type.c_str());
    MHD_add_response_header(res, MHD_HTTP_HEADER_CACHE_CONTROL, "no-store");
    MHD_add_response_header(res, "X-Content-Type-Options", "nosniff");
    MHD_add_response_header(res, "X-Frame-Options", "DENY");
    MHD_add_response_header(res, "Referrer-Policy", "no-referrer");
    MHD_add_response_header(res, "Content-Security-Policy",
                            "default-src 'self'; script-src 'self' 'unsafe-inline'; style-src "
                            "'self' 'unsafe-inline'; img-src 'self' data:; connect-src 'self'; "
                            "frame-ancestors 'none'; base-uri 'none'; form-action 'none'");
  }

  /// A refused request: logged (cut, escaped, summarised), answered, and its connection closed.
  MHD_Result refuse(MHD_Connection *c, Request &rq, unsigned status, const std::string &reason,
                    const std::string &why) {
    refusal(reason, "refused " + clientText(rq.method, 10) + " " + clientText(rq.path) + " from " +
                        rq.client + " (Origin: " +
                        (rq.origin.empty() ? "none" : clientText(rq.origin)) + "): " + why);
    rq.answered = true;
    responding(c);
    return queue(c, error(status, why, true));
  }

  static Conn *connOf(MHD_Connection *c) {
    const MHD_ConnectionInfo *i = MHD_get_connection_info(c, MHD_CONNECTION_INFO_SOCKET_CONTEXT);
    return i ? static_cast<Conn *>(i->socket_context) : nullptr;
  }
  /// The request is read: the watchdog's deadline no longer applies.
  void responding(MHD_Connection *c) {
    if (Conn *cn = connOf(c)) {
      std::lock_guard<std::mutex> g(connMu);
      cn->reading = false;
    }
  }

  // ---- the request handler ----------------------------------------------------------------
  MHD_Result begin(MHD_Connection *c, const char *url, const char *method, Request &rq) {
    rq.method = method;
    rq.path = url;
    if (Conn *cn = connOf(c)) rq.client = cn->client;
    const char *host = header(c, "Host");
    const char *origin = header(c, "Origin");
    if (origin) rq.origin = origin;
    if (!host || !hostAllowed(host))
      return refuse(c, rq, MHD_HTTP_MISDIRECTED_REQUEST, "foreign Host",
                    std::string("Host '") + (host ? clientText(host) : "none") +
                        "' is not this server's address (serve --http-host NAME allows a name)");
    if (origin && lower(origin) != "http://" + lower(host))
      return refuse(c, rq, MHD_HTTP_FORBIDDEN, "foreign Origin",
                    "cross-origin request refused (its Origin is not this server)");
    const std::string m = rq.method;
    const bool get = m == "GET" || m == "HEAD";
    const std::string &p = rq.path;
    if (p == "/") {
      if (!get) return refuse(c, rq, MHD_HTTP_METHOD_NOT_ALLOWED, "bad method", "/ takes GET");
      if (const char *t = MHD_lookup_connection_value(c, MHD_GET_ARGUMENT_KIND, "token")) {
        if (!sameToken(t, cfg.token))
          return refuse(c, rq, MHD_HTTP_FORBIDDEN, "wrong token", "wrong token");
        // The token into an HttpOnly cookie of this port, and out of the address bar.
        Reply r;
        r.status = MHD_HTTP_SEE_OTHER;
        r.type = "text/plain; charset=utf-8";
        r.body = "the token is stored; go to /\n";
        r.headers = {
            {"Location", "/"},
            {"Set-Cookie", cookieName + "=" + cfg.token + "; Path=/; HttpOnly; SameSite=Strict"}};
        rq.answered = true;
        responding(c);
        return queue(c, std::move(r));
      }
      const int cred = credential(c, false);
      if (cred == 0) {
        refusal("missing token", "refused GET / from " + rq.client + ": missing token");
        Reply r;
        r.status = MHD_HTTP_UNAUTHORIZED;
        r.type = "text/html; charset=utf-8";
        r.body =
            "<!DOCTYPE html><html><head><meta charset=\"utf-8\"><title>ladderjit live view</title>"
            "</head><body><p>The live view needs its token: open this address with "
            "<code>?token=TOKEN</code> once (serve wrote the token to " +
            (cfg.tokenFile.empty() ? std::string("its --http-token-file")
                                   : "<code>" + htmlEsc(cfg.tokenFile) + "</code>") +
            ").</p></body></html>\n";
        r.close = true;
        rq.answered = true;
        responding(c);
        return queue(c, std::move(r));
      }
      if (cred < 0) return refuse(c, rq, MHD_HTTP_FORBIDDEN, "wrong token", "wrong token");
      return defer(c, rq, Job{Job::Page, c, {}, {}});
    }
    if (p == "/dygraph.min.js" || p == "/dygraph.min.css") {
      // The trace panel's charting library (Debian's libjs-dygraphs), read at each request.
      if (!get) return refuse(c, rq, MHD_HTTP_METHOD_NOT_ALLOWED, "bad method", p + " takes GET");
      const int cred = credential(c, false);
      if (cred == 0)
        return refuse(c, rq, MHD_HTTP_UNAUTHORIZED, "missing token",
                      "missing token: open the page with ?token=TOKEN first");
      if (cred < 0) return refuse(c, rq, MHD_HTTP_FORBIDDEN, "wrong token", "wrong token");
      return defer(c, rq, Job{Job::Asset, c, {}, {}, "", p.substr(1)});
    }
    static const std::set<std::string> kApi = {
        "/api/model",      "/api/state",      "/api/locks",       "/api/events",
        "/api/force",      "/api/lock",       "/api/unlock",      "/api/edit",
        "/api/edit/draft", "/api/edit/check", "/api/edit/update", "/api/edit/discard",
        "/api/edit/grid",  "/api/trace",      "/api/read",        "/api/write"};
    const bool edit = p.rfind("/api/edit", 0) == 0;
    if (!kApi.count(p) || (edit && !be.edit)) {
      rq.answered = true;
      responding(c);
      return queue(c, error(MHD_HTTP_NOT_FOUND, "no such page: " + clientText(p), true));
    }
    const int cred = credential(c, true);
    if (cred == 0)
      return refuse(c, rq, MHD_HTTP_UNAUTHORIZED, "missing token",
                    "missing token: send 'Authorization: Bearer TOKEN' (the token is in the file "
                    "serve named at start), or open the page with ?token=TOKEN");
    if (cred < 0) return refuse(c, rq, MHD_HTTP_FORBIDDEN, "wrong token", "wrong token");
    // GET /api/trace reads the trace's status and last capture; POST /api/trace drives it.
    const bool post = p == "/api/force" || p == "/api/lock" || p == "/api/unlock" ||
                      p == "/api/write" || (edit && p != "/api/edit") ||
                      (p == "/api/trace" && !get);
    // A whole program's network JSON is larger than a command.
    rq.maxBody = p == "/api/edit/draft" ? cfg.maxEditBody : cfg.maxBody;
    if (post) {
      if (m != "POST") {
        rq.answered = true;
        responding(c);
        return queue(c, error(MHD_HTTP_METHOD_NOT_ALLOWED, p + " takes POST with a JSON body"));
      }
      if (cfg.readOnly)
        return refuse(c, rq, MHD_HTTP_FORBIDDEN, "read-only",
                      "this server is read-only (serve --http-read-only): nothing can be changed "
                      "from here");
      if (const char *cl = header(c, "Content-Length")) {
        char *end = nullptr;
        const unsigned long long n = std::strtoull(cl, &end, 10);
        if (n > rq.maxBody)
          return refuse(c, rq, MHD_HTTP_CONTENT_TOO_LARGE, "body too large",
                        "the body is larger than " + std::to_string(rq.maxBody) + " bytes");
      }
      if (p == "/api/edit/draft") {
        if (draftReading.exchange(true))
          return refuse(c, rq, MHD_HTTP_SERVICE_UNAVAILABLE, "busy",
                        "another draft is being received; retry");
        rq.bigBody = true;
      }
      if (edit) {
        rq.cmd = "edit";
        rq.edit = p.substr(std::strlen("/api/edit/"));
      } else if (p == "/api/force") {
        rq.cmd = "force";
        rq.keys = {"id", "line", "mode"};
      } else if (p == "/api/lock") {
        rq.cmd = "lock";
        rq.keys = {"item"};
      } else if (p == "/api/write") { // the watch table's write: monitor write's command
        rq.cmd = "write";
        rq.keys = {"writes"};
      } else if (p == "/api/trace") {
        rq.cmd = "trace";
        rq.keys = {"action", "text", "file"};
      } else {
        rq.cmd = "unlock";
        rq.keys = {"addr"};
      }
      return MHD_YES; // the body follows
    }
    if (!get) {
      rq.answered = true;
      responding(c);
      return queue(c, error(MHD_HTTP_METHOD_NOT_ALLOWED, p + " takes GET", true));
    }
    if (p == "/api/state") {
      rq.answered = true;
      responding(c);
      Reply r;
      r.body = jsonText(be.state());
      return queue(c, std::move(r));
    }
    if (p == "/api/model") return defer(c, rq, Job{Job::Model, c, {}, {}});
    if (p == "/api/edit") return defer(c, rq, Job{Job::Edit, c, {}, {}, "", rq.client});
    if (p == "/api/locks") return defer(c, rq, Job{Job::Locks, c, {{"cmd", "locks"}}, {}});
    if (p == "/api/read") {
      // ?a=ADDR,ADDR...: the watch table's values, as monitor read (addresses or symbols in
      // the program's dialect), at most 64 of them.
      const char *a = MHD_lookup_connection_value(c, MHD_GET_ARGUMENT_KIND, "a");
      json addrs = json::array();
      for (std::string_view rest = a ? a : ""; !rest.empty();) {
        const size_t comma = rest.find(',');
        std::string_view item = rest.substr(0, comma);
        if (!item.empty()) addrs.push_back(std::string(item));
        rest = comma == std::string_view::npos ? std::string_view() : rest.substr(comma + 1);
      }
      if (addrs.empty() || addrs.size() > 64) {
        rq.answered = true;
        responding(c);
        return queue(c, error(400, "GET /api/read?a=ADDR,ADDR... takes 1 to 64 addresses or "
                                   "symbols, got " +
                                       std::to_string(addrs.size())));
      }
      return defer(c, rq, Job{Job::Locks, c, {{"cmd", "read"}, {"addrs", std::move(addrs)}}, {}});
    }
    if (p == "/api/trace") {
      // ?have=ID: the id of the capture the page holds; the rows are sent only when newer.
      json q{{"cmd", "trace"}, {"action", "capture"}};
      // ?save=vcd|csv (&bits=1): the last capture as a file to download, as monitor trace save.
      if (const char *sv = MHD_lookup_connection_value(c, MHD_GET_ARGUMENT_KIND, "save")) {
        const std::string f = sv;
        if (f != "vcd" && f != "csv") {
          rq.answered = true;
          responding(c);
          return queue(c, error(400, "save must be vcd or csv, got '" + clientText(f) + "'"));
        }
        const char *bits = MHD_lookup_connection_value(c, MHD_GET_ARGUMENT_KIND, "bits");
        q = {{"cmd", "trace"},
             {"action", "save"},
             {"format", f},
             {"bits", bits && std::string(bits) == "1"}};
        return defer(c, rq, Job{Job::Locks, c, std::move(q), {}});
      }
      if (const char *hv = MHD_lookup_connection_value(c, MHD_GET_ARGUMENT_KIND, "have")) {
        char *end = nullptr;
        errno = 0;
        const unsigned long long id = std::strtoull(hv, &end, 10);
        if (!*hv || *end || errno || hv[0] == '-') {
          rq.answered = true;
          responding(c);
          return queue(c, error(400, "have must be a capture id (a decimal number), got '" +
                                         clientText(hv) + "'"));
        }
        q["have"] = static_cast<uint64_t>(id);
      }
      return defer(c, rq, Job{Job::Locks, c, std::move(q), {}});
    }
    return openStream(c, rq);
  }

  static std::string htmlEsc(const std::string &s) {
    std::string o;
    for (char ch : clientText(s, 400)) {
      if (ch == '<')
        o += "&lt;";
      else if (ch == '>')
        o += "&gt;";
      else if (ch == '&')
        o += "&amp;";
      else
        o += ch;
    }
    return o;
  }

  MHD_Result body(MHD_Connection *c, Request &rq, const char *data, size_t *size) {
    if (rq.answered || rq.deferred) { // the rest of a refused body is dropped
      *size = 0;
      return MHD_YES;
    }
    if (rq.body.size() + *size > rq.maxBody) {
      *size = 0;
      return refuse(c, rq, MHD_HTTP_CONTENT_TOO_LARGE, "body too large",
                    "the body is larger than " + std::to_string(rq.maxBody) + " bytes");
    }
    rq.body.append(data, *size);
    *size = 0;
    return MHD_YES;
  }

  MHD_Result finish(MHD_Connection *c, Request &rq) {
    if (rq.answered || rq.deferred) return MHD_YES;
    json b = json::parse(rq.body, nullptr, false);
    if (b.is_discarded() || !b.is_object()) {
      rq.answered = true;
      responding(c);
      return queue(c,
                   error(400, "the body must be a JSON object, e.g. {\"id\":12,\"mode\":\"on\"}"));
    }
    if (!rq.edit.empty()) // the edit session checks its own fields; the log names the size
      return defer(c, rq,
                   Job{Job::Edit, c, std::move(b),
                       rq.method + " " + rq.path + " (" + std::to_string(rq.body.size()) +
                           " bytes) from " + rq.client,
                       rq.edit, rq.client});
    if (rq.cmd == "trace") {
      // The page drives the trace; GET /api/trace reads it (status, capture).
      static const std::set<std::string> kTrace = {"define", "arm", "trigger", "stop"};
      const auto a = b.find("action");
      if (a == b.end() || !a->is_string() || !kTrace.count(a->get<std::string>())) {
        rq.answered = true;
        responding(c);
        return queue(c, error(400, "POST /api/trace needs \"action\": define (with \"text\"), "
                                   "arm, trigger or stop; GET /api/trace reads the status"));
      }
    }
    json r{{"cmd", rq.cmd}};
    for (const auto &[k, v] : b.items()) {
      if (std::find(rq.keys.begin(), rq.keys.end(), k) == rq.keys.end()) {
        rq.answered = true;
        responding(c);
        return queue(c, error(400, "unknown field '" + clientText(k) + "' in " + rq.path));
      }
      r[k] = v;
    }
    return defer(c, rq,
                 Job{Job::Command, c, r,
                     rq.method + " " + rq.path + " " +
                         clientText(b.dump(-1, ' ', false, json::error_handler_t::replace), 120) +
                         " from " + rq.client});
  }

  /// To the worker thread, the connection suspended until it has answered.
  MHD_Result defer(MHD_Connection *c, Request &rq, Job j) {
    responding(c);
    {
      std::lock_guard<std::mutex> g(jobMu);
      if (!stopping.load() && jobs.size() < kMaxJobs) {
        rq.deferred = true;
        MHD_suspend_connection(c);
        jobs.push_back(std::move(j));
        jobCv.notify_one();
        return MHD_YES;
      }
    }
    rq.answered = true;
    return queue(
        c, error(MHD_HTTP_SERVICE_UNAVAILABLE, "busy: too many requests at once; retry", true));
  }

  void workerLoop() {
    for (;;) {
      Job j;
      {
        std::unique_lock<std::mutex> g(jobMu);
        jobCv.wait(g, [&] { return !jobs.empty() || stopping.load(); });
        if (jobs.empty()) return;
        j = std::move(jobs.front());
        jobs.pop_front();
      }
      Reply r;
      if (stopping.load()) {
        r = error(MHD_HTTP_SERVICE_UNAVAILABLE, "the server is stopping", true);
      } else {
        try {
          switch (j.kind) {
          case Job::Page:
            r.type = "text/html; charset=utf-8";
            r.body = be.page();
            break;
          case Job::Model:
            r.body = jsonText(be.model());
            break;
          case Job::Locks: {
            json ans = be.command(j.req);
            const std::string cmd = j.req.value("cmd", std::string());
            if (cmd == "trace") ans["read_only"] = cfg.readOnly; // what the panel may do
            if ((cmd == "trace" || cmd == "read") && !ans.value("ok", false)) r.status = 400;
            r.body = jsonText(ans);
            if (j.req.value("action", std::string()) == "save" && ans.value("ok", false)) {
              // a download: the file's text itself, named after the capture
              const std::string f = j.req.value("format", std::string("vcd"));
              r.body = ans.value("data", std::string());
              r.type = f == "vcd" ? "text/plain; charset=utf-8" : "text/csv; charset=utf-8";
              r.headers.push_back(
                  {"Content-Disposition", "attachment; filename=\"capture-" +
                                              std::to_string(ans.value("capture", uint64_t{0})) +
                                              "." + f + "\""});
            }
            break;
          }
          case Job::Asset: {
            // A regular file of at most 4 MiB (dygraph.min.js is about 120 KiB).
            const std::string path = cfg.dygraphsDir + "/" + j.client;
            std::string text;
            if (!readSmallFile(path, size_t{4} << 20, text)) {
              r.status = MHD_HTTP_NOT_FOUND;
              r.type = "text/plain; charset=utf-8";
              r.body = "dygraphs is not installed: cannot read " + path +
                       " (Debian package libjs-dygraphs; scripts/setup.sh installs it). The "
                       "trace panel needs it to plot.\n";
              break;
            }
            r.type = j.client.size() > 3 && j.client.substr(j.client.size() - 3) == ".js"
                         ? "text/javascript; charset=utf-8"
                         : "text/css; charset=utf-8";
            r.body = std::move(text);
            break;
          }
          case Job::Edit: {
            auto [status, ans] = be.edit(j.action, j.req, j.client);
            if (!j.action.empty())
              log(j.line + ": " + std::to_string(status) + " " +
                  (ans.value("ok", false)
                       ? std::string("ok")
                       : "refused: " + clientText(ans.value("error", std::string("?")), 200)));
            r.status = status;
            r.body = jsonText(ans);
            break;
          }
          case Job::Command: {
            json ans = be.command(j.req);
            const bool ok = ans.value("ok", false);
            log(j.line + ": " +
                (ok ? std::string("ok")
                    : "refused: " + clientText(ans.value("error", std::string("?")), 200)));
            r.status = ok ? 200 : 400;
            r.body = jsonText(ans);
            break;
          }
          }
        } catch (const std::exception &e) {
          log(std::string("internal error: ") + e.what());
          r = error(500, std::string("internal error: ") + e.what());
        }
      }
      queue(j.c, std::move(r));
      MHD_resume_connection(j.c);
    }
  }

  // ---- SSE --------------------------------------------------------------------------------
  MHD_Result openStream(MHD_Connection *c, Request &rq) {
    Conn *cn = connOf(c);
    const std::string ip = cn ? cn->ip : "?";
    auto *s = new Stream;
    {
      std::lock_guard<std::mutex> g(streamMu);
      std::string why;
      if (static_cast<int>(streams.size()) >= cfg.maxStreams)
        why = "too many live pages (" + std::to_string(cfg.maxStreams) + "); close one";
      else if (streamsOf[ip] >= cfg.maxStreamsPerClient)
        why = "too many live pages from " + ip + " (" + std::to_string(cfg.maxStreamsPerClient) +
              "); close one";
      if (!why.empty()) {
        delete s;
        if (streamsOf[ip] == 0) streamsOf.erase(ip);
        return refuse(c, rq, MHD_HTTP_SERVICE_UNAVAILABLE, "too many streams", why);
      }
      s->c = c;
      s->im = this;
      s->ip = ip;
      s->ping = pingGen;
      streams.insert(s);
      ++streamsOf[ip];
    }
    be.watchers(+1);
    MHD_Response *res =
        MHD_create_response_from_callback(MHD_SIZE_UNKNOWN, 16 * 1024, &onStream, s, &onStreamEnd);
    decorate(res, "text/event-stream");
    rq.answered = true;
    responding(c);
    MHD_Result ok = MHD_queue_response(c, MHD_HTTP_OK, res);
    MHD_destroy_response(res);
    return ok;
  }

  static ssize_t onStream(void *cls, uint64_t, char *buf, size_t max) {
    Stream &s = *static_cast<Stream *>(cls);
    Impl &im = *s.im;
    std::lock_guard<std::mutex> g(im.streamMu);
    if (im.stopping.load()) return MHD_CONTENT_READER_END_OF_STREAM;
    if (s.off >= s.pending.size()) {
      s.pending.clear();
      s.off = 0;
      if (s.seq < im.msgSeq) {
        s.pending = im.msg;
        s.seq = im.msgSeq;
        s.ping = im.pingGen;
      } else if (s.ping < im.pingGen) {
        s.pending = ": ping\n\n";
        s.ping = im.pingGen;
      } else {
        // Nothing to send: asleep until the pump has a message or a ping (no busy loop, no
        // thread held).
        s.suspended = true;
        MHD_suspend_connection(s.c);
        return 0;
      }
    }
    const size_t n = std::min(max, s.pending.size() - s.off);
    std::memcpy(buf, s.pending.data() + s.off, n);
    s.off += n;
    return static_cast<ssize_t>(n);
  }

  static void onStreamEnd(void *cls) {
    auto *s = static_cast<Stream *>(cls);
    Impl &im = *s->im;
    {
      std::lock_guard<std::mutex> g(im.streamMu);
      im.streams.erase(s);
      if (--im.streamsOf[s->ip] <= 0) im.streamsOf.erase(s->ip);
    }
    im.be.watchers(-1);
    delete s;
  }

  /// Wake the sleeping streams (under no lock of MHD's).
  void wakeStreams() {
    std::vector<MHD_Connection *> wake;
    {
      std::lock_guard<std::mutex> g(streamMu);
      for (Stream *s : streams)
        if (s->suspended) {
          s->suspended = false;
          wake.push_back(s->c);
        }
    }
    for (MHD_Connection *c : wake) MHD_resume_connection(c);
  }

  void pumpLoop() {
    uint64_t seq = 0;
    while (!stopping.load()) {
      std::string text;
      const bool got = be.next(seq, text, std::chrono::milliseconds(1000));
      {
        std::lock_guard<std::mutex> g(streamMu);
        if (got) {
          msg = std::move(text);
          msgSeq = seq;
        } else {
          ++pingGen; // a second without a message: a comment line keeps the stream alive
        }
      }
      wakeStreams();
    }
  }

  // ---- the watchdog: slow requests, the refusal summary ----------------------------------
  void watchdogLoop() {
    std::unique_lock<std::mutex> rg(refMu);
    while (!stopping.load()) {
      refCv.wait_for(rg, std::chrono::milliseconds(200));
      flushRefusals(Clock::now());
      rg.unlock();
      uint64_t slow = 0;
      std::string first;
      {
        std::lock_guard<std::mutex> g(connMu);
        const auto limit = Clock::now() - std::chrono::seconds(cfg.requestSeconds);
        for (Conn *cn : conns)
          if (cn->reading && !cn->shut && cn->start < limit) {
            // The connection's fd is open: MHD tells us (under connMu) before it closes it.
            ::shutdown(cn->fd, SHUT_RDWR);
            cn->shut = true;
            if (slow++ == 0) first = cn->client;
          }
      }
      for (uint64_t i = 0; i < slow; ++i)
        refusal("slow request", "closed the connection of " + first + ": its request was not " +
                                    "complete within " + std::to_string(cfg.requestSeconds) + " s");
      rg.lock();
    }
  }

  static void onConnection(void *cls, MHD_Connection *c, void **ctx,
                           MHD_ConnectionNotificationCode code) {
    Impl &im = *static_cast<Impl *>(cls);
    if (code == MHD_CONNECTION_NOTIFY_STARTED) {
      auto *cn = new Conn;
      if (const MHD_ConnectionInfo *i =
              MHD_get_connection_info(c, MHD_CONNECTION_INFO_CONNECTION_FD))
        cn->fd = i->connect_fd;
      if (const MHD_ConnectionInfo *i =
              MHD_get_connection_info(c, MHD_CONNECTION_INFO_CLIENT_ADDRESS))
        addrOf(i->client_addr, cn->ip, cn->client);
      *ctx = cn;
      std::lock_guard<std::mutex> g(im.connMu);
      im.conns.insert(cn);
    } else if (code == MHD_CONNECTION_NOTIFY_CLOSED) {
      auto *cn = static_cast<Conn *>(*ctx);
      if (!cn) return;
      {
        std::lock_guard<std::mutex> g(im.connMu);
        im.conns.erase(cn);
      }
      delete cn;
      *ctx = nullptr;
    }
  }

  static void onCompleted(void *cls, MHD_Connection *c, void **con_cls,
                          MHD_RequestTerminationCode) {
    Impl &im = *static_cast<Impl *>(cls);
    auto *rq = static_cast<Request *>(*con_cls);
    if (rq && rq->bigBody) im.draftReading.store(false);
    delete rq;
    *con_cls = nullptr;
    // The next request on this connection (keep-alive) has its own deadline.
    if (Conn *cn = connOf(c)) {
      std::lock_guard<std::mutex> g(im.connMu);
      cn->reading = true;
      cn->start = Clock::now();
    }
  }

  static MHD_Result onRequest(void *cls, MHD_Connection *c, const char *url, const char *method,
                              const char *, const char *upload, size_t *uploadSize,
                              void **con_cls) {
    Impl &im = *static_cast<Impl *>(cls);
    auto *rq = static_cast<Request *>(*con_cls);
    try {
      if (!rq) {
        rq = new Request;
        *con_cls = rq;
        return im.begin(c, url, method, *rq);
      }
      if (*uploadSize) return im.body(c, *rq, upload, uploadSize);
      if (rq->cmd.empty()) return MHD_YES; // answered, deferred or a stream
      return im.finish(c, *rq);
    } catch (const std::exception &e) {
      im.log(std::string("internal error: ") + e.what());
      return MHD_NO;
    }
  }
};

HttpServer::HttpServer(HttpConfig cfg, HttpBackend backend) : impl_(std::make_unique<Impl>()) {
  impl_->cfg = std::move(cfg);
  impl_->be = std::move(backend);
}

HttpServer::~HttpServer() { stop(); }

bool HttpServer::start(std::string &error) {
  Impl &im = *impl_;
  const std::string where = im.cfg.host + ":" + std::to_string(im.cfg.port);
  addrinfo hints{};
  hints.ai_family = AF_UNSPEC;
  hints.ai_socktype = SOCK_STREAM;
  hints.ai_flags = AI_PASSIVE | AI_NUMERICSERV;
  addrinfo *ai = nullptr;
  const std::string portText = std::to_string(im.cfg.port);
  if (int rc = getaddrinfo(im.cfg.host.c_str(), portText.c_str(), &hints, &ai); rc != 0) {
    error = "--http: cannot listen on " + where + ": " + gai_strerror(rc);
    return false;
  }
  int fd = -1;
  std::string why = "no address";
  for (addrinfo *a = ai; a && fd < 0; a = a->ai_next) {
    fd = ::socket(a->ai_family, a->ai_socktype | SOCK_CLOEXEC, a->ai_protocol);
    if (fd < 0) continue;
    int one = 1;
    ::setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
    if (::bind(fd, a->ai_addr, a->ai_addrlen) != 0 || ::listen(fd, 64) != 0) {
      why = std::strerror(errno);
      ::close(fd);
      fd = -1;
    }
  }
  freeaddrinfo(ai);
  if (fd < 0) {
    error = "--http: cannot listen on " + where + ": " + why;
    return false;
  }
  sockaddr_storage ss{};
  socklen_t len = sizeof ss;
  ::getsockname(fd, reinterpret_cast<sockaddr *>(&ss), &len);
  im.port = ntohs(ss.ss_family == AF_INET6 ? reinterpret_cast<sockaddr_in6 *>(&ss)->sin6_port
                                           : reinterpret_cast<sockaddr_in *>(&ss)->sin_port);
  im.cookieName = "ljtoken_" + std::to_string(im.port);
  im.buildHostNames();
  // The limits: a connection holds at most connectionMemory bytes of MHD's (request line,
  // headers, read and write buffers; more is answered 431 / 414 and closed), no byte either way
  // for idleSeconds closes it, so does the watchdog when its request is not complete within
  // requestSeconds; maxConnections at once (more are closed at accept).
  im.daemon = MHD_start_daemon(
      MHD_USE_INTERNAL_POLLING_THREAD | MHD_USE_AUTO | MHD_ALLOW_SUSPEND_RESUME, 0, nullptr,
      nullptr, &Impl::onRequest, &im, MHD_OPTION_LISTEN_SOCKET, fd,
      MHD_OPTION_CONNECTION_MEMORY_LIMIT, im.cfg.connectionMemory, MHD_OPTION_CONNECTION_LIMIT,
      static_cast<unsigned>(im.cfg.maxConnections), MHD_OPTION_CONNECTION_TIMEOUT,
      static_cast<unsigned>(im.cfg.idleSeconds), MHD_OPTION_NOTIFY_CONNECTION, &Impl::onConnection,
      &im, MHD_OPTION_NOTIFY_COMPLETED, &Impl::onCompleted, &im, MHD_OPTION_END);
  if (!im.daemon) {
    ::close(fd);
    error = "--http: cannot start the HTTP server on " + where;
    return false;
  }
  port_ = im.port;
  im.pump = std::thread([&im] { im.pumpLoop(); });
  im.worker = std::thread([&im] { im.workerLoop(); });
  im.watchdog = std::thread([&im] { im.watchdogLoop(); });
  return true;
}

void HttpServer::stop() {
  if (!impl_ || !impl_->daemon) return;
  Impl &im = *impl_;
  im.stopping.store(true);
  im.jobCv.notify_all();
  im.refCv.notify_all();
  if (im.pump.joinable()) im.pump.join();
  if (im.worker.joinable()) im.worker.join();
  if (im.watchdog.joinable()) im.watchdog.join();
  im.wakeStreams(); // every stream ends (stopping), none stays suspended
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  MHD_stop_daemon(im.daemon);
  im.daemon = nullptr;
}

} // namespace lj::services

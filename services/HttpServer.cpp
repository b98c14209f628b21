// cpp-httplib behind HttpServer.h: routes, the token check, SSE streams, bad requests as 4xx.
#include "services/HttpServer.h"

#include <httplib.h>

#include <algorithm>
#include <exception>

namespace lj::io {

using nlohmann::json;

struct HttpServer::Impl {
  HttpConfig cfg;
  HttpBackend be;
  httplib::Server svr;
  std::thread thread;
  std::atomic<bool> stopping{false};
  std::atomic<int> streams{0};

  void log(const std::string &m) const {
    if (cfg.log) cfg.log("http: " + m);
  }
  static std::string origin(const httplib::Request &req) {
    std::string o = req.remote_addr + ":" + std::to_string(req.remote_port);
    std::string h = req.get_header_value("Origin");
    return o + " (Origin: " + (h.empty() ? std::string("none") : h) + ")";
  }
  /// Send `text` uncompressed: through a content provider of known length, which httplib never
  /// compresses (Debian's build would brotli a set_content body for a browser: ~57 s for the
  /// 7.5 MB page of a 10k-statement program).
  static void send(httplib::Response &res, int status, std::string text, const char *type) {
    res.status = status;
    auto body = std::make_shared<std::string>(std::move(text));
    res.set_content_provider(
        body->size(), type, [body](size_t off, size_t len, httplib::DataSink &sink) {
          return sink.write(body->data() + off, std::min(len, body->size() - off));
        });
  }
  static void reply(httplib::Response &res, int status, const json &j) {
    send(res, status, j.dump(-1, ' ', false, json::error_handler_t::replace) + "\n",
         "application/json");
  }
  static void error(httplib::Response &res, int status, const std::string &why) {
    reply(res, status, {{"ok", false}, {"error", why}});
  }

  /// The token check of every POST: 403 with the reason, logged with the origin.
  bool allowed(const httplib::Request &req, httplib::Response &res) const {
    std::string why;
    std::string auth = req.get_header_value("Authorization");
    std::string given = auth.rfind("Bearer ", 0) == 0 ? auth.substr(7) : std::string();
    if (given.empty()) given = req.get_header_value("X-Ladderjit-Token");
    if (cfg.readOnly)
      why = "this server is read-only (serve --http-read-only): nothing can be changed from here";
    else if (given.empty())
      why = "missing token: send 'Authorization: Bearer TOKEN' with the token serve printed at "
            "start (or the one of --http-token-file)";
    else if (!sameToken(given, cfg.token))
      why = "wrong token";
    if (why.empty()) return true;
    log("refused " + req.method + " " + req.path + " from " + origin(req) + ": " + why);
    error(res, 403, why);
    return false;
  }
  static bool sameToken(const std::string &a, const std::string &b) {
    if (a.size() != b.size() || b.empty()) return false;
    unsigned char d = 0;
    for (size_t i = 0; i < a.size(); ++i) d |= static_cast<unsigned char>(a[i] ^ b[i]);
    return d == 0;
  }

  /// POST /api/NAME: a JSON object body turned into the control request `cmd`.
  void post(const char *path, const char *cmd, std::initializer_list<const char *> keys) {
    std::string p = path;
    std::string c = cmd;
    std::vector<std::string> ks(keys.begin(), keys.end());
    svr.Post(p, [this, c, ks](const httplib::Request &req, httplib::Response &res) {
      if (!allowed(req, res)) return;
      json body = json::parse(req.body, nullptr, false);
      if (body.is_discarded() || !body.is_object()) {
        error(res, 400, "the body must be a JSON object, e.g. {\"id\":12,\"mode\":\"on\"}");
        return;
      }
      json r{{"cmd", c}};
      for (const std::string &k : ks)
        if (body.contains(k)) r[k] = body[k];
      for (const auto &[k, v] : body.items())
        if (std::find(ks.begin(), ks.end(), k) == ks.end()) {
          error(res, 400, "unknown field '" + k + "' in " + req.path);
          return;
        }
      json ans = be.command(r);
      const bool ok = ans.value("ok", false);
      log(req.method + " " + req.path + " " +
          body.dump(-1, ' ', false, json::error_handler_t::replace) + " from " + origin(req) +
          ": " + (ok ? std::string("ok") : "refused: " + ans.value("error", std::string("?"))));
      reply(res, ok ? 200 : 400, ans);
    });
  }

  void routes() {
    svr.Get("/", [this](const httplib::Request &, httplib::Response &res) {
      send(res, 200, be.page(), "text/html; charset=utf-8");
    });
    svr.Get("/api/model", [this](const httplib::Request &, httplib::Response &res) {
      reply(res, 200, be.model());
    });
    svr.Get("/api/state", [this](const httplib::Request &, httplib::Response &res) {
      reply(res, 200, be.state());
    });
    svr.Get("/api/locks", [this](const httplib::Request &, httplib::Response &res) {
      reply(res, 200, be.command({{"cmd", "locks"}}));
    });
    svr.Get("/api/events", [this](const httplib::Request &req, httplib::Response &res) {
      if (streams.fetch_add(1) >= cfg.maxStreams) {
        streams.fetch_sub(1);
        log("refused a live stream from " + origin(req) + ": " + std::to_string(cfg.maxStreams) +
            " are open");
        error(res, 503, "too many live pages (" + std::to_string(cfg.maxStreams) + "); close one");
        return;
      }
      be.watchers(+1);
      auto seq = std::make_shared<uint64_t>(0);
      res.set_header("Cache-Control", "no-cache");
      res.set_chunked_content_provider(
          "text/event-stream",
          [this, seq](size_t, httplib::DataSink &sink) {
            if (stopping.load()) return false;
            std::string text;
            if (!be.next(*seq, text, std::chrono::milliseconds(1000))) text = ": ping\n\n";
            return !stopping.load() && sink.write(text.data(), text.size());
          },
          [this](bool) {
            streams.fetch_sub(1);
            be.watchers(-1);
          });
    });
    for (const char *p : {"/api/force", "/api/lock", "/api/unlock"})
      svr.Get(p, [](const httplib::Request &req, httplib::Response &res) {
        error(res, 405, req.path + " takes POST with a JSON body");
      });
    post("/api/force", "force", {"id", "line", "mode"});
    post("/api/lock", "lock", {"item"});
    post("/api/unlock", "unlock", {"addr"});
    svr.set_error_handler([](const httplib::Request &req, httplib::Response &res) {
      // Our own answers carry a Content-Type; the library's (no route, unparsable) do not.
      if (res.has_header("Content-Type")) return;
      if (res.status == 404)
        error(res, 404, "no such page: " + req.path);
      else
        error(res, res.status, "bad request");
    });
    svr.set_exception_handler(
        [this](const httplib::Request &req, httplib::Response &res, std::exception_ptr ep) {
          std::string what = "internal error";
          try {
            if (ep) std::rethrow_exception(ep);
          } catch (const std::exception &e) {
            what += std::string(": ") + e.what();
          } catch (...) {
          }
          log(req.method + " " + req.path + " from " + origin(req) + ": " + what);
          error(res, 500, what);
        });
  }
};

HttpServer::HttpServer(HttpConfig cfg, HttpBackend backend) : impl_(std::make_unique<Impl>()) {
  impl_->cfg = std::move(cfg);
  impl_->be = std::move(backend);
}

HttpServer::~HttpServer() { stop(); }

bool HttpServer::start(std::string &error) {
  Impl &im = *impl_;
  // Each open SSE stream holds one worker: room for every stream plus the page and commands.
  const size_t workers = static_cast<size_t>(im.cfg.maxStreams) + 8;
  im.svr.new_task_queue = [workers] { return new httplib::ThreadPool(workers); };
  im.svr.set_payload_max_length(64 * 1024);
  im.svr.set_read_timeout(5, 0);
  im.svr.set_write_timeout(5, 0);
  im.routes();
  if (im.cfg.port == 0) {
    port_ = im.svr.bind_to_any_port(im.cfg.host);
  } else {
    port_ = im.svr.bind_to_port(im.cfg.host, im.cfg.port) ? im.cfg.port : -1;
  }
  if (port_ < 0) {
    error = "--http: cannot listen on " + im.cfg.host + ":" + std::to_string(im.cfg.port);
    return false;
  }
  im.thread = std::thread([&im] { im.svr.listen_after_bind(); });
  return true;
}

void HttpServer::stop() {
  if (!impl_ || !impl_->thread.joinable()) return;
  impl_->stopping.store(true);
  impl_->svr.stop();
  impl_->thread.join();
}

} // namespace lj::io

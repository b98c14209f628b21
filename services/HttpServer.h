// The live ladder view's HTTP server for `ladderjit serve --http` (docs/serve.md "Live view",
// docs/security.md "The live view's HTTP port"): libmicrohttpd (Debian libmicrohttpd-dev) with
// the page, the model, a Server-Sent Events stream of trace snapshots, POST commands (force,
// lock, unlock), the signal trace (GET / POST /api/trace) and Debian's dygraphs for the trace
// panel. Every request needs the token and a Host of this server; what a client may make
// the server hold (header bytes, body bytes, connections, streams, time) is bounded before it is
// read. It only calls the backend's functions; it never touches the scan thread.
#pragma once

#include <nlohmann/json.hpp>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <thread>
#include <vector>

namespace lj::services {

/// What the server serves, supplied by `serve` (tools/ladderjit/ServeHttp.cpp).
struct HttpBackend {
  std::function<std::string()> page;     ///< GET /: the self-contained HTML page
  std::function<nlohmann::json()> model; ///< GET /api/model: version + trace layout
  std::function<nlohmann::json()> state; ///< GET /api/state: the newest snapshot
  /// SSE: wait up to `timeout` for a message newer than `seq`; true with its text (whole
  /// `event:`/`data:` blocks) and `seq` advanced, false on timeout.
  std::function<bool(uint64_t &seq, std::string &text, std::chrono::milliseconds timeout)> next;
  std::function<void(int delta)> watchers; ///< an SSE stream opened (+1) or closed (-1)
  /// A control request (runtime/Controller handle: force, lock, unlock, locks).
  std::function<nlohmann::json(const nlohmann::json &)> command;
  /// The ladder editor's routes (runtime/EditSession.h, docs/ladder-edit.md): `action` empty for
  /// GET /api/edit, else draft / check / update / discard (POST /api/edit/ACTION) with the
  /// JSON body; `client` is "ADDR:PORT". Returns the HTTP status and the JSON answer. Unset: the
  /// routes answer 404.
  std::function<std::pair<unsigned, nlohmann::json>(
      const std::string &action, const nlohmann::json &body, const std::string &client)>
      edit;
};

struct HttpConfig {
  std::string host = "127.0.0.1";
  int port = 0; ///< 0 = any free port (port() tells which)
  /// Required on every request: `Authorization: Bearer TOKEN`, or the cookie the page sets when
  /// opened with `?token=TOKEN` together with `key` (header X-Ladderjit-Key or query `k`).
  std::string token;
  /// The page's own key (embedded in the page it serves): a cookie alone is not enough.
  std::string key;
  /// Host names (NAME or NAME:PORT) accepted besides the bound address and the loopback ones.
  std::vector<std::string> hosts;
  std::string tokenFile; ///< named in the 401 answer (where the token is)
  bool readOnly = false;
  /// Where GET /dygraph.min.js and /dygraph.min.css are read from, at each request (the trace
  /// panel's charting library, Debian's libjs-dygraphs; docs/trace.md "Page"). Missing: 404.
  std::string dygraphsDir = "/usr/share/javascript/dygraphs";
  int maxStreams = 32;                 ///< SSE streams at once; more get 503 (and are closed)
  int maxStreamsPerClient = 20;        ///< SSE streams of one client address at once
  int maxConnections = 256;            ///< open TCP connections; more are closed at once
  size_t connectionMemory = 32 * 1024; ///< request line + headers + read buffer, per connection
  size_t maxBody = 64 * 1024;          ///< POST body bytes, chunked included
  /// POST /api/edit/draft body bytes (a whole program's network JSON: a 10,000-statement
  /// program's is a few MiB); one such body is read at a time (another gets 503).
  size_t maxEditBody = size_t{16} << 20;
  int requestSeconds = 10; ///< headers and body complete within this after the connection
  int idleSeconds = 10;    ///< no byte either way for this long: closed
  std::function<void(const std::string &)> log;
};

/// A client's string for a log line: at most `max` bytes, control and non-ASCII bytes and the
/// backslash as \xNN, "..." when cut.
std::string clientText(const std::string &s, size_t max = 80);

class HttpServer {
public:
  HttpServer(HttpConfig cfg, HttpBackend backend);
  ~HttpServer();
  HttpServer(const HttpServer &) = delete;
  HttpServer &operator=(const HttpServer &) = delete;
  /// Bind and start serving on a thread of its own; false with `error` when it cannot bind.
  bool start(std::string &error);
  /// Stop serving; open streams end within a second.
  void stop();
  int port() const { return port_; }

  struct Impl;

private:
  std::unique_ptr<Impl> impl_;
  int port_ = -1;
};

} // namespace lj::services

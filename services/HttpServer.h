// The live ladder view's HTTP server for `ladderjit serve --http` (docs/serve.md "Live view"):
// cpp-httplib (Debian libcpp-httplib-dev) with the page, the model, a Server-Sent Events stream
// of trace snapshots, and POST commands (force, lock, unlock) behind a token. It only calls the
// backend's functions; it never touches the scan thread.
#pragma once

#include <nlohmann/json.hpp>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <thread>

namespace lj::io {

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
};

struct HttpConfig {
  std::string host = "127.0.0.1";
  int port = 0;      ///< 0 = any free port (port() tells which)
  std::string token; ///< required on every POST (Authorization: Bearer TOKEN)
  bool readOnly = false;
  int maxStreams = 32; ///< SSE streams at once; more get 503
  std::function<void(const std::string &)> log;
};

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

} // namespace lj::io

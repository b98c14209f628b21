// The live ladder view of a Server (`serve --http`) (docs/serve.md "Live view"). Composes the trace
// of the running version (runtime/TraceBuffer.h), the page (ladder/), the controller's force and
// lock requests and the HTTP server (services/HttpServer.h). A hub thread turns the newest trace
// snapshot into one SSE message 20 times a second for every page; the scan thread only copies
// the trace into its triple buffer at a tick boundary.
#pragma once

#include "runtime/Controller.h"
#include "runtime/Exchange.h"
#include "runtime/Executive.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace lj::rt {

struct LiveViewConfig {
  std::string host = "127.0.0.1";
  int port = 0;
  std::string token;
  std::string tokenFile;          ///< where the token is (named in the page's 401 answer)
  std::vector<std::string> hosts; ///< --http-host: Host names answered besides the address
  bool readOnly = false;
  uint64_t periodNs = 1000000;
  std::string engine; ///< for the page's header
};

class LiveView {
public:
  LiveView(Executive &exec, Exchange &ex, Controller &ctl,
           std::function<void(const std::string &)> log, LiveViewConfig cfg);
  ~LiveView();
  /// The after-tick hook that publishes the trace (add before exec.start).
  Executive::AfterTickHook hook();
  /// Start the hub and the HTTP server (after exec.start); false with `error`.
  bool start(std::string &error);
  /// True when the traced JIT build was still compiling: its thread is detached and ends with
  /// the process (the caller exits without destructors, as for the tier-up compile).
  bool stop();
  int port() const;

  struct Impl;

private:
  std::unique_ptr<Impl> impl_;
};

/// A fresh random token (32 hex digits) for --http.
std::string newHttpToken();

/// --http's token: read from `file` when it exists (refused when it is not a regular file of
/// this user or is accessible by group or others, like a private key), else a fresh one written
/// there with mode 0600. False with `error`.
bool httpToken(const std::string &file, std::string &token, bool &created, std::string &error);

} // namespace lj::rt

// The control interface of `ladderjit serve`: a Unix domain stream socket speaking JSON lines
// (one request object per line, one response object per line; docs/serve.md "Control").
#pragma once

#include "services/ClientSlots.h"

#include <nlohmann/json.hpp>
#include <sys/types.h>

#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <list>
#include <mutex>
#include <string>
#include <string_view>
#include <thread>

namespace lj::rt {

/// Deadlines of the control socket (serve --client-idle-s, --request-timeout-ms).
struct ControlOptions {
  /// A connection with no request in progress for this long is closed.
  std::chrono::milliseconds idleTimeout{30000};
  /// A request line must be complete this long after its first byte (else an error answer and
  /// the connection is closed); also bounds sending an answer to a client that does not read.
  std::chrono::milliseconds requestTimeout{2000};
  std::function<void(const std::string &)> log; ///< refused peers, deadlines; default: none
};

/// Serves requests on a socket; each connection gets its own thread (at most kMaxClients at
/// once, plus one reserved slot, docs/serve.md "Control"), so a slow request (an online change
/// compiling) does not stall a `read`. Only the server's own uid and root may connect: the
/// socket file is 0600 and every accepted connection's SO_PEERCRED is checked.
class ControlSocket {
public:
  using Handler = std::function<nlohmann::json(const nlohmann::json &request)>;
  static constexpr int kMaxClients = 16;

  explicit ControlSocket(Handler h, ControlOptions o = {})
      : handler_(std::move(h)), opt_(std::move(o)) {}
  /// Stops accepting, closes every connection, joins the threads and removes the socket file.
  ~ControlSocket();
  ControlSocket(const ControlSocket &) = delete;
  ControlSocket &operator=(const ControlSocket &) = delete;

  /// Bind and listen on `path`, mode 0600 whatever the umask (a stale socket file of ours
  /// nobody answers on is replaced; a live one, or one owned by another user, is an error),
  /// then serve on a background thread.
  bool start(const std::string &path, std::string &error);
  void stop();
  const std::string &path() const { return path_; }

  /// The answer line (ending in '\n') to one request line, as a connection gets it. Never
  /// throws: a malformed line, a handler exception and strings that are not UTF-8 all give a
  /// well-formed JSON answer.
  static std::string answer(const Handler &h, std::string_view line);
  /// Whether a peer with effective uid `uid` may use the socket: our own euid and root.
  static bool allowedPeer(uid_t uid);

private:
  void acceptLoop();
  void admit(int fd);
  void serveClient(services::ClientSlot *c);
  void logLine(const std::string &s) const {
    if (opt_.log) opt_.log(s);
  }

  Handler handler_;
  ControlOptions opt_;
  std::string path_;
  int listenFd_ = -1;
  int wakePipe_[2] = {-1, -1};
  std::atomic<bool> stopping_{false};
  std::thread acceptThread_;
  std::mutex mu_;
  std::list<services::ClientSlot>
      clients_; // finished ones are joined at the next accept; guarded by mu_
};

/// Client side: send `request` to the server at `path` and return its response. False with
/// `error` when the server cannot be reached, is not run by us or root (SO_PEERCRED), or
/// answers garbage. `timeoutMs` bounds the wait.
bool controlRequest(const std::string &path, const nlohmann::json &request,
                    nlohmann::json &response, std::string &error, int timeoutMs = 120000);

} // namespace lj::rt

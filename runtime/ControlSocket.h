// The control interface of `ladderjit serve`: a Unix domain stream socket speaking JSON lines
// (one request object per line, one response object per line; docs/serve.md "Control").
#pragma once

#include <nlohmann/json.hpp>

#include <atomic>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace lj::rt {

/// Serves requests on a socket; each connection gets its own thread (at most kMaxClients at
/// once), so a slow request (an online change compiling) does not stall a `read`.
class ControlSocket {
public:
  using Handler = std::function<nlohmann::json(const nlohmann::json &request)>;
  static constexpr int kMaxClients = 16;

  explicit ControlSocket(Handler h) : handler_(std::move(h)) {}
  /// Stops accepting, closes every connection, joins the threads and removes the socket file.
  ~ControlSocket();
  ControlSocket(const ControlSocket &) = delete;
  ControlSocket &operator=(const ControlSocket &) = delete;

  /// Bind and listen on `path` (a stale socket file nobody answers on is replaced; a live one
  /// is an error), then serve on a background thread.
  bool start(const std::string &path, std::string &error);
  void stop();
  const std::string &path() const { return path_; }

private:
  void acceptLoop();
  void serveClient(int fd, std::atomic<bool> &done);

  Handler handler_;
  std::string path_;
  int listenFd_ = -1;
  int wakePipe_[2] = {-1, -1};
  std::atomic<bool> stopping_{false};
  std::atomic<int> clients_{0};
  std::thread acceptThread_;
  std::mutex mu_;
  struct Client {
    std::thread thread;
    std::shared_ptr<std::atomic<bool>> done;
  };
  std::vector<Client> clientThreads_; // finished ones are joined at the next accept
  std::vector<int> clientFds_;
};

/// Client side: send `request` to the server at `path` and return its response. False with
/// `error` when the server cannot be reached or answers garbage. `timeoutMs` bounds the wait.
bool controlRequest(const std::string &path, const nlohmann::json &request,
                    nlohmann::json &response, std::string &error, int timeoutMs = 120000);

} // namespace lj::rt

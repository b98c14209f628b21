// Unix-socket JSON-lines server and client for the serve control interface.
#include "runtime/ControlSocket.h"

#include <fcntl.h>
#include <poll.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace lj::rt {

namespace {

constexpr size_t kMaxLine = 1 << 20; // a request longer than this is refused

bool fillAddress(const std::string &path, sockaddr_un &addr, std::string &error) {
  std::memset(&addr, 0, sizeof addr);
  addr.sun_family = AF_UNIX;
  if (path.empty() || path.size() >= sizeof addr.sun_path) {
    error = "control socket path '" + path + "' is empty or longer than " +
            std::to_string(sizeof addr.sun_path - 1) + " bytes";
    return false;
  }
  std::memcpy(addr.sun_path, path.data(), path.size());
  return true;
}

bool writeAll(int fd, const std::string &s) {
  size_t off = 0;
  while (off < s.size()) {
    ssize_t n = ::send(fd, s.data() + off, s.size() - off, MSG_NOSIGNAL);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    off += static_cast<size_t>(n);
  }
  return true;
}

} // namespace

ControlSocket::~ControlSocket() { stop(); }

bool ControlSocket::start(const std::string &path, std::string &error) {
  sockaddr_un addr;
  if (!fillAddress(path, addr, error)) return false;
  struct stat st;
  if (::lstat(path.c_str(), &st) == 0) {
    if (!S_ISSOCK(st.st_mode)) {
      error = "control socket path '" + path + "' exists and is not a socket";
      return false;
    }
    int probe = ::socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
    bool live =
        probe >= 0 && ::connect(probe, reinterpret_cast<sockaddr *>(&addr), sizeof addr) == 0;
    if (probe >= 0) ::close(probe);
    if (live) {
      error = "control socket '" + path + "' is in use by another server";
      return false;
    }
    ::unlink(path.c_str()); // stale: left by a server that was killed
  }
  listenFd_ = ::socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (listenFd_ < 0 || ::bind(listenFd_, reinterpret_cast<sockaddr *>(&addr), sizeof addr) != 0 ||
      ::listen(listenFd_, 16) != 0 || ::pipe2(wakePipe_, O_CLOEXEC) != 0) {
    error = "control socket '" + path + "': " + std::strerror(errno);
    if (listenFd_ >= 0) ::close(listenFd_);
    listenFd_ = -1;
    return false;
  }
  path_ = path;
  acceptThread_ = std::thread([this] { acceptLoop(); });
  return true;
}

void ControlSocket::stop() {
  if (listenFd_ < 0) return;
  stopping_.store(true);
  char c = 1;
  [[maybe_unused]] ssize_t w = ::write(wakePipe_[1], &c, 1);
  if (acceptThread_.joinable()) acceptThread_.join();
  std::vector<Client> threads;
  {
    std::lock_guard<std::mutex> g(mu_);
    for (int fd : clientFds_) ::shutdown(fd, SHUT_RDWR); // wakes their recv
    threads.swap(clientThreads_);
  }
  for (Client &c : threads) c.thread.join();
  ::close(listenFd_);
  ::close(wakePipe_[0]);
  ::close(wakePipe_[1]);
  listenFd_ = -1;
  ::unlink(path_.c_str());
}

void ControlSocket::acceptLoop() {
  while (!stopping_.load()) {
    pollfd fds[2] = {{listenFd_, POLLIN, 0}, {wakePipe_[0], POLLIN, 0}};
    if (::poll(fds, 2, -1) < 0) {
      if (errno == EINTR) continue;
      return;
    }
    if (fds[1].revents) return;
    int fd = ::accept4(listenFd_, nullptr, nullptr, SOCK_CLOEXEC);
    if (fd < 0) continue;
    if (clients_.load() >= kMaxClients) {
      writeAll(fd, R"({"ok":false,"error":"too many control clients"})"
                   "\n");
      ::close(fd);
      continue;
    }
    clients_.fetch_add(1);
    std::lock_guard<std::mutex> g(mu_);
    std::erase_if(clientThreads_, [](Client &c) {
      if (!c.done->load()) return false;
      c.thread.join();
      return true;
    });
    clientFds_.push_back(fd);
    auto done = std::make_shared<std::atomic<bool>>(false);
    clientThreads_.push_back({std::thread([this, fd, done] { serveClient(fd, *done); }), done});
  }
}

void ControlSocket::serveClient(int fd, std::atomic<bool> &done) {
  std::string buf;
  char chunk[4096];
  bool open = true;
  while (open && !stopping_.load()) {
    ssize_t n = ::recv(fd, chunk, sizeof chunk, 0);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    buf.append(chunk, static_cast<size_t>(n));
    size_t nl;
    while ((nl = buf.find('\n')) != std::string::npos) {
      std::string line = buf.substr(0, nl);
      buf.erase(0, nl + 1);
      nlohmann::json resp;
      nlohmann::json req = nlohmann::json::parse(line, nullptr, false);
      if (req.is_discarded() || !req.is_object())
        resp = {{"ok", false}, {"error", "request is not a JSON object"}};
      else
        resp = handler_(req);
      if (!writeAll(fd, resp.dump() + "\n")) open = false;
    }
    if (buf.size() > kMaxLine) {
      writeAll(fd, R"({"ok":false,"error":"request line too long"})"
                   "\n");
      break;
    }
  }
  {
    std::lock_guard<std::mutex> g(mu_);
    std::erase(clientFds_, fd);
  }
  ::close(fd);
  clients_.fetch_sub(1);
  done.store(true);
}

bool controlRequest(const std::string &path, const nlohmann::json &request,
                    nlohmann::json &response, std::string &error, int timeoutMs) {
  sockaddr_un addr;
  if (!fillAddress(path, addr, error)) return false;
  int fd = ::socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (fd < 0 || ::connect(fd, reinterpret_cast<sockaddr *>(&addr), sizeof addr) != 0) {
    error = "cannot connect to the server at '" + path + "': " + std::strerror(errno) +
            " (is `ladderjit serve` running? see --control)";
    if (fd >= 0) ::close(fd);
    return false;
  }
  if (!writeAll(fd, request.dump() + "\n")) {
    error = "cannot send to '" + path + "': " + std::strerror(errno);
    ::close(fd);
    return false;
  }
  std::string buf;
  char chunk[4096];
  while (buf.find('\n') == std::string::npos) {
    pollfd p{fd, POLLIN, 0};
    int r = ::poll(&p, 1, timeoutMs);
    if (r < 0 && errno == EINTR) continue;
    if (r <= 0) {
      error = "no answer from the server at '" + path + "'";
      ::close(fd);
      return false;
    }
    ssize_t n = ::recv(fd, chunk, sizeof chunk, 0);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      error = "the server at '" + path + "' closed the connection without an answer";
      ::close(fd);
      return false;
    }
    buf.append(chunk, static_cast<size_t>(n));
  }
  ::close(fd);
  response = nlohmann::json::parse(buf.substr(0, buf.find('\n')), nullptr, false);
  if (response.is_discarded() || !response.is_object()) {
    error = "the server at '" + path + "' answered something that is not a JSON object";
    return false;
  }
  return true;
}

} // namespace lj::rt

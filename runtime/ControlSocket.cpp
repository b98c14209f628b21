// Unix-socket JSON-lines server and client for the serve control interface.
#include "runtime/ControlSocket.h"

#include "formats/StateJson.h"
#include "runtime/ControlPath.h"
#include "services/ClientSlots.h"

#include <fcntl.h>
#include <poll.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <set>
#include <vector>

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

nlohmann::json failure(const std::string &msg) { return {{"ok", false}, {"error", msg}}; }

bool peerUid(int fd, uid_t &uid) {
  ucred cr{};
  socklen_t len = sizeof cr;
  if (::getsockopt(fd, SOL_SOCKET, SO_PEERCRED, &cr, &len) != 0) return false;
  uid = cr.uid;
  return true;
}

/// Parse one request; a key given twice in one object is refused (which one would win is a
/// guess: nlohmann keeps the last, another reader the first), named in `duplicate`.
nlohmann::json parseRequest(std::string_view line, std::string &duplicate) {
  std::vector<std::set<std::string>> open; // keys seen, per enclosing object
  auto cb = [&](int, nlohmann::json::parse_event_t ev, nlohmann::json &parsed) {
    using E = nlohmann::json::parse_event_t;
    if (ev == E::object_start) {
      open.emplace_back();
    } else if (ev == E::object_end) {
      if (!open.empty()) open.pop_back();
    } else if (ev == E::key && !open.empty() && parsed.is_string()) {
      if (!open.back().insert(parsed.get<std::string>()).second && duplicate.empty())
        duplicate = parsed.get<std::string>();
    }
    return true;
  };
  return nlohmann::json::parse(line, cb, false);
}

} // namespace

bool ControlSocket::allowedPeer(uid_t uid) { return uid == 0 || uid == ::geteuid(); }

std::string ControlSocket::answer(const Handler &h, std::string_view line) {
  nlohmann::json resp;
  try {
    std::string duplicate;
    nlohmann::json req = parseRequest(line, duplicate);
    if (req.is_discarded() || !req.is_object())
      resp = failure("request is not a JSON object");
    else if (!duplicate.empty())
      resp = failure("request has the key '" + duplicate + "' more than once");
    else
      resp = h(req);
  } catch (const std::exception &e) {
    resp = failure(std::string("internal error: ") + e.what());
  } catch (...) {
    resp = failure("internal error");
  }
  try {
    return formats::dumpJson(resp) + "\n"; // user bytes that are not UTF-8 become U+FFFD
  } catch (...) {                          // bad_alloc: still an answer, never an abort
    return R"({"ok":false,"error":"internal error"})"
           "\n";
  }
}

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
    if (st.st_uid != ::geteuid()) {
      error = "control socket path '" + path + "' exists and belongs to uid " +
              std::to_string(st.st_uid) + ", not to us";
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
  bool bound = false;
  if (listenFd_ >= 0) {
    // The socket file is created 0600 whatever the caller's umask (connecting needs write
    // permission on it); chmod again in case the file system ignored the umask.
    mode_t old = ::umask(0177);
    bound = ::bind(listenFd_, reinterpret_cast<sockaddr *>(&addr), sizeof addr) == 0;
    int saved = errno;
    ::umask(old);
    errno = saved;
    if (bound && ::chmod(path.c_str(), 0600) != 0) {
      saved = errno;
      ::unlink(path.c_str());
      errno = saved;
      bound = false;
    }
  }
  if (!bound || ::listen(listenFd_, 16) != 0 || ::pipe2(wakePipe_, O_CLOEXEC) != 0) {
    error = "control socket '" + path + "': " + std::strerror(errno);
    if (bound) ::unlink(path.c_str());
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
  services::closeAll(clients_, mu_); // the shutdown wakes their poll
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
    uid_t uid = 0;
    if (!peerUid(fd, uid) || !allowedPeer(uid)) {
      // The 0600 mode already keeps other users out; this holds even if it was loosened.
      std::string msg = "permission denied: uid " + std::to_string(uid) +
                        " may not use this control socket (only " +
                        (::geteuid() == 0 ? std::string("root")
                                          : "uid " + std::to_string(::geteuid()) + " and root") +
                        ")";
      writeAll(fd, formats::dumpJson(failure(msg)) + "\n");
      ::close(fd);
      logLine("control: connection refused: " + msg);
      continue;
    }
    admit(fd);
  }
}

// Slots: kMaxClients connections, plus one reserved for when every one of them is busy with
// a request (a `load` compiling), so `monitor stop` always gets in. When all slots are taken,
// the connection that has been idle longest (else the one longest stuck in an incomplete
// request) is closed to make room: an idle connection never locks the operator out.
void ControlSocket::admit(int fd) {
  services::setSendTimeout(fd, opt_.requestTimeout);
  std::lock_guard<std::mutex> g(mu_);
  services::reapFinished(clients_);
  bool evicted = false;
  const int active = services::makeRoom(clients_, kMaxClients, evicted);
  if (evicted)
    logLine("control: all " + std::to_string(kMaxClients) +
            " slots taken; closed the connection idle longest to admit a new one");
  if (active >= kMaxClients + 1) { // every slot, the reserved one too, is running a request
    writeAll(fd, R"({"ok":false,"error":"too many control clients"})"
                 "\n");
    ::close(fd);
    return;
  }
  services::ClientSlot &c = clients_.emplace_back();
  c.fd = fd;
  c.sinceMs = services::steadyMs();
  c.thread = std::thread([this, p = &c] { serveClient(p); });
}

void ControlSocket::serveClient(services::ClientSlot *c) {
  const int fd = c->fd;
  std::string buf;
  char chunk[4096];
  int64_t since = services::steadyMs(); // idle since, or the first byte of the request in `buf`
  while (!stopping_.load()) {
    const bool partial = !buf.empty();
    int64_t left =
        since + (partial ? opt_.requestTimeout : opt_.idleTimeout).count() - services::steadyMs();
    if (left <= 0) {
      if (partial) {
        std::string msg = "request not complete within " +
                          std::to_string(opt_.requestTimeout.count()) + " ms of its first byte";
        writeAll(fd, formats::dumpJson(failure(msg)) + "\n");
        logLine("control: connection closed: " + msg);
      }
      break; // idle: closed quietly (a client reconnects per request)
    }
    pollfd p{fd, POLLIN, 0};
    int r = ::poll(&p, 1, static_cast<int>(std::min<int64_t>(left, 1000)));
    if (r < 0 && errno == EINTR) continue;
    if (r < 0) break;
    if (r == 0) continue;
    ssize_t n = ::recv(fd, chunk, sizeof chunk, 0);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    if (buf.empty()) {
      since = services::steadyMs();
      c->sinceMs = since;
      c->state = services::ClientSlot::Receiving;
    }
    buf.append(chunk, static_cast<size_t>(n));
    bool open = true;
    size_t nl;
    while (open && (nl = buf.find('\n')) != std::string::npos) {
      c->state = services::ClientSlot::Handling;
      std::string line = buf.substr(0, nl);
      buf.erase(0, nl + 1);
      std::string out = answer(handler_, line);
      // Answered: the rest (if any) is a new request. Set before sending, so a client that
      // has its answer never sees this connection still counted as busy.
      since = services::steadyMs();
      c->sinceMs = since;
      c->state = buf.empty() ? services::ClientSlot::Idle : services::ClientSlot::Receiving;
      if (!writeAll(fd, out)) open = false;
    }
    if (!open) break;
    if (buf.size() > kMaxLine) {
      writeAll(fd, R"({"ok":false,"error":"request line too long"})"
                   "\n");
      break;
    }
  }
  std::lock_guard<std::mutex> g(mu_); // stop() and admit() shutdown() only fds still open
  ::close(fd);
  c->fd = -1;
  c->done.store(true);
}

bool controlRequest(const std::string &path, const nlohmann::json &request,
                    nlohmann::json &response, std::string &error, int timeoutMs) {
  sockaddr_un addr;
  if (!fillAddress(path, addr, error)) return false;
  int fd = ::socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (fd < 0 || ::connect(fd, reinterpret_cast<sockaddr *>(&addr), sizeof addr) != 0) {
    error = connectError(path, errno);
    if (fd >= 0) ::close(fd);
    return false;
  }
  // The server must run as us or root: a socket planted by another user is never trusted
  // with a write (or believed in a read).
  uid_t server = 0;
  if (!peerUid(fd, server) || !ControlSocket::allowedPeer(server)) {
    error = "refusing the server at '" + path + "': it runs as uid " + std::to_string(server) +
            ", not as uid " + std::to_string(::geteuid()) + " or root";
    ::close(fd);
    return false;
  }
  if (!writeAll(fd, formats::dumpJson(request) + "\n")) {
    error = "cannot send to '" + path + "': " + std::strerror(errno);
    ::close(fd);
    return false;
  }
  std::string buf;
  char chunk[65536];
  size_t scanned = 0; // bytes known to hold no '\n': an answer may be megabytes (a trace)
  while (buf.find('\n', scanned) == std::string::npos) {
    scanned = buf.size();
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

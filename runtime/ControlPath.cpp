// The private runtime directory of the control socket and monitor's checks of a socket path.
#include "runtime/ControlPath.h"

#include <dirent.h>
#include <fcntl.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/un.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace lj::rt {

namespace {

std::string uidText(uid_t u) { return std::to_string(u); }

// `dir` opened without following a symlink must be a directory owned by us; `fix` tightens a
// mode with group/other bits to 0700 (a directory we made under another umask), else those
// bits are an error.
bool verifyDir(const std::string &dir, bool fix, std::string &error) {
  int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
  if (fd < 0) {
    error = "control directory '" + dir + "': " +
            (errno == ELOOP || errno == ENOTDIR ? std::string("not a directory (a symlink?)")
                                                : std::string(std::strerror(errno)));
    return false;
  }
  struct stat st;
  bool ok = ::fstat(fd, &st) == 0;
  if (ok && st.st_uid != ::geteuid()) {
    error = "control directory '" + dir + "' belongs to uid " + uidText(st.st_uid) +
            ", not to uid " + uidText(::geteuid()) + ": refusing it (remove it, or give --control)";
    ok = false;
  } else if (ok && (st.st_mode & 077) != 0) {
    if (!fix || ::fchmod(fd, 0700) != 0) {
      char m[8];
      std::snprintf(m, sizeof m, "%04o", static_cast<unsigned>(st.st_mode & 07777));
      error = "control directory '" + dir + "' has mode " + m + "; it must be 0700";
      ok = false;
    }
  } else if (!ok) {
    error = "control directory '" + dir + "': " + std::strerror(errno);
  }
  ::close(fd);
  return ok;
}

bool isDir(const std::string &p) {
  struct stat st;
  return ::lstat(p.c_str(), &st) == 0 && S_ISDIR(st.st_mode);
}

// Candidates in order of preference; the first one whose parent exists is used.
std::vector<std::string> candidates() {
  if (const char *env = std::getenv("LADDERJIT_RUNTIME_DIR"); env && *env) return {env};
  const uid_t uid = ::geteuid();
  std::vector<std::string> out;
  if (uid == 0) {
    out.push_back("/run/ladderjit");
  } else if (const char *x = std::getenv("XDG_RUNTIME_DIR"); x && x[0] == '/') {
    struct stat st;
    // systemd's per-user directory: ours and private, else it is not used.
    if (::lstat(x, &st) == 0 && S_ISDIR(st.st_mode) && st.st_uid == uid && (st.st_mode & 077) == 0)
      out.push_back(std::string(x) + "/ladderjit");
  }
  out.push_back("/tmp/ladderjit-" + uidText(uid));
  return out;
}

std::string parentOf(const std::string &p) {
  size_t slash = p.find_last_of('/');
  if (slash == std::string::npos) return ".";
  return slash == 0 ? "/" : p.substr(0, slash);
}

bool connects(const std::string &path) {
  sockaddr_un addr{};
  addr.sun_family = AF_UNIX;
  if (path.size() >= sizeof addr.sun_path) return false;
  std::memcpy(addr.sun_path, path.data(), path.size());
  int fd = ::socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
  bool ok = fd >= 0 && ::connect(fd, reinterpret_cast<sockaddr *>(&addr), sizeof addr) == 0;
  if (fd >= 0) ::close(fd);
  return ok;
}

} // namespace

bool controlDir(bool create, std::string &dir, std::string &error) {
  std::vector<std::string> cs = candidates();
  for (size_t i = 0; i < cs.size(); ++i) {
    const std::string &c = cs[i];
    bool last = i + 1 == cs.size();
    if (!last && !isDir(parentOf(c))) continue; // e.g. no /run: fall back to /tmp
    if (create) {
      if (::mkdir(c.c_str(), 0700) != 0 && errno != EEXIST) {
        if (!last) continue;
        error = "cannot create the control directory '" + c + "': " + std::strerror(errno);
        return false;
      }
    } else if (!isDir(c) && !last) {
      continue;
    }
    if (!verifyDir(c, create, error)) return false;
    dir = c;
    return true;
  }
  error = "no control directory";
  return false;
}

bool defaultControlPath(std::string &path, std::string &error) {
  std::string dir;
  if (!controlDir(true, dir, error)) return false;
  path = dir + "/serve-" + std::to_string(::getpid()) + ".sock";
  return true;
}

bool findControlSocket(std::string &path, std::string &error) {
  std::string dir;
  if (!controlDir(false, dir, error)) {
    if (error.find("No such file") != std::string::npos)
      error = "no running server found (" + error + "); give --control PATH";
    return false;
  }
  std::vector<std::string> live;
  if (DIR *d = ::opendir(dir.c_str())) {
    while (dirent *e = ::readdir(d)) {
      std::string name = e->d_name;
      if (name.size() < 6 || name.compare(name.size() - 5, 5, ".sock") != 0) continue;
      std::string p = dir + "/" + name;
      std::string ignored;
      if (checkControlSocket(p, ignored) && connects(p)) live.push_back(p);
    }
    ::closedir(d);
  }
  if (live.size() == 1) {
    path = live[0];
    return true;
  }
  error = live.empty() ? "no running server found in '" + dir + "'; give --control PATH"
                       : "several servers are running in '" + dir + "'; give --control PATH";
  return false;
}

std::string connectError(const std::string &path, int err) {
  std::string out = "cannot connect to the server at '" + path + "': " + std::strerror(err);
  // Only a missing socket or one nobody listens on suggests that serve is not running.
  if (err == ENOENT || err == ECONNREFUSED)
    return out + " (is `ladderjit serve` running? see --control)";
  if (err == EACCES || err == EPERM)
    return out + " (run monitor as the user serve runs as, or as root)";
  return out;
}

bool checkControlSocket(const std::string &path, std::string &error) {
  const uid_t me = ::geteuid();
  struct stat st;
  if (::lstat(path.c_str(), &st) != 0) {
    error = connectError(path, errno);
    return false;
  }
  if (!S_ISSOCK(st.st_mode)) {
    error = "'" + path + "' is not a socket";
    return false;
  }
  if (st.st_uid != me && st.st_uid != 0) {
    error = "refusing the control socket '" + path + "': it belongs to uid " + uidText(st.st_uid) +
            ", not to uid " + uidText(me) + " or root";
    return false;
  }
  const std::string dir = parentOf(path);
  struct stat ds;
  if (::stat(dir.c_str(), &ds) != 0 || !S_ISDIR(ds.st_mode)) {
    error = "cannot use the directory of the control socket '" + path + "'";
    return false;
  }
  if (ds.st_uid != me && ds.st_uid != 0) {
    error = "refusing the control socket '" + path + "': its directory belongs to uid " +
            uidText(ds.st_uid) + ", not to uid " + uidText(me) + " or root";
    return false;
  }
  // A directory others may write to lets them replace the socket, unless it is sticky.
  if ((ds.st_mode & 022) != 0 && (ds.st_mode & S_ISVTX) == 0) {
    error = "refusing the control socket '" + path +
            "': its directory is writable by other users (and not sticky)";
    return false;
  }
  return true;
}

} // namespace lj::rt

// Output files: a private temporary directory beside OUT, a rename over OUT, and the cleanup of
// temporary files when ladderjit is stopped by a signal (formats/OutputFile.h).
#include "formats/OutputFile.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <mutex>
#include <pthread.h>
#include <sys/stat.h>
#include <thread>
#include <unistd.h>
#include <vector>

namespace lj::formats {
namespace {

namespace fs = std::filesystem;

struct Registry {
  std::mutex mu;
  std::vector<std::string> paths;
  std::vector<const std::atomic<int> *> groups;
};

Registry &registry() {
  static Registry *r = new Registry; // never destroyed: the watcher thread may outlive main
  return *r;
}

std::string errnoText(int e) { return std::strerror(e); }

/// Remove a directory tree. The signal cleanup thread and the thread that made the tree may
/// remove it at the same time, and one remove_all stops at an entry the other removed first:
/// retry until it is gone.
void removeTree(const std::string &path) {
  std::error_code ec;
  for (int i = 0; i < 200; ++i) {
    fs::remove_all(path, ec);
    if (!fs::exists(fs::symlink_status(path, ec))) return;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
}

} // namespace

bool outputReplaceable(const std::string &path, std::string &error) {
  if (path == "-") return true;
  if (path.empty()) {
    error = "an empty output file name";
    return false;
  }
  struct stat st;
  if (::lstat(path.c_str(), &st) != 0) {
    if (errno == ENOENT) return true;
    error = "cannot write '" + path + "': " + errnoText(errno);
    return false;
  }
  if (S_ISREG(st.st_mode)) return true;
  error = "'" + path + "' exists and is not a regular file (" +
          (S_ISLNK(st.st_mode)   ? "a symbolic link"
           : S_ISDIR(st.st_mode) ? "a directory"
                                 : "a device, FIFO or socket") +
          "); refusing to replace it";
  return false;
}

bool checkOutputPath(const std::string &path, std::string &error) {
  if (path == "-") return true;
  OutputFile probe;
  return probe.open(path, error);
}

OutputFile::~OutputFile() { discard(); }

bool OutputFile::open(const std::string &path, std::string &error) {
  discard();
  if (!outputReplaceable(path, error)) return false;
  path_ = path;
  std::string tmpl = path + ".XXXXXX";
  if (!::mkdtemp(tmpl.data())) {
    error = "cannot write '" + path + "': " + errnoText(errno);
    return false;
  }
  dir_ = tmpl;
  registerTempPath(dir_);
  // The file inside keeps the last name component, for messages of tools that write it.
  std::string base = path.substr(path.rfind('/') == std::string::npos ? 0 : path.rfind('/') + 1);
  temp_ = dir_ + "/" + base;
  return true;
}

bool OutputFile::write(std::string_view data, std::string &error) {
  int fd = ::open(temp_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
  if (fd < 0) {
    error = "cannot write '" + path_ + "': " + errnoText(errno);
    return false;
  }
  const char *p = data.data();
  size_t n = data.size();
  while (n > 0) {
    ssize_t w = ::write(fd, p, n);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) {
      error = "cannot write '" + path_ + "': " + errnoText(w < 0 ? errno : ENOSPC);
      ::close(fd);
      return false;
    }
    p += w;
    n -= static_cast<size_t>(w);
  }
  if (::close(fd) != 0) {
    error = "cannot write '" + path_ + "': " + errnoText(errno);
    return false;
  }
  return true;
}

bool OutputFile::commit(std::string &error) {
  bool ok = outputReplaceable(path_, error);
  if (ok && std::rename(temp_.c_str(), path_.c_str()) != 0) {
    error = "cannot write '" + path_ + "': " + errnoText(errno);
    ok = false;
  }
  discard();
  return ok;
}

void OutputFile::discard() {
  if (dir_.empty()) return;
  removeTree(dir_);
  unregisterTempPath(dir_);
  dir_.clear();
  temp_.clear();
}

bool writeOutputFile(const std::string &path, std::string_view data, std::string &error) {
  if (path == "-") {
    if (std::fwrite(data.data(), 1, data.size(), stdout) != data.size() ||
        std::fflush(stdout) != 0) {
      error = "cannot write to standard output: " + errnoText(errno);
      return false;
    }
    return true;
  }
  OutputFile f;
  return f.open(path, error) && f.write(data, error) && f.commit(error);
}

void registerTempPath(const std::string &path) {
  Registry &r = registry();
  std::lock_guard g(r.mu);
  r.paths.push_back(path);
}

void unregisterTempPath(const std::string &path) {
  Registry &r = registry();
  std::lock_guard g(r.mu);
  auto it = std::find(r.paths.begin(), r.paths.end(), path);
  if (it != r.paths.end()) r.paths.erase(it);
}

void registerProcessGroup(const std::atomic<int> *pgid) {
  Registry &r = registry();
  std::lock_guard g(r.mu);
  r.groups.push_back(pgid);
}

void unregisterProcessGroup(const std::atomic<int> *pgid) {
  Registry &r = registry();
  std::lock_guard g(r.mu);
  r.groups.erase(std::remove(r.groups.begin(), r.groups.end(), pgid), r.groups.end());
}

void installSignalCleanup() {
  static std::once_flag once;
  std::call_once(once, [] {
    sigset_t set;
    sigemptyset(&set);
    sigaddset(&set, SIGINT);
    sigaddset(&set, SIGTERM);
    sigaddset(&set, SIGHUP);
    pthread_sigmask(SIG_BLOCK, &set, nullptr);
    // A plain thread (not a signal handler), so it may take the lock and remove directory trees.
    std::thread([set] {
      int sig = 0;
      while (sigwait(&set, &sig) != 0) {
      }
      Registry &r = registry();
      {
        std::lock_guard g(r.mu);
        for (const std::atomic<int> *pg : r.groups)
          if (int id = pg->load(); id > 0) ::kill(-id, SIGKILL); // our own child's group
        for (const std::string &p : r.paths) removeTree(p);
        r.paths.clear();
      }
      // Die of the same signal, as without the cleanup.
      std::signal(sig, SIG_DFL);
      sigset_t one;
      sigemptyset(&one);
      sigaddset(&one, sig);
      pthread_sigmask(SIG_UNBLOCK, &one, nullptr);
      ::raise(sig);
      std::_Exit(128 + sig);
    }).detach();
  });
}

} // namespace lj::formats

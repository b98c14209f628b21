// The linker half of `ladderjit compile`: write the program object, the ABI shim, tick.c and the
// public headers into a private temp directory, run the system C compiler on them (posix_spawnp,
// no shell), append the signed trailer and rename the result into place.
#include "jit/AotInternal.h"

#include "jit/AotSources.inc" // generated: kAbiH, kProgramH, kTickC, kShimC
#include "ladderjit/program.h"
#include "signing/AotSigned.h"

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <spawn.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>
#include <vector>

extern char **environ;

namespace lj::jit::detail {

namespace {

namespace fs = std::filesystem;

// The exports of program.h, all at version LJPROG_1; everything else becomes local.
constexpr const char *kVersionScript = "LJPROG_1 {\n"
                                       "  global:\n"
                                       "    ljprog_abi_version; ljprog_hash; ljprog_slice_count;\n"
                                       "    ljprog_state_size; ljprog_state_reset; ljprog_init;\n"
                                       "    ljprog_tick; ljprog_entries;\n"
                                       "  local: *;\n"
                                       "};\n";

bool writeFile(const fs::path &p, std::string_view bytes, std::string &error) {
  std::ofstream out(p, std::ios::binary | std::ios::trunc);
  if (!out || !out.write(bytes.data(), static_cast<std::streamsize>(bytes.size())) ||
      !out.flush()) {
    error = "cannot write '" + p.string() + "'";
    return false;
  }
  return true;
}

/// A mkdtemp directory removed with everything in it when the object dies.
class TempDir {
public:
  bool create(const std::string &in, std::string &error) {
    const char *base = std::getenv("TMPDIR");
    std::string templ =
        (in.empty() ? std::string(base && *base ? base : "/tmp") : in) + "/ladderjit-aot-XXXXXX";
    std::vector<char> buf(templ.begin(), templ.end());
    buf.push_back('\0');
    if (!mkdtemp(buf.data())) {
      error = "cannot create a temporary directory in '" + templ + "': " + std::strerror(errno);
      return false;
    }
    path_ = buf.data();
    return true;
  }
  ~TempDir() {
    std::error_code ec;
    if (!path_.empty()) fs::remove_all(path_, ec);
  }
  const fs::path &path() const { return path_; }

private:
  fs::path path_;
};

/// Run argv[0] (searched in PATH) in a process group of its own and wait at most `timeoutS`
/// seconds; then the whole group (the driver and the compiler, assembler and linker it started)
/// is killed. False with a message unless it exits with 0.
bool spawnAndWait(const std::vector<std::string> &args, unsigned timeoutS, std::atomic<int> *group,
                  std::string &error) {
  std::vector<char *> argv;
  for (const std::string &a : args) argv.push_back(const_cast<char *>(a.c_str()));
  argv.push_back(nullptr);
  posix_spawnattr_t attr;
  posix_spawnattr_init(&attr);
  // The caller may block SIGINT/SIGTERM for its cleanup thread (formats/OutputFile.h): the
  // compiler starts with no signal blocked.
  sigset_t none;
  sigemptyset(&none);
  posix_spawnattr_setsigmask(&attr, &none);
  posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETPGROUP | POSIX_SPAWN_SETSIGMASK);
  posix_spawnattr_setpgroup(&attr, 0);
  pid_t pid = 0;
  int rc = posix_spawnp(&pid, argv[0], nullptr, &attr, argv.data(), environ);
  posix_spawnattr_destroy(&attr);
  if (rc != 0) {
    error = "cannot run the C compiler '" + args[0] + "': " + std::strerror(rc) +
            " (set LADDERJIT_CC to a C compiler driver)";
    return false;
  }
  if (group) group->store(pid);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(timeoutS);
  int status = 0;
  bool timedOut = false;
  for (;;) {
    pid_t w = waitpid(pid, &status, WNOHANG);
    if (w == pid) break;
    if (w < 0 && errno != EINTR) {
      error = std::string("waitpid failed: ") + std::strerror(errno);
      kill(-pid, SIGKILL);
      if (group) group->store(0);
      return false;
    }
    if (std::chrono::steady_clock::now() >= deadline) {
      timedOut = true;
      kill(-pid, SIGKILL); // the group of our own child, made above
      while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
      }
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  if (group) group->store(0);
  if (timedOut) {
    error = "the C compiler '" + args[0] + "' did not finish within " + std::to_string(timeoutS) +
            " s; killed (raise the bound with --cc-timeout or LADDERJIT_CC_TIMEOUT)";
    return false;
  }
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return true;
  error = "the C compiler '" + args[0] + "' failed to link the shared object (" +
          (WIFEXITED(status) ? "exit status " + std::to_string(WEXITSTATUS(status))
                             : "killed by signal " + std::to_string(WTERMSIG(status))) +
          ")";
  return false;
}

} // namespace

bool linkSharedObject(std::string_view obj, const AotOptions &opts, uint32_t slices,
                      std::string &error) {
  const std::string &hash = opts.programHash, &output = opts.output;
  unsigned timeoutS = opts.ccTimeoutS;
  if (timeoutS == 0) {
    timeoutS = kDefaultCcTimeoutS;
    if (const char *env = std::getenv("LADDERJIT_CC_TIMEOUT"); env && *env) {
      if (!parseCcTimeout(env, timeoutS, error)) {
        error = "LADDERJIT_CC_TIMEOUT: " + error;
        return false;
      }
    }
  }
  TempDir dir;
  if (!dir.create(opts.tempDir, error)) return false;
  const fs::path d = dir.path();
  std::error_code ec;
  fs::create_directories(d / "include" / "ladderjit", ec);
  if (ec) {
    error = "cannot create '" + (d / "include").string() + "': " + ec.message();
    return false;
  }
  if (!writeFile(d / "include/ladderjit/abi.h", aot_src::kAbiH, error) ||
      !writeFile(d / "include/ladderjit/program.h", aot_src::kProgramH, error) ||
      !writeFile(d / "tick.c", aot_src::kTickC, error) ||
      !writeFile(d / "shim.c", aot_src::kShimC, error) || !writeFile(d / "program.o", obj, error) ||
      !writeFile(d / "ljprog.map", kVersionScript, error))
    return false;

  const char *cc = std::getenv("LADDERJIT_CC");
  const fs::path linked = d / "program.so";
  // -fvisibility=hidden keeps tick.c's functions out of the dynamic table; -z now / relro
  // resolve and protect everything at dlopen, so a missing libc symbol fails there, not mid-scan.
  std::vector<std::string> args = {cc && *cc ? cc : "cc",
                                   "-shared",
                                   "-fPIC",
                                   "-O2",
                                   "-std=c11",
                                   "-fvisibility=hidden",
                                   "-nostartfiles", // no crt objects: no constructors to run
                                   "-I" + (d / "include").string(),
                                   "-DLJPROG_HASH_VALUE=\"" + hash + "\"",
                                   "-DLJPROG_SLICES=" + std::to_string(slices) + "u",
                                   (d / "shim.c").string(),
                                   (d / "tick.c").string(),
                                   (d / "program.o").string(),
                                   "-Wl,--version-script=" + (d / "ljprog.map").string(),
                                   "-Wl,-z,noexecstack",
                                   "-Wl,-z,relro",
                                   "-Wl,-z,now",
                                   "-o",
                                   linked.string()};
  if (!spawnAndWait(args, timeoutS, opts.ccProcessGroup, error)) return false;

  std::ifstream in(linked, std::ios::binary);
  std::string image((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in.good() && !in.eof()) {
    error = "cannot read the linked object '" + linked.string() + "'";
    return false;
  }
  signing::AotMeta meta;
  meta.abi = LJPROG_ABI_VERSION;
  meta.program = hash;
  meta.source = opts.sourceHash.empty() ? hash : opts.sourceHash;
  meta.plc2Nvalue = opts.plc2Nvalue;
  meta.slices = slices;
  meta.stateSize = sizeof(lj_state);
  if (!signing::signImage(image, meta, *opts.signingKey, error)) return false;

  // Atomic replace: a host never sees a half-written .so at `output`. The temp file is new
  // (O_EXCL: nothing planted at its name is followed or written), mode 0666 less the umask.
  std::string tmp;
  int fd = -1;
  for (int n = 0; fd < 0 && n < 100; ++n) {
    tmp = output + ".tmp" + std::to_string(getpid()) + "-" + std::to_string(n);
    fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
    if (fd < 0 && errno != EEXIST) break;
  }
  if (fd < 0) {
    error = "cannot write '" + output + "': " + std::strerror(errno);
    return false;
  }
  bool wrote = true;
  for (size_t at = 0; wrote && at < image.size();) {
    ssize_t w = ::write(fd, image.data() + at, image.size() - at);
    if (w < 0 && errno == EINTR) continue;
    wrote = w > 0;
    if (wrote) at += static_cast<size_t>(w);
  }
  if (::close(fd) != 0) wrote = false;
  if (!wrote) {
    error = "cannot write '" + output + "': " + std::strerror(errno ? errno : ENOSPC);
    fs::remove(tmp, ec);
    return false;
  }
  if (std::rename(tmp.c_str(), output.c_str()) != 0) {
    error = "cannot write '" + output + "': " + std::strerror(errno);
    fs::remove(tmp, ec);
    return false;
  }
  return true;
}

} // namespace lj::jit::detail

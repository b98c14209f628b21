// The C baseline lane of `ladderjit bench --c-baseline` (docs/bench.md): gen/CTranslate.h's C,
// built by one system compiler into the bench's private directory under a time bound, and
// dlopen'ed. Only bench loads these files: they are never an engine of run or serve.
#include "tools/ladderjit/BenchCmd.h"

#include "gen/CTranslate.h"

#include <dlfcn.h>
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <fstream>
#include <thread>

extern char **environ;

namespace lj::cli::bench {

bool cBaselineSupports(const VerifiedProgram &prog, std::string &error) {
  return gen::cTranslatable(prog, error);
}

namespace {

/// Run `args` (no shell), stderr to `log`; kill it after `timeoutS` seconds.
bool runBounded(const std::vector<std::string> &args, const std::string &log, unsigned timeoutS,
                std::string &error) {
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, STDERR_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                   0600);
  posix_spawn_file_actions_addopen(&fa, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  std::vector<char *> argv;
  for (const std::string &a : args) argv.push_back(const_cast<char *>(a.c_str()));
  argv.push_back(nullptr);
  pid_t pid = 0;
  int rc = posix_spawn(&pid, argv[0], &fa, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&fa);
  if (rc != 0) {
    error = "cannot run " + args[0] + ": " + std::strerror(rc);
    return false;
  }
  auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(timeoutS);
  int status = 0;
  for (;;) {
    pid_t w = ::waitpid(pid, &status, WNOHANG);
    if (w == pid) break;
    if (w < 0 && errno != EINTR) {
      error = "waitpid: " + std::string(std::strerror(errno));
      return false;
    }
    if (std::chrono::steady_clock::now() > deadline) {
      ::kill(pid, SIGKILL); // our own child
      ::waitpid(pid, &status, 0);
      error = "did not finish within the time bound of " + std::to_string(timeoutS) +
              " s (--c-timeout); killed";
      return false;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    std::ifstream in(log);
    std::string first;
    std::getline(in, first);
    error = "failed (" + first + ")";
    return false;
  }
  return true;
}

} // namespace

bool buildCBaseline(const VerifiedProgram &prog, const CBuild &b, const std::string &dir,
                    unsigned timeoutS, Lane &lane, std::string &error) {
  using Clock = std::chrono::steady_clock;
  std::string base = b.compiler.substr(b.compiler.rfind('/') + 1);
  std::string name = base + b.level;
  std::string cPath = dir + "/baseline.c", so = dir + "/" + name + ".so";
  auto t0 = Clock::now();
  {
    std::ofstream out(cPath, std::ios::trunc);
    out << gen::translateToC(prog);
    if (!out) {
      error = "cannot write " + cPath;
      return false;
    }
  }
  double translateUs = std::chrono::duration<double, std::micro>(Clock::now() - t0).count();
  auto t1 = Clock::now();
  if (!runBounded({b.compiler, b.level, "-fPIC", "-shared", "-w", "-o", so, cPath},
                  dir + "/" + name + ".log", timeoutS, error))
    return false;
  double ccUs = std::chrono::duration<double, std::micro>(Clock::now() - t1).count();
  auto t2 = Clock::now();
  void *h = ::dlopen(so.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!h) {
    error = std::string("dlopen: ") + ::dlerror();
    return false;
  }
  lane.keepAlive = std::shared_ptr<void>(h, [](void *p) { ::dlclose(p); });
  lane.entries.ctx = nullptr;
  lane.entries.init = reinterpret_cast<lj_part_fn>(::dlsym(h, "ljc_init"));
  lane.entries.plc1 = reinterpret_cast<lj_part_fn>(::dlsym(h, "ljc_plc1"));
  lane.entries.plc2_slice = reinterpret_cast<lj_slice_fn>(::dlsym(h, "ljc_plc2_slice"));
  lane.entries.plc2_slice_count =
      prog.slices.empty() ? 1u : static_cast<uint32_t>(prog.slices.size());
  if (!lane.entries.init || !lane.entries.plc1 || !lane.entries.plc2_slice) {
    error = "the built object lacks its entries";
    return false;
  }
  lane.name = name;
  lane.engine = "c";
  lane.tier = b.level;
  lane.phases.lowerUs = translateUs; // translation to C
  lane.phases.codegenUs = ccUs;      // the whole compiler run (compile + link)
  lane.phases.loadUs = std::chrono::duration<double, std::micro>(Clock::now() - t2).count();
  lane.phases.totalUs = translateUs + ccUs + lane.phases.loadUs;
  struct stat st {};
  if (::stat(so.c_str(), &st) == 0) lane.phases.codeBytes = static_cast<uint64_t>(st.st_size);
  return true;
}

} // namespace lj::cli::bench

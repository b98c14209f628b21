// The linker half of `ladderjit compile`: write the program object, the ABI shim, tick.c and the
// public headers into a private temp directory, run the system C compiler on them (posix_spawnp,
// no shell), append the signed trailer and rename the result into place.
#include "jit/AotInternal.h"

#include "engines/AotSigned.h"
#include "jit/AotSources.inc" // generated: kAbiH, kProgramH, kTickC, kShimC
#include "ladderjit/program.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <spawn.h>
#include <sys/wait.h>
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
  bool create(std::string &error) {
    const char *base = std::getenv("TMPDIR");
    std::string templ = std::string(base && *base ? base : "/tmp") + "/ladderjit-aot-XXXXXX";
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

/// Run argv[0] (searched in PATH) and wait; false with a message unless it exits with 0.
bool spawnAndWait(const std::vector<std::string> &args, std::string &error) {
  std::vector<char *> argv;
  for (const std::string &a : args) argv.push_back(const_cast<char *>(a.c_str()));
  argv.push_back(nullptr);
  pid_t pid = 0;
  int rc = posix_spawnp(&pid, argv[0], nullptr, nullptr, argv.data(), environ);
  if (rc != 0) {
    error = "cannot run the C compiler '" + args[0] + "': " + std::strerror(rc) +
            " (set LADDERJIT_CC to a C compiler driver)";
    return false;
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) {
      error = std::string("waitpid failed: ") + std::strerror(errno);
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
  TempDir dir;
  if (!dir.create(error)) return false;
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
  if (!spawnAndWait(args, error)) return false;

  std::ifstream in(linked, std::ios::binary);
  std::string image((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (!in.good() && !in.eof()) {
    error = "cannot read the linked object '" + linked.string() + "'";
    return false;
  }
  io::AotMeta meta;
  meta.abi = LJPROG_ABI_VERSION;
  meta.program = hash;
  meta.source = opts.sourceHash.empty() ? hash : opts.sourceHash;
  meta.plc2Nvalue = opts.plc2Nvalue;
  meta.slices = slices;
  meta.stateSize = sizeof(lj_state);
  if (!io::signImage(image, meta, *opts.signingKey, error)) return false;

  // Atomic replace: a host never sees a half-written .so at `output`.
  std::string tmp = output + ".tmp" + std::to_string(getpid());
  if (!writeFile(tmp, image, error)) {
    error = "cannot write '" + output + "'";
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

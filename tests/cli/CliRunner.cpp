// Child-process runner for the CLI tests (posix_spawn, output redirected to scratch files).
#include "CliRunner.h"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

extern char **environ;

namespace lj::clitest {

namespace {

std::string &scratchPath() {
  static std::string dir;
  return dir;
}

// Removes the scratch directory after a run without failures; keeps it for inspection
// otherwise.
class ScratchCleanup : public ::testing::Environment {
public:
  void TearDown() override {
    if (!scratchPath().empty() && ::testing::UnitTest::GetInstance()->failed_test_count() == 0) {
      std::error_code ec;
      std::filesystem::remove_all(scratchPath(), ec);
    }
  }
};
[[maybe_unused]] ::testing::Environment *const kCleanup =
    ::testing::AddGlobalTestEnvironment(new ScratchCleanup);

} // namespace

std::string scratchDir() {
  std::string &dir = scratchPath();
  if (dir.empty()) {
    std::string tmpl = ::testing::TempDir() + "ladderjit-cli-XXXXXX";
    if (!mkdtemp(tmpl.data())) std::abort();
    dir = tmpl;
  }
  return dir;
}

std::string writeScratch(const std::string &name, const std::string &text) {
  std::string path = scratchDir() + "/" + name;
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

std::string slurp(const std::string &path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::string sourcePath(const std::string &rel) {
  return std::string(LADDERJIT_SOURCE_DIR) + "/" + rel;
}

CliResult runCli(const std::vector<std::string> &args) { return runBinary(LADDERJIT_BIN, args); }

CliResult runBinary(const std::string &binary, const std::vector<std::string> &args) {
  static int counter = 0;
  std::string base = scratchDir() + "/run" + std::to_string(++counter);
  std::string outPath = base + ".out", errPath = base + ".err";

  std::vector<std::string> argvStore;
  argvStore.push_back(binary);
  argvStore.insert(argvStore.end(), args.begin(), args.end());
  std::vector<char *> argv;
  for (std::string &a : argvStore) argv.push_back(a.data());
  argv.push_back(nullptr);

  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&fa, 1, outPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&fa, 2, errPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = 0;
  CliResult r;
  int rc = posix_spawn(&pid, argv[0], &fa, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&fa);
  if (rc != 0) {
    ADD_FAILURE() << "cannot start " << argv[0];
    return r;
  }
  int status = 0;
  waitpid(pid, &status, 0);
  if (WIFEXITED(status)) r.exitCode = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) r.signal = WTERMSIG(status);
  r.out = slurp(outPath);
  r.err = slurp(errPath);
  return r;
}

std::vector<std::string> lines(const std::string &text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) out.push_back(line);
  return out;
}

long long csvValue(const std::string &csv, long long tick, const std::string &col) {
  constexpr long long kMissing = -999999999;
  std::vector<std::string> rows = lines(csv);
  if (rows.empty()) {
    ADD_FAILURE() << "empty CSV output";
    return kMissing;
  }
  auto split = [](const std::string &row) {
    std::vector<std::string> cells;
    std::stringstream ss(row);
    std::string cell;
    while (std::getline(ss, cell, ',')) cells.push_back(cell);
    return cells;
  };
  std::vector<std::string> header = split(rows[0]);
  size_t c = 0;
  while (c < header.size() && header[c] != col) ++c;
  if (c == header.size()) {
    ADD_FAILURE() << "no column " << col << " in header " << rows[0];
    return kMissing;
  }
  for (size_t i = 1; i < rows.size(); ++i) {
    std::vector<std::string> cells = split(rows[i]);
    if (!cells.empty() && std::stoll(cells[0]) == tick && c < cells.size())
      return std::stoll(cells[c]);
  }
  ADD_FAILURE() << "no row for tick " << tick;
  return kMissing;
}

} // namespace lj::clitest

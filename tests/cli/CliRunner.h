// Runs the built `ladderjit` binary as a child process and captures its exit status, stdout
// and stderr, so the CLI tests check exactly what a user sees.
#pragma once

#include <string>
#include <vector>

namespace lj::clitest {

/// What one run of the binary produced.
struct CliResult {
  int exitCode = -1;    ///< exit status, -1 when the process did not exit normally
  int signal = 0;       ///< terminating signal (a crash), 0 when it exited
  std::string out, err; ///< captured stdout / stderr
};

/// Run `ladderjit args...` (no shell involved).
CliResult runCli(const std::vector<std::string> &args);

/// Run `binary args...` the same way (a copy of the driver in another directory).
CliResult runBinary(const std::string &binary, const std::vector<std::string> &args);

/// Absolute path of a file in the source tree (`examples/lathe_panel.stl`).
std::string sourcePath(const std::string &rel);

/// The whole content of a file (empty if it cannot be read).
std::string slurp(const std::string &path);

/// A fresh scratch directory for this test process, removed at exit unless a test failed (then
/// its files are left for inspection).
std::string scratchDir();

/// Write `text` to `scratchDir()/name` and return the path.
std::string writeScratch(const std::string &name, const std::string &text);

/// Split CSV/JSONL output into lines (no trailing empty line).
std::vector<std::string> lines(const std::string &text);

/// Value of column `col` in CSV row of `tick` (header row names the columns). Fails the
/// current test and returns a sentinel when the table has no such row or column.
long long csvValue(const std::string &csv, long long tick, const std::string &col);

} // namespace lj::clitest

// The subcommands of the `ladderjit` driver (CLI.md), one function each, plus the front-end
// loading they share. Each returns the process exit code.
#pragma once

#include "instructions/Program.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace lj::cli {

/// Exit codes (CLI.md): 0 success / clean, 1 program errors (or fuzz mismatch), 2 usage or I/O.
enum Exit : int { kOk = 0, kProgramErrors = 1, kUsage = 2 };

/// Print `ladderjit: error: <msg>` to stderr and return kUsage.
int usageError(const std::string &msg);

/// Read and verify PROGRAM; diagnostics go to stderr. On failure sets `exitCode` (1 for program
/// errors, 2 for an unreadable file) and returns nothing.
std::optional<VerifiedProgram> loadProgram(const std::string &path, int32_t plc2Nvalue,
                                           int &exitCode);

struct CheckArgs {
  std::string program;
  int32_t plc2Nvalue = 200;
  bool print = false; ///< dump the verified program (lj::printProgram) to stdout
};
int runCheck(const CheckArgs &a);

struct RunArgs {
  std::string program;
  std::string engine = "jit"; ///< interp | jit | aot:PATH
  uint64_t ticks = 1;
  uint64_t periodMs = 1;
  int32_t plc2Nvalue = 200;
  uint64_t maxBackwardSteps = 1000000; ///< watchdog limit per tick (DIALECT.md 4)
  std::vector<std::string> sets;       ///< ADDR=VALUE items
  std::string stimulus;                ///< file, empty = none
  std::vector<std::string> watch;      ///< comma lists as given
  std::string format = "csv";          ///< csv | jsonl
  std::string dump;                    ///< file ("-" = stdout), empty = none
  std::string params;                  ///< file, empty = none
};
int runRun(const RunArgs &a);

struct EmitArgs {
  std::string program;
  int optLevel = 2;
  int32_t plc2Nvalue = 200;
};
int runEmitLlvm(const EmitArgs &a);

struct FuzzArgs {
  uint64_t seed = 1;
  uint64_t programs = 1000;
  uint32_t ticks = 50;
};
int runFuzz(const FuzzArgs &a);

/// Whether this build contains the JIT / the fuzzer (their libraries may land later).
bool haveJit();
bool haveFuzz();

} // namespace lj::cli

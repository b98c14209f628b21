// The subcommands of the `ladderjit` driver (CLI.md), one function each, plus the front-end
// loading they share. Each returns the process exit code.
#pragma once

#include "ir/Engine.h"
#include "ir/Program.h"
#include "pipeline/ProgramFile.h"
#include "runtime/Server.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lj::cli {

/// Exit codes (CLI.md): 0 success / clean, 1 program errors (or fuzz mismatch), 2 usage or I/O.
enum Exit : int { kOk = 0, kProgramErrors = 1, kUsage = 2 };

/// Print `ladderjit: error: <msg>` to stderr and return kUsage.
int usageError(const std::string &msg);
/// Flush stdout; a write that failed turns `code` kOk into kUsage (with a message).
int checkStdout(int code);

/// PROGRAM as read: an STL file, or a plc.dit container (pipeline/ProgramFile.h).
using pipeline::effectiveNvalue;
using pipeline::programHashOf;
using pipeline::ProgramSource;

/// Read PROGRAM into `src`. An unreadable file or a bad container is an input error: prints
/// it, sets `exitCode` to 2 and returns false (docs/plc-dit.md "Exit codes").
bool readProgram(const std::string &path, ProgramSource &src, int &exitCode,
                 std::string_view dialect = {});

/// Verify a read PROGRAM (with its symbols, for a container); diagnostics go to stderr. On
/// failure sets `exitCode` to 1 and returns nothing.
std::optional<VerifiedProgram> loadProgram(const ProgramSource &src, int32_t plc2Nvalue,
                                           int &exitCode);

/// How a command that is not `check` reports the warnings of a program that verified.
enum class WarningReport {
  All,     ///< every diagnostic (check, and any program with errors)
  Summary, ///< one line: the count and the command that lists them (run, ladder, serve)
  None,    ///< --quiet: not even that line
};
/// loadProgram for run / ladder: errors are printed in full; warnings of a program that
/// verified as `report` says (warningSummary; `dialect`: the --dialect option given).
std::optional<VerifiedProgram> loadProgram(const ProgramSource &src, int32_t plc2Nvalue,
                                           int &exitCode, WarningReport report,
                                           std::string_view dialect);
/// The one line that stands for `count` verifier warnings of PROGRAM `path` outside `check`:
/// "ladderjit: PATH: N verifier warnings; `ladderjit check PATH` lists them" (with --dialect
/// NAME when `dialect` is given). Empty for count 0.
std::string warningSummary(const std::string &path, size_t count, std::string_view dialect = {});

struct CheckArgs {
  std::string dialect; ///< --dialect NAME (pipeline/Dialects.h), empty = by file name
  std::string program;
  int32_t plc2Nvalue = 200;
  bool plc2NvalueGiven = false; ///< --plc2-nvalue was on the command line
  bool print = false;           ///< dump the verified program (lj::printProgram) to stdout
};
int runCheck(const CheckArgs &a);

struct RunArgs {
  std::string dialect; ///< --dialect NAME (pipeline/Dialects.h), empty = by file name
  std::string program;
  std::string engine = "jit"; ///< interp | jit | aot:PATH
  uint64_t ticks = 1;
  uint64_t periodMs = 1;
  bool periodMsGiven = false; ///< --period-ms was on the command line (beats a plc.dit)
  int32_t plc2Nvalue = 200;
  bool plc2NvalueGiven = false;        ///< --plc2-nvalue was on the command line (beats a plc.dit)
  uint64_t maxBackwardSteps = 1000000; ///< watchdog limit per tick (DIALECT.md 4)
  std::vector<std::string> sets;       ///< ADDR=VALUE items
  std::string stimulus;                ///< file, empty = none
  std::vector<std::string> watch;      ///< comma lists as given
  std::string format = "csv";          ///< csv | jsonl
  std::string dump;                    ///< file ("-" = stdout), empty = none
  std::string params;                  ///< file, empty = none
  std::vector<std::string> trustKeys;  ///< --trust-key public keys, empty = the default key
  std::string tier = "direct";         ///< --tier direct | interp-first | interp-fast-opt
  std::string tierSwitchTicks;         ///< --tier-switch-tick N[,M]: switch exactly there
  std::string vcd;                     ///< --vcd FILE: the watch addresses as a VCD, empty = none
  bool vcdBits = false;                ///< --vcd-bits: elements as bit wires (docs/trace.md)
  bool quiet = false;                  ///< --quiet: no verifier-warning count line
};
int runRun(const RunArgs &a);

struct EmitArgs {
  std::string dialect; ///< --dialect NAME (pipeline/Dialects.h), empty = by file name
  std::string program;
  int optLevel = 2;
  int32_t plc2Nvalue = 200;
  bool plc2NvalueGiven = false;
};
int runEmitLlvm(const EmitArgs &a);

struct DitArgs {
  std::string dialect; ///< --dialect NAME (pipeline/Dialects.h), empty = by file name
  std::string program; ///< STL file
  std::string symbols; ///< symbols file, empty = none
  std::string params;  ///< P values file, empty = none
  int32_t plc2Nvalue = 200;
  uint64_t periodMs = 1;
  std::string output; ///< container path, "-" = stdout
};
/// `ladderjit dit`: write a plc.dit from an STL file, symbols and parameters (docs/plc-dit.md).
int runDit(const DitArgs &a);

struct CompileArgs {
  std::string dialect; ///< --dialect NAME (pipeline/Dialects.h), empty = by file name
  std::string program;
  std::string output;       ///< the .so to write
  std::string cpu = "host"; ///< host | generic
  int32_t plc2Nvalue = 200;
  bool plc2NvalueGiven = false; ///< --plc2-nvalue was on the command line (beats a plc.dit)
  std::string signKey;          ///< --sign-key private key, empty = the default key pair
  std::string ccTimeout;        ///< --cc-timeout SECONDS, empty = $LADDERJIT_CC_TIMEOUT or 120
};
/// `ladderjit compile`: build PROGRAM into a shared object with the C ABI (docs/aot.md).
int runCompile(const CompileArgs &a);

/// `--engine aot:PATH`: load the .so if a key of `trustKeys` (--trust-key; none = the default
/// public key) signed it and it was built from `src` with `plc2Nvalue`. Null with `error` set on
/// any problem (docs/aot.md "Loading", "Trust").
std::unique_ptr<Engine> loadAotEngine(const std::string &soPath, const ProgramSource &src,
                                      int32_t plc2Nvalue, const std::vector<std::string> &trustKeys,
                                      std::string &error);

struct KeygenArgs {
  std::string output; ///< DIR/NAME: writes NAME.key (private, 0600) and NAME.pub
};
/// `ladderjit keygen`: a new Ed25519 key pair for signing AOT .so files (docs/aot.md "Trust").
int runKeygen(const KeygenArgs &a);

struct FuzzArgs {
  std::string dialect; ///< --dialect NAME (pipeline/Dialects.h), empty = by file name
  uint64_t seed = 1;
  uint64_t programs = 1000;
  uint32_t ticks = 50;
  bool roundTrip = false; ///< each program against its ladder JSON round trip, on the interpreter
  bool switches = false;  ///< engine switches at random ticks against an unswitched interpreter
  bool trace = false;     ///< both engines traced, traces compared (ir/Trace.h)
  bool edit = false;      ///< editor grids against the grid evaluator (fuzz/EditFuzz.h)
};
int runFuzz(const FuzzArgs &a);

struct BenchArgs {
  std::string dialect; ///< --dialect NAME (pipeline/Dialects.h), empty = by file name
  std::string program;
  std::string engine = "all";  ///< interp | jit | aot | all
  std::string tier = "both";   ///< fast | opt | both (JIT; AOT is always the optimizing tier)
  uint64_t scans = 2000;       ///< timed full scans per engine
  std::string stimulus;        ///< file of '@TICK ADDR=VALUE' lines; empty = pseudo-random inputs
  std::string format = "text"; ///< text | json
  uint64_t seed = 1;           ///< pseudo-random inputs
  bool cache = false;          ///< compile through the object cache (default: cache off)
  bool cBaseline = false;      ///< also translate to C and build with gcc / clang
  bool trace = false;          ///< also time the traced builds of the live view (ir/Trace.h)
  uint32_t cTimeoutS = 300;    ///< time bound of one C compile
  int32_t plc2Nvalue = 200;
  bool plc2NvalueGiven = false;
  bool corpus = false;        ///< the shape corpus instead of PROGRAM (gen/ShapeCorpus.h)
  uint32_t rounds = 9;        ///< --corpus: rounds of --scans scans, median of round medians
  std::string shapes;         ///< --corpus: comma-separated shape names (empty: all)
  int32_t statements = 10000; ///< --corpus: statements per shape
  std::string keepPrograms;   ///< --corpus: directory to write the generated programs to
  bool quiet = false;         ///< --quiet: no verifier-warning count line
};
/// `ladderjit bench`: compile phases and scan times of PROGRAM per engine and tier
/// (docs/bench.md).
int runBench(const BenchArgs &a);

struct LadderArgs {
  std::string dialect; ///< --dialect NAME (pipeline/Dialects.h), empty = by file name
  std::string program;
  std::string format = "text"; ///< text | json | svg | html | layout
  std::string output;          ///< empty or "-": stdout
  int32_t plc2Nvalue = 200;
  bool plc2NvalueGiven = false;
  bool quiet = false; ///< --quiet: no verifier-warning count line
};
/// `ladderjit ladder`: the program as networks (docs/ladder-json.md).
int runLadder(const LadderArgs &a);

/// `serve`'s options: the Server's (runtime/Server.h), filled in by Main.cpp.
using ServeArgs = rt::ServerOptions;
/// CLOCK_MONOTONIC (steady_clock) ns at the start of main: serve's "start" for the time to the
/// first tick (docs/serve.md "Time to first tick").
int64_t mainStartNs();
/// `ladderjit serve`: the real-time runtime (docs/serve.md).
int runServe(const ServeArgs &a);

struct MonitorArgs {
  std::string control;           ///< socket path, empty = the only server in the runtime dir
  std::vector<std::string> args; ///< command and its arguments
  bool allowShrink = false;      ///< load: accept an empty program or one that lacks a part
};
/// `ladderjit monitor`: client of a running serve (docs/serve.md "Control").
int runMonitor(const MonitorArgs &a);

} // namespace lj::cli

// Pieces of `ladderjit bench` (docs/bench.md) shared by its files: one measured engine ("lane")
// and the C baseline (BenchCBaseline.cpp).
#pragma once

#include "ir/Engine.h"
#include "ir/Program.h"
#include "jit/Jit.h"
#include "tools/ladderjit/Commands.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace lj::cli::bench {

/// Compile phases of one lane, microseconds (0 = not applicable).
struct Phases {
  double lowerUs = 0, optimizeUs = 0, codegenUs = 0, linkUs = 0, cacheUs = 0, loadUs = 0;
  double totalUs = 0;
  uint64_t codeBytes = 0; ///< object bytes (JIT), .so bytes (AOT, C baseline)
  bool cacheHit = false;
};

/// One engine and tier whose scans are timed.
struct Lane {
  std::string name; ///< "interp", "jit-fast", "jit-opt", "aot", "gcc-O2", ...
  std::string engine, tier;
  std::unique_ptr<Engine> engine_; ///< null for the C baseline (entries only)
  std::shared_ptr<void> keepAlive; ///< the C baseline's dlopen handle
  lj_entries entries{};
  Phases phases;
  std::unique_ptr<lj_state> state;
  std::vector<double> scanNs;
  uint64_t faults = 0;
};

/// Scan-time statistics of one lane, ns.
struct Stats {
  double minNs = 0, medianNs = 0, p99Ns = 0, meanNs = 0;
};
Stats statsOf(std::vector<double> v);

/// Median scan time of lane A over lane B, named "A/B".
struct Ratio {
  std::string name;
  double value;
};
/// The ratios docs/bench.md lists, for the lanes present.
std::vector<Ratio> ratiosOf(const std::vector<Lane> &lanes, const std::vector<Stats> &st);

struct FrontTimes {
  double readUs = 0, parseUs = 0, verifyUs = 0;
};

/// The report on stdout, text or JSON; `notes` are printed as they are.
void printText(const BenchArgs &a, const VerifiedProgram &prog, const FrontTimes &ft,
               const std::vector<Lane> &lanes, const std::vector<Stats> &st,
               const std::vector<Ratio> &ratios, const std::vector<std::string> &notes);
void printJson(const BenchArgs &a, double overheadNs, const VerifiedProgram &prog,
               const FrontTimes &ft, const std::vector<Lane> &lanes, const std::vector<Stats> &st,
               const std::vector<Ratio> &ratios, const std::vector<std::string> &notes);

/// A C baseline build: one compiler at one -O level.
struct CBuild {
  std::string compiler; ///< executable name: gcc, clang, clang-19
  std::string level;    ///< "-O1" / "-O2"
};

/// Translate `prog` to C, build it with `b` into `dir` within `timeoutS` seconds and load it.
/// False with `error` naming what is not expressible, or what the compiler said.
bool buildCBaseline(const VerifiedProgram &prog, const CBuild &b, const std::string &dir,
                    unsigned timeoutS, Lane &lane, std::string &error);

/// Whether `prog` can be translated (every statement in the C baseline's subset); else `error`
/// names the first statement that cannot.
bool cBaselineSupports(const VerifiedProgram &prog, std::string &error);

/// What one measured program leaves: its lanes (lanes[0] the interpreter), their statistics
/// over all scans and, per lane, the median of every round. Not movable (the lanes' engines
/// refer to `prog`).
struct Measured {
  Measured() = default;
  Measured(const Measured &) = delete;
  Measured &operator=(const Measured &) = delete;
  std::optional<VerifiedProgram> prog;
  FrontTimes ft;
  std::vector<Lane> lanes;
  std::vector<Stats> st;
  std::vector<Ratio> ratios;
  std::vector<std::string> notes;
  std::vector<std::vector<double>> roundMedians; ///< parallel to lanes
  double overheadNs = 0;
};

/// Compile `a.program` on the lanes `a` asks for, run `rounds` rounds of `a.scans` scans and
/// check every final state against the interpreter's. kOk or the command's exit code (the
/// error already printed).
int measure(const BenchArgs &a, Measured &m, unsigned rounds);

/// `bench --corpus` (BenchCorpus.cpp): every shape of gen/ShapeCorpus.h on jit-opt, aot and
/// the C baseline, with the ratio to the best C setting per shape.
int runCorpus(const BenchArgs &a);

} // namespace lj::cli::bench

// Pieces of `ladderjit bench` (docs/bench.md) shared by its files: one measured engine ("lane")
// and the C baseline (BenchCBaseline.cpp).
#pragma once

#include "ir/Engine.h"
#include "ir/Program.h"
#include "jit/Jit.h"

#include <cstdint>
#include <memory>
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

} // namespace lj::cli::bench

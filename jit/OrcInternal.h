// What the files of jit/ that drive ORC share: the session's state, the thread count of a
// compile and the linking of a version's objects into a new JITDylib (jit/OrcSession.cpp).
#pragma once

#include "jit/Jit.h"
#include "jit/ObjectCache.h"

#include <llvm/ExecutionEngine/Orc/JITTargetMachineBuilder.h>
#include <llvm/ExecutionEngine/Orc/LLJIT.h>
#include <llvm/Support/MemoryBuffer.h>

#include <ctime>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <unordered_map>
#include <vector>

namespace lj::jit {

struct Session::Impl {
  Tier tier = Tier::Optimizing;
  std::unique_ptr<llvm::orc::LLJIT> jit;
  llvm::orc::JITDylib *runtime = nullptr;
  /// Settings of the tier's code generator; every compile thread makes its own TargetMachine
  /// from it (a TargetMachine is not safe to share between concurrent compiles).
  std::optional<llvm::orc::JITTargetMachineBuilder> jtmb;
  std::mutex mu; ///< guards nextVersion
  uint64_t nextVersion = 1;
  /// Session::enableIncremental: the in-memory leaf cache every compile of the session uses.
  std::shared_ptr<ObjectCache> leafCache;
  /// The leaf keys of the session's last incremental compile by their digest input (hashing
  /// every group of the 10k program with SHA-256 costs ~3 ms; a lookup of the same bytes a
  /// fraction of it). Only valid for `keyContext` (profile, tier, chunk size).
  std::mutex keyMu;
  std::string keyContext;
  std::unordered_map<std::string, std::string> leafKeys;
};

/// Threads a compile may use: opts.compileThreads, or with 0 the hardware's (at least 1).
inline size_t compileThreadCount(const JitOptions &opts) {
  if (opts.compileThreads > 0) return static_cast<size_t>(opts.compileThreads);
  return std::max<size_t>(std::thread::hardware_concurrency(), 1);
}

/// CPU time of the calling thread, in microseconds.
inline double threadCpuUs() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) * 1e6 + static_cast<double>(ts.tv_nsec) / 1e3;
}

/// Link `objs` into a new JITDylib of `self` and look up the entries. `t` holds the phases so
/// far (compile started at `t0`); linkUs and codegenUs are filled in and `t` copied to `times`.
std::unique_ptr<Engine> linkVersion(Session &self, Session::Impl &im,
                                    std::vector<std::unique_ptr<llvm::MemoryBuffer>> objs,
                                    const VerifiedProgram &prog, double t0, CompileTimes t,
                                    std::string &error, CompileTimes *times);

/// The incremental compile of Session::compile (jit/IncrementalCompile.cpp): one object per
/// leaf, each looked up in `cache` (may be null) under leafCacheKey and stored there when new.
std::unique_ptr<Engine> compileIncremental(Session &self, Session::Impl &im,
                                           const VerifiedProgram &prog, const JitOptions &opts,
                                           ObjectCache *cache, std::string &error,
                                           CompileTimes *times);

} // namespace lj::jit

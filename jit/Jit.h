// The ORC JIT facade (STYLE.md 3): compile a verified program to native scan functions.
// Nothing outside jit/ includes llvm/ExecutionEngine/Orc/*.
#pragma once

#include "ir/Engine.h"
#include "ir/Program.h"

#include <cstdint>
#include <memory>
#include <string>

namespace lj::jit {

class ObjectCache; // jit/ObjectCache.h
struct CompileTimes;

/// Compile tier: Fast = no IR passes + FastISel; Optimizing = a tailored InstCombine/SimplifyCFG
/// pipeline + SelectionDAG codegen at CodeGenOptLevel::Less (jit/Pipeline.cpp).
enum class Tier { Fast, Optimizing };

/// A whole build at the optimizing tier (not an incremental one: there a chunk is the group an
/// online change compiles again) and AOT emit consecutive chunks of a body with clean cuts into
/// one function up to these bounds (lowering::LowerOptions::mergeIr / mergeStores /
/// mergeIndexed; docs/BENCHMARKS.md "Shape corpus").
inline constexpr int32_t kOptMergeIr = 9000;
inline constexpr int32_t kOptMergeStores = 200;
inline constexpr int32_t kOptMergeIndexed = 16;

struct JitOptions {
  Tier tier = Tier::Optimizing;
  /// Statements per generated function for long bodies (0 = one function per body). Only cut
  /// where no logic-stack entry is live, so the result never depends on it.
  int32_t chunkStatements = 150;
  /// Threads compiling at once: the program is lowered into this many modules (contiguous groups
  /// of bodies of about equal size), each compiled to an object on its own thread and linked
  /// into the version's JITDylib. 1 = everything on the calling thread; 0 = one per hardware
  /// thread (std::thread::hardware_concurrency). The generated code is the same either way,
  /// apart from cross-module calls.
  int32_t compileThreads = 0;
  /// Fewer threads for smaller programs: each needs this many statements (a thread, a context
  /// and a TargetMachine cost about a millisecond). Tests set 1 to force partitioning.
  int32_t minStatementsPerThread = 500;
  /// Reuse objects of an identical earlier compile (checked before any IR is built) and store
  /// new ones; null = always compile. `ladderjit run` passes ObjectCache::fromEnvironment().
  std::shared_ptr<ObjectCache> cache = nullptr;
  /// Contacts compiled as forced constants (ir/Forces.h, docs/serve.md "Forcing").
  ContactForces forces{};
  /// Incremental compile (lowering/Incremental.h): every rung group (a chunk of a long body, or
  /// a short body) is its own object, looked up in `cache` under a key of its content and what
  /// it depends on (jit::leafCacheKey) and compiled only when missing; a small spine of entry
  /// and dispatch functions is compiled every time. `compileThreads` threads compile the
  /// missing groups. Same behaviour as a whole-program compile; one call per group more.
  bool incremental = false;
  /// Incremental only: rung groups missing from the cache (at the session's tier) are compiled
  /// at the fast tier (no IR passes, FastISel), which costs a few milliseconds per group instead
  /// of tens. For an online change: the new code runs at once, and a later compile of the same
  /// program without this option builds the optimized groups (CompileTimes::leavesQuick says
  /// how many that would replace). A group whose optimized object is cached is used as is.
  bool quickLeaves = false;
  /// Receives the phase times when the caller passes none (callers that reach the JIT through
  /// engines::makeEngine). Null: not reported.
  CompileTimes *times = nullptr;
  /// A traced build recording into this buffer (ir/Trace.h, lowering/Lower.h LowerOptions::trace);
  /// never cached (the address is baked into the code). Null: untraced, today's code.
  int32_t *trace = nullptr;
};

/// Wall-clock time of each compile phase, in microseconds. With several compile threads,
/// lower/optimize are the slowest thread's, codegen runs to the end of linking (so it includes
/// linkUs and cacheUs). For `ladderjit bench` (docs/bench.md).
struct CompileTimes {
  double lowerUs = 0, optimizeUs = 0, codegenUs = 0;
  double linkUs = 0;        ///< JITLink (adding the objects, resolving the entries); AOT: cc
  double cacheUs = 0;       ///< object cache lookup + store (0 without a cache)
  uint64_t objectBytes = 0; ///< size of the object file(s) linked
  bool cacheHit = false;    ///< the objects came from the cache (lower/optimize are then 0)
  double cpuUs = 0; ///< CPU time of lowering, optimizing and codegen over all threads (incremental:
                    ///< and of the link)
  uint32_t leaves = 0;         ///< incremental: distinct rung groups (leaf objects) linked
  uint32_t leavesCompiled = 0; ///< incremental: of them compiled now (the rest from the cache)
  uint32_t leavesQuick = 0;    ///< incremental: of them at the fast tier (JitOptions::quickLeaves)
  double keysUs = 0;           ///< incremental: the groups' cache keys (part of lowerUs)
  double spineUs = 0;          ///< incremental: the spine's code generation (0 when cached)
  bool spineCached = false;    ///< incremental: the spine's object came from the cache
};

/// Compile `prog` (which must outlive the engine) into an Engine. On failure returns null and
/// sets `error`. `times`, when given, receives the phase times.
std::unique_ptr<Engine> compile(const VerifiedProgram &prog, const JitOptions &opts,
                                std::string &error, CompileTimes *times = nullptr);

/// The LLVM IR the JIT would compile, after the given -O level (0..3).
bool emitLlvm(const VerifiedProgram &prog, int optLevel, std::string &out, std::string &error);

/// One ORC JIT instance of one tier holding any number of program versions, each in its own
/// JITDylib (STYLE.md 10). For hot reload: compile v2 while v1 keeps running, swap the entry
/// table at a tick boundary, then destroy v1's engine, which removes its JITDylib. Engines keep
/// their session alive. Safe to compile from several threads.
class Session : public std::enable_shared_from_this<Session> {
public:
  /// A new JIT for `tier`; null with `error` set when the host target is unusable.
  static std::shared_ptr<Session> create(Tier tier, std::string &error);
  ~Session();
  Session(const Session &) = delete;
  Session &operator=(const Session &) = delete;

  /// Compile `prog` as a new version in this session (same contract as jit::compile; the
  /// session's tier applies, `opts.tier` is ignored).
  std::unique_ptr<Engine> compile(const VerifiedProgram &prog, const JitOptions &opts,
                                  std::string &error, CompileTimes *times = nullptr);
  Tier tier() const;
  /// Every later compile of this session is incremental (JitOptions::incremental) with an
  /// in-memory leaf cache of the session's own, unless the options bring a cache: an online
  /// change that edits one rung recompiles that rung's group and links the rest from memory.
  void enableIncremental();

  struct Impl; ///< ORC state, defined in jit/OrcSession.cpp

private:
  explicit Session(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

} // namespace lj::jit

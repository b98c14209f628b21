// The JIT's object cache (docs/aot.md "Object cache"): compiled objects of a program, keyed by a
// SHA-256 over everything that decides the code, in memory and in a directory on disk. A
// damaged or foreign file is never trusted: it is ignored, counted and rewritten.
#pragma once

#include "ir/Forces.h"
#include "ir/Program.h"

#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace lj::jit {

/// A set of object files under one key; safe to use from several threads.
class ObjectCache {
public:
  /// A cache in `dir` (created, mode 0700, on first store); empty `dir` = in memory only.
  explicit ObjectCache(std::string dir);

  /// The cache the environment asks for: null when LADDERJIT_CACHE=off, else in
  /// $LADDERJIT_CACHE_DIR, $XDG_CACHE_HOME/ladderjit or $HOME/.cache/ladderjit (in memory only
  /// when none of them is set).
  static std::shared_ptr<ObjectCache> fromEnvironment();

  /// The objects stored under `key` (64 hex digits), from memory or disk. False on a miss,
  /// including a disk file that is damaged or holds another key (counted in `rejected`).
  bool lookup(const std::string &key, std::vector<std::string> &objects);

  /// Remember `objects` under `key`, in memory and (best effort, atomically) on disk.
  void store(const std::string &key, const std::vector<std::string_view> &objects);

  /// Path of the disk file of `key` (empty for a memory-only cache).
  std::string pathFor(const std::string &key) const;
  const std::string &dir() const { return dir_; }

  struct Stats {
    uint64_t hits = 0, misses = 0;
    uint64_t memoryHits = 0, diskHits = 0; ///< hits by tier
    uint64_t rejected = 0;                 ///< disk files ignored as damaged or foreign
    uint64_t stores = 0, writeErrors = 0;
  };
  Stats stats() const;
  /// Forget the in-memory copies (the next lookup reads the disk).
  void dropMemory();

private:
  std::string dir_;
  mutable std::mutex mu_;
  std::unordered_map<std::string, std::vector<std::string>> memory_;
  std::vector<std::string> order_; ///< memory keys, oldest first (eviction order)
  size_t memoryBytes_ = 0;
  Stats stats_;
};

/// What besides the program decides the object code of a JIT compile.
struct CacheKeyInputs {
  std::string triple, cpu, features; ///< the code generator's target
  int tier = 0;                      ///< jit::Tier
  int32_t chunkStatements = 0;
  uint32_t partitions = 1;
  ContactForces forces{}; ///< forced contacts compile to constants (ir/Forces.h)
};

/// The cache key of a compile: SHA-256 (64 hex digits) over a format tag, the ladderjit version,
/// the identity of the running executable (so any rebuild of ladderjit invalidates the cache),
/// the LLVM version, `in` and programDigest(prog).
std::string objectCacheKey(const VerifiedProgram &prog, const CacheKeyInputs &in);

/// The key of one leaf of an incremental compile (lowering/Incremental.h): SHA-256 over a format
/// tag, the build identity and LLVM version as objectCacheKey, the target and tier of `in`, its
/// chunk size (it decides how loops inside the leaf are outlined), the profile's name and the
/// leaf's own bytes (lower::leafDigestInput, which holds its forces). `in.partitions` and
/// `in.forces` are not read.
std::string leafCacheKey(const CacheKeyInputs &in, std::string_view profile,
                         std::string_view leafBytes);

/// The cache key of an incremental compile's spine: SHA-256 over a format tag, the build and
/// target identity of leafCacheKey, and the spine's IR as bitcode (lowering/Incremental.h names
/// its leaves by position, so the IR, and with it the object, is the same for every version
/// whose bodies are cut the same way; the IR decides the object completely).
std::string spineCacheKey(const CacheKeyInputs &in, std::string_view bitcode);

/// SHA-256 (64 hex digits) over every field of `prog` that the lowering reads (all but `file`).
std::string programDigest(const VerifiedProgram &prog);

} // namespace lj::jit

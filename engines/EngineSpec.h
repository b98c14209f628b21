// Building an Engine from its name, in one place: `interp | jit | aot:PATH.so` is parsed once
// into an EngineSpec, and makeEngine builds it for the CLI, serve, the fuzzer and the tests.
#pragma once

#include "engines/AotLoader.h"
#include "ir/Engine.h"
#include "ir/Program.h"
#include "ir/Status.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

namespace lj::jit {
class ObjectCache;
class Session;
struct CompileTimes;
} // namespace lj::jit

namespace lj::engines {

enum class EngineKind : uint8_t {
  Interp, ///< the reference interpreter (the oracle)
  Jit,    ///< native code through the ORC JIT (jit/Jit.h)
  Aot,    ///< a shared object built by `ladderjit compile` (docs/aot.md)
};

/// Which engine to build.
struct EngineSpec {
  EngineKind kind = EngineKind::Interp;
  /// Aot: the .so to load. Empty: build one from the program into the temp directory, load it
  /// (with every check) and unlink it, the whole `compile` + `run --engine aot:` path in one go.
  std::string soPath;
};

/// "interp", "jit" or "aot".
const char *engineKindName(EngineKind kind);

/// Parse the `--engine` value (CLI.md): `interp`, `jit` or `aot:PATH.so`. Errors are
/// InvalidArgument, worded for that option.
Result<EngineSpec> parseEngineSpec(std::string_view text);

/// How to build it; each field applies to one kind only.
struct EngineOptions {
  bool fastTier = false;                   ///< Jit: Tier::Fast instead of Tier::Optimizing
  std::shared_ptr<jit::ObjectCache> cache; ///< Jit without a session: reuse objects (null: never)
  /// Jit without a session and without `cache`: the cache the environment asks for
  /// (jit::ObjectCache::fromEnvironment, docs/aot.md "Object cache"), made with the engine.
  bool cacheFromEnvironment = false;
  /// Jit: compile as a new version in this session (serve keeps one for all versions; the
  /// session's tier applies). Null: a session of its own per engine.
  jit::Session *session = nullptr;
  /// Aot with a path: the program (and nvalue) the .so must have been built from
  /// (engines/AotLoader.h aotExpectOf). Required.
  std::optional<engines::AotExpect> aotExpect;
  /// Aot: the signers whose .so files load (docs/aot.md "Trust"). Required with a path; without
  /// one, the temp .so is signed with aotSigningKey, which this set must trust.
  const signing::TrustedKeys *aotTrust = nullptr;
  /// Aot without a path: the key that signs the temp .so. Null (and aotTrust null): a throwaway
  /// key pair made for this one build, trusted for this one load only.
  const signing::SigningKey *aotSigningKey = nullptr;
  /// Interp and Jit: contacts built as forced (ir/Forces.h, docs/serve.md "Forcing"). Aot
  /// refuses a non-empty set (a prebuilt .so cannot be changed).
  ContactForces forces{};
  /// Interp and Jit: a traced build recording into this buffer of traceLayout(prog).words words
  /// (ir/Trace.h), which must outlive the engine. Aot refuses it (a .so is never traced).
  int32_t *trace = nullptr;
  /// Jit in an incremental session: compile the rung groups missing from its cache at the fast
  /// tier (jit::JitOptions::quickLeaves; serve's online change), and report the phase times.
  bool quickLeaves = false;
  jit::CompileTimes *times = nullptr;
};

/// Build the engine for `prog`, which must outlive it. EngineFailed with the JIT's or the
/// loader's message (the loader's names the file) when it cannot be built.
Result<std::unique_ptr<Engine>> makeEngine(const EngineSpec &spec, const VerifiedProgram &prog,
                                           const EngineOptions &opts = {});

} // namespace lj::engines

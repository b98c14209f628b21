// Ahead-of-time build (docs/aot.md): a verified program becomes a shared object exporting the
// C ABI of runtime_abi/include/ladderjit/program.h. Same lowering and optimizing pipeline as the
// JIT; the system C compiler (`cc`, or $LADDERJIT_CC) links it.
#pragma once

#include "ir/Program.h"

#include <atomic>
#include <charconv>
#include <cstdint>
#include <string>

namespace lj::signing {
class SigningKey;
}

namespace lj::jit {

struct CompileTimes; // jit/Jit.h

struct AotOptions {
  std::string output;      ///< path of the .so to write (replaced atomically)
  std::string programHash; ///< what ljprog_hash() returns: "sha256:" + 64 lowercase hex digits
  std::string
      sourceHash; ///< the program without the nvalue (engines::sourceHash); empty = programHash
  int32_t plc2Nvalue = 0; ///< recorded in the signed trailer (the slicing is in `prog`)
  /// Signs the trailer (docs/aot.md "Trust"); required. Not owned.
  const signing::SigningKey *signingKey = nullptr;
  /// false: the host CPU and its features (fastest, may not run elsewhere); true: the portable
  /// baseline of the architecture (x86-64 without extensions).
  bool genericCpu = false;
  int32_t chunkStatements = 150; ///< as JitOptions::chunkStatements
  /// When given, receives the phase times (codegen = the object; link = the C compiler's link,
  /// signing and the atomic rename) and the object's size. Not owned.
  CompileTimes *times = nullptr;
  /// Seconds the C compiler may take before its process group is killed (docs/aot.md "Time
  /// bound"); 0: $LADDERJIT_CC_TIMEOUT, else kDefaultCcTimeoutS.
  unsigned ccTimeoutS = 0;
  /// Where the linker makes its private temporary directory; empty: $TMPDIR, else /tmp.
  std::string tempDir;
  /// When given, holds the C compiler's process group id while it runs (0 otherwise), so a
  /// signal handler of the caller can kill it (formats/OutputFile.h). Not owned.
  std::atomic<int> *ccProcessGroup = nullptr;
};

/// The C compiler's default time bound in seconds (`compile --cc-timeout`, LADDERJIT_CC_TIMEOUT).
inline constexpr unsigned kDefaultCcTimeoutS = 120;
/// The largest time bound accepted, in seconds (one day).
inline constexpr unsigned kMaxCcTimeoutS = 86400;
/// Parse a time bound in seconds (1..kMaxCcTimeoutS); false with `error` naming the value.
inline bool parseCcTimeout(const std::string &text, unsigned &seconds, std::string &error) {
  unsigned long long v = 0;
  auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size() || v < 1 ||
      v > kMaxCcTimeoutS) {
    error = "expected 1.." + std::to_string(kMaxCcTimeoutS) + " seconds, got '" + text + "'";
    return false;
  }
  seconds = static_cast<unsigned>(v);
  return true;
}

/// Compile `prog` into a shared object at `opts.output`. On failure returns false, sets `error`
/// and leaves no output file behind. Spawns the C compiler without a shell.
bool compileSharedObject(const VerifiedProgram &prog, const AotOptions &opts, std::string &error);

/// Whether `hash` has the form ljprog_hash() promises ("sha256:" + 64 lowercase hex digits).
bool isProgramHash(const std::string &hash);

} // namespace lj::jit

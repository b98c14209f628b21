// The ORC JIT facade (STYLE.md 3): compile a verified program to native scan functions.
// Nothing outside jit/ includes llvm/ExecutionEngine/Orc/*.
#pragma once

#include "instructions/Engine.h"
#include "instructions/Program.h"

#include <memory>
#include <string>

namespace lj::jit {

/// Compile tier: Fast = IR O0 + FastISel; Optimizing = O2 pipeline + full codegen.
enum class Tier { Fast, Optimizing };

struct JitOptions {
  Tier tier = Tier::Optimizing;
};

/// Wall-clock time of each compile phase, in microseconds.
struct CompileTimes {
  double lowerUs = 0, optimizeUs = 0, codegenUs = 0;
};

/// Compile `prog` (which must outlive the engine) into an Engine. On failure returns null and
/// sets `error`. `times`, when given, receives the phase times.
std::unique_ptr<Engine> compile(const VerifiedProgram &prog, const JitOptions &opts,
                                std::string &error, CompileTimes *times = nullptr);

/// The LLVM IR the JIT would compile, after the given -O level (0..3).
bool emitLlvm(const VerifiedProgram &prog, int optLevel, std::string &out, std::string &error);

} // namespace lj::jit

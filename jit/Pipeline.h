// Shared JIT plumbing below the facade: one-time native target setup, the host target machine
// and the IR optimization pipelines of both tiers.
#pragma once

#include <llvm/IR/Module.h>
#include <llvm/Support/CodeGen.h>
#include <llvm/Support/Error.h>
#include <llvm/Target/TargetMachine.h>

#include <memory>

namespace lj::lower {
struct LowerOptions;
}

namespace lj::jit {

/// Initialize the native target, asm printer and parser once per process (thread-safe).
void initNativeTarget();

/// A TargetMachine for the host CPU and features at codegen level `level`.
llvm::Expected<std::unique_ptr<llvm::TargetMachine>> hostTargetMachine(llvm::CodeGenOptLevel level);

/// Optimize `m` for -O`level`: 0 = none (the fast tier), 2 = the optimizing tier's tailored
/// function pipeline, 1 and 3 = LLVM's standard O1 / O3 (for comparison dumps only).
/// `tm` supplies the cost model.
void optimizeModule(llvm::Module &m, int level, llvm::TargetMachine *tm);

/// Sets `lo`'s chunk-merge bounds as a whole optimizing build uses them (jit/Jit.h kOptMerge*).
void mergeChunksAsOptimizingBuild(lower::LowerOptions &lo);

/// Monotonic time in microseconds, for CompileTimes.
double nowUs();

} // namespace lj::jit

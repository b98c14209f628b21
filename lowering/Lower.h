// Public entry of the lowering stage: a VerifiedProgram becomes one llvm::Module whose entry
// functions have the signatures of runtime_abi's lj_part_fn / lj_slice_fn (STYLE.md 5).
#pragma once

#include "instructions/Program.h"

#include <llvm/IR/DataLayout.h>
#include <llvm/IR/LLVMContext.h>
#include <llvm/IR/Module.h>
#include <llvm/Support/Error.h>

#include <memory>
#include <string>

namespace lj::lower {

/// Names of the entry functions in every lowered module.
inline constexpr const char *kInitSymbol = "lj_init"; ///< uint32_t(void *ctx, lj_state *)
inline constexpr const char *kPlc1Symbol = "lj_plc1"; ///< uint32_t(void *ctx, lj_state *)
inline constexpr const char *kPlc2Symbol = "lj_plc2"; ///< uint32_t(void *, lj_state *, uint32_t)

struct LowerOptions {
  /// Target statement count of one generated function for part, slice and subroutine bodies;
  /// bodies are cut only where no stack entry is live (0 = never cut). Keeps compile time linear.
  int32_t chunkStatements = 150;
  /// Name the IR values after the addresses they hold (readable dumps; costs compile time).
  bool readableNames = true;
};

/// Lower `prog` for a target with `dl` / `triple`. Fails (never crashes) if the program
/// contradicts the facts the verifier promised (a front-end bug) or the ABI layout mismatches.
llvm::Expected<std::unique_ptr<llvm::Module>>
lowerProgram(const VerifiedProgram &prog, llvm::LLVMContext &ctx, const llvm::DataLayout &dl,
             const std::string &triple, const LowerOptions &opts = {});

} // namespace lj::lower

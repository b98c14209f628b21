// Public entry of the lowering stage: a VerifiedProgram becomes one llvm::Module whose entry
// functions have the signatures of runtime_abi's lj_part_fn / lj_slice_fn (STYLE.md 5).
#pragma once

#include "ir/Forces.h"
#include "ir/Program.h"

#include <llvm/IR/DataLayout.h>
#include <llvm/IR/LLVMContext.h>
#include <llvm/IR/Module.h>
#include <llvm/Support/Error.h>

#include <memory>
#include <string>
#include <vector>

namespace lj::lower {

/// Names of the entry functions in every lowered module.
inline constexpr const char *kInitSymbol = "lj_init"; ///< uint32_t(void *ctx, lj_state *)
inline constexpr const char *kPlc1Symbol = "lj_plc1"; ///< uint32_t(void *ctx, lj_state *)
inline constexpr const char *kPlc2Symbol = "lj_plc2"; ///< uint32_t(void *, lj_state *, uint32_t)

struct LowerOptions {
  /// Target statement count of one generated function for part, slice and subroutine bodies;
  /// bodies are cut only where no stack entry is live (0 = never cut). Keeps compile time linear.
  int32_t chunkStatements = 150;
  /// Whole builds at the optimizing tier: a body cut into chunks (not inside JMP spans) has
  /// consecutive chunks emitted into one function, through one emitter whose image cache keeps
  /// field values from rung to rung, until a carried cut or until the function holds
  /// `mergeIr` IR instructions, `mergeStores` stores or `mergeIndexed` loads and stores at
  /// addresses computed at run time (0 = one function per chunk). Across fewer function
  /// boundaries the dense image bytes of a program are loaded and stored once per function
  /// instead of once per chunk (docs/BENCHMARKS.md "Shape corpus"); the store and indexed
  /// bounds keep out what makes optimization and code generation grow faster than linearly
  /// in a function: long chains of neighbouring stores (edge memories) and accesses whose
  /// address is unknown until run time (table instructions), which every other access must
  /// be ordered against.
  int32_t mergeIr = 0;
  int32_t mergeStores = 0;
  int32_t mergeIndexed = 0;
  /// Name the IR values after the addresses they hold (readable dumps; costs compile time).
  bool readableNames = true;
  /// Split the program into `partitions` modules compiled independently (in parallel): this
  /// module defines only the bodies of partition `partition` and declares the functions of the
  /// others it calls. Subroutine and slice functions then get external linkage so the modules
  /// link together; the entry symbols keep their names in whichever module defines them.
  uint32_t partitions = 1;
  uint32_t partition = 0;
  /// Contacts compiled as forced (ir/Forces.h): each conducts its constant. Null or empty: none
  /// (the code is the same as a build without forces). Must outlive lowerProgram.
  const ContactForces *forces = nullptr;
  /// A traced build (ir/Trace.h): the statements store their trace words into this buffer of
  /// traceLayout(prog).words int32 words, its address baked into the code. Null: no trace code
  /// at all (the default; an AOT .so is always untraced). Must outlive the compiled code.
  int32_t *trace = nullptr;
};

/// Which of `partitions` modules defines the body of each top-level function, in the order
/// subroutines, init, PLC1, PLC2 slices (the lj_plc2 switch is always in partition 0): contiguous
/// groups of about equal statement counts, so parallel compiles take about the same time.
std::vector<uint32_t> planPartitions(const VerifiedProgram &prog, uint32_t partitions);

/// Lower `prog` for a target with `dl` / `triple`. Fails (never crashes) if the program
/// contradicts the facts the verifier promised (a front-end bug) or the ABI layout mismatches.
llvm::Expected<std::unique_ptr<llvm::Module>>
lowerProgram(const VerifiedProgram &prog, llvm::LLVMContext &ctx, const llvm::DataLayout &dl,
             const std::string &triple, const LowerOptions &opts = {});

} // namespace lj::lower

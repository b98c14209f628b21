// Incremental lowering (docs/architecture.md "Incremental compile"): the program's code as leaf
// functions, each lowered into a module of its own so the JIT can compile, cache and link it by
// itself, plus a spine module (entries, PLC2 slice switch, subroutine functions, chunk
// dispatchers) that calls the leaves by symbol. A leaf is one chunk of a long body or a whole
// short body; what decides its code is exactly leafDigestInput().
#pragma once

#include "ir/Program.h"
#include "lowering/Lower.h"

#include <llvm/IR/Module.h>
#include <llvm/Support/Error.h>

#include <functional>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

namespace lj::lower {

/// One chunk function of a long body. A carried cut hands live ST/MS entries to the next chunk
/// through the body's carry buffer (ST position k at byte k, MS position k at byte msBase + k):
/// the chunk loads positions [stLoad, depth) / [msLoad, msDepth) on entry and stores
/// [stStore, depth) / [msStore, msDepth) at its end (-1: none). The ranges are the positions the
/// chunk touches, so their size is bounded by its statement count, not by the stack depth.
struct ChunkPlan {
  StmtRange r;
  bool carriedIn = false, carriedOut = false;
  /// The body has cuts inside JMP spans: a JMP to a label of another chunk (which then starts
  /// with that label) returns kStatusJump + the chunk's index to the body's dispatcher.
  bool jumps = false;
  int32_t stLoad = -1, msLoad = -1, stStore = -1, msStore = -1;
};

/// Label statement index -> index of the chunk of its body that starts with it.
using LabelChunks = std::unordered_map<int32_t, uint32_t>;

/// One leaf function: `i32 (ptr s)`, or `i32 (ptr s, ptr carry)` when `carried`.
struct Leaf {
  StmtRange r;
  int32_t deadDepth = 0;   ///< ST entries on entry that are never read (they hold 0)
  uint32_t retnStatus = 0; ///< what a taken RETN returns (FunctionEmitter)
  bool chunk = false;      ///< a chunk of a cut body (`plan` applies), else a whole body
  ChunkPlan plan;
  bool carried = false; ///< the body has carried cuts: the leaf takes the carry buffer
  int32_t msBase = 0;   ///< MS offset in the carry buffer
  std::shared_ptr<const LabelChunks> labelChunk; ///< bodies with ChunkPlan::jumps
};

/// The bytes that decide a leaf's object code besides the target, tier, chunk size, profile and
/// build: its statements with their operands and verifier facts, positions relative to the leaf
/// (a jump or loop inside it), the callee's subroutine number (a CALL), the chunk a jump out of
/// it goes on at, edge / timer / counter / pulse slots as assigned (they are absolute state
/// offsets), the forced contacts, and the leaf's frame (dead depth, RETN status, chunk plan,
/// carry layout). Source lines, statement ids and symbols are not in it: they do not change the
/// code. `forced`: forceTable(prog, forces) (empty: nothing forced).
std::string leafDigestInput(const VerifiedProgram &prog, const Leaf &leaf,
                            const std::vector<int8_t> &forced);

/// Called once per leaf in program order while the spine is lowered; returns the symbol the
/// spine calls it by (equal symbols must mean equal code: the JIT names leaves by their key).
using LeafNamer = std::function<std::string(const Leaf &)>;

/// The spine of `prog` (opts.partitions must be 1): lj_init, lj_plc1, lj_plc2 and the slice
/// functions, the subroutine functions (external, the leaves call them) and the dispatchers of
/// cut bodies, with every leaf declared as an external function named by `namer`.
llvm::Expected<std::unique_ptr<llvm::Module>>
lowerSpine(const VerifiedProgram &prog, llvm::LLVMContext &ctx, const llvm::DataLayout &dl,
           const std::string &triple, const LowerOptions &opts, const LeafNamer &namer);

/// `leaf` as a module defining the external function `symbol` (and the loop bodies it
/// outlines, internal), declaring the subroutine functions it calls.
llvm::Expected<std::unique_ptr<llvm::Module>>
lowerLeaf(const VerifiedProgram &prog, const Leaf &leaf, const std::string &symbol,
          llvm::LLVMContext &ctx, const llvm::DataLayout &dl, const std::string &triple,
          const LowerOptions &opts);

} // namespace lj::lower

// Lowers a run of statements into one LLVM function. The ST and MS stacks exist only at compile
// time (vectors of i1 SSA values); state fields go through a per-block ImageCache.
#pragma once

#include "instructions/Program.h"
#include "lowering/AbiTypes.h"
#include "lowering/ImageCache.h"
#include "lowering/Lower.h"

#include <llvm/Analysis/InstSimplifyFolder.h>
#include <llvm/IR/Function.h>
#include <llvm/IR/IRBuilder.h>
#include <llvm/IR/Module.h>

#include <unordered_map>
#include <vector>

namespace lj::lower {

/// Module-wide facts shared by every function emitter.
struct ModuleContext {
  const VerifiedProgram &prog;
  llvm::Module &mod;
  StateLayout layout;
  LowerOptions opts;
  std::vector<llvm::Function *> subFns; ///< parallel to prog.subs
};

/// Status a body chunk of a subroutine returns when a RETN fired (never seen by the host).
inline constexpr uint32_t kStatusReturn = 0x80000000u;

/// Emits statements into `fn`, whose state pointer is `state`. Usage: emitRange, then finish.
class FunctionEmitter {
public:
  /// `retnStatus`: what a taken RETN returns from `fn` (0 in a subroutine's own function,
  /// kStatusReturn in one of its chunks).
  FunctionEmitter(ModuleContext &mc, llvm::Function *fn, llvm::Value *state, uint32_t retnStatus);

  /// Lower statements [r.begin, r.end), entering with `deadDepth` ST entries that are never read
  /// (they hold 0) and an empty MS.
  llvm::Error emitRange(StmtRange r, int32_t deadDepth);
  /// Store the cached state and return LJ_FAULT_NONE; checks every jump target was placed.
  llvm::Error finish();

private:
  // EmitFlow.cpp: dispatch and control flow.
  llvm::Error emitStmt(int32_t i);
  llvm::Error emitJmp(int32_t i);
  void emitLabel(int32_t i);
  void emitLoop(int32_t i);
  llvm::Error emitNext(int32_t i);
  llvm::Error emitCall(int32_t i);
  void emitRetn();
  /// `if (++steps > max_backward_steps) return LJ_FAULT_WATCHDOG;` then branch to `next`.
  void watchdogStep(llvm::BasicBlock *next);
  llvm::BasicBlock *labelBlock(int32_t lblIndex);
  llvm::BasicBlock *newBlock(const char *name);
  /// Flush the cache, branch to `bb` unless the current block already ended, continue there.
  void continueIn(llvm::BasicBlock *bb);
  llvm::Error fail(int32_t i, const std::string &what) const;

  // EmitBasic.cpp: operands, contacts, coils, stack instructions.
  llvm::Value *readBit(const Operand &op);
  llvm::Value *readInt(const Operand &op);
  /// Write the low bits of `v` (i32) into register `op`; only when `en` is 1 if given.
  void writeInt(const Operand &op, llvm::Value *v, llvm::Value *en);
  /// Edge memory of instance `slot`: returns {rise, fall} of `cur` and stores m := cur.
  std::pair<llvm::Value *, llvm::Value *> edge(int32_t slot, llvm::Value *cur);
  llvm::Error emitBasic(int32_t i);
  llvm::Error emitCoil(int32_t i);

  // EmitBlocks.cpp: function blocks.
  llvm::Error emitBlock(int32_t i);
  /// EN of a single-input block: ST0, or 1 when ST is empty.
  llvm::Value *enable() const;
  /// Output of a single-input block: replaces ST0, or is pushed when ST was empty.
  void setOutput(llvm::Value *out);
  void emitMath(const Stmt &s);
  void emitCompare(const Stmt &s);
  llvm::Error emitCounter(int32_t i);
  llvm::Error emitTimer(int32_t i);
  llvm::Error emitPulse(int32_t i);

  llvm::Value *notV(llvm::Value *v) { return b_.CreateNot(v); }
  /// `c ? a : b` on i1 values as and/or: FastISel cannot select an i1 `select` and would hand
  /// the rest of the block to SelectionDAG (the fast tier's compile time).
  llvm::Value *selectBit(llvm::Value *c, llvm::Value *a, llvm::Value *b) {
    return b_.CreateOr(b_.CreateAnd(c, a), b_.CreateAnd(notV(c), b));
  }

  ModuleContext &mc_;
  const VerifiedProgram &prog_;
  llvm::Function *fn_;
  /// InstSimplifyFolder folds `and i1 true, x`, `select true, a, b`... as they are built, so
  /// even -O0 IR has no trivially dead logic.
  llvm::IRBuilder<llvm::InstSimplifyFolder> b_;
  llvm::Value *state_;
  ImageCache cache_;
  uint32_t retnStatus_;
  std::vector<llvm::Value *> st_;                          ///< back() is ST0
  std::vector<llvm::Value *> ms_;                          ///< back() is top(MS)
  std::unordered_map<int32_t, llvm::BasicBlock *> labels_; ///< LBL statement -> its block
  struct Loop {
    int32_t loopIndex;
    llvm::BasicBlock *header;
    llvm::PHINode *remaining;
    llvm::BasicBlock *exit;
  };
  std::vector<Loop> loops_;
  llvm::BasicBlock *abort_ = nullptr; ///< `ret LJ_FAULT_WATCHDOG`, created on first use
};

/// Split [r.begin, r.end) into consecutive ranges of about `target` statements. Cuts are placed
/// only before statements where no ST entry is live (read later before a stack reset), MS is
/// empty, and no loop body or JMP..LBL span crosses the cut.
std::vector<StmtRange> planChunks(const VerifiedProgram &p, StmtRange r, int32_t target);

} // namespace lj::lower

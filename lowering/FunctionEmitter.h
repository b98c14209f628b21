// Lowers a run of statements into one LLVM function. The ST and MS stacks exist only at compile
// time (vectors of i1 SSA values); state fields go through a per-block ImageCache.
#pragma once

#include "ir/CncTable.h"
#include "ir/Profile.h"
#include "ir/Program.h"
#include "ir/Trace.h"
#include "lowering/AbiTypes.h"
#include "lowering/ImageCache.h"
#include "lowering/Incremental.h"
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
  /// Loop bodies outlined into their own functions, waiting to be lowered (LowerProgram.cpp
  /// lowers them after the body that calls them: no recursion, however deep the nesting).
  struct Outlined {
    llvm::Function *fn;
    StmtRange body;
  };
  std::vector<Outlined> pendingLoops;
  /// weightBefore[i]: bodyWeight of statements [0, i) (prefix sums: O(1) loop sizes).
  std::vector<int64_t> weightBefore;
  /// forceTable(prog, *opts.forces): -1 / 0 / 1 per statement, empty when nothing is forced.
  std::vector<int8_t> forced;
  /// traceLayout(prog) when opts.trace is set (EmitTrace.cpp), else empty.
  TraceLayout traceAt;
};

/// An internal `i32 (ptr s)` function for a chunk or an outlined loop body (LowerProgram.cpp);
/// `carried`: `i32 (ptr s, ptr carry)` for a chunk of a body with carried cuts.
llvm::Function *makeBodyFunction(ModuleContext &mc, const std::string &name, bool carried);

/// Where a chunk finds the carry buffer, and (bodies with ChunkPlan::jumps) which chunk starts
/// at each jumped-to label.
struct CarryBuffer {
  llvm::Value *buf = nullptr;
  int32_t msBase = 0;
  const LabelChunks *labelChunk = nullptr;
};

/// Status a body chunk of a subroutine returns when a RETN fired (never seen by the host).
inline constexpr uint32_t kStatusReturn = 0x80000000u;
/// Status kStatusJump + k: a chunk's JMP goes on at chunk k of the same body (never seen by the
/// host either; chunk indices stay far below 2^30).
inline constexpr uint32_t kStatusJump = 0x40000000u;
/// Status kStatusJumpOut + n: a JumpOut (FANUC JMPC) to label n of the sliced part was taken; it
/// passes up through every subroutine until the CALL in the sliced part that goes on at label n
/// (never seen by the host: the verifier keeps that CALL and its label in one slice).
inline constexpr uint32_t kStatusJumpOut = 0x20000000u;

/// Emits statements into `fn`, whose state pointer is `state`. Usage: emitRange, then finish.
class FunctionEmitter {
public:
  /// `retnStatus`: what a taken RETN returns from `fn` (0 in a subroutine's own function,
  /// kStatusReturn in one of its chunks).
  FunctionEmitter(ModuleContext &mc, llvm::Function *fn, llvm::Value *state, uint32_t retnStatus);

  /// Lower statements [r.begin, r.end), entering with `deadDepth` ST entries that are never read
  /// (they hold 0) and an empty MS.
  /// With `chunk`, the entries of a carried cut come from (and go to) `carry` instead.
  llvm::Error emitRange(StmtRange r, int32_t deadDepth, const ChunkPlan *chunk = nullptr,
                        const CarryBuffer *carry = nullptr);
  /// Store the cached state (and a carried chunk's entries) and return LJ_FAULT_NONE; checks
  /// every jump target was placed.
  llvm::Error finish();

private:
  // EmitTrace.cpp: one statement with its trace words around it (ir/Trace.h) when traced.
  llvm::Error emitStmt(int32_t i);
  /// Store the i1 or i32 `v` into trace word `word` (the buffer's address is a constant).
  void traceStore(int32_t word, llvm::Value *v);
  /// What a contact conducted, set by emitBasic for the trace (null: not a contact).
  llvm::Value *traceContact_ = nullptr;

  // EmitFlow.cpp: dispatch and control flow.
  llvm::Error emitStmtBody(int32_t i);
  llvm::Error emitJmp(int32_t i);
  void emitLabel(int32_t i);
  void emitLoop(int32_t i);
  /// A LOOP whose body is long becomes a call of the body's own function (lowered later), so
  /// no function grows with the loop nesting or the body length.
  void emitOutlinedLoop(int32_t i);
  bool outlines(int32_t loopIndex) const;
  llvm::Error emitNext(int32_t i);
  llvm::Error emitCall(int32_t i);
  /// A taken JumpOut returns kStatusJumpOut + its label's number.
  llvm::Error emitJumpOut(int32_t i);
  /// Return `status` from the function when ST0 (the enable) is 1, else go on (RETN, JumpOut).
  void returnWhenEnabled(uint32_t status, const char *name);
  /// Where a jump to label statement `lbl` goes from here: the label's block in this body, or a
  /// block returning kStatusJump + its chunk; null when neither (an internal error).
  llvm::BasicBlock *jumpTarget(int32_t lbl);
  void emitRetn();
  /// `if (++steps > max_backward_steps) return LJ_FAULT_WATCHDOG;` then branch to `next`.
  void watchdogStep(llvm::BasicBlock *next);
  llvm::BasicBlock *labelBlock(int32_t lblIndex);
  llvm::BasicBlock *newBlock(const char *name);
  /// Flush the cache, branch to `bb` unless the current block already ended, continue there.
  void continueIn(llvm::BasicBlock *bb);
  llvm::Error fail(int32_t i, const std::string &what) const;

  // EmitBasic.cpp: operands, contacts, coils, stack instructions.
  /// Where operand `op` (a Reg or Bit of a numeric area) lives: its image field, or `width`
  /// bytes (0: the operand's access width) of lj_state.mem for a profile-laid area.
  StateLoc areaLoc(const Operand &op, unsigned width = 0);
  /// lj_state offset of operand `op` (a Reg or Bit of a numeric area) as this body reads it:
  /// X and F from the synchronized input memory when the body's statements read it
  /// (ir/SyncInputs.h: FANUC level 2 and subroutines of a divided level 2).
  uint32_t readOffset(const Operand &op) const {
    const uint32_t off = tp().elementOffset(op.area, op.index);
    return syncReads_ ? tp().syncReadOffset(op.area, off) : off;
  }
  /// Field `f` of timer slot `slot` / the previous-input byte of PLS (`rise`) or PLF block
  /// `slot`, where the profile keeps them (TargetProfile::timerOffset / pulseOffset).
  StateLoc timerLoc(int32_t slot, TimerField f) const;
  StateLoc pulseLoc(bool rise, int32_t slot) const;
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
  // EmitIec.cpp: the Neza function blocks %TMi / %Ci (ir/IecBlocks.h).
  llvm::Error emitIecTimer(int32_t i);
  llvm::Error emitIecCounter(int32_t i);

  // EmitData.cpp: family Data (XMOV .. NTP). Helpers of that file go in this section.
  llvm::Error emitDataBlock(int32_t i);
  /// An XMOV/XCH operand (functions-2 0.6): a register (format 0) or B/P[value of the register]
  /// at a computed, clamped index with its in-range flag.
  struct DataRef {
    Operand reg;                  ///< format 0: the register itself
    Area area = Area::None;       ///< formats 1/2: B or P
    llvm::Value *index = nullptr; ///< formats 1/2: in-range index (0 when out of range)
    llvm::Value *ok = nullptr;    ///< index in range (i1)
  };
  DataRef dataResolve(const Operand &format, const Operand &addr);
  llvm::Value *dataRead(const DataRef &r);
  void dataWrite(const DataRef &r, llvm::Value *v, llvm::Value *en);
  /// Element `index` (i32, in range) of `a` through a computed address, with the read rule;
  /// flushes the cache first (so no later cached store can erase a store this load saw).
  llvm::Value *dataLoadAt(Area a, llvm::Value *index);
  /// Stores the low bits of `v` at a computed address, then flushes the cache.
  void dataStoreAt(Area a, llvm::Value *index, llvm::Value *v);
  /// `fault_index += en & !ok`; a block without an output then sees ST0 := ST0 & ok.
  void dataIndexFault(llvm::Value *en, llvm::Value *ok, bool hasOutput);
  /// An LLVM loop over idx = 0..n-1 (n - 1..0 when `backward`), entered only when `en`; carries
  /// one i32 (`init` on entry, null for none) through `body` and returns its final value.
  using DataBody = llvm::function_ref<llvm::Value *(llvm::Value *idx, llvm::Value *carried)>;
  llvm::Value *dataLoop(llvm::Value *en, int32_t n, bool backward, llvm::Value *init,
                        DataBody body);
  /// Store 0 / `v` into elements first..last of `a` (unrolled or a loop), only when `en`.
  void dataFill(Area a, int32_t first, int32_t last, llvm::Value *v, llvm::Value *en);
  void emitXmovXch(const Stmt &s);
  void emitBmov(const Stmt &s);
  void emitZrst(const Stmt &s);
  void emitTable(const Stmt &s);
  void emitAssemDisas(const Stmt &s);
  void emitAcvt(const Stmt &s);
  void emitPtnNtp(const Stmt &s);

  // EmitFanucData.cpp: the fanuc-b operations of family Data (FANUC PARI .. DSCHB, COM).
  // Helpers of that file go in this section.
  llvm::Error emitFanucData(int32_t i);
  /// The top `k` ST entries, ST0 first; pops `k - 1` of them (W1 then replaces ST0).
  std::vector<llvm::Value *> fdTake(size_t k);
  /// W1 of the RST family kept in edge slot `slot` (InterpFanucData.cpp), left in ST0.
  void fdW1(int32_t slot, llvm::Value *act, llvm::Value *rst, llvm::Value *err);
  /// `width` bytes at `k` bytes after register operand `o` (through the cache), as iN.
  llvm::Value *fdLoad(const Operand &o, int32_t k, unsigned width);
  /// Store the low bytes of `v` there; only when `en` if given.
  void fdStore(const Operand &o, int32_t k, unsigned width, llvm::Value *v, llvm::Value *en);
  /// Address of byte `dyn` (i64) after register operand `o` (computed: flush the cache first).
  llvm::Value *fdAddr(const Operand &o, llvm::Value *dyn);
  void emitFdConvert(const Stmt &s, int32_t slot);
  void emitFdConvertExt(const Stmt &s, int32_t slot);
  void emitFdCode(int32_t i);
  void emitFdIndexed(const Stmt &s, int32_t slot);
  void emitFdSearch(const Stmt &s, int32_t slot);
  void emitFdBcdIndexed(const Stmt &s, int32_t slot); // XMOV
  void emitFdBcdSearch(const Stmt &s, int32_t slot);  // DSCH
  void emitFdRotation(const Stmt &s, int32_t slot);   // ROT, ROTB

  // EmitNc.cpp: family Nc (MGET .. SAVEDATA), host callbacks. Helpers of that file go here.
  llvm::Error emitNcBlock(int32_t i);
  /// What a guarded host call gives back (all valid after the call's join block).
  struct NcCall {
    llvm::Value *called; ///< i1: the callback ran
    llvm::Value *ret;    ///< i32 return value (0 when not called or void)
    llvm::Value *out[2]; ///< i32 values returned through pointers (0 when not called)
  };
  /// When `cond`, call the lj_host member at byte offset `member` as
  /// `fn(ctx, args..., &out0, &out1)` if state->host and the member are non-null. Flushes the
  /// image cache and splits the basic block; the builder continues in the join block.
  NcCall ncHostCall(llvm::Value *cond, size_t member, bool returnsValue,
                    llvm::ArrayRef<llvm::Value *> args, unsigned outs = 0);
  /// Element `index` of area `a` read as i32 (read rule), through the cache.
  llvm::Value *ncRead(Area a, int32_t index);
  /// Write the low bits of `v` into element `index` of area `a` when `en` (null: always).
  void ncWrite(Area a, int32_t index, llvm::Value *v, llvm::Value *en);
  /// Store the low 16 bits of `v` into G[index] with a runtime index known to be in range
  /// (the cache must be flushed around it).
  void ncStoreGAt(llvm::Value *index, llvm::Value *v);
  void emitMpgSet(int32_t i);
  void emitRot(int32_t i);
  llvm::AllocaInst *ncOut_[2] = {nullptr, nullptr}; ///< out-parameter slots of host calls

  // EmitCnc.cpp: family Cnc (MDST .. RSTCLR), the CNC F/G table. Helpers of that file go here.
  llvm::Error emitCncBlock(int32_t i);
  /// Word base of one CNC statement: a constant word, or a runtime axis (`dyn` = axis*80 as
  /// i32, axis 0 when out of range; `valid` = axis in 0..31).
  struct CncBase {
    int32_t word = 0;
    llvm::Value *dyn = nullptr;
    llvm::Value *valid = nullptr;
  };
  /// F or G word `base + k` as i16 (a runtime base loads through a computed address).
  llvm::Value *cncLoad(Area a, const CncBase &base, int32_t k);
  /// G word `base + k` := f(old); with a runtime base the store keeps `old` unless valid.
  void cncUpdate(const CncBase &base, int32_t k,
                 llvm::function_ref<llvm::Value *(llvm::Value *)> f);
  /// Bit `bit` of F/G word `base + k` as i1.
  llvm::Value *cncBit(Area a, const CncBase &base, int32_t k, int32_t bit);
  /// One table action; `cond` receives a Status action's F bit.
  void emitCncAction(int32_t i, const cnc::Action &a, const CncBase &base, llvm::Value *act,
                     llvm::Value *&cond);
  /// SPDLBUS / SPDLBUS1 command words (docs/cnc-blocks.md "Spindle command").
  void emitCncSpindle(int32_t i, const cnc::Action &a, const CncBase &base, llvm::Value *act);

  /// The program's profile (area facts, CNC layout and table, timer units).
  const TargetProfile &tp() const { return *prog_.profile; }

  // EmitPmcTc.cpp: family PmcTc (FANUC TMR .. RNGx).
  llvm::Error emitPmcTcBlock(int32_t i);
  /// On-delay timing on inst_word[slot], [slot + 1] (interp/InterpPmcTc.cpp onDelay): W1 and
  /// the elapsed ms.
  std::pair<llvm::Value *, llvm::Value *> pmcOnDelay(int32_t slot, llvm::Value *act,
                                                     llvm::Value *presetMs);

  // EmitClassicLadder.cpp: family ClassicLadder (the scan clock, %T, %M, %C, %TM).
  llvm::Error emitClassicLadderBlock(int32_t i);

  // EmitFanucArith.cpp: the fanuc-c operations of family PmcTc (FANUC ADDB..DIVB, ADD..DIV,
  // NUME; they reuse the fd* helpers of EmitFanucData.cpp).
  llvm::Error emitFanucArith(int32_t i);
  void emitFaBinary(const Stmt &s, int32_t slot);
  void emitFaBcd(const Stmt &s, int32_t slot);

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
  /// The head both loop forms share (EmitFlow.cpp): read the count once, then per iteration a
  /// `remaining > 0` test and one watchdog step; leaves the insert point in the body block.
  Loop openLoop(int32_t i);
  std::vector<Loop> loops_;
  llvm::BasicBlock *abort_ = nullptr; ///< `ret LJ_FAULT_WATCHDOG`, created on first use
  const ChunkPlan *chunk_ = nullptr;  ///< set for a chunk with carried entries
  CarryBuffer carry_;
  StmtRange range_{};
  bool syncReads_ = false; ///< readsSyncInputs of the range's statements (one part each)
};

/// Split [r.begin, r.end) into consecutive ranges of about `target` statements. Cuts are placed
/// only before statements where no ST entry is live (read later before a stack reset), MS is
/// empty, and no loop body or JMP..LBL span crosses the cut.
/// Where no such cut comes for 2 * `target` statements, a carried cut (ChunkPlan) is placed at
/// the next statement outside loops and JMP spans, so a function's length stays bounded.
/// `weightBefore`: the prefix sums of ModuleContext::weightBefore (nullptr: computed here). The
/// work is linear in the statements of r outside its loops.
std::vector<ChunkPlan> planChunkFunctions(const VerifiedProgram &p, StmtRange r, int32_t target,
                                          const std::vector<int64_t> *weightBefore = nullptr);
/// Estimated size of the lowering of [r.begin, r.end), in the units of `target` (ordinary
/// statements weigh 1, rows whose lowering is long more).
int64_t bodyWeight(const VerifiedProgram &p, StmtRange r);
/// The ranges of planChunkFunctions.
std::vector<StmtRange> planChunks(const VerifiedProgram &p, StmtRange r, int32_t target);

} // namespace lj::lower

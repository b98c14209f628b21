// The trace words of a traced build (ir/Trace.h, docs/ladder-view.md "Live view"): around each
// statement, stores of what it conducted, its EN and output, and a box's values, into the
// runtime's buffer at an address baked into the code. Twin of the interpreter's runT<true>
// (interp/InterpFlow.cpp); an untraced build (LowerOptions::trace null) emits none of it.
#include "lowering/FunctionEmitter.h"

#include "ladderjit/abi.h"

namespace lj::lower {

void FunctionEmitter::traceStore(int32_t word, llvm::Value *v) {
  auto addr = reinterpret_cast<uintptr_t>(mc_.opts.trace + word);
  llvm::Constant *p =
      llvm::ConstantExpr::getIntToPtr(b_.getInt64(static_cast<uint64_t>(addr)), b_.getPtrTy());
  if (v->getType() != b_.getInt32Ty()) v = b_.CreateZExt(v, b_.getInt32Ty());
  b_.CreateStore(v, p);
}

llvm::Error FunctionEmitter::emitStmt(int32_t i) {
  if (!mc_.opts.trace) return emitStmtBody(i);
  const int32_t at = mc_.traceAt.at[i];
  const TraceKind kind = mc_.traceAt.kind[i];
  const Stmt &s = prog_.stmts[i];
  // Before: EN of boxes and flow (a taken JMP does not come back), a coil's input, LDT's 1.
  llvm::Value *en = nullptr;
  if (kind == TraceKind::Box || kind == TraceKind::Flow) {
    en = enable();
    traceStore(at, en);
  } else if (kind == TraceKind::Coil && !st_.empty()) {
    traceStore(at, st_.back());
  } else if (s.op == Op::LoadTrue) {
    traceStore(at, b_.getInt32(1));
  }
  traceContact_ = nullptr;
  if (llvm::Error e = emitStmtBody(i)) return e;
  if (kind == TraceKind::Contact && s.op != Op::LoadTrue) {
    if (!traceContact_) return fail(i, "traced contact without a conduction value");
    traceStore(at, traceContact_);
  }
  if (kind != TraceKind::Box) return llvm::Error::success();
  // After: output, operand values, the timer's elapsed / counter's value (ir/Trace.h Box).
  traceStore(at + 1, st_.empty() ? en : st_.back());
  int32_t k = at + 2;
  for (int o = 0; o < s.operandCount && o < 8; ++o)
    if (mc_.traceAt.operand[i] & (1u << o)) traceStore(k++, readInt(s.ops[o]));
  const InstrInfo &row = instrInfo(s.op);
  const int32_t slot = prog_.info[i].slot;
  if (row.family == Family::Core && row.state == StateKind::Timer)
    traceStore(k,
               b_.CreateTrunc(cache_.load(timerLoc(slot, TimerField::Elapsed)), b_.getInt32Ty()));
  else if (row.family == Family::Core && row.state == StateKind::Counter)
    traceStore(k, cache_.load(mc_.layout.counter(slot, CounterField::Value)));
  return llvm::Error::success();
}

} // namespace lj::lower

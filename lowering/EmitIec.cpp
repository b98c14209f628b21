// Lowering of the Neza function blocks %TMi / %Ci (twin of interp/InterpIec.cpp; semantics in
// docs/iec-il.md "Function blocks"), as straight-line selects over the block's words.
#include "lowering/FunctionEmitter.h"

#include "ir/IecBlocks.h"

namespace lj::lower {

namespace {

/// Word k of the block whose first word is `base`.
Operand blockWord(const Operand &base, int32_t k) {
  Operand o = base;
  o.index += k;
  return o;
}

} // namespace

llvm::Error FunctionEmitter::emitIecTimer(int32_t i) {
  using namespace iec;
  const Stmt &s = prog_.stmts[i];
  const Operand &base = s.ops[0];
  if (s.ops[1].kind != Operand::Kind::Const || s.ops[1].value < 0 || s.ops[1].value > 2 ||
      s.ops[2].kind != Operand::Kind::Const || s.ops[2].value < 0 || s.ops[2].value > 4)
    return fail(i, "timer type or time base is not a constant in range");
  const auto type = static_cast<TimerType>(s.ops[1].value);
  const uint32_t tbMs = kTimeBaseMs[s.ops[2].value];
  llvm::Value *zero = b_.getInt32(0);
  auto bitOf = [&](llvm::Value *w, int32_t b) {
    return b_.CreateICmpNE(b_.CreateAnd(w, b_.getInt32(1u << b)), zero);
  };
  auto toI32 = [&](llvm::Value *bit, int32_t b) {
    return b_.CreateShl(b_.CreateZExt(bit, b_.getInt32Ty()), b_.getInt32(static_cast<uint32_t>(b)));
  };
  llvm::Value *in = enable();
  llvm::Value *p = readInt(blockWord(base, kTimerP));
  p = b_.CreateSelect(b_.CreateICmpSLT(p, zero), zero, p, "preset");
  llvm::Value *status = readInt(blockWord(base, kTimerStatus));
  llvm::Value *q = bitOf(status, kTimerQ), *run = bitOf(status, kTimerRun);
  llvm::Value *prev = bitOf(status, kTimerPrevIn);
  llvm::Value *v = readInt(blockWord(base, kTimerV));
  llvm::Value *lo = b_.CreateAnd(readInt(blockWord(base, kTimerStartLo)), b_.getInt32(0xFFFF));
  llvm::Value *hi = b_.CreateShl(readInt(blockWord(base, kTimerStartHi)), b_.getInt32(16));
  llvm::Value *start = b_.CreateOr(lo, hi, "start");
  llvm::Value *now = b_.CreateTrunc(cache_.load(mc_.layout.scalar(Scalar::NowMs)), b_.getInt32Ty());
  llvm::Value *presetMs = b_.CreateMul(p, b_.getInt32(tbMs)); // <= 32767 * 60000 < 2^31
  // Timing while `active`: starts now when not running; el modulo 2^32 (interp: timing()).
  llvm::Value *done = nullptr, *value = nullptr;
  auto timing = [&](llvm::Value *active, llvm::Value *running, llvm::Value *t0) {
    llvm::Value *st = b_.CreateSelect(b_.CreateAnd(active, notV(running)), now, t0);
    llvm::Value *el = b_.CreateSub(now, st, "elapsed");
    done = b_.CreateICmpUGE(el, presetMs, "done");
    value = b_.CreateSelect(done, p, b_.CreateUDiv(el, b_.getInt32(tbMs)));
    return st;
  };
  llvm::Value *qN, *runN, *vN, *startN;
  switch (type) {
  case TimerType::Ton:
    startN = timing(b_.CreateAnd(in, notV(q)), run, start);
    qN = b_.CreateAnd(in, b_.CreateOr(q, done));
    runN = b_.CreateAnd(in, selectBit(q, run, notV(done)));
    vN = b_.CreateSelect(in, b_.CreateSelect(q, v, value), zero);
    break;
  case TimerType::Tof:
    startN = timing(b_.CreateAnd(notV(in), q), run, start);
    qN = b_.CreateOr(in, b_.CreateAnd(q, notV(done)));
    runN = b_.CreateAnd(notV(in), selectBit(q, notV(done), run));
    vN = b_.CreateSelect(in, zero, b_.CreateSelect(q, value, v));
    break;
  case TimerType::Tp:
  default: {
    llvm::Value *pulse = b_.CreateAnd(b_.CreateAnd(notV(q), in), notV(prev), "pulse");
    llvm::Value *q1 = b_.CreateOr(q, pulse), *run1 = b_.CreateOr(run, pulse);
    llvm::Value *start1 = b_.CreateSelect(pulse, now, start);
    startN = timing(q1, run1, start1);
    qN = b_.CreateAnd(q1, notV(done));
    runN = selectBit(q1, notV(done), run1);
    llvm::Value *v1 = b_.CreateSelect(q1, value, v);
    vN = b_.CreateSelect(b_.CreateAnd(notV(qN), notV(in)), zero, v1);
    break;
  }
  }
  writeInt(blockWord(base, kTimerV), vN, nullptr);
  writeInt(
      blockWord(base, kTimerStatus),
      b_.CreateOr(b_.CreateOr(toI32(qN, kTimerQ), toI32(runN, kTimerRun)), toI32(in, kTimerPrevIn)),
      nullptr);
  writeInt(blockWord(base, kTimerStartLo), startN, nullptr);
  writeInt(blockWord(base, kTimerStartHi), b_.CreateLShr(startN, b_.getInt32(16)), nullptr);
  setOutput(in);
  return llvm::Error::success();
}

llvm::Error FunctionEmitter::emitIecCounter(int32_t i) {
  using namespace iec;
  const Stmt &s = prog_.stmts[i];
  const Operand &base = s.ops[0];
  if (st_.size() < 4) return fail(i, "counter with too few ST entries");
  if (s.ops[1].kind != Operand::Kind::Const) return fail(i, "counter inputs are not a constant");
  const int32_t pins = s.ops[1].value;
  llvm::Value *cd = st_[st_.size() - 1], *cu = st_[st_.size() - 2];
  llvm::Value *preset = st_[st_.size() - 3], *reset = st_[st_.size() - 4];
  st_.resize(st_.size() - 4);
  llvm::Value *zero = b_.getInt32(0), *fls = b_.getFalse();
  auto bitOf = [&](llvm::Value *w, int32_t b) {
    return b_.CreateICmpNE(b_.CreateAnd(w, b_.getInt32(1u << b)), zero);
  };
  auto toI32 = [&](llvm::Value *bit, int32_t b) {
    return b_.CreateShl(b_.CreateZExt(bit, b_.getInt32Ty()), b_.getInt32(static_cast<uint32_t>(b)));
  };
  llvm::Value *status = readInt(blockWord(base, kCounterStatus));
  llvm::Value *e = bitOf(status, kCounterE), *full = bitOf(status, kCounterF);
  llvm::Value *prevUp = bitOf(status, kCounterPrevUp), *prevDown = bitOf(status, kCounterPrevDown);
  llvm::Value *up = (pins & kPinCu) ? b_.CreateAnd(cu, notV(prevUp), "up") : fls;
  llvm::Value *down = (pins & kPinCd) ? b_.CreateAnd(cd, notV(prevDown), "down") : fls;
  llvm::Value *prevUpN = (pins & kPinCu) ? cu : prevUp;
  llvm::Value *prevDownN = (pins & kPinCd) ? cd : prevDown;
  llvm::Value *rst = (pins & kPinR) ? reset : fls;
  llvm::Value *set = b_.CreateAnd(notV(rst), (pins & kPinS) ? preset : fls, "set");
  llvm::Value *v = readInt(blockWord(base, kCounterV));
  llvm::Value *p = readInt(blockWord(base, kCounterP));
  // Counting (neither R nor S): exactly one of up / down moves V.
  llvm::Value *countUp = b_.CreateAnd(up, notV(down)), *countDown = b_.CreateAnd(down, notV(up));
  llvm::Value *over = b_.CreateICmpSGE(v, b_.getInt32(kCounterMax));
  llvm::Value *under = b_.CreateICmpSLE(v, zero);
  llvm::Value *vUp = b_.CreateSelect(over, zero, b_.CreateAdd(v, b_.getInt32(1)));
  llvm::Value *vDown =
      b_.CreateSelect(under, b_.getInt32(kCounterMax), b_.CreateSub(v, b_.getInt32(1)));
  llvm::Value *counted = b_.CreateSelect(countUp, vUp, b_.CreateSelect(countDown, vDown, v));
  llvm::Value *fullC = selectBit(countUp, over, full);
  llvm::Value *eC = selectBit(countDown, under, e);
  llvm::Value *keep = b_.CreateAnd(notV(rst), notV(set)); // the counting case
  llvm::Value *vN = b_.CreateSelect(rst, zero, b_.CreateSelect(set, p, counted), "cv");
  llvm::Value *eN = b_.CreateAnd(keep, eC);
  llvm::Value *fullN = b_.CreateAnd(keep, fullC);
  llvm::Value *dN = b_.CreateAnd(notV(rst), b_.CreateOr(set, b_.CreateICmpEQ(counted, p)), "done");
  writeInt(blockWord(base, kCounterV), vN, nullptr);
  llvm::Value *w = b_.CreateOr(toI32(eN, kCounterE), toI32(dN, kCounterD));
  w = b_.CreateOr(w, toI32(fullN, kCounterF));
  w = b_.CreateOr(w, toI32(prevUpN, kCounterPrevUp));
  w = b_.CreateOr(w, toI32(prevDownN, kCounterPrevDown));
  writeInt(blockWord(base, kCounterStatus), w, nullptr);
  st_.push_back(dN);
  return llvm::Error::success();
}

} // namespace lj::lower

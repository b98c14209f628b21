// Function blocks (DIALECT.md 5, docs/dialect-notes.md "Function blocks"): math, compares, MOV,
// counters, timers, PLS/PLF/ALT. Every block is straight-line code: EN guards are selects, so a
// block never splits the basic block and the image stays in registers across it.
#include "lowering/FunctionEmitter.h"

#include "ir/Profile.h"

#include "ladderjit/abi.h"

namespace lj::lower {

llvm::Value *FunctionEmitter::enable() const {
  return st_.empty() ? llvm::ConstantInt::getTrue(fn_->getContext()) : st_.back();
}

void FunctionEmitter::setOutput(llvm::Value *out) {
  if (st_.empty())
    st_.push_back(out);
  else
    st_.back() = out;
}

llvm::Error FunctionEmitter::emitBlock(int32_t i) {
  const Stmt &s = prog_.stmts[i];
  switch (s.op) {
  case Op::Add:
  case Op::Subtract:
  case Op::Multiply:
  case Op::Divide:
  case Op::Increment:
  case Op::Decrement:
  case Op::BitAnd:
  case Op::BitOr:
  case Op::BitXor:
  case Op::Negate:
    emitMath(s);
    return llvm::Error::success();
  case Op::CompareLe:
  case Op::CompareLt:
  case Op::CompareRange:
  case Op::CompareEq:
    emitCompare(s);
    return llvm::Error::success();
  case Op::Move: {
    // Math and move blocks with EN = 0 write nothing; their output is EN.
    llvm::Value *en = enable();
    writeInt(s.ops[1], readInt(s.ops[0]), en);
    setOutput(en);
    return llvm::Error::success();
  }
  case Op::RegisterCounter:
  case Op::RingCounter:
  case Op::UpDownCounter:
    return emitCounter(i);
  case Op::OnDelayTimer:
  case Op::OffDelayTimer:
    return emitTimer(i);
  case Op::RisePulse:
  case Op::FallPulse:
  case Op::Toggle:
    return emitPulse(i);
  case Op::IecTimer: // the Neza blocks (EmitIec.cpp)
    return emitIecTimer(i);
  case Op::IecCounter:
    return emitIecCounter(i);
  default:
    return fail(i, "not a function block");
  }
}

void FunctionEmitter::emitMath(const Stmt &s) {
  llvm::Value *en = enable();
  llvm::Value *out = en;
  // int32 two's-complement wrap everywhere: plain add/sub/mul, never nsw/nuw (DIALECT.md 1).
  switch (s.op) {
  case Op::Increment:
  case Op::Decrement:
  case Op::Negate: {
    llvm::Value *x = readInt(s.ops[0]);
    llvm::Value *r = s.op == Op::Increment   ? b_.CreateAdd(x, b_.getInt32(1))
                     : s.op == Op::Decrement ? b_.CreateSub(x, b_.getInt32(1))
                                             : b_.CreateSub(b_.getInt32(0), x);
    writeInt(s.ops[0], r, en);
    break;
  }
  case Op::Divide: {
    // dialect-notes: b = 0 writes nothing, output 0, fault_divzero counts it (EN = 1 only);
    // INT32_MIN / -1 = INT32_MIN. The divisor is made safe first so sdiv never has UB.
    llvm::Value *a = readInt(s.ops[0]), *d = readInt(s.ops[1]);
    llvm::Value *zero = b_.CreateICmpEQ(d, b_.getInt32(0), "divzero");
    llvm::Value *ovf = b_.CreateAnd(b_.CreateICmpEQ(a, b_.getInt32(INT32_MIN)),
                                    b_.CreateICmpEQ(d, b_.getInt32(-1)));
    llvm::Value *safe = b_.CreateSelect(b_.CreateOr(zero, ovf), b_.getInt32(1), d);
    llvm::Value *q = b_.CreateSDiv(a, safe); // INT32_MIN / 1 = INT32_MIN
    out = b_.CreateAnd(en, notV(zero));
    writeInt(s.ops[2], q, out);
    StateLoc fz = mc_.layout.scalar(Scalar::FaultDivzero);
    llvm::Value *count = b_.CreateZExt(b_.CreateAnd(en, zero), b_.getInt32Ty());
    cache_.store(fz, b_.CreateAdd(cache_.load(fz), count));
    break;
  }
  default: {
    llvm::Value *a = readInt(s.ops[0]), *c = readInt(s.ops[1]);
    llvm::Value *r = nullptr;
    switch (s.op) {
    case Op::Add:
      r = b_.CreateAdd(a, c);
      break;
    case Op::Subtract:
      r = b_.CreateSub(a, c);
      break;
    case Op::Multiply:
      r = b_.CreateMul(a, c);
      break;
    case Op::BitAnd:
      r = b_.CreateAnd(a, c);
      break;
    case Op::BitOr:
      r = b_.CreateOr(a, c);
      break;
    default:
      r = b_.CreateXor(a, c);
      break; // WXOR
    }
    writeInt(s.ops[2], r, en);
    break;
  }
  }
  setOutput(out);
}

void FunctionEmitter::emitCompare(const Stmt &s) {
  // Output = EN and condition, signed int32 after the read rule (functions-2 1.1-1.4).
  llvm::Value *en = enable();
  llvm::Value *a = readInt(s.ops[0]), *c = readInt(s.ops[1]);
  llvm::Value *cond = nullptr;
  switch (s.op) {
  case Op::CompareLe:
    cond = b_.CreateICmpSLE(a, c);
    break;
  case Op::CompareLt:
    cond = b_.CreateICmpSLT(a, c);
    break;
  case Op::CompareEq:
    cond = b_.CreateICmpEQ(a, c);
    break;
  default: { // ACMP lo hi x: lo < x < hi
    llvm::Value *x = readInt(s.ops[2]);
    cond = b_.CreateAnd(b_.CreateICmpSLT(a, x), b_.CreateICmpSLT(x, c));
    break;
  }
  }
  setOutput(b_.CreateAnd(en, cond));
}

llvm::Error FunctionEmitter::emitCounter(int32_t i) {
  // hnc8-functions-1.md 3.3, common counter algorithm, as straight-line selects.
  const Stmt &s = prog_.stmts[i];
  const int32_t slot = prog_.info[i].slot;
  const size_t k = s.op == Op::RingCounter ? 2 : 4;
  if (st_.size() < k) return fail(i, "counter with too few ST entries");
  if (s.op == Op::RegisterCounter ? (slot < 0 || slot >= LJ_EDGE_SLOTS)
                                  : (slot < 0 || slot >= LJ_TC_SLOTS))
    return fail(i, "counter slot " + std::to_string(slot) + " out of range");
  std::vector<llvm::Value *> in(st_.end() - k, st_.end()); // in[0] = input 1 (loaded first)
  st_.resize(st_.size() - k);
  llvm::Value *fls = b_.getFalse();
  llvm::Value *cnt = in[0];
  llvm::Value *s1 = k == 4 ? in[1] : fls, *dn = k == 4 ? in[2] : fls, *rst = in[k - 1];

  llvm::Value *pv = readInt(s.ops[1]); // preset read on every execution
  llvm::Value *init = b_.CreateZExt(s1, b_.getInt32Ty());
  StateLoc prevLoc = s.op == Op::RegisterCounter ? mc_.layout.edge(slot)
                                                 : mc_.layout.counter(slot, CounterField::Prev);
  StateLoc valLoc = mc_.layout.counter(slot, CounterField::Value);
  llvm::Value *cv = s.op == Op::RegisterCounter ? readInt(s.ops[0]) : cache_.load(valLoc);
  llvm::Value *prev = b_.CreateICmpNE(cache_.load(prevLoc), b_.getInt8(0));

  llvm::Value *rise = b_.CreateAnd(cnt, notV(prev), "count");
  llvm::Value *up =
      b_.CreateSelect(b_.CreateICmpSGE(cv, pv), init, b_.CreateAdd(cv, b_.getInt32(1)));
  llvm::Value *down =
      b_.CreateSelect(b_.CreateICmpSLE(cv, init), pv, b_.CreateSub(cv, b_.getInt32(1)));
  llvm::Value *counted = b_.CreateSelect(rise, b_.CreateSelect(dn, down, up), cv);
  llvm::Value *cvNew = b_.CreateSelect(rst, b_.CreateSelect(dn, pv, init), counted, "cv");
  llvm::Value *reached = selectBit(dn, b_.CreateICmpSLE(cvNew, init), b_.CreateICmpSGE(cvNew, pv));
  llvm::Value *out = b_.CreateAnd(notV(rst), reached, "reached");

  if (s.op == Op::RegisterCounter) {
    writeInt(s.ops[0], cvNew, nullptr); // value in its register, written truncated
  } else {
    cache_.store(valLoc, cvNew);
    cache_.store(mc_.layout.counter(slot, CounterField::Out), b_.CreateZExt(out, b_.getInt8Ty()));
  }
  cache_.store(prevLoc, b_.CreateZExt(cnt, b_.getInt8Ty())); // also during reset
  st_.push_back(out);
  return llvm::Error::success();
}

llvm::Error FunctionEmitter::emitTimer(int32_t i) {
  // docs/dialect-notes.md "Timers", as selects over the lj_timer fields.
  const Stmt &s = prog_.stmts[i];
  const int32_t slot = prog_.info[i].slot;
  if (slot < 0 || slot >= tp().timerSlots()) return fail(i, "timer slot out of range");
  int32_t unit = s.ops[1].value;
  if (s.ops[1].kind != Operand::Kind::Const || unit < 0 || unit > 3)
    return fail(i, "timer unit is not a constant 0..3");
  llvm::Type *i64 = b_.getInt64Ty();
  llvm::Value *zero64 = b_.getInt64(0);
  llvm::Value *en = enable();
  llvm::Value *len = b_.CreateSExt(readInt(s.ops[2]), i64);
  llvm::Value *preset =
      b_.CreateMul(len, b_.getInt64(tp().timerUnitMs[unit])); // fits: |len| < 2^31
  preset = b_.CreateSelect(b_.CreateICmpSLT(preset, zero64), zero64, preset, "preset");
  llvm::Value *now = cache_.load(mc_.layout.scalar(Scalar::NowMs));
  StateLoc startL = timerLoc(slot, TimerField::Start);
  StateLoc elapsedL = timerLoc(slot, TimerField::Elapsed);
  StateLoc outL = timerLoc(slot, TimerField::Out);
  StateLoc runL = timerLoc(slot, TimerField::Running);
  llvm::Value *start = cache_.load(startL);
  llvm::Value *runOld = b_.CreateICmpNE(cache_.load(runL), b_.getInt8(0));
  auto elapsedSince = [&](llvm::Value *t0) {
    llvm::Value *el = b_.CreateSub(now, t0);
    return b_.CreateSelect(b_.CreateICmpSLT(el, zero64), zero64, el, "elapsed");
  };
  llvm::Value *out, *running, *elapsed, *startNew;
  if (s.op == Op::OnDelayTimer) {
    startNew = b_.CreateSelect(b_.CreateAnd(en, notV(runOld)), now, start);
    llvm::Value *el = elapsedSince(startNew);
    llvm::Value *done = b_.CreateICmpSGE(el, preset);
    out = b_.CreateAnd(en, done);
    running = en;
    elapsed = b_.CreateSelect(en, b_.CreateSelect(done, preset, el), zero64);
  } else { // STMR
    llvm::Value *outOld = b_.CreateICmpNE(cache_.load(outL), b_.getInt8(0));
    llvm::Value *active = b_.CreateAnd(notV(en), outOld, "offdelay");
    startNew = b_.CreateSelect(b_.CreateAnd(active, notV(runOld)), now, start);
    llvm::Value *el = elapsedSince(startNew);
    llvm::Value *done = b_.CreateICmpSGE(el, preset);
    out = b_.CreateOr(en, b_.CreateAnd(active, notV(done)));
    running = b_.CreateAnd(notV(en), selectBit(active, notV(done), runOld));
    elapsed = b_.CreateSelect(
        en, zero64,
        b_.CreateSelect(active, b_.CreateSelect(done, preset, el), cache_.load(elapsedL)));
  }
  cache_.store(startL, startNew);
  cache_.store(elapsedL, elapsed);
  cache_.store(outL, b_.CreateZExt(out, b_.getInt8Ty()));
  cache_.store(runL, b_.CreateZExt(running, b_.getInt8Ty()));
  setOutput(out);
  return llvm::Error::success();
}

llvm::Error FunctionEmitter::emitPulse(int32_t i) {
  // dialect-notes: PLS out = EN & !prev; PLF out = !EN & prev; ALT toggles on EN & !prev;
  // all three update prev = EN on every execution.
  const Stmt &s = prog_.stmts[i];
  const int32_t slot = prog_.info[i].slot;
  if (slot < 0 || slot >= (s.op == Op::Toggle ? LJ_BLOCK_SLOTS : tp().pulseSlots()))
    return fail(i, "block number out of range");
  llvm::Value *en = enable();
  BlockArray prevArr = s.op == Op::RisePulse   ? BlockArray::PlsPrev
                       : s.op == Op::FallPulse ? BlockArray::PlfPrev
                                               : BlockArray::AltPrev;
  StateLoc prevL =
      s.op == Op::Toggle ? mc_.layout.block(prevArr, slot) : pulseLoc(s.op == Op::RisePulse, slot);
  llvm::Value *prev = b_.CreateICmpNE(cache_.load(prevL), b_.getInt8(0));
  llvm::Value *out;
  if (s.op == Op::RisePulse) {
    out = b_.CreateAnd(en, notV(prev));
  } else if (s.op == Op::FallPulse) {
    out = b_.CreateAnd(notV(en), prev);
  } else {
    StateLoc stateL = mc_.layout.block(BlockArray::AltState, slot);
    llvm::Value *old = b_.CreateICmpNE(cache_.load(stateL), b_.getInt8(0));
    out = b_.CreateXor(old, b_.CreateAnd(en, notV(prev)));
    cache_.store(stateL, b_.CreateZExt(out, b_.getInt8Ty()));
  }
  cache_.store(prevL, b_.CreateZExt(en, b_.getInt8Ty()));
  setOutput(out);
  return llvm::Error::success();
}

StateLoc FunctionEmitter::timerLoc(int32_t slot, TimerField f) const {
  if (!tp().blockState.timers) return mc_.layout.timer(slot, f);
  static constexpr uint32_t kOff[] = {offsetof(lj_timer, start_ms), offsetof(lj_timer, elapsed_ms),
                                      offsetof(lj_timer, out), offsetof(lj_timer, running)};
  static constexpr const char *kName[] = {"start", "elapsed", "out", "running"};
  const unsigned fi = static_cast<unsigned>(f);
  std::string name;
  if (mc_.opts.readableNames) name = "tmr" + std::to_string(slot) + "." + kName[fi];
  return mc_.layout.memBytes(tp().timerOffset(slot) + kOff[fi], fi < 2 ? 8 : 1, std::move(name));
}

StateLoc FunctionEmitter::pulseLoc(bool rise, int32_t slot) const {
  if (!tp().blockState.rise)
    return mc_.layout.block(rise ? BlockArray::PlsPrev : BlockArray::PlfPrev, slot);
  std::string name;
  if (mc_.opts.readableNames) name = std::string(rise ? "rise" : "fall") + std::to_string(slot);
  return mc_.layout.memBytes(tp().pulseOffset(rise, slot), 1, std::move(name));
}

} // namespace lj::lower

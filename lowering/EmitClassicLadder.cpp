// Lowering of family ClassicLadder (twin of interp/InterpClassicLadder.cpp; LinuxCNC 2.9
// `calc.c`, docs/classicladder.md "Timers, monostables and counters"): the scan clock and the old
// timer, monostable, counter and IEC timer as straight-line selects over the block's words
// (ir/ClBlocks.h).
#include "lowering/FunctionEmitter.h"

#include "ir/ClBlocks.h"

namespace lj::lower {

namespace {

/// Word k of the block whose first word is `base`.
Operand clWord(const Operand &base, int32_t k) {
  Operand o = base;
  o.index += k;
  return o;
}

} // namespace

llvm::Error FunctionEmitter::emitClassicLadderBlock(int32_t i) {
  using namespace clblocks;
  const Stmt &s = prog_.stmts[i];
  const Operand &base = s.ops[0];
  auto k32 = [&](int32_t v) { return b_.getInt32(static_cast<uint32_t>(v)); };
  auto get = [&](int32_t k) { return readInt(clWord(base, k)); };
  auto set = [&](int32_t k, llvm::Value *v) { writeInt(clWord(base, k), v, nullptr); };
  auto flag = [&](int32_t k) { return b_.CreateICmpNE(get(k), k32(0)); };
  auto word = [&](llvm::Value *bit) { return b_.CreateZExt(bit, b_.getInt32Ty()); };
  auto pop = [&]() {
    llvm::Value *v = st_.back();
    st_.pop_back();
    return v;
  };
  auto dt = [&]() { return readInt(clWord(s.ops[1], kClockDt)); };
  switch (s.op) {
  case Op::ClClock: {
    if (s.ops[1].kind != Operand::Kind::Const) return fail(i, "clock mode is not a constant");
    llvm::Value *now =
        b_.CreateTrunc(cache_.load(mc_.layout.scalar(Scalar::NowMs)), b_.getInt32Ty(), "now32");
    if (s.ops[1].value == kClockPowerUp) {
      set(kClockDt, k32(0));
      set(kClockPrev, b_.CreateSub(now, k32(kFirstPeriodMs)));
    } else {
      set(kClockDt, b_.CreateSub(now, get(kClockPrev), "dt"));
      set(kClockPrev, now);
    }
    return llvm::Error::success();
  }
  case Op::ClTimer: {
    if (st_.size() < 2) return fail(i, "timer with too few ST entries");
    llvm::Value *c = pop(), *e = pop();
    llvm::Value *value = get(kTimerValueMs), *done = flag(kTimerDone);
    llvm::Value *running = flag(kTimerRunning);
    llvm::Value *left = b_.CreateICmpSGT(value, k32(0), "left");
    llvm::Value *count = b_.CreateAnd(e, b_.CreateAnd(left, c), "count");
    llvm::Value *finished = b_.CreateAnd(e, notV(left));
    // !E: reload, R = D = 0; counting: V -= dt, R = 1, D = 0; V <= 0: R = 0, D = 1
    llvm::Value *vN = b_.CreateSelect(e, b_.CreateSelect(count, b_.CreateSub(value, dt()), value),
                                      get(kTimerPresetMs));
    llvm::Value *rN = b_.CreateAnd(e, b_.CreateOr(count, b_.CreateAnd(left, running)));
    llvm::Value *dN =
        b_.CreateOr(finished, b_.CreateAnd(b_.CreateAnd(e, left), b_.CreateAnd(notV(c), done)));
    set(kTimerValueMs, vN);
    set(kTimerRunning, word(rN));
    set(kTimerDone, word(dN));
    st_.push_back(dN);
    return llvm::Error::success();
  }
  case Op::ClMonostable: {
    llvm::Value *in = enable();
    llvm::Value *value = get(kMonoValueMs);
    llvm::Value *start = b_.CreateAnd(b_.CreateAnd(in, notV(flag(kMonoInputBak))),
                                      b_.CreateICmpEQ(value, k32(0)), "start");
    llvm::Value *v1 = b_.CreateSelect(start, get(kMonoPresetMs), value);
    llvm::Value *r1 = b_.CreateOr(start, flag(kMonoRunning));
    llvm::Value *left = b_.CreateICmpSGT(v1, k32(0));
    llvm::Value *vN = b_.CreateSelect(left, b_.CreateSub(v1, dt()), v1);
    llvm::Value *rN = b_.CreateAnd(left, r1);
    set(kMonoValueMs, vN);
    set(kMonoRunning, word(rN));
    set(kMonoInputBak, word(in));
    setOutput(rN);
    return llvm::Error::success();
  }
  case Op::ClCounter: {
    if (st_.size() < 4) return fail(i, "counter with too few ST entries");
    llvm::Value *down = pop(), *up = pop(), *preset = pop(), *reset = pop();
    llvm::Value *v = get(kCounterValue), *bak = get(kCounterValueBak);
    llvm::Value *p = get(kCounterPreset);
    llvm::Value *riseUp = b_.CreateAnd(up, notV(flag(kCounterUpBak)));
    llvm::Value *riseDown = b_.CreateAnd(down, notV(flag(kCounterDownBak)));
    llvm::Value *plus = b_.CreateAdd(v, k32(1));
    plus = b_.CreateSelect(b_.CreateICmpSGT(plus, k32(kCounterMax)), k32(0), plus);
    bak = b_.CreateSelect(riseUp, v, bak);
    v = b_.CreateSelect(riseUp, plus, v);
    llvm::Value *minus = b_.CreateSub(v, k32(1));
    minus = b_.CreateSelect(b_.CreateICmpSLT(minus, k32(0)), k32(kCounterMax), minus);
    bak = b_.CreateSelect(riseDown, v, bak);
    v = b_.CreateSelect(riseDown, minus, v);
    bak = b_.CreateSelect(preset, v, bak);
    v = b_.CreateSelect(preset, p, v);
    bak = b_.CreateSelect(reset, v, bak);
    v = b_.CreateSelect(reset, k32(0), v);
    llvm::Value *doneN = b_.CreateICmpEQ(v, p);
    llvm::Value *emptyN =
        b_.CreateAnd(b_.CreateICmpEQ(v, k32(kCounterMax)), b_.CreateICmpEQ(bak, k32(0)));
    llvm::Value *fullN =
        b_.CreateAnd(b_.CreateICmpEQ(v, k32(0)), b_.CreateICmpEQ(bak, k32(kCounterMax)));
    set(kCounterUpBak, word(up));
    set(kCounterDownBak, word(down));
    set(kCounterValue, v);
    set(kCounterValueBak, bak);
    set(kCounterDone, word(doneN));
    set(kCounterEmpty, word(emptyN));
    set(kCounterFull, word(fullN));
    st_.push_back(emptyN);
    return llvm::Error::success();
  }
  case Op::ClIecTimer: {
    if (s.ops[2].kind != Operand::Kind::Const || s.ops[3].kind != Operand::Kind::Const)
      return fail(i, "IEC timer mode or base is not a constant");
    const int32_t mode = s.ops[2].value, baseMs = s.ops[3].value;
    llvm::Value *in = enable();
    llvm::Value *q = flag(kIecQ), *v = get(kIecValue), *started = flag(kIecStarted);
    llvm::Value *p = get(kIecPreset), *bak = flag(kIecInputBak);
    llvm::Value *qN, *vN, *startedN, *inc;
    // TOF / TP while started: count while V < P, else end (Q = 0, V = 0, not started)
    auto timeOut = [&](llvm::Value *st, llvm::Value *q0, llvm::Value *v0) {
      llvm::Value *below = b_.CreateICmpSLT(v0, p);
      inc = b_.CreateAnd(st, below);
      llvm::Value *end = b_.CreateAnd(st, notV(below));
      qN = b_.CreateAnd(q0, notV(end));
      vN = b_.CreateSelect(end, k32(0), v0);
      startedN = b_.CreateAnd(st, notV(end));
    };
    if (mode == kIecTon) {
      llvm::Value *below = b_.CreateICmpSLT(v, p);
      inc = b_.CreateAnd(in, below);
      qN = b_.CreateAnd(in, b_.CreateOr(notV(below), q));
      vN = b_.CreateSelect(in, v, k32(0));
      startedN = started;
    } else if (mode == kIecTof) {
      llvm::Value *st = b_.CreateAnd(notV(in), b_.CreateOr(bak, started));
      timeOut(st, b_.CreateOr(in, q), b_.CreateSelect(in, k32(0), v));
    } else {
      llvm::Value *pulse = b_.CreateAnd(b_.CreateAnd(in, notV(bak)), notV(started), "pulse");
      timeOut(b_.CreateOr(pulse, started), b_.CreateOr(pulse, q),
              b_.CreateSelect(pulse, k32(0), v));
    }
    llvm::Value *acc = b_.CreateAdd(get(kIecAcc), dt());
    llvm::Value *tick = b_.CreateAnd(inc, b_.CreateICmpSGE(acc, k32(baseMs)));
    set(kIecAcc, b_.CreateSelect(inc, b_.CreateSelect(tick, b_.CreateSub(acc, k32(baseMs)), acc),
                                 get(kIecAcc)));
    vN = b_.CreateSelect(tick, b_.CreateAdd(vN, k32(1)), vN);
    set(kIecQ, word(qN));
    set(kIecValue, vN);
    set(kIecStarted, word(startedN));
    set(kIecInputBak, word(in));
    setOutput(qN);
    return llvm::Error::success();
  }
  default:
    return fail(i, "not a ClassicLadder block");
  }
}

} // namespace lj::lower

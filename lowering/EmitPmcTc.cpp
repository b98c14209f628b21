// Lowering of family PmcTc: the FANUC PMC timers TMR/TMRC, the counters CTR/CTRB/CTRC, COMPB,
// COMP/COIN, NEx and RNGx, as straight-line selects mirroring interp/InterpPmcTc.cpp (the
// oracle) step by step; the unit tables and the BCD reading are ir/PmcTc.h's.
#include "ir/PmcTc.h"
#include "lowering/FunctionEmitter.h"

#include "ladderjit/abi.h"

namespace lj::lower {

std::pair<llvm::Value *, llvm::Value *> FunctionEmitter::pmcOnDelay(int32_t slot, llvm::Value *act,
                                                                    llvm::Value *presetMs) {
  auto k32 = [&](uint32_t v) { return b_.getInt32(v); };
  StateLoc startL = mc_.layout.instWord(slot), phaseL = mc_.layout.instWord(slot + 1);
  llvm::Value *start = cache_.load(startL), *phase = cache_.load(phaseL);
  llvm::Value *now =
      b_.CreateTrunc(cache_.load(mc_.layout.scalar(Scalar::NowMs)), b_.getInt32Ty(), "now32");
  llvm::Value *idle = b_.CreateICmpEQ(phase, k32(0));
  llvm::Value *startNew = b_.CreateSelect(b_.CreateAnd(act, idle), now, start);
  llvm::Value *timing = b_.CreateSelect(idle, k32(1), phase);
  llvm::Value *el = b_.CreateSub(now, startNew, "elapsed");
  llvm::Value *reached =
      b_.CreateAnd(b_.CreateICmpEQ(timing, k32(1)), b_.CreateICmpUGE(el, presetMs));
  llvm::Value *phaseNew =
      b_.CreateSelect(act, b_.CreateSelect(reached, k32(2), timing), k32(0), "phase");
  cache_.store(startL, startNew);
  cache_.store(phaseL, phaseNew);
  llvm::Value *done = b_.CreateICmpEQ(phaseNew, k32(2));
  llvm::Value *elapsed = b_.CreateSelect(b_.CreateICmpEQ(phaseNew, k32(0)), k32(0),
                                         b_.CreateSelect(done, presetMs, el));
  return {done, elapsed};
}

llvm::Error FunctionEmitter::emitPmcTcBlock(int32_t i) {
  const Stmt &s = prog_.stmts[i];
  const auto &o = s.ops;
  const int32_t slot = prog_.info[i].slot;
  auto k32 = [&](int32_t v) { return b_.getInt32(static_cast<uint32_t>(v)); };
  // pmc::presetMs: a count <= 0 is 0 ms; 32767 * 60000 fits an i32.
  auto preset = [&](llvm::Value *count, llvm::Value *unit) {
    return b_.CreateSelect(b_.CreateICmpSLE(count, k32(0)), k32(0), b_.CreateMul(count, unit));
  };
  // pmc::bcdValue of a register (`width` bytes of it) or a constant as written.
  auto bcd = [&](const Operand &op, int width) -> llvm::Value * {
    if (op.kind == Operand::Kind::Const) return k32(op.value);
    llvm::Value *raw = readInt(op);
    llvm::Value *v = k32(0);
    int32_t scale = 1;
    for (int k = 0; k < 2 * width; ++k) {
      llvm::Value *nib = b_.CreateAnd(b_.CreateLShr(raw, k32(4 * k)), k32(0xF));
      v = b_.CreateAdd(v, b_.CreateMul(nib, k32(scale)));
      scale *= 10;
    }
    return v;
  };
  switch (s.op) {
  case Op::PmcTimer:
  case Op::PmcTimerAddr: {
    if (slot < 0 || slot + 1 >= LJ_INST_WORDS)
      return fail(i, "inst_word slot " + std::to_string(slot) + " out of range");
    llvm::Value *unit;
    if (s.op == Op::PmcTimer) {
      llvm::Value *code = readInt(o[2]);
      unit = k32(static_cast<int32_t>(pmc::tmrDefaultUnit(o[0].value)));
      for (int32_t c = 5; c >= 1; --c)
        unit = b_.CreateSelect(b_.CreateICmpEQ(code, k32(c)),
                               k32(static_cast<int32_t>(pmc::kTmrUnits[c])), unit);
    } else {
      unit = k32(static_cast<int32_t>(pmc::tmrcUnitMs(o[0].value)));
    }
    auto [out, elapsed] = pmcOnDelay(slot, enable(), preset(readInt(o[1]), unit));
    if (s.op == Op::PmcTimerAddr) writeInt(o[2], elapsed, nullptr);
    setOutput(out);
    break;
  }
  case Op::PmcCounter: {
    if (st_.size() < 4) return fail(i, "counter with too few ST entries");
    if (slot < 0 || slot >= LJ_EDGE_SLOTS) return fail(i, "counter edge slot out of range");
    llvm::Value *act = st_.back(), *rst = st_[st_.size() - 2], *down = st_[st_.size() - 3],
                *cn0 = st_[st_.size() - 4];
    st_.resize(st_.size() - 4);
    // CTR follows the counter data type system parameter (reference 6.4), read at run time:
    // in BCD the preset and count are 4 BCD digits (pmc::bcdValue) and the count is written
    // back as the 4 digits of its value.
    const uint32_t typeAt = tp().systemParams.counterFormat;
    const bool byType = o[2].kind == Operand::Kind::Const &&
                        o[2].value == pmc::kCounterSystemType && typeAt; // CTR, not CTRB/CTRC
    llvm::Value *isBcd = b_.getFalse();
    if (byType) {
      llvm::Value *t = cache_.load(mc_.layout.memBytes(typeAt, 1, "counter_type"));
      isBcd = b_.CreateICmpEQ(t, b_.getInt8(TargetProfile::kCounterBcd), "bcd");
    }
    auto bcd4 = [&](llvm::Value *raw) {
      llvm::Value *v = k32(0);
      int32_t scale = 1;
      for (int k = 0; k < 4; ++k, scale *= 10)
        v = b_.CreateAdd(
            v, b_.CreateMul(b_.CreateAnd(b_.CreateLShr(raw, k32(4 * k)), k32(0xF)), k32(scale)));
      return v;
    };
    auto value = [&](llvm::Value *raw) {
      return byType ? b_.CreateSelect(isBcd, bcd4(raw), raw) : raw;
    };
    llvm::Value *pv = value(readInt(o[0])), *cv = value(readInt(o[1]));
    llvm::Value *init = b_.CreateZExt(cn0, b_.getInt32Ty());
    StateLoc prevL = mc_.layout.edge(slot);
    llvm::Value *prev = b_.CreateICmpNE(cache_.load(prevL), b_.getInt8(0));
    llvm::Value *rise = b_.CreateAnd(act, notV(prev), "count");
    llvm::Value *up = b_.CreateSelect(b_.CreateICmpSGE(cv, pv), init, b_.CreateAdd(cv, k32(1)));
    llvm::Value *dn = b_.CreateSelect(b_.CreateICmpSLE(cv, init), pv, b_.CreateSub(cv, k32(1)));
    llvm::Value *counted = b_.CreateSelect(rise, b_.CreateSelect(down, dn, up), cv);
    llvm::Value *next = b_.CreateSelect(rst, b_.CreateSelect(down, pv, init), counted, "cv");
    cache_.store(prevL, b_.CreateZExt(act, b_.getInt8Ty()));
    llvm::Value *written = next;
    if (byType) { // the 4 BCD digits of next (>= 0 in BCD)
      llvm::Value *digits = k32(0), *rest = next;
      for (int k = 0; k < 4; ++k) {
        digits = b_.CreateOr(digits, b_.CreateShl(b_.CreateURem(rest, k32(10)), k32(4 * k)));
        rest = b_.CreateUDiv(rest, k32(10));
      }
      written = b_.CreateSelect(isBcd, digits, next);
    }
    writeInt(o[1], written, nullptr);
    // The value as the register holds it (its width, its area's sign).
    const unsigned width = o[1].width ? o[1].width : tp().area(o[1].area).bytes;
    llvm::Value *stored = written;
    if (width < 4) {
      llvm::Value *t = b_.CreateTrunc(written, b_.getIntNTy(8 * width));
      stored = tp().area(o[1].area).isSigned ? b_.CreateSExt(t, b_.getInt32Ty())
                                             : b_.CreateZExt(t, b_.getInt32Ty());
    }
    stored = value(stored);
    llvm::Value *reached =
        selectBit(down, b_.CreateICmpSLE(stored, init), b_.CreateICmpSGE(stored, pv));
    st_.push_back(b_.CreateAnd(notV(rst), reached, "w1"));
    break;
  }
  case Op::PmcCompareFlags: {
    llvm::Value *en = enable();
    llvm::Value *in = readInt(o[0]), *ref = readInt(o[1]);
    llvm::Value *flags = b_.CreateAnd(readInt(o[2]), k32(~(pmc::kFlagZ | pmc::kFlagN)));
    llvm::Value *z = b_.CreateZExt(b_.CreateICmpEQ(in, ref), b_.getInt32Ty());
    llvm::Value *n = b_.CreateZExt(b_.CreateICmpSLT(in, ref), b_.getInt32Ty());
    flags = b_.CreateOr(flags, b_.CreateOr(z, b_.CreateShl(n, k32(1))));
    writeInt(o[2], flags, en);
    break;
  }
  case Op::BcdCompare: {
    if (st_.size() < 2) return fail(i, "BCD compare with too few ST entries");
    llvm::Value *act = st_.back(), *byt = st_[st_.size() - 2];
    st_.resize(st_.size() - 2);
    auto cond = [&](int width) {
      llvm::Value *in = bcd(o[1], width), *ref = bcd(o[2], width);
      return o[0].value == pmc::kBcdEqual ? b_.CreateICmpEQ(in, ref) : b_.CreateICmpSLE(in, ref);
    };
    llvm::Value *c1 = cond(1), *c2 = cond(2);
    st_.push_back(b_.CreateAnd(act, selectBit(byt, c2, c1), "w1"));
    break;
  }
  case Op::CompareNe: {
    llvm::Value *en = enable();
    setOutput(b_.CreateAnd(en, b_.CreateICmpNE(readInt(o[0]), readInt(o[1]))));
    break;
  }
  case Op::CompareBetween: {
    llvm::Value *en = enable();
    llvm::Value *d1 = readInt(o[0]), *d2 = readInt(o[1]), *x = readInt(o[2]);
    llvm::Value *a = b_.CreateAnd(b_.CreateICmpSLE(d1, x), b_.CreateICmpSLE(x, d2));
    llvm::Value *c = b_.CreateAnd(b_.CreateICmpSLE(d2, x), b_.CreateICmpSLE(x, d1));
    setOutput(b_.CreateAnd(en, b_.CreateOr(a, c)));
    break;
  }
  default:
    return emitFanucArith(i); // fanuc-c's arithmetic (EmitFanucArith.cpp)
  }
  return llvm::Error::success();
}

} // namespace lj::lower

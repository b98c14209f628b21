// Lowering of family Cnc: chapter-6 CNC blocks on F/G words (hnc8-cnc-interface.md 2, 3.1). The
// CNC table of the program's profile (TargetProfile::cncRows, ir/CncTable.h) is interpreted at
// compile time into straight-line IR: constant words go through the image cache, EN guards are
// selects. Only a runtime axis operand (JOGSW, STEPAXIS, JOGVEL, AXEN, AXISMOVE, AXISMVTO, AXLMF2)
// and SPDLBUS1's gear use computed addresses: the index is clamped into range and the store writes
// the old value back when the axis is invalid, so the code stays branch-free (docs/cnc-blocks.md
// "Runtime axis").
#include "lowering/FunctionEmitter.h"

#include "ladderjit/abi.h"

namespace lj::lower {

using cnc::Action;
using cnc::Do;
using cnc::Src;

llvm::Value *FunctionEmitter::cncLoad(Area a, const CncBase &base, int32_t k) {
  if (!base.dyn) return cache_.load(mc_.layout.area(a, base.word + k));
  cache_.flush(); // computed address: nothing cached may be reused across it
  llvm::Value *p0 = mc_.layout.address(b_, state_, mc_.layout.area(a, k));
  llvm::Value *p =
      b_.CreateInBoundsGEP(b_.getInt16Ty(), p0, b_.CreateZExt(base.dyn, b_.getInt64Ty()));
  return b_.CreateLoad(b_.getInt16Ty(), p);
}

void FunctionEmitter::cncUpdate(const CncBase &base, int32_t k,
                                llvm::function_ref<llvm::Value *(llvm::Value *)> f) {
  if (!base.dyn) {
    StateLoc loc = mc_.layout.area(Area::NcControl, base.word + k);
    cache_.store(loc, f(cache_.load(loc)));
    return;
  }
  cache_.flush();
  llvm::Value *p0 = mc_.layout.address(b_, state_, mc_.layout.area(Area::NcControl, k));
  llvm::Value *p =
      b_.CreateInBoundsGEP(b_.getInt16Ty(), p0, b_.CreateZExt(base.dyn, b_.getInt64Ty()));
  llvm::Value *old = b_.CreateLoad(b_.getInt16Ty(), p);
  b_.CreateStore(b_.CreateSelect(base.valid, f(old), old), p);
  cache_.flush();
}

llvm::Value *FunctionEmitter::cncBit(Area a, const CncBase &base, int32_t k, int32_t bit) {
  llvm::Value *w = cncLoad(a, base, k);
  return b_.CreateICmpNE(b_.CreateAnd(w, b_.getInt16(static_cast<uint16_t>(1u << bit))),
                         b_.getInt16(0));
}

namespace {

/// `word` with bit `bit` replaced by `on`.
llvm::Value *withBit(llvm::IRBuilderBase &b, llvm::Value *word, int32_t bit, llvm::Value *on) {
  auto mask = static_cast<uint16_t>(1u << bit);
  llvm::Value *cleared = b.CreateAnd(word, b.getInt16(static_cast<uint16_t>(~mask)));
  return b.CreateOr(cleared, b.CreateShl(b.CreateZExt(on, b.getInt16Ty()), bit));
}

} // namespace

void FunctionEmitter::emitCncAction(int32_t i, const Action &a, const CncBase &base,
                                    llvm::Value *act, llvm::Value *&cond) {
  const Stmt &s = prog_.stmts[i];
  const cnc::Resolved r = cnc::resolve(a, s);
  if (!r.applies) return;
  auto dirOn = [&]() -> llvm::Value * {
    llvm::Value *d = readBit(s.ops[a.dirOp]);
    return a.pol ? d : notV(d);
  };
  auto source = [&]() -> llvm::Value * {
    switch (a.src) {
    case Src::Operand:
      return readInt(s.ops[a.srcOp]);
    case Src::Const:
      return b_.getInt32(static_cast<uint32_t>(a.value));
    case Src::OneShl:
      return b_.getInt32(1u << s.ops[a.srcOp].value);
    case Src::None:
      break;
    }
    return b_.getInt32(0);
  };
  auto keepUnlessAct = [&](llvm::Value *nv, llvm::Value *old) {
    return b_.CreateSelect(act, nv, old);
  };
  switch (a.what) {
  case Do::Level: {
    llvm::Value *on = a.dirOp >= 0 ? b_.CreateAnd(act, dirOn()) : act;
    cncUpdate(base, r.word, [&](llvm::Value *old) { return withBit(b_, old, r.bit, on); });
    return;
  }
  case Do::Ack: {
    llvm::Value *on = b_.CreateAnd(act, cncBit(Area::NcStatus, base, r.auxWord, r.auxBit));
    cncUpdate(base, r.word, [&](llvm::Value *old) { return withBit(b_, old, r.bit, on); });
    return;
  }
  case Do::Jog: {
    llvm::Value *v = b_.CreateSelect(
        act, b_.CreateSelect(dirOn(), b_.getInt16(1), b_.getInt16(0xFFFF)), b_.getInt16(0));
    cncUpdate(base, r.word, [&](llvm::Value *) { return v; });
    return;
  }
  case Do::Write: {
    llvm::Value *v = b_.CreateSExt(source(), b_.getInt64Ty()); // upper words: the sign
    for (int k = 0; k < a.width; ++k) {
      llvm::Value *part = b_.CreateTrunc(b_.CreateLShr(v, 16 * k), b_.getInt16Ty());
      cncUpdate(base, r.word + k, [&](llvm::Value *old) { return keepUnlessAct(part, old); });
    }
    return;
  }
  case Do::Field: {
    auto mask = static_cast<uint16_t>(((1u << a.width) - 1u) << r.bit);
    llvm::Value *v = b_.CreateAnd(b_.CreateShl(b_.CreateTrunc(source(), b_.getInt16Ty()), r.bit),
                                  b_.getInt16(mask));
    cncUpdate(base, r.word, [&](llvm::Value *old) {
      llvm::Value *nv =
          b_.CreateOr(b_.CreateAnd(old, b_.getInt16(static_cast<uint16_t>(~mask))), v);
      return keepUnlessAct(nv, old);
    });
    return;
  }
  case Do::Status:
    cond = cncBit(Area::NcStatus, base, r.word, r.bit);
    return;
  case Do::Push:
    return; // emitCncBlock pushes it
  case Do::ModeSet: {
    // One-hot 1..64 -> its code (kModeCode); anything else requests nothing.
    llvm::Value *v = source();
    llvm::Value *code = b_.getInt16(0), *hot = b_.getFalse();
    for (int k = 0; k < 7; ++k) {
      llvm::Value *is = b_.CreateICmpEQ(v, b_.getInt32(1u << k));
      code = b_.CreateSelect(is, b_.getInt16(static_cast<uint16_t>(tp().modeCode[k])), code);
      hot = b_.CreateOr(hot, is);
    }
    llvm::Value *en = b_.CreateAnd(act, hot);
    llvm::Value *v16 = b_.CreateTrunc(v, b_.getInt16Ty());
    cncUpdate(base, r.auxWord, [&](llvm::Value *old) {
      return b_.CreateSelect(en, b_.CreateOr(b_.CreateAnd(old, b_.getInt16(0xFF80)), v16), old);
    });
    cncUpdate(base, r.word, [&](llvm::Value *old) {
      return b_.CreateSelect(en, b_.CreateOr(b_.CreateAnd(old, b_.getInt16(0xFFF0)), code), old);
    });
    return;
  }
  case Do::ModeGet: {
    llvm::Value *code = b_.CreateAnd(cncLoad(Area::NcStatus, base, r.word), b_.getInt16(0xF));
    llvm::Value *v = b_.getInt32(0);
    for (int k = 0; k < 7; ++k)
      v = b_.CreateSelect(
          b_.CreateICmpEQ(code, b_.getInt16(static_cast<uint16_t>(tp().modeCode[k]))),
          b_.getInt32(1u << k), v);
    writeInt(s.ops[a.srcOp], v, act);
    return;
  }
  case Do::UserOut: {
    llvm::Value *lo = b_.CreateZExt(cncLoad(Area::NcStatus, base, r.word), b_.getInt32Ty());
    llvm::Value *hi = b_.CreateZExt(cncLoad(Area::NcStatus, base, r.word + 1), b_.getInt32Ty());
    llvm::Value *u = b_.CreateOr(lo, b_.CreateShl(hi, 16));
    for (int k = 0; k < 4; ++k) {
      Operand byte = s.ops[a.srcOp];
      byte.index += k; // bit k of the user output -> byte k/8, bit k%8
      writeInt(byte, b_.CreateLShr(u, 8 * k), act);
    }
    return;
  }
  case Do::Spindle:
    emitCncSpindle(i, a, base, act);
    return;
  }
}

void FunctionEmitter::emitCncSpindle(int32_t i, const Action &a, const CncBase &base,
                                     llvm::Value *act) {
  const Stmt &s = prog_.stmts[i];
  const cnc::Resolved r = cnc::resolve(a, s);
  llvm::Type *i64 = b_.getInt64Ty();
  llvm::Value *lo = b_.CreateZExt(cncLoad(Area::NcStatus, base, r.auxWord), b_.getInt32Ty());
  llvm::Value *hi = b_.CreateZExt(cncLoad(Area::NcStatus, base, r.auxWord + 1), b_.getInt32Ty());
  llvm::Value *sval = b_.CreateSExt(b_.CreateOr(lo, b_.CreateShl(hi, 16)), i64);
  llvm::Value *ovr = b_.CreateSExt(cncLoad(Area::NcControl, base, r.aux2Word), i64);
  // |S * ovr| < 2^47: exact in 64 bits; sdiv by 100 truncates toward zero.
  llvm::Value *cmd = b_.CreateSDiv(b_.CreateMul(sval, ovr), b_.getInt64(100));
  llvm::Value *write = act;
  if (a.gearOp >= 0) {
    // Gear g uses P[pbase + 5(g-1) ..]; out of range: nothing written, fault, output 0.
    llvm::Value *gear = b_.CreateSExt(readInt(s.ops[a.gearOp]), i64);
    const int64_t pbase = s.ops[a.pOp].index;
    llvm::Value *blk = b_.CreateAdd(
        b_.getInt64(pbase), b_.CreateMul(b_.getInt64(5), b_.CreateSub(gear, b_.getInt64(1))));
    llvm::Value *ok =
        b_.CreateAnd(b_.CreateICmpSGE(gear, b_.getInt64(1)),
                     b_.CreateICmpSLT(b_.CreateAdd(blk, b_.getInt64(4)), b_.getInt64(LJ_P_COUNT)));
    llvm::Value *safe = b_.CreateSelect(ok, blk, b_.getInt64(pbase)); // pbase + 4 is verified
    cache_.flush();
    llvm::Value *p0 = mc_.layout.address(b_, state_, mc_.layout.area(Area::Param, 0));
    auto loadP = [&](int k) {
      llvm::Value *idx = b_.CreateAdd(safe, b_.getInt64(k));
      return b_.CreateSExt(
          b_.CreateLoad(b_.getInt32Ty(), b_.CreateInBoundsGEP(b_.getInt32Ty(), p0, idx)), i64);
    };
    llvm::Value *maxRpm = loadP(0), *num = loadP(3), *den = loadP(4);
    // cmd * num wraps in 64 bits; den = 0: no ratio; INT64_MIN / -1 = INT64_MIN.
    llvm::Value *prod = b_.CreateMul(cmd, num);
    llvm::Value *denZero = b_.CreateICmpEQ(den, b_.getInt64(0));
    llvm::Value *ovf = b_.CreateAnd(b_.CreateICmpEQ(prod, b_.getInt64(INT64_MIN)),
                                    b_.CreateICmpEQ(den, b_.getInt64(-1)));
    llvm::Value *safeDen = b_.CreateSelect(b_.CreateOr(denZero, ovf), b_.getInt64(1), den);
    cmd = b_.CreateSelect(denZero, cmd, b_.CreateSDiv(prod, safeDen));
    llvm::Value *cap = b_.CreateMul(maxRpm, b_.getInt64(1000)); // rpm -> 0.001 rpm
    llvm::Value *capped = b_.CreateSelect(
        b_.CreateICmpSGT(cmd, cap), cap,
        b_.CreateSelect(b_.CreateICmpSLT(cmd, b_.CreateNeg(cap)), b_.CreateNeg(cap), cmd));
    cmd = b_.CreateSelect(b_.CreateICmpSGT(maxRpm, b_.getInt64(0)), capped, cmd);
    llvm::Value *fault = b_.CreateAnd(act, notV(ok));
    StateLoc fi = mc_.layout.scalar(Scalar::FaultIndex);
    cache_.store(fi, b_.CreateAdd(cache_.load(fi), b_.CreateZExt(fault, b_.getInt32Ty())));
    if (!st_.empty()) st_.back() = b_.CreateAnd(st_.back(), notV(fault));
    write = b_.CreateAnd(act, ok);
  }
  for (int k = 0; k < 2; ++k) {
    llvm::Value *part = b_.CreateTrunc(b_.CreateLShr(cmd, 16 * k), b_.getInt16Ty());
    cncUpdate(base, r.word + k,
              [&](llvm::Value *old) { return b_.CreateSelect(write, part, old); });
  }
}

llvm::Error FunctionEmitter::emitCncBlock(int32_t i) {
  const Stmt &s = prog_.stmts[i];
  const cnc::CncRow *row = tp().cncRow(s.op);
  const CncLayout &lay = tp().cnc;
  if (!row) return fail(i, "no lowering for this instruction");
  const InstrInfo &info = instrInfo(s.op);

  // Word base: axis A*80, channel 2560+C*80, or absolute (hnc8-cnc-interface.md 0).
  CncBase base;
  if (row->base == cnc::Base::Channel) {
    base.word = lay.channelBase + s.ops[row->where].value * lay.blockWords;
  } else if (row->base == cnc::Base::Axis) {
    if (!cnc::runtimeAxis(*row, s)) {
      base.word = s.ops[row->where].value * lay.blockWords;
    } else {
      llvm::Value *axis = readInt(s.ops[row->where]);
      base.valid = b_.CreateICmpULT(axis, b_.getInt32(lay.axes), "axis.ok");
      base.dyn = b_.CreateMul(b_.CreateSelect(base.valid, axis, b_.getInt32(0)),
                              b_.getInt32(lay.blockWords));
    }
  }

  if (info.stack == StackRule::Push) { // AXRDY: a status source pushed like a contact
    cnc::Resolved r = cnc::resolve(row->act[0], s);
    st_.push_back(cncBit(Area::NcStatus, base, r.word, r.bit));
    return llvm::Error::success();
  }

  llvm::Value *act = enable();
  if (base.dyn) {
    // A bad runtime axis writes nothing; when the block would have written it counts one fault
    // and gives output 0 (same rule as the interpreter, docs/cnc-blocks.md).
    bool always = false, onAct = false;
    for (int k = 0; k < row->count; ++k) {
      always = always || cnc::writesOn(row->act[k], false);
      onAct = onAct || cnc::writesOn(row->act[k], true);
    }
    llvm::Value *writes = always ? b_.getTrue() : onAct ? act : b_.getFalse();
    llvm::Value *fault = b_.CreateAnd(writes, notV(base.valid));
    StateLoc fi = mc_.layout.scalar(Scalar::FaultIndex);
    cache_.store(fi, b_.CreateAdd(cache_.load(fi), b_.CreateZExt(fault, b_.getInt32Ty())));
    if (!st_.empty()) st_.back() = b_.CreateAnd(st_.back(), notV(fault));
  }
  llvm::Value *cond = b_.getFalse();
  for (int k = 0; k < row->count; ++k) emitCncAction(i, row->act[k], base, act, cond);
  if (info.output == OutputRule::Compare) setOutput(b_.CreateAnd(act, cond));
  return llvm::Error::success();
}

} // namespace lj::lower

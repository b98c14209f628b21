// Lowering of family Nc: NC services (chapter-4 CNC blocks, host callbacks, stateful chapter-6
// blocks), written from the same rules as interp/InterpNc.cpp (docs/dialect-notes.md
// "NC services"). F/G work is straight-line selects; only a host call (or MPGSET's runtime axis)
// branches, after flushing the image cache.
#include "ir/Profile.h"
#include "lowering/FunctionEmitter.h"

#include "ladderjit/abi.h"

#include <cstddef>

namespace lj::lower {

namespace {

/// The target's CNC words (profile): FC[k] / GC[k] = F/G[channelBase + blockWords * ch + k]
/// (hnc8-cnc-interface.md 1.3, 1.4).
int32_t chanBase(const CncLayout &cnc, int32_t ch) { return cnc.channelBase + cnc.blockWords * ch; }

} // namespace

llvm::Value *FunctionEmitter::ncRead(Area a, int32_t index) {
  Operand op;
  op.kind = Operand::Kind::Reg;
  op.area = a;
  op.index = index;
  return readInt(op);
}

void FunctionEmitter::ncWrite(Area a, int32_t index, llvm::Value *v, llvm::Value *en) {
  Operand op;
  op.kind = Operand::Kind::Reg;
  op.area = a;
  op.index = index;
  writeInt(op, v, en);
}

void FunctionEmitter::ncStoreGAt(llvm::Value *index, llvm::Value *v) {
  llvm::Value *base = mc_.layout.address(b_, state_, mc_.layout.area(Area::NcControl, 0));
  llvm::Value *addr =
      b_.CreateInBoundsGEP(b_.getInt16Ty(), base, b_.CreateZExt(index, b_.getInt64Ty()));
  b_.CreateStore(b_.CreateTrunc(v, b_.getInt16Ty()), addr);
}

FunctionEmitter::NcCall FunctionEmitter::ncHostCall(llvm::Value *cond, size_t member,
                                                    bool returnsValue,
                                                    llvm::ArrayRef<llvm::Value *> args,
                                                    unsigned outs) {
  llvm::Type *i32 = b_.getInt32Ty();
  llvm::Type *ptr = b_.getPtrTy();
  NcCall r{b_.getFalse(), b_.getInt32(0), {b_.getInt32(0), b_.getInt32(0)}};
  if (auto *c = llvm::dyn_cast<llvm::ConstantInt>(cond); c && c->isZero()) return r;
  // Out-parameter slots live in the entry block (one pair per function).
  for (unsigned k = 0; k < outs; ++k)
    if (!ncOut_[k]) {
      llvm::IRBuilder<> eb(&fn_->getEntryBlock(), fn_->getEntryBlock().begin());
      ncOut_[k] = eb.CreateAlloca(i32, nullptr, "host.out");
    }

  cache_.flush(); // the branches below end the straight-line region
  llvm::Value *host =
      b_.CreateLoad(ptr, mc_.layout.address(b_, state_, mc_.layout.scalar(Scalar::Host)), "host");
  llvm::BasicBlock *from = b_.GetInsertBlock();
  llvm::BasicBlock *haveHost = newBlock("host");
  llvm::BasicBlock *doCall = newBlock("host.call");
  llvm::BasicBlock *join = newBlock("host.done");
  b_.CreateCondBr(b_.CreateAnd(cond, b_.CreateIsNotNull(host)), haveHost, join);

  b_.SetInsertPoint(haveHost);
  llvm::Value *fn =
      b_.CreateLoad(ptr, b_.CreateConstInBoundsGEP1_64(b_.getInt8Ty(), host, member), "callback");
  b_.CreateCondBr(b_.CreateIsNotNull(fn), doCall, join);

  b_.SetInsertPoint(doCall);
  llvm::Value *ctx = b_.CreateLoad(
      ptr, b_.CreateConstInBoundsGEP1_64(b_.getInt8Ty(), host, offsetof(lj_host, ctx)), "ctx");
  std::vector<llvm::Type *> params{ptr};
  std::vector<llvm::Value *> callArgs{ctx};
  for (llvm::Value *a : args) {
    params.push_back(i32);
    callArgs.push_back(a);
  }
  for (unsigned k = 0; k < outs; ++k) {
    b_.CreateStore(b_.getInt32(0), ncOut_[k]); // a host that writes nothing leaves 0
    params.push_back(ptr);
    callArgs.push_back(ncOut_[k]);
  }
  auto *ft = llvm::FunctionType::get(returnsValue ? i32 : b_.getVoidTy(), params, false);
  llvm::CallInst *call = b_.CreateCall(ft, fn, callArgs);
  llvm::Value *ret = returnsValue ? static_cast<llvm::Value *>(call) : b_.getInt32(0);
  llvm::Value *outVals[2] = {b_.getInt32(0), b_.getInt32(0)};
  for (unsigned k = 0; k < outs; ++k) outVals[k] = b_.CreateLoad(i32, ncOut_[k]);
  b_.CreateBr(join);

  b_.SetInsertPoint(join);
  auto phi = [&](llvm::Type *ty, llvm::Value *none, llvm::Value *got) {
    llvm::PHINode *p = b_.CreatePHI(ty, 3);
    p->addIncoming(none, from);
    p->addIncoming(none, haveHost);
    p->addIncoming(got, doCall);
    return p;
  };
  r.called = phi(b_.getInt1Ty(), b_.getFalse(), b_.getTrue());
  if (returnsValue) r.ret = phi(i32, b_.getInt32(0), ret);
  for (unsigned k = 0; k < outs; ++k) r.out[k] = phi(i32, b_.getInt32(0), outVals[k]);
  return r;
}

llvm::Error FunctionEmitter::emitNcBlock(int32_t i) {
  const Stmt &s = prog_.stmts[i];
  const StmtInfo &info = prog_.info[i];
  const Operand *o = s.ops.data();
  const CncLayout &kCnc = tp().cnc;
  auto k32 = [&](int32_t v) { return b_.getInt32(static_cast<uint32_t>(v)); };
  switch (s.op) {
  case Op::MCodeGet: {
    // out = EN and one of FC[48..55] holds the M code (functions-1 3.1); nothing written.
    llvm::Value *en = enable();
    int32_t cb = chanBase(kCnc, o[0].value);
    llvm::Value *pending = b_.getFalse();
    for (int k = 0; k < kCnc.mCodeSlots; ++k)
      pending =
          b_.CreateOr(pending, b_.CreateICmpEQ(ncRead(Area::NcStatus, cb + kCnc.mCodeWord + k),
                                               k32(o[1].value)));
    setOutput(b_.CreateAnd(en, pending));
    return llvm::Error::success();
  }
  case Op::MCodeAck: {
    llvm::Value *en = enable();
    int32_t cb = chanBase(kCnc, o[0].value);
    for (int k = 0; k < kCnc.mCodeSlots; ++k) {
      llvm::Value *hit =
          b_.CreateICmpEQ(ncRead(Area::NcStatus, cb + kCnc.mCodeWord + k), k32(o[1].value));
      ncWrite(Area::NcControl, cb + kCnc.mCodeWord + k, k32(o[1].value), b_.CreateAnd(en, hit));
    }
    return llvm::Error::success();
  }
  case Op::TCodeGet: {
    llvm::Value *en = enable();
    llvm::Value *t = ncRead(Area::NcStatus, chanBase(kCnc, o[0].value) + kCnc.tCodeWord);
    llvm::Value *got = b_.CreateAnd(en, b_.CreateICmpNE(t, k32(-1)));
    if (o[1].kind == Operand::Kind::Const) {
      setOutput(b_.CreateAnd(got, b_.CreateICmpEQ(t, k32(o[1].value))));
    } else {
      writeInt(o[1], t, got);
      setOutput(got);
    }
    return llvm::Error::success();
  }
  case Op::TCodeAck: {
    int32_t cb = chanBase(kCnc, o[0].value);
    ncWrite(Area::NcControl, cb + kCnc.tCodeWord, ncRead(Area::NcStatus, cb + kCnc.tCodeWord),
            enable());
    return llvm::Error::success();
  }
  case Op::HandwheelPulse:
    ncHostCall(enable(), offsetof(lj_host, mpg_input), false, {k32(o[1].value), readInt(o[0])});
    return llvm::Error::success();
  case Op::TempSensor: {
    // raw: the signed 16-bit AD word X[n] (low byte), X[n+1] (high byte).
    int32_t x = o[1].index, p = o[3].index;
    llvm::Value *word =
        b_.CreateOr(ncRead(Area::Input, x), b_.CreateShl(ncRead(Area::Input, x + 1), 8));
    llvm::Value *raw = b_.CreateSExt(b_.CreateTrunc(word, b_.getInt16Ty()), b_.getInt32Ty());
    ncHostCall(enable(), offsetof(lj_host, temp_input), false,
               {k32(o[0].value), raw, k32(o[2].value), ncRead(Area::Param, p),
                ncRead(Area::Param, p + 1), ncRead(Area::Param, p + 2),
                ncRead(Area::Param, p + 3)});
    return llvm::Error::success();
  }
  case Op::PartCount:
  case Op::PartClear: {
    llvm::Value *en = enable();
    int32_t g =
        chanBase(kCnc, o[0].value) + kCnc.partCountWord; // GC[19] part count (functions-2 2.19)
    llvm::Value *v =
        s.op == Op::PartCount ? b_.CreateAdd(ncRead(Area::NcControl, g), k32(1)) : k32(0);
    ncWrite(Area::NcControl, g, v, en);
    setOutput(en);
    return llvm::Error::success();
  }
  case Op::HeadSensors: {
    llvm::Value *en = enable();
    if (o[1].value == 0)
      for (int32_t k = 0; k < o[0].value; ++k)
        ncWrite(Area::DWord, o[2].index + k, ncRead(Area::NcControl, 3080 + k), en);
    return llvm::Error::success();
  }
  case Op::VarGet: {
    llvm::Value *en = enable();
    NcCall c = ncHostCall(en, offsetof(lj_host, var_get), true,
                          {k32(o[0].value), readInt(o[1]), k32(o[2].value)}, 1);
    writeInt(o[3], c.out[0], b_.CreateAnd(c.called, b_.CreateICmpNE(c.ret, k32(0))));
    setOutput(en);
    return llvm::Error::success();
  }
  case Op::VarSet: {
    llvm::Value *en = enable();
    ncHostCall(en, offsetof(lj_host, var_set), true,
               {k32(o[0].value), readInt(o[1]), k32(o[2].value), readInt(o[3])});
    setOutput(en);
    return llvm::Error::success();
  }
  case Op::ToolVectorOn:
  case Op::ToolVectorOff: {
    llvm::Value *en = enable();
    ncHostCall(en, offsetof(lj_host, tool_vector), false,
               {k32(o[0].value), k32(s.op == Op::ToolVectorOn ? 1 : 0)});
    setOutput(en);
    return llvm::Error::success();
  }
  case Op::PanelDisplay: {
    llvm::Value *en = enable();
    llvm::Value *v = readInt(o[0]);
    NcCall c = ncHostCall(en, offsetof(lj_host, nixie_encode), true, {v, k32(o[1].value)});
    llvm::Value *code =
        b_.CreateAnd(b_.CreateSelect(c.called, c.ret, v), k32(o[1].value ? 0xFFFF : 0xFF));
    writeInt(o[2], code, en);
    if (o[1].value && tp().area(o[2].area).bytes == 1)
      ncWrite(o[2].area, o[2].index + 1, b_.CreateLShr(code, 8), en);
    setOutput(en);
    return llvm::Error::success();
  }
  case Op::ToolInUse:
    ncHostCall(enable(), offsetof(lj_host, tool_in_use), false, {readInt(o[0]), readInt(o[1])});
    return llvm::Error::success();
  case Op::ToolLife: {
    if (info.slot < 0 || info.slot + 1 >= LJ_INST_WORDS)
      return fail(i, "inst_word slot " + std::to_string(info.slot) + " out of range");
    // [slot] installs counted, [slot + 1] previous ACT; the response is written every time.
    llvm::Value *en = enable();
    StateLoc countLoc = mc_.layout.instWord(info.slot),
             prevLoc = mc_.layout.instWord(info.slot + 1);
    llvm::Value *count = cache_.load(countLoc);
    llvm::Value *rise = b_.CreateAnd(en, b_.CreateICmpEQ(cache_.load(prevLoc), k32(0)));
    cache_.store(prevLoc, b_.CreateZExt(en, b_.getInt32Ty()));
    llvm::Value *next = b_.CreateAdd(count, k32(1));
    llvm::Value *reached = b_.CreateAnd(rise, b_.CreateICmpSGE(next, k32(o[1].value)));
    llvm::Value *nc = b_.CreateSelect(rise, b_.CreateSelect(reached, k32(0), next), count);
    cache_.store(countLoc, nc);
    writeInt(o[2], b_.CreateZExt(reached, b_.getInt32Ty()), nullptr);
    return llvm::Error::success();
  }
  case Op::ToolSelect: {
    NcCall c = ncHostCall(enable(), offsetof(lj_host, tool_select), true,
                          {readInt(o[0]), readInt(o[1])}, 2);
    llvm::Value *found = b_.CreateAnd(c.called, b_.CreateICmpNE(c.ret, k32(0)));
    writeInt(o[3], c.out[0], found);
    writeInt(o[2], c.out[1], b_.CreateAnd(c.called, notV(found)));
    setOutput(found);
    return llvm::Error::success();
  }
  case Op::SpindleAnalog: {
    // rpm = FC[10+2sp] (32 bits, low word first); DA -> reference operand and GC[10+2sp].
    int32_t cb = chanBase(kCnc, o[0].value), w = cb + 10 + 2 * o[1].value;
    llvm::Value *lo = b_.CreateAnd(ncRead(Area::NcStatus, w), k32(0xFFFF));
    llvm::Value *rpm = b_.CreateOr(lo, b_.CreateShl(ncRead(Area::NcStatus, w + 1), 16));
    NcCall c = ncHostCall(enable(), offsetof(lj_host, spindle_da), true,
                          {k32(o[0].value), k32(o[1].value), rpm, readInt(o[2]), k32(o[4].index)});
    writeInt(o[3], c.ret, c.called);
    ncWrite(Area::NcControl, w, c.ret, c.called);
    ncWrite(Area::NcControl, w + 1, b_.CreateLShr(c.ret, 16), c.called);
    return llvm::Error::success();
  }
  case Op::SlaveHomingEnable:
    ncHostCall(b_.getTrue(), offsetof(lj_host, slave_home), false,
               {k32(o[0].value), b_.CreateZExt(enable(), b_.getInt32Ty())});
    return llvm::Error::success();
  case Op::HandwheelSet:
    emitMpgSet(i);
    return llvm::Error::success();
  case Op::MagazineRotate:
    if (st_.size() < 5) return fail(i, "MagazineRotate with fewer than 5 ST entries");
    emitRot(i);
    return llvm::Error::success();
  case Op::RaiseEvent:
  case Op::SaveRetained: {
    if (info.slot < 0 || info.slot >= LJ_EDGE_SLOTS)
      return fail(i, "edge slot " + std::to_string(info.slot) + " out of range");
    llvm::Value *en = enable();
    llvm::Value *rise = edge(info.slot, en).first;
    if (s.op == Op::SaveRetained) {
      ncHostCall(rise, offsetof(lj_host, save_data), false, {});
      return llvm::Error::success();
    }
    // G[3040 + n/16] bit n%16 := ACT; the host hears of the rising edge.
    int32_t n = o[0].value;
    StateLoc loc = mc_.layout.area(Area::NcControl, 3040 + n / 16);
    llvm::Value *old = cache_.load(loc);
    auto mask = static_cast<uint16_t>(1u << (n % 16));
    llvm::Value *nv = b_.CreateOr(b_.CreateAnd(old, b_.getInt16(static_cast<uint16_t>(~mask))),
                                  b_.CreateShl(b_.CreateZExt(en, b_.getInt16Ty()), n % 16));
    cache_.store(loc, nv);
    ncHostCall(rise, offsetof(lj_host, event), false, {k32(n)});
    return llvm::Error::success();
  }
  default:
    return fail(i, "no lowering for this instruction");
  }
}

void FunctionEmitter::emitMpgSet(int32_t i) {
  const Stmt &s = prog_.stmts[i];
  llvm::Value *en = enable();
  llvm::Value *axis = readInt(s.ops[1]);
  // An axis outside 0..31: nothing happens, output 0, fault_index counts it (DIALECT.md 4).
  llvm::Value *bad = b_.CreateAnd(en, b_.CreateICmpUGT(axis, b_.getInt32(31)));
  StateLoc fi = mc_.layout.scalar(Scalar::FaultIndex);
  cache_.store(fi, b_.CreateAdd(cache_.load(fi), b_.CreateZExt(bad, b_.getInt32Ty())));
  if (!st_.empty()) st_.back() = b_.CreateAnd(st_.back(), notV(bad));
  llvm::Value *ok = b_.CreateAnd(en, notV(bad));
  llvm::Value *ovr = readInt(s.ops[2]);
  if (auto *c = llvm::dyn_cast<llvm::ConstantInt>(ok); c && c->isZero()) return;

  cache_.flush(); // GA[k] below has a runtime address
  llvm::BasicBlock *set = newBlock("mpg.set");
  llvm::BasicBlock *done = newBlock("mpg.done");
  b_.CreateCondBr(ok, set, done);
  b_.SetInsertPoint(set);
  llvm::Value *ga = b_.CreateMul(axis, b_.getInt32(80));
  ncStoreGAt(b_.CreateAdd(ga, b_.getInt32(9)), ovr); // GA[9] = multiplier
  NcCall c = ncHostCall(b_.getTrue(), offsetof(lj_host, mpg_delta), true,
                        {b_.getInt32(static_cast<uint32_t>(s.ops[0].value))});
  llvm::BasicBlock *store = newBlock("mpg.pulses");
  b_.CreateCondBr(c.called, store, done);
  b_.SetInsertPoint(store);
  ncStoreGAt(b_.CreateAdd(ga, b_.getInt32(10)), c.ret); // GA[10/11] = pulses, low word first
  ncStoreGAt(b_.CreateAdd(ga, b_.getInt32(11)), b_.CreateLShr(c.ret, 16));
  b_.CreateBr(done);
  b_.SetInsertPoint(done);
}

void FunctionEmitter::emitRot(int32_t i) {
  // hnc8-cnc-interface.md 2 #59, in 64 bits so no difference can overflow.
  const Stmt &s = prog_.stmts[i];
  llvm::Value *in[5];
  for (int k = 4; k >= 0; --k) {
    in[k] = st_.back(); // in5 is ST0, in1 (ACT) the deepest
    st_.pop_back();
  }
  llvm::Type *i64 = b_.getInt64Ty();
  llvm::Value *n = b_.getInt64(static_cast<uint64_t>(s.ops[0].value));
  auto modN = [&](llvm::Value *x) {
    llvm::Value *r = b_.CreateSRem(x, n);
    return b_.CreateSelect(b_.CreateICmpSLT(r, b_.getInt64(0)), b_.CreateAdd(r, n), r);
  };
  llvm::Value *base = b_.CreateZExt(in[1], i64);
  llvm::Value *c = b_.CreateSub(b_.CreateSExt(readInt(s.ops[1]), i64), base);
  llvm::Value *t = b_.CreateSub(b_.CreateSExt(readInt(s.ops[2]), i64), base);
  llvm::Value *fwd = modN(b_.CreateSub(t, c)), *rev = modN(b_.CreateSub(c, t));
  llvm::Value *reverse = b_.CreateAnd(in[2], b_.CreateICmpSLT(rev, fwd)); // a tie goes forward
  llvm::Value *steps = b_.CreateSelect(reverse, rev, fwd);
  llvm::Value *before = b_.CreateSelect(reverse, modN(b_.CreateAdd(t, b_.getInt64(1))),
                                        modN(b_.CreateAdd(b_.CreateSub(t, b_.getInt64(1)), n)));
  llvm::Value *steps4 = b_.CreateSelect(b_.CreateICmpSGT(steps, b_.getInt64(0)),
                                        b_.CreateSub(steps, b_.getInt64(1)), b_.getInt64(0));
  steps = b_.CreateSelect(in[3], steps4, steps);
  llvm::Value *tp = b_.CreateSelect(in[3], before, t);
  llvm::Value *result = b_.CreateSelect(in[4], steps, b_.CreateAdd(tp, base));
  writeInt(s.ops[3], b_.CreateTrunc(result, b_.getInt32Ty()), in[0]);
  st_.push_back(b_.CreateAnd(in[0], reverse)); // ACT = 0: nothing written, output 0
}

} // namespace lj::lower

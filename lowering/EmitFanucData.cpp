// Lowering of the FANUC transfer, search, conversion and flow operations (fanuc-b rows of
// ir/OpTable.h; twin of interp/InterpFanucData.cpp, whose file comment gives the input and W1
// rules). Static byte accesses go through the ImageCache; the table accesses of XMOVB and DSCHB
// use computed addresses (the cache is flushed around them) with alignment 1, since a FANUC
// word may start at any byte (reference 3.1).
#include "lowering/EmitBcd.h"
#include "lowering/FunctionEmitter.h"

#include "ladderjit/abi.h"

#include <llvm/IR/Constants.h>
#include <llvm/IR/GlobalVariable.h>
#include <llvm/IR/Intrinsics.h>

#include <algorithm>

namespace lj::lower {

namespace {

/// Bytes from operand `o` to the end of the range of its area it lies in.
int64_t roomAfter(const TargetProfile &tp, const Operand &o) {
  const AreaInfo &ai = tp.area(o.area);
  const int64_t end = o.index < ai.count ? ai.count : int64_t{ai.upperLo} + ai.upperCount;
  return end - o.index;
}

} // namespace

std::vector<llvm::Value *> FunctionEmitter::fdTake(size_t k) {
  std::vector<llvm::Value *> in(k);
  for (size_t j = 0; j < k; ++j) in[j] = st_[st_.size() - 1 - j];
  st_.resize(st_.size() - (k - 1));
  return in;
}

void FunctionEmitter::fdW1(int32_t slot, llvm::Value *act, llvm::Value *rst, llvm::Value *err) {
  StateLoc loc = mc_.layout.edge(slot);
  llvm::Value *held = b_.CreateICmpNE(cache_.load(loc), b_.getInt8(0));
  llvm::Value *w = b_.CreateAnd(selectBit(act, err, held), notV(rst));
  cache_.store(loc, b_.CreateZExt(w, b_.getInt8Ty()));
  st_.back() = w;
}

llvm::Value *FunctionEmitter::fdLoad(const Operand &o, int32_t k, unsigned width) {
  Operand c = o;
  c.index += k;
  return cache_.load(areaLoc(c, width));
}

void FunctionEmitter::fdStore(const Operand &o, int32_t k, unsigned width, llvm::Value *v,
                              llvm::Value *en) {
  Operand c = o;
  c.index += k;
  StateLoc loc = areaLoc(c, width);
  llvm::Value *nv = b_.CreateZExtOrTrunc(v, loc.type);
  if (en) nv = b_.CreateSelect(en, nv, cache_.load(loc));
  cache_.store(loc, nv);
}

llvm::Value *FunctionEmitter::fdAddr(const Operand &o, llvm::Value *dyn) {
  llvm::Value *p = b_.CreateConstInBoundsGEP1_64(b_.getInt8Ty(), state_, readOffset(o));
  return b_.CreateInBoundsGEP(b_.getInt8Ty(), p, dyn);
}

llvm::Error FunctionEmitter::emitFanucData(int32_t i) {
  const Stmt &s = prog_.stmts[i];
  const int32_t slot = prog_.info[i].slot;
  const StateKind sk = instrInfo(s.op).state;
  if (sk == StateKind::Edge && (slot < 0 || slot >= LJ_EDGE_SLOTS))
    return fail(i, "edge slot " + std::to_string(slot) + " out of range");
  const size_t need = s.op == Op::CommonCoil ? 1 : instrInfo(s.op).inputs;
  if (st_.size() < need) return fail(i, "too few ST entries for its inputs");
  switch (s.op) {
  case Op::ParityCheck: {
    auto in = fdTake(3); // ACT, RST, O.E
    llvm::Value *byte = fdLoad(s.ops[0], 0, 1);
    llvm::Value *ones = b_.CreateUnaryIntrinsic(llvm::Intrinsic::ctpop, byte);
    llvm::Value *odd = b_.CreateTrunc(ones, b_.getInt1Ty());
    // O.E = 1: an even count is the error; O.E = 0: an odd count.
    fdW1(slot, in[0], in[1], b_.CreateXor(odd, in[2]));
    break;
  }
  case Op::ShiftWord: {
    auto in = fdTake(4); // ACT, RST, CONT, DIR
    llvm::Value *v = fdLoad(s.ops[0], 0, 2);
    llvm::Value *right = in[3];
    llvm::Value *r = b_.CreateSelect(right, b_.CreateLShr(v, 1), b_.CreateShl(v, 1));
    llvm::Value *out =
        b_.CreateTrunc(b_.CreateSelect(right, v, b_.CreateLShr(v, 15)), b_.getInt1Ty());
    r = b_.CreateSelect(in[2], b_.CreateOr(r, v), r);
    fdStore(s.ops[0], 0, 2, r, in[0]);
    fdW1(slot, in[0], in[1], out);
    break;
  }
  case Op::BcdDecode: {
    llvm::Value *v = fdLoad(s.ops[0], 0, 1);
    llvm::Value *m =
        b_.CreateICmpEQ(b_.CreateAnd(v, b_.getInt8(static_cast<uint8_t>(s.ops[2].value))),
                        b_.getInt8(static_cast<uint8_t>(s.ops[1].value)));
    st_.back() = b_.CreateAnd(st_.back(), m);
    break;
  }
  case Op::GroupDecode: {
    llvm::Value *act = st_.back();
    llvm::Value *delta = b_.CreateSub(b_.CreateSExt(readInt(s.ops[0]), b_.getInt64Ty()),
                                      b_.getInt64(static_cast<uint64_t>(int64_t{s.ops[1].value})));
    for (int32_t j = 0; j < s.ops[2].value; ++j) {
      llvm::Value *rel = b_.CreateSub(delta, b_.getInt64(static_cast<uint64_t>(8 * j)));
      llvm::Value *hit = b_.CreateAnd(act, b_.CreateICmpULT(rel, b_.getInt64(8)));
      llvm::Value *bit = b_.CreateShl(
          b_.getInt8(1), b_.CreateAnd(b_.CreateTrunc(rel, b_.getInt8Ty()), b_.getInt8(7)));
      fdStore(s.ops[3], j, 1, b_.CreateSelect(hit, bit, b_.getInt8(0)), nullptr);
    }
    break;
  }
  case Op::BcdConvert:
    emitFdConvert(s, slot);
    break;
  case Op::BcdConvertExt:
    emitFdConvertExt(s, slot);
    break;
  case Op::CodeTable:
  case Op::CodeTableBinary:
    emitFdCode(i);
    break;
  case Op::TableRows: // read by their COD/CODB at compile time; ST0 stays
    break;
  case Op::IndexedTable:
    emitFdIndexed(s, slot);
    break;
  case Op::SearchTable:
    emitFdSearch(s, slot);
    break;
  case Op::BcdIndexedTable:
    emitFdBcdIndexed(s, slot);
    break;
  case Op::BcdSearchTable:
    emitFdBcdSearch(s, slot);
    break;
  case Op::BcdRotation:
  case Op::BinaryRotation:
    emitFdRotation(s, slot);
    break;
  case Op::CommonBegin:
    cache_.store(mc_.layout.edge(slot), b_.CreateZExt(st_.back(), b_.getInt8Ty()));
    break;
  case Op::CommonCoil: {
    const int32_t com = i - s.ops[1].value;
    if (com < 0 || prog_.stmts[com].op != Op::CommonBegin)
      return fail(i, "COM coil does not point at its COM");
    const int32_t comSlot = prog_.info[com].slot;
    llvm::Value *on = b_.CreateICmpNE(cache_.load(mc_.layout.edge(comSlot)), b_.getInt8(0));
    const Operand &op = s.ops[0];
    StateLoc loc = areaLoc(op, tp().area(op.area).bytes);
    llvm::Type *ty = loc.type;
    llvm::Value *old = cache_.load(loc);
    auto bitOf = [&](llvm::Value *v) {
      return b_.CreateShl(b_.CreateZExt(v, ty), static_cast<uint64_t>(op.bit));
    };
    llvm::Value *mask = llvm::ConstantInt::get(ty, uint64_t{1} << op.bit);
    llvm::Value *cleared = b_.CreateAnd(old, b_.CreateNot(mask));
    llvm::Value *st0 = st_.back();
    llvm::Value *nv = nullptr;
    switch (s.ops[2].value) {
    case 0:
      nv = b_.CreateOr(cleared, bitOf(b_.CreateAnd(on, st0)));
      break;
    case 1:
      nv = b_.CreateOr(cleared, bitOf(b_.CreateAnd(on, notV(st0))));
      break;
    case 2:
      nv = b_.CreateOr(old, bitOf(b_.CreateAnd(on, st0)));
      break;
    default:
      nv = b_.CreateAnd(old, b_.CreateNot(bitOf(b_.CreateAnd(on, st0))));
      break;
    }
    cache_.store(loc, nv);
    break;
  }
  default:
    return fail(i, "no lowering for this instruction");
  }
  return llvm::Error::success();
}

void FunctionEmitter::emitFdConvert(const Stmt &s, int32_t slot) {
  auto in = fdTake(4); // ACT, RST, CNV, BYT
  llvm::Value *act = in[0], *cnv = in[2], *byt = in[3];
  llvm::Value *lo = b_.CreateZExt(fdLoad(s.ops[0], 0, 1), b_.getInt32Ty());
  llvm::Value *hi = b_.CreateZExt(fdLoad(s.ops[0], 1, 1), b_.getInt32Ty());
  llvm::Value *raw = b_.CreateSelect(byt, b_.CreateOr(lo, b_.CreateShl(hi, 8)), lo);
  auto [value, bad] = bcdValue(b_, raw, 4); // BYT = 0: the high digits are 0
  llvm::Value *big =
      b_.CreateICmpUGT(raw, b_.CreateSelect(byt, b_.getInt32(9999), b_.getInt32(99)));
  llvm::Value *bcd = b_.CreateTrunc(
      bcdDigits(b_, b_.CreateZExt(b_.CreateSelect(big, b_.getInt32(0), raw), b_.getInt64Ty()), 4),
      b_.getInt32Ty());
  llvm::Value *result = b_.CreateSelect(cnv, value, bcd);
  llvm::Value *err = b_.CreateSelect(cnv, bad, big);
  llvm::Value *en = b_.CreateAnd(act, notV(err));
  fdStore(s.ops[1], 0, 1, result, en);
  fdStore(s.ops[1], 1, 1, b_.CreateLShr(result, 8), b_.CreateAnd(en, byt));
  fdW1(slot, act, in[1], err);
}

void FunctionEmitter::emitFdConvertExt(const Stmt &s, int32_t slot) {
  auto in = fdTake(4); // ACT, RST, CNV, SIN
  llvm::Value *act = in[0], *cnv = in[2], *sin = in[3];
  const int width = s.ops[0].width, digits = 2 * width;
  llvm::Value *x = readInt(s.ops[0]); // sign-extended
  llvm::Value *raw = width == 4 ? x : b_.CreateAnd(x, b_.getInt32((1u << (8 * width)) - 1u));
  // BCD -> binary, negated when SIN = 1.
  auto [v, bad] = bcdValue(b_, raw, digits);
  llvm::Value *fromBcd = b_.CreateSelect(sin, b_.CreateSub(b_.getInt32(0), v), v);
  // Binary -> BCD of |x|.
  llvm::Value *x64 = b_.CreateSExt(x, b_.getInt64Ty());
  llvm::Value *neg = b_.CreateICmpSLT(x64, b_.getInt64(0));
  llvm::Value *mag = b_.CreateSelect(neg, b_.CreateSub(b_.getInt64(0), x64), x64);
  int64_t max = 1;
  for (int k = 0; k < digits; ++k) max *= 10;
  llvm::Value *over = b_.CreateICmpSGE(mag, b_.getInt64(static_cast<uint64_t>(max)));
  llvm::Value *toBcd = b_.CreateTrunc(
      bcdDigits(b_, b_.CreateSelect(over, b_.getInt64(0), mag), digits), b_.getInt32Ty());
  llvm::Value *result = b_.CreateSelect(cnv, fromBcd, toBcd);
  llvm::Value *overflow = b_.CreateAnd(notV(cnv), over);
  llvm::Value *err = b_.CreateSelect(cnv, bad, over);
  llvm::Value *negative =
      b_.CreateAnd(notV(err), b_.CreateSelect(cnv, b_.CreateICmpSLT(fromBcd, b_.getInt32(0)), neg));
  writeInt(s.ops[1], result, b_.CreateAnd(act, notV(err)));
  // R9000: N (#1), V (#5); the other bits kept.
  llvm::Value *flags = fdLoad(s.ops[2], 0, 1);
  llvm::Value *nf =
      b_.CreateOr(b_.CreateAnd(flags, b_.getInt8(static_cast<uint8_t>(~0x22u))),
                  b_.CreateOr(b_.CreateShl(b_.CreateZExt(negative, b_.getInt8Ty()), 1),
                              b_.CreateShl(b_.CreateZExt(overflow, b_.getInt8Ty()), 5)));
  fdStore(s.ops[2], 0, 1, nf, act);
  fdW1(slot, act, in[1], err);
}

void FunctionEmitter::emitFdCode(int32_t i) {
  const Stmt &s = prog_.stmts[i];
  const int32_t slot = prog_.info[i].slot;
  const bool binary = s.op == Op::CodeTableBinary;
  auto in = fdTake(binary ? 2 : 3); // ACT, RST[, BYT]
  llvm::Value *act = in[0];
  const int32_t size = s.ops[0].value;
  llvm::Value *raw = b_.CreateZExt(fdLoad(s.ops[1], 0, 1), b_.getInt32Ty());
  llvm::Value *index = raw, *err = b_.getFalse();
  if (!binary) {
    auto [v, bad] = bcdValue(b_, raw, 2);
    index = v;
    err = bad;
  }
  err = b_.CreateOr(err, b_.CreateICmpUGE(index, b_.getInt32(static_cast<uint32_t>(size))));
  llvm::Value *value = b_.getInt32(0);
  if (size > 0) {
    // The constant table of the TableRows statements after this one, as a private global.
    std::vector<uint32_t> entries;
    for (int32_t k = 0; k < size; ++k)
      entries.push_back(
          static_cast<uint32_t>(prog_.stmts[i + 1 + k / kMaxOperands].ops[k % kMaxOperands].value));
    llvm::Constant *init = llvm::ConstantDataArray::get(fn_->getContext(), entries);
    auto *table = new llvm::GlobalVariable(mc_.mod, init->getType(), true,
                                           llvm::GlobalValue::PrivateLinkage, init, "fanuc.cod");
    llvm::Value *k = b_.CreateZExt(b_.CreateSelect(err, b_.getInt32(0), index), b_.getInt64Ty());
    value = b_.CreateLoad(b_.getInt32Ty(),
                          b_.CreateInBoundsGEP(init->getType(), table, {b_.getInt64(0), k}));
  }
  llvm::Value *en = b_.CreateAnd(act, notV(err));
  if (binary) {
    writeInt(s.ops[2], value, en);
  } else {
    fdStore(s.ops[2], 0, 1, value, en);
    fdStore(s.ops[2], 1, 1, b_.CreateLShr(value, 8), b_.CreateAnd(en, in[2]));
  }
  fdW1(slot, act, in[1], err);
}

void FunctionEmitter::emitFdIndexed(const Stmt &s, int32_t slot) {
  auto in = fdTake(3); // ACT, RST, RW
  llvm::Value *act = in[0], *rw = in[2];
  const int64_t items = s.ops[0].value;
  const unsigned width = s.ops[2].width;
  llvm::Type *ty = b_.getIntNTy(8 * width);
  llvm::Value *cap = b_.CreateSExt(readInt(s.ops[1]), b_.getInt64Ty());
  llvm::Value *index = b_.CreateSExt(readInt(s.ops[4]), b_.getInt64Ty());
  llvm::Value *end = b_.CreateAdd(index, b_.getInt64(static_cast<uint64_t>(items)));
  llvm::Value *err =
      b_.CreateOr(b_.CreateOr(b_.CreateICmpSLT(index, b_.getInt64(0)), b_.CreateICmpSGT(end, cap)),
                  b_.CreateICmpSGT(b_.CreateMul(end, b_.getInt64(width)),
                                   b_.getInt64(static_cast<uint64_t>(roomAfter(tp(), s.ops[2])))));
  llvm::Value *en = b_.CreateAnd(act, notV(err));
  llvm::BasicBlock *body = newBlock("xmovb"), *join = newBlock("xmovb.end");
  cache_.flush();
  b_.CreateCondBr(en, body, join);
  b_.SetInsertPoint(body);
  for (int64_t k = 0; k < items; ++k) {
    llvm::Value *t =
        fdAddr(s.ops[2], b_.CreateMul(b_.CreateAdd(index, b_.getInt64(k)), b_.getInt64(width)));
    llvm::Value *d = fdAddr(s.ops[3], b_.getInt64(static_cast<uint64_t>(k) * width));
    // RW = 1 writes the data into the table, RW = 0 reads the table into the data.
    llvm::Value *from = b_.CreateSelect(rw, d, t), *to = b_.CreateSelect(rw, t, d);
    b_.CreateAlignedStore(b_.CreateAlignedLoad(ty, from, llvm::Align(1)), to, llvm::Align(1));
  }
  b_.CreateBr(join);
  b_.SetInsertPoint(join);
  fdW1(slot, act, in[1], err);
}

void FunctionEmitter::emitFdSearch(const Stmt &s, int32_t slot) {
  auto in = fdTake(2); // ACT, RST
  llvm::Value *act = in[0];
  const unsigned width = s.ops[1].width;
  llvm::Type *ty = b_.getIntNTy(8 * width);
  llvm::Value *cap = b_.CreateSExt(readInt(s.ops[0]), b_.getInt64Ty());
  llvm::Value *key = b_.CreateTrunc(readInt(s.ops[2]), ty);
  llvm::Value *badCap =
      b_.CreateOr(b_.CreateICmpSLT(cap, b_.getInt64(0)),
                  b_.CreateICmpSGT(b_.CreateMul(cap, b_.getInt64(width)),
                                   b_.getInt64(static_cast<uint64_t>(roomAfter(tp(), s.ops[1])))));
  llvm::Value *run =
      b_.CreateAnd(b_.CreateAnd(act, notV(badCap)), b_.CreateICmpSGT(cap, b_.getInt64(0)));
  llvm::BasicBlock *entry = b_.GetInsertBlock();
  llvm::BasicBlock *loop = newBlock("dschb"), *latch = newBlock("dschb.next"),
                   *done = newBlock("dschb.end");
  cache_.flush();
  b_.CreateCondBr(run, loop, done);
  // The loop's values depend on the phi: a plain builder, since the folding one would simplify
  // the phi while it has only its entry value.
  llvm::IRBuilder<> lb(loop);
  llvm::PHINode *k = lb.CreatePHI(lb.getInt64Ty(), 2, "k");
  k->addIncoming(lb.getInt64(0), entry);
  llvm::Value *item = lb.CreateInBoundsGEP(
      lb.getInt8Ty(), lb.CreateConstInBoundsGEP1_64(lb.getInt8Ty(), state_, readOffset(s.ops[1])),
      lb.CreateMul(k, lb.getInt64(width)));
  llvm::Value *v = lb.CreateAlignedLoad(ty, item, llvm::Align(1));
  lb.CreateCondBr(lb.CreateICmpEQ(v, key), done, latch);
  lb.SetInsertPoint(latch);
  llvm::Value *k1 = lb.CreateAdd(k, lb.getInt64(1));
  k->addIncoming(k1, latch);
  lb.CreateCondBr(lb.CreateICmpSLT(k1, cap), loop, done);
  b_.SetInsertPoint(done);
  llvm::PHINode *found = b_.CreatePHI(b_.getInt64Ty(), 3, "found");
  found->addIncoming(b_.getInt64(static_cast<uint64_t>(-1)), entry);
  found->addIncoming(k, loop);
  found->addIncoming(b_.getInt64(static_cast<uint64_t>(-1)), latch);
  llvm::Value *err = b_.CreateOr(badCap, b_.CreateICmpSLT(found, b_.getInt64(0)));
  writeInt(s.ops[3], b_.CreateTrunc(found, b_.getInt32Ty()), b_.CreateAnd(act, notV(err)));
  fdW1(slot, act, in[1], err);
}

// XMOV: twin of interp bcdIndexedTable (one item of 1 or 2 bytes by BYT at a BCD index).
void FunctionEmitter::emitFdBcdIndexed(const Stmt &s, int32_t slot) {
  auto in = fdTake(4); // ACT, RST, RW, BYT
  llvm::Value *act = in[0], *rw = in[2], *byt = in[3];
  llvm::Value *lo = b_.CreateZExt(fdLoad(s.ops[3], 0, 1), b_.getInt32Ty());
  llvm::Value *hi = b_.CreateZExt(fdLoad(s.ops[3], 1, 1), b_.getInt32Ty());
  llvm::Value *raw = b_.CreateSelect(byt, b_.CreateOr(lo, b_.CreateShl(hi, 8)), lo);
  auto [value, bad] = bcdValue(b_, raw, 4); // BYT = 0: the high digits are 0
  llvm::Value *index = b_.CreateZExt(value, b_.getInt64Ty());
  llvm::Value *width = b_.CreateSelect(byt, b_.getInt64(2), b_.getInt64(1));
  llvm::Value *err = b_.CreateOr(
      b_.CreateOr(bad, b_.CreateICmpSGE(index, b_.getInt64(static_cast<uint64_t>(s.ops[0].value)))),
      b_.CreateICmpSGT(b_.CreateMul(b_.CreateAdd(index, b_.getInt64(1)), width),
                       b_.getInt64(static_cast<uint64_t>(roomAfter(tp(), s.ops[1])))));
  llvm::Value *en = b_.CreateAnd(act, notV(err));
  llvm::BasicBlock *body = newBlock("xmov"), *low = newBlock("xmov.low"),
                   *high = newBlock("xmov.high"), *join = newBlock("xmov.end");
  cache_.flush();
  b_.CreateCondBr(en, body, join);
  b_.SetInsertPoint(body);
  llvm::Value *t = fdAddr(s.ops[1], b_.CreateMul(index, width));
  llvm::Value *d = fdAddr(s.ops[2], b_.getInt64(0));
  // RW = 1 writes the data into the table, RW = 0 reads the table into the data.
  llvm::Value *from = b_.CreateSelect(rw, d, t), *to = b_.CreateSelect(rw, t, d);
  // Both bytes are read before either is written, as the interpreter does: the table item and
  // the data may overlap (e.g. table R1, data R2).
  llvm::Type *i8 = b_.getInt8Ty();
  llvm::Value *b0 = b_.CreateAlignedLoad(i8, from, llvm::Align(1));
  b_.CreateCondBr(byt, high, low);
  b_.SetInsertPoint(low);
  b_.CreateAlignedStore(b0, to, llvm::Align(1));
  b_.CreateBr(join);
  b_.SetInsertPoint(high);
  llvm::Value *b1 =
      b_.CreateAlignedLoad(i8, b_.CreateConstInBoundsGEP1_64(i8, from, 1), llvm::Align(1));
  b_.CreateAlignedStore(b0, to, llvm::Align(1));
  b_.CreateAlignedStore(b1, b_.CreateConstInBoundsGEP1_64(i8, to, 1), llvm::Align(1));
  b_.CreateBr(join);
  b_.SetInsertPoint(join);
  fdW1(slot, act, in[1], err);
}

// DSCH: twin of interp bcdSearchTable.
void FunctionEmitter::emitFdBcdSearch(const Stmt &s, int32_t slot) {
  auto in = fdTake(3); // ACT, RST, BYT
  llvm::Value *act = in[0], *byt = in[2];
  llvm::Type *i8 = b_.getInt8Ty(), *i32 = b_.getInt32Ty();
  auto item = [&](llvm::Value *klo, llvm::Value *khi) {
    return b_.CreateSelect(byt, b_.CreateOr(klo, b_.CreateShl(khi, 8)), klo);
  };
  llvm::Value *key =
      item(b_.CreateZExt(fdLoad(s.ops[2], 0, 1), i32), b_.CreateZExt(fdLoad(s.ops[2], 1, 1), i32));
  const int64_t room = roomAfter(tp(), s.ops[1]), cap = s.ops[0].value;
  llvm::Value *n = b_.CreateSelect(byt, b_.getInt64(static_cast<uint64_t>(std::min(cap, room / 2))),
                                   b_.getInt64(static_cast<uint64_t>(std::min(cap, room))));
  llvm::Value *width = b_.CreateSelect(byt, b_.getInt64(2), b_.getInt64(1));
  llvm::Value *run = b_.CreateAnd(act, b_.CreateICmpSGT(n, b_.getInt64(0)));
  llvm::BasicBlock *entry = b_.GetInsertBlock();
  llvm::BasicBlock *loop = newBlock("dsch"), *latch = newBlock("dsch.next"),
                   *done = newBlock("dsch.end");
  cache_.flush();
  b_.CreateCondBr(run, loop, done);
  llvm::IRBuilder<> lb(loop); // plain builder: see emitFdSearch
  llvm::PHINode *k = lb.CreatePHI(lb.getInt64Ty(), 2, "k");
  k->addIncoming(lb.getInt64(0), entry);
  llvm::Value *head = lb.CreateConstInBoundsGEP1_64(i8, state_, readOffset(s.ops[1]));
  llvm::Value *at = lb.CreateInBoundsGEP(i8, head, lb.CreateMul(k, width));
  // The high byte only with BYT = 1 (read the low one again otherwise: no access past the range).
  llvm::Value *atHi = lb.CreateSelect(byt, lb.CreateConstInBoundsGEP1_64(i8, at, 1), at);
  llvm::Value *vlo = lb.CreateZExt(lb.CreateAlignedLoad(i8, at, llvm::Align(1)), i32);
  llvm::Value *vhi = lb.CreateZExt(lb.CreateAlignedLoad(i8, atHi, llvm::Align(1)), i32);
  llvm::Value *v = lb.CreateSelect(byt, lb.CreateOr(vlo, lb.CreateShl(vhi, 8)), vlo);
  lb.CreateCondBr(lb.CreateICmpEQ(v, key), done, latch);
  lb.SetInsertPoint(latch);
  llvm::Value *k1 = lb.CreateAdd(k, lb.getInt64(1));
  k->addIncoming(k1, latch);
  lb.CreateCondBr(lb.CreateICmpSLT(k1, n), loop, done);
  b_.SetInsertPoint(done);
  llvm::PHINode *found = b_.CreatePHI(b_.getInt64Ty(), 3, "found");
  found->addIncoming(b_.getInt64(static_cast<uint64_t>(-1)), entry);
  found->addIncoming(k, loop);
  found->addIncoming(b_.getInt64(static_cast<uint64_t>(-1)), latch);
  // A found index the result's digits cannot hold (100 and up with BYT = 0) is an error.
  llvm::Value *err = b_.CreateOr(
      b_.CreateICmpSLT(found, b_.getInt64(0)),
      b_.CreateICmpSGE(found, b_.CreateSelect(byt, b_.getInt64(10000), b_.getInt64(100))));
  llvm::Value *en = b_.CreateAnd(act, notV(err));
  llvm::Value *bcd =
      b_.CreateTrunc(bcdDigits(b_, b_.CreateSelect(err, b_.getInt64(0), found), 4), i32);
  fdStore(s.ops[3], 0, 1, bcd, en);
  fdStore(s.ops[3], 1, 1, b_.CreateLShr(bcd, 8), b_.CreateAnd(en, byt));
  fdW1(slot, act, in[1], err);
}

// ROT / ROTB: twin of interp bcdRotation / binaryRotation (rotate()). Positions are checked
// in range first, so the modular steps need no division: c', g' lie in 0..n-1.
void FunctionEmitter::emitFdRotation(const Stmt &s, int32_t slot) {
  const bool bcd = s.op == Op::BcdRotation;
  auto in = fdTake(bcd ? 6 : 5); // ACT, INC, POS, DIR, [BYT,] RN0
  llvm::Value *act = in[0], *inc = in[1], *pos = in[2], *dir = in[3], *byt = bcd ? in[4] : nullptr;
  llvm::Type *i32 = b_.getInt32Ty(), *i64 = b_.getInt64Ty();
  auto k64 = [&](int64_t v) { return b_.getInt64(static_cast<uint64_t>(v)); };
  llvm::Value *n, *c, *g, *bad = b_.getFalse();
  if (bcd) {
    // 2 digits from 1 byte (BYT = 0) or 4 from 2 bytes (BYT = 1); a digit above 9 is an error.
    auto position = [&](const Operand &o) {
      llvm::Value *lo = b_.CreateZExt(fdLoad(o, 0, 1), i32);
      llvm::Value *hi = b_.CreateZExt(fdLoad(o, 1, 1), i32);
      auto [v, digitBad] =
          bcdValue(b_, b_.CreateSelect(byt, b_.CreateOr(lo, b_.CreateShl(hi, 8)), lo), 4);
      bad = b_.CreateOr(bad, digitBad);
      return b_.CreateZExt(v, i64);
    };
    n = k64(s.ops[0].value);
    c = position(s.ops[1]);
    g = position(s.ops[2]);
  } else {
    n = b_.CreateSExt(readInt(s.ops[1]), i64);
    c = b_.CreateSExt(readInt(s.ops[2]), i64);
    g = b_.CreateSExt(readInt(s.ops[3]), i64);
  }
  llvm::Value *first = b_.CreateZExt(in[bcd ? 5 : 4], i64); // RN0: positions from 0 or 1
  llvm::Value *cc = b_.CreateSub(c, first), *gg = b_.CreateSub(g, first);
  // n >= 2 and 0 <= c', g' < n (unsigned: a negative c' or g' is above n).
  llvm::Value *ok = b_.CreateAnd(b_.CreateAnd(notV(bad), b_.CreateICmpSGE(n, k64(2))),
                                 b_.CreateAnd(b_.CreateICmpULT(cc, n), b_.CreateICmpULT(gg, n)));
  llvm::Value *d = b_.CreateSub(gg, cc);
  llvm::Value *fwd = b_.CreateSelect(b_.CreateICmpSLT(d, k64(0)), b_.CreateAdd(d, n), d);
  llvm::Value *rev =
      b_.CreateSelect(b_.CreateICmpSGT(d, k64(0)), b_.CreateSub(n, d), b_.CreateSub(k64(0), d));
  llvm::Value *reverse = b_.CreateAnd(dir, b_.CreateICmpSLT(rev, fwd)); // a tie goes forward
  llvm::Value *steps = b_.CreateSelect(reverse, rev, fwd);
  llvm::Value *next = b_.CreateAdd(gg, k64(1)), *prev = b_.CreateSub(gg, k64(1));
  llvm::Value *before =
      b_.CreateAdd(b_.CreateSelect(reverse, b_.CreateSelect(b_.CreateICmpEQ(next, n), k64(0), next),
                                   b_.CreateSelect(b_.CreateICmpSLT(prev, k64(0)),
                                                   b_.CreateSub(n, k64(1)), prev)),
                   first);
  llvm::Value *stepsBefore =
      b_.CreateSelect(b_.CreateICmpEQ(steps, k64(0)), k64(0), b_.CreateSub(steps, k64(1)));
  llvm::Value *result = b_.CreateSelect(inc, b_.CreateSelect(pos, stepsBefore, steps),
                                        b_.CreateSelect(pos, before, g));
  if (bcd) // the result must fit the digits of its width
    ok = b_.CreateAnd(ok, b_.CreateICmpULE(result, b_.CreateSelect(byt, k64(9999), k64(99))));
  llvm::Value *en = b_.CreateAnd(act, ok);
  if (bcd) {
    llvm::Value *digits =
        b_.CreateTrunc(bcdDigits(b_, b_.CreateSelect(en, result, k64(0)), 4), i32);
    fdStore(s.ops[3], 0, 1, digits, en);
    fdStore(s.ops[3], 1, 1, b_.CreateLShr(digits, 8), b_.CreateAnd(en, byt));
  } else {
    writeInt(s.ops[4], b_.CreateTrunc(result, i32), en);
  }
  // W1: the direction of an execution that decided one, else the previous W1.
  StateLoc loc = mc_.layout.edge(slot);
  llvm::Value *w = selectBit(en, reverse, b_.CreateICmpNE(cache_.load(loc), b_.getInt8(0)));
  cache_.store(loc, b_.CreateZExt(w, b_.getInt8Ty()));
  st_.back() = w;
}

} // namespace lj::lower

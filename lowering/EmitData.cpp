// Lowering of family Data: data operations (hnc8-functions-2.md 2.2-2.13, 2.17-2.18; decisions
// in docs/dialect-notes.md "Data operations"). Constant ranges of up to kUnroll elements become
// straight-line cached loads/stores guarded by selects; longer ones an LLVM loop entered only
// when EN = 1. Computed indices (XMOV/XCH formats 1/2, the COD index) are clamped into range
// and accessed through computed addresses with the ImageCache flush rules.
#include "lowering/FunctionEmitter.h"

#include "ladderjit/abi.h"

#include <cassert>
#include <vector>

namespace lj::lower {

namespace {

/// Ranges up to this many elements are unrolled.
constexpr int32_t kUnroll = 32;

Operand element(Area a, int32_t index) {
  Operand o;
  o.kind = Operand::Kind::Reg;
  o.area = a;
  o.index = index;
  return o;
}

/// Mask of an element of `width` bits (8, 16 or 32) as a uint32.
uint32_t widthMask(int width) { return width >= 32 ? ~0u : (1u << width) - 1u; }

} // namespace

llvm::Error FunctionEmitter::emitDataBlock(int32_t i) {
  const Stmt &s = prog_.stmts[i];
  switch (s.op) {
  case Op::IndexedMove:
  case Op::Exchange:
    emitXmovXch(s);
    break;
  case Op::BlockMove:
    emitBmov(s);
    break;
  case Op::Fill: {
    // The value is read once, before any write (functions-2 2.4); output rule None.
    llvm::Value *v = readInt(s.ops[2]);
    dataFill(s.ops[0].area, s.ops[0].index, s.ops[1].index, v, enable());
    break;
  }
  case Op::ZoneReset:
    emitZrst(s);
    break;
  case Op::TableEncode:
  case Op::TableDecode:
  case Op::TableLookup:
  case Op::TableSearch:
    emitTable(s);
    break;
  case Op::Pack:
  case Op::Unpack:
    emitAssemDisas(s);
    break;
  case Op::RangeConvert:
    emitAcvt(s);
    break;
  case Op::PointToNumber:
  case Op::NumberToPoint:
    emitPtnNtp(s);
    break;
  default:
    return emitFanucData(i); // fanuc-b's operations (EmitFanucData.cpp)
  }
  return llvm::Error::success();
}

llvm::Value *FunctionEmitter::dataLoadAt(Area a, llvm::Value *index) {
  cache_.flush();
  StateLoc base = mc_.layout.area(a, 0);
  llvm::Value *p = b_.CreateConstInBoundsGEP1_64(b_.getInt8Ty(), state_, base.offset);
  llvm::Value *addr = b_.CreateInBoundsGEP(base.type, p, b_.CreateZExt(index, b_.getInt64Ty()));
  llvm::Value *v = b_.CreateLoad(base.type, addr);
  if (base.type->getIntegerBitWidth() == 32) return v;
  return tp().area(a).isSigned ? b_.CreateSExt(v, b_.getInt32Ty())
                               : b_.CreateZExt(v, b_.getInt32Ty());
}

void FunctionEmitter::dataStoreAt(Area a, llvm::Value *index, llvm::Value *v) {
  StateLoc base = mc_.layout.area(a, 0);
  llvm::Value *p = b_.CreateConstInBoundsGEP1_64(b_.getInt8Ty(), state_, base.offset);
  llvm::Value *addr = b_.CreateInBoundsGEP(base.type, p, b_.CreateZExt(index, b_.getInt64Ty()));
  b_.CreateStore(b_.CreateTrunc(v, base.type), addr);
  cache_.flush(); // the cache may hold the old value of the element just written
}

FunctionEmitter::DataRef FunctionEmitter::dataResolve(const Operand &format, const Operand &addr) {
  DataRef r;
  if (format.value == 0) {
    r.reg = addr;
    r.ok = b_.getTrue();
    return r;
  }
  r.area = format.value == 1 ? Area::Retained : Area::Param;
  llvm::Value *k = readInt(addr);
  // Unsigned compare: a negative index is out of range too.
  r.ok = b_.CreateICmpULT(k, b_.getInt32(static_cast<uint32_t>(tp().area(r.area).count)));
  r.index = b_.CreateSelect(r.ok, k, b_.getInt32(0));
  return r;
}

llvm::Value *FunctionEmitter::dataRead(const DataRef &r) {
  return r.index ? dataLoadAt(r.area, r.index) : readInt(r.reg);
}

void FunctionEmitter::dataWrite(const DataRef &r, llvm::Value *v, llvm::Value *en) {
  if (!r.index) {
    writeInt(r.reg, v, en);
    return;
  }
  // Straight-line: store the old value back when disabled (the clamped index is in range).
  llvm::Value *old = dataLoadAt(r.area, r.index);
  dataStoreAt(r.area, r.index, b_.CreateSelect(en, v, old));
}

void FunctionEmitter::dataIndexFault(llvm::Value *en, llvm::Value *ok, bool hasOutput) {
  llvm::Value *fault = b_.CreateAnd(en, notV(ok), "index.fault");
  StateLoc fi = mc_.layout.scalar(Scalar::FaultIndex);
  cache_.store(fi, b_.CreateAdd(cache_.load(fi), b_.CreateZExt(fault, b_.getInt32Ty())));
  if (!hasOutput && !st_.empty()) st_.back() = b_.CreateAnd(st_.back(), notV(fault));
}

llvm::Value *FunctionEmitter::dataLoop(llvm::Value *en, int32_t n, bool backward, llvm::Value *init,
                                       DataBody body) {
  cache_.flush();
  llvm::BasicBlock *pre = b_.GetInsertBlock();
  llvm::BasicBlock *loop = newBlock("data.loop");
  llvm::BasicBlock *exit = newBlock("data.end");
  b_.CreateCondBr(en, loop, exit);
  b_.SetInsertPoint(loop);
  // Both incoming values are added before anything uses the phis, so the simplifying folder
  // never sees a one-input phi (it would fold the induction variable to its start value).
  llvm::PHINode *i = b_.CreatePHI(b_.getInt32Ty(), 2, "i");
  llvm::PHINode *carried = init ? b_.CreatePHI(b_.getInt32Ty(), 2, "carried") : nullptr;
  llvm::Instruction *next = llvm::BinaryOperator::CreateAdd(i, b_.getInt32(1), "i.next");
  b_.Insert(next);
  i->addIncoming(b_.getInt32(0), pre);
  i->addIncoming(next, loop);
  llvm::Value *idx = backward ? b_.CreateSub(b_.getInt32(n - 1), i) : static_cast<llvm::Value *>(i);
  llvm::Value *out = body(idx, carried);
  cache_.flush();
  if (carried) {
    carried->addIncoming(init, pre);
    carried->addIncoming(out, b_.GetInsertBlock());
  }
  llvm::BasicBlock *latch = b_.GetInsertBlock();
  (void)latch;
  assert(latch == loop && "a data loop body is straight-line");
  llvm::Value *more = b_.Insert(new llvm::ICmpInst(llvm::ICmpInst::ICMP_SLT, next, b_.getInt32(n)));
  b_.CreateCondBr(more, loop, exit);
  b_.SetInsertPoint(exit);
  if (!carried) return nullptr;
  llvm::PHINode *result = b_.CreatePHI(b_.getInt32Ty(), 2, "carried.out");
  result->addIncoming(init, pre);
  result->addIncoming(out, loop);
  return result;
}

void FunctionEmitter::dataFill(Area a, int32_t first, int32_t last, llvm::Value *v,
                               llvm::Value *en) {
  if (last < first) return;
  if (last - first + 1 <= kUnroll) {
    for (int32_t k = first; k <= last; ++k) writeInt(element(a, k), v, en);
    return;
  }
  dataLoop(en, last - first + 1, false, nullptr, [&](llvm::Value *idx, llvm::Value *) {
    dataStoreAt(a, b_.CreateAdd(idx, b_.getInt32(first)), v);
    return nullptr;
  });
}

void FunctionEmitter::emitXmovXch(const Stmt &s) {
  // Both operands are resolved (index registers read) before anything is written; out of range
  // on either side: nothing written, output 0, fault_index + 1 (DIALECT.md 4).
  llvm::Value *en = enable();
  DataRef r1 = dataResolve(s.ops[0], s.ops[1]);
  DataRef r2 = dataResolve(s.ops[2], s.ops[3]);
  llvm::Value *ok = b_.CreateAnd(r1.ok, r2.ok);
  llvm::Value *doIt = b_.CreateAnd(en, ok);
  llvm::Value *v1 = dataRead(r1);
  if (s.op == Op::IndexedMove) {
    dataWrite(r2, v1, doIt);
    dataIndexFault(en, ok, true);
    setOutput(doIt);
    return;
  }
  llvm::Value *v2 = dataRead(r2);
  dataWrite(r1, v2, doIt); // operand 1 first, then operand 2 (the interpreter's order)
  dataWrite(r2, v1, doIt);
  dataIndexFault(en, ok, false);
}

void FunctionEmitter::emitBmov(const Stmt &s) {
  const Operand &src = s.ops[0], &dst = s.ops[1];
  const int32_t n = s.ops[2].value;
  llvm::Value *en = enable();
  if (n <= kUnroll) {
    // memmove semantics for free: every value is loaded before the first store.
    std::vector<llvm::Value *> v;
    for (int32_t k = 0; k < n; ++k) v.push_back(readInt(element(src.area, src.index + k)));
    for (int32_t k = 0; k < n; ++k) writeInt(element(dst.area, dst.index + k), v[k], en);
  } else {
    // memmove semantics: when the destination overlaps the source from above, copy backward.
    bool backward = src.area == dst.area && dst.index > src.index;
    dataLoop(en, n, backward, nullptr, [&](llvm::Value *idx, llvm::Value *) {
      llvm::Value *v = dataLoadAt(src.area, b_.CreateAdd(idx, b_.getInt32(src.index)));
      dataStoreAt(dst.area, b_.CreateAdd(idx, b_.getInt32(dst.index)), v);
      return nullptr;
    });
  }
  setOutput(en);
}

void FunctionEmitter::emitZrst(const Stmt &s) {
  const Operand &a = s.ops[0], &b = s.ops[1];
  llvm::Value *en = enable();
  llvm::Value *zero = b_.getInt32(0);
  if (a.kind == Operand::Kind::Reg) {
    dataFill(a.area, a.index, b.index, zero, en);
  } else {
    // Bits index * width + bit from a to b: partial first/last elements are masked, the whole
    // elements between them are zeroed.
    const int w = tp().bitWidth(a.area);
    auto clearBits = [&](int32_t index, int lo, int hi) {
      uint32_t m = widthMask(hi - lo + 1) << lo;
      Operand e = element(a.area, index);
      writeInt(e, b_.CreateAnd(readInt(e), b_.getInt32(~m)), en);
    };
    if (a.index == b.index) {
      clearBits(a.index, a.bit, b.bit);
    } else {
      int32_t first = a.index, last = b.index;
      if (a.bit != 0) clearBits(first++, a.bit, w - 1);
      if (b.bit != w - 1) clearBits(last--, 0, b.bit);
      dataFill(a.area, first, last, zero, en);
    }
  }
  setOutput(en);
}

void FunctionEmitter::emitTable(const Stmt &s) {
  const Operand &t = s.ops[0];
  const int32_t n = s.ops[1].value;
  llvm::Value *en = enable();
  llvm::Value *x = readInt(s.ops[2]);
  auto entry = [&](int32_t k) { return readInt(element(t.area, t.index + k)); };
  switch (s.op) {
  case Op::TableEncode: { // first T[i] == x -> 1 << i, none -> 0; scanned from the end so i wins
    llvm::Value *r = b_.getInt32(0);
    for (int32_t k = n - 1; k >= 0; --k)
      r = b_.CreateSelect(b_.CreateICmpEQ(entry(k), x), b_.getInt32(1u << k), r);
    writeInt(s.ops[3], r, en);
    return;
  }
  case Op::TableDecode: { // lowest set bit i < n of x -> T[i], none -> 0
    llvm::Value *r = b_.getInt32(0);
    for (int32_t k = n - 1; k >= 0; --k) {
      llvm::Value *bitK = b_.CreateICmpNE(b_.CreateAnd(x, b_.getInt32(1u << k)), b_.getInt32(0));
      r = b_.CreateSelect(bitK, entry(k), r);
    }
    writeInt(s.ops[3], r, en);
    return;
  }
  case Op::TableLookup: { // T[x] for 0 <= x < n, else an index fault
    llvm::Value *ok = b_.CreateICmpULT(x, b_.getInt32(static_cast<uint32_t>(n)));
    llvm::Value *k = b_.CreateSelect(ok, x, b_.getInt32(0));
    llvm::Value *v = dataLoadAt(t.area, b_.CreateAdd(k, b_.getInt32(t.index)));
    writeInt(s.ops[3], v, b_.CreateAnd(en, ok));
    dataIndexFault(en, ok, false);
    return;
  }
  default: { // SER: smallest i with T[i] == x (-1: none) -> dst := i, output EN and found
    llvm::Value *r = b_.getInt32(-1);
    if (n <= kUnroll) {
      for (int32_t k = n - 1; k >= 0; --k)
        r = b_.CreateSelect(b_.CreateICmpEQ(entry(k), x), b_.getInt32(k), r);
    } else {
      r = dataLoop(en, n, true, r, [&](llvm::Value *idx, llvm::Value *carried) {
        llvm::Value *v = dataLoadAt(t.area, b_.CreateAdd(idx, b_.getInt32(t.index)));
        return b_.CreateSelect(b_.CreateICmpEQ(v, x), idx, carried);
      });
    }
    llvm::Value *found = b_.CreateAnd(en, b_.CreateICmpSGE(r, b_.getInt32(0)), "found");
    writeInt(s.ops[3], r, found);
    setOutput(found);
    return;
  }
  }
}

void FunctionEmitter::emitAssemDisas(const Stmt &s) {
  llvm::Value *en = enable();
  const int32_t n = s.ops[1].value;
  if (s.op == Op::Pack) {
    // Raw pieces of the source width, the first in the least-significant bits; pieces at or
    // beyond bit 32 are lost (functions-2 2.11).
    const Operand &src = s.ops[0];
    const int w = tp().bitWidth(src.area);
    llvm::Value *acc = b_.getInt32(0);
    for (int32_t k = 0; k < n && k * w < 32; ++k) {
      llvm::Value *raw =
          b_.CreateAnd(readInt(element(src.area, src.index + k)), b_.getInt32(widthMask(w)));
      acc = b_.CreateOr(acc, b_.CreateShl(raw, static_cast<uint64_t>(k * w)));
    }
    writeInt(s.ops[2], acc, en);
    return;
  }
  // DISAS: pieces of the destination width from the raw source, logical shifts, 0 past bit 32.
  const Operand &dst = s.ops[2];
  const int w = tp().bitWidth(dst.area);
  llvm::Value *raw =
      b_.CreateAnd(readInt(s.ops[0]), b_.getInt32(widthMask(tp().bitWidth(s.ops[0].area))));
  for (int32_t k = 0; k < n; ++k) {
    llvm::Value *piece = k * w < 32 ? b_.CreateAnd(b_.CreateLShr(raw, static_cast<uint64_t>(k * w)),
                                                   b_.getInt32(widthMask(w)))
                                    : b_.getInt32(0);
    writeInt(element(dst.area, dst.index + k), piece, en);
  }
}

void FunctionEmitter::emitAcvt(const Stmt &s) {
  // dst := (x - P[k]) * (P[k+3] - P[k+2]) / (P[k+1] - P[k]) + P[k+2] in int64: exact
  // differences, wrapping product, truncating sdiv made safe first, wrapping sum. A zero source
  // range writes nothing, counts fault_divzero and gives ST0 := 0 (dialect-notes).
  const int32_t k = s.ops[0].index;
  llvm::Value *en = enable();
  llvm::Type *i64 = b_.getInt64Ty();
  auto p = [&](int32_t j) { return b_.CreateSExt(readInt(element(Area::Param, k + j)), i64); };
  llvm::Value *smin = p(0), *smax = p(1), *dmin = p(2), *dmax = p(3);
  llvm::Value *x = b_.CreateSExt(readInt(s.ops[1]), i64);
  llvm::Value *den = b_.CreateSub(smax, smin);
  llvm::Value *num = b_.CreateMul(b_.CreateSub(x, smin), b_.CreateSub(dmax, dmin));
  llvm::Value *zero = b_.CreateICmpEQ(den, b_.getInt64(0), "range.zero");
  llvm::Value *ovf = b_.CreateAnd(b_.CreateICmpEQ(num, b_.getInt64(INT64_MIN)),
                                  b_.CreateICmpEQ(den, b_.getInt64(-1)));
  llvm::Value *safe = b_.CreateSelect(b_.CreateOr(zero, ovf), b_.getInt64(1), den);
  llvm::Value *q = b_.CreateSDiv(num, safe); // INT64_MIN / 1 = INT64_MIN
  llvm::Value *r = b_.CreateTrunc(b_.CreateAdd(q, dmin), b_.getInt32Ty());
  writeInt(s.ops[2], r, b_.CreateAnd(en, notV(zero)));
  llvm::Value *fault = b_.CreateAnd(en, zero);
  StateLoc fz = mc_.layout.scalar(Scalar::FaultDivzero);
  cache_.store(fz, b_.CreateAdd(cache_.load(fz), b_.CreateZExt(fault, b_.getInt32Ty())));
  if (!st_.empty()) st_.back() = b_.CreateAnd(st_.back(), notV(fault));
}

void FunctionEmitter::emitPtnNtp(const Stmt &s) {
  llvm::Value *en = enable();
  if (s.op == Op::PointToNumber) {
    // First active point wins: chain the selects from the last pair to the first.
    llvm::Value *r = b_.getInt32(0), *any = b_.getFalse();
    for (int p = kMaxOperands - 2; p >= 1; p -= 2) {
      llvm::Value *on = readBit(s.ops[p]);
      r = b_.CreateSelect(on, b_.getInt32(static_cast<uint32_t>(s.ops[p + 1].value)), r);
      any = b_.CreateOr(any, on);
    }
    writeInt(s.ops[0], r, b_.CreateAnd(en, any));
    return;
  }
  // NTP: point := (x == number), pairs in order, x read once before any point is written.
  llvm::Value *x = readInt(s.ops[0]);
  for (int p = 1; p < kMaxOperands; p += 2) {
    const Operand &pt = s.ops[p + 1];
    StateLoc loc = mc_.layout.area(pt.area, pt.index);
    llvm::Type *ty = loc.type;
    llvm::Value *old = cache_.load(loc);
    llvm::Value *mask =
        llvm::ConstantInt::get(ty, llvm::APInt::getOneBitSet(ty->getIntegerBitWidth(), pt.bit));
    llvm::Value *eq = b_.CreateICmpEQ(x, b_.getInt32(static_cast<uint32_t>(s.ops[p].value)));
    llvm::Value *nv =
        b_.CreateOr(b_.CreateAnd(old, b_.CreateNot(mask)),
                    b_.CreateShl(b_.CreateZExt(eq, ty), static_cast<uint64_t>(pt.bit)));
    cache_.store(loc, b_.CreateSelect(en, nv, old));
  }
}

} // namespace lj::lower

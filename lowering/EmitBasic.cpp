// Basic instructions (hnc8-core.md 4.2, DIALECT.md 3): contacts, edge contacts, ANB/ORB,
// MPS/MRD/MPP and coils, on compile-time stacks of i1 values. Operand reads follow the read
// rule of DIALECT.md 1 (X/Y/R zero-extended, F/G/W sign-extended, D/B/P as is).
#include "lowering/FunctionEmitter.h"

#include "ladderjit/abi.h"

namespace lj::lower {

StateLoc FunctionEmitter::areaLoc(const Operand &op, unsigned width) {
  const uint32_t off = readOffset(op);
  if (!StateLayout::inMem(off)) return mc_.layout.area(op.area, op.index);
  if (width == 0) width = op.width ? op.width : tp().area(op.area).bytes;
  std::string name;
  if (mc_.opts.readableNames)
    name = std::string(tp().area(op.area).name) + std::to_string(op.index);
  return mc_.layout.memBytes(off, width, std::move(name));
}

llvm::Value *FunctionEmitter::readBit(const Operand &op) {
  std::string name;
  if (mc_.opts.readableNames)
    name = std::string(tp().area(op.area).name) + std::to_string(op.index) + "." +
           std::to_string(op.bit);
  if (op.area == Area::Timer || op.area == Area::Counter) {
    // Tn.0 / Cn.0: the timer's / counter's output byte (dialect-notes "Function blocks").
    int slot = tp().tcSlot(op.area, op.index);
    llvm::Value *out = op.area == Area::Timer
                           ? cache_.load(mc_.layout.timer(slot, TimerField::Out))
                           : cache_.load(mc_.layout.counter(slot, CounterField::Out));
    return b_.CreateICmpNE(out, llvm::ConstantInt::get(out->getType(), 0), name);
  }
  llvm::Value *v = cache_.load(areaLoc(op, tp().area(op.area).bytes));
  if (op.bit == 0) return b_.CreateTrunc(v, b_.getInt1Ty(), name);
  // (v & 1 << k) != 0: the canonical bit test, so InstCombine has nothing to rewrite.
  llvm::Value *mask = llvm::ConstantInt::get(
      v->getType(), llvm::APInt::getOneBitSet(v->getType()->getIntegerBitWidth(), op.bit));
  return b_.CreateICmpNE(b_.CreateAnd(v, mask), llvm::ConstantInt::get(v->getType(), 0), name);
}

llvm::Value *FunctionEmitter::readInt(const Operand &op) {
  if (op.kind == Operand::Kind::Const) return b_.getInt32(static_cast<uint32_t>(op.value));
  llvm::Value *v = cache_.load(areaLoc(op));
  if (v->getType()->getIntegerBitWidth() == 32) return v;
  return tp().area(op.area).isSigned ? b_.CreateSExt(v, b_.getInt32Ty())
                                     : b_.CreateZExt(v, b_.getInt32Ty());
}

void FunctionEmitter::writeInt(const Operand &op, llvm::Value *v, llvm::Value *en) {
  StateLoc loc = areaLoc(op);
  llvm::Value *nv = b_.CreateTrunc(v, loc.type); // a write keeps the low 8/16/32 bits
  if (en) nv = b_.CreateSelect(en, nv, cache_.load(loc));
  cache_.store(loc, nv);
}

std::pair<llvm::Value *, llvm::Value *> FunctionEmitter::edge(int32_t slot, llvm::Value *cur) {
  // DIALECT.md 3: rise = cur & !m, fall = !cur & m, then m = cur -- on every execution. Under
  // EdgePolicy::PerObject m is the object's previous-scan image, written only by EdgeImage.cpp.
  StateLoc loc = mc_.layout.edge(slot);
  llvm::Value *m = b_.CreateICmpNE(cache_.load(loc), b_.getInt8(0), "m");
  if (tp().edgePolicy == EdgePolicy::PerInstance)
    cache_.store(loc, b_.CreateZExt(cur, b_.getInt8Ty()));
  return {b_.CreateAnd(cur, notV(m), "rise"), b_.CreateAnd(notV(cur), m, "fall")};
}

llvm::Error FunctionEmitter::emitBasic(int32_t i) {
  const Stmt &s = prog_.stmts[i];
  const StmtInfo &info = prog_.info[i];
  auto edgeSlot = [&]() -> llvm::Expected<int32_t> {
    if (info.slot < 0 || info.slot >= LJ_EDGE_SLOTS)
      return fail(i, "edge slot " + std::to_string(info.slot) + " out of range");
    return info.slot;
  };
  // A forced contact (ModuleContext::forced, docs/serve.md "Forcing") conducts its constant.
  const int8_t force = mc_.forced.empty() ? -1 : mc_.forced[i];
  auto contact = [&](llvm::Value *real) -> llvm::Value * {
    return traceContact_ = force >= 0 ? b_.getInt1(force != 0) : real;
  };
  switch (s.op) {
  case Op::Load:
    st_.push_back(contact(readBit(s.ops[0])));
    return llvm::Error::success();
  case Op::LoadNot:
    st_.push_back(contact(notV(readBit(s.ops[0]))));
    return llvm::Error::success();
  case Op::LoadTrue:
    st_.push_back(b_.getTrue());
    return llvm::Error::success();
  case Op::LoadRise:
  case Op::LoadFall: {
    llvm::Expected<int32_t> slot = edgeSlot();
    if (!slot) return slot.takeError();
    auto [rise, fall] = edge(*slot, readBit(s.ops[0]));
    st_.push_back(contact(s.op == Op::LoadRise ? rise : fall)); // memory updated even when forced
    return llvm::Error::success();
  }
  default:
    break;
  }
  if (st_.empty()) return fail(i, "combine with an empty ST");
  llvm::Value *&st0 = st_.back();
  switch (s.op) {
  case Op::And:
    st0 = b_.CreateAnd(st0, contact(readBit(s.ops[0])));
    break;
  case Op::AndNot:
    st0 = b_.CreateAnd(st0, contact(notV(readBit(s.ops[0]))));
    break;
  case Op::Or:
    st0 = b_.CreateOr(st0, contact(readBit(s.ops[0])));
    break;
  case Op::OrNot:
    st0 = b_.CreateOr(st0, contact(notV(readBit(s.ops[0]))));
    break;
  case Op::AndRise:
  case Op::AndFall:
  case Op::OrRise:
  case Op::OrFall: {
    // The edge instance always executes, whatever ST0 is: and/or of i1, never a branch.
    llvm::Expected<int32_t> slot = edgeSlot();
    if (!slot) return slot.takeError();
    auto [rise, fall] = edge(*slot, readBit(s.ops[0]));
    llvm::Value *e = contact((s.op == Op::AndRise || s.op == Op::OrRise) ? rise : fall);
    st0 = (s.op == Op::AndRise || s.op == Op::AndFall) ? b_.CreateAnd(st0, e) : b_.CreateOr(st0, e);
    break;
  }
  case Op::AndBlock:
  case Op::OrBlock: {
    if (st_.size() < 2) return fail(i, "AndBlock/OrBlock with fewer than 2 ST entries");
    llvm::Value *top = st_.back();
    st_.pop_back();
    st_.back() =
        s.op == Op::AndBlock ? b_.CreateAnd(st_.back(), top) : b_.CreateOr(st_.back(), top);
    break;
  }
  case Op::BranchPush:
    ms_.push_back(st0);
    break;
  case Op::BranchRead:
  case Op::BranchPop:
    if (ms_.empty()) return fail(i, "BranchRead/BranchPop with an empty MS");
    st0 = ms_.back();
    if (s.op == Op::BranchPop) ms_.pop_back();
    break;
  default:
    return emitCoil(i);
  }
  return llvm::Error::success();
}

llvm::Error FunctionEmitter::emitCoil(int32_t i) {
  const Stmt &s = prog_.stmts[i];
  const Operand &op = s.ops[0];
  if (st_.empty()) return fail(i, "coil with an empty ST");
  if (op.kind != Operand::Kind::Bit || !hasArea(kCoilAreas, op.area) ||
      !tp().area(op.area).writable)
    return fail(i, "coil operand is not a writable bit");
  StateLoc loc = areaLoc(op, tp().area(op.area).bytes);
  llvm::Type *ty = loc.type;
  llvm::Value *old = cache_.load(loc);
  llvm::Value *st0 = st_.back();
  llvm::Value *mask =
      llvm::ConstantInt::get(ty, llvm::APInt::getOneBitSet(ty->getIntegerBitWidth(), op.bit));
  // The bit as an element value. zext + shl rather than a select: FastISel selects an i8
  // select through a branchy pseudo, which made the fast tier's scan 25% slower.
  auto bitOf = [&](llvm::Value *v) {
    return b_.CreateShl(b_.CreateZExt(v, ty), static_cast<uint64_t>(op.bit));
  };
  auto cleared = [&] { return b_.CreateAnd(old, b_.CreateNot(mask)); };
  llvm::Value *nv = nullptr;
  switch (s.op) {
  case Op::Coil:
    nv = b_.CreateOr(cleared(), bitOf(st0));
    break;
  case Op::CoilNot:
    nv = b_.CreateOr(cleared(), bitOf(notV(st0)));
    break;
  case Op::Set:
    nv = b_.CreateOr(old, bitOf(st0));
    break;
  case Op::Reset:
    nv = b_.CreateAnd(old, b_.CreateNot(bitOf(st0)));
    break;
  default:
    return fail(i, "not a basic instruction");
  }
  cache_.store(loc, nv);
  return llvm::Error::success();
}

} // namespace lj::lower

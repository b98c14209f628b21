// Lowering of the FANUC arithmetic (fanuc-c rows of ir/OpTable.h: BinaryArith, BcdArith,
// BcdConstant), as straight-line selects mirroring interp/InterpFanucArith.cpp (the oracle) step
// by step, in the same order of reads and writes (an operand may share bytes with another or
// with R9000). The operation is a constant of the statement, so only its own arithmetic is
// emitted; the BCD width (BYT) is an input, so both widths are computed and selected.
#include "ir/PmcArith.h"
#include "lowering/EmitBcd.h"
#include "lowering/FunctionEmitter.h"

#include "ladderjit/abi.h"

#include <tuple>

namespace lj::lower {

llvm::Error FunctionEmitter::emitFanucArith(int32_t i) {
  const Stmt &s = prog_.stmts[i];
  const int32_t slot = prog_.info[i].slot;
  if (instrInfo(s.op).state == StateKind::Edge && (slot < 0 || slot >= LJ_EDGE_SLOTS))
    return fail(i, "edge slot " + std::to_string(slot) + " out of range");
  if (st_.size() < instrInfo(s.op).inputs) return fail(i, "too few ST entries for its inputs");
  switch (s.op) {
  case Op::BinaryArith:
    emitFaBinary(s, slot);
    break;
  case Op::BcdArith:
    emitFaBcd(s, slot);
    break;
  case Op::BcdConstant: {
    auto in = fdTake(2); // ACT, BYT
    llvm::Value *pattern = b_.getInt32(static_cast<uint32_t>(s.ops[0].value));
    fdStore(s.ops[1], 0, 1, pattern, in[0]);
    fdStore(s.ops[1], 1, 1, b_.CreateLShr(pattern, 8), b_.CreateAnd(in[0], in[1]));
    st_.back() = in[0]; // no W1: ACT stays in ST0
    break;
  }
  default:
    return fail(i, "no lowering for this instruction");
  }
  return llvm::Error::success();
}

void FunctionEmitter::emitFaBinary(const Stmt &s, int32_t slot) {
  auto in = fdTake(2); // ACT, RST
  llvm::Value *act = in[0];
  const int width = s.ops[1].width;
  const int32_t op = s.ops[0].value;
  auto k64 = [&](int64_t v) { return b_.getInt64(static_cast<uint64_t>(v)); };
  llvm::Value *x = b_.CreateSExt(readInt(s.ops[1]), b_.getInt64Ty());
  llvm::Value *y = b_.CreateSExt(readInt(s.ops[2]), b_.getInt64Ty());
  llvm::Value *divZero = b_.getFalse(), *r = nullptr, *rem = nullptr;
  switch (op) {
  case pmc::kArithAdd:
    r = b_.CreateAdd(x, y);
    break;
  case pmc::kArithSub:
    r = b_.CreateSub(x, y);
    break;
  case pmc::kArithMul:
    r = b_.CreateMul(x, y); // |x|, |y| <= 2^31: no i64 overflow
    break;
  default: {
    divZero = b_.CreateICmpEQ(y, k64(0));
    llvm::Value *d = b_.CreateSelect(divZero, k64(1), y); // i64: INT32_MIN / -1 is defined
    r = b_.CreateSDiv(x, d);
    rem = b_.CreateSRem(x, d);
    break;
  }
  }
  llvm::Value *overflow = b_.CreateOr(b_.CreateICmpSLT(r, k64(pmc::minOf(width))),
                                      b_.CreateICmpSGT(r, k64(pmc::maxOf(width))));
  // The result wrapped to its bytes, sign-extended (reference 3.1).
  llvm::Value *stored =
      b_.CreateSExt(b_.CreateTrunc(r, b_.getIntNTy(8 * width)), b_.getInt32Ty(), "stored");
  llvm::Value *en = b_.CreateAnd(act, notV(divZero));
  writeInt(s.ops[3], stored, en);
  if (rem) writeInt(s.ops[5], b_.CreateTrunc(rem, b_.getInt32Ty()), en);
  // R9000: Z (#0), N (#1) of the stored result, V (#5) overflow; the other bits kept.
  llvm::Value *flags = fdLoad(s.ops[4], 0, 1);
  auto bit = [&](llvm::Value *c, int32_t mask) {
    return b_.CreateSelect(c, b_.getInt8(static_cast<uint8_t>(mask)), b_.getInt8(0));
  };
  llvm::Value *nf = b_.CreateOr(
      b_.CreateAnd(flags, b_.getInt8(static_cast<uint8_t>(
                              ~(pmc::kArithFlagZ | pmc::kArithFlagN | pmc::kArithFlagV)))),
      b_.CreateOr(b_.CreateOr(bit(b_.CreateICmpEQ(stored, b_.getInt32(0)), pmc::kArithFlagZ),
                              bit(b_.CreateICmpSLT(stored, b_.getInt32(0)), pmc::kArithFlagN)),
                  bit(overflow, pmc::kArithFlagV)));
  fdStore(s.ops[4], 0, 1, nf, en);
  fdW1(slot, act, in[1], b_.CreateOr(divZero, overflow));
}

void FunctionEmitter::emitFaBcd(const Stmt &s, int32_t slot) {
  auto in = fdTake(3); // ACT, RST, BYT
  llvm::Value *act = in[0], *byt = in[2];
  const int32_t op = s.ops[0].value;
  const bool constant = s.ops[2].kind == Operand::Kind::Const;
  auto k32 = [&](int64_t v) { return b_.getInt32(static_cast<uint32_t>(v)); };
  // The operands' raw bytes, read before any write (as the interpreter does).
  auto raw = [&](const Operand &o, int n) -> llvm::Value * {
    llvm::Value *lo = b_.CreateZExt(fdLoad(o, 0, 1), b_.getInt32Ty());
    if (n == 1) return lo;
    return b_.CreateOr(lo, b_.CreateShl(b_.CreateZExt(fdLoad(o, 1, 1), b_.getInt32Ty()), 8));
  };
  llvm::Value *err[2], *bcd[2];
  for (int n = 1; n <= 2; ++n) {
    const int64_t limit = pmc::bcdLimit(2 * n);
    auto [x, badX] = bcdValue(b_, raw(s.ops[1], n), 2 * n);
    llvm::Value *y, *badY;
    if (constant) {
      y = k32(s.ops[2].value);
      badY = b_.getInt1(s.ops[2].value >= limit);
    } else {
      std::tie(y, badY) = bcdValue(b_, raw(s.ops[2], n), 2 * n);
    }
    llvm::Value *bad = b_.CreateOr(badX, badY), *r = nullptr;
    switch (op) {
    case pmc::kArithAdd:
      r = b_.CreateAdd(x, y);
      break;
    case pmc::kArithSub:
      r = b_.CreateSub(x, y); // negative: an error
      break;
    case pmc::kArithMul:
      r = b_.CreateMul(x, y); // 9999 * 9999 < 2^31
      break;
    default: {
      llvm::Value *zero = b_.CreateICmpEQ(y, k32(0));
      bad = b_.CreateOr(bad, zero);
      r = b_.CreateUDiv(x, b_.CreateSelect(zero, k32(1), y)); // the remainder is dropped
      break;
    }
    }
    llvm::Value *outside =
        b_.CreateOr(b_.CreateICmpSLT(r, k32(0)), b_.CreateICmpSGE(r, k32(limit)));
    err[n - 1] = b_.CreateOr(bad, outside);
    bcd[n - 1] = bcdDigits(b_, b_.CreateSelect(err[n - 1], k32(0), r), 2 * n);
  }
  llvm::Value *e = selectBit(byt, err[1], err[0]);
  llvm::Value *en = b_.CreateAnd(act, notV(e));
  fdStore(s.ops[3], 0, 1, b_.CreateSelect(byt, bcd[1], bcd[0]), en);
  fdStore(s.ops[3], 1, 1, b_.CreateLShr(bcd[1], 8), b_.CreateAnd(en, byt));
  fdW1(slot, act, in[1], e);
}

} // namespace lj::lower

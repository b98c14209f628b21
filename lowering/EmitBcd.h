// The BCD codec (ir/Bcd.h) emitted as LLVM IR, for the FANUC data and arithmetic instructions
// (lowering/EmitFanucData.cpp, lowering/EmitFanucArith.cpp).
#pragma once

#include "ir/Bcd.h"

#include <llvm/IR/Constants.h>
#include <llvm/IR/IRBuilder.h>

#include <utility>

namespace lj::lower {

/// The binary value of the low `digits` (at most 8) BCD digits of the i32 `raw`, and whether
/// one of them is above 9 (the value then takes that nibble at its binary value, as
/// bcd::decodeLoose does).
inline std::pair<llvm::Value *, llvm::Value *> bcdValue(llvm::IRBuilderBase &b, llvm::Value *raw,
                                                        int digits) {
  llvm::Value *v = b.getInt32(0), *bad = b.getFalse();
  for (int k = 0; k < digits; ++k) {
    llvm::Value *d =
        b.CreateAnd(b.CreateLShr(raw, static_cast<uint64_t>(bcd::kDigitBits * k)), 0xF);
    bad = b.CreateOr(bad, b.CreateICmpUGT(d, b.getInt32(9)));
    v = b.CreateAdd(v, b.CreateMul(d, b.getInt32(static_cast<uint32_t>(bcd::limit(k)))));
  }
  return {v, bad};
}

/// `digits` BCD digits of the non-negative integer `v` (bcd::encode), in v's type (i32 or i64;
/// the digits must fit it).
inline llvm::Value *bcdDigits(llvm::IRBuilderBase &b, llvm::Value *v, int digits) {
  llvm::Type *t = v->getType();
  llvm::Value *r = llvm::ConstantInt::get(t, 0);
  for (int k = 0; k < digits; ++k) {
    llvm::Value *d = b.CreateURem(
        b.CreateUDiv(v, llvm::ConstantInt::get(t, static_cast<uint64_t>(bcd::limit(k)))),
        llvm::ConstantInt::get(t, 10));
    r = b.CreateOr(r, b.CreateShl(d, static_cast<uint64_t>(bcd::kDigitBits * k)));
  }
  return r;
}

} // namespace lj::lower

// Facts of the FANUC PMC arithmetic (ADDB..DIVB, ADD..DIV, NUME; ops BinaryArith, BcdArith,
// BcdConstant) that the front end (frontends/fanuc/ArithFunctional.cpp), the interpreter
// (interp/InterpFanucArith.cpp) and the lowering (lowering/EmitFanucArith.cpp) share: the
// operation codes, the R9000 flag bits and the value ranges (FANUC PMC manual ref 2,
// 3.1, 3.2, 6.10; the [EXT] readings are rows of docs/fanuc-pmc.md).
#pragma once

#include "ir/Bcd.h"

#include <cstdint>

namespace lj::pmc {

/// Operand 0 of BinaryArith / BcdArith: which operation.
constexpr int32_t kArithAdd = 0, kArithSub = 1, kArithMul = 2, kArithDiv = 3;

/// R9000 bits written by the binary arithmetic (reference 2 names Z #0, N #1 and V #5 for
/// COMPB/DCNVB; 6.10 [EXT] "overflow/sign/zero"): Z the result is 0, N it is negative, V
/// overflow.
constexpr int32_t kArithFlagZ = 0x01, kArithFlagN = 0x02, kArithFlagV = 0x20;

/// The R9000 byte and the first byte of the DIVB remainder (reference 2 [EXT]: R9002..R9005).
constexpr int32_t kFlagsRelay = 9000, kRemainderRelay = 9002;

/// Smallest and largest signed value of `width` (1, 2, 4) bytes (reference 3.1).
constexpr int64_t minOf(int width) { return -(int64_t{1} << (8 * width - 1)); }
constexpr int64_t maxOf(int width) { return (int64_t{1} << (8 * width - 1)) - 1; }

/// 10^digits: the first value that does not fit `digits` BCD digits (reference 3.2).
constexpr int64_t bcdLimit(int digits) { return bcd::limit(digits); }

} // namespace lj::pmc

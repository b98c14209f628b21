// Facts of the FANUC PMC timers, counters and compares (family PmcTc) that the interpreter
// (interp/InterpPmcTc.cpp) and the lowering (lowering/EmitPmcTc.cpp) share: time units, the
// preset reading, the BCD reading and the R9000 flag bits (FANUC PMC manual ref 2,
// 3.2, 6.3, 6.6; choices in docs/fanuc-pmc.md).
#pragma once

#include "ir/Bcd.h"

#include <cstdint>

namespace lj::pmc {

/// R9000 bits written by COMPB (reference 2): Z (#0) equal, N (#1) input < comparison.
constexpr int32_t kFlagZ = 1, kFlagN = 2;

/// PmcCounter's data-type operand (ops[2]): binary always (CTRB, CTRC), or the counter data type
/// of the system parameter (CTR, reference 6.4 [L1971-L1973]: BCD or binary, "chosen globally";
/// TargetProfile::SystemParams::counterFormat). In BCD the preset and the count are 4 BCD digits
/// in their 2 bytes, 0..9999 (reference 6.4 [L2031]).
constexpr int32_t kCounterBinary = 0, kCounterSystemType = 1;

/// BcdCompare relation operand: COMP (input <= comparison) or COIN (input == comparison).
constexpr int32_t kBcdLessEqual = 0, kBcdEqual = 1;

/// TMR precision codes in T9000.. (reference 6.3 [L1631-L1653]): 0 default, 1 1 ms, 2 10 ms,
/// 3 100 ms, 4 1 s, 5 1 min. A code outside 0..5 is read as 0 (docs/fanuc-pmc.md [EXT] row).
constexpr uint32_t kTmrUnits[6] = {0, 1, 10, 100, 1000, 60000};
/// Default TMR unit (reference 6.3 [L1555-L1559]): timers 1-8 48 ms, 9 and up 8 ms.
constexpr uint32_t tmrDefaultUnit(int32_t timer) { return timer <= 8 ? 48 : 8; }
constexpr uint32_t tmrUnitMs(int32_t code, int32_t timer) {
  return code >= 1 && code <= 5 ? kTmrUnits[code] : tmrDefaultUnit(timer);
}

/// TMRC precision codes (reference 6.3 [L1797-L1833]): 0 8 ms, 1 48 ms, 2 1 s, 3 10 s, 4 1 min,
/// 5 1 ms, 6 10 ms, 7 100 ms.
constexpr uint32_t kTmrcUnits[8] = {8, 48, 1000, 10000, 60000, 1, 10, 100};
constexpr uint32_t tmrcUnitMs(int32_t code) { return kTmrcUnits[code & 7]; }

/// The preset in ms of a 2-byte preset count (the count of time units, 0..32767; a negative
/// count is 0).
constexpr uint32_t presetMs(int32_t count, uint32_t unit) {
  return count <= 0 ? 0u : static_cast<uint32_t>(count) * unit; // 32767 * 60000 < 2^31
}

/// The value of `width` (1 or 2) bytes of BCD in the low bits of `raw`: each nibble a decimal
/// digit, a nibble above 9 taken at its binary value (docs/fanuc-pmc.md [EXT] row).
constexpr int32_t bcdValue(int32_t raw, int width) {
  return static_cast<int32_t>(bcd::decodeLoose(static_cast<uint32_t>(raw), 2 * width));
}

} // namespace lj::pmc

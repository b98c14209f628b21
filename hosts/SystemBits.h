// The system bits a target's runtime writes before every tick (ir/Profile.h SystemBit: FANUC
// R9091 constants and clocks, R9015 first scan). Every host that runs ticks (`run`'s simulation,
// the test machine) calls it, so all engines see the same values.
#pragma once

#include "ir/Profile.h"
#include "ladderjit/abi.h"

#include <cstdint>

namespace lj::hosts {

/// Write `tp`'s system bits into `s` for tick number `tick` at s.now_ms (set now_ms first).
void writeSystemBits(const TargetProfile &tp, lj_state &s, uint64_t tick);

} // namespace lj::hosts

// What every engine relies on in a verified program (ir/Program.h), checked by the libFuzzer
// targets on each program a front end accepts: a violation is a front-end or verifier bug.
#pragma once

#include "ir/Program.h"

#include <cstddef>

namespace lj::fuzztest {

/// Traps unless the statement facts cover every statement and the PLC2 slices tile the sliced
/// part exactly, in order.
inline void checkProgramInvariants(const VerifiedProgram &p) {
  if (p.info.size() != p.stmts.size() || p.slices.empty() ||
      p.slices.size() != p.sliceDepth.size() || p.slices.front().begin != p.plc2.begin ||
      p.slices.back().end != p.plc2.end)
    __builtin_trap();
  for (size_t k = 1; k < p.slices.size(); ++k)
    if (p.slices[k].begin != p.slices[k - 1].end) __builtin_trap();
}

} // namespace lj::fuzztest

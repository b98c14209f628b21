// Which statements read the synchronized input memory (ir/Profile.h TargetProfile::SyncInputs,
// FANUC level 2, FANUC 0i-D PMC manual 4.1), a fact of the verified program that the
// interpreter and the lowering each apply in their own way (interp/Interpreter.cpp decodes the
// operand at the copy, lowering/EmitBasic.cpp areaLoc addresses it).
#pragma once

#include "ir/Profile.h"
#include "ir/Program.h"

namespace lj {

/// Whether the engines keep `p`'s synchronized input memory: the profile has one and the sliced
/// part is divided. An undivided sliced part runs right after the every-tick part in the same
/// tick, and that part cannot write the inputs, so it reads them live: the same values.
inline bool latchesSyncInputs(const VerifiedProgram &p) {
  return p.profile && p.profile->syncInputs.bytes != 0 && p.slices.size() > 1;
}

/// Whether statement `i` of `p` reads the synchronized input memory instead of the live inputs:
/// latchesSyncInputs(p) and `i` lies outside the init and every-tick parts, so in the sliced part
/// or in a subroutine, which only the sliced part calls on such a target (FANUC level 1 cannot
/// call, ref 4.2).
inline bool readsSyncInputs(const VerifiedProgram &p, int32_t i) {
  auto in = [i](StmtRange r) { return i >= r.begin && i < r.end; };
  return latchesSyncInputs(p) && !in(p.plc1) && !in(p.init);
}

} // namespace lj

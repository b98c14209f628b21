// The stack effect of one instruction, from its table row and the ST depth before it
// (DIALECT.md 3 and 5): the one place that turns a StackRule into numbers.
#pragma once

#include "ir/OpTable.h"

#include <algorithm>
#include <cstdint>

namespace lj {

/// What one statement does to the ST and MS stacks.
struct StackEffect {
  int32_t reads = 0;   ///< ST entries (from the top) whose value it reads
  int32_t pops = 0;    ///< ST entries it removes
  int32_t pushes = 0;  ///< ST entries it adds after popping
  int32_t msDelta = 0; ///< +1 MPS, -1 MPP
  bool resets = false; ///< Structural: both stacks emptied
  /// ST depth after the statement (never below 0).
  int32_t after(int32_t depth) const { return resets ? 0 : std::max(depth - pops, 0) + pushes; }
};

/// Effect of an instruction with row `ii` at ST depth `depth` on a valid program. MRD/MPP
/// overwrite ST0 without reading it; a single-input block reads ST0 only when there is one.
constexpr StackEffect stackEffect(const InstrInfo &ii, int32_t depth) {
  const int32_t top = depth > 0 ? 1 : 0;
  StackEffect e;
  switch (ii.stack) {
  case StackRule::Push:
    e.pushes = 1;
    break;
  case StackRule::Combine:
    e.reads = 1;
    e.pops = top;
    e.pushes = 1;
    break;
  case StackRule::BlockPop:
    e.reads = 2;
    e.pops = std::min(depth, 2);
    e.pushes = 1;
    break;
  case StackRule::MpsPush:
    e.reads = 1;
    e.pops = top;
    e.pushes = 1;
    e.msDelta = 1;
    break;
  case StackRule::MsRead:
  case StackRule::MsPop:
    e.pops = top;
    e.pushes = 1;
    e.msDelta = ii.stack == StackRule::MsPop ? -1 : 0;
    break;
  case StackRule::Coil:
    e.reads = 1;
    break;
  case StackRule::Structural:
    e.resets = true;
    break;
  case StackRule::Block:
    e.reads = std::min<int32_t>(ii.inputs, depth);
    if (ii.inputs > 1) {
      e.pops = std::min<int32_t>(ii.inputs, depth);
      e.pushes = 1;
    } else if (ii.output != OutputRule::None) {
      e.pops = top;
      e.pushes = 1;
    }
    break;
  }
  return e;
}

} // namespace lj

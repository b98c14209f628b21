// Rung boundaries of a verified program (Program.h RungRange): a logic rung starts where MS is
// empty and no ST entry present is read later before the next stack reset; markers are rungs of
// their own. PLC2 slice boundaries (SlicePlanner.cpp) are a subset of these.
#include "ir/StackEffect.h"
#include "verify/VerifierInternal.h"

#include <climits>

namespace lj::verifier {

void planRungs(Context &cx) {
  VerifiedProgram &p = cx.prog;
  auto n = static_cast<int32_t>(p.stmts.size());
  p.rungs.clear();
  // lowest[i]: the lowest ST position read by statement i or a later one before the next reset
  // (the argument of SlicePlanner.cpp: entries before i are dead iff lowest[i] >= depth(i)).
  std::vector<int32_t> lowest(static_cast<size_t>(n) + 1, INT32_MAX);
  for (int32_t i = n - 1; i >= 0; --i) {
    const InstrInfo &ii = instrInfo(p.stmts[static_cast<size_t>(i)].op);
    int32_t d = p.info[static_cast<size_t>(i)].depth;
    auto at = static_cast<size_t>(i);
    if (ii.stack == StackRule::Structural) continue; // lowest[at] stays INT32_MAX
    int32_t k = stackEffect(ii, d).reads;
    lowest[at] = std::min(k > 0 ? d - k : INT32_MAX, lowest[at + 1]);
  }
  for (int32_t i = 0; i < n; ++i) {
    const StmtInfo &in = p.info[static_cast<size_t>(i)];
    if (instrInfo(p.stmts[static_cast<size_t>(i)].op).stack == StackRule::Structural) {
      p.rungs.push_back({RungRange::Kind::Marker, {i, i + 1}});
      continue;
    }
    bool boundary = in.msDepth == 0 && lowest[static_cast<size_t>(i)] >= in.depth;
    if (boundary || p.rungs.empty() || p.rungs.back().kind == RungRange::Kind::Marker)
      p.rungs.push_back({RungRange::Kind::Logic, {i, i + 1}});
    else
      p.rungs.back().range.end = i + 1;
  }
}

} // namespace lj::verifier

// Where a long body may be cut into separate LLVM functions (compile time stays linear in the
// program size). A cut needs no live ST entry, an empty MS, and no loop or jump across it; the
// entries still on ST there are dead and the next function starts them as 0.
#include "lowering/FunctionEmitter.h"

#include <algorithm>
#include <set>

namespace lj::lower {

namespace {

// Backward liveness of ST positions (0 = bottom): which entries present before statement i are
// read by a later statement before being overwritten or reset.
void liveTransfer(const Stmt &s, int32_t d, std::set<int32_t> &live) {
  const InstrInfo &row = instrInfo(s.op);
  switch (row.stack) {
  case StackRule::Push:
    live.erase(d);
    break;
  case StackRule::Combine:
  case StackRule::MpsPush:
  case StackRule::Coil:
    live.insert(d - 1);
    break;
  case StackRule::BlockPop:
    live.insert(d - 1);
    live.insert(d - 2);
    break;
  case StackRule::MsRead:
  case StackRule::MsPop:
    live.erase(d - 1);
    break;
  case StackRule::Structural:
    live.clear();
    break;
  case StackRule::Block: {
    const int32_t k = row.inputs;
    const bool writes = row.output != OutputRule::None;
    if (d >= k && d > 0) {
      if (writes) live.erase(d - k);
      for (int32_t p = d - k; p < d; ++p) live.insert(p);
    } else if (writes) {
      live.erase(d);
    }
    break;
  }
  }
}

} // namespace

std::vector<StmtRange> planChunks(const VerifiedProgram &p, StmtRange r, int32_t target) {
  const int32_t n = r.end - r.begin;
  if (target <= 0 || n <= target) return {r};
  // ok[j] says whether a cut before statement r.begin + j is allowed.
  std::vector<char> ok(static_cast<size_t>(n), 1);
  ok[0] = 0;
  std::vector<int32_t> spans(static_cast<size_t>(n) + 1, 0); // difference array of JMP spans
  int32_t nest = 0;
  for (int32_t i = r.begin; i < r.end; ++i) {
    const Stmt &s = p.stmts[i];
    const StmtInfo &info = p.info[i];
    if (nest > 0 || info.msDepth != 0) ok[i - r.begin] = 0;
    if (s.op == Op::LoopBegin) ++nest;
    if (s.op == Op::LoopEnd) --nest;
    if (s.op == Op::Jump && info.target >= r.begin && info.target < r.end) {
      // Cuts before statements lo+1 .. hi would separate the JMP from its label.
      int32_t lo = std::min(i, info.target), hi = std::max(i, info.target);
      spans[lo + 1 - r.begin] += 1;
      spans[hi + 1 - r.begin] -= 1;
    }
  }
  int32_t open = 0;
  for (int32_t j = 0; j < n; ++j) {
    open += spans[j];
    if (open > 0) ok[j] = 0;
  }
  std::set<int32_t> live;
  for (int32_t i = r.end - 1; i >= r.begin; --i) {
    liveTransfer(p.stmts[i], p.info[i].depth, live);
    if (!live.empty()) ok[i - r.begin] = 0;
  }
  std::vector<StmtRange> out;
  int32_t start = r.begin;
  for (int32_t i = r.begin + 1; i < r.end; ++i) {
    if (ok[i - r.begin] && i - start >= target) {
      out.push_back({start, i});
      start = i;
    }
  }
  out.push_back({start, r.end});
  return out;
}

} // namespace lj::lower

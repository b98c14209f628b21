// Where a long body may be cut into separate LLVM functions (compile time stays linear in the
// program size). A cut needs a rung boundary (VerifiedProgram::rungs: no live ST entry, an empty
// MS) and no loop or jump across it; the entries still on ST there are dead and the next
// function starts them as 0.
#include "lowering/FunctionEmitter.h"

#include <algorithm>

namespace lj::lower {

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
    if (s.op == Op::LOOP) ++nest;
    if (s.op == Op::NEXT) --nest;
    if (s.op == Op::JMP && info.target >= r.begin && info.target < r.end) {
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
  // Only at a rung start (VerifiedProgram::rungs): MS empty, every ST entry present dead.
  std::vector<char> rungStart(static_cast<size_t>(n), 0);
  for (const RungRange &rr : p.rungs)
    if (rr.range.begin >= r.begin && rr.range.begin < r.end)
      rungStart[rr.range.begin - r.begin] = 1;
  for (int32_t j = 0; j < n; ++j)
    if (!rungStart[j]) ok[j] = 0;
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

// Where a long body may be cut into separate LLVM functions (compile time stays linear in the
// program size). No loop (one that stays inline) and no JMP..LBL span may cross a cut. A clean
// cut has no live ST entry and an empty MS: the entries still on ST there are dead and the next
// function starts them as 0. Where a body has no clean cut for long (one long rung, a deep MS),
// a carried cut hands the live entries to the next function through the body's carry buffer.
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

// Lowest ST (ms = false) or MS position statement i may read, replace or pop (its depth when
// it touches none). Structural statements are handled by the caller.
int32_t touchedLow(const VerifiedProgram &p, int32_t i, bool ms) {
  const StmtInfo &info = p.info[i];
  const InstrInfo &row = instrInfo(p.stmts[i].op);
  int32_t d = ms ? info.msDepth : info.depth, n = 0;
  switch (row.stack) {
  case StackRule::Push:
    break;
  case StackRule::MpsPush:
    n = ms ? 0 : 1;
    break;
  case StackRule::MsRead:
  case StackRule::MsPop:
    n = 1;
    break;
  case StackRule::BlockPop:
    n = ms ? 0 : 2;
    break;
  case StackRule::Block:
    n = ms ? 0 : std::max<int32_t>(row.inputs, 1);
    break;
  default: // Combine, Coil
    n = ms ? 0 : 1;
    break;
  }
  return std::max(d - n, 0);
}

// The positions a chunk exchanges through the carry buffer (ChunkPlan).
void carryRanges(const VerifiedProgram &p, ChunkPlan &c) {
  int32_t st = p.info[c.r.begin].depth, ms = p.info[c.r.begin].msDepth;
  bool reset = false; // a structural statement emptied both stacks
  for (int32_t i = c.r.begin; i < c.r.end; ++i) {
    if (instrInfo(p.stmts[i].op).stack == StackRule::Structural) {
      reset = true;
      break;
    }
    st = std::min(st, touchedLow(p, i, false));
    ms = std::min(ms, touchedLow(p, i, true));
  }
  if (c.carriedIn) {
    c.stLoad = st;
    c.msLoad = ms;
  }
  if (c.carriedOut) {
    c.stStore = reset ? 0 : st;
    c.msStore = reset ? 0 : ms;
  }
}

} // namespace

std::vector<ChunkPlan> planChunkFunctions(const VerifiedProgram &p, StmtRange r, int32_t target) {
  const int32_t n = r.end - r.begin;
  if (target <= 0 || n <= target) return {ChunkPlan{r}};
  // clean[j] / carry[j]: whether a clean / carried cut before statement r.begin + j is allowed.
  std::vector<char> clean(static_cast<size_t>(n), 1), carry(static_cast<size_t>(n), 1);
  clean[0] = carry[0] = 0;
  std::vector<int32_t> spans(static_cast<size_t>(n) + 1, 0); // difference array of JMP spans
  int32_t nest = 0;
  for (int32_t i = r.begin; i < r.end; ++i) {
    const Stmt &s = p.stmts[i];
    const StmtInfo &info = p.info[i];
    if (nest > 0) clean[i - r.begin] = carry[i - r.begin] = 0;
    if (info.msDepth != 0) clean[i - r.begin] = 0;
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
    if (open > 0) clean[j] = carry[j] = 0;
  }
  std::set<int32_t> live;
  for (int32_t i = r.end - 1; i >= r.begin; --i) {
    liveTransfer(p.stmts[i], p.info[i].depth, live);
    if (!live.empty()) clean[i - r.begin] = 0;
  }
  // Greedy: a clean cut once `target` statements are in the chunk; a carried one only after
  // twice that without a clean cut (ordinary rung-structured code never needs one).
  std::vector<ChunkPlan> out;
  int32_t start = r.begin;
  bool carriedIn = false;
  for (int32_t i = r.begin + 1; i < r.end; ++i) {
    const int32_t len = i - start;
    const bool cleanCut = clean[i - r.begin] && len >= target;
    const bool carriedCut = !cleanCut && carry[i - r.begin] && len >= 2 * target;
    if (cleanCut || carriedCut) {
      out.push_back(ChunkPlan{{start, i}, carriedIn, carriedCut});
      start = i;
      carriedIn = carriedCut;
    }
  }
  out.push_back(ChunkPlan{{start, r.end}, carriedIn, false});
  for (ChunkPlan &c : out) carryRanges(p, c);
  return out;
}

std::vector<StmtRange> planChunks(const VerifiedProgram &p, StmtRange r, int32_t target) {
  std::vector<StmtRange> out;
  for (const ChunkPlan &c : planChunkFunctions(p, r, target)) out.push_back(c.r);
  return out;
}

} // namespace lj::lower

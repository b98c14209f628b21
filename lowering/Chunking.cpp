// Where a long body may be cut into separate LLVM functions (compile time stays linear in the
// program size). No loop (one that stays inline) and no JMP..LBL span may cross a cut. A clean
// cut is at a rung start (VerifiedProgram::rungs: no live ST entry, an empty MS): the entries
// still on ST there are dead and the next function starts them as 0. Where a body has no rung
// start for long (one long rung, a deep MS), a carried cut hands the live entries to the next
// function through the body's carry buffer.
#include "lowering/FunctionEmitter.h"

#include <algorithm>

namespace lj::lower {

namespace {

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

// Size of a statement's lowering in units of about 4 IR instructions (most rows: 1). Measured
// per row with bench/gen_worst (docs/BENCHMARKS.md "Compile time is linear"); the CTest
// CompileBound checks the resulting bound on every function, so a heavier lowering of a row
// shows there. Ranges of up to 32 elements are unrolled (lowering/EmitData.cpp): ~4 IR each.
int32_t stmtWeight(const Stmt &s) {
  auto unrolled = [](int32_t n) { return n >= 1 && n <= 32 ? n : 0; };
  switch (s.op) {
  case Op::BlockMove:
    return std::max(5, unrolled(s.ops[2].value));
  case Op::Fill:
  case Op::ZoneReset:
    return std::max(
        4, s.ops[0].kind == Operand::Kind::Reg ? unrolled(s.ops[1].index - s.ops[0].index + 1) : 0);
  case Op::TableEncode:
  case Op::TableDecode:
  case Op::TableSearch:
    return std::max(6, unrolled(s.ops[1].value));
  case Op::BusSpindleGeared:
    return 22;
  case Op::SpindleAnalog:
    return 10;
  case Op::ToolSelect:
  case Op::HandwheelSet:
  case Op::TempSensor:
    return 8;
  case Op::RangeConvert:
  case Op::PanelDisplay:
  case Op::MCodeGet:
  case Op::MCodeAck:
  case Op::TableLookup:
  case Op::VarGet:
  case Op::RaiseEvent:
    return 6;
  case Op::SaveRetained:
  case Op::ToolLife:
  case Op::BusSpindle:
  case Op::PointToNumber:
  case Op::VarSet:
  case Op::ChannelModeGet:
  case Op::ToolInUse:
    return 4;
  case Op::OnDelayTimer:
  case Op::SpindleJog:
  case Op::ToolVectorOn:
  case Op::ToolVectorOff:
  case Op::SlaveHomingEnable:
  case Op::HandwheelPulse:
  case Op::Divide:
  case Op::AndRise:
  case Op::AndFall:
  case Op::UserOutput:
  case Op::OrRise:
  case Op::OrFall:
  case Op::NumberToPoint:
  case Op::OffDelayTimer:
  case Op::AxisMoveAbsolute:
  case Op::AxisMoveRelative:
  case Op::LoopBegin: // four blocks and a phi
    return 3;
  case Op::MagazineRotate:
  case Op::LoadRise:
  case Op::LoadFall:
    return 2;
  default:
    return 1;
  }
}

} // namespace

int64_t bodyWeight(const VerifiedProgram &p, StmtRange r) {
  int64_t w = 0;
  for (int32_t i = r.begin; i < r.end; ++i) w += stmtWeight(p.stmts[i]);
  return w;
}

std::vector<ChunkPlan> planChunkFunctions(const VerifiedProgram &p, StmtRange r, int32_t target,
                                          const std::vector<int64_t> *weightBefore) {
  std::vector<int64_t> own;
  if (!weightBefore) { // prefix sums of the whole program (callers outside the lowering)
    own.push_back(0);
    for (int32_t i = 0; i < static_cast<int32_t>(p.stmts.size()); ++i)
      own.push_back(own.back() + stmtWeight(p.stmts[i]));
    weightBefore = &own;
  }
  const std::vector<int64_t> &w = *weightBefore;
  const int32_t n = r.end - r.begin;
  if (target <= 0 || n <= 1 || w[r.end] - w[r.begin] <= target) return {ChunkPlan{r}};
  // Only the statements of this body's own level are cut positions: a cut never falls inside a
  // loop (inline or outlined), and JMP/LBL never cross a loop body (DIALECT.md), so a nested
  // loop is skipped whole. The work is linear in the statements of this level, not in the body:
  // a nest of n outlined loops plans each of them once (O(n), not O(n^2) in all).
  std::vector<int32_t> pos; // statements at this level, ascending (a LOOP stands for its body)
  std::vector<std::pair<int32_t, int32_t>> pairs; // (JMP, LBL) pairs at this level
  std::vector<int32_t> labels;                    // jump targets at this level
  for (int32_t i = r.begin; i < r.end; ++i) {
    pos.push_back(i);
    const Stmt &s = p.stmts[i];
    const StmtInfo &info = p.info[i];
    if (s.op == Op::LoopBegin && info.target > i && info.target < r.end) {
      i = info.target; // the body and its NEXT: no cut before any of them
      continue;
    }
    if (s.op == Op::Jump && info.target >= r.begin && info.target < r.end) {
      pairs.emplace_back(i, info.target);
      labels.push_back(info.target);
    }
    if (s.op == Op::Call) // a CALL goes on at a label too when its callee takes a JumpOut
      for (const auto &[call, lbl] : exitsOfCall(p, i))
        if (lbl >= r.begin && lbl < r.end) {
          pairs.emplace_back(i, lbl);
          labels.push_back(lbl);
        }
  }
  std::sort(labels.begin(), labels.end());
  labels.erase(std::unique(labels.begin(), labels.end()), labels.end());
  const size_t m = pos.size();
  auto at = [&](int32_t stmt) {
    return static_cast<size_t>(std::lower_bound(pos.begin(), pos.end(), stmt) - pos.begin());
  };
  // Per position k (a cut before statement pos[k]): inSpan (between a JMP and its LBL), carried
  // (an ST entry is live or MS is not empty).
  std::vector<char> inSpan(m, 0), carried(m, 1);
  std::vector<int32_t> spans(m + 1, 0); // difference array of JMP spans
  for (auto [from, to] : pairs) {
    // Cuts before statements lo+1 .. hi would separate the JMP from its label.
    const size_t lo = at(std::min(from, to)), hi = at(std::max(from, to));
    spans[lo + 1] += 1;
    spans[hi + 1] -= 1;
  }
  int32_t open = 0;
  for (size_t k = 0; k < m; ++k) {
    open += spans[k];
    if (open > 0) inSpan[k] = 1;
  }
  // A cut anywhere but at a rung start (VerifiedProgram::rungs, in program order) carries the
  // live entries.
  auto rung = std::lower_bound(p.rungs.begin(), p.rungs.end(), r.begin,
                               [](const RungRange &rr, int32_t i) { return rr.range.begin < i; });
  for (size_t k = 0; k < m; ++k) {
    while (rung != p.rungs.end() && rung->range.begin < pos[k]) ++rung;
    if (rung != p.rungs.end() && rung->range.begin == pos[k]) carried[k] = 0;
    if (p.info[pos[k]].msDepth != 0) carried[k] = 1;
  }
  // Greedy: a clean cut once the chunk weighs `target` (statements of ordinary size); at twice
  // that without one, a carried cut, and at three times a cut inside JMP spans (rung-structured
  // code never needs either). A cut inside spans makes every jumped-to label (at this level)
  // start a chunk, so a JMP to another chunk returns kStatusJump + that chunk to the body.
  std::vector<int32_t> cuts;
  std::vector<char> cutCarried;
  bool jumps = false;
  int64_t weight = 0;
  for (size_t k = 1; k < m; ++k) {
    weight += w[pos[k]] - w[pos[k - 1]];
    if (weight < target) continue;
    const bool ok = inSpan[k] ? weight >= 3 * target : !carried[k] || weight >= 2 * target;
    if (ok) {
      jumps = jumps || inSpan[k];
      cuts.push_back(pos[k]);
      weight = 0;
    }
  }
  if (jumps) {
    cuts.insert(cuts.end(), labels.begin(), labels.end());
    std::sort(cuts.begin(), cuts.end());
    cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
    if (!cuts.empty() && cuts.front() == r.begin) cuts.erase(cuts.begin());
  }
  for (int32_t cut : cuts) cutCarried.push_back(carried[at(cut)]);
  std::vector<ChunkPlan> out;
  int32_t start = r.begin;
  bool carriedIn = false;
  cuts.push_back(r.end);
  for (size_t k = 0; k < cuts.size(); ++k) {
    const int32_t cut = cuts[k];
    const bool carriedOut = cut < r.end && cutCarried[k];
    out.push_back(ChunkPlan{{start, cut}, carriedIn, carriedOut});
    out.back().jumps = jumps;
    start = cut;
    carriedIn = carriedOut;
  }
  for (ChunkPlan &c : out) carryRanges(p, c);
  return out;
}

std::vector<StmtRange> planChunks(const VerifiedProgram &p, StmtRange r, int32_t target) {
  std::vector<StmtRange> out;
  for (const ChunkPlan &c : planChunkFunctions(p, r, target, nullptr)) out.push_back(c.r);
  return out;
}

} // namespace lj::lower

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

std::vector<ChunkPlan> planChunkFunctions(const VerifiedProgram &p, StmtRange r, int32_t target) {
  const int32_t n = r.end - r.begin;
  if (target <= 0 || n <= 1 || bodyWeight(p, r) <= target) return {ChunkPlan{r}};
  // Per cut position j (before statement r.begin + j): inLoop (inside an inline loop: never),
  // inSpan (between a JMP and its LBL), carried (an ST entry is live or MS is not empty).
  std::vector<char> inLoop(static_cast<size_t>(n), 0), inSpan(static_cast<size_t>(n), 0),
      carried(static_cast<size_t>(n), 0);
  std::vector<int32_t> spans(static_cast<size_t>(n) + 1, 0); // difference array of JMP spans
  std::vector<int32_t> labels;                               // jump targets outside loops
  int32_t nest = 0;
  for (int32_t i = r.begin; i < r.end; ++i) {
    const Stmt &s = p.stmts[i];
    const StmtInfo &info = p.info[i];
    if (nest > 0) inLoop[i - r.begin] = 1;
    if (s.op == Op::LoopBegin) ++nest;
    if (s.op == Op::LoopEnd) --nest;
    if (s.op == Op::Jump && info.target >= r.begin && info.target < r.end) {
      // Cuts before statements lo+1 .. hi would separate the JMP from its label.
      int32_t lo = std::min(i, info.target), hi = std::max(i, info.target);
      spans[lo + 1 - r.begin] += 1;
      spans[hi + 1 - r.begin] -= 1;
      if (nest == 0) labels.push_back(info.target);
    }
  }
  int32_t open = 0;
  for (int32_t j = 0; j < n; ++j) {
    open += spans[j];
    if (open > 0) inSpan[j] = 1;
  }
  // A cut anywhere but at a rung start (VerifiedProgram::rungs) carries the live entries.
  std::fill(carried.begin(), carried.end(), 1);
  for (const RungRange &rr : p.rungs)
    if (rr.range.begin >= r.begin && rr.range.begin < r.end) carried[rr.range.begin - r.begin] = 0;
  for (int32_t i = r.begin; i < r.end; ++i)
    if (p.info[i].msDepth != 0) carried[i - r.begin] = 1;
  // Greedy: a clean cut once the chunk weighs `target` (statements of ordinary size); at twice
  // that without one, a carried cut, and at three times a cut inside JMP spans (rung-structured
  // code never needs either). A cut inside spans makes every jumped-to label (outside loops)
  // start a chunk, so a JMP to another chunk returns kStatusJump + that chunk to the body.
  std::vector<int32_t> cuts;
  bool jumps = false;
  int64_t weight = 0;
  for (int32_t i = r.begin + 1; i < r.end; ++i) {
    const size_t j = static_cast<size_t>(i - r.begin);
    weight += stmtWeight(p.stmts[i - 1]);
    if (inLoop[j] || weight < target) continue;
    const bool ok = inSpan[j] ? weight >= 3 * target : !carried[j] || weight >= 2 * target;
    if (ok) {
      jumps = jumps || inSpan[j];
      cuts.push_back(i);
      weight = 0;
    }
  }
  if (jumps) {
    cuts.insert(cuts.end(), labels.begin(), labels.end());
    std::sort(cuts.begin(), cuts.end());
    cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
    if (!cuts.empty() && cuts.front() == r.begin) cuts.erase(cuts.begin());
  }
  std::vector<ChunkPlan> out;
  int32_t start = r.begin;
  bool carriedIn = false;
  cuts.push_back(r.end);
  for (int32_t cut : cuts) {
    const bool carriedOut = cut < r.end && carried[cut - r.begin];
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
  for (const ChunkPlan &c : planChunkFunctions(p, r, target)) out.push_back(c.r);
  return out;
}

} // namespace lj::lower

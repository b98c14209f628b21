// Random valid STL programs for differential fuzzing, driven by the instruction table: every row
// that is not a flow instruction is chosen and given operands from its OperandSpecs, stack rule
// and input count alone; a structural planner places parts, jumps, loops and subroutines.
#include "frontends/hnc8/Mnemonics.h"
#include "gen/GenPools.h"
#include "gen/ProgramGenerator.h"
#include "gen/RandomGen.h"
#include "ir/OpTable.h"
#include "ir/StackEffect.h"

#include <array>
#include <cassert>
#include <cctype>
#include <iterator>
#include <map>

namespace lj::gen {

namespace detail {

namespace {

/// Flow instructions whose placement needs the planner (labels, subroutines, scopes).
bool isPlanned(const InstrInfo &in) {
  if (in.stack == StackRule::Structural) return true;
  for (int i = 0; i < in.operandCount; ++i)
    if (hasArea(in.operands[i].areas, Area::Label) ||
        hasArea(in.operands[i].areas, Area::Subroutine))
      return true;
  return in.op == Op::Return; // only valid inside a subroutine
}

/// The per-program stack mixes (Profile, gen/RandomGen.h).
constexpr Profile kProfiles[] = {
    // Push Combine BlockPop MpsPush MsRead MsPop Coil Structural Block
    {{6, 5, 6, 2, 1, 2, 4, 0, 8}, 16}, // deep ANB/ORB nesting
    {{4, 6, 1, 1, 1, 1, 6, 0, 8}, 8},  // rung style, entries die
    {{3, 3, 2, 3, 3, 3, 4, 0, 12}, 6}, // MPS branches and blocks
};

} // namespace

RandomGen::RandomGen(const RandomOptions &o) : o_(o), rng_(o.seed) {
  for (const InstrInfo &in : instrTable())
    if (hnc8::spells(in.op) && !isPlanned(in)) generic_[static_cast<int>(in.stack)].push_back(&in);
  for (const InstrInfo *in : generic_[static_cast<int>(StackRule::Block)])
    if (in->inputs > 1) multi_.push_back(in);
}

bool RandomGen::eligible(const InstrInfo &in) const {
  switch (in.stack) {
  case StackRule::Push:
    return depth_ < prof_.depthCap;
  case StackRule::Combine:
  case StackRule::Coil:
    return depth_ >= 1;
  case StackRule::BlockPop:
    return depth_ >= 2;
  case StackRule::MpsPush:
    return depth_ >= 1 && ms_ < o_.maxMsDepth;
  case StackRule::MsRead:
  case StackRule::MsPop:
    return depth_ >= 1 && ms_ >= 1;
  case StackRule::Block:
    return in.inputs <= 1 || depth_ >= in.inputs;
  case StackRule::Structural:
    return false;
  }
  return false;
}

void RandomGen::emitOneGeneric() {
  std::array<int, 9> w{};
  for (int r = 0; r < 9; ++r) {
    bool any = false;
    for (const InstrInfo *in : generic_[r]) any = any || eligible(*in);
    w[r] = any ? prof_.weight[r] : 0;
  }
  // An empty ST leaves only pushes and blocks; a block that needs an input with an empty ST
  // only draws a warning, so prefer a push there.
  if (depth_ == 0) w[static_cast<int>(StackRule::Block)] = 1;
  // Blocks with several power-flow inputs (counters: 2/4, ROT: 5) are rare among ~100 block
  // rows and need a deep ST: now and then build the inputs up and emit one.
  if (rng_.chance(3)) {
    const InstrInfo *in = multi_[rng_.below(multi_.size())];
    if (in->inputs <= prof_.depthCap) {
      while (depth_ < in->inputs) emitPush();
      return emitGeneric(*in);
    }
  }
  if (rng_.below(1000) < kLongPerMille) {
    forceLong_ = true;
    emitGeneric(instrInfo(kLongRows[rng_.below(std::size(kLongRows))]));
    forceLong_ = false;
    return;
  }
  const auto &rows = generic_[rng_.weighted(w)];
  for (;;) {
    const InstrInfo *in = rows[rng_.below(rows.size())];
    if (eligible(*in)) return emitGeneric(*in);
  }
}

void RandomGen::emitPush() {
  const auto &rows = generic_[static_cast<int>(StackRule::Push)];
  emitGeneric(*rows[rng_.below(rows.size())]);
}

void RandomGen::emitGeneric(const InstrInfo &in) {
  std::string s = hnc8::mnemonicOf(in.op);
  if (in.op == Op::Coil && rng_.chance(5)) s = hnc8::mnemonicRow(in.op)->alias; // DIALECT.md 2
  if (!specialOperands(in, s))
    for (int i = 0; i < in.operandCount; ++i) s += " " + operand(in, i);
  emit(std::move(s));
  // The stacks move as ir/StackEffect.h says (the verifier reads the same function).
  const StackEffect e = stackEffect(in, depth_);
  depth_ = e.after(depth_);
  ms_ += e.msDelta;
}

void RandomGen::closeMs() {
  while (ms_ > 0) {
    assert(depth_ >= 1);
    emit("MPP");
    --ms_;
  }
}

void RandomGen::block(int32_t budget, int nest) {
  const int32_t end = size() + budget;
  while (size() < end) {
    int32_t left = end - size();
    bool deeper = nest < o_.maxNest && left >= 6;
    bool canCall = curSub_ + 1 < static_cast<int32_t>(subNumbers_.size());
    // Main parts call more often than subroutines, so most subroutines are reached.
    const int w[] = {90,
                     deeper ? 3 : 0,
                     deeper ? 2 : 0,
                     deeper ? 3 : 0,
                     canCall ? (curSub_ < 0 ? 8 : 3) : 0,
                     curSub_ >= 0 ? 2 : 0};
    int choice = rng_.weighted(w);
    int32_t inner = choice >= 1 && choice <= 3
                        ? static_cast<int32_t>(rng_.range(2, std::min<int64_t>(left - 4, 16)))
                        : 0;
    switch (choice) {
    case 0:
      emitOneGeneric();
      break;
    case 1:
      forwardJump(inner, nest);
      break;
    case 2:
      backwardJump(inner, nest);
      break;
    case 3:
      loop(inner, nest);
      break;
    case 4:
      call();
      break;
    default:
      retn();
      break;
    }
  }
  closeMs();
}

void RandomGen::forwardJump(int32_t budget, int nest) {
  closeMs();
  // With an empty ST the jump is unconditional (a warning); mostly give it a condition.
  if (depth_ == 0 ? rng_.chance(90) : rng_.chance(30)) emitPush();
  int32_t l = nextLabel_++;
  emit("JMP L" + std::to_string(l));
  block(budget, nest + 1);
  emit("LBL L" + std::to_string(l));
  resetStacks();
}

void RandomGen::backwardJump(int32_t budget, int nest) {
  closeMs();
  int32_t l = nextLabel_++;
  std::string g = "D" + std::to_string(kGuardFirst + nextGuard_++ % kGuardCount);
  int mode = rng_.weighted(std::array<int, 3>{82, 12, 6});
  if (o_.avoidWatchdog) mode = 0;
  if (mode == 0) {
    emit("LDT");
    emit("MOV 0 " + g);
  }
  emit("LBL L" + std::to_string(l));
  resetStacks();
  block(budget, nest + 1);
  // Guards: a counted loop (a huge bound runs into the watchdog), an input bit (runs into the
  // watchdog while the stimulus holds it), or unconditional (always the watchdog once reached).
  if (mode == 0) {
    int32_t bound = rng_.chance(90) ? static_cast<int32_t>(rng_.range(1, 6)) : 100000;
    if (o_.avoidWatchdog && bound > 6) bound = 6;
    emit("LDT");
    emit("INC " + g);
    emit("LT " + g + " " + std::to_string(bound));
  } else if (mode == 1) {
    emit("LD X" + std::to_string(pickIndex(rng_, Area::Input)) + "." +
         std::to_string(rng_.below(8)));
  } else {
    emit("LDT");
  }
  emit("JMP L" + std::to_string(l));
  // The label resets the stacks; after the JMP falls through ST holds the guard's entry.
  depth_ = 1;
  ms_ = 0;
}

/// Constant LOOP counts: skipped (-1, 0), once, and a few iterations.
constexpr int32_t kLoopCounts[] = {-1, 0, 1, 2, 3, 5};

void RandomGen::loop(int32_t budget, int nest) {
  closeMs();
  std::string n;
  if (rng_.chance(60)) {
    n = std::to_string(kLoopCounts[rng_.below(6)]);
  } else if (rng_.chance(60)) {
    // A register count: whatever the program left there (often large: the watchdog).
    const OperandSpec &sp = instrInfo(Op::LoopBegin).operands[0];
    n = regAddress(sp.areas, false);
  } else {
    n = operand(instrInfo(Op::LoopBegin), 0);
  }
  // Drawn after the default choice, so the default programs stay the same. A register count
  // then comes from an input byte (only the host writes X: at most 255 iterations).
  if (o_.avoidWatchdog)
    n = rng_.chance(40) ? "X" + std::to_string(pickIndex(rng_, Area::Input))
                        : std::to_string(kLoopCounts[rng_.below(std::size(kLoopCounts))]);
  emit("LOOP " + n);
  resetStacks();
  block(budget, nest + 1);
  emit("NEXT");
  resetStacks();
}

void RandomGen::call() {
  if (depth_ == 0 ? rng_.chance(60) : rng_.chance(20)) emitPush();
  int32_t first = curSub_ + 1;
  int32_t k = static_cast<int32_t>(rng_.range(first, static_cast<int64_t>(subNumbers_.size()) - 1));
  emit("CALL S" + std::to_string(subNumbers_[k]));
}

void RandomGen::retn() {
  if (depth_ == 0 ? rng_.chance(85) : rng_.chance(20)) emitPush();
  emit("RETN");
}

GenProgram RandomGen::run() {
  prof_ = kProfiles[rng_.below(std::size(kProfiles))];
  prof_.depthCap = std::min(prof_.depthCap, o_.maxDepth);
  int32_t subs = static_cast<int32_t>(rng_.range(0, o_.maxSubs));
  while (static_cast<int32_t>(subNumbers_.size()) < subs) {
    int32_t n = static_cast<int32_t>(rng_.chance(50) ? rng_.below(8) : rng_.below(512));
    bool dup = false;
    for (int32_t s : subNumbers_) dup = dup || s == n;
    if (!dup) subNumbers_.push_back(n);
  }
  // Markers: usually all three; otherwise any ordered subset (DIALECT.md 2 decides the parts).
  const char *markers[] = {"IEND", "1END", "2END"};
  bool present[3] = {true, true, true};
  if (rng_.chance(25))
    for (bool &p : present) p = rng_.chance(50);
  const int32_t total = std::max<int32_t>(o_.statements, 8);
  const int32_t subBudget = subs ? total / 5 / subs + 2 : 0;
  const int32_t mainBudget = std::max<int32_t>(total - subBudget * subs, 4);
  const int32_t share[4] = {mainBudget / 6, mainBudget / 3, mainBudget / 2, mainBudget / 3};
  for (int m = 0; m < 3; ++m) {
    if (!present[m]) continue;
    block(std::max<int32_t>(share[m], 1), 0);
    emit(markers[m]);
    resetStacks();
  }
  if (!present[2]) block(std::max<int32_t>(share[3], 1), 0);
  for (int32_t i = 0; i < subs; ++i) {
    curSub_ = i;
    emit("SP S" + std::to_string(subNumbers_[i]));
    resetStacks();
    block(subBudget, 0);
    emit("SPE");
    resetStacks();
  }
  GenProgram p;
  p.lines = std::move(lines_);
  static constexpr int32_t kNvalues[] = {0, 1, 2, 3, 5, 10, 200};
  p.plc2Nvalue = kNvalues[rng_.below(std::size(kNvalues))];
  return p;
}

GenProgram RandomGen::snippet(Op op) {
  prof_ = kProfiles[0];
  const InstrInfo &in = instrInfo(op);
  auto lines = [](std::initializer_list<const char *> l) {
    GenProgram p;
    for (const char *x : l) p.lines.emplace_back(x);
    return p;
  };
  switch (op) {
  case Op::EndInit:
  case Op::EndCyclic:
  case Op::EndSliced:
    return lines({"LDT", "OUT R0.0", "IEND", "LDT", "OUT R0.1", "1END", "LDT", "OUT R0.2", "2END"});
  case Op::Jump:
  case Op::Label:
    return lines({"LDT", "JMP L1", "LDT", "OUT R0.0", "LBL L1", "LDT", "OUT R0.1"});
  case Op::Call:
  case Op::SubBegin:
  case Op::SubEnd:
  case Op::Return:
    return lines({"LDT", "CALL S1", "1END", "2END", "SP S1", "LDT", "OUT R0.0", "LDT", "RETN",
                  "LDT", "OUT R0.1", "SPE"});
  case Op::LoopBegin:
  case Op::LoopEnd:
    return lines({"LOOP 3", "LDT", "INC D0", "NEXT"});
  default:
    break;
  }
  switch (in.stack) {
  case StackRule::Push:
    break;
  case StackRule::BlockPop:
    emitGeneric(instrInfo(Op::LoadTrue));
    emitGeneric(instrInfo(Op::LoadTrue));
    break;
  case StackRule::MsRead:
  case StackRule::MsPop:
    emitGeneric(instrInfo(Op::LoadTrue));
    emitGeneric(instrInfo(Op::BranchPush));
    break;
  default:
    for (int k = 0; k < std::max<int>(in.inputs, 1); ++k) emitGeneric(instrInfo(Op::LoadTrue));
    break;
  }
  emitGeneric(in);
  if (op == Op::BranchRead) emitGeneric(instrInfo(Op::BranchPop));
  closeMs();
  GenProgram p;
  p.lines = std::move(lines_);
  p.plc2Nvalue = 0;
  return p;
}

} // namespace detail

GenProgram generateRandom(const RandomOptions &opts) { return detail::RandomGen(opts).run(); }

GenProgram generateSnippet(Op op, uint64_t seed) {
  RandomOptions o;
  o.seed = seed;
  return detail::RandomGen(o).snippet(op);
}

} // namespace lj::gen

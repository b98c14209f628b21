// State slots of instruction instances: edge bits (LDP..ORF, CTR) numbered in statement order,
// timer/counter slots (lj_tc_slot) with the one-kind-per-number rule, and PLS/PLF/ALT block
// numbers (DIALECT.md 3, 6; dialect-notes "Function blocks").
#include "verify/VerifierInternal.h"

#include "ir/Profile.h"

#include "ladderjit/abi.h"

#include <algorithm>
#include <array>
#include <map>
#include <span>
#include <string>
#include <tuple>
#include <vector>

namespace lj::verifier {

namespace {

/// First user of each slot of one family (timers, counters, or one block mnemonic).
class SlotUsers {
public:
  explicit SlotUsers(size_t slots) : first_(slots, -1) {}
  int32_t &operator[](size_t slot) { return first_[slot]; }

private:
  std::vector<int32_t> first_;
};

std::string lineText(const Stmt &s) { return "line " + std::to_string(s.loc.line); }

/// Timers (TMRB/STMR) and counters (CTRC/CTUD): T/C numbers, one instruction kind per number.
void timerCounter(Context &cx, int32_t i, SlotUsers &users, const char *family, Area area) {
  const Stmt &s = cx.stmt(i);
  int32_t n = s.ops[0].value;
  int slot = cx.tp.tcSlot(area, n);
  // A profile with more numbers than it has slots (TargetProfile::timerSlots).
  if (slot >= (area == Area::Timer ? cx.tp.timerSlots() : LJ_TC_SLOTS)) slot = -1;
  const std::string letter = cx.tp.area(area).name;
  std::string name = letter + std::to_string(n);
  if (slot < 0) {
    // The number spaces of the profile, e.g. "T0..T127, T300..T427".
    const TargetProfile &tp = cx.tp;
    std::string spaces;
    for (const NumberRange &r : area == Area::Timer ? tp.timerNumbers : tp.counterNumbers)
      spaces += (spaces.empty() ? "" : ", ") + letter + std::to_string(r.lo) + ".." + letter +
                std::to_string(r.hi);
    cx.error(s.ops[0].loc, "LJ1019",
             std::string(family) + " number " + std::to_string(n) + " is not valid (" + spaces +
                 ")");
    return;
  }
  cx.info(i).slot = slot;
  int32_t &first = users[static_cast<size_t>(slot)];
  if (first < 0) {
    first = i;
    return;
  }
  const Stmt &f = cx.stmt(first);
  if (f.op != s.op) {
    cx.error(s.ops[0].loc, "LJ1020",
             std::string(family) + " " + name + " is used by both " + cx.spell(f.op) + " (" +
                 lineText(f) + ") and " + cx.spell(s.op));
    cx.note(f.ops[0].loc, name + " is first used here");
  } else {
    cx.warning(s.ops[0].loc, "LJ1021",
               std::string(family) + " " + name + " is also used on " + lineText(f) +
                   "; both instructions share its state");
  }
}

/// The operations that own an edge bit, as the error about running out of them names them.
constexpr Op kEdgeOps[] = {Op::LoadRise, Op::LoadFall, Op::AndRise,        Op::AndFall,
                           Op::OrRise,   Op::OrFall,   Op::RegisterCounter};

std::string spellAll(const Context &cx, std::span<const Op> ops) {
  std::string out;
  for (Op op : ops) out += (out.empty() ? "" : "/") + std::string(cx.spell(op));
  return out;
}

} // namespace

void assignSlots(Context &cx) {
  // PerObject (ir/Profile.h EdgePolicy): the edge contacts of one object share its slot.
  const bool perObject = cx.tp.edgePolicy == EdgePolicy::PerObject;
  std::map<std::tuple<int, int32_t, int>, int32_t> objectSlot;
  std::vector<Operand> &objects = cx.prog.edgeObjects;
  objects.clear();
  const auto blockSlots = static_cast<size_t>(
      std::max({LJ_BLOCK_SLOTS, LJ_TC_SLOTS, cx.tp.timerSlots(), cx.tp.pulseSlots()}));
  SlotUsers timers(blockSlots), counters(blockSlots), pls(blockSlots), plf(blockSlots),
      alt(blockSlots);
  int32_t edges = 0, words = 0;
  auto n = static_cast<int32_t>(cx.prog.stmts.size());
  for (int32_t i = 0; i < n; ++i) {
    const Stmt &s = cx.stmt(i);
    const InstrInfo &ii = instrInfo(s.op);
    switch (ii.state) {
    case StateKind::None:
      break;
    case StateKind::Edge:
      if (perObject && isContact(s.op)) {
        const Operand &o = s.ops[0];
        auto [it, fresh] = objectSlot.try_emplace(
            std::tuple<int, int32_t, int>{static_cast<int>(o.area), o.index, o.bit}, edges);
        cx.info(i).slot = it->second;
        if (!fresh) break;
        objects.push_back(o);
      } else if (perObject) {
        objects.push_back(Operand{}); // a slot of this instruction alone
      }
      // One edge bit per instruction instance (per object: per new object), in statement order.
      if (!perObject || !isContact(s.op)) cx.info(i).slot = edges;
      ++edges;
      if (edges == LJ_EDGE_SLOTS + 1)
        cx.error(s.loc, "LJ1022",
                 "too many edge instructions (more than " + std::to_string(LJ_EDGE_SLOTS) + " " +
                     spellAll(cx, kEdgeOps) + ")");
      break;
    case StateKind::Timer:
      timerCounter(cx, i, timers, "timer", Area::Timer);
      break;
    case StateKind::Counter:
      timerCounter(cx, i, counters, "counter", Area::Counter);
      break;
    case StateKind::Words:
      // Two per-instance words (lj_state.inst_word), in statement order.
      cx.info(i).slot = words;
      words += 2;
      if (words > LJ_INST_WORDS && words <= LJ_INST_WORDS + 2)
        cx.error(s.loc, "LJ1023",
                 "too many stateful CNC blocks (more than " + std::to_string(LJ_INST_WORDS / 2) +
                     " " + cx.spell(Op::ToolLife) + ")");
      break;
    case StateKind::Pls:
    case StateKind::Plf:
    case StateKind::Alt: {
      SlotUsers &users = ii.state == StateKind::Pls ? pls : ii.state == StateKind::Plf ? plf : alt;
      // Checked by the parser: 0..511 (HNC-8), 1..1000 (FANUC, TargetProfile::pulseSlots).
      auto num = static_cast<size_t>(s.ops[0].value);
      const int limit = ii.state == StateKind::Alt ? LJ_BLOCK_SLOTS : cx.tp.pulseSlots();
      if (s.ops[0].value < 0 || s.ops[0].value >= limit) {
        cx.error(s.ops[0].loc, "LJ1024",
                 std::string(cx.spell(ii.op)) + " block number " + std::to_string(s.ops[0].value) +
                     " is out of range (0.." + std::to_string(limit - 1) + ")");
        break;
      }
      cx.info(i).slot = s.ops[0].value;
      if (users[num] < 0) {
        users[num] = i;
      } else {
        cx.warning(s.ops[0].loc, "LJ1025",
                   std::string(cx.spell(ii.op)) + " block " + std::to_string(num) +
                       " is also used on " + lineText(cx.stmt(users[num])) +
                       "; both instructions share its state");
      }
      break;
    }
    }
  }
  cx.prog.edgeSlots = edges;
  cx.prog.wordSlots = words;
}

} // namespace lj::verifier

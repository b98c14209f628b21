// State slots of instruction instances: edge bits (LDP..ORF, CTR) numbered in statement order,
// timer/counter slots (lj_tc_slot) with the one-kind-per-number rule, and PLS/PLF/ALT block
// numbers (DIALECT.md 3, 6; dialect-notes "Function blocks").
#include "verify/VerifierInternal.h"

#include "ladderjit/abi.h"

#include <array>

namespace lj::verifier {

namespace {

/// First user of each slot of one family (timers, counters, or one block mnemonic).
class SlotUsers {
public:
  SlotUsers() { first_.fill(-1); }
  int32_t &operator[](size_t slot) { return first_[slot]; }

private:
  std::array<int32_t, LJ_BLOCK_SLOTS> first_{};
};

std::string lineText(const Stmt &s) { return "line " + std::to_string(s.loc.line); }

/// Timers (TMRB/STMR) and counters (CTRC/CTUD): T/C numbers, one instruction kind per number.
void timerCounter(Context &cx, int32_t i, SlotUsers &users, const char *family, char letter) {
  const Stmt &s = cx.stmt(i);
  int32_t n = s.ops[0].value;
  int slot = lj_tc_slot(n);
  std::string name = std::string(1, letter) + std::to_string(n);
  if (slot < 0) {
    cx.error(s.ops[0].loc, std::string(family) + " number " + std::to_string(n) +
                               " is not valid (" + letter + "0.." + letter + "127, " + letter +
                               "300.." + letter + "427)");
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
    cx.error(s.ops[0].loc, std::string(family) + " " + name + " is used by both " +
                               instrInfo(f.op).mnemonic + " (" + lineText(f) + ") and " +
                               instrInfo(s.op).mnemonic);
    cx.note(f.ops[0].loc, name + " is first used here");
  } else {
    cx.warning(s.ops[0].loc, std::string(family) + " " + name + " is also used on " + lineText(f) +
                                 "; both instructions share its state");
  }
}

} // namespace

void assignSlots(Context &cx) {
  SlotUsers timers, counters, pls, plf, alt;
  int32_t edges = 0, words = 0;
  auto n = static_cast<int32_t>(cx.prog.stmts.size());
  for (int32_t i = 0; i < n; ++i) {
    const Stmt &s = cx.stmt(i);
    const InstrInfo &ii = instrInfo(s.op);
    switch (ii.state) {
    case StateKind::None:
      break;
    case StateKind::Edge:
      // One edge bit per instruction instance, in statement order.
      cx.info(i).slot = edges++;
      if (edges == LJ_EDGE_SLOTS + 1)
        cx.error(s.loc, "too many edge instructions (more than " + std::to_string(LJ_EDGE_SLOTS) +
                            " LDP/LDF/ANDP/ANDF/ORP/ORF/CTR)");
      break;
    case StateKind::Timer:
      timerCounter(cx, i, timers, "timer", 'T');
      break;
    case StateKind::Counter:
      timerCounter(cx, i, counters, "counter", 'C');
      break;
    case StateKind::Words:
      // Two per-instance words (lj_state.inst_word), in statement order.
      cx.info(i).slot = words;
      words += 2;
      if (words > LJ_INST_WORDS && words <= LJ_INST_WORDS + 2)
        cx.error(s.loc, "too many stateful CNC blocks (more than " +
                            std::to_string(LJ_INST_WORDS / 2) + " TOOLLIFE)");
      break;
    case StateKind::Pls:
    case StateKind::Plf:
    case StateKind::Alt: {
      SlotUsers &users = ii.state == StateKind::Pls ? pls : ii.state == StateKind::Plf ? plf : alt;
      auto num = static_cast<size_t>(s.ops[0].value); // 0..511, checked by the parser
      cx.info(i).slot = s.ops[0].value;
      if (users[num] < 0) {
        users[num] = i;
      } else {
        cx.warning(s.ops[0].loc, std::string(ii.mnemonic) + " block " + std::to_string(num) +
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

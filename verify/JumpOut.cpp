// Jumps out of a subroutine (Op::JumpOut, FANUC JMPC; docs/fanuc-pmc.md "JMPC"): each JumpOut
// names a label of the sliced part (FANUC level 2), it stands only in a subroutine, and every
// CALL of the sliced part whose callee can take one (itself or through the subroutines it calls)
// gets that label as a second place to go on (VerifiedProgram::callExits). A CALL of another part
// whose callee can leave that way is an error: its label is not in the caller's part.
#include "verify/VerifierInternal.h"

#include <algorithm>
#include <unordered_map>

namespace lj::verifier {

namespace {

std::string lineOf(const Stmt &s) { return "line " + std::to_string(s.loc.line); }

} // namespace

void checkJumpOuts(Context &cx) {
  const size_t nsubs = cx.prog.subs.size();
  const std::string lbl = cx.tp.area(Area::Label).name;
  const std::string end2 = cx.spell(Op::EndSliced);

  // Labels of the sliced part by number (duplicates are Scopes.cpp's error).
  std::unordered_map<int32_t, int32_t> labels;
  for (const Unit &u : cx.units) {
    if (u.kind != Unit::Kind::Plc2) continue;
    for (int32_t i = u.body.begin; i < u.body.end; ++i)
      if (cx.stmt(i).op == Op::Label) labels.try_emplace(cx.stmt(i).ops[0].index, i);
  }

  // Each subroutine's own JumpOut targets (label statement indices).
  std::vector<std::vector<int32_t>> exits(nsubs);
  std::vector<int32_t> unitOfSub(nsubs, -1);
  bool any = false;
  for (size_t u = 0; u < cx.units.size(); ++u) {
    const Unit &unit = cx.units[u];
    if (unit.kind == Unit::Kind::Sub)
      unitOfSub[static_cast<size_t>(unit.sub)] = static_cast<int32_t>(u);
    for (int32_t i = unit.body.begin; i < unit.body.end; ++i) {
      const Stmt &s = cx.stmt(i);
      if (s.op != Op::JumpOut) continue;
      const std::string what =
          std::string(cx.spell(Op::JumpOut)) + " " + lbl + std::to_string(s.ops[0].index);
      if (unit.kind != Unit::Kind::Sub) {
        cx.error(s.loc, "LJ1004",
                 what +
                     " outside a subroutine: it leaves a subroutine for a label "
                     "before " +
                     end2);
        continue;
      }
      auto it = labels.find(s.ops[0].index);
      if (it == labels.end()) {
        cx.error(s.ops[0].loc, "LJ1005",
                 "missing label " + lbl + std::to_string(s.ops[0].index) + " before " + end2 +
                     ": " + what + " goes on at a label of the part that ends with " + end2);
        continue;
      }
      cx.info(i).target = it->second;
      exits[static_cast<size_t>(unit.sub)].push_back(it->second);
      any = true;
    }
  }
  if (!any) return;

  // Close over the call graph: a subroutine leaves for every label its callees leave for.
  // Rounds until nothing grows; the call depth bounds them, and nsubs + 1 rounds bound a cycle
  // (recursion, reported by checkCallGraph).
  bool grew = true;
  for (size_t round = 0; grew && round <= nsubs; ++round) {
    grew = false;
    for (size_t sub = 0; sub < nsubs; ++sub) {
      if (unitOfSub[sub] < 0) continue;
      std::vector<int32_t> &mine = exits[sub];
      const size_t before = mine.size();
      for (const CallSite &e : cx.calls[static_cast<size_t>(unitOfSub[sub])]) {
        const std::vector<int32_t> &theirs = exits[static_cast<size_t>(e.callee)];
        mine.insert(mine.end(), theirs.begin(), theirs.end());
      }
      std::sort(mine.begin(), mine.end());
      mine.erase(std::unique(mine.begin(), mine.end()), mine.end());
      grew = grew || mine.size() != before;
    }
  }

  // Every CALL of a main part whose callee can leave: in the sliced part a second target (and
  // a span no slice boundary cuts), elsewhere an error.
  for (size_t u = 0; u < cx.units.size(); ++u) {
    const Unit &unit = cx.units[u];
    if (unit.kind == Unit::Kind::Sub) continue;
    for (const CallSite &e : cx.calls[u]) {
      const std::vector<int32_t> &to = exits[static_cast<size_t>(e.callee)];
      if (to.empty()) continue;
      if (unit.kind != Unit::Kind::Plc2) {
        cx.error(cx.stmt(e.stmt).loc, "LJ1006",
                 std::string(cx.spell(Op::Call)) + " of a subroutine that can leave through " +
                     cx.spell(Op::JumpOut) + " for " + lbl +
                     std::to_string(cx.stmt(to.front()).ops[0].index) + " (" +
                     lineOf(cx.stmt(to.front())) + "), a label before " + end2 +
                     ": this call is not in that part");
        continue;
      }
      for (int32_t l : to) {
        cx.prog.callExits.emplace_back(e.stmt, l);
        cx.jumpSpans.emplace_back(std::min(l, e.stmt), std::max(l, e.stmt));
      }
    }
  }
  std::sort(cx.prog.callExits.begin(), cx.prog.callExits.end());
}

} // namespace lj::verifier

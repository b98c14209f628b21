// The verifier's entry point and its first pass: program parts, markers and subroutines
// (DIALECT.md 2, dialect-notes "Program parts"). Later passes live in Scopes.cpp,
// StateSlots.cpp, CallGraph.cpp and SlicePlanner.cpp.
#include "verify/VerifierInternal.h"

#include "ir/Profile.h"

#include <algorithm>

namespace lj {

namespace verifier {

namespace {

bool isMarker(Op op) { return op == Op::EndInit || op == Op::EndCyclic || op == Op::EndSliced; }
int markerRank(Op op) { return op == Op::EndInit ? 0 : op == Op::EndCyclic ? 1 : 2; }
std::string lineOf(const Stmt &s) { return "line " + std::to_string(s.loc.line); }

/// A subroutine as the dialect writes it ("S7").
std::string subText(const Context &cx, int32_t n) {
  return std::string(cx.tp.area(Area::Subroutine).name) + std::to_string(n);
}

/// The part markers in the order the profile runs the parts ("IEND, 1END, 2END").
std::string markerOrder(const Context &cx) {
  std::string out;
  for (const PartSpec &p : cx.tp.parts)
    out += (out.empty() ? "" : ", ") + std::string(cx.spell(p.endMarker));
  return out;
}

Unit::Kind partKind(int rank) {
  return rank == 0 ? Unit::Kind::Init : rank == 1 ? Unit::Kind::Plc1 : Unit::Kind::Plc2;
}

void addPart(Context &cx, int rank, StmtRange r, bool (&have)[3]) {
  if (rank > 2) {
    // After 2END only subroutines may follow (dialect-notes "Program parts").
    for (int32_t i = r.begin; i < r.end; ++i) {
      if (isMarker(cx.stmt(i).op) || cx.stmt(i).op == Op::SubEnd) continue; // reported already
      cx.error(cx.stmt(i).loc, "LJ1026",
               "statement after " + std::string(cx.spell(Op::EndSliced)) + " outside a subroutine");
      break;
    }
    return;
  }
  StmtRange &dst = rank == 0 ? cx.prog.init : rank == 1 ? cx.prog.plc1 : cx.prog.plc2;
  dst = r;
  have[rank] = true;
  cx.units.push_back({partKind(rank), r, -1});
}

/// Main region [0, mainEnd): markers split it into parts.
void planParts(Context &cx, int32_t mainEnd) {
  int32_t first[3] = {-1, -1, -1};
  int lastRank = -1;
  std::vector<int32_t> markers; // accepted markers, in order
  for (int32_t i = 0; i < mainEnd; ++i) {
    const Stmt &s = cx.stmt(i);
    if (s.op == Op::SubEnd) {
      cx.error(s.loc, "LJ1027",
               std::string(cx.spell(Op::SubEnd)) + " without " + cx.spell(Op::SubBegin));
      continue;
    }
    if (!isMarker(s.op)) continue;
    int rank = markerRank(s.op);
    if (first[rank] >= 0) {
      cx.error(s.loc, "LJ1028",
               std::string("duplicate ") + cx.spell(s.op) + " (first on " +
                   lineOf(cx.stmt(first[rank])) + ")");
    } else if (rank < lastRank) {
      cx.error(s.loc, "LJ1029",
               std::string(cx.spell(s.op)) + " after " + cx.spell(cx.stmt(markers.back()).op) +
                   ": markers must come in the order " + markerOrder(cx));
    } else {
      first[rank] = i;
      lastRank = rank;
      markers.push_back(i);
    }
  }
  // Statements before the first marker belong to the part it ends; statements after a marker
  // belong to the next part. No marker at all: one PLC1 part.
  bool have[3] = {false, false, false};
  int32_t start = 0;
  int rank = markers.empty() ? 1 : markerRank(cx.stmt(markers[0]).op);
  for (int32_t m : markers) {
    addPart(cx, rank, {start, m}, have);
    start = m + 1;
    rank = markerRank(cx.stmt(m).op) + 1;
  }
  if (start < mainEnd || markers.empty() || rank <= 2) addPart(cx, rank, {start, mainEnd}, have);
  // Parts that do not exist are empty ranges where they would have been.
  if (!have[0]) cx.prog.init = {0, 0};
  if (!have[1]) cx.prog.plc1 = {cx.prog.init.end, cx.prog.init.end};
  if (!have[2]) cx.prog.plc2 = {cx.prog.plc1.end, cx.prog.plc1.end};
}

void openSub(Context &cx, int32_t sp) {
  const Stmt &s = cx.stmt(sp);
  int32_t number = s.ops[0].index;
  auto idx = static_cast<int32_t>(cx.prog.subs.size());
  cx.prog.subs.push_back({number, sp, {sp + 1, sp + 1}});
  int16_t &slot = cx.prog.subByNumber[static_cast<size_t>(number)];
  if (slot >= 0) {
    const Subroutine &prev = cx.prog.subs[static_cast<size_t>(slot)];
    cx.error(s.ops[0].loc, "LJ1030",
             "duplicate subroutine " + subText(cx, number) + " (first on " +
                 lineOf(cx.stmt(prev.spIndex)) + ")");
  } else {
    slot = static_cast<int16_t>(idx);
  }
}

void closeSub(Context &cx, int32_t end) {
  Subroutine &sub = cx.prog.subs.back();
  sub.body.end = end;
  cx.units.push_back({Unit::Kind::Sub, sub.body, static_cast<int32_t>(cx.prog.subs.size() - 1)});
}

/// Subroutine region [mainEnd, N): only `SP Sn ... SPE` blocks.
void planSubs(Context &cx, int32_t mainEnd) {
  auto n = static_cast<int32_t>(cx.prog.stmts.size());
  bool inSub = false, outsideReported = false;
  for (int32_t i = mainEnd; i < n; ++i) {
    const Stmt &s = cx.stmt(i);
    if (s.op == Op::SubBegin) {
      if (inSub) {
        const Subroutine &cur = cx.prog.subs.back();
        cx.error(s.loc, "LJ1031",
                 "nested " + std::string(cx.spell(Op::SubBegin)) + ": " + subText(cx, cur.number) +
                     " (" + lineOf(cx.stmt(cur.spIndex)) + ") has no " + cx.spell(Op::SubEnd) +
                     " before it");
        closeSub(cx, i);
      }
      openSub(cx, i);
      inSub = true;
      outsideReported = false;
    } else if (s.op == Op::SubEnd) {
      if (inSub) {
        closeSub(cx, i);
        inSub = false;
      } else {
        cx.error(s.loc, "LJ1032",
                 std::string(cx.spell(Op::SubEnd)) + " without " + cx.spell(Op::SubBegin));
      }
    } else if (isMarker(s.op)) {
      cx.error(s.loc, "LJ1033",
               std::string(cx.spell(s.op)) + " after a subroutine: " + cx.spell(Op::SubBegin) +
                   " before the end of the main parts (first " + cx.spell(Op::SubBegin) + " on " +
                   lineOf(cx.stmt(mainEnd)) + ")");
    } else if (!inSub && !outsideReported) {
      cx.error(s.loc, "LJ1034", "statement after the subroutines");
      outsideReported = true;
    }
  }
  if (inSub) {
    const Subroutine &cur = cx.prog.subs.back();
    cx.error(cx.stmt(cur.spIndex).loc, "LJ1035",
             std::string(cx.spell(Op::SubBegin)) + " " + subText(cx, cur.number) + " has no " +
                 cx.spell(Op::SubEnd));
    closeSub(cx, n);
  }
}

} // namespace

void planStructure(Context &cx) {
  auto n = static_cast<int32_t>(cx.prog.stmts.size());
  int32_t mainEnd = n;
  for (int32_t i = 0; i < n; ++i) {
    if (cx.stmt(i).op == Op::SubBegin) {
      mainEnd = i;
      break;
    }
  }
  planParts(cx, mainEnd);
  planSubs(cx, mainEnd);
}

} // namespace verifier

std::optional<VerifiedProgram> verify(const ParsedProgram &parsed, const VerifyOptions &given,
                                      Diagnostics &diags) {
  if (!parsed.profile) {
    diags.error({}, "LJ1036", "the program names no target profile (its front end must set one)");
    return std::nullopt;
  }
  const VerifyOptions opts = given.resolved(*parsed.profile);
  VerifiedProgram prog;
  prog.file = parsed.file;
  prog.dialect = parsed.dialect;
  prog.profile = parsed.profile;
  prog.stmts = parsed.stmts;
  prog.info.assign(prog.stmts.size(), StmtInfo{});
  prog.subByNumber.assign(
      static_cast<size_t>(std::max<int32_t>(512, prog.profile->area(Area::Subroutine).count)), -1);
  prog.plc2Nvalue = *opts.plc2Nvalue;
  int errorsBefore = diags.errorCount();

  verifier::Context cx(opts, diags, prog);
  cx.dropped = parsed.dropped;
  if (prog.stmts.size() > static_cast<size_t>(std::max(*opts.maxStatements, 0))) {
    const Stmt &over = prog.stmts[static_cast<size_t>(std::max(*opts.maxStatements, 0))];
    cx.error(over.loc, "LJ1037",
             "program has " + std::to_string(prog.stmts.size()) +
                 " statements, more than the limit of " + std::to_string(*opts.maxStatements));
  }
  verifier::planStructure(cx);
  cx.calls.resize(cx.units.size());
  for (size_t u = 0; u < cx.units.size(); ++u) verifier::checkUnit(cx, u);
  verifier::assignSlots(cx);
  verifier::checkData(cx);
  verifier::checkNc(cx);
  verifier::checkCnc(cx);
  verifier::checkCallGraph(cx);
  verifier::checkJumpOuts(cx);
  if (diags.errorCount() > errorsBefore) return std::nullopt;
  verifier::planRungs(cx);
  verifier::planSlices(cx);
  prog.comments = parsed.comments;
  prog.symbols = parsed.symbols;
  prog.written = parsed.written;
  prog.grids = parsed.grids;
  return prog;
}

} // namespace lj

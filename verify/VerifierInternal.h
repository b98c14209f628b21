// Shared state of the verifier's passes (structure, scopes and stacks, call graph, slicing).
// Internal to verify/: not part of the front end's public interface.
#pragma once

#include "ir/Diagnostics.h"
#include "verify/Verify.h"

#include <string>
#include <vector>

namespace lj::verifier {

/// A unit of code with its own stacks, labels and double-coil set: a main part or a subroutine.
struct Unit {
  enum class Kind : uint8_t { Init, Plc1, Plc2, Sub } kind = Kind::Plc1;
  StmtRange body;
  int32_t sub = -1; ///< index into VerifiedProgram::subs for Kind::Sub
};

/// One CALL edge of the call graph.
struct CallSite {
  int32_t stmt = 0;
  int32_t callee = 0; ///< index into subs
};

/// Everything the passes share while verifying one program.
struct Context {
  Context(const VerifyOptions &o, Diagnostics &d, VerifiedProgram &p)
      : opts(o), diags(d), prog(p), tp(*p.profile) {}
  const VerifyOptions &opts; ///< every limit set (verify() fills the unset ones from `tp`)
  Diagnostics &diags;
  VerifiedProgram &prog;
  const TargetProfile &tp; ///< the program's profile (area facts, number spaces, parts)
  std::vector<Unit> units;
  /// CALL sites per unit (parallel to units).
  std::vector<std::vector<CallSite>> calls;
  /// JMP/LBL pairs as (min, max) statement indices: no slice boundary in (min, max].
  std::vector<std::pair<int32_t, int32_t>> jumpSpans;
  /// Lines the parser dropped (their stack effects are applied silently).
  std::vector<DroppedStmt> dropped;

  const Stmt &stmt(int32_t i) const { return prog.stmts[static_cast<size_t>(i)]; }
  StmtInfo &info(int32_t i) { return prog.info[static_cast<size_t>(i)]; }
  void error(SourceLoc l, const char *code, std::string m) { diags.error(l, code, std::move(m)); }
  void warning(SourceLoc l, const char *code, std::string m) {
    diags.warning(l, code, std::move(m));
  }
  void note(SourceLoc l, std::string m) { diags.note(l, std::move(m)); }
  /// `op` / `o` as the program's dialect writes them (messages name what the user wrote).
  const char *spell(Op op) const { return spelling(prog.dialect, op); }
  std::string operandText(const Operand &o) const {
    return prog.dialect ? prog.dialect->formatOperand(o) : std::string("?");
  }
};

/// Parts, markers and subroutines (DIALECT.md 2): fills units, prog.init/plc1/plc2/subs.
void planStructure(Context &cx);

/// Per unit: loops and scopes, labels and jumps, ST/MS depths, MPS pairing, double coils,
/// unreachable code, CALL sites (Scopes.cpp).
void checkUnit(Context &cx, size_t unitIndex);

/// Edge slots, timer/counter slots, PLS/PLF/ALT numbers and their reuse checks.
void assignSlots(Context &cx);

/// Recursion, call depth and never-called subroutines.
void checkCallGraph(Context &cx);

/// JumpOut targets (labels of the sliced part), and the labels each CALL there can go on at
/// (VerifiedProgram::callExits, jumpSpans); after checkCallGraph (JumpOut.cpp).
void checkJumpOuts(Context &cx);

/// PLC2 slices per dialect-notes "PLC2 slicing" (SlicePlanner.cpp).
void planSlices(Context &cx);

/// Rung boundaries (Rungs.cpp): fills prog.rungs.
void planRungs(Context &cx);

/// Family checks of data operations: constant ranges inside their area, FMOV/ZRST bounds
/// (VerifyData.cpp).
void checkData(Context &cx);
/// Family Nc block-fit checks (VerifyNc.cpp).
void checkNc(Context &cx);
/// Family Cnc checks: alarm number gap, USEROUT bytes, SPDLBUS1 P block, MDST modes
/// (VerifyCnc.cpp).
void checkCnc(Context &cx);

} // namespace lj::verifier

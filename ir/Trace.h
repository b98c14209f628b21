// The power-flow trace of the live ladder view (docs/ladder-view.md "Live view"): what a traced
// engine build records per statement instance, in one table both engines read, so the
// interpreter and the JIT write byte-identical traces (the differential fuzzer compares them).
// The trace is a separate int32 buffer owned by the runtime, never a field of lj_state; an
// untraced build (the default, and every AOT .so) records nothing and is today's code.
#pragma once

#include "ir/OpTable.h"
#include "ir/Profile.h"
#include "ir/Program.h"

#include <cstdint>
#include <vector>

namespace lj {

/// What a statement records. Words are int32; a statement that did not run in a scan keeps the
/// words of its last execution (a loop body or a subroutine called twice: the last one wins).
enum class TraceKind : uint8_t {
  None,    ///< records nothing (ANB/ORB, MPS/MRD/MPP, LBL, LOOP/NEXT, part markers)
  Contact, ///< [0] the contact's own conduction after its force: 0/1 (an edge contact its
           ///< own pulse, not the operand's level; LDT 1)
  Coil,    ///< [0] the coil's power input ST0: 0/1 (OUT/OOUT/SET/RST)
  Box,     ///< [0] EN (ST0 before, 1 with an empty ST), [1] the output (ST0 after, EN when
           ///< the block leaves ST empty), then values read after the block ran: each
           ///< register or constant operand of a core block (the compare operands, the math
           ///< destination, the timer's preset...) in operand order, then the timer's
           ///< elapsed_ms (low 32 bits) or the counter's value for blocks owning one
  Flow,    ///< [0] EN before JMP / CALL / RETN (whether it is taken)
};

/// Core-block operands recorded as values: registers of the data areas and constants.
inline bool traceOperand(const TargetProfile &tp, const Operand &o) {
  if (o.kind == Operand::Kind::Const) return true;
  return o.kind == Operand::Kind::Reg &&
         hasArea(static_cast<AreaMask>(kSrcAreas | kDstAreas), o.area) && tp.area(o.area).bytes > 0;
}

inline TraceKind traceKind(Op op) {
  if (isContact(op) || op == Op::LoadTrue) return TraceKind::Contact;
  const InstrInfo &r = instrInfo(op);
  switch (r.stack) {
  case StackRule::Coil:
    return TraceKind::Coil;
  case StackRule::Block:
    return TraceKind::Box;
  default:
    break;
  }
  if (op == Op::Jump || op == Op::Call || op == Op::Return) return TraceKind::Flow;
  return TraceKind::None;
}

/// Where each statement's words are: one table for every engine and the page.
struct TraceLayout {
  std::vector<int32_t> at;      ///< parallel to prog.stmts: first word, -1 = records nothing
  std::vector<TraceKind> kind;  ///< parallel to prog.stmts
  std::vector<uint8_t> operand; ///< Box: bit k set = operand k is recorded as a value
  int32_t words = 0;            ///< size of the buffer in int32 words
};

inline TraceLayout traceLayout(const VerifiedProgram &prog) {
  TraceLayout l;
  const size_t n = prog.stmts.size();
  l.at.assign(n, -1);
  l.kind.assign(n, TraceKind::None);
  l.operand.assign(n, 0);
  for (size_t i = 0; i < n; ++i) {
    const Stmt &st = prog.stmts[i];
    TraceKind k = traceKind(st.op);
    l.kind[i] = k;
    if (k == TraceKind::None) continue;
    l.at[i] = l.words;
    int32_t w = 1;
    if (k == TraceKind::Box) {
      w = 2;
      const InstrInfo &r = instrInfo(st.op);
      if (r.family == Family::Core) {
        for (int o = 0; o < st.operandCount && o < 8; ++o)
          if (traceOperand(*prog.profile, st.ops[o])) {
            l.operand[i] |= static_cast<uint8_t>(1u << o);
            ++w;
          }
        if (r.state == StateKind::Timer || r.state == StateKind::Counter) ++w;
      }
    }
    l.words += w;
  }
  return l;
}

} // namespace lj

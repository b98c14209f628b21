// Statement dispatch of the reference interpreter (twin of lowering/EmitFlow.cpp and
// EmitBasic.cpp): contacts, edge contacts, ANB/ORB, MPS/MRD/MPP and coils inline in the loop
// (hnc8-core.md 4.2), JMP/LBL, CALL/RETN, LOOP/NEXT and the watchdog (docs/dialect-notes.md
// "Flow"); function blocks go to InterpBlocks.cpp and the family files.
#include "interp/Interpreter.h"
#include "interp/InterpreterInternal.h"
#include "ir/SyncInputs.h"

#include <cassert>

namespace lj {

using namespace interp;

uint32_t Interpreter::Impl::runPart(lj_state *s, StmtRange range, int32_t startDepth) {
  Frame f = frame(0);
  // A part (or a PLC2 slice) starts with empty MS; a slice starts with the dead entries the
  // previous slice left, as zeros (dialect-notes "PLC2 slicing").
  for (int32_t i = 0; i < startDepth; ++i) f.push(false);
  // A JumpOut never leaves a part: the verifier puts its label in the slice of every CALL that
  // can take it.
  Flow r = run(s, f, range.begin, range.end);
  assert(r != Flow::JumpOut && "a JumpOut left a part");
  return r == Flow::Watchdog ? LJ_FAULT_WATCHDOG : LJ_FAULT_NONE;
}

Flow Interpreter::Impl::call(lj_state *s, int32_t sub) {
  // The callee starts with empty stacks of its own; the caller's frame is untouched.
  Frame f = frame(1 + static_cast<size_t>(sub));
  const StmtRange body = prog.subs[sub].body;
  Flow r = run(s, f, body.begin, body.end);
  return r == Flow::Watchdog || r == Flow::JumpOut ? r : Flow::Done;
}

template <bool kTrace>
Flow Interpreter::Impl::runT(lj_state *s, Frame &f, int32_t begin, int32_t end) {
  int32_t pc = begin;
  while (pc < end) {
    const Code &c = code[pc];
    // The dynamic depth must equal the verifier's static one, except at a label reached by a
    // jump (the LBL empties the stacks anyway).
    assert((c.op == Op::Label || f.sp == prog.info[pc].depth) && "ST depth differs from verifier");
    // A forced contact (Code::force, docs/serve.md "Forcing") conducts its constant; a traced
    // build records what it conducts (ir/Trace.h).
    auto contact = [&](bool real) {
      bool v = c.force >= 0 ? c.force != 0 : real;
      if constexpr (kTrace) trace[traceAt.at[pc]] = v;
      return v;
    };
    if constexpr (kTrace) {
      // EN is recorded before the statement runs (a taken JMP never comes back here).
      TraceKind tk = traceAt.kind[pc];
      if (tk == TraceKind::Box || tk == TraceKind::Flow)
        trace[traceAt.at[pc]] = f.input();
      else if (tk == TraceKind::Coil)
        trace[traceAt.at[pc]] = f.top();
      else if (c.op == Op::LoadTrue)
        trace[traceAt.at[pc]] = 1;
    }
    switch (c.op) {
    // Contacts (hnc8-core.md 4.2).
    case Op::Load:
      f.push(contact(readBit(s, c.a)));
      break;
    case Op::LoadNot:
      f.push(contact(!readBit(s, c.a)));
      break;
    case Op::LoadTrue:
      f.push(true);
      break;
    case Op::LoadRise: // the edge memory is updated with the real bit even when forced
      f.push(contact(edgeSample(s, c.slot, readBit(s, c.a), true, edgeUpdates)));
      break;
    case Op::LoadFall:
      f.push(contact(edgeSample(s, c.slot, readBit(s, c.a), false, edgeUpdates)));
      break;
    case Op::And: { // the contact is evaluated (and traced) whatever ST0 is
      bool v = contact(readBit(s, c.a));
      f.setTop(f.top() && v);
      break;
    }
    case Op::AndNot: { // the contact is evaluated (and traced) whatever ST0 is
      bool v = contact(!readBit(s, c.a));
      f.setTop(f.top() && v);
      break;
    }
    case Op::Or: { // the contact is evaluated (and traced) whatever ST0 is
      bool v = contact(readBit(s, c.a));
      f.setTop(f.top() || v);
      break;
    }
    case Op::OrNot: { // the contact is evaluated (and traced) whatever ST0 is
      bool v = contact(!readBit(s, c.a));
      f.setTop(f.top() || v);
      break;
    }
    // Edge combines sample first: they must update m whatever ST0 is (no short-circuit).
    case Op::AndRise: {
      bool e = contact(edgeSample(s, c.slot, readBit(s, c.a), true, edgeUpdates));
      f.setTop(f.top() && e);
      break;
    }
    case Op::AndFall: {
      bool e = contact(edgeSample(s, c.slot, readBit(s, c.a), false, edgeUpdates));
      f.setTop(f.top() && e);
      break;
    }
    case Op::OrRise: {
      bool e = contact(edgeSample(s, c.slot, readBit(s, c.a), true, edgeUpdates));
      f.setTop(f.top() || e);
      break;
    }
    case Op::OrFall: {
      bool e = contact(edgeSample(s, c.slot, readBit(s, c.a), false, edgeUpdates));
      f.setTop(f.top() || e);
      break;
    }
    case Op::AndBlock: {
      bool t = f.pop();
      f.setTop(f.top() && t);
      break;
    }
    case Op::OrBlock: {
      bool t = f.pop();
      f.setTop(f.top() || t);
      break;
    }
    case Op::BranchPush:
      assert(f.msp < f.msCap);
      f.ms[f.msp++] = f.top();
      break;
    case Op::BranchRead:
      assert(f.msp > 0);
      f.setTop(f.ms[f.msp - 1] != 0);
      break;
    case Op::BranchPop:
      assert(f.msp > 0);
      f.setTop(f.ms[--f.msp] != 0);
      break;
    // Coils leave ST unchanged.
    case Op::Coil:
      writeBit(s, c.a, f.top());
      break;
    case Op::CoilNot:
      writeBit(s, c.a, !f.top());
      break;
    case Op::Set:
      writeBit(s, c.a, readBit(s, c.a) || f.top());
      break;
    case Op::Reset:
      writeBit(s, c.a, readBit(s, c.a) && !f.top());
      break;

    // Structure: both stacks are emptied (dialect-notes "Stacks and blocks").
    case Op::EndInit:
    case Op::EndCyclic:
    case Op::EndSliced:
    case Op::SubBegin:
    case Op::SubEnd:
    case Op::Label:
    case Op::LoopEnd:
      f.clear();
      break;
    case Op::Jump:
      if (f.input()) {
        // A taken backward jump counts one watchdog step, checked before jumping.
        if (c.target < pc && ++s->steps > s->max_backward_steps) return Flow::Watchdog;
        pc = c.target; // the LBL runs next and empties the stacks
        continue;
      }
      break;
    case Op::Call:
      if (f.input()) {
        Flow r = call(s, c.target);
        if (r == Flow::Watchdog) return r;
        if (r == Flow::JumpOut) {
          // The callee left for a label: go on there when it is in this run (the sliced part's
          // slice holding this CALL), else leave this run too (docs/fanuc-pmc.md "JMPC").
          const int32_t to = jumpOutLabel;
          if (to < begin || to >= end) return r;
          if (to < pc && ++s->steps > s->max_backward_steps) return Flow::Watchdog;
          pc = to; // the LBL runs next and empties the stacks
          continue;
        }
      }
      break;
    case Op::JumpOut:
      if (f.input()) {
        jumpOutLabel = c.target;
        return Flow::JumpOut;
      }
      break;
    case Op::Return:
      if (f.input()) return Flow::Return;
      break;
    case Op::LoopBegin: {
      int32_t n = readValue(s, c.a); // read once on entry
      const int32_t next = c.target;
      f.clear();
      for (int32_t i = 0; i < n; ++i) {
        if (++s->steps > s->max_backward_steps) return Flow::Watchdog;
        f.clear();
        Flow r = run(s, f, pc + 1, next);
        if (r != Flow::Done) return r; // RETN inside a loop leaves the subroutine
      }
      f.clear();
      pc = next + 1;
      continue;
    }
    default:
      if (c.wide >= 0) {
        BlockCall call{s, f, c, wide[c.wide].data(), prog.stmts[pc], prog.info[pc], *prog.profile};
        bool done = opFamily(c.op) == Family::Data            ? runData(call)
                    : opFamily(c.op) == Family::Nc            ? runNc(call)
                    : opFamily(c.op) == Family::PmcTc         ? runPmcTc(call)
                    : opFamily(c.op) == Family::ClassicLadder ? runClassicLadder(call)
                                                              : runCnc(call);
        if (!done) unimplemented = c.op;
      } else {
        block(s, f, c);
      }
      break;
    }
    if constexpr (kTrace)
      if (traceAt.kind[pc] == TraceKind::Box) traceAfter(s, f, pc);
    ++pc;
  }
  return Flow::Done;
}

void Interpreter::Impl::traceAfter(lj_state *s, const Frame &f, int32_t pc) {
  // The order of ir/Trace.h Box: [0] EN (already written), [1] output, operand values, then the
  // timer's elapsed or the counter's value.
  int32_t *w = trace + traceAt.at[pc];
  w[1] = f.sp > 0 ? f.top() : w[0];
  int32_t k = 2;
  const Stmt &st = prog.stmts[pc];
  for (int o = 0; o < st.operandCount && o < 8; ++o)
    if (traceAt.operand[pc] & (1u << o))
      w[k++] = readValue(s, decode(*prog.profile, st.ops[o], readsSyncInputs(prog, pc)));
  const StateKind sk = instrInfo(st.op).state;
  if (instrInfo(st.op).family == Family::Core && sk == StateKind::Timer)
    w[k] = static_cast<int32_t>(static_cast<uint32_t>(timerAt(s, code[pc].slot).elapsed_ms));
  else if (instrInfo(st.op).family == Family::Core && sk == StateKind::Counter)
    w[k] = s->C[code[pc].slot].value;
}

template Flow Interpreter::Impl::runT<true>(lj_state *, Frame &, int32_t, int32_t);
template Flow Interpreter::Impl::runT<false>(lj_state *, Frame &, int32_t, int32_t);

} // namespace lj

// The reference interpreter (the oracle). Written straight from DIALECT.md, docs/dialect-notes.md
// and the reference tables; it shares no code with the lowering or the JIT (STYLE.md 8).
//
// Shape: operands are decoded once into byte offsets of lj_state; each scope (part, subroutine,
// loop body) runs as a statement range with explicit ST/MS stacks. Recursion is a compile error,
// so every subroutine can own one preallocated pair of stacks; loops run on their scope's stacks
// (they are emptied at LOOP and NEXT anyway).
#include "interp/Interpreter.h"
#include "interp/InterpreterInternal.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cassert>
#include <cstddef>
#include <cstring>
#include <vector>

namespace lj {

using namespace interp;

// Bit operands are reduced to "one byte and a mask", which matches DIALECT.md 1 (bit k of a
// little-endian element) only on a little-endian host; the ABI is little-endian by definition.
static_assert(std::endian::native == std::endian::little, "lj_state is little-endian");

namespace {
/// How a statement range ended.
enum class Flow { Done, Return, Watchdog };
/// Edge contact on one instance's memory m (DIALECT.md 3): always updates m.
bool edgeSample(lj_state *s, int32_t slot, bool cur, bool rising) {
  bool m = s->edge[slot] != 0;
  s->edge[slot] = cur;
  return rising ? (cur && !m) : (!cur && m);
}

/// The common counter algorithm of hnc8-functions-1.md 3.3, verbatim. `cv` and `prev` are the
/// instance's value and edge memory; returns the output.
bool countStep(bool cnt, bool s1, bool dn, bool rst, int32_t pv, int32_t &cv, bool &prev) {
  int32_t init = s1 ? 1 : 0;
  bool out;
  if (rst) {
    cv = dn ? pv : init;
    out = false;
  } else {
    if (cnt && !prev) {
      if (!dn)
        cv = (cv >= pv) ? init : cv + 1; // cv < pv <= INT32_MAX: no overflow
      else
        cv = (cv <= init) ? pv : cv - 1; // cv > init >= 0: no overflow
    }
    out = dn ? (cv <= init) : (cv >= pv);
  }
  prev = cnt;
  return out;
}

/// Timer preset in ms, 64-bit; a negative preset counts as 0 (dialect-notes "Timers").
int64_t presetMs(int32_t unit, int32_t len) {
  static constexpr int64_t kUnitMs[4] = {1, 1000, 60000, 3600000};
  int64_t p = int64_t(len) * kUnitMs[unit & 3];
  return p < 0 ? 0 : p;
}

int64_t elapsedSince(const lj_state *s, int64_t start) {
  int64_t now = static_cast<int64_t>(s->now_ms);
  return now > start ? now - start : 0;
}

/// Whether a verifier-assigned slot indexes its lj_state array (checked once, in asserts).
[[maybe_unused]] bool slotInRange(StateKind k, int32_t slot) {
  switch (k) {
  case StateKind::None:
    return true;
  case StateKind::Edge:
    return slot >= 0 && slot < LJ_EDGE_SLOTS;
  case StateKind::Timer:
  case StateKind::Counter:
    return slot >= 0 && slot < LJ_TC_SLOTS;
  case StateKind::Words:
    return slot >= 0 && slot + 1 < LJ_INST_WORDS;
  default:
    return slot >= 0 && slot < LJ_BLOCK_SLOTS;
  }
}

} // namespace

struct Interpreter::Impl {
  const VerifiedProgram &prog;
  std::vector<Code> code; ///< parallel to prog.stmts
  /// All decoded operands of the non-core statements (Code::wide indexes it).
  std::vector<std::array<Ref, kMaxOperands>> wide;
  /// The last executed instruction that had no semantics (Op::Count_: none so far).
  Op unimplemented = Op::Count_;
  // Stacks: [0] is shared by the main parts, [1 + i] belongs to subroutine i.
  std::vector<std::vector<uint8_t>> stStore, msStore;

  explicit Impl(const VerifiedProgram &p);
  Frame frame(size_t scope);
  uint32_t runPart(lj_state *s, StmtRange range, int32_t startDepth);
  Flow run(lj_state *s, Frame &f, int32_t begin, int32_t end);
  Flow call(lj_state *s, int32_t sub);
  void block(lj_state *s, Frame &f, const Code &c);
};

Interpreter::Impl::Impl(const VerifiedProgram &p) : prog(p) {
  code.resize(p.stmts.size());
  for (size_t i = 0; i < p.stmts.size(); ++i) {
    const Stmt &st = p.stmts[i];
    Code &c = code[i];
    c.op = st.op;
    c.a = decode(st.ops[0]);
    c.b = decode(st.ops[1]);
    c.c = decode(st.ops[2]);
    c.target = p.info[i].target;
    c.slot = p.info[i].slot;
    if (opFamily(st.op) != Family::Core) {
      c.wide = static_cast<int32_t>(wide.size());
      std::array<Ref, kMaxOperands> &w = wide.emplace_back();
      for (int k = 0; k < st.operandCount; ++k) w[k] = decode(st.ops[k]);
    }
    assert(slotInRange(instrInfo(c.op).state, c.slot) && "state slot out of range");
    assert((c.op != Op::Jump && c.op != Op::LoopBegin) ||
           (c.target >= 0 && static_cast<size_t>(c.target) < p.stmts.size()));
    assert(c.op != Op::Call || (c.target >= 0 && static_cast<size_t>(c.target) < p.subs.size()));
  }
  // Stack capacity per scope: the deepest "depth before" in the scope, plus one because a
  // statement raises the depth by at most one.
  auto need = [&](StmtRange r, int32_t &st, int32_t &ms) {
    for (int32_t i = r.begin; i < r.end; ++i) {
      st = std::max(st, p.info[i].depth + 1);
      ms = std::max(ms, p.info[i].msDepth + 1);
    }
  };
  int32_t st = std::max(p.maxDepth, 0) + 1, ms = std::max(p.maxMsDepth, 0) + 1;
  need(p.init, st, ms);
  need(p.plc1, st, ms);
  need(p.plc2, st, ms);
  for (int32_t d : p.sliceDepth) st = std::max(st, d + 1);
  stStore.emplace_back(st);
  msStore.emplace_back(ms);
  for (const Subroutine &sub : p.subs) {
    int32_t sst = 1, sms = 1;
    need(sub.body, sst, sms);
    stStore.emplace_back(sst);
    msStore.emplace_back(sms);
  }
}

Frame Interpreter::Impl::frame(size_t scope) {
  return Frame{stStore[scope].data(), msStore[scope].data(),
               static_cast<int32_t>(stStore[scope].size()),
               static_cast<int32_t>(msStore[scope].size())};
}

uint32_t Interpreter::Impl::runPart(lj_state *s, StmtRange range, int32_t startDepth) {
  Frame f = frame(0);
  // A part (or a PLC2 slice) starts with empty MS; a slice starts with the dead entries the
  // previous slice left, as zeros (dialect-notes "PLC2 slicing").
  for (int32_t i = 0; i < startDepth; ++i) f.push(false);
  return run(s, f, range.begin, range.end) == Flow::Watchdog ? LJ_FAULT_WATCHDOG : LJ_FAULT_NONE;
}

Flow Interpreter::Impl::call(lj_state *s, int32_t sub) {
  // The callee starts with empty stacks of its own; the caller's frame is untouched.
  Frame f = frame(1 + static_cast<size_t>(sub));
  const StmtRange body = prog.subs[sub].body;
  Flow r = run(s, f, body.begin, body.end);
  return r == Flow::Watchdog ? Flow::Watchdog : Flow::Done;
}

Flow Interpreter::Impl::run(lj_state *s, Frame &f, int32_t begin, int32_t end) {
  int32_t pc = begin;
  while (pc < end) {
    const Code &c = code[pc];
    // The dynamic depth must equal the verifier's static one, except at a label reached by a
    // jump (the LBL empties the stacks anyway).
    assert((c.op == Op::Label || f.sp == prog.info[pc].depth) && "ST depth differs from verifier");
    // A forced contact (Stmt::force, docs/serve.md "Forcing") conducts its constant.
    auto contact = [&](bool real) {
      int8_t force = prog.stmts[pc].force;
      return force >= 0 ? force != 0 : real;
    };
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
      f.push(contact(edgeSample(s, c.slot, readBit(s, c.a), true)));
      break;
    case Op::LoadFall:
      f.push(contact(edgeSample(s, c.slot, readBit(s, c.a), false)));
      break;
    case Op::And:
      f.setTop(f.top() && contact(readBit(s, c.a)));
      break;
    case Op::AndNot:
      f.setTop(f.top() && contact(!readBit(s, c.a)));
      break;
    case Op::Or:
      f.setTop(f.top() || contact(readBit(s, c.a)));
      break;
    case Op::OrNot:
      f.setTop(f.top() || contact(!readBit(s, c.a)));
      break;
    // Edge combines sample first: they must update m whatever ST0 is (no short-circuit).
    case Op::AndRise: {
      bool e = contact(edgeSample(s, c.slot, readBit(s, c.a), true));
      f.setTop(f.top() && e);
      break;
    }
    case Op::AndFall: {
      bool e = contact(edgeSample(s, c.slot, readBit(s, c.a), false));
      f.setTop(f.top() && e);
      break;
    }
    case Op::OrRise: {
      bool e = contact(edgeSample(s, c.slot, readBit(s, c.a), true));
      f.setTop(f.top() || e);
      break;
    }
    case Op::OrFall: {
      bool e = contact(edgeSample(s, c.slot, readBit(s, c.a), false));
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
      if (f.input() && call(s, c.target) == Flow::Watchdog) return Flow::Watchdog;
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
        BlockCall call{s, f, c, wide[c.wide].data(), prog.stmts[pc], prog.info[pc]};
        bool done = opFamily(c.op) == Family::Data ? runData(call)
                    : opFamily(c.op) == Family::Nc ? runNc(call)
                                                   : runCnc(call);
        if (!done) unimplemented = c.op;
      } else {
        block(s, f, c);
      }
      break;
    }
    ++pc;
  }
  return Flow::Done;
}

// Function blocks with data (DIALECT.md 5, hnc8-functions-1/-2.md).
void Interpreter::Impl::block(lj_state *s, Frame &f, const Code &c) {
  switch (c.op) {
  case Op::Add:
  case Op::Subtract:
  case Op::Multiply:
  case Op::BitAnd:
  case Op::BitOr:
  case Op::BitXor: {
    bool en = f.input();
    if (en) {
      int32_t a = readValue(s, c.a), b = readValue(s, c.b), r = 0;
      switch (c.op) {
      case Op::Add:
        r = addWrap(a, b);
        break;
      case Op::Subtract:
        r = subWrap(a, b);
        break;
      case Op::Multiply:
        r = mulWrap(a, b);
        break;
      case Op::BitAnd:
        r = a & b;
        break;
      case Op::BitOr:
        r = a | b;
        break;
      default:
        r = a ^ b;
        break;
      }
      writeValue(s, c.c, r);
    }
    f.output(en);
    return;
  }
  case Op::Divide: {
    bool en = f.input(), out = en;
    if (en) {
      int32_t a = readValue(s, c.a), b = readValue(s, c.b);
      if (b == 0) {
        ++s->fault_divzero; // nothing written, output 0
        out = false;
      } else {
        writeValue(s, c.c, (a == INT32_MIN && b == -1) ? INT32_MIN : a / b);
      }
    }
    f.output(out);
    return;
  }
  case Op::Increment:
  case Op::Decrement:
  case Op::Negate: {
    bool en = f.input();
    if (en) {
      int32_t x = readValue(s, c.a);
      int32_t r = c.op == Op::Increment   ? addWrap(x, 1)
                  : c.op == Op::Decrement ? subWrap(x, 1)
                                          : subWrap(0, x);
      writeValue(s, c.a, r);
    }
    f.output(en);
    return;
  }
  case Op::Move: {
    bool en = f.input();
    if (en) writeValue(s, c.b, readValue(s, c.a));
    f.output(en);
    return;
  }
  case Op::CompareLe:
    f.output(f.input() && readValue(s, c.a) <= readValue(s, c.b));
    return;
  case Op::CompareLt:
    f.output(f.input() && readValue(s, c.a) < readValue(s, c.b));
    return;
  case Op::CompareEq:
    f.output(f.input() && readValue(s, c.a) == readValue(s, c.b));
    return;
  case Op::CompareRange: {
    int32_t lo = readValue(s, c.a), hi = readValue(s, c.b), x = readValue(s, c.c);
    f.output(f.input() && lo < x && x < hi);
    return;
  }

  // Counters: pop k inputs (first loaded = input 1 = deepest), push the output.
  case Op::RegisterCounter: {
    bool rst = f.pop(), dn = f.pop(), s1 = f.pop(), cnt = f.pop();
    int32_t cv = readValue(s, c.a);
    bool prev = s->edge[c.slot] != 0;
    bool out = countStep(cnt, s1, dn, rst, readValue(s, c.b), cv, prev);
    writeValue(s, c.a, cv);
    s->edge[c.slot] = prev;
    f.push(out);
    return;
  }
  case Op::RingCounter:
  case Op::UpDownCounter: {
    bool rst = f.pop(), dn = false, s1 = false;
    if (c.op == Op::UpDownCounter) {
      dn = f.pop();
      s1 = f.pop();
    }
    bool cnt = f.pop();
    lj_counter &k = s->C[c.slot];
    bool prev = k.prev != 0;
    bool out = countStep(cnt, s1, dn, rst, readValue(s, c.b), k.value, prev);
    k.prev = prev;
    k.out = out;
    f.push(out);
    return;
  }

  // Timers (dialect-notes "Timers"); state in T[slot], time from now_ms.
  case Op::OnDelayTimer: {
    lj_timer &t = s->T[c.slot];
    int64_t preset = presetMs(readValue(s, c.b), readValue(s, c.c));
    if (f.input()) {
      if (!t.running) {
        t.running = 1;
        t.start_ms = static_cast<int64_t>(s->now_ms);
      }
      int64_t el = elapsedSince(s, t.start_ms);
      t.out = el >= preset;
      t.elapsed_ms = std::min(el, preset);
    } else {
      t.running = 0;
      t.out = 0;
      t.elapsed_ms = 0;
    }
    f.output(t.out != 0);
    return;
  }
  case Op::OffDelayTimer: {
    lj_timer &t = s->T[c.slot];
    int64_t preset = presetMs(readValue(s, c.b), readValue(s, c.c));
    if (f.input()) {
      t.out = 1;
      t.running = 0;
      t.elapsed_ms = 0;
    } else if (t.out) {
      if (!t.running) {
        t.running = 1;
        t.start_ms = static_cast<int64_t>(s->now_ms);
      }
      int64_t el = elapsedSince(s, t.start_ms);
      if (el >= preset) {
        t.out = 0;
        t.running = 0;
        t.elapsed_ms = preset;
      } else {
        t.elapsed_ms = el;
      }
    }
    f.output(t.out != 0);
    return;
  }

  // Power-flow edge and toggle blocks; prev = EN on every execution.
  case Op::RisePulse: {
    bool en = f.input();
    bool out = en && !s->pls_prev[c.slot];
    s->pls_prev[c.slot] = en;
    f.output(out);
    return;
  }
  case Op::FallPulse: {
    bool en = f.input();
    bool out = !en && s->plf_prev[c.slot];
    s->plf_prev[c.slot] = en;
    f.output(out);
    return;
  }
  case Op::Toggle: {
    bool en = f.input();
    if (en && !s->alt_prev[c.slot]) s->alt_state[c.slot] = !s->alt_state[c.slot];
    s->alt_prev[c.slot] = en;
    f.output(s->alt_state[c.slot] != 0);
    return;
  }
  default:
    assert(false && "instruction without interpreter semantics");
    return;
  }
}

namespace {
uint32_t initEntry(void *ctx, lj_state *s) { return static_cast<Interpreter *>(ctx)->runInit(s); }
uint32_t plc1Entry(void *ctx, lj_state *s) { return static_cast<Interpreter *>(ctx)->runPlc1(s); }
uint32_t sliceEntry(void *ctx, lj_state *s, uint32_t k) {
  return static_cast<Interpreter *>(ctx)->runPlc2Slice(s, k);
}
} // namespace

Interpreter::Interpreter(const VerifiedProgram &prog) : impl_(std::make_unique<Impl>(prog)) {
  entries_.ctx = this;
  entries_.init = initEntry;
  entries_.plc1 = plc1Entry;
  entries_.plc2_slice = sliceEntry;
  entries_.plc2_slice_count = sliceCount();
}

Interpreter::~Interpreter() = default;

uint32_t Interpreter::runInit(lj_state *s) { return impl_->runPart(s, impl_->prog.init, 0); }

uint32_t Interpreter::runPlc1(lj_state *s) { return impl_->runPart(s, impl_->prog.plc1, 0); }

uint32_t Interpreter::runPlc2Slice(lj_state *s, uint32_t slice) {
  const VerifiedProgram &p = impl_->prog;
  if (p.slices.empty()) return slice == 0 ? impl_->runPart(s, p.plc2, 0) : LJ_FAULT_NONE;
  if (slice >= p.slices.size()) return LJ_FAULT_NONE;
  int32_t depth = slice < p.sliceDepth.size() ? p.sliceDepth[slice] : 0;
  return impl_->runPart(s, p.slices[slice], depth);
}

Op Interpreter::unimplemented() const { return impl_->unimplemented; }

uint32_t Interpreter::sliceCount() const {
  return std::max<uint32_t>(1u, static_cast<uint32_t>(impl_->prog.slices.size()));
}

namespace {
/// The interpreter behind the common Engine interface (instructions/Engine.h).
class InterpreterEngine final : public Engine {
public:
  explicit InterpreterEngine(const VerifiedProgram &prog) : interp_(prog) {}
  const lj_entries &entries() const override { return interp_.entries(); }
  const char *name() const override { return "interp"; }

private:
  Interpreter interp_;
};
} // namespace

std::unique_ptr<Engine> makeInterpreterEngine(const VerifiedProgram &prog) {
  return std::make_unique<InterpreterEngine>(prog);
}

} // namespace lj

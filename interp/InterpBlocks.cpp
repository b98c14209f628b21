// Function blocks of the reference interpreter (twin of lowering/EmitBlocks.cpp; DIALECT.md 5,
// docs/dialect-notes.md "Function blocks"): math, compares, MOV, counters, timers, PLS/PLF/ALT.
#include "interp/Interpreter.h"
#include "interp/InterpreterInternal.h"
#include "ir/Profile.h"

#include <cassert>

namespace lj {

using namespace interp;

namespace {

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
int64_t presetMs(const TargetProfile &tp, int32_t unit, int32_t len) {
  int64_t p = int64_t(len) * tp.timerUnitMs[unit & 3];
  return p < 0 ? 0 : p;
}

int64_t elapsedSince(const lj_state *s, int64_t start) {
  int64_t now = static_cast<int64_t>(s->now_ms);
  return now > start ? now - start : 0;
}

} // namespace

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

  // Timers (dialect-notes "Timers"); state in timer slot `slot` (T[slot] or the profile's
  // BlockState), time from now_ms.
  case Op::OnDelayTimer: {
    lj_timer &t = timerAt(s, c.slot);
    int64_t preset = presetMs(*prog.profile, readValue(s, c.b), readValue(s, c.c));
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
    lj_timer &t = timerAt(s, c.slot);
    int64_t preset = presetMs(*prog.profile, readValue(s, c.b), readValue(s, c.c));
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
    uint8_t &prev = pulseAt(s, true, c.slot);
    bool out = en && !prev;
    prev = en;
    f.output(out);
    return;
  }
  case Op::FallPulse: {
    bool en = f.input();
    uint8_t &prev = pulseAt(s, false, c.slot);
    bool out = !en && prev;
    prev = en;
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
  case Op::IecTimer: // the Neza blocks (InterpIec.cpp)
    iecTimer(s, f, c);
    return;
  case Op::IecCounter:
    iecCounter(s, f, c);
    return;
  default:
    assert(false && "instruction without interpreter semantics");
    return;
  }
}

} // namespace lj

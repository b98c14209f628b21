// Interpreter semantics of family Nc: NC services (chapter-4 CNC blocks, host callbacks, stateful
// chapter-6 blocks). Written straight from hnc8-functions-1.md 2.4/3.1, hnc8-functions-2.md
// 2.19-2.23, hnc8-cnc-interface.md section 2 and docs/dialect-notes.md "NC services".
#include "interp/InterpreterInternal.h"
#include "ir/Profile.h"

namespace lj::interp {

namespace {

/// The target's CNC words (profile): FC[k] / GC[k] = F/G[channelBase + blockWords * ch + k]
/// (hnc8-cnc-interface.md 1.3, 1.4).
int32_t chanBase(const CncLayout &cnc, int32_t ch) { return cnc.channelBase + cnc.blockWords * ch; }

/// Store the low 16 bits of v into G[i] (a write keeps the low bits, DIALECT.md 1).
void setG(lj_state *s, int32_t i, int32_t v) {
  s->img.G[i] = static_cast<int16_t>(static_cast<uint16_t>(static_cast<uint32_t>(v) & 0xFFFFu));
}

/// A 32-bit value across two G words, low word first (hnc8-cnc-interface.md 0).
void setG32(lj_state *s, int32_t i, int32_t v) {
  setG(s, i, v);
  setG(s, i + 1, static_cast<int32_t>(static_cast<uint32_t>(v) >> 16));
}

/// Mathematical modulo (result in 0..n-1) for n > 0.
int64_t modN(int64_t x, int64_t n) {
  int64_t r = x % n;
  return r < 0 ? r + n : r;
}

/// The callback `member` of the state's host, or null (no host or no such service).
template <typename Fn> Fn callback(const lj_state *s, Fn lj_host::*member) {
  return s->host ? s->host->*member : nullptr;
}

/// ROT (hnc8-cnc-interface.md 2 #59): pops 5 inputs, pushes the direction bit.
void rot(const BlockCall &b) {
  bool in5 = b.f.pop(), in4 = b.f.pop(), in3 = b.f.pop(), in2 = b.f.pop(), act = b.f.pop();
  bool reverse = false;
  if (act) {
    int64_t n = b.ops[0].value; // 1..32767 (table)
    int64_t base = in2 ? 1 : 0;
    int64_t c = int64_t{readValue(b.s, b.ops[1])} - base;
    int64_t t = int64_t{readValue(b.s, b.ops[2])} - base;
    int64_t fwd = modN(t - c, n), rev = modN(c - t, n);
    reverse = in3 && rev < fwd; // a tie rotates forward
    int64_t steps = reverse ? rev : fwd;
    int64_t tp = t;
    if (in4) {
      steps = steps > 0 ? steps - 1 : 0;
      tp = reverse ? modN(t + 1, n) : modN(t - 1 + n, n);
    }
    int64_t result = in5 ? steps : tp + base;
    writeValue(b.s, b.ops[3], static_cast<int32_t>(static_cast<uint32_t>(result)));
  }
  b.f.push(reverse); // ACT = 0: nothing written, output 0
}

} // namespace

bool runNc(const BlockCall &b) {
  lj_state *s = b.s;
  const CncLayout &kCnc = b.tp.cnc;
  Frame &f = b.f;
  const Ref *o = b.ops;
  const bool en = f.input();
  switch (b.c.op) {
  case Op::MCodeGet: {
    // out = EN and one of FC[48..55] holds the M code; nothing written (functions-1 3.1).
    int32_t cb = chanBase(kCnc, o[0].value);
    bool pending = false;
    for (int k = 0; k < kCnc.mCodeSlots; ++k)
      pending = pending || s->img.F[cb + kCnc.mCodeWord + k] == o[1].value;
    f.output(en && pending);
    return true;
  }
  case Op::MCodeAck:
    // Every slot k holding the M code is acknowledged: GC[48+k] := M (functions-1 3.1).
    if (en) {
      int32_t cb = chanBase(kCnc, o[0].value);
      for (int k = 0; k < kCnc.mCodeSlots; ++k)
        if (s->img.F[cb + kCnc.mCodeWord + k] == o[1].value)
          setG(s, cb + kCnc.mCodeWord + k, o[1].value);
    }
    return true;
  case Op::TCodeGet: {
    // FC[56] != -1: a T code is pending; it goes to the destination, or is compared with a
    // constant destination (functions-1 3.1 TGET resolution).
    int16_t t = s->img.F[chanBase(kCnc, o[0].value) + kCnc.tCodeWord];
    bool pending = t != -1;
    if (o[1].kind == Ref::Kind::Const) {
      f.output(en && pending && t == o[1].value);
    } else {
      if (en && pending) writeValue(s, o[1], t);
      f.output(en && pending);
    }
    return true;
  }
  case Op::TCodeAck:
    if (en) {
      int32_t cb = chanBase(kCnc, o[0].value);
      setG(s, cb + kCnc.tCodeWord, s->img.F[cb + kCnc.tCodeWord]); // GC[56] := FC[56]
    }
    return true;
  case Op::HandwheelPulse:
    if (en)
      if (auto fn = callback(s, &lj_host::mpg_input))
        fn(s->host->ctx, o[1].value, readValue(s, o[0]));
    return true;
  case Op::TempSensor:
    if (en)
      if (auto fn = callback(s, &lj_host::temp_input)) {
        // raw: the 16-bit AD word of the X group, X[n] low byte, X[n+1] high byte, signed.
        int32_t x = b.stmt.ops[1].index, p = b.stmt.ops[3].index;
        auto raw = static_cast<int16_t>(s->img.X[x] | (s->img.X[x + 1] << 8));
        fn(s->host->ctx, o[0].value, raw, o[2].value, s->img.P[p], s->img.P[p + 1], s->img.P[p + 2],
           s->img.P[p + 3]);
      }
    return true;
  case Op::PartCount:
  case Op::PartClear:
    // The part count of channel ch is GC[19] (functions-2 2.19, 2.20); level-triggered.
    if (en) {
      int32_t i = chanBase(kCnc, o[0].value) + kCnc.partCountWord;
      setG(s, i, b.c.op == Op::PartCount ? addWrap(s->img.G[i], 1) : 0);
    }
    f.output(en);
    return true;
  case Op::HeadSensors:
    // enable == 0: D[start + i] := temperature i = G[3080 + i] (functions-2 2.21).
    if (en && o[1].value == 0)
      for (int32_t i = 0; i < o[0].value; ++i)
        s->img.D[b.stmt.ops[2].index + i] = s->img.G[3080 + i];
    return true;
  case Op::VarGet:
    if (en)
      if (auto fn = callback(s, &lj_host::var_get)) {
        int32_t v = 0;
        if (fn(s->host->ctx, o[0].value, readValue(s, o[1]), o[2].value, &v) != 0)
          writeValue(s, o[3], v);
      }
    f.output(en);
    return true;
  case Op::VarSet:
    if (en)
      if (auto fn = callback(s, &lj_host::var_set))
        fn(s->host->ctx, o[0].value, readValue(s, o[1]), o[2].value, readValue(s, o[3]));
    f.output(en);
    return true;
  case Op::ToolVectorOn:
  case Op::ToolVectorOff:
    if (en)
      if (auto fn = callback(s, &lj_host::tool_vector))
        fn(s->host->ctx, o[0].value, b.c.op == Op::ToolVectorOn ? 1 : 0);
    f.output(en);
    return true;
  case Op::PanelDisplay:
    if (en) {
      int32_t v = readValue(s, o[0]);
      if (auto fn = callback(s, &lj_host::nixie_encode)) v = fn(s->host->ctx, v, o[1].value);
      // The low 8 (width 0) or 16 (width 1) bits: a byte area gets 1 or 2 bytes starting at the
      // operand, low byte first; a W/D/B element gets the masked value.
      int32_t code =
          static_cast<int32_t>(static_cast<uint32_t>(v) & (o[1].value ? 0xFFFFu : 0xFFu));
      if (o[2].kind == Ref::Kind::U8) {
        writeValue(s, o[2], code);
        if (o[1].value) {
          Ref next = o[2];
          next.off += 1;
          writeValue(s, next, code >> 8);
        }
      } else {
        writeValue(s, o[2], code);
      }
    }
    f.output(en);
    return true;
  case Op::ToolInUse:
    if (en)
      if (auto fn = callback(s, &lj_host::tool_in_use))
        fn(s->host->ctx, readValue(s, o[0]), readValue(s, o[1]));
    return true;
  case Op::ToolLife: {
    // inst_word[slot] = installs counted, [slot + 1] = ACT of the previous execution. Every
    // execution writes the response: 1 when this rising edge reached the count, else 0.
    int32_t &count = s->inst_word[b.c.slot];
    int32_t &prev = s->inst_word[b.c.slot + 1];
    bool rise = en && prev == 0;
    prev = en ? 1 : 0;
    bool reached = false;
    if (rise) {
      count = addWrap(count, 1);
      if (count >= o[1].value) {
        reached = true;
        count = 0;
      }
    }
    writeValue(s, o[2], reached ? 1 : 0);
    return true;
  }
  case Op::ToolSelect: {
    bool found = false;
    if (en)
      if (auto fn = callback(s, &lj_host::tool_select)) {
        int32_t pocket = 0, error = 0;
        found = fn(s->host->ctx, readValue(s, o[0]), readValue(s, o[1]), &pocket, &error) != 0;
        if (found)
          writeValue(s, o[3], pocket);
        else
          writeValue(s, o[2], error);
      }
    f.output(found);
    return true;
  }
  case Op::SpindleAnalog:
    if (en)
      if (auto fn = callback(s, &lj_host::spindle_da)) {
        // rpm: the spindle's S command FC[10+2sp] (32 bits, low word first); the DA value goes
        // to the reference operand and to GC[10+2sp] (hnc8-cnc-interface.md 2 #33, 1.4).
        int32_t cb = chanBase(kCnc, o[0].value), sp = o[1].value;
        uint32_t lo = static_cast<uint16_t>(s->img.F[cb + 10 + 2 * sp]);
        uint32_t hi = static_cast<uint16_t>(s->img.F[cb + 11 + 2 * sp]);
        int32_t rpm = wrap(lo | (hi << 16));
        int32_t da = fn(s->host->ctx, o[0].value, sp, rpm, readValue(s, o[2]), b.stmt.ops[4].index);
        writeValue(s, o[3], da);
        setG32(s, cb + 10 + 2 * sp, da);
      }
    return true;
  case Op::SlaveHomingEnable:
    // Level, like a coil: the host is told the enable state on every execution.
    if (auto fn = callback(s, &lj_host::slave_home)) fn(s->host->ctx, o[0].value, en ? 1 : 0);
    return true;
  case Op::HandwheelSet:
    if (en) {
      int32_t axis = readValue(s, o[1]);
      if (axis < 0 || axis > 31) {
        // A runtime index out of range: nothing happens, output 0, fault counted (DIALECT.md 4).
        ++s->fault_index;
        if (f.sp > 0) f.setTop(false);
        return true;
      }
      setG(s, axis * 80 + 9, readValue(s, o[2])); // GA[9] = multiplier
      if (auto fn = callback(s, &lj_host::mpg_delta))
        setG32(s, axis * 80 + 10, fn(s->host->ctx, o[0].value)); // GA[10/11] = pulses
    }
    return true;
  case Op::MagazineRotate:
    rot(b);
    return true;
  case Op::RaiseEvent: {
    // G[3040 + n/16] bit n%16 := ACT (level); the host hears of the rising edge.
    uint8_t &m = s->edge[b.c.slot];
    bool rise = en && !m;
    m = en;
    int32_t n = o[0].value;
    auto word = static_cast<uint16_t>(s->img.G[3040 + n / 16]);
    uint16_t mask = static_cast<uint16_t>(1u << (n % 16));
    setG(s, 3040 + n / 16, en ? (word | mask) : (word & ~mask));
    if (rise)
      if (auto fn = callback(s, &lj_host::event)) fn(s->host->ctx, n);
    return true;
  }
  case Op::SaveRetained: {
    uint8_t &m = s->edge[b.c.slot];
    bool rise = en && !m;
    m = en;
    if (rise)
      if (auto fn = callback(s, &lj_host::save_data)) fn(s->host->ctx);
    return true;
  }
  default:
    return false; // no semantics: Interpreter::unimplemented() reports it
  }
}

} // namespace lj::interp

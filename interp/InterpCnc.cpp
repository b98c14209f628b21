// Interpreter semantics of family Cnc: chapter-6 CNC blocks on F/G words
// (hnc8-cnc-interface.md 2 and 3.1), by reading the program's profile's CNC table
// (TargetProfile::cncRows, ir/CncTable.h) at run time. Written plainly, word by word, as the
// oracle the lowering is checked against.
#include "interp/InterpreterInternal.h"
#include "ir/CncTable.h"

#include <cstdint>

namespace lj::interp {

namespace {

using cnc::Action;
using cnc::Do;
using cnc::Src;

bool fBit(const lj_state *s, int32_t w, int32_t b) {
  return ((static_cast<uint16_t>(s->img.F[w]) >> b) & 1u) != 0;
}

void setGBit(lj_state *s, int32_t w, int32_t b, bool on) {
  auto u = static_cast<uint16_t>(s->img.G[w]);
  auto m = static_cast<uint16_t>(1u << b);
  u = on ? static_cast<uint16_t>(u | m) : static_cast<uint16_t>(u & ~m);
  s->img.G[w] = static_cast<int16_t>(u);
}

void setGWord(lj_state *s, int32_t w, uint32_t v) {
  s->img.G[w] = static_cast<int16_t>(static_cast<uint16_t>(v & 0xFFFFu));
}

/// Value of a Write / Field / ModeSet source.
int32_t source(const BlockCall &b, const Action &a) {
  switch (a.src) {
  case Src::Operand:
    return readValue(b.s, b.ops[a.srcOp]);
  case Src::Const:
    return a.value;
  case Src::OneShl:
    return static_cast<int32_t>(1u << b.stmt.ops[a.srcOp].value);
  case Src::None:
    break;
  }
  return 0;
}

/// The 32-bit S value (F, low word first) scaled by the override in percent, then (SPDLBUS1) by
/// the gear's P block. All 64-bit arithmetic wraps (docs/cnc-blocks.md "SPDLBUS1").
bool spindleCommand(const BlockCall &b, const Action &a, int32_t sWord, int32_t ovrWord,
                    int64_t &cmd) {
  const lj_state *s = b.s;
  auto sval = static_cast<int32_t>(
      static_cast<uint32_t>(static_cast<uint16_t>(s->img.F[sWord])) |
      (static_cast<uint32_t>(static_cast<uint16_t>(s->img.F[sWord + 1])) << 16));
  cmd = static_cast<int64_t>(sval) * s->img.G[ovrWord] / 100; // |S * ovr| < 2^47: exact
  if (a.gearOp < 0) return true;
  const int64_t gear = readValue(b.s, b.ops[a.gearOp]);
  const int64_t blk = int64_t{b.stmt.ops[a.pOp].index} + 5 * (gear - 1);
  if (gear < 1 || blk + 4 >= LJ_P_COUNT) return false;
  const int64_t maxRpm = s->img.P[blk], num = s->img.P[blk + 3], den = s->img.P[blk + 4];
  if (den != 0) {
    auto prod = static_cast<int64_t>(static_cast<uint64_t>(cmd) * static_cast<uint64_t>(num));
    cmd = (prod == INT64_MIN && den == -1) ? INT64_MIN : prod / den;
  }
  if (maxRpm > 0) {
    const int64_t cap = maxRpm * 1000; // rpm -> 0.001 rpm
    cmd = cmd > cap ? cap : cmd < -cap ? -cap : cmd;
  }
  return true;
}

} // namespace

bool runCnc(const BlockCall &b) {
  const cnc::CncRow *row = b.tp.cncRow(b.c.op);
  const CncLayout &lay = b.tp.cnc;
  if (!row) return false;
  lj_state *s = b.s;
  const Stmt &st = b.stmt;
  const InstrInfo &info = instrInfo(b.c.op);

  // Word base of the row: axis A*80, channel 2560+C*80, or absolute (hnc8-cnc-interface.md 0).
  int32_t base = 0;
  bool valid = true;
  if (row->base == cnc::Base::Axis) {
    int32_t axis = readValue(s, b.ops[row->where]);
    valid = axis >= 0 && axis < lay.axes;
    base = valid ? axis * lay.blockWords : 0;
  } else if (row->base == cnc::Base::Channel) {
    base = lay.channelBase + st.ops[row->where].value * lay.blockWords;
  }

  if (info.stack == StackRule::Push) { // AXRDY: a status source pushed like a contact
    cnc::Resolved r = cnc::resolve(row->act[0], st);
    b.f.push(fBit(s, base + r.word, r.bit));
    return true;
  }

  const bool act = b.f.input();
  if (!valid) {
    // A runtime axis outside 0..31: nothing written; a block that would have written counts one
    // fault and gives output 0 (DIALECT.md 4, docs/cnc-blocks.md).
    bool writes = false;
    for (int i = 0; i < row->count; ++i) writes = writes || cnc::writesOn(row->act[i], act);
    if (writes) {
      ++s->fault_index;
      if (b.f.sp > 0) b.f.setTop(false);
    }
    return true;
  }

  bool cond = false;
  for (int i = 0; i < row->count; ++i) {
    const Action &a = row->act[i];
    const cnc::Resolved r = cnc::resolve(a, st);
    if (!r.applies) continue;
    const int32_t w = base + r.word;
    auto dirOn = [&] { return readBit(s, b.ops[a.dirOp]) == a.pol; };
    switch (a.what) {
    case Do::Level:
      setGBit(s, w, r.bit, act && (a.dirOp < 0 || dirOn()));
      break;
    case Do::Ack:
      setGBit(s, w, r.bit, act && fBit(s, base + r.auxWord, r.auxBit));
      break;
    case Do::Jog:
      s->img.G[w] = static_cast<int16_t>(act ? (dirOn() ? 1 : -1) : 0);
      break;
    case Do::Write: {
      if (!act) break;
      const int64_t v = source(b, a); // sign-extended into the upper words
      for (int k = 0; k < a.width; ++k)
        setGWord(s, w + k, static_cast<uint32_t>(static_cast<uint64_t>(v) >> (16 * k)));
      break;
    }
    case Do::Field: {
      if (!act) break;
      const uint32_t mask = ((1u << a.width) - 1u) << r.bit;
      const uint32_t v = static_cast<uint32_t>(source(b, a)) << r.bit;
      setGWord(s, w, (static_cast<uint16_t>(s->img.G[w]) & ~mask) | (v & mask));
      break;
    }
    case Do::Status:
      cond = fBit(s, w, r.bit);
      break;
    case Do::Push:
      break; // handled above
    case Do::ModeSet: {
      if (!act) break;
      const int32_t v = source(b, a);
      for (int k = 0; k < 7; ++k) {
        if (v != (1 << k)) continue;
        const int32_t hot = base + r.auxWord;
        setGWord(s, hot,
                 (static_cast<uint16_t>(s->img.G[hot]) & ~0x7Fu) | static_cast<uint32_t>(v));
        setGWord(s, w,
                 (static_cast<uint16_t>(s->img.G[w]) & ~0xFu) |
                     static_cast<uint32_t>(b.tp.modeCode[k]));
      }
      break; // 0, several bits or > 64: no request (docs/cnc-blocks.md)
    }
    case Do::ModeGet: {
      if (!act) break;
      const int32_t code = static_cast<uint16_t>(s->img.F[w]) & 0xF;
      int32_t v = 0;
      for (int k = 0; k < 7; ++k)
        if (b.tp.modeCode[k] == code) v = 1 << k;
      writeValue(s, b.ops[a.srcOp], v);
      break;
    }
    case Do::UserOut: {
      if (!act) break;
      const uint32_t u = static_cast<uint16_t>(s->img.F[w]) |
                         (static_cast<uint32_t>(static_cast<uint16_t>(s->img.F[w + 1])) << 16);
      Ref byte = b.ops[a.srcOp]; // Y or R: one byte per element, bit k -> byte k/8, bit k%8
      for (uint32_t k = 0; k < 4; ++k, ++byte.off)
        writeValue(s, byte, static_cast<int32_t>((u >> (8 * k)) & 0xFFu));
      break;
    }
    case Do::Spindle: {
      if (!act) break;
      int64_t cmd = 0;
      if (!spindleCommand(b, a, base + r.auxWord, base + r.aux2Word, cmd)) {
        ++s->fault_index; // gear outside its P blocks: nothing written, output 0
        if (b.f.sp > 0) b.f.setTop(false);
        break;
      }
      setGWord(s, w, static_cast<uint32_t>(static_cast<uint64_t>(cmd)));
      setGWord(s, w + 1, static_cast<uint32_t>(static_cast<uint64_t>(cmd) >> 16));
      break;
    }
    }
  }
  if (info.output == OutputRule::Compare) b.f.output(act && cond);
  return true;
}

} // namespace lj::interp

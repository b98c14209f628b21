// Internals of the reference interpreter shared by its files (Interpreter.cpp: decoding and
// entries; InterpFlow.cpp: dispatch, basic instructions, flow; InterpBlocks.cpp: function blocks;
// InterpData.cpp, InterpNc.cpp, InterpCnc.cpp: the families of ir/OpTable.h `Family`). Not part
// of the library's interface.
#pragma once

#include "interp/Interpreter.h"
#include "ir/Profile.h"
#include "ir/Program.h"
#include "ir/Trace.h"
#include "ladderjit/abi.h"

#include <array>
#include <cassert>
#include <cstddef>
#include <cstring>
#include <vector>

namespace lj::interp {

/// An operand decoded once: a constant, an element (read rule by width) or one bit.
struct Ref {
  enum class Kind : uint8_t { None, Const, U8, I16, I32, Bit, I8, U16 } kind = Kind::None;
  uint8_t mask = 0;  ///< Bit: mask inside the byte at `off`
  uint32_t off = 0;  ///< byte offset inside lj_state
  int32_t value = 0; ///< Const
};

/// One statement ready to run.
struct Code {
  Op op = Op::LoadTrue;
  Ref a, b, c;         ///< operands in table order (L/S operands are not decoded)
  int32_t target = -1; ///< JMP: its LBL; LOOP: its NEXT; CALL: index into subs
  int32_t slot = -1;   ///< edge / timer / counter / PLS-PLF-ALT slot, first inst_word
  int32_t wide = -1;   ///< non-core families: index of its WideRefs in Impl::wide
  int8_t force = -1;   ///< contacts: -1 not forced, else the forced value (ir/Forces.h)
};

/// The ST and MS stacks of one active scope. Entries are 0/1; top is [sp - 1].
struct Frame {
  uint8_t *st;
  uint8_t *ms;
  int32_t stCap, msCap;
  int32_t sp = 0, msp = 0;

  void clear() { sp = msp = 0; }
  void push(bool v) {
    assert(sp < stCap && "ST deeper than the verifier said");
    st[sp++] = v;
  }
  bool pop() {
    assert(sp > 0 && "ST underflow the verifier should have rejected");
    return st[--sp] != 0;
  }
  bool top() const {
    assert(sp > 0);
    return st[sp - 1] != 0;
  }
  void setTop(bool v) {
    assert(sp > 0);
    st[sp - 1] = v;
  }
  /// EN of a single-input block: ST0, or 1 (left rail) when ST is empty (DIALECT.md 3).
  bool input() const { return sp > 0 ? st[sp - 1] != 0 : true; }
  /// Output of a single-input block: replaces ST0, or is pushed when ST was empty.
  void output(bool v) {
    if (sp > 0)
      st[sp - 1] = v;
    else
      push(v);
  }
};

/// `o` decoded with the area facts of `tp` (the program's profile).
inline Ref decode(const TargetProfile &tp, const Operand &o) {
  Ref r;
  switch (o.kind) {
  case Operand::Kind::None:
    return r;
  case Operand::Kind::Const:
    r.kind = Ref::Kind::Const;
    r.value = o.value;
    return r;
  case Operand::Kind::Reg: {
    const AreaInfo &ai = tp.area(o.area);
    if (ai.bytes == 0) return r; // L, S: handled through StmtInfo::target
    const uint32_t bytes = o.width ? o.width : ai.bytes;
    r.kind = bytes == 1   ? (ai.isSigned ? Ref::Kind::I8 : Ref::Kind::U8)
             : bytes == 2 ? (ai.isSigned ? Ref::Kind::I16 : Ref::Kind::U16)
                          : Ref::Kind::I32;
    r.off = tp.elementOffset(o.area, o.index);
    return r;
  }
  case Operand::Kind::Bit: {
    r.kind = Ref::Kind::Bit;
    if (o.area == Area::Timer || o.area == Area::Counter) {
      // Tn.0 / Cn.0 read the output bit of the timer / counter (dialect-notes "Function blocks").
      int slot = tp.tcSlot(o.area, o.index);
      assert(slot >= 0 && o.bit == 0);
      r.off = o.area == Area::Timer
                  ? static_cast<uint32_t>(offsetof(lj_state, T) + slot * sizeof(lj_timer) +
                                          offsetof(lj_timer, out))
                  : static_cast<uint32_t>(offsetof(lj_state, C) + slot * sizeof(lj_counter) +
                                          offsetof(lj_counter, out));
      r.mask = 1;
      return r;
    }
    r.off = tp.elementOffset(o.area, o.index) + static_cast<uint32_t>(o.bit / 8);
    r.mask = static_cast<uint8_t>(1u << (o.bit % 8));
    return r;
  }
  }
  return r;
}

/// `o` decoded as a statement reads it: with `sync` (the statement reads the synchronized input
/// memory, ir/SyncInputs.h) an area that memory holds (FANUC X, F) is read from its copy.
inline Ref decode(const TargetProfile &tp, const Operand &o, bool sync) {
  Ref r = decode(tp, o);
  if (sync && (o.kind == Operand::Kind::Reg || o.kind == Operand::Kind::Bit))
    r.off = tp.syncReadOffset(o.area, r.off);
  return r;
}

/// The Neza function blocks %TMi / %Ci (InterpIec.cpp, docs/iec-il.md "Function blocks").
void iecTimer(lj_state *s, Frame &f, const Code &c);
void iecCounter(lj_state *s, Frame &f, const Code &c);

inline unsigned char *bytes(lj_state *s) { return reinterpret_cast<unsigned char *>(s); }

/// Read rule of DIALECT.md 1: X/Y/R zero-extend, F/G/W sign-extend, D/B/P as is.
inline int32_t readValue(lj_state *s, const Ref &r) {
  const unsigned char *p = bytes(s) + r.off;
  switch (r.kind) {
  case Ref::Kind::Const:
    return r.value;
  case Ref::Kind::U8:
    return *p;
  case Ref::Kind::I8:
    return static_cast<int8_t>(*p);
  case Ref::Kind::U16: {
    uint16_t v;
    std::memcpy(&v, p, sizeof v);
    return v;
  }
  case Ref::Kind::I16: {
    int16_t v;
    std::memcpy(&v, p, sizeof v);
    return v;
  }
  case Ref::Kind::I32: {
    int32_t v;
    std::memcpy(&v, p, sizeof v);
    return v;
  }
  case Ref::Kind::Bit:
    return (*p & r.mask) != 0;
  case Ref::Kind::None:
    break;
  }
  assert(false && "reading an operand that is not a value");
  return 0;
}

/// A write keeps the low 8/16/32 bits of the destination (DIALECT.md 1).
inline void writeValue(lj_state *s, const Ref &r, int32_t v) {
  unsigned char *p = bytes(s) + r.off;
  switch (r.kind) {
  case Ref::Kind::U8:
  case Ref::Kind::I8:
    *p = static_cast<uint8_t>(static_cast<uint32_t>(v) & 0xFFu);
    return;
  case Ref::Kind::U16:
  case Ref::Kind::I16: {
    uint16_t w = static_cast<uint16_t>(static_cast<uint32_t>(v) & 0xFFFFu);
    std::memcpy(p, &w, sizeof w);
    return;
  }
  case Ref::Kind::I32:
    std::memcpy(p, &v, sizeof v);
    return;
  default:
    assert(false && "writing an operand that is not a register");
  }
}

inline bool readBit(lj_state *s, const Ref &r) { return (bytes(s)[r.off] & r.mask) != 0; }

inline void writeBit(lj_state *s, const Ref &r, bool v) {
  unsigned char &b = bytes(s)[r.off];
  b = static_cast<unsigned char>(v ? (b | r.mask) : (b & ~r.mask));
}

// int32 two's-complement arithmetic without undefined behaviour (DIALECT.md 1).
inline int32_t wrap(uint32_t v) { return static_cast<int32_t>(v); }
inline int32_t addWrap(int32_t a, int32_t b) { return wrap(uint32_t(a) + uint32_t(b)); }
inline int32_t subWrap(int32_t a, int32_t b) { return wrap(uint32_t(a) - uint32_t(b)); }
inline int32_t mulWrap(int32_t a, int32_t b) { return wrap(uint32_t(a) * uint32_t(b)); }

/// Every operand of a non-core statement, decoded (index = operand position).
using WideRefs = Ref[kMaxOperands];

/// What a family implementation gets for one statement: the state, the scope's stacks, the
/// decoded statement (`ops` holds all its operands) and the verifier's facts.
struct BlockCall {
  lj_state *s;
  Frame &f;
  const Code &c;
  const Ref *ops;
  const Stmt &stmt;
  const StmtInfo &info;
  const TargetProfile &tp; ///< the program's profile
};

/// Family Data (InterpData.cpp): XMOV .. NTP. Each family runner returns false for an
/// instruction it has no semantics for (the catalogue completeness test checks none is left).
bool runData(const BlockCall &b);
/// Family Data, the FANUC transfer/search/conversion/flow operations (InterpFanucData.cpp).
bool runFanucData(const BlockCall &b);
/// Family Nc (InterpNc.cpp): MGET .. SAVEDATA.
bool runNc(const BlockCall &b);
/// Family Cnc (InterpCnc.cpp): the chapter-6 F/G blocks, MDST .. RSTCLR.
bool runCnc(const BlockCall &b);
/// Family PmcTc (InterpPmcTc.cpp): FANUC TMR .. RNGx.
bool runPmcTc(const BlockCall &b);
/// Family ClassicLadder (InterpClassicLadder.cpp): the scan clock and ClassicLadder's blocks.
bool runClassicLadder(const BlockCall &b);
/// Family PmcTc, the FANUC arithmetic ADDB..DIVB, ADD..DIV, NUME (InterpFanucArith.cpp).
bool runFanucArith(const BlockCall &b);

} // namespace lj::interp

namespace lj::interp {

/// How a statement range ended.
/// How a run of statements ended. JumpOut: a subroutine took a JumpOut (FANUC JMPC); the run
/// that holds Impl::jumpOutLabel goes on there, every other run returns JumpOut too.
enum class Flow { Done, Return, Watchdog, JumpOut };

/// Edge contact on memory m (DIALECT.md 3): updates m when it is the instance's own
/// (EdgePolicy::PerInstance); an object's previous-scan image (PerObject) is only read here.
inline bool edgeSample(lj_state *s, int32_t slot, bool cur, bool rising, bool update) {
  bool m = s->edge[slot] != 0;
  if (update) s->edge[slot] = cur;
  return rising ? (cur && !m) : (!cur && m);
}

} // namespace lj::interp

namespace lj {

struct Interpreter::Impl {
  const VerifiedProgram &prog;
  std::vector<interp::Code> code; ///< parallel to prog.stmts
  /// All decoded operands of the non-core statements (Code::wide indexes it).
  std::vector<std::array<interp::Ref, kMaxOperands>> wide;
  /// The last executed instruction that had no semantics (Op::Count_: none so far).
  Op unimplemented = Op::Count_;
  /// The label (statement index in the sliced part) of the JumpOut being taken (Flow::JumpOut).
  int32_t jumpOutLabel = -1;
  // Stacks: [0] is shared by the main parts, [1 + i] belongs to subroutine i.
  std::vector<std::vector<uint8_t>> stStore, msStore;
  /// EdgePolicy::PerInstance: edge contacts update their memory.
  bool edgeUpdates = true;
  /// EdgePolicy::PerObject: (slot, object bit) sampled at the end of every PLC1 run.
  std::vector<std::pair<int32_t, interp::Ref>> edgeImage;

  /// A traced build (ir/Trace.h): the buffer the statements record into, and where.
  int32_t *trace = nullptr;
  TraceLayout traceAt;

  /// The lj_timer of timer slot `slot` and the previous-input byte of PLS (`rise`) / PLF block
  /// `slot`, where the profile keeps them (TargetProfile::timerOffset / pulseOffset).
  lj_timer &timerAt(lj_state *s, int32_t slot) const {
    return *reinterpret_cast<lj_timer *>(reinterpret_cast<uint8_t *>(s) +
                                         prog.profile->timerOffset(slot));
  }
  uint8_t &pulseAt(lj_state *s, bool rise, int32_t slot) const {
    return reinterpret_cast<uint8_t *>(s)[prog.profile->pulseOffset(rise, slot)];
  }

  Impl(const VerifiedProgram &p, const ContactForces &forces, int32_t *traceBuf);
  interp::Frame frame(size_t scope);
  uint32_t runPart(lj_state *s, StmtRange range, int32_t startDepth);
  /// runT<true> when traced: the untraced loop has no trace code at all.
  interp::Flow run(lj_state *s, interp::Frame &f, int32_t begin, int32_t end) {
    return trace ? runT<true>(s, f, begin, end) : runT<false>(s, f, begin, end);
  }
  template <bool kTrace>
  interp::Flow runT(lj_state *s, interp::Frame &f, int32_t begin, int32_t end);
  /// The words of statement `pc` that are known after it ran (Box: output and values).
  void traceAfter(lj_state *s, const interp::Frame &f, int32_t pc);
  interp::Flow call(lj_state *s, int32_t sub);
  void block(lj_state *s, interp::Frame &f, const interp::Code &c);
};

} // namespace lj

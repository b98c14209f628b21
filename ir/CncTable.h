// The shape of a CNC interface table (issue 4 item 2): for each block of family Cnc, the F/G
// words and bits it touches and how, as data. A target profile holds its rows
// (TargetProfile::cncRows; HNC-8: profiles/hnc8/CncTable.cpp); the interpreter and the lowering
// both interpret them, so correcting a mapping is a one-line change in the profile
// (docs/cnc-blocks.md).
#pragma once

#include "ir/OpTable.h"
#include "ir/Program.h"

#include <cstdint>

namespace lj::cnc {

/// Where a row's words are counted from: axis A -> A*80, channel C -> 2560 + C*80 (A or C is
/// the row's `where` operand), System -> absolute word numbers.
enum class Base : uint8_t { Axis, Channel, System };

/// What one action does. ACT is the block's input (ST0, or 1 with an empty ST).
enum class Do : uint8_t {
  Level,   ///< G bit := ACT [and dir == pol when dirOp >= 0], on every execution (like OUT)
  Ack,     ///< G bit := ACT and F[aux].(auxBit + d), on every execution (d: see bitOp)
  Jog,     ///< G word := ACT ? (dir == pol ? +1 : -1) : 0, on every execution
  Write,   ///< when ACT: `width` G words (1, 2 or 4; little-endian, sign-extended) := source
  Field,   ///< when ACT: G bits [bit, bit + width) of one word := source (low bits)
  Status,  ///< condition := F bit; the row's output is ACT and the condition
  Push,    ///< push the F bit (a status source like a contact, no input)
  ModeSet, ///< when ACT and source is one-hot 1..64: G[aux].0-6 := it, G[word].0-3 := its code
  ModeGet, ///< when ACT: destination := one-hot of the code F[word].0-3 (0 if none)
  UserOut, ///< when ACT: 4 bytes from destination := the 32-bit F[word..word+1]
  Spindle, ///< when ACT: G[word+2sp] (32 bit) := S(F[aux+2sp]) * G[aux2+sp] / 100 [gear scaled]
};

/// Source of a Write / Field / ModeSet value.
enum class Src : uint8_t {
  None,
  Operand, ///< operand srcOp, read by the area's read rule (or the constant)
  Const,   ///< `value`
  OneShl,  ///< 1 << (constant operand srcOp)
};

/// One action of a row. Word numbers are relative to the row's base unless Base::System.
struct Action {
  Do what;
  int16_t word;       ///< G word (setters) or F word (Status, Push, ModeGet, UserOut)
  int8_t bit = 0;     ///< bit of `word` (Level, Ack, Field first bit, Status, Push)
  int8_t width = 1;   ///< Write: words; Field: bits
  int8_t wordOp = -1; ///< constant operand added to `word` (SPDLOVRD's spindle)
  /// Constant operand selecting the bit: bit index = bit + (value - lo) counted across words
  /// (word += index / 16); the action applies only when lo <= value <= hi.
  int8_t bitOp = -1;
  int32_t lo = 0, hi = 0;
  Src src = Src::None;
  int8_t srcOp = -1; ///< Src::Operand / OneShl; ModeGet / UserOut: the destination operand
  int32_t value = 0; ///< Src::Const
  int8_t dirOp = -1; ///< bit operand of Level / Jog
  bool pol = true;   ///< the dir value that means "on" (Level) or "+" (Jog)
  int16_t aux = 0;   ///< Ack: F word; ModeSet: one-hot G word; Spindle: F word of S
  int8_t auxBit = 0; ///< Ack: F bit
  int16_t aux2 = 0;  ///< Spindle: G word of the override
  int8_t spOp = -1;  ///< Spindle: constant spindle operand
  int8_t gearOp = -1, pOp = -1; ///< Spindle: gear operand and P block (SPDLBUS1), else -1
};

constexpr int kMaxActions = 3;

/// One block: its base, the operand naming the axis / channel, and its actions in order.
struct CncRow {
  Op op;
  Base base;
  int8_t where;    ///< operand holding the axis / channel number (-1 for System)
  bool documented; ///< the manual names the register (else inferred, hnc8-cnc-interface.md 2)
  uint8_t count;
  Action act[kMaxActions];
  const char *effect; ///< one line for docs/cnc-blocks.md
};

/// An action's constant word and bit for one statement (the base is added by the engine).
struct Resolved {
  bool applies = true;  ///< false: the bit operand is outside [lo, hi]
  int32_t word = 0;     ///< relative to the base (absolute for Base::System)
  int32_t bit = 0;      ///< 0..15
  int32_t auxWord = 0;  ///< Ack: F word; Spindle: F word of S
  int32_t auxBit = 0;   ///< Ack: F bit
  int32_t aux2Word = 0; ///< Spindle: override word
};
Resolved resolve(const Action &a, const Stmt &s);

/// Whether `a` writes on an execution with input `act` (decides whether a bad runtime axis
/// counts a fault).
inline bool writesOn(const Action &a, bool act) {
  switch (a.what) {
  case Do::Level:
  case Do::Ack:
  case Do::Jog:
    return true;
  case Do::Status:
  case Do::Push:
    return false;
  default:
    return act;
  }
}

/// Whether row `r` reads its axis at run time (a register operand) in statement `s`.
inline bool runtimeAxis(const CncRow &r, const Stmt &s) {
  return r.base == Base::Axis && s.ops[r.where].kind != Operand::Kind::Const;
}

} // namespace lj::cnc

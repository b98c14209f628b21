// The builders the op table's row files use (OpRows*.h, assembled in OpTable.cpp): operand
// positions by role and area, and the ROW / ROWX macros of one InstrInfo. Internal to ir/: only
// the row files and OpTable.cpp include it; everyone else reads the table through OpTable.h.
#pragma once

#include "ir/OpTable.h"

#include <cstdint>

namespace lj::oprows {

inline constexpr int64_t kI32Min = INT32_MIN;
inline constexpr int64_t kI32Max = INT32_MAX;

// Operand position builders.
constexpr OperandSpec bitRead(const char *role) {
  return {role, kContactAreas, true, false, 0, 0, false};
}
constexpr OperandSpec bitWrite(const char *role) {
  return {role, kCoilAreas, true, false, 0, 0, true};
}
constexpr OperandSpec src(const char *role) {
  return {role, kSrcAreas, false, true, kI32Min, kI32Max, false};
}
constexpr OperandSpec dst(const char *role) { return {role, kDstAreas, false, false, 0, 0, true}; }
/// Read and written in place (INC, DEC, NEG): the destination areas.
constexpr OperandSpec inout(const char *role) { return dst(role); }
constexpr OperandSpec konst(const char *role, int64_t lo, int64_t hi) {
  return {role, 0, false, true, lo, hi, false};
}
constexpr OperandSpec label() { return {"label", areas(Area::Label), false, false, 0, 0, false}; }
constexpr OperandSpec sub() {
  return {"subroutine", areas(Area::Subroutine), false, false, 0, 0, false};
}
constexpr OperandSpec preset() {
  return {"preset", areas(Area::Relay, Area::Word, Area::DWord, Area::Retained, Area::Param),
          false,    true,
          kI32Min,  kI32Max,
          false};
}
constexpr OperandSpec none() { return {nullptr, 0, false, false, 0, 0, false}; }

// Builders of the data, NC and CNC rows.
inline constexpr AreaMask kIndirectAreas =
    areas(Area::NcControl, Area::Relay, Area::Word, Area::DWord, Area::Retained);
inline constexpr AreaMask kBitSrcAreas =
    areas(Area::Input, Area::Output, Area::NcStatus, Area::NcControl, Area::Relay, Area::Word,
          Area::DWord, Area::Param, Area::Retained);
/// A register (never a constant) from `mask`.
constexpr OperandSpec reg(const char *role, AreaMask mask, bool writes) {
  return {role, mask, false, false, 0, 0, writes};
}
/// A constant or a register from `mask`, written by the instruction when `writes`.
constexpr OperandSpec regOrConst(const char *role, AreaMask mask, bool writes) {
  return {role, mask, false, true, kI32Min, kI32Max, writes};
}
constexpr OperandSpec i32Const(const char *role) { return konst(role, kI32Min, kI32Max); }
constexpr OperandSpec bitDir(const char *role) {
  return {role, kBitSrcAreas, true, false, 0, 0, false};
}
/// ZRST bounds: a bit address or a whole register of a writable area.
constexpr OperandSpec zoneBound(const char *role) {
  return {role, kDstAreas, true, false, 0, 0, true, true};
}
constexpr OperandSpec chan() { return konst("channel", 0, 3); }
constexpr OperandSpec axis() { return konst("axis", 0, 31); }
constexpr OperandSpec spindle() { return konst("spindle", 0, 3); }
/// A constant 0..31 or any readable register holding the axis number.
constexpr OperandSpec axisAny() { return {"axis", kSrcAreas, false, true, 0, 31, false}; }
constexpr OperandSpec gear() {
  return regOrConst(
      "gear",
      areas(Area::Output, Area::NcControl, Area::Relay, Area::Word, Area::DWord, Area::Retained),
      false);
}
constexpr OperandSpec pblock() { return reg("parameter block", areas(Area::Param), false); }
/// `s` touching `n` consecutive elements (OperandSpec::span).
constexpr OperandSpec spanning(OperandSpec s, uint8_t n) {
  s.span = n;
  return s;
}
/// `s` accepting only the constants in `v` (OperandSpec::values).
constexpr OperandSpec onlyValues(OperandSpec s, std::span<const ValueRange> v) {
  s.values = v;
  return s;
}
/// Alarms 1..256 (G3010-3025) and prompts 501..884 (G3056-3079; hnc8-cnc-interface.md 2).
inline constexpr ValueRange kAlarmNumbers[] = {{1, 256}, {501, 884}};
/// A FANUC data length (ROTB's format): 1, 2 or 4 bytes.
inline constexpr ValueRange kDataLengths[] = {{1, 2}, {4, 4}};

// Timer/counter numbers are constants 0..427; the gap 128..299 is rejected by the verifier.
constexpr OperandSpec tcNumber(const char *role) { return konst(role, 0, 427); }

using SR = StackRule;
using IR = InputRule;
using OR_ = OutputRule;
using SK = StateKind;

#define ROW(op, fam, stack, in, k, out, st, n, o0, o1, o2, o3, text)                               \
  InstrInfo {                                                                                      \
    Op::op, #op, Family::fam, SR::stack, IR::in, k, OR_::out, SK::st, n, {o0, o1, o2, o3}, text    \
  }

// Rows with more than four operands.
#define ROWX(op, fam, stack, in, k, out, st, n, text, ...)                                         \
  InstrInfo {                                                                                      \
    Op::op, #op, Family::fam, SR::stack, IR::in, k, OR_::out, SK::st, n, {__VA_ARGS__}, text       \
  }

} // namespace lj::oprows

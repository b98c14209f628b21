// Neza objects as IEC IL writes them (modicon-neza.md 1): `%I0.1`, `%Q1.5`, `%M12`, `%S1`,
// `%MW5`, `%MW5:X3`, `%KW2`, `%SW30`, `%L6`, `SR5`, constants; each as an IR operand on the
// profile's layout (profiles/iec/IecProfile.h) and back.
#pragma once

#include "ir/Program.h"

#include <optional>
#include <string>
#include <string_view>

namespace lj::iec {

/// What kind of Neza object an operand is (the instruction tables' operand columns).
enum class ObjClass : uint8_t {
  Immediate, ///< 0 / 1 (bit instructions) or a word constant
  InputBit,  ///< %Ii.j
  OutputBit, ///< %Qi.j
  MemoryBit, ///< %Mi
  SystemBit, ///< %Si
  WordBit,   ///< %MWi:Xk, %KWi:Xk, %SWi:Xk (%KW read-only)
  Word,      ///< %MWi, %SWi
  ConstWord, ///< %KWi
  Label,     ///< %Li
  Sub,       ///< SRi
  Timer,     ///< %TMi (BLK %TMi, IN %TMi); op: its first word
  Counter,   ///< %Ci (BLK %Ci, CU %Ci ...); op: its first word
  BlockBit,  ///< %TMi.Q, %Ci.E, %Ci.D, %Ci.F: read-only (L1133-1159)
  BlockWord, ///< %TMi.V, %Ci.V (read-only), %TMi.P, %Ci.P (writable, 0..9999)
};

struct Object {
  ObjClass cls = ObjClass::Immediate;
  int32_t number = 0;    ///< %Mi: i; %Ii.j: i * 16 + j; words, blocks: i
  bool writable = false; ///< BlockWord: the preset %TMi.P / %Ci.P
  Operand op;            ///< the IR operand (loc not set)
};

/// Parse one object (case-insensitive, leading zeros accepted). Fails with `error` naming the
/// problem ("%I4.0: unit 4 is out of range (0..3)").
std::optional<Object> parseObject(std::string_view text, std::string &error);

/// `op` as IEC IL text (`%I0.1`, `%M40`, `%MW5:X3`, `%L6`, `SR5`, `12`); the scratch bits of
/// the front end's expansions print as `%~n`.
std::string formatOperand(const Operand &op);

} // namespace lj::iec

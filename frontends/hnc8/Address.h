// The HNC-8 address syntax (DIALECT.md 1, docs/dialect-notes.md "Text"): an area letter, a
// decimal element number and an optional `.bit` (`X10.3`, `d05`, `T300.0`). The one lexer the
// STL parser, the symbol table's address check and the command line (formats/Address.h) share.
#pragma once

#include "ir/Area.h"
#include "ir/SymbolTable.h"

#include <cstdint>
#include <string>
#include <string_view>

namespace lj::hnc8 {

/// An address as written, lexed but not checked against the profile: numbers saturate far
/// above any index (kSaturated), so a huge one is "out of range", never wrapped.
struct AddressText {
  /// Ok, or the first part that is not there: the area letter, the element number (digits,
  /// then the end or `.`), or the bit number (digits to the end after `.`).
  enum class Lex : uint8_t { Ok, NoArea, NoIndex, NoBit } lex = Lex::Ok;
  Area area = Area::None;
  int64_t index = 0;
  int64_t bit = -1; ///< -1: no `.bit`
};

/// The value numbers saturate at.
inline constexpr int64_t kSaturated = int64_t{1} << 40;

/// Decimal digits of `t` from `pos` (advanced past them), saturating at kSaturated; false when
/// there are none.
bool readDecimal(std::string_view t, size_t &pos, int64_t &value);

/// Lex `t` as an HNC-8 address (area letters case-insensitive, leading zeros accepted).
AddressText lexAddress(std::string_view t);

/// Canonical text of an HNC-8 operand address (`x010.3` -> `X10.3`), or empty with `error` set
/// when `text` is not a valid address (area letter, index range, bit number).
std::string canonicalAddress(std::string_view text, std::string &error);

/// HNC-8 specification: "symbol names 1000 entries"; names and comments in bytes (a UTF-8 CJK
/// character takes 3).
inline constexpr size_t kMaxSymbols = 1000;
inline constexpr size_t kMaxNameBytes = 64;
inline constexpr size_t kMaxCommentBytes = 256;

/// The rules of an HNC-8 symbol table (the limits above, canonicalAddress).
const SymbolRules &symbolRules();

} // namespace lj::hnc8

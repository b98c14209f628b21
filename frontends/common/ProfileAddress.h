// The address syntax of a profile-laid dialect (FANUC PMC): the area's name as the profile
// spells it (case-insensitive), the element number, then `.bit` or, on the command line,
// `:width` (`R100`, `F0.3`, `D100:4`). The one lexer the FANUC parser, its symbol rules and the
// command line (formats/Address.h parseProfileAddress) share; each says what is wrong its way.
#pragma once

#include "ir/Area.h"
#include "ir/Profile.h"

#include <cstdint>
#include <string_view>

namespace lj::frontend {

/// An address as written, lexed but not checked against the area's ranges. Numbers saturate at
/// 2^40, far above any index, so a huge one is "out of range", never wrapped.
struct ProfileAddressText {
  /// Ok, or the first part that is not there: the area name (the text before the first digit
  /// or `.` names no area), the element number (digits, then the end, `.` or `:`), the bit
  /// number (digits to the end after `.`), the width (`1`, `2` or `4` to the end after `:`).
  enum class Lex : uint8_t { Ok, NoArea, NoIndex, NoBit, NoWidth } lex = Lex::Ok;
  Area area = Area::None;
  size_t nameEnd = 0; ///< where the area name ends in the text
  int64_t index = 0;
  int64_t bit = -1; ///< -1: no `.bit`
  int width = 0;    ///< 0: no `:width`
  char sep = 0;     ///< '.', ':' or 0: what follows the element number
};

/// Lex `t` as an address of `tp`'s areas.
ProfileAddressText lexProfileAddress(const TargetProfile &tp, std::string_view t);

} // namespace lj::frontend

// Memory areas of the HNC-8 process image: letters, element counts, widths and signedness.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

namespace lj {

/// One memory area (DIALECT.md section 1). The order is the order of AreaMask bits.
enum class Area : uint8_t {
  Input,      ///< X
  Output,     ///< Y
  NcStatus,   ///< F
  NcControl,  ///< G
  Relay,      ///< R
  Word,       ///< W
  DWord,      ///< D
  Retained,   ///< B
  Param,      ///< P
  Timer,      ///< T
  Counter,    ///< C
  Label,      ///< L
  Subroutine, ///< S
  None
};

constexpr int kAreaCount = 13;

using AreaMask = uint16_t;
constexpr AreaMask bit(Area a) { return static_cast<AreaMask>(1u << static_cast<unsigned>(a)); }
template <typename... A> constexpr AreaMask areas(A... a) { return (bit(a) | ... | 0); }
constexpr bool hasArea(AreaMask m, Area a) { return (m & bit(a)) != 0; }

/// Static facts about one area.
struct AreaInfo {
  char letter;
  int32_t count; ///< elements when contiguous from 0 (T/C: see validIndex)
  uint8_t bytes; ///< element width in bytes (0 for T/C/L/S)
  bool isSigned; ///< read rule: sign-extend (true) or zero-extend (false)
  bool writable; ///< writable by ordinary program instructions
};

const AreaInfo &areaInfo(Area a);

/// Area named by a letter (case-insensitive), if any.
std::optional<Area> areaFromLetter(char c);

/// Whether element `n` exists in area `a` (T/C have the gap 128..299; L 0..9999; S 0..511).
bool validIndex(Area a, int64_t n);

/// Byte offset of element 0 of a numeric area (X Y F G R W D B P) inside lj_state (abi.h); 0
/// for the other areas. Element n is at stateOffset(a) + n * areaInfo(a).bytes.
uint32_t stateOffset(Area a);

/// Number of bits of one element (8, 16, 32), or 1 for T/C whose only bit is .0.
int bitWidth(Area a);

} // namespace lj

// Memory areas by role (the core never names a dialect letter) and the per-area facts a target
// profile gives for each (read through a profile: ir/Profile.h TargetProfile::area() and friends;
// the HNC-8 values are in profiles/hnc8/Areas.cpp).
#pragma once

#include <cstdint>

namespace lj {

/// One memory area by what it holds (DIALECT.md section 1 lists HNC-8's). The order is the order
/// of AreaMask bits.
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

/// Static facts about one area, as the target profile gives them.
struct AreaInfo {
  char letter;   ///< how the dialect writes it (one letter for HNC-8)
  int32_t count; ///< elements when contiguous from 0 (timers/counters: see validIndex)
  uint8_t bytes; ///< element width in bytes (0 for timer/counter/label/subroutine areas)
  bool isSigned; ///< read rule: sign-extend (true) or zero-extend (false)
  bool writable; ///< writable by ordinary program instructions
  bool bitAddressable = false; ///< `A12.3` bit addresses accepted (contacts, coils)
  uint32_t offset = 0;         ///< byte offset of element 0 inside lj_state (numeric areas)
};

} // namespace lj

// Memory areas by role (the core never names a dialect letter) and the per-area facts a target
// profile gives for each (read through a profile: ir/Profile.h TargetProfile::area() and friends;
// the HNC-8 values are in profiles/hnc8/Areas.cpp, FANUC's in profiles/fanuc/Areas.cpp).
#pragma once

#include <cstdint>

namespace lj {

/// One memory area by what it holds (DIALECT.md section 1 lists HNC-8's; a role a target does
/// not have has count 0 in its profile). The order is the order of AreaMask bits.
enum class Area : uint8_t {
  Input,       ///< machine -> PLC inputs
  Output,      ///< PLC -> machine outputs
  NcStatus,    ///< NC -> PLC signals
  NcControl,   ///< PLC -> NC signals
  Relay,       ///< internal relays (system relays included where the target puts them there)
  Word,        ///< 16-bit registers
  DWord,       ///< 32-bit registers
  Retained,    ///< retained registers
  Param,       ///< parameters (read-only to the program)
  Timer,       ///< timer number space (contacts read the output bit)
  Counter,     ///< counter number space
  Label,       ///< jump labels
  Subroutine,  ///< subroutine numbers
  KeepRelay,   ///< keep relays (nonvolatile bits)
  ExtraRelay,  ///< extra relays
  MessageBits, ///< message request / status bits
  TimerData,   ///< timer presets and time-base settings as data
  CounterData, ///< counter presets and current values as data
  DataTable,   ///< the data table (nonvolatile bytes)
  SystemBits,  ///< system bits written by the runtime
  SystemWords, ///< system words written by the runtime
  ConstWords,  ///< constant words (read-only to the program)
  None
};

constexpr int kAreaCount = 22;

using AreaMask = uint32_t;
constexpr AreaMask bit(Area a) { return static_cast<AreaMask>(1u << static_cast<unsigned>(a)); }
template <typename... A> constexpr AreaMask areas(A... a) { return (bit(a) | ... | 0); }
constexpr bool hasArea(AreaMask m, Area a) { return (m & bit(a)) != 0; }

/// Static facts about one area, as the target profile gives them.
struct AreaInfo {
  const char *name; ///< how the dialect writes it ("X" for HNC-8 and FANUC, "%MW" for IEC)
  int32_t count;    ///< elements when contiguous from 0 (timers/counters: see validIndex)
  uint8_t bytes;    ///< element width in bytes (0 for timer/counter/label/subroutine areas)
  bool isSigned;    ///< read rule: sign-extend (true) or zero-extend (false)
  bool writable;    ///< writable by ordinary program instructions
  bool bitAddressable = false; ///< `A12.3` bit addresses accepted (contacts, coils)
  uint32_t offset = 0;         ///< byte offset of element 0 inside lj_state (numeric areas)
  /// A second range of element numbers [upperLo, upperLo + upperCount) laid out right after the
  /// first `count` elements (FANUC T9000.., C5000..). 0: none.
  int32_t upperLo = 0;
  int32_t upperCount = 0;
  /// The lowest element number of the first range (FANUC labels and subroutines start at 1:
  /// L1, P1); elements below it do not exist.
  int32_t first = 0;
};

} // namespace lj

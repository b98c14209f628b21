// The target profile: everything the core (verify/, interp/, lowering/, the generator) needs to
// know about a target that is not an operation's meaning. One value per target (HNC-8:
// profiles/hnc8/Areas.cpp; all of them: profiles/Profiles.h). A program carries the profile it
// was written for (ParsedProgram::profile, VerifiedProgram::profile): the core reads area facts
// through it, never through a global.
#pragma once

#include "ir/Area.h"
#include "ir/CncTable.h"
#include "ir/OpTable.h"

#include "ladderjit/abi.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

namespace lj {

/// An inclusive range of numbers (timer numbers, retentive counters...).
struct NumberRange {
  int32_t lo = 0, hi = -1;
  constexpr bool contains(int64_t n) const { return n >= lo && n <= hi; }
};

/// Who owns an edge memory: each instruction instance (HNC-8: two LDP X1.0 see the same edge
/// independently; the contact updates its memory on every execution), or the addressed object
/// (IEC IL: two LDR %M5 in one scan share it). PerObject: one slot per object
/// (VerifiedProgram::edgeObjects), the previous-scan image, which the engines sample at the end of
/// every run of the cyclic part; an edge contact compares the object with it and writes nothing.
enum class EdgePolicy : uint8_t { PerInstance, PerObject };

/// One program part in execution order: its end marker and how it is scheduled.
struct PartSpec {
  const char *role; ///< "init", "cyclic", "sliced"
  Op endMarker;     ///< the operation that ends it
  enum class Schedule : uint8_t { Once, EveryTick, Sliced } schedule;
};

/// The CNC interface words (hnc8-cnc-interface.md 0, 1.3, 1.4): per-axis / per-channel blocks of
/// F/G words and the channel words the NC services use.
struct CncLayout {
  int32_t blockWords;    ///< words per axis or channel block
  int32_t channelBase;   ///< first channel word
  int32_t axes;          ///< axis blocks
  int32_t channels;      ///< channel blocks
  int32_t mCodeWord;     ///< FC/GC word of the first M-code slot
  int32_t mCodeSlots;    ///< M-code slots per channel
  int32_t tCodeWord;     ///< FC/GC word of the T code
  int32_t partCountWord; ///< GC word of the part count
};

/// A system bit the runtime writes before every tick (FANUC R9091 / R9015, IEC %S): where it is
/// and what it holds. hosts/SystemBits.h applies a profile's list.
struct SystemBit {
  enum class Kind : uint8_t {
    Zero,      ///< always 0
    One,       ///< always 1 (also "running": the program runs whenever a tick runs)
    FirstScan, ///< 1 during the first tick after power-up / start, else 0
    Clock,     ///< 1 for halfPeriodMs, then 0 for halfPeriodMs, from now_ms = 0
  };
  uint32_t offset; ///< byte inside lj_state
  uint8_t bit;     ///< bit 0..7 of that byte
  Kind kind;
  uint32_t halfPeriodMs = 0; ///< Clock
};

struct TargetProfile {
  const char *name;                               ///< "hnc8"
  std::array<AreaInfo, kAreaCount + 1> areas;     ///< by Area (Area::None last)
  std::array<NumberRange, 2> timerNumbers;        ///< valid timer numbers
  std::array<NumberRange, 2> counterNumbers;      ///< valid counter numbers
  std::array<int64_t, 4> timerUnitMs;             ///< timer unit code -> milliseconds
  AreaMask retentiveAreas;                        ///< kept across power-off
  NumberRange retentiveTimers, retentiveCounters; ///< kept across power-off
  std::array<PartSpec, 3> parts;                  ///< in execution order
  int32_t maxStatements;                          ///< program size limit
  int32_t maxCallDepth;                           ///< nesting of calls
  int32_t defaultSliceStatements;                 ///< statements per tick of the sliced part
  int32_t maxStackDepth;                          ///< ST entries (0 = unbounded)
  int32_t maxBranchDepth;                         ///< MS entries (0 = unbounded)
  EdgePolicy edgePolicy;
  CncLayout cnc;
  std::span<const char *const> hostServices; ///< lj_host callbacks the target may call
  /// CNC interface rows, one per family-Cnc Op in Op order (empty: the target has none).
  std::span<const cnc::CncRow> cncRows;
  /// Mode code (F/G channel word bits 0-3) of one-hot mode bit i (ModeSet / ModeGet actions).
  std::array<int32_t, 7> modeCode;
  /// System bits the runtime writes before every tick (empty: none).
  std::span<const SystemBit> systemBits;
  /// Where timer slots (lj_timer records) and PLS / PLF block slots (one byte each) live. All
  /// zero (HNC-8, IEC): lj_state.T with LJ_TC_SLOTS slots and pls_prev / plf_prev with
  /// LJ_BLOCK_SLOTS. A profile with more numbers than abi.h's arrays (FANUC: TMRB 1..500, DIFU /
  /// DIFD 1..1000) keeps them at these byte offsets of lj_state (inside lj_state.mem) instead.
  struct BlockState {
    uint32_t timers = 0;    ///< lj_state offset of timer slot 0 (0: lj_state.T)
    int32_t timerSlots = 0; ///< slots there
    uint32_t rise = 0;      ///< lj_state offset of rising-edge (PLS) slot 0 (0: pls_prev)
    uint32_t fall = 0;      ///< lj_state offset of falling-edge (PLF) slot 0 (0: plf_prev)
    int32_t pulseSlots = 0; ///< slots of each
  } blockState{};
  /// The synchronized input memory of the sliced part (FANUC level 2, ref 4.1): when the sliced
  /// part is divided (more than one slice), the engines copy the `bytes` bytes of lj_state at
  /// `from` to `copy` right before slice 0 runs, i.e. at the start of every scan of the sliced
  /// part, and every read of an area in `areas` by a statement of the sliced part or of a
  /// subroutine reads the copy (offset - from + copy) instead of the live bytes. The every-tick
  /// part keeps reading live inputs. All zero (HNC-8, IEC): none.
  struct SyncInputs {
    AreaMask areas = 0;
    uint32_t from = 0, copy = 0, bytes = 0;
  } syncInputs{};
  /// System parameters the host writes into lj_state at power-up (from --params) and the
  /// engines read at run time: byte offsets, 0 = the target has none.
  struct SystemParams {
    /// Counter data type of CTR (FANUC ref 6.4, "chosen globally on the system parameter
    /// screen"): the byte is 0 for binary, 1 for BCD (kCounterBcd).
    uint32_t counterFormat = 0;
  } systemParams{};
  static constexpr uint8_t kCounterBinary = 0, kCounterBcd = 1;

  /// Where a read of element `n` of area `a` at lj_state offset `off` goes when the reader
  /// reads the synchronized input memory (SyncInputs): the copy for an area the memory holds,
  /// `off` itself otherwise.
  constexpr uint32_t syncReadOffset(Area a, uint32_t off) const {
    return hasArea(syncInputs.areas, a) ? off - syncInputs.from + syncInputs.copy : off;
  }

  /// The facts of area `a`.
  constexpr const AreaInfo &area(Area a) const { return areas[static_cast<int>(a)]; }

  /// Area the dialect writes as the one-letter name `c` (case-insensitive), if any.
  constexpr std::optional<Area> areaFromLetter(char c) const {
    const char t[2] = {c, 0};
    return areaFromName(std::string_view(t, 1));
  }

  /// Area the dialect writes as `n` (ASCII case-insensitive, "X", "%MW"), if any.
  constexpr std::optional<Area> areaFromName(std::string_view n) const {
    auto up = [](char c) { return c >= 'a' && c <= 'z' ? static_cast<char>(c - 'a' + 'A') : c; };
    for (int i = 0; i < kAreaCount; ++i) {
      std::string_view an = areas[i].name ? std::string_view(areas[i].name) : std::string_view();
      if (an.empty() || an.size() != n.size() || areas[i].count <= 0) continue;
      bool same = true;
      for (size_t k = 0; k < n.size() && same; ++k) same = up(an[k]) == up(n[k]);
      if (same) return static_cast<Area>(i);
    }
    return std::nullopt;
  }

  /// Whether element `n` exists in area `a` (timers/counters: the number spaces).
  constexpr bool validIndex(Area a, int64_t n) const {
    if (n < 0) return false;
    if (a == Area::Timer || a == Area::Counter) return tcSlot(a, n) >= 0;
    const AreaInfo &i = area(a);
    return (n >= i.first && n < i.count) ||
           (i.upperCount > 0 && n >= i.upperLo && n < int64_t(i.upperLo) + i.upperCount);
  }

  /// Whether elements n .. n + len - 1 all exist in one range of area `a` (a multi-byte access).
  constexpr bool validSpan(Area a, int64_t n, int64_t len) const {
    if (len <= 0 || !validIndex(a, n) || !validIndex(a, n + len - 1)) return false;
    const AreaInfo &i = area(a);
    return (n < i.count) == (n + len - 1 < i.count);
  }

  /// Byte offset of element 0 of a numeric area inside lj_state (abi.h); 0 for the other
  /// areas. Element n is at elementOffset(a, n).
  constexpr uint32_t stateOffset(Area a) const { return area(a).offset; }

  /// Byte offset inside lj_state of element `n` (a valid index) of numeric area `a`: the upper
  /// range (AreaInfo::upperLo) follows the first `count` elements.
  constexpr uint32_t elementOffset(Area a, int64_t n) const {
    const AreaInfo &i = area(a);
    int64_t k = n < i.count ? n : i.count + (n - i.upperLo);
    return i.offset + static_cast<uint32_t>(k) * i.bytes;
  }

  /// Timer (a == Area::Timer) or counter slot of number n: its position in the concatenated
  /// number ranges (HNC-8: abi.h lj_tc_slot), or -1 when n is not a valid number.
  constexpr int tcSlot(Area a, int64_t n) const {
    int base = 0;
    for (const NumberRange &r : a == Area::Timer ? timerNumbers : counterNumbers) {
      if (r.contains(n)) return base + static_cast<int>(n - r.lo);
      base += r.hi - r.lo + 1;
    }
    return -1;
  }

  /// The number of slot k (inverse of tcSlot), or -1.
  constexpr int64_t tcNumber(Area a, int k) const {
    for (const NumberRange &r : a == Area::Timer ? timerNumbers : counterNumbers) {
      if (k <= r.hi - r.lo) return r.lo + k;
      k -= r.hi - r.lo + 1;
    }
    return -1;
  }

  /// Number of bits of one element (8, 16, 32), or 1 for timers/counters whose only bit is .0.
  constexpr int bitWidth(Area a) const {
    if (a == Area::Timer || a == Area::Counter) return 1;
    return area(a).bytes * 8;
  }

  /// Timer slots of the profile (lj_state.T or BlockState::timers).
  constexpr int timerSlots() const {
    return blockState.timers ? blockState.timerSlots : LJ_TC_SLOTS;
  }
  /// Byte offset inside lj_state of the lj_timer of timer slot `slot` (< timerSlots()).
  constexpr uint32_t timerOffset(int slot) const {
    return (blockState.timers ? blockState.timers : static_cast<uint32_t>(offsetof(lj_state, T))) +
           static_cast<uint32_t>(slot) * static_cast<uint32_t>(sizeof(lj_timer));
  }
  /// PLS / PLF block slots of the profile (lj_state.pls_prev or BlockState::rise).
  constexpr int pulseSlots() const {
    return blockState.rise ? blockState.pulseSlots : LJ_BLOCK_SLOTS;
  }
  /// Byte offset inside lj_state of the previous-input byte of PLS (`rise`) or PLF block `slot`.
  constexpr uint32_t pulseOffset(bool rise, int slot) const {
    const uint32_t base =
        rise ? (blockState.rise ? blockState.rise
                                : static_cast<uint32_t>(offsetof(lj_state, pls_prev)))
             : (blockState.fall ? blockState.fall
                                : static_cast<uint32_t>(offsetof(lj_state, plf_prev)));
    return base + static_cast<uint32_t>(slot);
  }

  /// The CNC row of `op`, or nullptr when `op` is not driven by the table.
  const cnc::CncRow *cncRow(Op op) const {
    if (opFamily(op) != Family::Cnc) return nullptr;
    const size_t i = static_cast<size_t>(op) - static_cast<size_t>(Op::ChannelModeSet);
    return i < cncRows.size() ? &cncRows[i] : nullptr;
  }
};

} // namespace lj

// The target profile: everything the core (verify/, interp/, lowering/, the generator) needs to
// know about a target that is not an operation's meaning. One value per target; the linked
// profile library implements targetProfile() (HNC-8: profiles/hnc8/Areas.cpp).
#pragma once

#include "ir/Area.h"
#include "ir/OpTable.h"

#include <array>
#include <cstdint>
#include <span>

namespace lj {

/// An inclusive range of numbers (timer numbers, retentive counters...).
struct NumberRange {
  int32_t lo = 0, hi = -1;
  constexpr bool contains(int64_t n) const { return n >= lo && n <= hi; }
};

/// Who owns an edge memory: each instruction instance (HNC-8: two LDP X1.0 see the same edge
/// independently), or the addressed object (IEC IL: two LDR %M5 in one scan share it).
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
};

/// The profile of the target this build runs (HNC-8 is the one profile so far).
const TargetProfile &targetProfile();

} // namespace lj

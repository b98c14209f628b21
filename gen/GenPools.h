// Address pools shared by the random program generator and the stimulus generator: programs
// read and write a few elements per area (so instructions interact), plus the last element of
// each area now and then (range edges).
#pragma once

#include "gen/Rng.h"
#include "ir/Area.h"
#include "profiles/hnc8/Hnc8Profile.h"

#include <cstdint>

namespace lj::gen {

/// Elements 0..n-1 of each area are the "hot" pool.
constexpr int32_t poolSize(Area a) {
  switch (a) {
  case Area::Relay:
    return 16;
  case Area::DWord:
    return 12;
  case Area::Retained:
    return 4;
  case Area::Param:
    return 4;
  default:
    return 8;
  }
}

/// D registers the structural planner reserves for backward-jump guards; generic statements
/// never write them, so a guard counts as planned (unless the planner wants it not to).
constexpr int32_t kGuardFirst = 88;
constexpr int32_t kGuardCount = 12;

/// M and T codes the stimulus puts into the channel words FC[48..55] / FC[56] and the generator
/// gives MGET / MACK / TGET, so requests and blocks match now and then (cnc-interface 1.6).
constexpr int32_t kMCodes[] = {3, 5, 6, 30, 0};
constexpr int32_t kTCodes[] = {0, 1, 12, 99};

/// F word `k` of channel `ch` (FC[k], cnc-interface 1.3) and of axis `axis` (FA[k], 1.1).
constexpr int32_t fcWord(int32_t ch, int32_t k) { return 2560 + 80 * ch + k; }
constexpr int32_t faWord(int32_t axis, int32_t k) { return 80 * axis + k; }

/// A hot element of `a`, or (rarely) its last valid element. T and C numbers come from
/// tcNumber().
inline int32_t pickIndex(Rng &rng, Area a) {
  if (rng.chance(4)) return hnc8::profile().area(a).count - 1;
  return static_cast<int32_t>(rng.below(static_cast<uint64_t>(poolSize(a))));
}

/// A valid timer/counter number: mostly 0..5, sometimes the edges 127/300/427.
inline int32_t tcNumber(Rng &rng) {
  static constexpr int32_t kEdges[] = {127, 300, 301, 427};
  if (rng.chance(20)) return kEdges[rng.below(4)];
  return static_cast<int32_t>(rng.below(6));
}

/// A constant from a mix of small values, boundaries of every width and random int32.
inline int32_t interestingConst(Rng &rng) {
  static constexpr int32_t kEdges[] = {
      0,      1,     -1,    2,         255,       256,           -128, 127,  32767,
      -32768, 65535, 65536, INT32_MAX, INT32_MIN, INT32_MIN + 1, -2,   1000, 100000};
  switch (rng.below(4)) {
  case 0:
    return static_cast<int32_t>(rng.range(-3, 20));
  case 1:
    return static_cast<int32_t>(rng.range(0, 1000));
  case 2:
    return kEdges[rng.below(sizeof kEdges / sizeof kEdges[0])];
  default:
    return static_cast<int32_t>(static_cast<uint32_t>(rng.next()));
  }
}

} // namespace lj::gen

// The IEC 61131-3 Instruction List target profile (Modicon TSX Neza, modicon-neza.md; layout:
// profiles/iec/Areas.cpp). Only the IEC front end, the IEC generator and the profile registry
// (profiles/Profiles.h) name it; the core reads the profile a program carries.
#pragma once

#include "ir/Profile.h"

#include <cstdint>

namespace lj::iec {

/// The IEC IL (Neza) profile.
const TargetProfile &profile();

/// How many of each Neza object there are (docs/iec-il.md "Process image": all of them live in
/// lj_state.mem, abi.h v3). Counts are the seed's where it gives them (modicon-neza.md 1.1, 1.2).
constexpr int32_t kUnits = 4;           ///< %Ii.j / %Qi.j: i = 0 base PLC, 1..3 expansion units
constexpr int32_t kPointsPerUnit = 16;  ///< j = 0..15 (assumption: 2 bytes per unit)
constexpr int32_t kMemoryBits = 128;    ///< %M0..%M127 (L542)
constexpr int32_t kRetainedBits = 64;   ///< %M0..%M63 survive a power failure (L542)
constexpr int32_t kEdgeMemoryBits = 32; ///< edge instructions take %M0..%M31 only (L574-575)
constexpr int32_t kSystemBits = 128;    ///< %S0..%S127 (L523)
constexpr int32_t kWords = 200;         ///< %MW0..%MW199 (assumption: the W area)
constexpr int32_t kConstWords = 64;     ///< %KW0..%KW63 (assumption)
constexpr int32_t kSystemWords = 128;   ///< %SW0..%SW127 (assumption)
constexpr int32_t kTimers = 32;         ///< %TM0..%TM31 (L1269)
constexpr int32_t kCounters = 16;       ///< %C0..%C15 (L1104-1168)
constexpr int32_t kLabels = 64;         ///< %L0..%L63 (assumption)
constexpr int32_t kSubroutines = 64;    ///< SR0..SR63 (assumption)
constexpr int32_t kParenDepth = 8;      ///< AND( / OR( nesting (L925)
constexpr int32_t kMpsDepth = 8;        ///< MPS stack (L979)
/// Label the front end ends the scan at (END, ENDC, ENDCN): one past the user's labels.
constexpr int32_t kEndLabel = kLabels;
/// The ExtraRelay bytes: scratch bits of the N / XOR / OPEN / SHORT expansions, one bit per use,
/// never named by a program (docs/iec-il.md "The accumulator on the IR").
constexpr int32_t kScratchBytes = 300;

} // namespace lj::iec

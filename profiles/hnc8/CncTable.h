// The HNC-8 CNC interface table (issue 4 item 2): the rows of ir/CncTable.h for every chapter-6
// block of family Cnc. The core reads them through the profile (TargetProfile::cncRows); this
// header is for the profile itself and for tests of the table.
#pragma once

#include "ir/CncTable.h"

#include <cstddef>
#include <cstdint>
#include <span>

namespace lj::cnc {

/// Words per axis / channel block and the first channel word (hnc8-cnc-interface.md 0).
constexpr int32_t kBlockWords = 80;
constexpr int32_t kChannelBase = 2560;
constexpr int32_t kAxes = 32;

/// Mode code (F/G[2560+80C].0-3) of one-hot mode bit i (auto, single, manual, increment, home,
/// MPG, PMC; hnc8-cnc-interface.md 2 MDST).
constexpr int32_t kModeCode[7] = {1, 7, 2, 3, 5, 4, 6};

/// One row per family-Cnc Op, in Op order (TargetProfile::cncRows of the HNC-8 profile).
constexpr size_t kRowCount =
    static_cast<size_t>(Op::ResetClear) - static_cast<size_t>(Op::ChannelModeSet) + 1;
extern const CncRow kRows[kRowCount];

/// The row of `op`, or nullptr when `op` is not driven by this table.
const CncRow *cncRow(Op op);
/// All rows.
std::span<const CncRow> cncTable();

} // namespace lj::cnc

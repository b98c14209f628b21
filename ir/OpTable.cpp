// The semantic instruction table: the row files, one per family or dialect (Arrow Gandiva's
// function_registry_*.cc), assembled in Op order. OpRowsCore.h: the core rows every dialect
// spells (hnc8-core.md); OpRowsHnc8Data.h / OpRowsHnc8Nc.h / OpRowsHnc8Cnc.h: HNC-8's data, NC
// and chapter-6 rows (hnc8-functions-1/-2.md, hnc8-cnc-interface.md); OpRowsIec.h: the Neza
// blocks; OpRowsFanuc.h: the FANUC PMC rows; OpRowsClassicLadder.h: ClassicLadder's blocks. Adding
// an instruction = one row in its file + its spelling in the front ends that have it + its two
// semantics (interpreter, lowering) + tests.
#include "ir/OpTable.h"

#include "ir/OpRowsClassicLadder.h"
#include "ir/OpRowsCore.h"
#include "ir/OpRowsFanuc.h"
#include "ir/OpRowsHnc8Cnc.h"
#include "ir/OpRowsHnc8Data.h"
#include "ir/OpRowsHnc8Nc.h"
#include "ir/OpRowsIec.h"

#include <array>
#include <cstddef>

namespace lj {

namespace {

#undef ROW
#undef ROWX

/// The row files one after another.
template <size_t... N>
constexpr std::array<InstrInfo, (N + ...)> concat(const InstrInfo (&...parts)[N]) {
  std::array<InstrInfo, (N + ...)> out{};
  size_t i = 0;
  auto add = [&](const auto &part) {
    for (const InstrInfo &row : part) out[i++] = row;
  };
  (add(parts), ...);
  return out;
}

constexpr auto kTable =
    concat(oprows::kCoreRows, oprows::kHnc8DataRows, oprows::kHnc8NcRows, oprows::kHnc8CncRows,
           oprows::kIecRows, oprows::kFanucRows, oprows::kClassicLadderRows);

static_assert(kTable.size() == kOpCount, "one row per Op");

constexpr bool rowsInOrder() {
  for (int i = 0; i < kOpCount; ++i)
    if (static_cast<int>(kTable[i].op) != i) return false;
  return true;
}
static_assert(rowsInOrder(), "rows are in Op order");

} // namespace

const InstrInfo &instrInfo(Op op) { return kTable[static_cast<size_t>(op)]; }

std::span<const InstrInfo> instrTable() { return {kTable.data(), kTable.size()}; }

} // namespace lj

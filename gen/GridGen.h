// Random editor grids (ladder/Grid.h) for `ladderjit fuzz --edit`: valid rungs of bit logic per
// dialect (random networks placed as the view places them), and random edits as the HNC-8 PLC
// screen makes them (insert / delete element, insert row / column, add / remove a vertical
// line, replace a contact's kind) that keep or break validity.
#pragma once

#include "gen/Rng.h"
#include "ladder/Grid.h"

#include <string>
#include <string_view>
#include <vector>

namespace lj::gen {

/// The addresses a dialect's grids use: `inputs` are only read (the stimulus writes them),
/// `outputs` are written by outputs and read by contacts of other rungs.
struct GridPools {
  std::vector<std::string> inputs, outputs;
  bool edges = false; ///< edge contacts (HNC-8 LDP / LDF and their AND / OR forms)
  /// Fan-outs with contacts in a branch before the last (a branch stack: MPS/MRD/MPP); FANUC
  /// PMC mnemonics have none, so there every branch but the last is one output.
  bool branchStack = true;
};

/// The pools of "hnc8" (X / Y, R), "fanuc" (X / Y, R) or "iec" (%I / %Q, %M); empty for
/// another name.
GridPools gridPools(std::string_view dialect);

/// One part "PLC1" of 1..maxRungs valid rungs. Within a rung no output address repeats and no
/// contact reads an address the rung writes (the grid evaluator reads a rung's contacts before
/// its outputs write; a program interleaves them).
std::vector<ladder::GridPart> randomGrids(Rng &rng, const GridPools &pools, int maxRungs);

enum class GridEditKind : uint8_t {
  InsertElement,
  DeleteElement,
  InsertRow,
  DeleteRow,
  InsertColumn,
  AddLink,
  RemoveLink,
  ReplaceContact
};

struct GridEdit {
  GridEditKind kind = GridEditKind::InsertElement;
  int rung = 0, row = 0, col = 0; ///< 0-based; col is the boundary of a link edit
  ladder::GridCell cell;          ///< InsertElement / ReplaceContact: the new cell
  std::string text() const;
};

/// A random edit of `parts[0]` (it keeps the rule of randomGrids about a rung's addresses).
GridEdit randomEdit(Rng &rng, const std::vector<ladder::GridPart> &parts, const GridPools &pools);
/// Apply it. InsertColumn fills the new column with a line on every row it would cut.
void applyEdit(std::vector<ladder::GridPart> &parts, const GridEdit &e);

} // namespace lj::gen

// The editor's oracle (docs/ladder-edit.md "Grid and oracle"): a grid's rungs evaluated
// directly as relay logic, read left to right from the drawing (power enters every row at the
// left rail, passes a cell whose contact conducts or a line, spreads along the vertical links of
// a column boundary, reaches the outputs), never through networks or program text, so that
// `ladderjit fuzz --edit` can hold the generated program on the interpreter against it.
// Scope: bit logic (contacts NO / NC / rising / falling edge, coil, negated coil, set, reset)
// over a bit image keyed by the operand text; a grid with a box is refused.
#pragma once

#include "ladder/Grid.h"

#include <string>
#include <unordered_map>
#include <vector>

namespace lj::ladder {

/// Bits by the address text the grid writes (`X1.0`, `%Q0.3`); missing bits read 0.
using BitImage = std::unordered_map<std::string, bool>;

class GridEvaluator {
public:
  /// Take `parts` (kept by reference: they must outlive the evaluator). False with `error`
  /// naming the cell of an element it does not evaluate (a box). Edge memories start at 0, as
  /// a loaded program's (DIALECT.md 3: zero at (re)load).
  bool load(const std::vector<GridPart> &parts, std::string &error);
  /// One scan: every rung of every part in order. Within a rung every contact reads the image
  /// as the rung found it; then its outputs write, top row first (the last write wins).
  void scan(BitImage &bits);

private:
  const std::vector<GridPart> *parts_ = nullptr;
  /// The edge bit of each edge contact (DIALECT.md 3: one per instance, updated on every
  /// execution): by part, rung, cell index.
  std::vector<std::vector<std::vector<uint8_t>>> edge_;
};

} // namespace lj::ladder

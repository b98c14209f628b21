// The editor's grid (docs/ladder-edit.md "Grid and oracle"): a rung as the HNC-8 PLC screen
// edits it (梯图编辑), rows x columns of cells between the power rails plus vertical links
// between rows at column boundaries. Conversions: grid -> networks (series/parallel trees,
// Network.h) with a located error per cell for what no dialect can express, and networks ->
// grid through the view's placement (Layout.h), so the editor shows what the view shows.
// Depends on the networks and the IR only; operands are checked by a caller-given function
// (the dialect's address parser, pipeline/Dialects.h), never by naming a front end here.
#pragma once

#include "ladder/Network.h"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace lj::ladder {

/// What one cell holds. Contacts (常开, 常闭, edge) and the line (直线) pass power from the
/// left boundary of the cell to the right one; outputs (逻辑输出, 取反输出, set, reset) and a
/// box (功能模块) take the power at their left boundary and end at the right rail; BoxPart is a
/// cell a box to its left or above covers.
enum class CellKind : uint8_t {
  Empty,
  Wire,
  ContactNO,
  ContactNC,
  ContactRise,
  ContactFall,
  Coil,
  CoilNot,
  Set,
  Reset,
  Box,
  BoxPart
};

bool isContactCell(CellKind k);
bool isOutputCell(CellKind k); ///< Coil, CoilNot, Set, Reset (not Box)
/// The editor's name of a kind: "empty", "line", "no", "nc", "rise", "fall", "coil", "coil-not",
/// "set", "reset", "box", "box-part".
const char *cellKindName(CellKind k);

struct GridCell {
  CellKind kind = CellKind::Empty;
  std::string operand;               ///< contact / output: the address text of the dialect
  std::string instr;                 ///< box: the instruction in the dialect's words
  std::vector<std::string> operands; ///< box: its operands
  bool operator==(const GridCell &) const = default;
};

/// One rung: `rows` x `cols` cells (row-major) and the vertical links. Link (r, b) joins row r
/// and row r + 1 on boundary b, the boundary left of column b (1 <= b < cols; boundary 0 is the
/// left rail, which joins every row already).
struct GridRung {
  int rows = 1, cols = 1;
  std::vector<GridCell> cells;
  std::vector<uint8_t> links; ///< (rows - 1) x (cols + 1), row-major
  std::vector<std::string> comment;

  static GridRung blank(int rows, int cols);
  GridCell &at(int r, int c) { return cells[static_cast<size_t>(r * cols + c)]; }
  const GridCell &at(int r, int c) const { return cells[static_cast<size_t>(r * cols + c)]; }
  bool link(int r, int b) const {
    return r >= 0 && r + 1 < rows && b > 0 && b < cols &&
           links[static_cast<size_t>(r * (cols + 1) + b)] != 0;
  }
  void setLink(int r, int b, bool on) {
    if (r >= 0 && r + 1 < rows && b > 0 && b < cols)
      links[static_cast<size_t>(r * (cols + 1) + b)] = on ? 1 : 0;
  }
  /// Editing (编辑网络): a row before `r` / a column before `c` (cells empty; links move with
  /// their cells), and removing row `r` / column `c`.
  void insertRow(int r);
  void deleteRow(int r);
  void insertColumn(int c);
  void deleteColumn(int c);
  bool operator==(const GridRung &o) const {
    return rows == o.rows && cols == o.cols && cells == o.cells && links == o.links;
  }
};

struct GridPart {
  std::string name; ///< "PLC1" (what the program text's part is)
  std::vector<GridRung> rungs;
};

/// An error on one cell: what the editor draws on it. `row` and `col` are 0-based here and
/// 1-based in text().
struct GridError {
  std::string part;
  int rung = 0; ///< 1-based
  int row = 0, col = 0;
  std::string message;
  std::string text() const;
};

/// Checks one operand of a cell (a contact's or output's address, a box's operand) in the
/// dialect's address syntax; false with `error` naming the problem. Null: no check.
using OperandCheck =
    std::function<bool(CellKind kind, const std::string &operand, std::string &error)>;

/// The rung as a network (a Series; Network.h): series left to right, a vertical link joins
/// the rows it spans into a parallel (where they meet again) or a fan-out (where they part to
/// their own outputs). Errors, each on its cell: an operand missing or refused by `check`; an
/// element after an output (逻辑输出可以加前置，不可以加后置); an element, output or vertical
/// link connected to no path from the rail to an output; a short circuit (a path of lines only
/// from the rail to an output, or a line in parallel with elements); a box that is not a
/// one-input box of `d` or has no input; links that join branches which parted before
/// (no series/parallel form). True and `out` set only when there are none.
bool gridToNetwork(const GridRung &g, const DialectText &d, const OperandCheck &check,
                   const std::string &part, int rung, Node &out, std::vector<GridError> &errors);

/// The grid of a ladder rung: its cells where the view (layoutRung) places them. False with
/// `error` for a rung with no drawing (STL or marker rungs) or an element the grid has no cell
/// for (an always-true contact, a box with several inputs).
bool gridOfRung(const Rung &rung, GridRung &out, std::string &error);

/// The program text of grid parts in dialect `d`: each rung through gridToNetwork and the
/// dialect's printer (DialectText::printStmts), parts ended by `partEnd` lines (the dialect's
/// end of a part, e.g. "1END"; empty: none). False with the located errors.
bool gridProgramText(const std::vector<GridPart> &parts, const DialectText &d,
                     const OperandCheck &check, const std::vector<std::string> &partEnd,
                     std::string &out, std::vector<GridError> &errors);

/// A readable drawing of the rung, one text line per row (`|` rails, `+` links, contacts
/// `[X1.0]` / `[/X1.0]` / `[P X1.0]`, outputs `(Y0.0)` / `(/Y0.0)` / `(S Y0.0)` / `(R Y0.0)`):
/// what the fuzzer prints for a mismatch.
std::string gridText(const GridRung &g);

} // namespace lj::ladder

// The grid's power flow (GridEval.h), from the drawing rules alone: the power at each column
// boundary of each row, boundary by boundary from the left rail to the right.
#include "ladder/GridEval.h"

namespace lj::ladder {

bool GridEvaluator::load(const std::vector<GridPart> &parts, std::string &error) {
  parts_ = &parts;
  edge_.assign(parts.size(), {});
  for (size_t p = 0; p < parts.size(); ++p)
    for (size_t r = 0; r < parts[p].rungs.size(); ++r) {
      const GridRung &g = parts[p].rungs[r];
      for (int row = 0; row < g.rows; ++row)
        for (int c = 0; c < g.cols; ++c)
          if (g.at(row, c).kind == CellKind::Box) {
            error = GridError{parts[p].name, static_cast<int>(r + 1), row, c,
                              "the grid evaluator has no boxes (bit logic only)"}
                        .text();
            return false;
          }
      edge_[p].emplace_back(g.cells.size(), 0);
    }
  return true;
}

void GridEvaluator::scan(BitImage &bits) {
  auto read = [&](const std::string &a) {
    auto it = bits.find(a);
    return it != bits.end() && it->second;
  };
  for (size_t p = 0; p < parts_->size(); ++p)
    for (size_t r = 0; r < (*parts_)[p].rungs.size(); ++r) {
      const GridRung &g = (*parts_)[p].rungs[r];
      std::vector<uint8_t> &edges = edge_[p][r];
      // Whether each cell passes power from its left to its right boundary, read before any
      // output of the rung writes; edge contacts update their bit whatever the power.
      std::vector<uint8_t> passes(g.cells.size(), 0);
      for (int row = 0; row < g.rows; ++row)
        for (int c = 0; c < g.cols; ++c) {
          const size_t i = static_cast<size_t>(row * g.cols + c);
          const GridCell &cell = g.cells[i];
          switch (cell.kind) {
          case CellKind::Wire:
            passes[i] = 1;
            break;
          case CellKind::ContactNO:
            passes[i] = read(cell.operand);
            break;
          case CellKind::ContactNC:
            passes[i] = !read(cell.operand);
            break;
          case CellKind::ContactRise:
          case CellKind::ContactFall: {
            const bool cur = read(cell.operand), was = edges[i] != 0;
            passes[i] = cell.kind == CellKind::ContactRise ? cur && !was : !cur && was;
            edges[i] = cur;
            break;
          }
          default:
            break;
          }
        }
      // Power on the left boundary of each column: boundary 0 is the rail; boundary b gets
      // what passed the cells of column b - 1, shared by the rows a vertical line joins there.
      std::vector<uint8_t> power(static_cast<size_t>(g.rows), 1), next(power.size());
      std::vector<uint8_t> left(g.cells.size(), 0); // the power at each cell's left boundary
      for (int b = 0; b < g.cols; ++b) {
        if (b > 0) {
          for (int row = 0; row < g.rows; ++row)
            next[static_cast<size_t>(row)] = power[static_cast<size_t>(row)] &&
                                             passes[static_cast<size_t>(row * g.cols + b - 1)];
          for (int top = 0; top < g.rows;) { // each run of rows the links join at b
            int bottom = top;
            while (g.link(bottom, b)) ++bottom;
            bool any = false;
            for (int row = top; row <= bottom; ++row) any = any || next[static_cast<size_t>(row)];
            for (int row = top; row <= bottom; ++row) next[static_cast<size_t>(row)] = any;
            top = bottom + 1;
          }
          power = next;
        }
        for (int row = 0; row < g.rows; ++row)
          left[static_cast<size_t>(row * g.cols + b)] = power[static_cast<size_t>(row)];
      }
      // The outputs, top row first (the last write wins).
      for (size_t i = 0; i < g.cells.size(); ++i) {
        const GridCell &cell = g.cells[i];
        const bool on = left[i] != 0;
        switch (cell.kind) {
        case CellKind::Coil:
          bits[cell.operand] = on;
          break;
        case CellKind::CoilNot:
          bits[cell.operand] = !on;
          break;
        case CellKind::Set:
          if (on) bits[cell.operand] = true;
          break;
        case CellKind::Reset:
          if (on) bits[cell.operand] = false;
          break;
        default:
          break;
        }
      }
    }
}

} // namespace lj::ladder

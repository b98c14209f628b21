// Random editor grids and edits (GridGen.h). A rung is drawn by making a random network
// (contacts in series, nested parallels, one or more outputs behind a fan-out) and placing it
// as the ladder view does (ladder::gridOfRung), so every generated grid is one the editor shows.
#include "gen/GridGen.h"

#include <algorithm>
#include <set>

namespace lj::gen {

using ladder::CellKind;
using ladder::GridCell;
using ladder::GridPart;
using ladder::GridRung;
using ladder::Node;
using ladder::NodeKind;

GridPools gridPools(std::string_view dialect) {
  GridPools p;
  if (dialect == "hnc8" || dialect == "fanuc") {
    for (int i = 0; i < 16; ++i)
      p.inputs.push_back("X" + std::to_string(i / 8) + "." + std::to_string(i % 8));
    for (int i = 0; i < 8; ++i) p.outputs.push_back("Y0." + std::to_string(i));
    for (int i = 0; i < 16; ++i)
      p.outputs.push_back("R" + std::to_string(i / 8) + "." + std::to_string(i % 8));
    p.edges = dialect == "hnc8";
    p.branchStack = dialect == "hnc8";
  } else if (dialect == "iec") {
    for (int i = 0; i < 16; ++i) p.inputs.push_back("%I0." + std::to_string(i));
    for (int i = 0; i < 8; ++i) p.outputs.push_back("%Q0." + std::to_string(i));
    for (int i = 0; i < 16; ++i) p.outputs.push_back("%M" + std::to_string(i));
  }
  return p;
}

namespace {

const std::string &pickOf(Rng &rng, const std::vector<std::string> &v) {
  return v[rng.below(v.size())];
}

CellKind randomContact(Rng &rng, bool edges) {
  static constexpr int kW[] = {60, 30, 5, 5};
  int k = rng.weighted(std::span<const int>(kW, edges ? 4 : 2));
  return static_cast<CellKind>(static_cast<int>(CellKind::ContactNO) + k);
}

CellKind randomOutput(Rng &rng) {
  static constexpr int kW[] = {55, 15, 15, 15};
  return static_cast<CellKind>(static_cast<int>(CellKind::Coil) + rng.weighted(kW));
}

class NetGen {
public:
  NetGen(Rng &rng, const GridPools &p) : r_(rng), p_(p) {}

  ladder::Rung rung() {
    const int n = static_cast<int>(r_.range(1, 4));
    std::vector<std::string> outs;
    while (static_cast<int>(outs.size()) < n) {
      const std::string &a = pickOf(r_, p_.outputs);
      if (std::find(outs.begin(), outs.end(), a) == outs.end()) outs.push_back(a);
    }
    written_ = std::set<std::string>(outs.begin(), outs.end());
    ladder::Rung rung;
    rung.kind = ladder::Rung::Kind::Ladder;
    rung.network.kind = NodeKind::Series;
    rung.network.children = inputs(0);
    for (Node &t : tail(outs, 0)) rung.network.children.push_back(std::move(t));
    return rung;
  }

private:
  Node leaf(NodeKind k) {
    Node n;
    n.kind = k;
    n.elem.id = id_++;
    return n;
  }

  Node contact() {
    Node n = leaf(NodeKind::Contact);
    CellKind k = randomContact(r_, p_.edges);
    n.contact = static_cast<ladder::ContactKind>(static_cast<int>(k) -
                                                 static_cast<int>(CellKind::ContactNO));
    static constexpr Op kOps[] = {Op::Load, Op::LoadNot, Op::LoadRise, Op::LoadFall};
    n.elem.op = kOps[static_cast<int>(n.contact)];
    std::string a;
    do a = r_.chance(70) ? pickOf(r_, p_.inputs) : pickOf(r_, p_.outputs);
    while (written_.count(a));
    n.elem.operands = {a};
    n.elem.symbols = {""};
    return n;
  }

  /// Items of a series: contacts and parallels of 2..3 branches.
  std::vector<Node> inputs(int depth) {
    std::vector<Node> items;
    const int k = static_cast<int>(r_.range(1, depth == 0 ? 3 : 2));
    for (int i = 0; i < k; ++i) {
      if (depth < 2 && r_.chance(depth == 0 ? 30 : 15)) {
        Node p;
        p.kind = NodeKind::Parallel;
        const int m = static_cast<int>(r_.range(2, 3));
        for (int j = 0; j < m; ++j) {
          std::vector<Node> b = inputs(depth + 1);
          if (b.size() == 1 && b[0].kind == NodeKind::Parallel) { // OR of ORs: one parallel
            for (Node &c : b[0].children) p.children.push_back(std::move(c));
          } else if (b.size() == 1) {
            p.children.push_back(std::move(b[0]));
          } else {
            Node s;
            s.kind = NodeKind::Series;
            s.children = std::move(b);
            p.children.push_back(std::move(s));
          }
        }
        items.push_back(std::move(p));
      } else {
        items.push_back(contact());
      }
    }
    return items;
  }

  /// The outputs `outs` behind the series so far: one output, or a fan-out of branches.
  std::vector<Node> tail(const std::vector<std::string> &outs, int depth) {
    if (outs.size() == 1) {
      Node o = leaf(NodeKind::Coil);
      static constexpr Op kOps[] = {Op::Coil, Op::CoilNot, Op::Set, Op::Reset};
      o.elem.op = kOps[static_cast<int>(randomOutput(r_)) - static_cast<int>(CellKind::Coil)];
      o.elem.operands = {outs[0]};
      o.elem.symbols = {""};
      return {std::move(o)};
    }
    const size_t k =
        std::min<size_t>(outs.size(), depth > 0 ? 2 : static_cast<size_t>(r_.range(2, 3)));
    std::vector<std::vector<std::string>> groups(k);
    for (size_t i = 0; i < outs.size(); ++i)
      groups[i < k ? i : p_.branchStack ? r_.below(k) : k - 1].push_back(outs[i]);
    Node f;
    f.kind = NodeKind::FanOut;
    for (const auto &g : groups) {
      Node b;
      b.kind = NodeKind::Series;
      const bool last = &g == &groups.back();
      if (g.size() > 1 || ((p_.branchStack || last) && r_.chance(50))) b.children = inputs(1);
      for (Node &t : tail(g, depth + 1)) b.children.push_back(std::move(t));
      f.children.push_back(std::move(b));
    }
    return {std::move(f)};
  }

  Rng &r_;
  const GridPools &p_;
  std::set<std::string> written_;
  StmtId id_ = 0;
};

/// Addresses a rung reads (contacts) and writes (outputs).
void addressesOf(const GridRung &g, std::set<std::string> &read, std::set<std::string> &written) {
  for (const GridCell &c : g.cells) {
    if (ladder::isContactCell(c.kind)) read.insert(c.operand);
    if (ladder::isOutputCell(c.kind)) written.insert(c.operand);
  }
}

} // namespace

std::vector<GridPart> randomGrids(Rng &rng, const GridPools &pools, int maxRungs) {
  std::vector<GridPart> parts(1);
  parts[0].name = "PLC1";
  const int n = static_cast<int>(rng.range(1, std::max(1, maxRungs)));
  for (int i = 0; i < n; ++i) {
    NetGen gen(rng, pools);
    ladder::Rung rung = gen.rung();
    GridRung g;
    std::string error;
    if (ladder::gridOfRung(rung, g, error)) parts[0].rungs.push_back(std::move(g));
  }
  return parts;
}

std::string GridEdit::text() const {
  static const char *const kNames[] = {
      "insert element", "delete element",    "insert row",           "delete row",
      "insert column",  "add vertical line", "remove vertical line", "replace contact"};
  std::string t = std::string(kNames[static_cast<int>(kind)]) + " rung " +
                  std::to_string(rung + 1) + " row " + std::to_string(row + 1) + " column " +
                  std::to_string(col + 1);
  if (kind == GridEditKind::InsertElement || kind == GridEditKind::ReplaceContact)
    t += std::string(": ") + ladder::cellKindName(cell.kind) +
         (cell.operand.empty() ? "" : " " + cell.operand);
  return t;
}

GridEdit randomEdit(Rng &rng, const std::vector<GridPart> &parts, const GridPools &pools) {
  GridEdit e;
  if (parts.empty() || parts[0].rungs.empty()) return e;
  e.rung = static_cast<int>(rng.below(parts[0].rungs.size()));
  const GridRung &g = parts[0].rungs[static_cast<size_t>(e.rung)];
  static constexpr int kW[] = {35, 15, 8, 5, 8, 8, 8, 13};
  e.kind = static_cast<GridEditKind>(rng.weighted(kW));
  e.row = static_cast<int>(rng.below(static_cast<uint64_t>(g.rows)));
  e.col = static_cast<int>(rng.below(static_cast<uint64_t>(g.cols)));
  std::set<std::string> read, written;
  addressesOf(g, read, written);
  auto cellsOf = [&](auto pred) {
    std::vector<std::pair<int, int>> v;
    for (int r = 0; r < g.rows; ++r)
      for (int c = 0; c < g.cols; ++c)
        if (pred(g.at(r, c).kind)) v.push_back({r, c});
    return v;
  };
  auto at = [&](const std::vector<std::pair<int, int>> &v) {
    if (v.empty()) return false;
    auto [r, c] = v[rng.below(v.size())];
    e.row = r;
    e.col = c;
    return true;
  };
  switch (e.kind) {
  case GridEditKind::InsertElement: {
    // Mostly onto a line (what keeps a rung valid), else anywhere.
    if (rng.chance(70)) at(cellsOf([](CellKind k) { return k == CellKind::Wire; }));
    const int what = static_cast<int>(rng.below(100));
    if (what < 65) {
      e.cell.kind = randomContact(rng, pools.edges);
      e.cell.operand = pickOf(rng, pools.inputs); // never written: reads no output of the rung
    } else if (what < 85) {
      e.cell.kind = CellKind::Wire;
    } else {
      e.cell.kind = randomOutput(rng);
      std::string a;
      for (int tries = 0; tries < 20; ++tries) {
        a = pickOf(rng, pools.outputs);
        if (!read.count(a) && !written.count(a)) break;
        a.clear();
      }
      if (a.empty()) e.cell.kind = CellKind::Wire;
      e.cell.operand = a;
    }
    break;
  }
  case GridEditKind::DeleteElement:
    at(cellsOf([](CellKind k) { return k != CellKind::Empty; }));
    break;
  case GridEditKind::ReplaceContact:
    if (!at(cellsOf([](CellKind k) { return ladder::isContactCell(k); }))) break;
    e.cell = g.at(e.row, e.col);
    e.cell.kind = randomContact(rng, pools.edges);
    break;
  case GridEditKind::AddLink:
  case GridEditKind::RemoveLink:
    e.row = static_cast<int>(rng.below(static_cast<uint64_t>(std::max(1, g.rows - 1))));
    e.col = static_cast<int>(rng.range(1, std::max(1, g.cols - 1)));
    break;
  default:
    break;
  }
  return e;
}

void applyEdit(std::vector<GridPart> &parts, const GridEdit &e) {
  if (parts.empty() || e.rung < 0 || static_cast<size_t>(e.rung) >= parts[0].rungs.size()) return;
  GridRung &g = parts[0].rungs[static_cast<size_t>(e.rung)];
  const bool inside = e.row >= 0 && e.row < g.rows && e.col >= 0 && e.col < g.cols;
  switch (e.kind) {
  case GridEditKind::InsertElement:
  case GridEditKind::ReplaceContact:
    if (inside) g.at(e.row, e.col) = e.cell;
    break;
  case GridEditKind::DeleteElement:
    if (inside) g.at(e.row, e.col) = GridCell{};
    break;
  case GridEditKind::InsertRow:
    g.insertRow(e.row);
    break;
  case GridEditKind::DeleteRow:
    g.deleteRow(e.row);
    break;
  case GridEditKind::InsertColumn: {
    g.insertColumn(e.col);
    for (int r = 0; r < g.rows; ++r) {
      const bool left = e.col == 0 || g.at(r, e.col - 1).kind != CellKind::Empty;
      const bool right = e.col + 1 < g.cols && g.at(r, e.col + 1).kind != CellKind::Empty &&
                         g.at(r, e.col + 1).kind != CellKind::BoxPart;
      if (left && right) g.at(r, e.col).kind = CellKind::Wire;
    }
    break;
  }
  case GridEditKind::AddLink:
    g.setLink(e.row, e.col, true);
    break;
  case GridEditKind::RemoveLink:
    g.setLink(e.row, e.col, false);
    break;
  }
}

} // namespace lj::gen

// The editor's grid (Grid.h). grid -> network: the rung is read as a graph whose nodes are the
// points where cells meet (one per column boundary and row, those a vertical link joins made
// one, the left rail one node) and whose edges are the cells, left to right. Series/parallel
// reduction (two edges between the same nodes: parallel; a node with one edge in and one out:
// series) leaves a tree from the rail: a node with several edges out is a fan-out. What does not
// reduce to a tree has no series/parallel form and is an error on its cell. network -> grid: the
// view's placement (layoutRung), cell by cell.
#include "ladder/Grid.h"

#include "ladder/Json.h"
#include "ladder/Layout.h"

#include <algorithm>
#include <cstdlib>
#include <map>
#include <numeric>
#include <unordered_map>

namespace lj::ladder {

bool isContactCell(CellKind k) {
  return k == CellKind::ContactNO || k == CellKind::ContactNC || k == CellKind::ContactRise ||
         k == CellKind::ContactFall;
}

bool isOutputCell(CellKind k) {
  return k == CellKind::Coil || k == CellKind::CoilNot || k == CellKind::Set ||
         k == CellKind::Reset;
}

const char *cellKindName(CellKind k) {
  static const char *const kNames[] = {"empty", "line",     "no",  "nc",    "rise", "fall",
                                       "coil",  "coil-not", "set", "reset", "box",  "box-part"};
  return kNames[static_cast<int>(k)];
}

GridRung GridRung::blank(int rows, int cols) {
  GridRung g;
  g.rows = std::max(rows, 1);
  g.cols = std::max(cols, 1);
  g.cells.assign(static_cast<size_t>(g.rows * g.cols), GridCell{});
  g.links.assign(static_cast<size_t>((g.rows - 1) * (g.cols + 1)), 0);
  return g;
}

void GridRung::insertRow(int r) {
  r = std::clamp(r, 0, rows);
  GridRung n = blank(rows + 1, cols);
  n.comment = comment;
  for (int i = 0; i < rows; ++i)
    for (int c = 0; c < cols; ++c) n.at(i < r ? i : i + 1, c) = at(i, c);
  for (int i = 0; i + 1 < rows; ++i)
    for (int b = 1; b < cols; ++b) n.setLink(i < r ? i : i + 1, b, link(i, b));
  *this = std::move(n);
}

void GridRung::deleteRow(int r) {
  if (rows <= 1 || r < 0 || r >= rows) return;
  GridRung n = blank(rows - 1, cols);
  n.comment = comment;
  for (int i = 0; i < n.rows; ++i)
    for (int c = 0; c < cols; ++c) n.at(i, c) = at(i < r ? i : i + 1, c);
  for (int i = 0; i + 1 < n.rows; ++i)
    for (int b = 1; b < cols; ++b) n.setLink(i, b, link(i < r ? i : i + 1, b));
  *this = std::move(n);
}

void GridRung::insertColumn(int c) {
  c = std::clamp(c, 0, cols);
  GridRung n = blank(rows, cols + 1);
  n.comment = comment;
  for (int i = 0; i < rows; ++i)
    for (int k = 0; k < cols; ++k) n.at(i, k < c ? k : k + 1) = at(i, k);
  for (int i = 0; i + 1 < rows; ++i)
    for (int b = 1; b < cols; ++b) n.setLink(i, b <= c ? b : b + 1, link(i, b));
  *this = std::move(n);
}

void GridRung::deleteColumn(int c) {
  if (cols <= 1 || c < 0 || c >= cols) return;
  GridRung n = blank(rows, cols - 1);
  n.comment = comment;
  for (int i = 0; i < rows; ++i)
    for (int k = 0; k < n.cols; ++k) n.at(i, k) = at(i, k < c ? k : k + 1);
  for (int i = 0; i + 1 < rows; ++i)
    for (int b = 1; b < cols; ++b) {
      if (b == c + 1) continue;
      n.setLink(i, b <= c ? b : b - 1, link(i, b));
    }
  *this = std::move(n);
}

std::string GridError::text() const {
  return part + " rung " + std::to_string(rung) + " row " + std::to_string(row + 1) + " column " +
         std::to_string(col + 1) + ": " + message;
}

namespace {

/// A one-input box (MOV, ADD...) at the right rail: it takes the power at its left; whatever
/// it passes on is dead, as after an output.
bool isOutputBox(Op op) {
  const InstrInfo &ii = instrInfo(op);
  return ii.stack == StackRule::Block && ii.inputs <= 1;
}

Op contactLoad(CellKind k) {
  switch (k) {
  case CellKind::ContactNC:
    return Op::LoadNot;
  case CellKind::ContactRise:
    return Op::LoadRise;
  case CellKind::ContactFall:
    return Op::LoadFall;
  default:
    return Op::Load;
  }
}

ContactKind contactKind(CellKind k) {
  switch (k) {
  case CellKind::ContactNC:
    return ContactKind::NC;
  case CellKind::ContactRise:
    return ContactKind::Rise;
  case CellKind::ContactFall:
    return ContactKind::Fall;
  default:
    return ContactKind::NO;
  }
}

Op outputOp(CellKind k) {
  switch (k) {
  case CellKind::CoilNot:
    return Op::CoilNot;
  case CellKind::Set:
    return Op::Set;
  case CellKind::Reset:
    return Op::Reset;
  default:
    return Op::Coil;
  }
}

/// One edge of the rung's graph: a cell, or what reduction made of several. `items` is the
/// series it stands for (a contact, a Parallel, an output leaf); a line alone is no items.
struct Edge {
  int from = 0, to = 0;
  std::vector<Node> items;
  bool wire = true; ///< lines only
  int row = 0, col = 0;
  bool alive = true;
  std::vector<int> rows; ///< a parallel the reduction made: the row each branch starts on
};

struct UnionFind {
  std::vector<int> p;
  explicit UnionFind(int n) : p(static_cast<size_t>(n)) { std::iota(p.begin(), p.end(), 0); }
  int find(int x) {
    while (p[static_cast<size_t>(x)] != x)
      x = p[static_cast<size_t>(x)] = p[static_cast<size_t>(p[static_cast<size_t>(x)])];
    return x;
  }
  void join(int a, int b) { p[static_cast<size_t>(find(a))] = find(b); }
};

/// `items` as one parallel branch: a single node, or a Series of them.
Node branchOf(std::vector<Node> items) {
  if (items.size() == 1) return std::move(items[0]);
  Node s;
  s.kind = NodeKind::Series;
  s.children = std::move(items);
  return s;
}

class Reader {
public:
  Reader(const GridRung &g, const DialectText &d, const OperandCheck &check,
         const std::string &part, int rung, std::vector<GridError> &errors)
      : g_(g), d_(d), check_(check), part_(part), rung_(rung), errors_(errors) {}

  bool read(Node &out) {
    const size_t before = errors_.size();
    cells();
    if (errors_.size() != before) return false;
    connected();
    if (errors_.size() != before) return false;
    if (!reduce()) return false;
    return tree(out);
  }

private:
  int node(int r, int b) { return uf_.find(b == 0 ? 0 : b * g_.rows + r); }

  void error(int r, int c, std::string msg) {
    errors_.push_back({part_, rung_, r, c, std::move(msg)});
  }

  bool operand(int r, int c, CellKind k, const std::string &text) {
    if (text.empty()) {
      error(r, c, std::string("the ") + cellKindName(k) + " has no address");
      return false;
    }
    std::string err;
    if (check_ && !check_(k, text, err)) {
      error(r, c, "'" + text + "': " + err);
      return false;
    }
    return true;
  }

  void cells() {
    const int R = g_.rows, C = g_.cols;
    // A run of vertical lines joins its rows; the rows between its ends may pass through (a
    // fan-out to rows below), its two ends must meet a cell.
    for (int b = 1; b < C; ++b)
      for (int top = 0; top + 1 < R;) {
        if (!g_.link(top, b)) {
          ++top;
          continue;
        }
        int bottom = top;
        while (g_.link(bottom, b)) {
          uf_.join(b * R + bottom, b * R + bottom + 1);
          ++bottom;
        }
        for (int row : {top, bottom}) {
          auto filled = [&](int c) {
            return c >= 0 && c < C && g_.at(row, c).kind != CellKind::Empty &&
                   g_.at(row, c).kind != CellKind::BoxPart;
          };
          if (!filled(b - 1) && !filled(b))
            error(row, b, "a vertical line ends on this row at no element (unconnected)");
        }
        top = bottom;
      }
    int sink = (C + 1) * R;
    for (int r = 0; r < R; ++r)
      for (int c = 0; c < C; ++c) {
        const GridCell &cell = g_.at(r, c);
        if (cell.kind == CellKind::Empty || cell.kind == CellKind::BoxPart) continue;
        Edge e;
        e.row = r;
        e.col = c;
        e.from = node(r, c);
        if (cell.kind == CellKind::Wire) {
          e.to = node(r, c + 1);
        } else if (isContactCell(cell.kind)) {
          if (c + 1 == C) {
            error(r, c, "a contact in the last column reaches the right rail without an output");
            continue;
          }
          e.to = node(r, c + 1);
          e.wire = false;
          Node n;
          n.kind = NodeKind::Contact;
          n.contact = contactKind(cell.kind);
          n.elem.op = contactLoad(cell.kind);
          n.elem.id = r * C + c; // the cell: where a printer's error on it is drawn
          n.elem.operands = {cell.operand};
          n.elem.symbols = {""};
          operand(r, c, cell.kind, cell.operand);
          e.items.push_back(std::move(n));
        } else { // an output or a box: ends at the right rail, nothing after it on its row
          for (int k = c + 1; k < C; ++k) {
            CellKind after = g_.at(r, k).kind;
            if (after == CellKind::Empty ||
                (after == CellKind::BoxPart && cell.kind == CellKind::Box))
              continue;
            error(r, k,
                  std::string("a ") + cellKindName(after) +
                      " after an output: an output may have elements before it, never after "
                      "(逻辑输出可以加前置，不可以加后置)");
            break;
          }
          e.to = sink++;
          e.wire = false;
          Node n;
          if (cell.kind == CellKind::Box) {
            n.kind = NodeKind::Box;
            Op op = Op::LoadTrue;
            if (cell.instr.empty() || !d_.lookup || !d_.lookup(cell.instr, op)) {
              error(r, c, "'" + cell.instr + "' is no instruction of the " + d_.name + " dialect");
              continue;
            }
            if (!isOutputBox(op)) {
              error(r, c, "box " + cell.instr + " is not a one-input box the editor draws");
              continue;
            }
            n.elem.op = op;
            n.elem.id = r * C + c;
            n.elem.drawn = cell.instr;
            for (const std::string &o : cell.operands) {
              operand(r, c, cell.kind, o);
              n.elem.operands.push_back(o);
              n.elem.symbols.push_back("");
            }
          } else {
            n.kind = NodeKind::Coil;
            n.elem.op = outputOp(cell.kind);
            n.elem.id = r * C + c;
            n.elem.operands = {cell.operand};
            n.elem.symbols = {""};
            operand(r, c, cell.kind, cell.operand);
          }
          sinks_.push_back(e.to);
          e.items.push_back(std::move(n));
        }
        edges_.push_back(std::move(e));
      }
    sinkFrom_ = (C + 1) * R;
  }

  bool isSink(int n) const { return n >= sinkFrom_; }

  /// Every cell on a path from the rail to an output; no such path of lines only.
  void connected() {
    std::map<int, std::vector<size_t>> out, in;
    for (size_t i = 0; i < edges_.size(); ++i) {
      out[edges_[i].from].push_back(i);
      in[edges_[i].to].push_back(i);
    }
    auto walk = [&](std::vector<int> todo, std::map<int, std::vector<size_t>> &adj, bool fwd,
                    bool wiresOnly) {
      std::map<int, bool> seen;
      for (int t : todo) seen[t] = true;
      while (!todo.empty()) {
        int v = todo.back();
        todo.pop_back();
        for (size_t i : adj[v]) {
          if (wiresOnly && !edges_[i].wire) continue;
          int w = fwd ? edges_[i].to : edges_[i].from;
          if (!seen[w]) {
            seen[w] = true;
            todo.push_back(w);
          }
        }
      }
      return seen;
    };
    std::map<int, bool> fromRail = walk({0}, out, true, false);
    std::map<int, bool> toOutput = walk(sinks_, in, false, false);
    std::map<int, bool> lines = walk({0}, out, true, true);
    for (const Edge &e : edges_) {
      const CellKind k = g_.at(e.row, e.col).kind;
      if (!fromRail[e.from])
        error(e.row, e.col,
              std::string("the ") + cellKindName(k) +
                  " gets no power from the left rail (unconnected)");
      else if (!toOutput[e.to])
        error(e.row, e.col,
              std::string("the ") + cellKindName(k) + " leads to no output (unconnected)");
      else if (isSink(e.to) && lines[e.from])
        error(e.row, e.col,
              "short circuit: lines only from the left rail to this output (it needs a contact)");
    }
  }

  static bool parallelWithLine(const Edge &a, const Edge &b) { return a.wire || b.wire; }

  bool reduce() {
    for (bool changed = true; changed;) {
      changed = false;
      // Parallel: edges between the same two nodes.
      std::map<std::pair<int, int>, size_t> first;
      for (size_t i = 0; i < edges_.size(); ++i) {
        Edge &e = edges_[i];
        if (!e.alive) continue;
        auto [it, fresh] = first.emplace(std::make_pair(e.from, e.to), i);
        if (fresh) continue;
        Edge &a = edges_[it->second];
        if (parallelWithLine(a, e)) {
          const Edge &w = a.wire ? a : e;
          error(w.row, w.col, "short circuit: this line bridges the elements in parallel with it");
          return false;
        }
        // The branches top row first (each keeps the row it starts on).
        std::vector<std::pair<int, Node>> branches;
        for (Edge *x : {&a, &e}) {
          if (x->items.size() == 1 && x->items[0].kind == NodeKind::Parallel && x->items[0].rail) {
            for (size_t k = 0; k < x->items[0].children.size(); ++k)
              branches.push_back({x->rows[k], std::move(x->items[0].children[k])});
          } else {
            branches.push_back({x->row, branchOf(std::move(x->items))});
          }
        }
        std::stable_sort(branches.begin(), branches.end(),
                         [](const auto &l, const auto &r) { return l.first < r.first; });
        Node p;
        p.kind = NodeKind::Parallel;
        p.rail = true; // marks a parallel this reduction made (flattened when it grows)
        a.rows.clear();
        for (auto &[row, n] : branches) {
          a.rows.push_back(row);
          p.children.push_back(std::move(n));
        }
        a.items.clear();
        a.items.push_back(std::move(p));
        a.row = std::min(a.row, e.row);
        a.col = std::min(a.col, e.col);
        a.wire = false;
        e.alive = false;
        changed = true;
      }
      // Series: a node with one edge in and one edge out.
      std::unordered_map<int, int> inDeg, outDeg;
      std::unordered_map<int, size_t> inEdge, outEdge;
      for (size_t i = 0; i < edges_.size(); ++i)
        if (edges_[i].alive) {
          ++outDeg[edges_[i].from];
          outEdge[edges_[i].from] = i;
          ++inDeg[edges_[i].to];
          inEdge[edges_[i].to] = i;
        }
      for (auto [v, n] : inDeg) {
        if (n != 1 || v == 0 || isSink(v) || outDeg[v] != 1) continue;
        Edge &a = edges_[inEdge[v]];
        Edge &b = edges_[outEdge[v]];
        if (!a.alive || !b.alive || &a == &b) continue;
        if (a.items.empty()) a.rows = std::move(b.rows); // a line before b's parallel
        for (Node &x : b.items) a.items.push_back(std::move(x));
        a.to = b.to;
        a.wire = a.wire && b.wire;
        b.alive = false;
        changed = true;
        break; // degrees changed; count again
      }
    }
    return true;
  }

  std::vector<size_t> outOf(int v) const {
    std::vector<size_t> r;
    for (size_t i = 0; i < edges_.size(); ++i)
      if (edges_[i].alive && edges_[i].from == v) r.push_back(i);
    std::sort(r.begin(), r.end(), [&](size_t a, size_t b) {
      return edges_[a].row != edges_[b].row ? edges_[a].row < edges_[b].row
                                            : edges_[a].col < edges_[b].col;
    });
    return r;
  }

  static void clearMarks(Node &n) {
    if (n.kind == NodeKind::Parallel) n.rail = false;
    for (Node &c : n.children) clearMarks(c);
  }

  void append(Node &s, Edge &e) {
    for (Node &x : e.items) {
      clearMarks(x);
      s.children.push_back(std::move(x));
    }
  }

  bool grow(int v, Node &s) {
    std::vector<size_t> outs = outOf(v);
    if (outs.size() == 1) {
      Edge &e = edges_[outs[0]];
      append(s, e);
      return isSink(e.to) || grow(e.to, s);
    }
    Node f;
    f.kind = NodeKind::FanOut;
    for (size_t i : outs) {
      Node b;
      b.kind = NodeKind::Series;
      Edge &e = edges_[i];
      append(b, e);
      if (!isSink(e.to) && !grow(e.to, b)) return false;
      if (b.children.size() == 1 && b.children[0].kind == NodeKind::FanOut) {
        // lines only to a second junction: its branches are branches of this one
        for (Node &x : b.children[0].children) f.children.push_back(std::move(x));
        continue;
      }
      f.children.push_back(std::move(b));
    }
    s.children.push_back(std::move(f));
    return true;
  }

  bool tree(Node &out) {
    std::unordered_map<int, std::vector<size_t>> in;
    for (size_t i = 0; i < edges_.size(); ++i)
      if (edges_[i].alive) in[edges_[i].to].push_back(i);
    bool ok = true;
    for (auto &[v, es] : in)
      if (es.size() > 1) {
        const Edge &e = edges_[*std::max_element(es.begin(), es.end(), [&](size_t a, size_t b) {
          return edges_[a].row < edges_[b].row;
        })];
        error(e.row, e.col,
              "a vertical line joins branches that parted before: no series/parallel form "
              "(draw the shared part once)");
        ok = false;
      }
    std::vector<size_t> rail = outOf(0);
    if (rail.size() > 1) {
      const Edge &e = edges_[rail[1]];
      error(e.row, e.col,
            "a second network from the left rail in this rung: join it with a vertical line or "
            "make it a rung of its own");
      ok = false;
    }
    if (rail.empty()) {
      error(0, 0, "the rung has no output");
      ok = false;
    }
    if (!ok) return false;
    out = Node{};
    out.kind = NodeKind::Series;
    return grow(0, out);
  }

  const GridRung &g_;
  const DialectText &d_;
  const OperandCheck &check_;
  const std::string &part_;
  int rung_;
  std::vector<GridError> &errors_;
  UnionFind uf_{(g_.cols + 1) * g_.rows};
  std::vector<Edge> edges_;
  std::vector<int> sinks_;
  int sinkFrom_ = 0;
};

void collect(const Node &n, std::unordered_map<StmtId, const Node *> &byId) {
  if (n.kind == NodeKind::Contact || n.kind == NodeKind::Coil || n.kind == NodeKind::Box)
    byId[n.elem.id] = &n;
  for (const Node &c : n.children) collect(c, byId);
}

} // namespace

bool gridToNetwork(const GridRung &g, const DialectText &d, const OperandCheck &check,
                   const std::string &part, int rung, Node &out, std::vector<GridError> &errors) {
  if (g.rows < 1 || g.cols < 1 || g.cells.size() != static_cast<size_t>(g.rows * g.cols) ||
      g.links.size() != static_cast<size_t>((g.rows - 1) * (g.cols + 1))) {
    errors.push_back({part, rung, 0, 0, "malformed grid (cell or link count)"});
    return false;
  }
  Reader reader(g, d, check, part, rung, errors);
  return reader.read(out);
}

bool gridOfRung(const Rung &rung, GridRung &out, std::string &error) {
  if (rung.kind != Rung::Kind::Ladder) {
    error = "the rung has no ladder drawing (statement text only)";
    return false;
  }
  std::unordered_map<StmtId, const Node *> byId;
  collect(rung.network, byId);
  RungLayout l = layoutRung(rung, 1, {});
  out = GridRung::blank(std::max(l.rows, 1), std::max(l.cols, 1));
  out.comment = rung.comment;
  for (const Cell &c : l.cells) {
    auto elem = [&]() -> const Element * {
      auto it = byId.find(c.stmt);
      return it == byId.end() ? nullptr : &it->second->elem;
    };
    auto put = [&](CellKind k) {
      const Element *e = elem();
      if (c.row >= out.rows || c.col >= out.cols) return false;
      GridCell &cell = out.at(c.row, c.col);
      cell.kind = k;
      cell.operand = e && !e->operands.empty() ? e->operands[0] : c.text;
      return true;
    };
    bool ok = true;
    if (c.kind == "wire") {
      for (int k = c.col; k < c.col + c.width && k < out.cols; ++k)
        out.at(c.row, k).kind = CellKind::Wire;
    } else if (c.kind == "vlink") {
      for (int r = c.row; r < c.row + c.height; ++r) out.setLink(r, c.col, true);
    } else if (c.kind == "join") {
      // an ANB / MPS: no drawing of its own
    } else if (c.kind == "contact-no") {
      ok = put(CellKind::ContactNO);
    } else if (c.kind == "contact-nc") {
      ok = put(CellKind::ContactNC);
    } else if (c.kind == "contact-rise") {
      ok = put(CellKind::ContactRise);
    } else if (c.kind == "contact-fall") {
      ok = put(CellKind::ContactFall);
    } else if (c.kind == "coil") {
      ok = put(CellKind::Coil);
    } else if (c.kind == "coil-not") {
      ok = put(CellKind::CoilNot);
    } else if (c.kind == "set") {
      ok = put(CellKind::Set);
    } else if (c.kind == "rst") {
      ok = put(CellKind::Reset);
    } else if (c.kind == "box" && c.pins.size() <= 1 && elem()) {
      const Element *e = elem();
      for (int r = c.row; r < c.row + c.height && r < out.rows; ++r)
        for (int k = c.col; k < c.col + c.width && k < out.cols; ++k)
          out.at(r, k).kind = CellKind::BoxPart;
      GridCell &cell = out.at(c.row, c.col);
      cell.kind = CellKind::Box;
      cell.instr = drawnText(*e);
      for (size_t k = 0; k < e->operands.size(); ++k)
        if (!(e->implied >> k & 1)) cell.operands.push_back(e->operands[k]);
    } else {
      ok = false;
    }
    if (!ok) {
      error = "row " + std::to_string(c.row + 1) + " column " + std::to_string(c.col + 1) +
              ": the grid has no cell for this " + c.kind + " (" + c.text + ")";
      return false;
    }
  }
  return true;
}

bool gridProgramText(const std::vector<GridPart> &parts, const DialectText &d,
                     const OperandCheck &check, const std::vector<std::string> &partEnd,
                     std::string &out, std::vector<GridError> &errors) {
  if (!d.printStmts) {
    errors.push_back({"", 0, 0, 0, std::string("the ") + d.name + " dialect prints no text"});
    return false;
  }
  bool ok = true;
  for (size_t p = 0; p < parts.size(); ++p) {
    const GridPart &part = parts[p];
    for (size_t r = 0; r < part.rungs.size(); ++r) {
      const int number = static_cast<int>(r + 1);
      Node net;
      if (!gridToNetwork(part.rungs[r], d, check, part.name, number, net, errors)) {
        ok = false;
        continue;
      }
      std::vector<Element> stmts;
      std::string err;
      if (!rungStatements(net, stmts, err, &d)) {
        errors.push_back({part.name, number, 0, 0, err});
        ok = false;
        continue;
      }
      if (!stmts.empty()) stmts[0].before = part.rungs[r].comment;
      std::vector<StmtText> t;
      for (const Element &e : stmts) t.push_back(stmtTextOf(e));
      std::string text;
      if (!d.printStmts(t, text, err)) {
        // "statement K: ...": drawn on the cell of statement K, or of the element after it (a
        // branch push has no cell of its own: the first element of its branch).
        size_t k = 0;
        if (err.rfind("statement ", 0) == 0) {
          k = static_cast<size_t>(std::max(1L, std::strtol(err.c_str() + 10, nullptr, 10)) - 1);
          if (size_t colon = err.find(": "); colon != std::string::npos)
            err = err.substr(colon + 2);
        }
        k = std::min(k, stmts.size() - 1);
        const StackRule rule = instrInfo(stmts[k].op).stack;
        if (rule == StackRule::MpsPush || rule == StackRule::MsRead || rule == StackRule::MsPop)
          err = std::string("this branch starts with contacts behind a fan-out that is not the "
                            "last, which needs a branch stack (") +
                kFanWords[0] + "/" + kFanWords[1] + "/" + kFanWords[2] + "); the " + d.name +
                " dialect has no text for it (" + err +
                "): move the branch last or give it a rung of its own";
        size_t at = k;
        while (at < stmts.size() && stmts[at].id < 0) ++at;
        if (at == stmts.size())
          for (at = k; at > 0 && stmts[at].id < 0;) --at;
        const GridRung &g = part.rungs[r];
        const StmtId id = stmts[at].id >= 0 ? stmts[at].id : 0;
        errors.push_back({part.name, number, id / g.cols, id % g.cols, err});
        ok = false;
        continue;
      }
      out += text;
    }
    if (p < partEnd.size() && !partEnd[p].empty()) out += partEnd[p] + "\n";
  }
  return ok;
}

std::string gridText(const GridRung &g) {
  constexpr size_t kW = 10;
  auto cellText = [](const GridCell &c) -> std::string {
    switch (c.kind) {
    case CellKind::Empty:
    case CellKind::BoxPart:
      return "";
    case CellKind::Wire:
      return std::string(kW, '-');
    case CellKind::ContactNO:
      return "[" + c.operand + "]";
    case CellKind::ContactNC:
      return "[/" + c.operand + "]";
    case CellKind::ContactRise:
      return "[P " + c.operand + "]";
    case CellKind::ContactFall:
      return "[N " + c.operand + "]";
    case CellKind::Coil:
      return "(" + c.operand + ")";
    case CellKind::CoilNot:
      return "(/" + c.operand + ")";
    case CellKind::Set:
      return "(S " + c.operand + ")";
    case CellKind::Reset:
      return "(R " + c.operand + ")";
    case CellKind::Box: {
      std::string t = "[" + c.instr;
      for (const std::string &o : c.operands) t += " " + o;
      return t + "]";
    }
    }
    return "";
  };
  std::string out;
  for (int r = 0; r < g.rows; ++r) {
    std::string line = "|", under = " ";
    for (int c = 0; c < g.cols; ++c) {
      if (c > 0) {
        line += r > 0 && g.link(r - 1, c) ? '+' : g.link(r, c) ? '+' : ' ';
        under += g.link(r, c) ? '|' : ' ';
      }
      std::string t = cellText(g.at(r, c));
      bool wired = g.at(r, c).kind != CellKind::Empty && g.at(r, c).kind != CellKind::BoxPart;
      if (t.size() < kW) t += std::string(kW - t.size(), wired ? '-' : ' ');
      line += t;
      under += std::string(std::max(t.size(), kW), ' ');
    }
    out += line + "|\n";
    if (r + 1 < g.rows) out += under + "\n";
  }
  return out;
}

} // namespace lj::ladder

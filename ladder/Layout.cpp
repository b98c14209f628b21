// The grid layout of rungs (Layout.h, docs/ladder-view.md "Layout rules"; research 1.9):
// series = left to right, parallel / fan-out = branches stacked downward from one column with a
// vertical link, outputs deferred and right-justified at the right rail, box inputs on row bands.
#include "ladder/Layout.h"

#include <algorithm>
#include <bit>

namespace lj::ladder {

namespace {

constexpr int kBoxWidth = 2;

/// The cell kind of an instruction drawn as written (Layout.h), or nullptr: drawn as itself.
const char *formKind(DrawAs as) {
  switch (as) {
  case DrawAs::Contact:
    return "contact-instr";
  case DrawAs::Compare:
    return "compare";
  case DrawAs::Operate:
    return "operate";
  case DrawAs::Jump:
    return "jump";
  case DrawAs::Call:
    return "call";
  case DrawAs::End:
    return "end";
  case DrawAs::Return:
    return "return";
  case DrawAs::Plain:
  case DrawAs::Hidden:
  case DrawAs::Marker: // a marker rung's statement: drawn as its text
    break;
  }
  return nullptr;
}

/// Cells an instruction drawn as written takes: a comparison block 1 row x 2 columns, an
/// operation block 1 x 4, the others 1 (modicon-neza.md 9 rule 7).
int formWidth(DrawAs as) { return as == DrawAs::Compare ? 2 : as == DrawAs::Operate ? 4 : 1; }

/// Cells an output takes at the right rail.
int outputWidth(const Node &n) {
  if (formKind(n.elem.form)) return formWidth(n.elem.form);
  return n.kind == NodeKind::Box ? kBoxWidth : 1;
}

class Placer {
public:
  Placer(RungLayout &out, const std::vector<Symbol> &symbols) : out_(out), symbols_(symbols) {}

  /// Lays `n` out with its top-left at (row, col); returns {width, height} of its inputs part
  /// (deferred outputs add no width). `last` = it ends its series (a box there is an output).
  std::pair<int, int> place(const Node &n, int row, int col, bool last) {
    switch (n.kind) {
    case NodeKind::Series:
      return series(n, row, col);
    case NodeKind::Parallel:
    case NodeKind::FanOut:
      return branches(n, row, col);
    case NodeKind::Contact: {
      Cell c = contactCell(n, row, col);
      const int w = c.width;
      add(std::move(c));
      return {w, 1};
    }
    case NodeKind::Coil:
      outputs_.push_back({&n, row, col, {}, {}});
      return {0, 1};
    case NodeKind::Box:
      return box(n, row, col, last);
    }
    return {0, 1};
  }

  void finish() {
    int outW = 0;
    for (const Output &o : outputs_) outW = std::max(outW, outputWidth(*o.node));
    int inputs = std::max(kMinInputCols, maxCol_);
    for (const Output &o : outputs_) inputs = std::max(inputs, o.col);
    out_.cols = inputs + outW;
    for (const Output &o : outputs_) {
      int w = outputWidth(*o.node);
      int at = out_.cols - w;
      std::vector<int> rows = o.pins.empty() ? std::vector<int>{o.row} : o.pins;
      for (size_t i = 0; i < rows.size(); ++i) {
        int from = o.pins.empty() ? o.col : o.pinCols[i];
        if (from < at) wire(rows[i], from, at - from);
      }
      if (o.node->kind == NodeKind::Box) {
        Cell b = boxCell(*o.node, o.row, at, boxHeight(*o.node, static_cast<int>(rows.size())));
        for (int pr : o.pins) b.pins.push_back(pr - o.row);
        b.height = std::max(b.height, o.pins.empty() ? 1 : o.pins.back() - o.row + 1);
        add(b);
      } else
        add(coilCell(*o.node, o.row, at));
    }
    for (const Cell &c : out_.cells) out_.rows = std::max(out_.rows, c.row + c.height);
    std::stable_sort(out_.cells.begin(), out_.cells.end(), [](const Cell &a, const Cell &b) {
      return a.row != b.row ? a.row < b.row : a.col < b.col;
    });
  }

private:
  struct Output {
    const Node *node;
    int row, col;
    std::vector<int> pins, pinCols; ///< box inputs: each pin's row and where its band ends
  };

  void add(Cell c) {
    maxCol_ = std::max(maxCol_, c.kind == "vlink" || c.kind == "join" ? c.col : c.col + c.width);
    out_.cells.push_back(std::move(c));
  }

  void wire(int row, int col, int width) {
    Cell c;
    c.kind = "wire";
    c.row = row;
    c.col = col;
    c.width = width;
    out_.cells.push_back(c); // wires do not widen the inputs part
    maxCol_ = std::max(maxCol_, col + width);
  }

  void vlink(int row, int col, int height, StmtId stmt) {
    Cell c;
    c.kind = "vlink";
    c.row = row;
    c.col = col;
    c.height = height;
    c.stmt = stmt;
    add(c);
  }

  std::string symbolOf(const Element &e, size_t k) const {
    if (k < e.symbols.size() && !e.symbols[k].empty()) return e.symbols[k];
    if (k < e.operands.size())
      for (const Symbol &s : symbols_)
        if (s.address == e.operands[k]) return s.name;
    return {};
  }

  Cell elemCell(const Element &e, const char *kind, int row, int col) const {
    Cell c;
    c.kind = kind;
    c.row = row;
    c.col = col;
    c.stmt = e.id;
    c.comment = e.hasComment ? e.comment : std::string();
    if (!e.operands.empty()) {
      c.text = e.operands[0];
      c.symbol = symbolOf(e, 0);
    }
    return c;
  }

  /// An instruction drawn as written: its text as written, its bit or label operand (for the
  /// cross-reference), the statements it stands for.
  Cell formCell(const Element &e, int row, int col) const {
    Cell c = elemCell(e, formKind(e.form), row, col);
    c.text = drawnText(e);
    c.symbol = e.operands.empty() ? std::string() : symbolOf(e, 0);
    c.operands = e.operands;
    c.width = formWidth(e.form);
    c.covers = e.covers;
    return c;
  }

  Cell contactCell(const Node &n, int row, int col) const {
    static const char *const kKind[] = {"contact-no", "contact-nc", "contact-rise", "contact-fall",
                                        "contact-true"};
    if (formKind(n.elem.form)) return formCell(n.elem, row, col);
    return elemCell(n.elem, kKind[static_cast<int>(n.contact)], row, col);
  }

  Cell coilCell(const Node &n, int row, int col) const {
    if (formKind(n.elem.form)) return formCell(n.elem, row, col);
    const char *kind = n.elem.op == Op::Set       ? "set"
                       : n.elem.op == Op::Reset   ? "rst"
                       : n.elem.op == Op::CoilNot ? "coil-not"
                                                  : "coil";
    return elemCell(n.elem, kind, row, col);
  }

  static int boxHeight(const Node &n, int pins) {
    if (formKind(n.elem.form)) return std::max(1, pins);
    int lines = 1 + static_cast<int>(n.elem.operands.size()) -
                std::popcount(n.elem.implied); // mnemonic + one line per drawn operand
    return std::max({1, pins, (lines + 2) / 3});
  }

  Cell boxCell(const Node &n, int row, int col, int height) const {
    if (formKind(n.elem.form)) {
      Cell c = formCell(n.elem, row, col);
      c.height = height;
      return c;
    }
    Cell c = elemCell(n.elem, "box", row, col);
    c.text = drawnText(n.elem);
    c.symbol.clear();
    for (size_t k = 0; k < n.elem.operands.size(); ++k) {
      if (n.elem.implied >> k & 1) continue; // not in the source (DialectText::implied)
      std::string s = symbolOf(n.elem, k);
      c.operands.push_back(n.elem.operands[k] + (s.empty() ? "" : "<" + s + ">"));
    }
    c.width = kBoxWidth;
    c.height = height;
    return c;
  }

  std::pair<int, int> series(const Node &s, int row, int col) {
    int c = col, h = 1;
    for (size_t i = 0; i < s.children.size(); ++i) {
      const Node &k = s.children[i];
      if (k.join == Join::Block && k.link.id >= 0) { // the ANB that joined this block
        Cell j;
        j.kind = "join";
        j.text = kBlockJoinWord;
        j.row = row;
        j.col = c;
        j.width = 0;
        j.stmt = k.link.id;
        add(j);
      }
      auto [w, hh] = place(k, row, c, i + 1 == s.children.size());
      c += w;
      h = std::max(h, hh);
    }
    return {c - col, h};
  }

  /// Parallel (OR: joined again on the right) or fan-out (each branch ends at the rail).
  std::pair<int, int> branches(const Node &p, int row, int col) {
    bool join = p.kind == NodeKind::Parallel;
    std::vector<std::pair<int, int>> at; // {row, width}
    int r = row, width = 0;
    for (const Node &b : p.children) {
      auto [w, h] = place(b, r, col, true);
      at.push_back({r, w});
      width = std::max(width, w);
      r += std::max(h, 1);
    }
    if (!p.children.empty() && p.children[0].link.id >= 0) { // the MPS at the junction
      Cell c;
      c.kind = "join";
      c.text = kFanWords[0];
      c.row = row;
      c.col = col;
      c.width = 0;
      c.stmt = p.children[0].link.id;
      add(c);
    }
    for (size_t i = 1; i < at.size(); ++i) {
      // the segment down to branch i carries its link: ORB (block join) or MRD/MPP (entry)
      int h = at[i].first - at[i - 1].first;
      vlink(at[i - 1].first, col, h, p.children[i].link.id);
      if (join) vlink(at[i - 1].first, col + width, h, -1);
    }
    if (join)
      for (auto [br, w] : at)
        if (w < width) wire(br, col + w, width - w);
    return {width, r - row};
  }

  std::pair<int, int> box(const Node &n, int row, int col, bool last) {
    Output o{&n, row, col, {}, {}};
    int r = row, inW = 0;
    std::vector<std::pair<int, int>> bands;
    for (const Node &in : n.children) {
      auto [w, h] = place(in, r, col, false);
      bands.push_back({r, w});
      inW = std::max(inW, w);
      r += std::max(h, 1);
    }
    for (auto [br, w] : bands) {
      o.pins.push_back(br);
      o.pinCols.push_back(col + w);
    }
    int pins = static_cast<int>(bands.size());
    int h = std::max(r - row, boxHeight(n, pins));
    bool output = last && instrInfo(n.elem.op).stack != StackRule::Push;
    if (output) {
      outputs_.push_back(o);
      return {inW, h};
    }
    for (auto [br, w] : bands)
      if (w < inW) wire(br, col + w, inW - w);
    Cell b = boxCell(n, row, col + inW, std::max(h, boxHeight(n, pins)));
    for (auto [br, w] : bands) b.pins.push_back(br - row);
    const int bw = b.width;
    add(b);
    return {inW + bw, h};
  }

  RungLayout &out_;
  const std::vector<Symbol> &symbols_;
  std::vector<Output> outputs_;
  int maxCol_ = 0;
};

std::string stmtLine(const Element &e) {
  std::string t = drawnText(e);
  for (size_t k = 0; k < e.operands.size() && !e.drawnWhole; ++k)
    if (!(e.implied >> k & 1))
      t += " " + (k < e.symbols.size() && !e.symbols[k].empty() ? e.symbols[k] : e.operands[k]);
  return t;
}

} // namespace

bool numbered(const Rung &rung) {
  const Rung::Kind k = rung.drawing.empty() ? rung.kind : rung.drawing[0].kind;
  return k != Rung::Kind::Marker;
}

std::string commentLine(const std::string &open, const std::string &close,
                        const std::string &text) {
  return open + " " + text + (close.empty() ? "" : " " + close);
}

RungLayout layoutRung(const Rung &rung, int number, const std::vector<Symbol> &symbols) {
  RungLayout r;
  r.number = number;
  r.comment = rung.comment;
  r.lead = rung.lead;
  // As the user wrote it where the dialect says so (Rung::drawing), else as the statements are.
  const Rung::Drawing *d = rung.drawing.empty() ? nullptr : &rung.drawing[0];
  const Rung::Kind kind = d ? d->kind : rung.kind;
  const std::vector<Element> &stmts = d ? d->stmts : rung.stmts;
  if (d) r.hidden = d->hidden;
  if (kind == Rung::Kind::Ladder) {
    r.kind = "ladder";
    Placer p(r, symbols);
    p.place(d ? d->network : rung.network, 0, 0, true);
    p.finish();
    return r;
  }
  if (kind == Rung::Kind::Marker && stmts.empty()) {
    r.kind = "hidden"; // only what the front end added on its own
    return r;
  }
  r.kind = kind == Rung::Kind::Stl ? "stl" : "marker";
  r.cols = kMinInputCols + 1;
  for (size_t i = 0; i < stmts.size(); ++i) {
    Cell c;
    c.kind = r.kind;
    c.row = static_cast<int>(i);
    c.width = r.cols;
    c.text = stmtLine(stmts[i]);
    c.comment = stmts[i].hasComment ? stmts[i].comment : std::string();
    c.stmt = stmts[i].id;
    c.covers = stmts[i].covers;
    r.cells.push_back(c);
  }
  r.rows = static_cast<int>(stmts.size());
  return r;
}

namespace {

/// One grid per program (docs/ladder-view.md "Layout rules"): every ladder rung of the program
/// gets the same right rail, the widest of the rungs up to a 2-cell box at the output column
/// (kMinInputCols + 2), so the rail does not move between coil rungs and box rungs; a rung
/// wider than that keeps its own width and scrolls. The outputs at the right rail move right
/// with it, each row they occupy (a box's input pins too) continued by wire to them.
void oneGrid(Layout &l) {
  int cols = 0;
  for (const PartLayout &p : l.parts)
    for (const RungLayout &r : p.rungs)
      if (r.kind == "ladder" && r.cols <= kMinInputCols + 2) cols = std::max(cols, r.cols);
  for (PartLayout &p : l.parts)
    for (RungLayout &r : p.rungs) {
      if (r.kind != "ladder" || r.cols >= cols) continue;
      const int delta = cols - r.cols;
      std::vector<Cell> wires;
      for (Cell &c : r.cells) {
        if (c.kind == "wire" || c.kind == "vlink" || c.kind == "join" || c.col + c.width != r.cols)
          continue;
        std::vector<int> rows{c.row};
        for (int pin : c.pins)
          if (pin > 0) rows.push_back(c.row + pin);
        for (int row : rows) {
          auto w = std::find_if(r.cells.begin(), r.cells.end(), [&](const Cell &x) {
            return x.kind == "wire" && x.row == row && x.col + x.width == c.col;
          });
          if (w != r.cells.end()) {
            w->width += delta;
          } else {
            Cell nw;
            nw.kind = "wire";
            nw.row = row;
            nw.col = c.col;
            nw.width = delta;
            wires.push_back(nw);
          }
        }
        c.col += delta;
      }
      r.cells.insert(r.cells.end(), wires.begin(), wires.end());
      r.cols = cols;
    }
}

} // namespace

/// A grid source drawn as its editor draws it (ir/Program.h GridPartDrawing): every cell where
/// the source has it, with the symbol the front end named it by.
static Layout gridLayout(const Networks &nets, Layout l) {
  for (const GridPartDrawing &gp : nets.grids) {
    PartLayout pl;
    pl.name = gp.name;
    int number = 0;
    for (const GridRungDrawing &gr : gp.rungs) {
      RungLayout rl;
      rl.number = ++number;
      rl.kind = "ladder";
      rl.comment = gr.comment;
      rl.rows = gr.rows;
      rl.cols = gr.cols;
      for (const GridCellDrawing &gc : gr.cells) {
        Cell c;
        c.row = gc.row;
        c.col = gc.col;
        c.width = gc.width;
        c.height = gc.height;
        c.kind = gc.kind;
        c.text = gc.text;
        c.operands = gc.operands;
        c.pins = gc.pins;
        c.stmt = gc.stmt;
        c.symbol = gc.symbol;
        rl.cells.push_back(std::move(c));
      }
      pl.rungs.push_back(std::move(rl));
    }
    l.parts.push_back(std::move(pl));
  }
  return l;
}

Layout layout(const Networks &nets) {
  Layout l;
  l.file = nets.file;
  if (nets.text && nets.text->commentOpen) {
    l.commentOpen = nets.text->commentOpen;
    l.commentClose = nets.text->commentClose ? nets.text->commentClose : "";
  }
  if (!nets.grids.empty()) return gridLayout(nets, std::move(l));
  for (const Part &p : nets.parts) {
    PartLayout pl;
    pl.name = p.name;
    int number = 0; // ladder and STL rungs from 1 in each part; markers have none
    for (const Rung &rung : p.rungs)
      pl.rungs.push_back(layoutRung(rung, numbered(rung) ? ++number : 0, nets.symbols));
    l.parts.push_back(std::move(pl));
  }
  oneGrid(l);
  return l;
}

} // namespace lj::ladder

// The text form of `ladderjit ladder --format text`: per part and rung, the rung comment and the
// network as an indented series/parallel drawing (docs/ladder-json.md "Text form").
#include "ladder/Text.h"

#include "ladder/Layout.h"

#include <algorithm>
#include <vector>

namespace lj::ladder {

namespace {

bool isLeaf(const Node &n) {
  return n.kind == NodeKind::Contact || n.kind == NodeKind::Coil ||
         (n.kind == NodeKind::Box && n.children.empty());
}

/// The symbol table of the networks being rendered (renderText), to name operands written as
/// plain addresses.
thread_local const std::vector<Symbol> *gSymbols = nullptr;
/// The dialect's comment syntax (DialectText::commentOpen / commentClose).
thread_local std::string gOpen = ";", gClose;

std::string comment(const std::string &c) { return commentLine(gOpen, gClose, c); }

std::string operandText(const Element &e, size_t k) {
  std::string t = e.operands[k];
  if (k < e.symbols.size() && !e.symbols[k].empty()) return t + "<" + e.symbols[k] + ">";
  if (gSymbols)
    for (const Symbol &s : *gSymbols)
      if (s.address == t) return t + "<" + s.name + ">";
  return t;
}

std::string leafText(const Node &n) {
  const Element &e = n.elem;
  std::string t;
  if (e.form != DrawAs::Plain) { // an instruction drawn as written (Rung::drawing)
    t = (n.kind == NodeKind::Contact ? "-[" : "[") + drawnText(e) +
        (n.kind == NodeKind::Contact ? "]-" : "]");
    if (n.rail) t = "|rail| " + t;
  } else if (n.kind == NodeKind::Contact) {
    static const char *const kGlyph[] = {"-[ ]-", "-[/]-", "-[P]-", "-[N]-", "-[T]-"};
    t = kGlyph[static_cast<int>(n.contact)];
    if (!e.operands.empty()) t += " " + operandText(e, 0);
  } else if (n.kind == NodeKind::Coil) {
    switch (e.op) {
    case Op::Set:
      t = "-(S)-";
      break;
    case Op::Reset:
      t = "-(R)-";
      break;
    case Op::CoilNot:
      t = "-(/)-";
      break;
    default:
      t = "-( )-";
    }
    if (!e.operands.empty()) t += " " + operandText(e, 0);
  } else {
    t = "[" + drawnText(e);
    for (size_t k = 0; k < e.operands.size() && !e.drawnWhole; ++k)
      if (!(k < 32 && (e.implied >> k & 1u))) // not in the source: drawn by no view
        t += " " + operandText(e, k);
    t += "]";
    if (n.rail) t = "|rail| " + t;
  }
  if (e.hasComment) t += "  " + comment(e.comment);
  return t;
}

using Lines = std::vector<std::string>;

/// The lines of a node. A series stacks its children (runs of leaves on one line, joined by
/// "--"); a parallel starts each branch with "|-", a fan-out with "o-"; box inputs with ":".
Lines render(const Node &n);

void indent(Lines &out, const Lines &in, const std::string &first, const std::string &rest) {
  if (in.empty()) {
    out.push_back(first + "(empty)");
    return;
  }
  for (size_t i = 0; i < in.size(); ++i) out.push_back((i == 0 ? first : rest) + in[i]);
}

Lines series(const Node &s) {
  Lines out;
  std::string run;
  auto flush = [&] {
    if (!run.empty()) out.push_back(run);
    run.clear();
  };
  for (const Node &c : s.children) {
    for (const std::string &b : c.elem.before) {
      flush();
      out.push_back(comment(b));
    }
    if (isLeaf(c)) {
      run += (run.empty() ? "" : " -- ") + leafText(c);
      if (c.elem.hasComment) flush(); // the comment ends the line
      continue;
    }
    flush();
    Lines sub = render(c);
    out.insert(out.end(), sub.begin(), sub.end());
  }
  flush();
  return out;
}

Lines render(const Node &n) {
  Lines out;
  switch (n.kind) {
  case NodeKind::Series:
    return series(n);
  case NodeKind::Parallel:
    out.push_back("parallel");
    for (const Node &b : n.children) indent(out, render(b), "|- ", "|  ");
    return out;
  case NodeKind::FanOut:
    out.push_back("fan-out");
    for (const Node &b : n.children) {
      // The branch entries are drawn with the dialect's spelling of the push/read/pop.
      const std::string kEntry[] = {"", "", std::string("(") + kFanWords[0] + ") ",
                                    std::string("(") + kFanWords[1] + ") ",
                                    std::string("(") + kFanWords[2] + ") "};
      Lines br = render(b);
      if (br.empty()) br.push_back("(empty)");
      br[0] = kEntry[static_cast<int>(b.entry)] + br[0];
      indent(out, br, "o- ", "   ");
    }
    return out;
  case NodeKind::Box:
    out.push_back(leafText(n));
    for (size_t i = 0; i < n.children.size(); ++i) {
      out.push_back("  input " + std::to_string(i + 1) + ":");
      indent(out, render(n.children[i]), "  : ", "  : ");
    }
    return out;
  default:
    out.push_back(leafText(n));
    return out;
  }
}

std::string stmtText(const Element &e) {
  std::string t = drawnText(e);
  for (size_t k = 0; k < e.operands.size() && !e.drawnWhole; ++k) t += " " + operandText(e, k);
  if (e.hasComment) t += "  " + comment(e.comment);
  return t;
}

} // namespace

/// A grid source (ir/Program.h GridPartDrawing) as text, cell by cell where its editor draws it:
/// each row between the rails `|`, 12 characters a cell, a line of `|` between rows where a
/// vertical wire joins them.
static std::string gridText(const Networks &nets) {
  constexpr size_t kW = 12;
  std::string out;
  for (const GridPartDrawing &gp : nets.grids) {
    out += "=== " + gp.name + " ===\n";
    int number = 0;
    for (const GridRungDrawing &gr : gp.rungs) {
      out += "rung " + std::to_string(++number) + "\n";
      for (const std::string &c : gr.comment) out += "  " + comment(c) + "\n";
      const size_t cols = static_cast<size_t>(std::max(gr.cols, 1));
      std::vector<std::string> rows(static_cast<size_t>(std::max(gr.rows, 0)),
                                    std::string(cols * kW, ' '));
      std::vector<std::string> links(rows.size(), std::string(cols * kW + 1, ' '));
      for (const GridCellDrawing &c : gr.cells) {
        if (c.row < 0 || static_cast<size_t>(c.row) >= rows.size() || c.col < 0 ||
            static_cast<size_t>(c.col) >= cols)
          continue;
        if (c.kind == "vlink") {
          links[static_cast<size_t>(c.row)][static_cast<size_t>(c.col) * kW] = '|';
          continue;
        }
        // How the cell's text is framed, by kind (a block, compare...: in brackets).
        static const struct {
          const char *kind, *open, *close;
        } kFrames[] = {{"wire", "", ""},
                       {"contact-no", "[ ", " ]"},
                       {"contact-nc", "[/", " ]"},
                       {"contact-rise", "[P ", "]"},
                       {"contact-fall", "[N ", "]"},
                       {"coil", "( ", " )"},
                       {"coil-not", "(/", " )"},
                       {"set", "(S ", ")"},
                       {"rst", "(R ", ")"},
                       {"operate", "{", "}"},
                       {"jump", "(", ")"},
                       {"call", "(", ")"}};
        std::string t = "[" + c.text + "]";
        for (const auto &f : kFrames)
          if (c.kind == f.kind) t = f.open + c.text + f.close; // a wire has no text
        const size_t w = static_cast<size_t>(std::max(c.width, 1)) * kW;
        std::string cell(w, '-');
        if (t.size() > w - 2) t = t.substr(0, w - 2);
        cell.replace((w - t.size()) / 2, t.size(), t);
        std::string &line = rows[static_cast<size_t>(c.row)];
        const size_t at = static_cast<size_t>(c.col) * kW;
        line.replace(at, std::min(w, line.size() - at),
                     cell.substr(0, std::min(w, line.size() - at)));
        for (int k = 1; k < c.height && static_cast<size_t>(c.row + k) < rows.size(); ++k) {
          std::string &below = rows[static_cast<size_t>(c.row + k)];
          std::string box(std::min(w, below.size() - at), ' ');
          if (!box.empty()) box.front() = box.back() = '|';
          below.replace(at, box.size(), box);
        }
      }
      size_t last = rows.size();
      while (last > 0 && rows[last - 1].find_first_not_of(' ') == std::string::npos &&
             links[last - 1].find('|') == std::string::npos &&
             (last < 2 || links[last - 2].find('|') == std::string::npos))
        --last;
      for (size_t r = 0; r < last; ++r) {
        out += "  |" + rows[r] + "|\n";
        if (links[r].find('|') != std::string::npos)
          out += "  |" + links[r].substr(0, cols * kW) + "|\n";
      }
    }
  }
  return out;
}

std::string renderText(const Networks &nets) {
  if (!nets.grids.empty()) {
    gOpen = nets.text && nets.text->commentOpen ? nets.text->commentOpen : ";";
    gClose = nets.text && nets.text->commentClose ? nets.text->commentClose : "";
    return gridText(nets);
  }
  std::string out;
  gSymbols = &nets.symbols;
  gOpen = nets.text && nets.text->commentOpen ? nets.text->commentOpen : ";";
  gClose = nets.text && nets.text->commentClose ? nets.text->commentClose : "";
  for (const Part &p : nets.parts) {
    out += "=== " + p.name + " ===\n";
    int number = 0; // ladder and STL rungs from 1 in each part (as the layout numbers them)
    for (const Rung &rung : p.rungs) {
      // As the user wrote it where the dialect says so (Rung::drawing).
      const Rung::Drawing *d = rung.drawing.empty() ? nullptr : &rung.drawing[0];
      const Rung::Kind kind = d ? d->kind : rung.kind;
      const std::vector<Element> &stmts = d ? d->stmts : rung.stmts;
      for (const std::string &m : rung.lead) out += "--- " + m + " ---\n";
      if (kind == Rung::Kind::Marker) {
        for (const std::string &c : rung.comment) out += comment(c) + "\n";
        for (const Element &e : stmts) out += "--- " + stmtText(e) + " ---\n";
        continue;
      }
      out += "rung " + std::to_string(++number) + (kind == Rung::Kind::Stl ? " (STL)" : "") + "\n";
      for (const std::string &c : rung.comment) out += "  " + comment(c) + "\n";
      if (kind == Rung::Kind::Ladder) {
        for (const std::string &l : render(d ? d->network : rung.network)) out += "  " + l + "\n";
      } else {
        for (const Element &e : stmts) {
          for (const std::string &b : e.before) out += "  " + comment(b) + "\n";
          out += "  | " + stmtText(e) + "\n";
        }
      }
    }
  }
  for (const std::string &c : nets.trailingComments) out += comment(c) + "\n";
  gSymbols = nullptr;
  return out;
}

} // namespace lj::ladder

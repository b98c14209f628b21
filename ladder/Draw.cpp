// The layout as JSON, SVG and a self-contained HTML page (docs/ladder-view.md). The SVG is
// written here, in C++, for both formats: one renderer, identical drawings in the file and the
// page; the page embeds the layout JSON and every drawn element carries data-stmt="ID" and the
// class "off", so a live view can colour elements by statement id without re-laying out.
#include "ladder/Layout.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <vector>

namespace lj::ladder {

namespace {

using json = nlohmann::ordered_json;

constexpr int kStlRH = 20; ///< one statement line of an STL rung
constexpr int kCW = 90, kRH = 60, kLM = 56, kRM = 16, kCommentH = 16, kGap = 18, kTitleH = 28;

std::string esc(const std::string &s) {
  std::string o;
  for (size_t i = 0; i < s.size(); ++i) {
    const char c = s[i];
    // U+2028 / U+2029 as references: program text never holds a raw JavaScript line end.
    if (c == '\xE2' && i + 2 < s.size() && s[i + 1] == '\x80' &&
        (s[i + 2] == '\xA8' || s[i + 2] == '\xA9')) {
      o += s[i + 2] == '\xA8' ? "&#x2028;" : "&#x2029;";
      i += 2;
      continue;
    }
    switch (c) {
    case '&':
      o += "&amp;";
      break;
    case '<':
      o += "&lt;";
      break;
    case '>':
      o += "&gt;";
      break;
    case '"':
      o += "&quot;";
      break;
    case '\'':
      o += "&#39;";
      break;
    default:
      o += c;
    }
  }
  return o;
}

std::string n(int v) { return std::to_string(v); }

class Svg {
public:
  std::string out;
  int width = 0;
  std::string commentOpen = ";", commentClose; ///< the dialect's (Layout::commentOpen)

  void line(int x1, int y1, int x2, int y2, const char *cls = nullptr) {
    out += "<line x1=\"" + n(x1) + "\" y1=\"" + n(y1) + "\" x2=\"" + n(x2) + "\" y2=\"" + n(y2) +
           "\"" + (cls ? std::string(" class=\"") + cls + "\"" : "") + "/>";
  }
  void text(int x, int y, const std::string &t, const char *cls, const char *anchor = "middle") {
    out += "<text x=\"" + n(x) + "\" y=\"" + n(y) + "\" class=\"" + cls + "\" text-anchor=\"" +
           anchor + "\">" + esc(t) + "</text>";
  }

  void cell(const Cell &c, int top) {
    int x = kLM + c.col * kCW, y = top + c.row * kRH + kRH / 2, w = c.width * kCW;
    // Wires and links name the grid point at their left end / top (`data-at="row,col"`), so the
    // live page colours each by whether power reaches that point (docs/ladder-view.md).
    if (c.kind == "wire") {
      out += "<line x1=\"" + n(x) + "\" y1=\"" + n(y) + "\" x2=\"" + n(x + w) + "\" y2=\"" + n(y) +
             "\" class=\"w\"" + atAttr(c) + "/>";
      return;
    }
    if (c.kind == "vlink") {
      out += "<g class=\"vlink off\"" + stmtAttr(c) + atAttr(c) + ">";
      line(x, y, x, y + c.height * kRH, "w");
      out += "</g>";
      return;
    }
    if (c.kind == "join") {
      out += "<g class=\"join\"" + stmtAttr(c) + "><title>" + esc(c.text) + " (id " + n(c.stmt) +
             ")</title></g>";
      return;
    }
    out += "<g class=\"el " + c.kind + " off\"" + stmtAttr(c) + "><title>" + esc(title(c)) +
           "</title>";
    int mx = x + w / 2;
    if (c.kind.rfind("contact", 0) == 0) {
      line(x, y, mx - 10, y, "w");
      line(mx + 10, y, x + w, y, "w");
      line(mx - 10, y - 12, mx - 10, y + 12, "sym");
      line(mx + 10, y - 12, mx + 10, y + 12, "sym");
      if (c.kind == "contact-nc") line(mx - 14, y + 12, mx + 14, y - 12, "sym");
      // the glyph inside the contact (a drawing mark, not an address area): edge P/N, LDT T
      const char *mark = markOf(
          c.kind,
          {{"contact-rise", "P-edge"}, {"contact-fall", "N-edge"}, {"contact-true", "T-true"}});
      if (mark) text(mx, y + 5, std::string(1, *mark), "mark");
      labels(c, mx, y);
    } else if (c.kind == "coil" || c.kind == "coil-not" || c.kind == "set" || c.kind == "rst") {
      line(x, y, mx - 12, y, "w");
      line(mx + 12, y, x + w, y, "w");
      out += "<path class=\"sym\" d=\"M" + n(mx - 6) + "," + n(y - 13) + " Q" + n(mx - 16) + "," +
             n(y) + " " + n(mx - 6) + "," + n(y + 13) + " M" + n(mx + 6) + "," + n(y - 13) + " Q" +
             n(mx + 16) + "," + n(y) + " " + n(mx + 6) + "," + n(y + 13) + "\"/>";
      const char *mark =
          markOf(c.kind, {{"set", "S-set"}, {"rst", "R-reset"}, {"coil-not", "/-negated"}});
      if (mark) text(mx, y + 5, std::string(1, *mark), "mark");
      labels(c, mx, y);
    } else if (c.kind == "box") {
      int bt = top + c.row * kRH + 4, bh = c.height * kRH - 8;
      out += "<rect class=\"box\" x=\"" + n(x + 6) + "\" y=\"" + n(bt) + "\" width=\"" + n(w - 12) +
             "\" height=\"" + n(bh) + "\"/>";
      line(x, y, x + 6, y, "w");
      for (int pr : c.pins)
        if (pr > 0) line(x, y + pr * kRH, x + 6, y + pr * kRH, "w");
      line(x + w - 6, y, x + w, y, "w");
      text(mx, bt + 14, c.text, "mn");
      for (size_t k = 0; k < c.operands.size(); ++k)
        text(mx, bt + 28 + 14 * static_cast<int>(k), c.operands[k], "op");
    } else if (c.kind == "stl") { // compact lines, one boxed listing
      int ly = top + 4 + c.row * kStlRH;
      out += "<rect class=\"stl\" x=\"" + n(x + 6) + "\" y=\"" + n(ly) + "\" width=\"" + n(w - 12) +
             "\" height=\"" + n(kStlRH) + "\"/>";
      text(x + 14, ly + 14,
           c.text +
               (c.comment.empty() ? "" : "  " + commentLine(commentOpen, commentClose, c.comment)),
           "code", "start");
    } else if (c.kind == "compare" || c.kind == "operate") {
      // A comparison contact / an operation block (modicon-neza.md 9 rule 7): a block with the
      // expression as written, 2 / 4 cells wide; wires on both sides.
      int bt = top + c.row * kRH + 16, bh = kRH - 32;
      line(x, y, x + 6, y, "w");
      line(x + w - 6, y, x + w, y, "w");
      out += "<rect class=\"box\" x=\"" + n(x + 6) + "\" y=\"" + n(bt) + "\" width=\"" + n(w - 12) +
             "\" height=\"" + n(bh) + "\"/>";
      text(mx, y + 4, c.text, "code");
      if (!c.symbol.empty()) text(mx, y + 27, c.symbol, "symb");
    } else if (c.kind == "jump" || c.kind == "call" || c.kind == "end" || c.kind == "return") {
      // An action at the right rail: a wire into a tag with its mark (`>>` for a jump as the Neza
      // ladder draws `>>%L6`), the instruction as written above it.
      line(x, y, mx - 22, y, "w");
      out += "<path class=\"sym\" d=\"M" + n(mx - 22) + "," + n(y - 10) + " L" + n(mx + 14) + "," +
             n(y - 10) + " L" + n(mx + 24) + "," + n(y) + " L" + n(mx + 14) + "," + n(y + 10) +
             " L" + n(mx - 22) + "," + n(y + 10) + " Z\"/>";
      const char *mark = c.kind == "jump"   ? ">>"
                         : c.kind == "call" ? "()"
                         : c.kind == "end"  ? "END"
                                            : "RET";
      text(mx, y + 4, mark, "mark");
      text(mx, y - 15, c.text, "addr");
    } else if (c.kind == "contact-instr") {
      // A contact-like element labelled with the instruction as written (`XOR %M2`, `N`).
      line(x, y, mx - 10, y, "w");
      line(mx + 10, y, x + w, y, "w");
      line(mx - 10, y - 12, mx - 10, y + 12, "sym");
      line(mx + 10, y - 12, mx + 10, y + 12, "sym");
      text(mx, y - 17, c.text, "addr");
      if (!c.symbol.empty()) text(mx, y + 27, c.symbol, "symb");
    } else { // a marker, and any kind this renderer does not know: its text
      text(x + w / 2, y + 5, c.text, "mn");
    }
    out += "</g>";
  }

  /// One rung with its top at `y`: comment, number, rails and cells; returns its height (no
  /// gap after it). `width` grows to the rung's right edge.
  int rung(const RungLayout &r, const std::string &partName, int y) {
    const int top = y;
    out +=
        "<g class=\"rung\" data-part=\"" + esc(partName) + "\" data-rung=\"" + n(r.number) + "\">";
    for (const std::string &m : r.lead) { // a marker written before it (FANUC COME)
      y += kRH / 2; // where a marker rung (END1) draws its text: the middle of its width
      text(kLM + (kMinInputCols + 1) * kCW / 2, y - 6, m, "mn");
    }
    for (const std::string &c : r.comment) {
      y += kCommentH;
      text(kLM + 4, y - 3, commentLine(commentOpen, commentClose, c), "cm", "start");
    }
    int h = r.kind == "stl" ? std::max(1, r.rows) * kStlRH + 8 : std::max(1, r.rows) * kRH;
    if (r.number > 0) // markers have no number
      text(kLM - 10, r.kind == "stl" ? y + 18 : y + kRH / 2 + 5, n(r.number), "num", "end");
    if (r.kind == "ladder") {
      line(kLM, y + 4, kLM, y + h - 4, "rail");
      int rx = kLM + r.cols * kCW;
      line(rx, y + 4, rx, y + h - 4, "rail");
    }
    for (const Cell &c : r.cells) cell(c, y);
    if (r.kind == "stl") text(kLM + r.cols * kCW - 10, y + 18, "STL", "tag", "end"); // on top
    int right = kLM + r.cols * kCW + kRM;
    if (r.kind == "ladder") right = std::max(right, trailingComments(r, y));
    out += "</g>";
    width = std::max(width, right);
    return y + h - top;
  }

  /// A part: its title, then each rung; returns its height.
  int part(const PartLayout &p, int top, bool title) {
    int y = top;
    if (title) {
      text(8, y + 20, p.name, "part", "start");
      y += kTitleH;
    }
    for (const RungLayout &r : p.rungs)
      if (r.kind != "hidden") y += rung(r, p.name, y) + kGap; // hidden: nothing to draw
    return y - top;
  }

private:
  /// The statements' trailing comments right of the right rail, one line per row as the HNC-8
  /// editor shows them: the comments of the row's elements in column order. Returns the right
  /// edge of the widest line (an estimate: 6.5 px per ASCII character, 11 px otherwise).
  int trailingComments(const RungLayout &r, int y) {
    std::vector<const Cell *> cs;
    for (const Cell &c : r.cells)
      if (!c.comment.empty()) cs.push_back(&c);
    std::stable_sort(cs.begin(), cs.end(), [](const Cell *a, const Cell *b) {
      return a->row != b->row ? a->row < b->row : a->col < b->col;
    });
    const int x = kLM + r.cols * kCW + 10;
    int right = 0;
    for (size_t i = 0; i < cs.size();) {
      std::string line;
      const int row = cs[i]->row;
      for (; i < cs.size() && cs[i]->row == row; ++i)
        line += (line.empty() ? "" : "  ") + cs[i]->comment;
      line = commentLine(commentOpen, commentClose, line);
      text(x, y + row * kRH + kRH / 2 + 4, line, "tc", "start");
      double w = 0;
      for (unsigned char ch : line)
        if ((ch & 0xC0) != 0x80) w += ch < 0x80 ? 6.5 : 11; // one per code point
      right = std::max(right, x + static_cast<int>(w) + kRM);
    }
    return right;
  }

  /// The mark drawn inside an element of `kind`: the first letter of its table entry.
  static const char *markOf(const std::string &kind,
                            std::initializer_list<std::pair<const char *, const char *>> table) {
    for (const auto &[k, m] : table)
      if (kind == k) return m;
    return nullptr;
  }
  static std::string stmtAttr(const Cell &c) {
    return c.stmt >= 0 ? " data-stmt=\"" + n(c.stmt) + "\"" : std::string();
  }
  static std::string atAttr(const Cell &c) {
    return " data-at=\"" + n(c.row) + "," + n(c.col) + "\"";
  }
  static std::string title(const Cell &c) {
    std::string t = c.kind + " " + c.text;
    for (const std::string &o : c.operands) t += " " + o;
    if (!c.symbol.empty()) t += " <" + c.symbol + ">";
    if (!c.comment.empty()) t += " ; " + c.comment;
    return t + " (id " + n(c.stmt) + ")";
  }
  void labels(const Cell &c, int mx, int y) {
    text(mx, y - 17, c.text, "addr");
    if (!c.symbol.empty()) text(mx, y + 27, c.symbol, "symb");
  }
};

/// A renderer with the layout's comment syntax.
Svg svgOf(const Layout &l) {
  Svg s;
  s.commentOpen = l.commentOpen;
  s.commentClose = l.commentClose;
  return s;
}

const char *kStyle =
    ".lad line.w,.lad path.sym,.lad line.sym{stroke:#222;stroke-width:1.6;fill:none}"
    ".lad line.rail{stroke:#000;stroke-width:3}"
    ".lad rect.box{fill:#fffbe8;stroke:#222;stroke-width:1.6}"
    ".lad rect.stl{fill:#f1f1f1;stroke:#f1f1f1}"
    ".lad text{font-family:'DejaVu Sans','WenQuanYi Zen Hei',sans-serif;font-size:12px;fill:#111}"
    ".lad text.addr{font-weight:bold}.lad text.symb{fill:#2a5db0;font-size:11px}"
    ".lad text.mark{font-weight:bold;font-size:13px}.lad text.mn{font-weight:bold}"
    ".lad text.op{font-size:11px}.lad text.code{font-family:'DejaVu Sans Mono',monospace}"
    ".lad text.cm{fill:#2e7d32;font-style:italic}.lad text.num{fill:#666}"
    ".lad text.tc{fill:#2e7d32;font-style:italic;font-size:11px}"
    ".lad text.part{font-size:16px;font-weight:bold}.lad text.tag{fill:#999;font-size:10px}"
    ".lad g.on line.w,.lad g.on line.sym,.lad g.on path.sym{stroke:#0a0;stroke-width:2.6}"
    ".lad g.el:hover line,.lad g.el:hover path,.lad g.el:hover rect{stroke:#d35400}";

std::string svgDoc(const std::string &body, int w, int h) {
  return "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"lad\" width=\"" + n(w) +
         "\" height=\"" + n(h) + "\" viewBox=\"0 0 " + n(w) + " " + n(h) + "\"><style>" + kStyle +
         "</style><rect width=\"100%\" height=\"100%\" fill=\"#fff\"/>" + body + "</svg>";
}

} // namespace

std::string layoutJson(const Layout &l, bool compact) {
  json j;
  j["format"] = "ladderjit-ladder-layout";
  j["version"] = 1;
  j["file"] = l.file;
  json parts = json::array();
  for (const PartLayout &p : l.parts) {
    json rungs = json::array();
    for (const RungLayout &r : p.rungs) {
      json cells = json::array();
      for (const Cell &c : r.cells) {
        json jc{{"row", c.row}, {"col", c.col}, {"width", c.width}};
        if (c.height != 1) jc["height"] = c.height;
        jc["kind"] = c.kind;
        if (!c.text.empty()) jc["text"] = c.text;
        if (!c.symbol.empty()) jc["symbol"] = c.symbol;
        if (!c.operands.empty()) jc["operands"] = c.operands;
        if (!c.pins.empty()) jc["pins"] = c.pins;
        if (!c.comment.empty()) jc["comment"] = c.comment;
        if (c.stmt >= 0) jc["stmt"] = c.stmt;
        if (!c.covers.empty()) jc["covers"] = c.covers;
        cells.push_back(jc);
      }
      json rung{{"number", r.number}, {"kind", r.kind}, {"comment", r.comment},
                {"cols", r.cols},     {"rows", r.rows}, {"cells", cells}};
      if (!r.hidden.empty()) rung["hidden"] = r.hidden;
      if (!r.lead.empty()) rung["lead"] = r.lead;
      rungs.push_back(std::move(rung));
    }
    parts.push_back({{"name", p.name}, {"rungs", rungs}});
  }
  j["parts"] = parts;
  return j.dump(compact ? -1 : 1, ' ', false, json::error_handler_t::replace) + "\n";
}

std::string renderSvg(const Layout &l) {
  Svg s = svgOf(l);
  int y = 8;
  for (const PartLayout &p : l.parts) y += s.part(p, y, true) + kGap;
  return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n" + svgDoc(s.out, std::max(s.width, 200), y) +
         "\n";
}

namespace {

/// JSON text inside a <script> element: no '<' at all (as \u003c, which JSON reads back as '<'),
/// so program data (a comment "<!--<script>", "</script>", a symbol, a file name) can neither end
/// the element nor put the HTML parser into its (double-)escaped script states, which only a
/// '<' enters; U+2028 and U+2029 as \u2028 and \u2029 (line ends to JavaScript). '<' occurs in
/// JSON only inside strings, so the text stays the same JSON. '>' and '&' are inert in a script
/// element and stay (the rungs' SVG text is most of a large page).
std::string scriptSafe(const std::string &data) {
  std::string out;
  out.reserve(data.size() + data.size() / 8);
  for (size_t i = 0; i < data.size(); ++i) {
    const char c = data[i];
    if (c == '<') {
      out += "\\u003c";
    } else if (c == '\xE2' && i + 2 < data.size() && data[i + 1] == '\x80' &&
               (data[i + 2] == '\xA8' || data[i + 2] == '\xA9')) {
      out += data[i + 2] == '\xA8' ? "\\u2028" : "\\u2029";
      i += 2;
    } else {
      out += c;
    }
  }
  return out;
}

std::string tabOf(const PartLayout &p, size_t i) {
  // The rungs drawn: a hidden one (only what the front end added) is not counted.
  const auto drawn = std::count_if(p.rungs.begin(), p.rungs.end(),
                                   [](const RungLayout &r) { return r.kind != "hidden"; });
  return "<button class=\"tab\" data-for=\"part-" + n(static_cast<int>(i)) + "\">" + esc(p.name) +
         " <small>(" + n(static_cast<int>(drawn)) + ")</small></button>";
}

/// The page around the parts: header, tabs, the sections, the layout JSON, the tab script.
std::string page(const Layout &l, const std::string &tabs, const std::string &sections,
                 const std::string &head, const std::string &data, const std::string &script) {
  return "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>" + esc(l.file) +
         " - ladder</title><style>"
         "body{margin:0;font-family:'DejaVu Sans',sans-serif;background:#fafafa}"
         "header{padding:6px 10px;background:#263238;color:#fff}header b{margin-right:12px}"
         "nav{padding:4px 6px;background:#eceff1;border-bottom:1px solid #ccc}"
         ".tab{border:1px solid #bbb;background:#fff;margin:2px;padding:4px 10px;cursor:pointer}"
         ".tab.sel{background:#1565c0;color:#fff}"
         "section.part{display:none;overflow:auto;padding:6px}section.part.sel{display:block}"
         "#info{font-size:12px;color:#444;margin-left:8px}" +
         head + "</style></head><body><header><b>" + esc(l.file) +
         "</b><span id=\"info\"></span></header><nav>" + tabs + "</nav><main>" + sections +
         "</main>" + data + "<script type=\"application/json\" id=\"ladder-layout\">" +
         scriptSafe(layoutJson(l, !data.empty())) +
         "</script><script>"
         "(function(){var tabs=document.querySelectorAll('.tab');"
         "function "
         "show(id){tabs.forEach(function(t){t.classList.toggle('sel',t.dataset.for===id)});"
         "document.querySelectorAll('section.part').forEach(function(s){"
         "s.classList.toggle('sel',s.id===id)})}"
         "tabs.forEach(function(t){t.addEventListener('click',function(){show(t.dataset.for);"
         "if(history.replaceState)history.replaceState(null,'','#'+t.dataset.for)})});"
         "var "
         // the page opens on the part named in its address, else on PLC1 (the first level, not
         // the init part), else on the first part
         "h=location.hash.slice(1),p1=document.querySelector('section.part[data-part=\"PLC1\"]');"
         "show(document.getElementById(h)?h:p1?p1.id:(tabs[0]?tabs[0].dataset.for:''));"
         "window.ladder={layout:JSON.parse(document.getElementById('ladder-layout').textContent),"
         "setState:function(id,on){document.querySelectorAll('[data-stmt=\"'+id+'\"]').forEach("
         "function(e){e.classList.toggle('on',!!on);e.classList.toggle('off',!on)})}};"
         "document.addEventListener('mouseover',function(ev){var "
         "g=ev.target.closest&&ev.target.closest('[data-stmt]');"
         "if(g)document.getElementById('info').textContent=g.querySelector('title')?g."
         "querySelector('title').textContent:''});"
         "})();</script>" +
         (script.empty() ? std::string() : "<script>" + script + "</script>") + "</body></html>\n";
}

} // namespace

std::string renderHtml(const Layout &l, const std::string &liveHead,
                       const std::string &liveScript) {
  std::string tabs, sections;
  for (size_t i = 0; i < l.parts.size(); ++i) {
    const PartLayout &p = l.parts[i];
    Svg s = svgOf(l);
    int h = s.part(p, 8, false) + 8;
    tabs += tabOf(p, i);
    sections += "<section class=\"part\" id=\"part-" + n(static_cast<int>(i)) + "\" data-part=\"" +
                esc(p.name) + "\">" + svgDoc(s.out, std::max(s.width, 200), h) + "</section>";
  }
  return page(l, tabs, sections, liveHead, {}, liveScript);
}

std::string renderLazyHtml(const Layout &l, const std::string &liveHead,
                           const std::string &liveScript) {
  // Each rung: an empty placeholder of its drawn size in the page, its SVG in one JSON array
  // (per part, per rung) that the live script draws from when the placeholder nears the view.
  std::string tabs, sections;
  json svgs = json::array();
  for (size_t i = 0; i < l.parts.size(); ++i) {
    const PartLayout &p = l.parts[i];
    tabs += tabOf(p, i);
    sections += "<section class=\"part\" id=\"part-" + n(static_cast<int>(i)) + "\" data-part=\"" +
                esc(p.name) + "\">";
    json part = json::array();
    for (size_t k = 0; k < p.rungs.size(); ++k) {
      Svg s = svgOf(l);
      int h = s.rung(p.rungs[k], p.name, 0);
      int w = std::max(s.width, 200);
      std::string svg = "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"lad\" width=\"" + n(w) +
                        "\" height=\"" + n(h) + "\">" + s.out + "</svg>";
      // Attributes in single quotes: the JSON string needs no escapes (text has ' as &#39;).
      std::replace(svg.begin(), svg.end(), '"', '\'');
      part.push_back(std::move(svg));
      sections += "<div class=\"rg\" data-p=\"" + n(static_cast<int>(i)) + "\" data-r=\"" +
                  n(static_cast<int>(k)) + "\" style=\"width:" + n(w) + "px;height:" + n(h) +
                  "px\"></div>";
    }
    sections += "</section>";
    svgs.push_back(std::move(part));
  }
  std::string head =
      std::string(kStyle) + ".rg{margin-bottom:" + n(kGap) + "px}.rg svg{display:block}" + liveHead;
  return page(l, tabs, sections, head,
              "<script type=\"application/json\" id=\"ladder-rungs\">" +
                  scriptSafe(svgs.dump(-1, ' ', false, json::error_handler_t::replace)) +
                  "</script>",
              liveScript);
}

} // namespace lj::ladder

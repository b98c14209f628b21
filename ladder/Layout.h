// Rungs on a grid as the HNC-8 ladder editor draws them (docs/ladder-view.md "Layout rules"):
// left and right power rails, contacts in series left to right, parallel branches below with
// vertical links, outputs right-justified at the right rail, function boxes spanning cells.
// Every drawn element keeps its statement id. Built from networks (Network.h); depends on them
// and the IR only. The SVG/HTML writers (Draw.cpp) and the layout JSON walk these cells.
#pragma once

#include "ladder/Network.h"

#include <string>
#include <vector>

namespace lj::ladder {

/// One placed thing. Grid units: `col`/`row` of the top-left cell, `width`/`height` in cells.
/// Kinds: contact-no|nc|rise|fall|true, coil, coil-not, set, rst, box, wire (horizontal, from
/// `col` over `width` cells on `row`), vlink (vertical line on the boundary left of `col`, from
/// the middle of `row` down `height` rows), join (an ANB: no drawing of its own), stl (one
/// statement of a rung with no drawable form), marker (END1, SUB, RET...). An instruction the
/// front end made into other statements is drawn as written (Rung::drawing, DrawAs):
/// contact-instr (`XOR %M2`, `N` in a series), compare (`%MW0 > 5`, 2 cells), operate
/// (`%MW1 := %MW1 + 1`, 4 cells), jump (`JMPC %L1`), call (`SR0`), end (`ENDC`), return
/// (`RETC`); `text` is the instruction as written.
struct Cell {
  int row = 0, col = 0, width = 1, height = 1;
  std::string kind;
  std::string text;                  ///< address (contact/coil), mnemonic (box), statement (stl)
  std::string symbol;                ///< symbol name of the address, or empty
  std::vector<std::string> operands; ///< box: operand texts (symbol appended as "<name>")
  std::vector<int> pins;             ///< box with inputs: each input pin's row, from `row`
  std::string comment;               ///< the element's trailing comment
  StmtId stmt = -1;
  /// The other statements the front end made of the instruction this cell draws as written.
  std::vector<StmtId> covers;
};

struct RungLayout {
  /// 1-based within the part, counting ladder and stl rungs only; 0: a marker or hidden rung
  /// (END1, `%L1:`, `SR0:`), which has no number.
  int number = 0;
  /// ladder | stl | marker | hidden (only statements the front end added on its own: nothing
  /// drawn, their ids in `hidden`)
  std::string kind;
  std::vector<std::string> comment; ///< the rung comment block
  int cols = 0, rows = 0;           ///< grid size between the rails
  std::vector<Cell> cells;
  std::vector<StmtId> hidden; ///< statements the front end added on its own: drawn by no cell
  /// Markers drawn before the rung (Rung::lead: FANUC `COME` written before it).
  std::vector<std::string> lead;
};

struct PartLayout {
  std::string name;
  std::vector<RungLayout> rungs;
};

struct Layout {
  std::string file;
  std::vector<PartLayout> parts;
  /// How a comment is drawn: in the dialect's syntax (DialectText::commentOpen / commentClose).
  std::string commentOpen = ";", commentClose;
};

/// A comment line as the dialect writes it (`; text`, `(* text *)`).
std::string commentLine(const std::string &open, const std::string &close, const std::string &text);

/// Columns left for inputs before the output column(s), at least (the editor's fixed grid).
constexpr int kMinInputCols = 7;

Layout layout(const Networks &nets);
/// `rung` drawn (as its user wrote it: Rung::drawing when set), numbered `number`.
RungLayout layoutRung(const Rung &rung, int number, const std::vector<Symbol> &symbols);
/// Whether `rung` is drawn with a number (a ladder or STL rung as drawn, not a marker).
bool numbered(const Rung &rung);

/// The layout JSON (docs/ladder-view.md "Layout JSON"): per part and rung, the cells. `compact`:
/// on one line (the live page), else indented.
std::string layoutJson(const Layout &l, bool compact = false);

/// One self-contained SVG of every part, stacked (docs/ladder-view.md).
std::string renderSvg(const Layout &l);
/// One self-contained HTML page: a tab per part, inline CSS/JS/SVG, the layout JSON embedded.
/// `liveHead` / `liveScript` (the live view, LiveScript.cpp) go into a <style> of the head and a
/// <script> after the page's own; empty: the static drawing.
std::string renderHtml(const Layout &l, const std::string &liveHead = {},
                       const std::string &liveScript = {});

/// The live page of `serve --http`: as renderHtml, but each rung is an empty placeholder of its
/// size and its SVG sits in the JSON array `ladder-rungs` (per part, per rung) for the live script
/// to draw only the rungs in or near the view (docs/ladder-view.md "Large programs").
std::string renderLazyHtml(const Layout &l, const std::string &liveHead,
                           const std::string &liveScript);

/// The live view's CSS and JS (`serve --http`, docs/ladder-view.md "Live view").
std::string liveCss();
std::string liveScript();
/// The ladder editor of the live page (docs/ladder-edit.md "The page editor"), sent after the
/// live script when the page may edit (not under --http-read-only).
std::string editorCss();
std::string editorScript();
/// The signal trace panel of the live page (docs/trace.md "Page"), sent after the live script.
std::string traceCss();
std::string traceScript();

} // namespace lj::ladder

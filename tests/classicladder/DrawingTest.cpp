// A ClassicLadder project is drawn as ClassicLadder's editor draws it (docs/classicladder.md
// "Ladder view"; issue 31 scope 1): every element in its own cell of the rung's grid, a block
// over the cells it covers, the vertical wires where the cells have them, one part per section;
// the networks (the program: JSON, statements) stay what the front end made.
#include "ladder/Json.h"
#include "ladder/Layout.h"
#include "ladder/Text.h"
#include "pipeline/Compile.h"

#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <vector>

using namespace lj;

namespace {

/// A rung file: rows of 10 cells (missing cells empty), its label and #NEXTRUNG.
std::string rungFile(int n, int next, const std::string &label,
                     const std::vector<std::vector<std::string>> &rows) {
  std::string s = "_FILE-rung_" + std::to_string(n) + ".csv\n#VER=2.0\n#LABEL=" + label +
                  "\n#COMMENT=\n#NEXTRUNG=" + std::to_string(next) + "\n";
  for (size_t y = 0; y < 6; ++y)
    for (size_t x = 0; x < 10; ++x) {
      const bool have = y < rows.size() && x < rows[y].size() && !rows[y][x].empty();
      s += (have ? rows[y][x] : std::string("0-0-0/0")) + (x < 9 ? " , " : "\n");
    }
  return s + "_/FILE-rung_" + std::to_string(n) + ".csv\n";
}

std::vector<std::string> row(std::vector<std::pair<int, std::string>> at) {
  std::vector<std::string> r(10, "");
  for (auto &[x, c] : at) r[static_cast<size_t>(x)] = c;
  return r;
}

/// A row wired by connections from column `from` to column 8, `last` in column 9 and the
/// cells of `at` (which may replace connections).
std::vector<std::string> wired(int from, const std::string &last,
                               std::vector<std::pair<int, std::string>> at) {
  std::vector<std::string> r(10, "");
  for (int x = from; x < 9; ++x) r[static_cast<size_t>(x)] = "9-0-0/0";
  r[9] = last;
  for (auto &[x, c] : at) r[static_cast<size_t>(x)] = c;
  return r;
}

const ladder::Cell *at(const ladder::RungLayout &r, int row, int col, const std::string &kind) {
  for (const ladder::Cell &c : r.cells)
    if (c.row == row && c.col == col && c.kind == kind) return &c;
  return nullptr;
}

} // namespace

/// The project of RungsAreDrawnOnTheirGrid (described there).
std::string drawingProject() {
  std::string p = "_FILES_CLASSICLADDER\n_FILE-sections.csv\n#VER=1.0\n#NAME000=Pump\n"
                  "#NAME001=Sub\n000,0,-1,0,1,0\n001,0,0,2,2,0\n_/FILE-sections.csv\n";
  std::vector<std::string> r0 = wired(1, "50-0-60/0", {{0, "1-0-50/0"}});
  std::vector<std::string> r1 =
      wired(4, "52-0-60/1", {{0, "2-0-50/1"}, {1, "9-1-0/0"}, {2, "99-0-0/0"}, {3, "13-0-0/0"}});
  std::vector<std::string> r2 = row({{2, "99-0-0/0"}, {3, "99-0-0/0"}});
  p += rungFile(0, 1, "R0", {r0, r1, r2});
  p += rungFile(1, -1, "R1",
                {wired(3, "54-0-0/0", {{0, "99-0-0/0"}, {1, "99-0-0/0"}, {2, "20-0-0/0"}})});
  p += rungFile(2, -1, "S", {wired(1, "50-0-60/2", {{0, "1-0-0/0"}})});
  p += "_FILE-arithmetic_expressions.csv\n0000,@270/0@>5\n_/FILE-arithmetic_expressions.csv\n";
  p += "_FILE-timers_iec.csv\n1,10,0\n_/FILE-timers_iec.csv\n";
  p += "_FILE-symbols.csv\n%I0,START,start key\n_/FILE-symbols.csv\n";
  p += "_/FILES_CLASSICLADDER\n";
  return p;
}

TEST(ClDrawing, RungsAreDrawnOnTheirGrid) {
  // Main section "Pump": rung 0 (label R0): %I0 NO -- wires -- coil %Q0 on row 0; %I1 NC on
  // row 1 in column 0, joined to row 0 by the vertical wire on the left of cell (1, 1), then a
  // wire into it; an IEC timer %TM0 whose alive cell is (3, 1) with its dead cells (2, 1),
  // (2, 2), (3, 2) (reference 3.2: the block covers 2 x 2 cells) and its output wired to a
  // set coil %Q1. Rung 1 (label R1): a compare block over columns 0-2 (alive at 2) and a jump
  // coil back to R0. Section "Sub" is SR0 with one rung: %B0 NC -> call... no: %B0 -> %Q2.
  const std::string p = drawingProject();
  Diagnostics d("t.clp");
  std::optional<VerifiedProgram> prog = pipeline::compileClp(p, "t.clp", VerifyOptions{}, d);
  ASSERT_TRUE(prog) << d.render();
  const ladder::Networks nets = ladder::fromProgram(*prog);
  EXPECT_FALSE(nets.parts.empty()) << "the networks stay the program";
  const ladder::Layout l = ladder::layout(nets);
  ASSERT_EQ(l.parts.size(), 2u);
  EXPECT_EQ(l.parts[0].name, "Pump");
  EXPECT_EQ(l.parts[1].name, "SR0 Sub");
  ASSERT_EQ(l.parts[0].rungs.size(), 2u);
  const ladder::RungLayout &a = l.parts[0].rungs[0];
  EXPECT_EQ(a.rows, 6);
  EXPECT_EQ(a.cols, 10);
  EXPECT_EQ(a.comment, std::vector<std::string>{"R0"});
  const ladder::Cell *i0 = at(a, 0, 0, "contact-no");
  ASSERT_TRUE(i0);
  EXPECT_EQ(i0->text, "%I0");
  EXPECT_EQ(i0->symbol, "START") << "symbols.csv names the variable";
  EXPECT_GE(i0->stmt, 0);
  EXPECT_TRUE(at(a, 0, 4, "wire"));
  const ladder::Cell *q0 = at(a, 0, 9, "coil");
  ASSERT_TRUE(q0);
  EXPECT_EQ(q0->text, "%Q0");
  EXPECT_GE(q0->stmt, 0);
  EXPECT_TRUE(at(a, 1, 0, "contact-nc"));
  const ladder::Cell *link = at(a, 0, 1, "vlink");
  ASSERT_TRUE(link) << "the vertical wire on the left of cell (1, 1) joins rows 0 and 1";
  EXPECT_EQ(link->height, 1);
  const ladder::Cell *tm = at(a, 1, 2, "box");
  ASSERT_TRUE(tm) << "the IEC timer over columns 2-3, rows 1-2";
  EXPECT_EQ(tm->text, "%TM0");
  EXPECT_EQ(tm->width, 2);
  EXPECT_EQ(tm->height, 2);
  EXPECT_GE(tm->stmt, 0);
  EXPECT_EQ(at(a, 1, 9, "set")->text, "%Q1");
  EXPECT_FALSE(at(a, 2, 2, "box")) << "a block's dead cells draw nothing";
  const ladder::RungLayout &b = l.parts[0].rungs[1];
  const ladder::Cell *cmp = at(b, 0, 0, "compare");
  ASSERT_TRUE(cmp) << "the compare block over columns 0-2";
  EXPECT_EQ(cmp->width, 3);
  EXPECT_EQ(cmp->text, "%IW0>5") << "the expression as the editor shows it";
  const ladder::Cell *j = at(b, 0, 9, "jump");
  ASSERT_TRUE(j);
  EXPECT_EQ(j->text, "JUMP R0");
  EXPECT_TRUE(at(l.parts[1].rungs[0], 0, 9, "coil"));
  // The text form draws the same grid.
  const std::string text = ladder::renderText(nets);
  EXPECT_NE(text.find("=== Pump ==="), std::string::npos) << text;
  EXPECT_NE(text.find("[ %I0 ]"), std::string::npos) << text;
  EXPECT_NE(text.find("[%TM0]"), std::string::npos) << text;
  EXPECT_NE(text.find("(JUMP R0)"), std::string::npos) << text;
}

// The network JSON of a project (`ladderjit ladder X.clp --format json`, CLI.md: accepted back as
// PROGRAM) reads back as the project itself while its networks are unchanged; ClassicLadder
// prints no program text, so an edited one is refused with the reason.
TEST(ClDrawing, UnchangedJsonReadsBackAsTheProject) {
  const std::string p = drawingProject();
  Diagnostics d("t.clp");
  std::optional<VerifiedProgram> prog = pipeline::compileClp(p, "t.clp", VerifyOptions{}, d);
  ASSERT_TRUE(prog) << d.render();
  const std::string json = ladder::writeJson(ladder::fromProgram(*prog), p);
  ladder::Networks back;
  std::string error, text;
  ASSERT_TRUE(ladder::readJson(json, back, error, *prog->dialect)) << error;
  ASSERT_TRUE(ladder::programText(back, *prog, p, text, error)) << error;
  EXPECT_EQ(text, p);
  std::string edited = json;
  const size_t at = edited.find("\"%I0\"");
  ASSERT_NE(at, std::string::npos);
  edited.replace(at, 5, "\"%I7\"");
  ASSERT_TRUE(ladder::readJson(edited, back, error, *prog->dialect)) << error;
  EXPECT_FALSE(ladder::programText(back, *prog, p, text, error));
  EXPECT_NE(error.find("prints no program text"), std::string::npos) << error;
}

// The verifier's double-coil warning (双线圈) names what the user wrote twice (%Q0 from two
// coils), never the front end's own scratch: two compare blocks both use the scratch bit their
// comparison goes through (before, `warning: double coil: cell319999` on 924.clp).
TEST(ClDrawing, DoubleCoilWarningsNameUserVariablesOnly) {
  std::string p = "_FILES_CLASSICLADDER\n_FILE-sections.csv\n#VER=1.0\n#NAME000=Main\n"
                  "000,0,-1,0,0,0\n_/FILE-sections.csv\n";
  p += rungFile(0, -1, "R0",
                {wired(3, "50-0-60/0", {{0, "99-0-0/0"}, {1, "99-0-0/0"}, {2, "20-0-0/0"}}),
                 wired(3, "50-0-60/1", {{0, "99-0-0/0"}, {1, "99-0-0/0"}, {2, "20-0-0/1"}}),
                 wired(1, "50-0-60/1", {{0, "1-0-50/0"}})});
  p += "_FILE-arithmetic_expressions.csv\n0000,@270/0@>5\n0001,@270/1@<3\n"
       "_/FILE-arithmetic_expressions.csv\n_/FILES_CLASSICLADDER\n";
  Diagnostics d("t.clp");
  std::optional<VerifiedProgram> prog = pipeline::compileClp(p, "t.clp", VerifyOptions{}, d);
  ASSERT_TRUE(prog) << d.render();
  const std::string text = d.render();
  EXPECT_NE(text.find("double coil: %Q1"), std::string::npos) << text;
  EXPECT_EQ(text.find("cell"), std::string::npos) << text;
  EXPECT_EQ(text.find("%~"), std::string::npos) << text;
}

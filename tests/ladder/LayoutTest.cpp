// Golden layouts of the manual's ORB / ANB / MPS examples (hnc8-core.md 4.9 and 4.10). The
// reference keeps the STL listings and the tables but not the ladder figures (4.10 says "the
// ladder figures are lost"), so each expected position below is written from the listing's
// structure read as the manual's drawing convention (series left to right, each LD-block of an
// ORB on its own row below, an MPS/MRD/MPP row per branch, coils at the right rail; research
// 1.9), line by line as cited. Only elements and links are listed; wires are checked by count.
#include "ladder/Layout.h"
#include "frontends/hnc8/FrontEnd.h"
#include "pipeline/Compile.h"

#include <gtest/gtest.h>

#include <set>

namespace lj::ladder {
namespace {

RungLayout one(const std::string &stl) {
  Diagnostics d("t.stl");
  std::optional<VerifiedProgram> p = pipeline::compileStl(stl, "t.stl", VerifyOptions{}, d);
  EXPECT_TRUE(p) << d.render();
  if (!p) return {};
  Layout l = layout(fromProgram(*p));
  EXPECT_EQ(l.parts.size(), 1u);
  EXPECT_EQ(l.parts[0].rungs.size(), 1u);
  return l.parts[0].rungs[0];
}

/// "kind row col text stmt" for elements, "vlink row col height stmt" for links with an id.
std::vector<std::string> shape(const RungLayout &r) {
  std::vector<std::string> out;
  for (const Cell &c : r.cells) {
    if (c.kind == "wire" || (c.kind == "vlink" && c.stmt < 0)) continue;
    if (c.kind == "vlink" || c.kind == "join")
      out.push_back(c.kind + " " + std::to_string(c.row) + " " + std::to_string(c.col) + " " +
                    std::to_string(c.kind == "vlink" ? c.height : 0) + " " +
                    std::to_string(c.stmt));
    else
      out.push_back(c.kind + " " + std::to_string(c.row) + " " + std::to_string(c.col) + " " +
                    c.text + " " + std::to_string(c.stmt));
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<std::string> sorted(std::vector<std::string> v) {
  std::sort(v.begin(), v.end());
  return v;
}

TEST(LadderLayout, OrbExample) {
  // hnc8-core.md 4.9 ORB (000:L935-996): three series blocks A·B, D·E, F·G, one per row, joined
  // at the rails' side by the two ORBs (steps 5 and 8), coil H = R10.1 at the right rail.
  RungLayout r = one("LD X1.0\nAND X2.0\nLD X1.1\nAND X2.1\nORB\nLD X1.2\nAND X2.2\nORB\n"
                     "OUT R10.1\n");
  EXPECT_EQ(shape(r), sorted({"contact-no 0 0 X1.0 0", "contact-no 0 1 X2.0 1",
                              "contact-no 1 0 X1.1 2", "contact-no 1 1 X2.1 3",
                              "vlink 0 0 1 4", // step 5 ORB: row 0 down to row 1
                              "contact-no 2 0 X1.2 5", "contact-no 2 1 X2.2 6",
                              "vlink 1 0 1 7", // step 8 ORB: row 1 down to row 2
                              "coil 0 7 R10.1 8"}));
  EXPECT_EQ(r.rows, 3);
  EXPECT_EQ(r.cols, kMinInputCols + 1);
}

TEST(LadderLayout, AnbExample) {
  // hnc8-core.md 4.9 ANB (000:L997-1066): (A+B) in the first column, then the ORB block
  // C·D / E·F / +G in columns 1-2 joined in series by the ANB (step 9), H = X2.2 in parallel
  // with all of it on row 3 (step 10), I = R10.0 at the rail.
  RungLayout r = one("LD X1.0\nOR X1.1\nLD X2.0\nAND X4.4\nLD X1.2\nAND X2.1\nORB\nOR X1.3\n"
                     "ANB\nOR X2.2\nOUT R10.0\n");
  EXPECT_EQ(shape(r),
            sorted({"contact-no 0 0 X1.0 0", "contact-no 1 0 X1.1 1",
                    "join 0 1 0 8", // step 9 ANB joins the block starting at column 1
                    "contact-no 0 1 X2.0 2", "contact-no 0 2 X4.4 3", "contact-no 1 1 X1.2 4",
                    "contact-no 1 2 X2.1 5",
                    "vlink 0 1 1 6", // step 7 ORB
                    "contact-no 2 1 X1.3 7", "contact-no 3 0 X2.2 9", "coil 0 7 R10.0 10"}));
  EXPECT_EQ(r.rows, 4);
}

TEST(LadderLayout, Mps1Example) {
  // hnc8-core.md 4.10 MPS-1 (000:L1095-1117): X1.0 then the MPS junction at column 1; branch
  // rows: Y1.0 (X1.1+X1.2, rows 0-1), MRD Y0.2 (X1.3·X1.4 + X1.5·X1.6, rows 2-3), MPP X1.7
  // with Y0.3 on row 4 and X2.3+X2.4 to Y0.4 below it (rows 5-6).
  RungLayout r = one("LD X1.0\nMPS\nLD X1.1\nOR X1.2\nANB\nOUT Y1.0\nMRD\nLD X1.3\nAND X1.4\n"
                     "LD X1.5\nAND X1.6\nORB\nANB\nOUT Y0.2\nMPP\nAND X1.7\nOUT Y0.3\nLD X2.3\n"
                     "OR X2.4\nANB\nOUT Y0.4\n");
  EXPECT_EQ(shape(r),
            sorted({"contact-no 0 0 X1.0 0",  "join 0 1 0 1", // MPS
                    "join 0 1 0 4",           "contact-no 0 1 X1.1 2",  "contact-no 1 1 X1.2 3",
                    "coil 0 7 Y1.0 5",
                    "vlink 0 1 2 6", // MRD: row 0 down to row 2
                    "join 2 1 0 12",          "contact-no 2 1 X1.3 7",  "contact-no 2 2 X1.4 8",
                    "contact-no 3 1 X1.5 9",  "contact-no 3 2 X1.6 10", "vlink 2 1 1 11", // ORB
                    "coil 2 7 Y0.2 13",       "vlink 2 1 2 14", // MPP: row 2 to 4
                    "contact-no 4 1 X1.7 15", "coil 4 7 Y0.3 16",       "join 5 2 0 19",
                    "contact-no 5 2 X2.3 17", "contact-no 6 2 X2.4 18", "coil 5 7 Y0.4 20"}));
  EXPECT_EQ(r.rows, 7);
}

TEST(LadderLayout, Mps3ExampleNestsFourDeep) {
  // hnc8-core.md 4.10 MPS-3 (000:L1140-1160): X1.0..X1.4 in series on row 0 with an MPS at
  // each of columns 1-4; the four MPPs drop to rows 1-4, each straight to its coil at the rail.
  RungLayout r = one("LD X1.0\nMPS\nAND X1.1\nMPS\nAND X1.2\nMPS\nAND X1.3\nMPS\nAND X1.4\n"
                     "OUT Y1.0\nMPP\nOUT Y1.1\nMPP\nOUT Y0.2\nMPP\nOUT Y2.0\nMPP\nOUT Y2.1\n");
  EXPECT_EQ(shape(r), sorted({"contact-no 0 0 X1.0 0", "join 0 1 0 1", "contact-no 0 1 X1.1 2",
                              "join 0 2 0 3", "contact-no 0 2 X1.2 4", "join 0 3 0 5",
                              "contact-no 0 3 X1.3 6", "join 0 4 0 7", "contact-no 0 4 X1.4 8",
                              "coil 0 7 Y1.0 9", "vlink 0 4 1 10", "coil 1 7 Y1.1 11",
                              "vlink 0 3 2 12", "coil 2 7 Y0.2 13", "vlink 0 2 3 14",
                              "coil 3 7 Y2.0 15", "vlink 0 1 4 16", "coil 4 7 Y2.1 17"}));
}

TEST(LadderLayout, WideRungScrollsAndDropsNothing) {
  std::string stl = "LD X0.0\n";
  for (int i = 1; i < 40; ++i) stl += "AND X" + std::to_string(i) + ".0\n";
  stl += "OUT Y0.0\n";
  RungLayout r = one(stl);
  std::set<StmtId> ids;
  for (const Cell &c : r.cells)
    if (c.stmt >= 0) ids.insert(c.stmt);
  EXPECT_EQ(ids.size(), 41u);
  EXPECT_EQ(r.cols, 41); // 40 contacts, then the coil column: the drawing widens (scrolls)
  Diagnostics d("t.stl");
  std::optional<VerifiedProgram> p = pipeline::compileStl(stl, "t.stl", VerifyOptions{}, d);
  ASSERT_TRUE(p);
  std::string svg = renderSvg(layout(fromProgram(*p)));
  EXPECT_NE(svg.find("data-stmt=\"40\""), std::string::npos);
}

TEST(LadderLayout, BoxSpansRowsAndHtmlCarriesStatementIds) {
  RungLayout r = one("LD X1.0\nLD X1.1\nLD X1.2\nLD X1.3\nCTUD 1 4\nOUT Y1.4\n");
  const Cell *box = nullptr;
  for (const Cell &c : r.cells)
    if (c.kind == "box") box = &c;
  ASSERT_NE(box, nullptr);
  EXPECT_EQ(box->text, "CTUD");
  EXPECT_EQ(box->height, 4); // one row per input (hnc8-core.md 4.2: CTUD reads 4 stacked inputs)
  EXPECT_EQ(box->width, 2);
}

TEST(LadderLayout, StlRungIsAnStlBoxKeepingEveryStatement) {
  // hnc8-core.md 4.2: OR after OUT has no drawing (a path back through the coil): STL box.
  RungLayout r = one("LD X0.0\nOUT Y0.0\nOR X0.1\nOUT Y0.1\n");
  EXPECT_EQ(r.kind, "stl");
  EXPECT_EQ(shape(r), sorted({"stl 0 0 LD X0.0 0", "stl 1 0 OUT Y0.0 1", "stl 2 0 OR X0.1 2",
                              "stl 3 0 OUT Y0.1 3"}));
  Diagnostics d("t.stl");
  std::optional<VerifiedProgram> p =
      pipeline::compileStl("LD X0.0\nOUT Y0.0\nOR X0.1\nOUT Y0.1\n", "t.stl", VerifyOptions{}, d);
  ASSERT_TRUE(p);
  std::string html = renderHtml(layout(fromProgram(*p)));
  EXPECT_NE(html.find("class=\"el stl off\" data-stmt=\"2\""), std::string::npos);
  const std::string ns = "http://www.w3.org/2000/svg"; // the SVG namespace: no network URL
  for (size_t k; (k = html.find(ns)) != std::string::npos;) html.erase(k, ns.size());
  EXPECT_EQ(html.find("http"), std::string::npos);
  EXPECT_EQ(html.find("src="), std::string::npos);
}

} // namespace
} // namespace lj::ladder

namespace lj::ladder {
namespace {

// One grid per program (docs/ladder-view.md "Layout rules"): a coil rung beside a rung ending in
// a 2-cell box (MOV) gets the box rung's right rail; its coil moves to the rail's column and the
// wire to it grows by the difference, so power still reaches it; a 40-contact rung keeps its own
// width (it scrolls) and does not widen the others.
TEST(LadderLayout, OneRightRailPerProgram) {
  Diagnostics d("t.stl");
  std::string wide;
  for (int i = 0; i < 40; ++i)
    wide += (i ? "AND X" : "LD X") + std::to_string(i / 8) + "." + std::to_string(i % 8) + "\n";
  std::optional<VerifiedProgram> p = pipeline::compileStl(
      "LD X1.0\nOUT Y1.0\nLD X1.1\nMOV 5 D1\n" + wide + "OUT Y2.0\n", "t.stl", VerifyOptions{}, d);
  ASSERT_TRUE(p) << d.render();
  Layout l = layout(fromProgram(*p));
  ASSERT_EQ(l.parts.size(), 1u);
  ASSERT_EQ(l.parts[0].rungs.size(), 3u);
  const RungLayout &coil = l.parts[0].rungs[0], &box = l.parts[0].rungs[1],
                   &w = l.parts[0].rungs[2];
  EXPECT_EQ(box.cols, kMinInputCols + 2); // the box at the output column takes two cells
  EXPECT_EQ(coil.cols, box.cols);
  EXPECT_EQ(w.cols, 41);
  int wires = 0;
  for (const Cell &c : coil.cells) {
    if (c.kind == "coil") {
      EXPECT_EQ(c.col, box.cols - 1) << "the coil stands at the right rail";
    }
    if (c.kind == "wire") {
      ++wires;
      EXPECT_EQ(c.col, 1);
      EXPECT_EQ(c.col + c.width, box.cols - 1) << "the wire reaches the moved coil";
    }
  }
  EXPECT_EQ(wires, 1);
}

} // namespace
} // namespace lj::ladder

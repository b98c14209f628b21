// A rung wider than any screen (docs/ladder-view.md "Wide rungs"): the layout keeps every element
// on its own column (no cap, nothing dropped), and the drawings grow to hold it: the SVG's width
// reaches the right rail and every coordinate lies inside it, in the static SVG, the static page
// and the live page's per-rung SVG, whose place (the scrolling section's child) has that width.
#include "frontends/hnc8/FrontEnd.h"
#include "ladder/Layout.h"
#include "pipeline/Compile.h"

#include <gtest/gtest.h>

#include <regex>

namespace lj::ladder {
namespace {

constexpr int kContacts = 40; // 40 x 90 px: several screens wide

Layout wide() {
  std::string stl = "LD X0.0\n";
  for (int i = 1; i < kContacts; ++i)
    stl += "AND X" + std::to_string(i / 8) + "." + std::to_string(i % 8) + "\n";
  stl += "OR R5.0\nOUT Y1.0\n"; // the parallel R5.0 spans the whole series
  Diagnostics d("wide.stl");
  std::optional<VerifiedProgram> p = pipeline::compileStl(stl, "wide.stl", VerifyOptions{}, d);
  EXPECT_TRUE(p) << d.render();
  return p ? layout(fromProgram(*p)) : Layout{};
}

/// The largest x coordinate of any drawn thing (x, x1, x2 attributes) and the svg width.
std::pair<int, int> extent(const std::string &svg) {
  int maxX = 0;
  static const std::regex attr(R"re(\bx[12]?=["'](\d+)["'])re");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), attr); it != std::sregex_iterator();
       ++it)
    maxX = std::max(maxX, std::stoi((*it)[1]));
  std::smatch w;
  EXPECT_TRUE(std::regex_search(svg, w, std::regex(R"re(<svg[^>]*width=["'](\d+)["'])re")));
  return {maxX, w.empty() ? 0 : std::stoi(w[1])};
}

TEST(LadderWideRung, EveryContactHasItsColumn) {
  Layout l = wide();
  ASSERT_EQ(l.parts.size(), 1u);
  ASSERT_EQ(l.parts[0].rungs.size(), 1u);
  const RungLayout &r = l.parts[0].rungs[0];
  std::vector<int> cols;
  int coilCol = -1, orRow = -1;
  for (const Cell &c : r.cells) {
    if (c.kind == "contact-no" && c.row == 0) cols.push_back(c.col);
    if (c.kind == "contact-no" && c.text == "R5.0") orRow = c.row;
    if (c.kind == "coil") coilCol = c.col;
  }
  ASSERT_EQ(cols.size(), static_cast<size_t>(kContacts));
  for (int i = 0; i < kContacts; ++i) EXPECT_EQ(cols[i], i) << "contact " << i;
  EXPECT_EQ(orRow, 1);              // the OR below the series
  EXPECT_EQ(r.cols, kContacts + 1); // 40 input columns, the coil's at the right rail
  EXPECT_EQ(coilCol, kContacts);
}

TEST(LadderWideRung, DrawingsHoldTheWholeRung) {
  Layout l = wide();
  const int railX = 56 + (kContacts + 1) * 90; // left margin + columns x cell width
  for (const std::string &doc : {renderSvg(l), renderHtml(l)}) {
    auto [maxX, width] = extent(doc);
    EXPECT_GE(maxX, railX);
    EXPECT_GE(width, maxX);
  }
  std::string live = renderLazyHtml(l, {}, {});
  size_t at = live.find("id=\"ladder-rungs\"");
  ASSERT_NE(at, std::string::npos);
  // The rungs' JSON writes every '<' as \u003c (issue 28 finding 6): read it back.
  std::string rungs = live.substr(at);
  for (size_t k = 0; (k = rungs.find("\\u003c", k)) != std::string::npos;) rungs.replace(k, 6, "<");
  auto [maxX, width] = extent(rungs);
  EXPECT_GE(maxX, railX);
  EXPECT_GE(width, maxX);
  // The rung's place in the scrolling section is as wide as its drawing.
  EXPECT_NE(live.find("style=\"width:" + std::to_string(width) + "px"), std::string::npos);
  EXPECT_NE(live.find("section.part{display:none;overflow:auto"), std::string::npos);
}

} // namespace
} // namespace lj::ladder

// Each dialect's drawing shows what its user wrote (issue 29 section 1; docs/ladder-view.md
// "Dialects"): the layout cells (kind + text) and rung numbers of small programs per dialect.
// Expected values are the manuals' forms: IEC IL as modicon-neza.md writes it (XOR 2.6, JMP
// `>>%L6` and labels 1.3, operation blocks `[%MW10 := %MW50 + 100]` 1.3, comparisons
// `[%MW1 < 1000]` 2.2, comments `(* *)` 9 rule 6), FANUC as fanuc-pmc.md (JMP / JMPE, END1,
// END2, `;` comments), HNC-8 as hnc8-core.md (the row number left of the left bus, `;` comments).
#include "ladder/Layout.h"
#include "ladder/Text.h"
#include "pipeline/Compile.h"

#include <gtest/gtest.h>

#include <optional>

namespace lj::ladder {
namespace {

struct Drawn {
  Layout layout;
  std::string text;
};

std::optional<Drawn> drawIl(const char *il) {
  Diagnostics d("t.il");
  std::optional<VerifiedProgram> p = pipeline::compileIl(il, "t.il", VerifyOptions{}, d);
  if (!p) {
    ADD_FAILURE() << d.render();
    return std::nullopt;
  }
  Networks n = fromProgram(*p);
  return Drawn{layout(n), renderText(n)};
}

std::optional<Drawn> drawPmc(const char *pmc) {
  Diagnostics d("t.pmc");
  std::optional<VerifiedProgram> p =
      pipeline::compilePmc(pmc, "t.pmc", VerifyOptions{}, d, nullptr);
  if (!p) {
    ADD_FAILURE() << d.render();
    return std::nullopt;
  }
  Networks n = fromProgram(*p);
  return Drawn{layout(n), renderText(n)};
}

const PartLayout *part(const Layout &l, const std::string &name) {
  for (const PartLayout &p : l.parts)
    if (p.name == name) return &p;
  return nullptr;
}

/// The drawn (not wire / link / join) cells of a rung as "kind text".
std::vector<std::string> cells(const RungLayout &r) {
  std::vector<std::string> out;
  for (const Cell &c : r.cells)
    if (c.kind != "wire" && c.kind != "vlink" && c.kind != "join")
      out.push_back(c.kind + " " + c.text);
  return out;
}

/// The numbers of a part's rungs in order (0: a marker or hidden rung).
std::vector<int> numbers(const PartLayout &p) {
  std::vector<int> out;
  for (const RungLayout &r : p.rungs) out.push_back(r.number);
  return out;
}

// modicon-neza.md 2.6: `XOR %M2` is one instruction; drawn as one contact-like element labelled
// as written, never as the expansion's scratch bits %~n or extra STL rungs.
TEST(LadderDrawing, IecXorFamilyAsWritten) {
  auto d = drawIl("LDF %M1\nXOR %M2\nST %M2\n"
                  "LD %I0.1\nXORN %M3\nST %Q0.1\n"
                  "LD %I0.2\nXORR %I0.3\nST %Q0.2\n"
                  "LD %I0.4\nN\nST %Q0.3\nEND\n");
  ASSERT_TRUE(d);
  const PartLayout *p = part(d->layout, "PLC1");
  ASSERT_TRUE(p);
  ASSERT_GE(p->rungs.size(), 4u);
  EXPECT_EQ(p->rungs[0].kind, "ladder");
  EXPECT_EQ(cells(p->rungs[0]),
            (std::vector<std::string>{"contact-fall %M1", "contact-instr XOR %M2", "coil %M2"}));
  EXPECT_EQ(cells(p->rungs[1]),
            (std::vector<std::string>{"contact-no %I0.1", "contact-instr XORN %M3", "coil %Q0.1"}));
  EXPECT_EQ(cells(p->rungs[2]), (std::vector<std::string>{
                                    "contact-no %I0.2", "contact-instr XORR %I0.3", "coil %Q0.2"}));
  EXPECT_EQ(cells(p->rungs[3]),
            (std::vector<std::string>{"contact-no %I0.4", "contact-instr N", "coil %Q0.3"}));
  // The XOR element stands for the 7 statements the front end made of it.
  int xors = 0;
  for (const Cell &c : p->rungs[0].cells) {
    if (c.kind != "contact-instr") continue;
    ++xors;
    EXPECT_EQ(c.covers.size(), 6u);
  }
  EXPECT_EQ(xors, 1);
  EXPECT_EQ(d->text.find("%~"), std::string::npos) << d->text;
}

// END / ENDC / ENDCN as an end mark, RET / RETC / RETCN as a return, JMP / JMPC %Li as a jump
// to the label; the `%L64:` label the front end adds for END is drawn by nothing; SR rungs
// count from 1, labels and SRi: headers have no number.
TEST(LadderDrawing, IecFlowAsWritten) {
  auto d = drawIl("LD %S1\nENDC\n"
                  "LD %I0.1\nJMPC %L1\n"
                  "LD %I0.2\nENDCN\n"
                  "JMP %L2\n"
                  "%L1:\nLD %I0.3\nSR0\n"
                  "%L2:\nEND\n"
                  "SR0:\nLD %I0.4\nST %Q0.1\nLD %I0.5\nRETC\nLD %I0.6\nRETCN\nRET\n");
  ASSERT_TRUE(d);
  const PartLayout *p = part(d->layout, "PLC1");
  ASSERT_TRUE(p);
  std::vector<std::vector<std::string>> got;
  for (const RungLayout &r : p->rungs) got.push_back(cells(r));
  const std::vector<std::vector<std::string>> want{
      {"contact-no %S1", "end ENDC"},
      {"contact-no %I0.1", "jump JMPC %L1"},
      {"contact-no %I0.2", "end ENDCN"},
      {"jump JMP %L2"},
      {"marker %L1:"},
      {"contact-no %I0.3", "call SR0"},
      {"marker %L2:"},
      {"end END"},
      {}, // the label END jumps to: hidden
  };
  EXPECT_EQ(got, want);
  EXPECT_EQ(numbers(*p), (std::vector<int>{1, 2, 3, 4, 0, 5, 0, 6, 0}));
  EXPECT_EQ(p->rungs.back().kind, "hidden");
  EXPECT_EQ(p->rungs.back().hidden.size(), 1u);
  const PartLayout *sr = part(d->layout, "SR0");
  ASSERT_TRUE(sr);
  got.clear();
  for (const RungLayout &r : sr->rungs) got.push_back(cells(r));
  EXPECT_EQ(got, (std::vector<std::vector<std::string>>{{"marker SR0:"},
                                                        {"contact-no %I0.4", "coil %Q0.1"},
                                                        {"contact-no %I0.5", "return RETC"},
                                                        {"contact-no %I0.6", "return RETCN"},
                                                        {"return RET"},
                                                        {}}));
  EXPECT_EQ(numbers(*sr), (std::vector<int>{0, 1, 2, 3, 4, 0})) << "SR rungs start at 1";
  for (const char *never : {"%L64", "T -> RETC", "[RETC]\n--- RET ---"})
    EXPECT_EQ(d->text.find(never), std::string::npos) << never << " in\n" << d->text;
}

// A comparison of two objects is drawn in the order written (modicon-neza.md 2.8: `[a > b]`);
// the IR keeps `a > b` as `b < a`, and `[7 <= %MW3]` a constant first as written.
TEST(LadderDrawing, IecComparisonsInTheirWrittenOrder) {
  auto d = drawIl("LD [%MW0 > %MW1]\nST %Q0.0\nLD [%MW2 >= %MW4]\nST %Q0.1\n"
                  "LD [7 <= %MW3]\nST %Q0.2\nEND\n");
  ASSERT_TRUE(d);
  const PartLayout *p = part(d->layout, "PLC1");
  ASSERT_TRUE(p);
  ASSERT_GE(p->rungs.size(), 3u);
  EXPECT_EQ(cells(p->rungs[0]), (std::vector<std::string>{"compare %MW0 > %MW1", "coil %Q0.0"}));
  EXPECT_EQ(cells(p->rungs[1]), (std::vector<std::string>{"compare %MW2 >= %MW4", "coil %Q0.1"}));
  EXPECT_EQ(cells(p->rungs[2]), (std::vector<std::string>{"compare 7 <= %MW3", "coil %Q0.2"}));
}

// Operation blocks (1 row x 4 columns) and comparison blocks (1 row x 2 columns) with the
// expression as written; comments in (* *).
TEST(LadderDrawing, IecBlocksAndComments) {
  auto d = drawIl("(* count up *)\nLD 1\n[%MW1 := %MW1 + 1]\n"
                  "LD [%MW0 > 5]\nST %Q0.3 (* over five *)\n"
                  "LD %I0.4\nAND [%MW2 < 10]\nST %Q0.4\nEND\n");
  ASSERT_TRUE(d);
  const PartLayout *p = part(d->layout, "PLC1");
  ASSERT_TRUE(p);
  ASSERT_GE(p->rungs.size(), 3u);
  EXPECT_EQ(cells(p->rungs[0]),
            (std::vector<std::string>{"contact-true ", "operate %MW1 := %MW1 + 1"}));
  EXPECT_EQ(cells(p->rungs[1]), (std::vector<std::string>{"compare %MW0 > 5", "coil %Q0.3"}));
  EXPECT_EQ(cells(p->rungs[2]),
            (std::vector<std::string>{"contact-no %I0.4", "compare %MW2 < 10", "coil %Q0.4"}));
  int widths = 0;
  for (const RungLayout &r : p->rungs)
    for (const Cell &c : r.cells) {
      if (c.kind == "operate") widths += c.width == 4 ? 1 : 100;
      if (c.kind == "compare") widths += c.width == 2 ? 1 : 100;
    }
  EXPECT_EQ(widths, 3) << "an operation block 4 cells, comparisons 2 (modicon-neza.md 9 rule 7)";
  EXPECT_EQ(d->layout.commentOpen, "(*");
  EXPECT_EQ(d->layout.commentClose, "*)");
  EXPECT_NE(d->text.find("(* count up *)"), std::string::npos) << d->text;
  EXPECT_NE(d->text.find("(* over five *)"), std::string::npos) << d->text;
  const std::string svg = renderSvg(d->layout);
  EXPECT_NE(svg.find("(* count up *)"), std::string::npos);
  EXPECT_EQ(svg.find("; count up"), std::string::npos);
}

// FANUC JMP .. JMPE (no label in the source): drawn as the JMP and the JMPE written, not as
// JMPB to a label L10000 of the front end's; END1 / END2 / SP / SPE markers are not numbered;
// each part counts rungs from 1; comments with `;`.
TEST(LadderDrawing, FanucAsWritten) {
  auto d = drawPmc("; level 1\nRD X0.0\nWRT R0.0\nEND1\n"
                   "RD X0.2\nJMP\nRD X0.3\nWRT R1.0\nJMPE\n"
                   "RD X0.6\nSUB 57 1\nWRT R1.2\n"
                   "RD X0.7\nCALL P1\nEND2\n"
                   "SP P1\nRD X1.0\nWRT R2.0\nSPE\nEND\n");
  ASSERT_TRUE(d);
  const PartLayout *l1 = part(d->layout, "PLC1"), *l2 = part(d->layout, "PLC2"),
                   *p1 = part(d->layout, "P1");
  ASSERT_TRUE(l1 && l2 && p1);
  EXPECT_EQ(numbers(*l1), (std::vector<int>{1, 0}));
  std::vector<std::vector<std::string>> got;
  for (const RungLayout &r : l2->rungs) got.push_back(cells(r));
  EXPECT_EQ(got,
            (std::vector<std::vector<std::string>>{{"contact-no X0.2", "jump JMP"},
                                                   {"contact-no X0.3", "coil R1.0"},
                                                   {"marker JMPE"},
                                                   {"contact-no X0.6", "box DIFU", "coil R1.2"},
                                                   {"contact-no X0.7", "call CALL P1"},
                                                   {"marker END2"}}));
  EXPECT_EQ(numbers(*l2), (std::vector<int>{1, 2, 0, 3, 4, 0}));
  EXPECT_EQ(numbers(*p1), (std::vector<int>{0, 1, 0}));
  EXPECT_EQ(d->text.find("L10000"), std::string::npos) << d->text;
  EXPECT_NE(d->text.find("; level 1"), std::string::npos) << d->text;
  EXPECT_EQ(d->layout.commentOpen, ";");
}

// HNC-8: no instruction is drawn otherwise (no drawStmts); markers (END1, SP, SPE) have no
// number and each part counts its rungs from 1; comments with `;`.
TEST(LadderDrawing, Hnc8NumbersAndComments) {
  Diagnostics diag("t.stl");
  std::optional<VerifiedProgram> p = pipeline::compileStl(
      "; first\nLD X0.0\nOUT Y0.0\nEND1\nLD X0.1\nCALL S1\nLD X0.2\nOUT Y0.1\nEND2\n"
      "SP S1\nLD X0.3\nOUT Y0.2\nSPE\n",
      "t.stl", VerifyOptions{}, diag);
  ASSERT_TRUE(p) << diag.render();
  Networks n = fromProgram(*p);
  Layout l = layout(n);
  const PartLayout *l1 = part(l, "PLC1"), *l2 = part(l, "PLC2"), *s1 = part(l, "S1");
  ASSERT_TRUE(l1 && l2 && s1);
  EXPECT_EQ(numbers(*l1), (std::vector<int>{1, 0}));
  EXPECT_EQ(numbers(*l2), (std::vector<int>{1, 2, 0}));
  EXPECT_EQ(numbers(*s1), (std::vector<int>{0, 1, 0}));
  for (const PartLayout &pl : l.parts)
    for (const RungLayout &r : pl.rungs) EXPECT_TRUE(r.hidden.empty());
  EXPECT_EQ(l.commentOpen, ";");
  EXPECT_NE(renderSvg(l).find("; first"), std::string::npos);
}

} // namespace
} // namespace lj::ladder

// The ladder view in the program's dialect (docs/ladder-view.md "Dialects"): a FANUC PMC
// program is drawn with the PMC's instruction names (fanuc-pmc.md 5, 6: RD/WRT, EQB, MOVW,
// TMRB, DIFU, END1) and addresses (R100.3, D100); an IEC IL program with the IL objects (%I0.1)
// and words (ST, the %L label as `%L1:`), never the HNC-8 ones (COIN, MOV, PLS, OUT).
#include "frontends/fanuc/FrontEnd.h"
#include "frontends/hnc8/FrontEnd.h"
#include "frontends/iec/FrontEnd.h"
#include "ladder/Json.h"
#include "ladder/Layout.h"
#include "ladder/Text.h"
#include "pipeline/Compile.h"

#include <gtest/gtest.h>

#include <optional>
#include <set>

namespace lj::ladder {
namespace {

std::set<std::string> texts(const Layout &l, const std::string &kindPrefix) {
  std::set<std::string> out;
  for (const PartLayout &p : l.parts)
    for (const RungLayout &r : p.rungs)
      for (const Cell &c : r.cells)
        if (c.kind.rfind(kindPrefix, 0) == 0) out.insert(c.text);
  return out;
}

/// The ladder layout of a FANUC program (none, and a test failure, when it does not compile).
std::optional<Layout> fanucLayout(const char *pmc) {
  Diagnostics d("t.pmc");
  std::optional<VerifiedProgram> p =
      pipeline::compilePmc(pmc, "t.pmc", VerifyOptions{}, d, nullptr);
  if (!p) {
    ADD_FAILURE() << d.render();
    return std::nullopt;
  }
  return layout(fromProgram(*p));
}

TEST(LadderDialect, FanucMnemonicsAndAddresses) {
  const char *pmc = "RD R100.3\n"
                    "EQB R10 8\n" // compare, byte
                    "WRT R1.0\n"
                    "END1\n"
                    "RD X0.1\n"
                    "DIFU 1\n"
                    "WRT R1.2\n"
                    "RD R1.0\n"
                    "MOVW D100 D102\n" // two-byte move
                    "RD.NOT R1.2\n"
                    "TMRB 2 5000\n"
                    "WRT R2.0\n"
                    "END2\n"
                    "END\n";
  std::optional<Layout> fl = fanucLayout(pmc);
  ASSERT_TRUE(fl);
  const Layout &l = *fl;
  EXPECT_EQ(texts(l, "box"), (std::set<std::string>{"EQB", "DIFU", "MOVW", "TMRB"}));
  EXPECT_EQ(texts(l, "marker"), (std::set<std::string>{"END1", "END2"}));
  std::set<std::string> contacts = texts(l, "contact");
  EXPECT_TRUE(contacts.count("R100.3")) << "the PMC address as written";
  EXPECT_TRUE(texts(l, "coil").count("R2.0"));
  bool d100 = false;
  for (const PartLayout &pl : l.parts)
    for (const RungLayout &r : pl.rungs)
      for (const Cell &c : r.cells)
        if (c.text == "MOVW") d100 = !c.operands.empty() && c.operands[0] == "D100";
  EXPECT_TRUE(d100) << "MOVW's first operand drawn as D100";
}

const Cell *boxNamed(const Layout &l, const std::string &text) {
  for (const PartLayout &p : l.parts)
    for (const RungLayout &r : p.rungs)
      for (const Cell &c : r.cells)
        if (c.kind == "box" && c.text == text) return &c;
  return nullptr;
}

// ref 6.3: "[SUB24 TMRB | timer number | set time (ms)]" and "[SUB77 TMRBF | timer number | set
// time]": the box shows those two parameters, not the IR's implied time unit between them.
TEST(LadderDialect, FanucFixedTimersDrawTheirTwoParameters) {
  const char *pmc = "RD X0.1\n"
                    "TMRB 2 5000\n"
                    "WRT R2.0\n"
                    "RD X0.2\n"
                    "TMRBF 3 700\n"
                    "WRT R2.1\n"
                    "RD X0.3\n"
                    "MOVW D100 D102\n"
                    "END1\n"
                    "END2\n"
                    "END\n";
  std::optional<Layout> fl = fanucLayout(pmc);
  ASSERT_TRUE(fl);
  const Layout &l = *fl;
  const Cell *tmrb = boxNamed(l, "TMRB"), *tmrbf = boxNamed(l, "TMRBF"),
             *movw = boxNamed(l, "MOVW");
  ASSERT_TRUE(tmrb && tmrbf && movw);
  EXPECT_EQ(tmrb->operands, (std::vector<std::string>{"2", "5000"}));
  EXPECT_EQ(tmrbf->operands, (std::vector<std::string>{"3", "700"}));
  EXPECT_EQ(movw->operands, (std::vector<std::string>{"D100", "D102"}))
      << "other boxes keep theirs";
  // The text form the same (it printed the implied unit: `[TMRB 2 0 5000]`).
  Diagnostics d("t.pmc");
  std::optional<VerifiedProgram> p =
      pipeline::compilePmc(pmc, "t.pmc", VerifyOptions{}, d, nullptr);
  ASSERT_TRUE(p) << d.render();
  const std::string text = renderText(fromProgram(*p));
  EXPECT_NE(text.find("[TMRB 2 5000]"), std::string::npos) << text;
  EXPECT_NE(text.find("[TMRBF 3 700]"), std::string::npos) << text;
}

// ROT / ROTB (ref 6.10): boxes named as the PMC names them, with the parameters as written
// (ROT: n, current, goal, result; ROTB: the format first).
TEST(LadderDialect, FanucRotationBoxes) {
  const char *pmc = "RD X0.5\nRD.STK X0.4\nRD.STK X0.3\nRD.STK X0.2\nRD.STK X0.1\nRD.STK X0.0\n"
                    "ROT 12 R10 R12 R14\n"
                    "WRT R0.0\n"
                    "RD X0.5\nRD.STK X0.3\nRD.STK X0.2\nRD.STK X0.1\nRD.STK X0.0\n"
                    "SUB 26 2 D0 D2 D4 D6\n"
                    "WRT R0.1\n"
                    "END1\nEND2\nEND\n";
  std::optional<Layout> fl = fanucLayout(pmc);
  ASSERT_TRUE(fl);
  const Layout &l = *fl;
  const Cell *rot = boxNamed(l, "ROT"), *rotb = boxNamed(l, "ROTB");
  ASSERT_TRUE(rot && rotb);
  EXPECT_EQ(rot->operands, (std::vector<std::string>{"12", "R10", "R12", "R14"}));
  EXPECT_EQ(rotb->operands, (std::vector<std::string>{"2", "D0", "D2", "D4", "D6"}));
}

// Functional instructions the front end turns into other operands (ir/Program.h WrittenInstr)
// are drawn as written, the word and parameters of fanuc-pmc.md: DEC's decode specification
// `nndd` (6.9, DEC SUB4), GTB's operands in their order (6.6; the IR's LTB swaps them), MOVE's two
// mask nibbles (6.8) - never the IR's `[DEC F10 3 255]`, `[LTB 5 D100]`, `[AND X1 240 R10]`. A
// symbol written as a parameter stays the address with its symbol.
TEST(LadderDialect, FanucWrittenParametersAsWritten) {
  const char *pmc = "RD X0.0\n"
                    "DEC F10 0311\n"
                    "WRT R0.0\n"
                    "RD X0.1\n"
                    "GTB D100 5\n"
                    "WRT R0.1\n"
                    "RD X0.2\n"
                    "MOVE 1111 0000 X1 R10\n"
                    "END1\n"
                    "END2\n"
                    "END\n";
  std::optional<Layout> fl = fanucLayout(pmc);
  ASSERT_TRUE(fl);
  const Cell *dec = boxNamed(*fl, "DEC"), *gtb = boxNamed(*fl, "GTB"), *mv = boxNamed(*fl, "MOVE");
  ASSERT_TRUE(dec && gtb && mv) << "boxes DEC, GTB, MOVE";
  EXPECT_EQ(dec->operands, (std::vector<std::string>{"F10", "0311"}));
  EXPECT_EQ(gtb->operands, (std::vector<std::string>{"D100", "5"}));
  EXPECT_EQ(mv->operands, (std::vector<std::string>{"1111", "0000", "X1", "R10"}));
  EXPECT_EQ(boxNamed(*fl, "LTB"), nullptr);
  EXPECT_EQ(boxNamed(*fl, "AND"), nullptr);
  // The text form too (ladderjit ladder --format text).
  Diagnostics d("t.pmc");
  std::optional<VerifiedProgram> p =
      pipeline::compilePmc(pmc, "t.pmc", VerifyOptions{}, d, nullptr);
  ASSERT_TRUE(p) << d.render();
  const std::string text = renderText(fromProgram(*p));
  EXPECT_NE(text.find("[GTB D100 5]"), std::string::npos) << text;
  EXPECT_NE(text.find("[MOVE 1111 0000 X1 R10]"), std::string::npos) << text;
}

// A functional instruction written `SUB n` with its parameters on `(PRM)` lines (fanuc-pmc.md
// 6.1, "SUB 5 / (PRM) 1") is a box under the name of SUB n, as one written by name: SUB 4 is
// DEC, SUB 25 DECB (the SUB number table). SUB 60 and SUB 61 are the word AND / OR, which in the
// PMC's text are RD-logic instructions: those boxes keep the `SUB n` they were written with.
TEST(LadderDialect, FanucSubNumberDrawnByName) {
  const char *pmc = "RD X0.0\n"
                    "SUB 4\n"
                    "(PRM) F10\n"
                    "(PRM) 0311\n"
                    "WRT R0.0\n"
                    "RD X0.1\n"
                    "SUB 25\n"
                    "(PRM) 0001\n"
                    "(PRM) D0\n"
                    "(PRM) 100\n"
                    "(PRM) R10\n"
                    "RD X0.2\n"
                    "SUB 60 1002 F26 D14 D12\n"
                    "END1\n"
                    "END2\n"
                    "END\n";
  std::optional<Layout> fl = fanucLayout(pmc);
  ASSERT_TRUE(fl);
  const Cell *dec = boxNamed(*fl, "DEC"), *decb = boxNamed(*fl, "DECB"),
             *sub60 = boxNamed(*fl, "SUB");
  ASSERT_TRUE(dec && decb && sub60) << "boxes DEC, DECB and SUB (60)";
  EXPECT_EQ(dec->operands, (std::vector<std::string>{"F10", "0311"}));
  EXPECT_EQ(decb->operands, (std::vector<std::string>{"0001", "D0", "100", "R10"}));
  EXPECT_EQ(sub60->operands, (std::vector<std::string>{"60", "1002", "F26", "D14", "D12"}));
  Diagnostics d("t.pmc");
  std::optional<VerifiedProgram> p =
      pipeline::compilePmc(pmc, "t.pmc", VerifyOptions{}, d, nullptr);
  ASSERT_TRUE(p) << d.render();
  const std::string text = renderText(fromProgram(*p));
  EXPECT_NE(text.find("[DEC F10 0311]"), std::string::npos) << text;
  EXPECT_NE(text.find("[DECB 0001 D0 100 R10]"), std::string::npos) << text;
  EXPECT_NE(text.find("[SUB 60 1002 F26 D14 D12]"), std::string::npos) << text;
  // The JSON keeps the instruction as written: networks -> program text gives it back.
  EXPECT_NE(writeJson(fromProgram(*p)).find("SUB 25 0001 D0 100 R10"), std::string::npos);
}

// COME and NOP make no statement (fanuc-pmc.md 6.1): drawn as the markers a FANUC ladder shows
// between the rungs, before the rung they were written before (the layout's "lead").
TEST(LadderDialect, FanucComeDrawnBetweenRungs) {
  const char *pmc = "RD X0.0\nCOM\nRD X0.1\nWRT Y0.0\nCOME\nRD X0.3\nWRT Y0.2\nNOP\n"
                    "RD X0.4\nWRT Y0.3\nEND1\nEND2\nEND\n";
  std::optional<Layout> fl = fanucLayout(pmc);
  ASSERT_TRUE(fl);
  const std::vector<RungLayout> &rs = fl->parts[0].rungs;
  ASSERT_EQ(rs.size(), 5u); // COM, three coil rungs, END1
  EXPECT_TRUE(rs[1].lead.empty());
  EXPECT_EQ(rs[2].lead, std::vector<std::string>{"COME"});
  EXPECT_EQ(rs[3].lead, std::vector<std::string>{"NOP"});
  EXPECT_NE(layoutJson(*fl).find("\"lead\""), std::string::npos);
  EXPECT_NE(renderSvg(*fl).find(">COME<"), std::string::npos);
  Diagnostics d("t.pmc");
  std::optional<VerifiedProgram> p =
      pipeline::compilePmc(pmc, "t.pmc", VerifyOptions{}, d, nullptr);
  ASSERT_TRUE(p) << d.render();
  const std::string text = renderText(fromProgram(*p));
  EXPECT_NE(text.find("-( )- Y0.0\n--- COME ---\nrung 3\n"), std::string::npos) << text;
  EXPECT_NE(text.find("-( )- Y0.2\n--- NOP ---\nrung 4\n"), std::string::npos) << text;
}

// An HNC-8 constant written in hex is drawn as written (`WAND R0 0xE0 R0`, lathe_panel.stl's
// mode reset), not as the IR's 224; a decimal one needs no record.
TEST(LadderDialect, Hnc8HexConstantAsWritten) {
  Diagnostics d("t.stl");
  std::optional<VerifiedProgram> p = pipeline::compileStl(
      "LDT\nWAND R0 0xE0 R0\nLDT\nWAND R1 15 R1\n", "t.stl", VerifyOptions{}, d);
  ASSERT_TRUE(p) << d.render();
  EXPECT_EQ(p->written.size(), 1u);
  Layout l = layout(fromProgram(*p));
  std::vector<std::vector<std::string>> ops;
  for (const PartLayout &pl : l.parts)
    for (const RungLayout &r : pl.rungs)
      for (const Cell &c : r.cells)
        if (c.kind == "box") ops.push_back(c.operands);
  EXPECT_EQ(ops, (std::vector<std::vector<std::string>>{{"R0", "0xE0", "R0"}, {"R1", "15", "R1"}}));
}

// An HNC-8 TMRB writes the time unit (hnc8-core.md: `TMRB 0 0 500`): all three operands drawn.
TEST(LadderDialect, Hnc8TimerKeepsItsTimeUnit) {
  Diagnostics d("t.stl");
  std::optional<VerifiedProgram> p =
      pipeline::compileStl("LD X0.1\nTMRB 0 1 500\nOUT R2.0\n", "t.stl", VerifyOptions{}, d);
  ASSERT_TRUE(p) << d.render();
  Layout l = layout(fromProgram(*p));
  const Cell *tmrb = boxNamed(l, "TMRB");
  ASSERT_TRUE(tmrb);
  EXPECT_EQ(tmrb->operands, (std::vector<std::string>{"0", "1", "500"}));
}

TEST(LadderDialect, IecObjectsAndWords) {
  const char *il = "LD %I0.1\n"
                   "AND %I0.2\n"
                   "ST %Q0.1\n"
                   "LD %I0.3\n"
                   "JMPC %L1\n"
                   "LD %I0.4\n"
                   "ST %Q0.2\n"
                   "%L1:\n"
                   "LD %I0.5\n"
                   "ST %Q0.3\n"
                   "END\n";
  Diagnostics d("t.il");
  std::optional<VerifiedProgram> p = pipeline::compileIl(il, "t.il", VerifyOptions{}, d);
  ASSERT_TRUE(p) << d.render();
  Layout l = layout(fromProgram(*p));
  std::set<std::string> contacts = texts(l, "contact");
  EXPECT_TRUE(contacts.count("%I0.1") && contacts.count("%I0.5"));
  EXPECT_TRUE(texts(l, "coil").count("%Q0.3"));
  std::set<std::string> markers = texts(l, "marker");
  EXPECT_TRUE(markers.count("%L1:")) << "the label as IL writes it";
  for (const std::string &m : markers) EXPECT_EQ(m.find("LBL"), std::string::npos) << m;
}

// The text form (`ladderjit ladder --format text`) names instructions as the drawing does: a
// FANUC program shows END1, SP, JMPC and ROTB, not the HNC-8 words or the IR's names.
TEST(LadderDialect, FanucTextForm) {
  const char *pmc = "END1\nRD X0.0\nCALL P1\nLBL L1\nEND2\nSP P1\nRD X0.1\nJMPC L1\n"
                    "RD R9091.0\nRD.STK R9091.1\nRD.STK R9091.1\nRD.STK R9091.0\nRD.STK X0.2\n"
                    "ROTB 2 D0 D2 D4 D6\nWRT R0.0\nSPE\nEND\n";
  Diagnostics d("t.pmc");
  std::optional<VerifiedProgram> p =
      pipeline::compilePmc(pmc, "t.pmc", VerifyOptions{}, d, nullptr);
  ASSERT_TRUE(p) << d.render();
  const std::string t = renderText(fromProgram(*p));
  for (const char *want : {"--- END1 ---", "--- END2 ---", "--- SP P1 ---", "--- SPE ---",
                           "[JMPC L1]", "[CALL P1]", "[ROTB 2 D0 D2 D4 D6]"})
    EXPECT_NE(t.find(want), std::string::npos) << want << " in\n" << t;
  for (const char *never : {"1END", "2END", "JumpOut", "BinaryRotation"})
    EXPECT_EQ(t.find(never), std::string::npos) << never << " in\n" << t;
}

} // namespace
} // namespace lj::ladder

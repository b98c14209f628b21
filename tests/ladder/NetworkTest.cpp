// Networks from STL (ladder/FromStl.cpp), back to STL (ToStl.cpp) and through JSON (Json.cpp):
// what has no drawing stays an STL rung; a network without hints gets canonical STL; JSON errors
// and program diagnostics name the place in the JSON.
#include "ladder/Network.h"
#include "frontends/hnc8/FrontEnd.h"
#include "ladder/Json.h"
#include "pipeline/Compile.h"
#include "verify/Verify.h"

#include <gtest/gtest.h>

namespace lj::ladder {
namespace {

VerifiedProgram verified(const std::string &text) {
  Diagnostics d("t.stl");
  std::optional<VerifiedProgram> p = pipeline::compileStl(text, "t.stl", VerifyOptions{}, d);
  EXPECT_TRUE(p) << d.render();
  return p ? *p : VerifiedProgram{};
}

std::string stlOf(const Networks &n) {
  std::vector<Element> st;
  std::string err;
  EXPECT_TRUE(toStatements(n, st, err)) << err;
  return stlText(st, nullptr, nullptr, &hnc8::dialectText());
}

TEST(LadderNetwork, RungBoundariesFollowDataflow) {
  // hnc8-core.md 6.5: a new rung starts at an LD whose value nothing later combines with what
  // was before; MPS-1 shows an LD after an OUT that still belongs to the rung (ANB follows).
  VerifiedProgram p = verified("LD X1.0\nOUT Y0.0\nLD X1.1\nOUT Y0.1\nAND X1.2\nLD X1.3\nANB\n"
                               "OUT Y0.2\n");
  ASSERT_EQ(p.rungs.size(), 2u);
  EXPECT_EQ(p.rungs[0].range.begin, 0);
  EXPECT_EQ(p.rungs[0].range.end, 2);
  EXPECT_EQ(p.rungs[1].range.end, 8);
  Networks n = fromProgram(p);
  ASSERT_EQ(n.parts.size(), 1u);
  EXPECT_EQ(n.parts[0].rungs[1].kind, Rung::Kind::Ladder);
}

TEST(LadderNetwork, UndrawableStaysStlVerbatim) {
  // OR around a coil would need a path back through the coil; MPP overwriting another entry's
  // ST0 has no branch to draw. Both stay STL rungs with their statements in order.
  for (const char *text : {"LD X0.0\nOUT Y0.0\nOR X0.1\nOUT Y0.1\n",
                           "LD X0.0\nMPS\nLD X0.1\nOUT Y0.0\nMPP\nOUT Y0.1\n"}) {
    Networks n = fromProgram(verified(text));
    ASSERT_EQ(n.parts[0].rungs.size(), 1u) << text;
    EXPECT_EQ(n.parts[0].rungs[0].kind, Rung::Kind::Stl) << text;
    EXPECT_EQ(stlOf(n), text);
  }
}

TEST(LadderNetwork, DrawableRegeneratesTheSameStatements) {
  const char *text = "LD X1.0\nLD X1.1\nLD X1.2\nORB\nANB\nOUT Y0.0\nLDT\nMOV 5 D1\nLD X0.0\n"
                     "LD X0.1\nLD X0.2\nLD X0.3\nCTR D0 5\nOUT Y0.1\n";
  Networks n = fromProgram(verified(text));
  for (const Rung &r : n.parts[0].rungs) EXPECT_EQ(r.kind, Rung::Kind::Ladder);
  EXPECT_EQ(stlOf(n), text); // deep-stack form kept (join hints), so the slicing counts agree
  Networks back;
  std::string err;
  ASSERT_TRUE(readJson(writeJson(n), back, err, hnc8::dialectText())) << err;
  EXPECT_EQ(stlOf(back), text);
}

TEST(LadderNetwork, CanonicalStlWithoutHints) {
  // A network made by another tool: no ids, joins or entries. (X0.0 | X0.1) then a fan-out whose
  // first branch has a contact: MPS ... MPP; the parallel contact takes the OR form.
  const char *json = R"({"format":"ladderjit-ladder","version":1,"dialect":"hnc8","parts":[
    {"name":"PLC1","rungs":[{"kind":"ladder","network":{"type":"series","children":[
      {"type":"parallel","children":[
        {"type":"contact","contact":"no","operands":[{"text":"X0.0"}]},
        {"type":"contact","contact":"nc","operands":[{"text":"X0.1"}]}]},
      {"type":"fanout","branches":[
        {"type":"series","children":[{"type":"contact","contact":"rise","operands":[{"text":"X0.2"}]},
                                     {"type":"coil","instr":"OUT","operands":[{"text":"Y0.0"}]}]},
        {"type":"series","children":[{"type":"coil","instr":"SET","operands":[{"text":"R1.0"}]}]}
      ]}]}}]}]})";
  Networks n;
  std::string err;
  ASSERT_TRUE(readJson(json, n, err, hnc8::dialectText())) << err;
  EXPECT_EQ(stlOf(n), "LD X0.0\nORI X0.1\nMPS\nANDP X0.2\nOUT Y0.0\nMPP\nSET R1.0\n");
}

// A lone CR inside a comment (found by fuzz_il: an IL comment over CR-only lines) must not make
// the JSON unreadable: comment lines hold no line break. Before it: one line per CR-separated
// piece; trailing: the CR becomes a blank. The pipeline's compile refuses such a text (LJ0001,
// RobustnessTest), so the program is parsed and verified here directly: fromProgram takes any
// verified program.
TEST(LadderNetwork, CommentsWithCarriageReturnsStayReadable) {
  Diagnostics d("t.stl");
  std::optional<VerifiedProgram> p =
      verify(parseStl("; one\rtwo\nLD X0.0 ; a\rb\nOUT Y0.0\n", "t.stl", d), VerifyOptions{}, d);
  ASSERT_TRUE(p) << d.render();
  Networks n = fromProgram(*p);
  ASSERT_EQ(n.parts[0].rungs.size(), 1u);
  EXPECT_EQ(n.parts[0].rungs[0].comment, (std::vector<std::string>{"one", "two"}));
  EXPECT_EQ(n.parts[0].rungs[0].network.children[0].elem.comment, "a b");
  Networks back;
  std::string err;
  ASSERT_TRUE(readJson(writeJson(n), back, err, hnc8::dialectText())) << err;
  EXPECT_EQ(stlOf(back), "; one\n; two\nLD X0.0 ; a b\nOUT Y0.0\n");
}

TEST(LadderNetwork, JsonErrorsNameThePlace) {
  const char *json = R"({"format":"ladderjit-ladder","version":1,"dialect":"hnc8","parts":[
    {"name":"PLC1","rungs":[{"kind":"ladder","network":{"type":"series","children":[
      {"type":"wire"}]}}]}]})";
  Networks n;
  std::string err;
  EXPECT_FALSE(readJson(json, n, err, hnc8::dialectText()));
  EXPECT_EQ(err, "parts[0].rungs[0].network.children[0].type: unknown node type 'wire'");
  // Another dialect's networks are not read as HNC-8 ones (their words are that dialect's).
  const char *fanuc = R"({"format":"ladderjit-ladder","version":1,"dialect":"fanuc",
    "source":"RD X0.0\nWRT Y0.0\nEND1\nEND2\nEND\n","parts":[]})";
  EXPECT_FALSE(readJson(fanuc, n, err, hnc8::dialectText()));
  EXPECT_EQ(err, "dialect: 'fanuc' networks read as 'hnc8'");
  StlFromJson stl;
  EXPECT_FALSE(stlFromJson(fanuc, stl, err, hnc8::dialectText()));
  EXPECT_FALSE(readJson("{", n, err, hnc8::dialectText()));
  EXPECT_EQ(err, "not valid JSON");
  // An operand that would become two STL tokens is refused, not pasted into the text.
  const char *inject = R"({"format":"ladderjit-ladder","version":1,"dialect":"hnc8","parts":[
    {"name":"PLC1","rungs":[{"kind":"stl","stmts":[{"instr":"LD","operands":[{"text":"X0.0\nOUT"}]}]}]}]})";
  EXPECT_FALSE(readJson(inject, n, err, hnc8::dialectText()));
  EXPECT_EQ(err, "parts[0].rungs[0].stmts[0].operands[0].text: a line break is not allowed here");
}

TEST(LadderNetwork, DiagnosticsPointIntoTheJson) {
  // OUT on X (read-only) in the second element of PLC1's first rung.
  const char *json = R"({"format":"ladderjit-ladder","version":1,"dialect":"hnc8","parts":[
    {"name":"PLC1","rungs":[{"kind":"ladder","network":{"type":"series","children":[
      {"type":"contact","contact":"no","id":7,"operands":[{"text":"X0.0"}]},
      {"type":"coil","instr":"OUT","id":8,"line":12,"col":3,"operands":[{"text":"X0.1"}]}]}}]}]})";
  StlFromJson src;
  std::string err;
  ASSERT_TRUE(stlFromJson(json, src, err, hnc8::dialectText())) << err;
  Diagnostics d("p.json");
  EXPECT_FALSE(pipeline::compileStl(src.text, "p.json", VerifyOptions{}, d, &src.symbols));
  std::string out = renderDiagnostics(d, src);
  EXPECT_NE(out.find("p.json:12:3: error: PLC1 rung 1 element 2 (id 8): X0.1 is read-only"),
            std::string::npos)
      << out;
}

} // namespace
} // namespace lj::ladder

// Instructions recorded as written (ir/Program.h WrittenInstr): a FANUC functional instruction
// whose written parameters differ from its IR operands, and IL instructions the front end
// expands into other statements with scratch bits (N, XOR, END), print back from their networks
// as the user wrote them (docs/ladder-json.md "written"), through the network JSON, and the
// printed text reads back as the same statements. The expected text is the input, written in the
// manuals' syntax (fanuc-pmc.md 6.6, 6.9; modicon-neza.md 2.6, 2.7, 4).
#include "frontends/fanuc/FrontEnd.h"
#include "frontends/iec/FrontEnd.h"
#include "ladder/Json.h"
#include "pipeline/Compile.h"

#include <gtest/gtest.h>

#include <functional>
#include <optional>
#include <string>

namespace lj::ladder {
namespace {

/// `prog`'s networks written as JSON, read back and printed whole in the dialect.
std::string printedThroughJson(const VerifiedProgram &prog, std::string &json) {
  json = writeJson(fromProgram(prog));
  Networks back;
  std::string error, text;
  EXPECT_TRUE(readJson(json, back, error, *prog.dialect)) << error;
  EXPECT_TRUE(programText(back, prog, "", text, error, true)) << error;
  return text;
}

// FANUC: DEC's decode specification `nndd` is two IR constants (fanuc-pmc.md 6.9, DEC SUB4:
// the value and a digit mask); GTB a b is the IR's LTB with its operands swapped (6.6); CALLU
// is the IR's (ON) and CALL (4.2). Each prints as written; the rest by the printer.
constexpr const char *kFanuc = "RD X0.0\n"
                               "DEC F10 0311\n"
                               "WRT R0.0\n"
                               "RD X0.1\n"
                               "GTB D100 5 ; over five\n"
                               "WRT R0.1\n"
                               "RD X0.2\n"
                               "EQB D100 5\n"
                               "WRT R0.2\n"
                               "END1\n"
                               "CALLU P1\n"
                               "END2\n"
                               "SP P1\n"
                               "RD X0.3\n"
                               "WRT R0.3\n"
                               "SPE\n";

TEST(WrittenText, FanucFunctionalInstructionsPrintAsWritten) {
  const std::string src = std::string(kFanuc) + "END\n";
  Diagnostics d("t.pmc");
  std::optional<VerifiedProgram> p =
      pipeline::compilePmc(src, "t.pmc", VerifyOptions{}, d, nullptr);
  ASSERT_TRUE(p) << d.render();
  // DEC: one statement (BcdDecode) with other operands than written; GTB: one (CompareLt,
  // swapped); CALLU: two. EQB prints from its statement and is not recorded.
  ASSERT_EQ(p->written.size(), 3u);
  EXPECT_EQ(p->written[0].text, "DEC F10 0311");
  EXPECT_EQ(p->written[1].text, "GTB D100 5");
  EXPECT_EQ(p->written[2].text, "CALLU P1");
  EXPECT_EQ(p->written[2].count, 2);
  std::string json;
  const std::string text = printedThroughJson(*p, json);
  EXPECT_EQ(text, kFanuc); // END, the source's last line, is no statement
  EXPECT_NE(json.find("\"DEC F10 0311\""), std::string::npos) << json;     // "written"
  EXPECT_NE(json.find("\"in_written\": true"), std::string::npos) << json; // CALLU's CALL
  // networks -> program -> networks: the text reads back as the same statements.
  Diagnostics d2("again.pmc");
  std::optional<VerifiedProgram> again =
      pipeline::compilePmc(text + "END\n", "again.pmc", VerifyOptions{}, d2, nullptr);
  ASSERT_TRUE(again) << d2.render();
  std::string error;
  EXPECT_TRUE(sameStatementsAs(fromProgram(*again), fromProgram(*p), error, false)) << error;
}

/// kFanuc (with END) whose network JSON `edit` changes, printed back as FANUC text.
std::string fanucEdited(const std::function<void(std::string &)> &edit) {
  const std::string src = std::string(kFanuc) + "END\n";
  Diagnostics d("t.pmc");
  std::optional<VerifiedProgram> p =
      pipeline::compilePmc(src, "t.pmc", VerifyOptions{}, d, nullptr);
  EXPECT_TRUE(p) << d.render();
  if (!p) return {};
  std::string json = writeJson(fromProgram(*p));
  edit(json);
  Networks back;
  std::string error, text;
  EXPECT_TRUE(readJson(json, back, error, *p->dialect)) << error;
  EXPECT_TRUE(programText(back, *p, src, text, error)) << error;
  return text;
}

TEST(WrittenText, FanucEditedWrittenInstructionPrintsFromItsStatement) {
  // The GTB's constant edited in the JSON (its statement is LTB 5 D100): its written text no
  // longer holds, so it is printed from the edited statement, LTB 7 D100 (D100 > 7).
  const std::string text = fanucEdited([](std::string &json) {
    const std::string five = "\"text\": \"5\""; // the GTB's, the first
    const size_t at = json.find(five);
    ASSERT_NE(at, std::string::npos) << json;
    json.replace(at, five.size(), "\"text\": \"7\"");
  });
  EXPECT_NE(text.find("LTB 7 D100 ; over five\n"), std::string::npos) << text;
  EXPECT_EQ(text.find("GTB"), std::string::npos) << text;
}

TEST(WrittenText, FanucEditedCalluPrintsAsCallu) {
  // The subprogram renamed P1 -> P2 (列表编辑): CALLU's call operand and SP's edited, so the
  // CALLU no longer prints as written. FANUC has no word for its always-true load alone (4.2:
  // CALLU is the unconditional call): it prints as CALLU P2, never as "(ON)" and CALL.
  const std::string text = fanucEdited([](std::string &json) {
    for (size_t at = json.find("\"P1\""); at != std::string::npos; at = json.find("\"P1\""))
      json.replace(at, 4, "\"P2\"");
  });
  EXPECT_NE(text.find("\nCALLU P2\n"), std::string::npos) << text;
  EXPECT_NE(text.find("\nSP P2\n"), std::string::npos) << text;
  EXPECT_EQ(text.find("(ON)"), std::string::npos) << text;
  Diagnostics d2("again.pmc");
  EXPECT_TRUE(pipeline::compilePmc(text, "again.pmc", VerifyOptions{}, d2, nullptr))
      << d2.render() << text;
}

// COM / COME (fanuc-pmc.md 6.1, "COM: when ACT = 0, coils up to COME are written 0"): COME makes
// no statement of its own. It stands between two rungs and stays there whichever of them is
// edited: the rung before it printed anew (COME must not go with it), the rung after it printed
// from its statements (COME stays before it), through the JSON's written text or its rung "lead"
// as the page editor sends it (a converted grid carries no written text). Losing it would be the
// front end's error "COM on line 2 has no COME before END1".
constexpr const char *kCom = "RD X0.0\n"
                             "COM\n"
                             "RD X0.1\n"
                             "WRT Y0.0\n"
                             "RD X0.2\n"
                             "WRT Y0.1\n"
                             "COME\n"
                             "RD X0.3\n"
                             "WRT Y0.2\n"
                             "END1\n"
                             "END2\n"
                             "END\n";

/// kCom's networks, `edit`ed, printed back as FANUC text (empty when refused, `error` says why).
std::string comEdited(const std::function<void(Networks &)> &edit, std::string &error) {
  Diagnostics d("t.pmc");
  std::optional<VerifiedProgram> p =
      pipeline::compilePmc(kCom, "t.pmc", VerifyOptions{}, d, nullptr);
  EXPECT_TRUE(p) << d.render();
  if (!p) return {};
  Networks back;
  EXPECT_TRUE(readJson(writeJson(fromProgram(*p)), back, error, *p->dialect)) << error;
  edit(back);
  std::string text;
  if (!programText(back, *p, kCom, text, error)) return {};
  Diagnostics d2("again.pmc");
  if (!pipeline::compilePmc(text, "again.pmc", VerifyOptions{}, d2, nullptr)) {
    error = d2.render();
    return {};
  }
  return text;
}

/// The contact that starts rung `r` of PLC1.
Element &firstContact(Networks &n, size_t r) {
  return n.parts[0].rungs[r].network.children[0].elem;
}

TEST(WrittenText, FanucComeStaysBetweenItsRungs) {
  std::string error;
  // The rung's lead, as the JSON and the drawing give it.
  comEdited(
      [](Networks &n) {
        ASSERT_EQ(n.parts[0].rungs.size(), 5u); // COM, 3 coil rungs, END1
        EXPECT_EQ(n.parts[0].rungs[3].lead, std::vector<std::string>{"COME"});
        EXPECT_TRUE(n.parts[0].rungs[2].lead.empty());
      },
      error);
  // The rung before COME edited.
  std::string text = comEdited([](Networks &n) { firstContact(n, 2).operands[0] = "X0.5"; }, error);
  EXPECT_EQ(text, "RD X0.0\nCOM\nRD X0.1\nWRT Y0.0\nRD X0.5\nWRT Y0.1\nCOME\nRD X0.3\nWRT Y0.2\n"
                  "END1\nEND2\nEND\n")
      << error;
  // The rung after COME edited in the JSON (its written text "COME / RD X0.3" no longer holds).
  text = comEdited([](Networks &n) { firstContact(n, 3).operands[0] = "X0.4"; }, error);
  EXPECT_NE(text.find("WRT Y0.1\nCOME\nRD X0.4\n"), std::string::npos) << text << error;
  // Both, the second as the page editor sends it: no written text, the rung's lead.
  text = comEdited(
      [](Networks &n) {
        firstContact(n, 2).operands[0] = "X0.5";
        Element &e = firstContact(n, 3);
        e.operands[0] = "X0.4";
        e.role = WrittenRole::None;
        e.written.clear();
      },
      error);
  EXPECT_NE(text.find("RD X0.5\nWRT Y0.1\nCOME\nRD X0.4\n"), std::string::npos) << text << error;
  // Without the lead either, COME is gone: refused by the front end, never a different program.
  text = comEdited(
      [](Networks &n) {
        firstContact(n, 2).operands[0] = "X0.5";
        Element &e = firstContact(n, 3);
        e.role = WrittenRole::None;
        e.written.clear();
        n.parts[0].rungs[3].lead.clear();
      },
      error);
  EXPECT_EQ(text, "");
  EXPECT_NE(error.find("has no COME"), std::string::npos) << error;
}

// A lead edited in the JSON is never dropped silently: one added to a rung is printed (here a
// second COME, which the front end refuses: COME without COM), one that contradicts the written
// text its rung's first instruction keeps is refused with the reason.
TEST(WrittenText, FanucLeadEditsAreNeverDropped) {
  std::string error;
  std::string text = comEdited([](Networks &n) { n.parts[0].rungs[2].lead = {"COME"}; }, error);
  EXPECT_EQ(text, "");
  EXPECT_NE(error.find("without COM"), std::string::npos) << error;
  text = comEdited([](Networks &n) { n.parts[0].rungs[3].lead = {"NOP"}; }, error);
  EXPECT_EQ(text, "");
  EXPECT_NE(error.find("PLC1 rung 4 element 1 (id 6): the rung's \"lead\" is not the lines its "
                       "first instruction was written after"),
            std::string::npos)
      << error;
}

TEST(WrittenText, FanucLeadTakesOnlyLinesBetweenRungs) {
  Diagnostics d("t.pmc");
  std::optional<VerifiedProgram> p =
      pipeline::compilePmc(kCom, "t.pmc", VerifyOptions{}, d, nullptr);
  ASSERT_TRUE(p) << d.render();
  std::string json = writeJson(fromProgram(*p));
  const size_t at = json.find("\"COME\"", json.find("\"lead\""));
  ASSERT_NE(at, std::string::npos) << json;
  json.replace(at, 6, "\"WRT Y0.7\"");
  Networks back;
  std::string error;
  EXPECT_FALSE(readJson(json, back, error, *p->dialect));
  EXPECT_NE(error.find("rungs[3].lead[0]: 'WRT Y0.7' is no line the fanuc dialect writes between "
                       "rungs"),
            std::string::npos)
      << error;
}

// IL: XOR (modicon-neza.md 2.6) and N (2.7) are expanded with scratch bits, END / ENDC (4) into
// a jump to the end of the main program; each prints as written.
constexpr const char *kIl = "LD %I0.1\n"
                            "XOR %I0.2\n"
                            "ST %Q0.1\n"
                            "LD %I0.3\n"
                            "N\n"
                            "ST %Q0.2\n"
                            "LD %S1\n"
                            "ENDC\n"
                            "LD %I0.4\n"
                            "XORN %M1 (* not M1 *)\n"
                            "ST %Q0.3\n"
                            "END\n";

TEST(WrittenText, IlExpansionsPrintAsWritten) {
  Diagnostics d("t.il");
  std::optional<VerifiedProgram> p = pipeline::compileIl(kIl, "t.il", VerifyOptions{}, d);
  ASSERT_TRUE(p) << d.render();
  ASSERT_EQ(p->written.size(), 5u);
  EXPECT_EQ(p->written[0].text, "XOR %I0.2");
  EXPECT_EQ(p->written[0].count, 7); // a := acc; push e; b := e; ORB; LDN a; ORN b; ANB
  EXPECT_EQ(p->written[1].text, "N");
  EXPECT_EQ(p->written[1].count, 3); // t := acc; ANDN t; ORN t
  EXPECT_EQ(p->written[2].text, "ENDC");
  EXPECT_EQ(p->written[3].text, "XORN %M1");
  EXPECT_EQ(p->written[4].text, "END");
  std::string json;
  const std::string text = printedThroughJson(*p, json);
  EXPECT_EQ(text, kIl);
  EXPECT_NE(json.find("\"XOR %I0.2\""), std::string::npos) << json; // "written"
  Diagnostics d2("again.il");
  std::optional<VerifiedProgram> again = pipeline::compileIl(text, "again.il", VerifyOptions{}, d2);
  ASSERT_TRUE(again) << d2.render();
  std::string error;
  EXPECT_TRUE(sameStatementsAs(fromProgram(*again), fromProgram(*p), error, false)) << error;
}

} // namespace
} // namespace lj::ladder

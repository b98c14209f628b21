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

// programText's line origins (ladder/Json.h): each line of the program text made from edited
// networks names the rung and element it came from, so the live view's editor can mark the cell
// of a diagnostic (docs/ladder-edit.md "Diagnostics"): copied lines by their statement, the lines
// of a reprinted rung by its statements in order, a comment line by the statement after it.
#include "frontends/hnc8/FrontEnd.h"
#include "ladder/Json.h"
#include "pipeline/Compile.h"

#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <vector>

namespace lj::ladder {
namespace {

constexpr const char *kStl = "LD X0.0\n"         // 1  PLC1 rung 1 element 1
                             "OUT Y0.0\n"        // 2  rung 1 element 2
                             "; second rung\n"   // 3  comment before rung 2
                             "LD X0.1\n"         // 4  rung 2 element 1
                             "OUT Y0.1 ; lamp\n" // 5  rung 2 element 2
                             "1END\n";           // 6  rung 3 (the marker)

std::vector<std::string> linesOf(const std::string &s) {
  std::vector<std::string> out;
  size_t p = 0;
  while (p < s.size()) {
    size_t nl = s.find('\n', p);
    if (nl == std::string::npos) nl = s.size();
    out.push_back(s.substr(p, nl - p));
    p = nl + 1;
  }
  return out;
}

TEST(ToTextOrigins, EveryLineNamesItsRungAndElement) {
  Diagnostics d("t.stl");
  std::optional<VerifiedProgram> p =
      pipeline::compileStl(kStl, "t.stl", VerifyOptions{}, d, nullptr);
  ASSERT_TRUE(p) << d.render();
  // The second rung gains a normally closed contact on X0.2 after its first contact, through
  // the JSON a page edits.
  std::string json = writeJson(fromProgram(*p));
  size_t at = json.find("\"X0.1\"");
  ASSERT_NE(at, std::string::npos) << json;
  at = json.find('}', json.find(']', at)) + 1; // the end of the X0.1 contact's object
  json.insert(at, ", {\"type\": \"contact\", \"contact\": \"nc\", \"operands\": [{\"text\": "
                  "\"X0.2\"}]}");
  Networks nets;
  std::string error;
  ASSERT_TRUE(readJson(json, nets, error, hnc8::dialectText())) << error << "\n" << json;
  std::string out;
  std::vector<LineOrigin> origins;
  ASSERT_TRUE(programText(nets, *p, kStl, out, error, false, &origins)) << error;
  const std::vector<std::string> lines = linesOf(out);
  ASSERT_EQ(origins.size(), lines.size()) << out;
  // Rung 1 is copied byte for byte, each line naming its statement.
  EXPECT_EQ(lines[0], "LD X0.0");
  EXPECT_EQ(origins[0].where, "PLC1 rung 1 element 1");
  EXPECT_EQ(origins[1].where, "PLC1 rung 1 element 2");
  EXPECT_EQ(origins[1].id, p->stmts[1].id);
  // Rung 2 is printed anew: its comment line goes to its first statement, the new contact is
  // element 2, the output element 3.
  bool sawComment = false, sawContact = false, sawOut = false;
  for (size_t i = 0; i < lines.size(); ++i) {
    if (lines[i].find("second rung") != std::string::npos) {
      sawComment = true;
      EXPECT_EQ(origins[i].where, "PLC1 rung 2 element 1") << lines[i];
    } else if (lines[i].rfind("ANI X0.2", 0) == 0) {
      sawContact = true;
      EXPECT_EQ(origins[i].where, "PLC1 rung 2 element 2") << lines[i];
    } else if (lines[i].rfind("OUT Y0.1", 0) == 0) {
      sawOut = true;
      EXPECT_EQ(origins[i].where, "PLC1 rung 2 element 3") << lines[i];
    }
  }
  EXPECT_TRUE(sawComment && sawContact && sawOut) << out;
  // The marker after the edit is copied again and named as its rung.
  EXPECT_EQ(lines.back(), "1END");
  EXPECT_EQ(origins.back().where, "PLC1 rung 3 element 1");
}

TEST(ToTextOrigins, UneditedNetworksGiveTheSourceAndOneOriginALine) {
  Diagnostics d("t.stl");
  std::optional<VerifiedProgram> p =
      pipeline::compileStl(kStl, "t.stl", VerifyOptions{}, d, nullptr);
  ASSERT_TRUE(p) << d.render();
  std::string out, error;
  std::vector<LineOrigin> origins;
  ASSERT_TRUE(programText(fromProgram(*p), *p, kStl, out, error, false, &origins)) << error;
  EXPECT_EQ(out, kStl);
  ASSERT_EQ(origins.size(), 6u);
  EXPECT_EQ(origins[2].where, "PLC1 rung 2 element 1"); // the comment line, before LD X0.1
  EXPECT_EQ(origins[4].where, "PLC1 rung 2 element 2");
}

} // namespace
} // namespace lj::ladder

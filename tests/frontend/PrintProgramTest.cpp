// printProgram: the dump used by `ladderjit check --print` and golden tests shows every fact of
// the verified program (values from DIALECT.md 3-4 and dialect-notes "PLC2 slicing").
#include "FrontEndTestUtil.h"
#include "verify/Verify.h"

#include <gtest/gtest.h>

#include <sstream>
#include <vector>

namespace lj {
namespace {

std::vector<std::vector<std::string>> words(const std::string &text) {
  std::vector<std::vector<std::string>> out;
  std::istringstream lines(text);
  std::string line;
  while (std::getline(lines, line)) {
    std::istringstream ws(line);
    std::vector<std::string> w;
    for (std::string x; ws >> x;) w.push_back(x);
    out.push_back(w);
  }
  return out;
}

using Words = std::vector<std::string>;

// PLC2 = LD/OUT/LDP/OUT with nvalue 1: the boundary is before LDP (the dead LD entry stays,
// depth 1), LDP owns edge slot 0.
TEST(PrintProgram, ShowsFacts) {
  VerifyOptions o;
  o.plc2Nvalue = 1;
  auto c = test::compile("LDT\nOUT Y9.0\n1END\nLD X0.0\nOUT Y0.0\nLDP X0.1\nOUT Y0.1\n2END\n"
                         "SP S3\nSPE\n",
                         o);
  ASSERT_TRUE(c.prog.has_value()) << c.diags;
  auto w = words(printProgram(*c.prog));
  ASSERT_EQ(w.size(), 16u);
  EXPECT_EQ(w[0], (Words{";", "program", "t.stl:", "10", "statements,", "1", "edge", "slots,",
                         "max", "ST", "depth", "2,", "max", "MS", "depth", "0"}));
  EXPECT_EQ(w[1], (Words{";", "init", "[0,0)", "plc1", "[0,2)", "plc2", "[3,7)"}));
  EXPECT_EQ(w[2], (Words{";", "sub", "S3", "sp", "8", "body", "[9,9)"}));
  EXPECT_EQ(w[3], (Words{";", "plc2", "nvalue", "1,", "2", "slice(s)"}));
  EXPECT_EQ(w[4], (Words{";", "slice", "0", "[3,5)", "st", "0"}));
  EXPECT_EQ(w[5], (Words{";", "slice", "1", "[5,7)", "st", "1"}));
  EXPECT_EQ(w[6], (Words{"0", "1:1", "plc1", "LDT", "st=0", "ms=0"}));
  EXPECT_EQ(w[7], (Words{"1", "2:1", "plc1", "OUT", "Y9.0", "st=1", "ms=0"}));
  EXPECT_EQ(w[8], (Words{"2", "3:1", "-", "1END", "st=0", "ms=0"}));
  EXPECT_EQ(w[9], (Words{"3", "4:1", "plc2", "LD", "X0.0", "st=0", "ms=0", "slice=0"}));
  EXPECT_EQ(w[10], (Words{"4", "5:1", "plc2", "OUT", "Y0.0", "st=1", "ms=0", "slice=0"}));
  EXPECT_EQ(w[11], (Words{"5", "6:1", "plc2", "LDP", "X0.1", "st=1", "ms=0", "slot=0", "slice=1"}));
  EXPECT_EQ(w[12], (Words{"6", "7:1", "plc2", "OUT", "Y0.1", "st=2", "ms=0", "slice=1"}));
  EXPECT_EQ(w[13], (Words{"7", "8:1", "-", "2END", "st=0", "ms=0"}));
  EXPECT_EQ(w[14], (Words{"8", "9:1", "-", "SP", "S3", "st=0", "ms=0"}));
  EXPECT_EQ(w[15], (Words{"9", "10:1", "-", "SPE", "st=0", "ms=0"}));
}

// Jumps, calls and blocks show target, input flag and the backward mark.
TEST(PrintProgram, ShowsTargetsAndFlags) {
  auto c = test::compile("LBL L1\nLD X0.0\nJMP L1\nLDT\nCALL S0\n2END\nSP S0\nSPE\n");
  ASSERT_TRUE(c.prog.has_value()) << c.diags;
  std::string out = printProgram(*c.prog);
  auto w = words(out);
  // 5 summary lines (program, parts, sub, nvalue, one slice) + 8 statements.
  ASSERT_EQ(w.size(), 13u) << out;
  EXPECT_EQ(w[7], (Words{"2", "3:1", "plc2", "JMP", "L1", "st=1", "ms=0", "target=0", "in", "back",
                         "slice=0"}));
  EXPECT_EQ(w[9],
            (Words{"4", "5:1", "plc2", "CALL", "S0", "st=2", "ms=0", "target=0", "in", "slice=0"}));
}

} // namespace
} // namespace lj

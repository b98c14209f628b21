// Golden diagnostics of the family-Cnc verifier checks (verify/VerifyCnc.cpp): the ALARM
// number gap, USEROUT's four bytes, SPDLBUS1's P block, constant MDST modes and the REFPT 5
// warning (hnc8-cnc-interface.md 2 #60, #20, #30, #1, #56; docs/cnc-blocks.md), and that
// docs/cnc-blocks.md lists the table as it is.
#include "FrontEndTestUtil.h"
#include "frontends/hnc8/Mnemonics.h"
#include "profiles/hnc8/CncTable.h"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

namespace lj {
namespace {

using test::compile;

std::string diags(std::string_view text) { return compile(text).diags; }

TEST(CncDiagnostics, AlarmNumberGap) {
  EXPECT_EQ(diags("LDT\nALARM 300\n"),
            "t.stl:2:7: error: ALARM number 300 is neither an alarm (1..256) nor a prompt "
            "(501..884) [LJ1040]\n");
  EXPECT_EQ(diags("LDT\nALARM 257\nALARM 500\n"),
            "t.stl:2:7: error: ALARM number 257 is neither an alarm (1..256) nor a prompt "
            "(501..884) [LJ1040]\n"
            "t.stl:3:7: error: ALARM number 500 is neither an alarm (1..256) nor a prompt "
            "(501..884) [LJ1040]\n");
  EXPECT_EQ(diags("LDT\nALARM 1\nALARM 256\nALARM 501\nALARM 884\n"), "");
}

TEST(CncDiagnostics, UserOutBytesMustFit) {
  EXPECT_EQ(diags("LDT\nUSEROUT 0 1 Y510\n"),
            "t.stl:2:13: error: USEROUT output bytes Y510..Y513 run past the end of Y "
            "(Y0..Y512) [LJ1041]\n");
  EXPECT_EQ(diags("LDT\nUSEROUT 0 1 R397\n"),
            "t.stl:2:13: error: USEROUT output bytes R397..R400 run past the end of R "
            "(R0..R399) [LJ1041]\n");
  EXPECT_EQ(diags("LDT\nUSEROUT 0 1 Y509\nUSEROUT 0 1 R396\n"), "");
}

TEST(CncDiagnostics, SpindleParameterBlockMustFit) {
  EXPECT_EQ(diags("LDT\nSPDLBUS1 0 1 R1 P196\n"),
            "t.stl:2:17: error: SPDLBUS1 parameter block P196..P200 runs past the end of P "
            "(P0..P199) [LJ1042]\n");
  EXPECT_EQ(diags("LDT\nSPDLBUS1 0 1 R1 P195\n"), "");
}

TEST(CncDiagnostics, MdstConstantModeIsOneHot) {
  EXPECT_EQ(diags("LDT\nMDST 0 3\n"),
            "t.stl:2:8: error: MDST mode 3 is not one of 1, 2, 4, 8, 16, 32, 64 (auto, single "
            "block, manual, increment, home, MPG, PMC) [LJ1043]\n");
  EXPECT_EQ(diags("LDT\nMDST 0 0\n"),
            "t.stl:2:8: error: MDST mode 0 is not one of 1, 2, 4, 8, 16, 32, 64 (auto, single "
            "block, manual, increment, home, MPG, PMC) [LJ1043]\n");
  EXPECT_EQ(diags("LDT\nMDST 0 64\nMDST 0 R0\n"), "");
}

TEST(CncDiagnostics, RefptFiveWarns) {
  test::Compiled c = compile("LDT\nREFPT 1 5\nOUT R1.0\n");
  EXPECT_TRUE(c.prog.has_value());
  EXPECT_EQ(c.diags, "t.stl:2:9: warning: REFPT 5: the 5th reference point has no status bit; "
                     "the output is always 0 [LJ1044]\n");
}

// docs/cnc-blocks.md renders the CNC table: one line per row, exactly as the table says.
TEST(CncDiagnostics, DocMatchesTable) {
  std::ifstream in(std::string(LJ_FRONTEND_DATA_DIR) + "/../../../docs/cnc-blocks.md");
  ASSERT_TRUE(in) << "docs/cnc-blocks.md not found";
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string doc = ss.str();
  for (const cnc::CncRow &r : cnc::cncTable()) {
    std::string line = std::string("| ") + hnc8::mnemonicOf(r.op) + " | " + r.effect + " | " +
                       (r.documented ? "documented" : "inferred") + " |\n";
    EXPECT_NE(doc.find(line), std::string::npos) << "missing or stale: " << line;
  }
}

} // namespace
} // namespace lj

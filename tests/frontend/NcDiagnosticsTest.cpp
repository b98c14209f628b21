// Golden diagnostics of family Nc's verifier checks (verify/VerifyNc.cpp): register blocks
// that must fit in their area, reported at the operand (DIALECT.md 6).
#include "FrontEndTestUtil.h"

#include <gtest/gtest.h>

namespace lj {
namespace {

using test::compile;

std::string diags(std::string_view text) { return compile(text).diags; }

TEST(NcDiagnostics, TempsenParameterBlockMustFit) {
  // P197..P200: the four board parameters run past P199.
  EXPECT_EQ(diags("TEMPSEN 0 X15 1 P197\n"),
            "t.stl:1:17: error: TEMPSEN parameter block P197..P200 runs past the end of area P "
            "(P0..P199) [LJ1049]\n");
  EXPECT_EQ(compile("TEMPSEN 0 X15 1 P196\n").errors, 0);
}

TEST(NcDiagnostics, TempsenAdWordMustFit) {
  // The AD word is X[n] (low byte) and X[n+1] (high byte).
  EXPECT_EQ(diags("TEMPSEN 0 X512 1 P0\n"),
            "t.stl:1:11: error: TEMPSEN AD word X512..X513 runs past the end of area X "
            "(X0..X512) [LJ1049]\n");
  EXPECT_EQ(compile("TEMPSEN 0 X511 1 P0\n").errors, 0);
}

TEST(NcDiagnostics, HeadsenRangeMustFit) {
  // hnc8-functions-2.md 2.21: reject start + count - 1 > 99.
  EXPECT_EQ(diags("LD X1.0\nHEADSEN 10 0 D91\n"),
            "t.stl:2:14: error: HEADSEN storage range D91..D100 runs past the end of area D "
            "(D0..D99) [LJ1049]\n");
  EXPECT_EQ(compile("LD X1.0\nHEADSEN 10 0 D90\n").errors, 0);
}

TEST(NcDiagnostics, SpdaParameterBlockMustFit) {
  EXPECT_EQ(diags("LDT\nSPDA 0 0 R1 R2 P196\n"),
            "t.stl:2:16: error: SPDA parameter block P196..P200 runs past the end of area P "
            "(P0..P199) [LJ1049]\n");
  EXPECT_EQ(compile("LDT\nSPDA 0 0 R1 R2 P195\n").errors, 0);
}

TEST(NcDiagnostics, NixieTwoBytesMustFit) {
  EXPECT_EQ(diags("LDT\nNIXIE R1 1 Y512\n"),
            "t.stl:2:12: error: NIXIE two-byte display Y512..Y513 runs past the end of area Y "
            "(Y0..Y512) [LJ1049]\n");
  EXPECT_EQ(compile("LDT\nNIXIE R1 0 Y512\n").errors, 0); // one byte fits
  EXPECT_EQ(compile("LDT\nNIXIE R1 1 W199\n").errors, 0); // a word holds both bytes
}

TEST(NcDiagnostics, AllErrorsReported) {
  test::Compiled c =
      compile("LDT\nSPDA 0 0 R1 R2 P199\nTEMPSEN 0 X15 1 P199\nLD X1.0\nHEADSEN 20 0 D99\n");
  EXPECT_EQ(c.errors, 3);
  EXPECT_FALSE(c.prog);
}

} // namespace
} // namespace lj

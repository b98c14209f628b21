// Golden diagnostics of the data operations (hnc8-functions-2.md 0.5, 2.2-2.18, DIALECT.md 6):
// ranges past the end of an area, FMOV/ZRST bounds, format constants and operand kinds, each an
// exact `file:line:col: error:` line at the offending operand; all errors are reported.
#include "FrontEndTestUtil.h"

#include <gtest/gtest.h>

namespace lj {
namespace {

using test::compile;

std::string diags(std::string_view text) { return compile(text).diags; }

// functions-2 0.5: `BMOV D98 D0 5` is an error (range past the end of the area).
TEST(DataDiagnostics, BmovSourceRange) {
  EXPECT_EQ(
      diags("LDT\nBMOV D98 D0 5\n"),
      "t.stl:2:6: error: BMOV source range D98..D102 runs past the end of D (D0..D99) [LJ1045]\n");
}

TEST(DataDiagnostics, BmovDestinationRange) {
  EXPECT_EQ(diags("LDT\nBMOV D0 W198 5\n"),
            "t.stl:2:9: error: BMOV destination range W198..W202 runs past the end of W "
            "(W0..W199) [LJ1045]\n");
}

// functions-2 2.3: the count is a constant (n <= 0 is rejected by the table's range).
TEST(DataDiagnostics, BmovCountConstant) {
  EXPECT_EQ(diags("LDT\nBMOV D0 D10 0\n"),
            "t.stl:2:13: error: constant '0' out of range for count of BMOV (1..1000) [LJ3016]\n");
  EXPECT_EQ(diags("LDT\nBMOV D0 D10 D1\n"),
            "t.stl:2:13: error: BMOV expects a constant as count, got register 'D1' [LJ3017]\n");
}

// functions-2 2.4: start and end of FMOV in one area, start <= end (dialect-notes).
TEST(DataDiagnostics, FmovBounds) {
  EXPECT_EQ(diags("LDT\nFMOV D0 W2 5\n"),
            "t.stl:2:9: error: FMOV start D0 and end W2 are in different areas [LJ1047]\n");
  EXPECT_EQ(diags("LDT\nFMOV D5 D1 0\n"),
            "t.stl:2:9: error: FMOV end D1 comes before start D5 [LJ1048]\n");
}

// functions-2 2.6: ZRST bounds in one form and one area, start <= end (bits ordered as
// index * width + bit).
TEST(DataDiagnostics, ZrstBounds) {
  EXPECT_EQ(diags("LDT\nZRST R1.0 R2\n"),
            "t.stl:2:11: error: ZRST start R1.0 and end R2 must both be registers or both be bit "
            "addresses [LJ1046]\n");
  EXPECT_EQ(diags("LDT\nZRST R2.3 R2.1\n"),
            "t.stl:2:11: error: ZRST end R2.1 comes before start R2.3 [LJ1048]\n");
  EXPECT_EQ(diags("LDT\nZRST W1 D3\n"),
            "t.stl:2:9: error: ZRST start W1 and end D3 are in different areas [LJ1047]\n");
  EXPECT_EQ(diags("LDT\nZRST R3 R2\n"),
            "t.stl:2:9: error: ZRST end R2 comes before start R3 [LJ1048]\n");
  EXPECT_EQ(diags("LDT\nZRST X1 R2\n"),
            "t.stl:2:6: error: X1 is read-only; ZRST cannot write its start (writable: Y, G, R, W, "
            "D or B) [LJ3010]\n");
}

// A one-element zone and a bit zone crossing an element boundary are fine.
TEST(DataDiagnostics, ZoneAccepted) {
  EXPECT_EQ(diags("LDT\nZRST D0 D0\nLDT\nZRST R1.7 R2.0\nLDT\nFMOV D3 D3 1\n"), "");
}

// functions-2 2.7-2.10: the table must lie inside its area; ENCO/DECO have at most 32 entries
// (one bit each in a 32-bit result).
TEST(DataDiagnostics, TableRanges) {
  EXPECT_EQ(diags("LDT\nENCO D98 5 D1 D2\n"),
            "t.stl:2:6: error: ENCO table D98..D102 runs past the end of D (D0..D99) [LJ1045]\n");
  EXPECT_EQ(
      diags("LDT\nENCO D0 33 D1 D2\n"),
      "t.stl:2:9: error: constant '33' out of range for table length of ENCO (1..32) [LJ3016]\n");
  EXPECT_EQ(diags("LD X1.0\nCOD D95 8 D1 D2\n"),
            "t.stl:2:5: error: COD table D95..D102 runs past the end of D (D0..D99) [LJ1045]\n");
  EXPECT_EQ(diags("LD X1.0\nSER W199 2 D1 D2\n"),
            "t.stl:2:5: error: SER table W199..W200 runs past the end of W (W0..W199) [LJ1045]\n");
  EXPECT_EQ(diags("LD X1.0\nDECO X500 13 D1 D2\n"), "");
}

// functions-2 2.11-2.13: ASSEM sources, DISAS destinations and the ACVT P block (P[k..k+3]).
TEST(DataDiagnostics, PackAndParameterBlock) {
  EXPECT_EQ(diags("LD X1.0\nASSEM X510 4 D0\n"), "t.stl:2:7: error: ASSEM source range X510..X513 "
                                                 "runs past the end of X (X0..X512) [LJ1045]\n");
  EXPECT_EQ(diags("LD X1.0\nDISAS D0 4 Y510\n"),
            "t.stl:2:12: error: DISAS destination range Y510..Y513 runs past the end of Y "
            "(Y0..Y512) [LJ1045]\n");
  EXPECT_EQ(diags("LD X1.0\nACVT P197 D0 D1\n"),
            "t.stl:2:6: error: ACVT parameter block P197..P200 runs past the end of P "
            "(P0..P199) [LJ1045]\n");
  EXPECT_EQ(diags("LD X1.0\nACVT P196 D0 D1\n"), "");
  EXPECT_EQ(
      diags("LD X1.0\nACVT D0 D0 D1\n"),
      "t.stl:2:6: error: area D is not allowed as parameter block of ACVT (allowed: P) [LJ3011]\n");
}

// functions-2 0.5 / 0.6: formats are constants 0..2, addresses registers of G R W D B.
TEST(DataDiagnostics, IndirectOperands) {
  EXPECT_EQ(diags("LDT\nXMOV 3 D0 0 D1\n"),
            "t.stl:2:6: error: constant '3' out of range for format 1 of XMOV (0..2) [LJ3016]\n");
  EXPECT_EQ(diags("LDT\nXMOV 0 5 0 D1\n"),
            "t.stl:2:8: error: XMOV expects a register as address 1, got constant '5' [LJ3015]\n");
  EXPECT_EQ(diags("LDT\nXCH 0 D0 0 X1\n"),
            "t.stl:2:12: error: X1 is read-only; XCH cannot write its address 2 (writable: G, R, "
            "W, D or B) [LJ3010]\n");
  EXPECT_EQ(diags("LDT\nXMOV 0 P3 2 D1\n"),
            "t.stl:2:8: error: area P is not allowed as address 1 of XMOV (allowed: G, R, W, D "
            "or B) [LJ3011]\n");
}

// functions-2 2.17-2.18: NTP's points are written; PTN needs all four pairs.
TEST(DataDiagnostics, PointOperands) {
  EXPECT_EQ(diags("LDT\nNTP R0 0 X0.0 1 Y0.1 2 Y0.2 3 Y0.3\n"),
            "t.stl:2:10: error: X0.0 is read-only; NTP cannot write its point 1 (writable: Y, G, "
            "R, W, D or B) [LJ3010]\n");
  EXPECT_EQ(diags("LDT\nPTN R0 Y0.0 0 Y0.1 1 Y0.2\n"),
            "t.stl:2:1: error: PTN takes 9 operands (destination, point 1, number 1, point 2, "
            "number 2, point 3, number 3, point 4, number 4), got 6 [LJ3003]\n");
}

// DIALECT.md 6: every error is reported, not only the first.
TEST(DataDiagnostics, AllErrorsReported) {
  test::Compiled c = compile("LDT\nBMOV D98 D99 5\nLDT\nZRST D9 D8\nLD X1.0\nACVT P199 D0 D1\n");
  EXPECT_EQ(c.errors, 4);
  EXPECT_EQ(
      c.diags,
      "t.stl:2:6: error: BMOV source range D98..D102 runs past the end of D (D0..D99) [LJ1045]\n"
      "t.stl:2:10: error: BMOV destination range D99..D103 runs past the end of D "
      "(D0..D99) [LJ1045]\n"
      "t.stl:4:9: error: ZRST end D8 comes before start D9 [LJ1048]\n"
      "t.stl:6:6: error: ACVT parameter block P199..P202 runs past the end of P "
      "(P0..P199) [LJ1045]\n");
}

} // namespace
} // namespace lj

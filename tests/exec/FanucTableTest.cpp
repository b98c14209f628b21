// FANUC BCD table instructions (fanuc-d: XMOV SUB 18, DSCH SUB 17) on every engine. Expected
// values are worked by hand from ../shared/reference/fanuc-pmc.md 6.2, 6.5 and 6.7 (cited per
// test), never what the code printed; the readings the reference leaves open are the [EXT]/[INF]
// rows of docs/fanuc-pmc.md.
#include "pipeline/Compile.h"
#include "tests/exec/FanucExec.h"

namespace lj::test {
namespace {

class FanucTable : public FanucExecTest {
protected:
  static int64_t byte(Machine &m, std::string_view a) { return get(m, a) & 0xFF; }
  static std::string d(int n) { return "D" + std::to_string(n); }
};
LJ_EXEC_SUITE(FanucTable);

// XMOV inputs BYT (X0.3), RW (X0.1), RST (X0.2), ACT (X0.0), loaded top to bottom (ref 5).
constexpr const char *kXmov = "RD X0.3\nRD.STK X0.1\nRD.STK X0.2\nRD.STK X0.0\n"
                              "XMOV 10 D150 R100 R200\nWRT R0.0\nEND1\nEND2\nEND\n";

// 6.5 XMOV, BYT = 0 (2-digit BCD, 1-byte items): capacity 10 = n + 1 for a table 0..9 [L2609],
// so index 9 (BCD 09) reads D159 and index 10 (BCD 10) is past it: W1 = 1 [L2625], nothing moved.
// RST clears W1 (6.2); ACT = 0 keeps it.
TEST_P(FanucTable, XmovReadsTwoDigitIndex) {
  auto m = pmc(kXmov);
  ASSERT_TRUE(m);
  for (int k = 0; k < 12; ++k) set(*m, d(150 + k), 0x10 + k);
  set(*m, "R200", 0x09);
  m->tick(); // ACT = 0: nothing moves
  EXPECT_EQ(byte(*m, "R100"), 0);
  set(*m, "X0.0", 1);
  m->tick();
  EXPECT_EQ(byte(*m, "R100"), 0x19); // D159
  EXPECT_EQ(get(*m, "R0.0"), 0);
  set(*m, "R200", 0x10); // index 10 with capacity 10
  set(*m, "R100", 0);
  m->tick();
  EXPECT_EQ(get(*m, "R0.0"), 1);
  EXPECT_EQ(byte(*m, "R100"), 0); // D160 not read
  set(*m, "X0.0", 0);             // ACT = 0 keeps W1 (6.2)
  m->tick();
  EXPECT_EQ(get(*m, "R0.0"), 1);
  set(*m, "X0.2", 1); // RST clears it
  m->tick();
  EXPECT_EQ(get(*m, "R0.0"), 0);
  set(*m, "X0.2", 0);
  set(*m, "X0.0", 1);
  set(*m, "R200", 0x0A); // not a BCD digit: an error (6.2 "invalid BCD")
  m->tick();
  EXPECT_EQ(get(*m, "R0.0"), 1);
  EXPECT_EQ(byte(*m, "R100"), 0);
  set(*m, "R200", 0x00); // index 0: D150
  m->tick();
  EXPECT_EQ(get(*m, "R0.0"), 0);
  EXPECT_EQ(byte(*m, "R100"), 0x10);
}

// 6.5 XMOV moves one item: with BYT = 1 the 2-byte item table[index] is copied as one value, so a
// table (R1) that overlaps the data (R2) still gives data = the item read before the move: R1 = 2,
// R2 = 0 -> R2 = 2, R3 = 0 (read, RW = 0); R2 = 5, R3 = 7 -> R1 = 5, R2 = 7 (write, RW = 1). Found
// by the 100k FANUC fuzz (the JIT copied byte by byte).
TEST_P(FanucTable, XmovOverlappingTableAndData) {
  auto m = pmc("RD X0.3\nRD.STK X0.1\nRD.STK X0.2\nRD.STK X0.0\n"
               "XMOV 12 R1 R2 R8\nEND1\nEND2\nEND\n");
  ASSERT_TRUE(m);
  set(*m, "X0.3", 1); // BYT = 1
  set(*m, "X0.0", 1); // ACT
  set(*m, "R1", 2);
  m->tick();
  EXPECT_EQ(byte(*m, "R2"), 2);
  EXPECT_EQ(byte(*m, "R3"), 0);
  set(*m, "X0.1", 1); // RW = 1: data R2..R3 into table[0] = R1..R2
  set(*m, "R2", 5);
  set(*m, "R3", 7);
  m->tick();
  EXPECT_EQ(byte(*m, "R1"), 5);
  EXPECT_EQ(byte(*m, "R2"), 7);
}

// 6.5 XMOV, BYT = 1 (4-digit BCD, 2-byte items, index in 2 bytes): item k is D150 + 2k, D151 + 2k.
// RW = 1 writes the data into the table [L2481-L2485].
TEST_P(FanucTable, XmovWritesFourDigitItems) {
  auto m = pmc(kXmov);
  ASSERT_TRUE(m);
  set(*m, "X0.3", 1);
  set(*m, "X0.1", 1);
  set(*m, "X0.0", 1);
  set(*m, "R200", 0x03); // BCD 0003
  set(*m, "R201", 0x00);
  set(*m, "R100", 0x34); // the BCD item 1234
  set(*m, "R101", 0x12);
  m->tick();
  EXPECT_EQ(byte(*m, "D156"), 0x34);
  EXPECT_EQ(byte(*m, "D157"), 0x12);
  EXPECT_EQ(byte(*m, "D155"), 0);
  EXPECT_EQ(byte(*m, "D158"), 0);
  EXPECT_EQ(get(*m, "R0.0"), 0);
  // Read it back (RW = 0) into R100..R101.
  set(*m, "X0.1", 0);
  set(*m, "R100", 0);
  set(*m, "R101", 0);
  m->tick();
  EXPECT_EQ(byte(*m, "R100"), 0x34);
  EXPECT_EQ(byte(*m, "R101"), 0x12);
  // BCD 0100 = index 100: past capacity 10 (the high byte counts with BYT = 1).
  set(*m, "R200", 0x00);
  set(*m, "R201", 0x01);
  m->tick();
  EXPECT_EQ(get(*m, "R0.0"), 1);
  // BYT = 0 reads only the low byte R200 = BCD 00: index 0, one byte D150 -> R100.
  set(*m, "X0.3", 0);
  set(*m, "D150", 0x77);
  m->tick();
  EXPECT_EQ(get(*m, "R0.0"), 0);
  EXPECT_EQ(byte(*m, "R100"), 0x77);
  EXPECT_EQ(byte(*m, "R101"), 0x12); // untouched with 1-byte items
}

// 6.5: an item past the end of the table's area is an error too (docs/fanuc-pmc.md [INF]):
// head D9998, capacity 5; BYT = 1 index 1 is D10000..D10001, outside D0-D9999.
TEST_P(FanucTable, XmovRangeEnd) {
  auto m = pmc("RD X0.3\nRD.STK X0.1\nRD.STK X0.2\nRD.STK X0.0\nXMOV 5 D9998 R100 R200\n"
               "WRT R0.0\nEND1\nEND2\nEND\n");
  ASSERT_TRUE(m);
  set(*m, "X0.0", 1);
  set(*m, "X0.3", 1);
  set(*m, "D9998", 0x21);
  set(*m, "D9999", 0x43);
  m->tick(); // index 0: D9998..D9999
  EXPECT_EQ(get(*m, "R0.0"), 0);
  EXPECT_EQ(byte(*m, "R100"), 0x21);
  EXPECT_EQ(byte(*m, "R101"), 0x43);
  set(*m, "R200", 0x01);
  m->tick();
  EXPECT_EQ(get(*m, "R0.0"), 1);
  set(*m, "X0.3", 0); // BYT = 0: index 1 is D9999
  m->tick();
  EXPECT_EQ(get(*m, "R0.0"), 0);
  EXPECT_EQ(byte(*m, "R100"), 0x43);
}

// DSCH inputs BYT (X0.3), RST (X0.2), ACT (X0.0).
constexpr const char *kDsch = "RD X0.3\nRD.STK X0.2\nRD.STK X0.0\nDSCH 5 D100 R10 R20\nWRT R0.0\n"
                              "END1\nEND2\nEND\n";

// 6.7 DSCH, BYT = 0: the first of the 5 items equal to the search data; its index goes to the
// result in BCD [L3047]; not found: W1 = 1 [L3051], the result kept. D105 is past capacity 5.
TEST_P(FanucTable, DschFindsFirstTwoDigitItem) {
  auto m = pmc(kDsch);
  ASSERT_TRUE(m);
  const int items[] = {0x11, 0x22, 0x33, 0x22, 0x55, 0x44};
  for (int k = 0; k < 6; ++k) set(*m, d(100 + k), items[k]);
  set(*m, "R10", 0x22);
  set(*m, "R20", 0x99);
  m->tick(); // ACT = 0
  EXPECT_EQ(byte(*m, "R20"), 0x99);
  set(*m, "X0.0", 1);
  m->tick();
  EXPECT_EQ(byte(*m, "R20"), 0x01); // the first of items 1 and 3
  EXPECT_EQ(get(*m, "R0.0"), 0);
  set(*m, "R10", 0x55);
  m->tick();
  EXPECT_EQ(byte(*m, "R20"), 0x04);
  set(*m, "R10", 0x44); // only in D105, past the capacity
  m->tick();
  EXPECT_EQ(get(*m, "R0.0"), 1);
  EXPECT_EQ(byte(*m, "R20"), 0x04);
  set(*m, "X0.2", 1); // RST clears W1 (6.2); the search still runs
  m->tick();
  EXPECT_EQ(get(*m, "R0.0"), 0);
}

// 6.7 DSCH, BYT = 1: 2-byte items D100+2k; the index is written as 4 BCD digits.
TEST_P(FanucTable, DschFourDigitItems) {
  auto m = pmc(kDsch);
  ASSERT_TRUE(m);
  set(*m, "X0.3", 1);
  set(*m, "X0.0", 1);
  set(*m, "D104", 0x34); // item 2 = 0x1234
  set(*m, "D105", 0x12);
  set(*m, "D108", 0x34); // item 4 = 0x5634
  set(*m, "D109", 0x56);
  set(*m, "R10", 0x34);
  set(*m, "R11", 0x56);
  set(*m, "R21", 0x77);
  m->tick();
  EXPECT_EQ(get(*m, "R0.0"), 0);
  EXPECT_EQ(byte(*m, "R20"), 0x04);
  EXPECT_EQ(byte(*m, "R21"), 0x00);
  set(*m, "R11", 0x12);
  m->tick();
  EXPECT_EQ(byte(*m, "R20"), 0x02);
  set(*m, "X0.3", 0); // BYT = 0: 1-byte items; 0x34 is D104 = item 4, R21 untouched
  set(*m, "R21", 0x77);
  m->tick();
  EXPECT_EQ(byte(*m, "R20"), 0x04);
  EXPECT_EQ(byte(*m, "R21"), 0x77);
}

// 6.7 DSCH: with BYT = 0 the result holds 2 BCD digits, so a match at index 99 is written as
// BCD 99 and one at index 100 or later is an error (docs/fanuc-pmc.md [INF]).
TEST_P(FanucTable, DschTwoDigitResultLimit) {
  auto m = pmc("RD X0.3\nRD.STK X0.2\nRD.STK X0.0\nDSCH 150 D0 R10 R20\nWRT R0.0\n"
               "END1\nEND2\nEND\n");
  ASSERT_TRUE(m);
  for (int k = 0; k < 150; ++k) set(*m, d(k), 0x01);
  set(*m, "D99", 0x02);
  set(*m, "D120", 0x03);
  set(*m, "X0.0", 1);
  set(*m, "R10", 0x02);
  m->tick();
  EXPECT_EQ(get(*m, "R0.0"), 0);
  EXPECT_EQ(byte(*m, "R20"), 0x99);
  set(*m, "R10", 0x03);
  m->tick();
  EXPECT_EQ(get(*m, "R0.0"), 1);
  EXPECT_EQ(byte(*m, "R20"), 0x99); // kept
  set(*m, "X0.3", 1);               // BYT = 1: items D0-D1, ...; 0x0303 is nowhere
  m->tick();
  EXPECT_EQ(get(*m, "R0.0"), 1);
  set(*m, "R11", 0x01);
  set(*m, "R10", 0x01); // 0x0101: item 0
  m->tick();
  EXPECT_EQ(get(*m, "R0.0"), 0);
  EXPECT_EQ(get(*m, "R20:2"), 0);
}

// Located errors for XMOV and DSCH (docs/fanuc-pmc.md "Rules").
TEST(FanucTableRules, LocatedErrors) {
  struct Case {
    const char *text;
    const char *want;
    int line, col;
  };
  const char *in3 = "RD X0.0\nRD.STK X0.0\nRD.STK X0.1\n";
  const char *in4 = "RD X0.0\nRD.STK X0.0\nRD.STK X0.1\nRD.STK X0.2\n";
  const std::string end = "END1\nEND2\nEND\n";
  const Case cases[] = {
      {"RD X0.0\nRD.STK X0.0\nRD.STK X0.1\nXMOV 10 D0 R0 R2\n",
       "XMOV needs its inputs BYT, RW, RST, ACT", 4, 1},
      {"RD X0.0\nRD.STK X0.1\nDSCH 10 D0 R0 R2\n", "DSCH needs its inputs BYT, RST, ACT", 3, 1},
      {"", "XMOV takes 4 parameters", 5, 1},
      {"", "expected a number as table capacity, got 'R5'", 5, 6},
      {"", "table capacity '0' out of range (1..9999)", 5, 6},
      {"", "table capacity '10000' out of range (1..9999)", 4, 6},
      {"", "DSCH searches the data table only", 4, 9},
      {"", "DSCH takes 4 parameters", 4, 1},
  };
  const std::string tails[] = {"",
                               "",
                               "XMOV 10 D0 R0\n",
                               "XMOV R5 D0 R0 R2\n",
                               "XMOV 0 D0 R0 R2\n",
                               "DSCH 10000 D0 R0 R2\n",
                               "DSCH 10 R0 R0 R2\n",
                               "DSCH 10 D0 R0 R2 R4\n"};
  for (size_t i = 0; i < sizeof(cases) / sizeof(cases[0]); ++i) {
    const Case &c = cases[i];
    std::string text = c.text;
    if (text.empty()) text = std::string(tails[i].rfind("XMOV", 0) == 0 ? in4 : in3) + tails[i];
    text += end;
    Diagnostics d("t.pmc");
    EXPECT_FALSE(pipeline::compilePmc(text, "t.pmc", VerifyOptions{}, d, nullptr)) << text;
    const std::string out = d.render();
    EXPECT_NE(out.find(c.want), std::string::npos) << out;
    const std::string loc = "t.pmc:" + std::to_string(c.line) + ":" + std::to_string(c.col) + ":";
    EXPECT_NE(out.find(loc), std::string::npos) << out << " want " << loc;
  }
}

} // namespace
} // namespace lj::test

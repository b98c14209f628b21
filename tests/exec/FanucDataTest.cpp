// FANUC transfer, search, conversion and flow instructions (fanuc-b) on every engine: the test
// vectors 8, 10-14 of ../shared/reference/fanuc-pmc.md section 7 and the rules of 6.5, 6.7-6.9,
// 4.2; expected values are the reference's (cited per test), never what the code printed. The
// readings the reference leaves open are the [EXT]/[INF] rows of docs/fanuc-pmc.md.
#include "pipeline/Compile.h"
#include "tests/exec/FanucExec.h"

namespace lj::test {
namespace {

class FanucData : public FanucExecTest {
protected:
  /// A byte as its unsigned bit pattern.
  static int64_t byte(Machine &m, std::string_view a) { return get(m, a) & 0xFF; }
  static std::string r(int n) { return "R" + std::to_string(n); }
  static std::string d(int n) { return "D" + std::to_string(n); }
};
LJ_EXEC_SUITE(FanucData);

// 7.8 XMOVB [L2535-L2551], read as d = 1, nn = 02 (docs/fanuc-pmc.md [INF] "XMOVB example"):
// table head D150, capacity R300 = 10, index R200 = 2; with X0.0 = 1, R100 <- D152 and
// R101 <- D153. An index whose items pass the capacity gives W1 = 1 (6.5 [L2527]).
TEST_P(FanucData, XmovbReadsTwoItemsFromIndexTwo) {
  auto m = pmc("RD X0.1\nRD.STK X0.2\nRD.STK X0.0\nXMOVB 0021 R300 D150 R100 R200\nWRT R0.0\n"
               "END1\nEND2\nEND\n");
  ASSERT_TRUE(m);
  for (int k = 0; k < 10; ++k) set(*m, d(150 + k), 0x30 + k);
  set(*m, "R300", 10);
  set(*m, "R200", 2);
  m->tick(); // ACT = 0: nothing moves
  EXPECT_EQ(get(*m, "R100:2"), 0);
  set(*m, "X0.0", 1);
  m->tick();
  EXPECT_EQ(byte(*m, "R100"), 0x32); // D152
  EXPECT_EQ(byte(*m, "R101"), 0x33); // D153
  EXPECT_EQ(get(*m, "R0.0"), 0);
  set(*m, "R200", 9); // items 9 and 10: 10 is past capacity 10
  set(*m, "R100", 0);
  m->tick();
  EXPECT_EQ(get(*m, "R0.0"), 1);
  EXPECT_EQ(byte(*m, "R100"), 0);
  set(*m, "X0.2", 1); // RST clears W1 (6.2)
  m->tick();
  EXPECT_EQ(get(*m, "R0.0"), 0);
  // RW = 1 writes the data into the table (6.5, errata L2485).
  set(*m, "X0.2", 0);
  set(*m, "X0.1", 1);
  set(*m, "R200", 4);
  set(*m, "R100", 0x5A);
  set(*m, "R101", 0xA5);
  m->tick();
  EXPECT_EQ(byte(*m, "D154"), 0x5A);
  EXPECT_EQ(byte(*m, "D155"), 0xA5);
  EXPECT_EQ(byte(*m, "D156"), 0x36);
  EXPECT_EQ(get(*m, "R0.0"), 0);
}

// 6.5 XMOVB with 2-byte items, basic specification (nn = 00: one item): item k is the two bytes
// at D150 + 2k, little-endian (3.1).
TEST_P(FanucData, XmovbTwoByteItems) {
  auto m = pmc("RD R9091.0\nRD.STK R9091.0\nRD.STK R9091.1\nXMOVB 0002 R300 D150 R100 R200\n"
               "WRT R0.0\nEND1\nEND2\nEND\n");
  ASSERT_TRUE(m);
  set(*m, "D154:2", -1234);
  set(*m, "R300:2", 5);
  set(*m, "R200:2", 2);
  m->tick();
  EXPECT_EQ(get(*m, "R100:2"), -1234);
  EXPECT_EQ(get(*m, "R0.0"), 0);
  set(*m, "R200:2", 5); // index 5 with capacity 5
  m->tick();
  EXPECT_EQ(get(*m, "R0.0"), 1);
  set(*m, "R200:2", -1);
  m->tick();
  EXPECT_EQ(get(*m, "R0.0"), 1);
}

// 7.10 PARI [L3439-L3443]: odd check (O.E = 1); X10 = 00111010 (four 1s) -> R0.0 = 1;
// X10 = 00111000 (three 1s) -> R0.0 = 0. Even check (O.E = 0) is the opposite (6.8).
TEST_P(FanucData, PariOddParityExample) {
  auto m = pmc("RD R9091.1\nRD.STK X0.1\nRD.STK X0.0\nPARI X10\nWRT R0.0\n"
               "RD R9091.0\nRD.STK X0.1\nRD.STK X0.0\nPARI X10\nWRT R0.1\nEND1\nEND2\nEND\n");
  ASSERT_TRUE(m);
  set(*m, "X0.0", 1);
  set(*m, "X10", 0b00111010);
  m->tick();
  EXPECT_EQ(get(*m, "R0.0"), 1);
  EXPECT_EQ(get(*m, "R0.1"), 0);
  set(*m, "X10", 0b00111000);
  m->tick();
  EXPECT_EQ(get(*m, "R0.0"), 0);
  EXPECT_EQ(get(*m, "R0.1"), 1);
  // ACT = 0 keeps W1; RST = 1 clears it (6.2, docs [EXT] "W1 of the RST family").
  set(*m, "X0.0", 0);
  m->tick();
  EXPECT_EQ(get(*m, "R0.1"), 1);
  set(*m, "X0.1", 1);
  m->tick();
  EXPECT_EQ(get(*m, "R0.1"), 0);
}

// 6.8 SFT [L3449-L3501]: 16 bits shifted by one; DIR 0 left, 1 right; W1 = 1 when a 1 is
// shifted out; CONT = 1 keeps the 1s ([INF] result = shifted | original).
TEST_P(FanucData, SftShiftsSixteenBits) {
  auto m = pmc("RD X0.3\nRD.STK X0.2\nRD.STK X0.1\nRD.STK X0.0\nSFT R100\nWRT R0.0\n"
               "END1\nEND2\nEND\n");
  ASSERT_TRUE(m);
  set(*m, "R100:2", 0x8001);
  set(*m, "X0.0", 1);
  m->tick(); // left
  EXPECT_EQ(get(*m, "R100:2"), 0x0002);
  EXPECT_EQ(get(*m, "R0.0"), 1);
  m->tick();
  EXPECT_EQ(get(*m, "R100:2"), 0x0004);
  EXPECT_EQ(get(*m, "R0.0"), 0);
  set(*m, "X0.3", 1); // right
  set(*m, "R100:2", 0x8001);
  m->tick();
  EXPECT_EQ(get(*m, "R100:2"), 0x4000);
  EXPECT_EQ(get(*m, "R0.0"), 1);
  set(*m, "X0.2", 1); // CONT, right: 0x4000 | 0x2000
  m->tick();
  EXPECT_EQ(get(*m, "R100:2"), 0x6000);
  EXPECT_EQ(get(*m, "R0.0"), 0);
  set(*m, "X0.3", 0); // CONT, left: 0x6000 | 0xC000
  m->tick();
  EXPECT_EQ(get(*m, "R100:2") & 0xFFFF, 0xE000);
}

// 7.11 COD [L3567-L3571]: R100 = 0 -> R200 = 10, R100 = 1 -> R200 = 3. The index and the table
// are BCD (6.9), so R200 holds BCD 10 = 0x10. An index past the table: W1 = 1, R200 kept.
TEST_P(FanucData, CodTableExample) {
  auto m = pmc("RD R9091.0\nRD.STK X0.1\nRD.STK X0.0\nCOD 2 R100 R200\n(PRM) 10\n(PRM) 3\n"
               "WRT R0.0\nEND1\nEND2\nEND\n");
  ASSERT_TRUE(m);
  set(*m, "X0.0", 1);
  set(*m, "R100", 0);
  m->tick();
  EXPECT_EQ(byte(*m, "R200"), 0x10);
  EXPECT_EQ(get(*m, "R0.0"), 0);
  set(*m, "R100", 1);
  m->tick();
  EXPECT_EQ(byte(*m, "R200"), 0x03);
  EXPECT_EQ(byte(*m, "R201"), 0); // BYT = 0: one byte
  set(*m, "R100", 2);
  m->tick();
  EXPECT_EQ(get(*m, "R0.0"), 1);
  EXPECT_EQ(byte(*m, "R200"), 0x03);
  set(*m, "R100", 0x1A); // not BCD
  set(*m, "X0.1", 1);    // RST
  m->tick();
  EXPECT_EQ(get(*m, "R0.0"), 0);
}

// 6.9 COD with BYT = 1: 4-digit BCD entries, two bytes out (3.2 [L389-L409]: 1234 is 34, 12).
TEST_P(FanucData, CodFourDigitEntries) {
  auto m = pmc("RD R9091.1\nRD.STK R9091.0\nRD.STK R9091.1\nSUB 7\n(PRM) 12\n(PRM) R100\n"
               "(PRM) D10\n(PRM) 0\n(PRM) 1\n(PRM) 2\n(PRM) 3\n(PRM) 4\n(PRM) 5\n(PRM) 6\n"
               "(PRM) 7\n(PRM) 8\n(PRM) 9\n(PRM) 1234\n(PRM) 9999\nEND1\nEND2\nEND\n");
  ASSERT_TRUE(m);
  set(*m, "R100", 0x10); // BCD 10: the eleventh entry, 1234
  m->tick();
  EXPECT_EQ(byte(*m, "D10"), 0x34);
  EXPECT_EQ(byte(*m, "D11"), 0x12);
  set(*m, "R100", 0x11);
  m->tick();
  EXPECT_EQ(get(*m, "D10:2") & 0xFFFF, 0x9999);
}

// 6.9 CODB [L3577-L3629] with the Gray-code table of 3.4 [L513-L821]: a binary index (the Gray
// code read from X0) selects the value it encodes, for all 16 codes.
TEST_P(FanucData, CodbDecodesTheGrayCodeTable) {
  const int gray[16] = {0b0000, 0b0001, 0b0011, 0b0010, 0b0110, 0b0111, 0b0101, 0b0100,
                        0b1100, 0b1101, 0b1111, 0b1110, 0b1010, 0b1011, 0b1001, 0b1000};
  int value[16] = {};
  for (int v = 0; v < 16; ++v) value[gray[v]] = v;
  std::string text = "RD R9091.0\nRD.STK R9091.1\nCODB 2 16 X0 D20";
  for (int g = 0; g < 16; ++g) text += " " + std::to_string(value[g] * 1000 - 7000);
  text += "\nWRT R0.0\nEND1\nEND2\nEND\n";
  auto m = pmc(text);
  ASSERT_TRUE(m);
  for (int v = 0; v < 16; ++v) {
    set(*m, "X0", gray[v]);
    m->tick();
    EXPECT_EQ(get(*m, "D20:2"), v * 1000 - 7000) << "gray " << gray[v];
    EXPECT_EQ(get(*m, "R0.0"), 0);
  }
  set(*m, "X0", 16); // past the 16 entries
  m->tick();
  EXPECT_EQ(get(*m, "R0.0"), 1);
}

// 7.12 DEC [L3857-L3871]: ACT = F7.0, data F10, spec 0311 -> R0.0 = 1 iff F10 = 3; binary 10
// (0x0A) is not BCD 10, so it does not match 1011 either; ACT = 0 -> W1 = 0 (6.2 [L3849]).
TEST_P(FanucData, DecDecodesM3) {
  auto m = pmc("RD F7.0\nDEC F10 0311\nWRT R0.0\nRD F7.0\nDEC F10 1011\nWRT R0.1\n"
               "RD F7.0\nDEC F10 0501\nWRT R0.2\nRD F7.0\nDEC F10 1010\nWRT R0.3\n"
               "END1\nEND2\nEND\n");
  ASSERT_TRUE(m);
  set(*m, "F7.0", 1);
  set(*m, "F10", 3);
  m->tick();
  EXPECT_EQ(get(*m, "R0.0"), 1);
  EXPECT_EQ(get(*m, "R0.1"), 0);
  set(*m, "F10", 4);
  m->tick();
  EXPECT_EQ(get(*m, "R0.0"), 0);
  set(*m, "F10", 0x0A);
  m->tick();
  EXPECT_EQ(get(*m, "R0.1"), 0);
  set(*m, "F10", 0x10); // BCD 10
  m->tick();
  EXPECT_EQ(get(*m, "R0.1"), 1);
  set(*m, "F10", 0x35); // 01: low digit 5 only; 10: high digit 1 only
  m->tick();
  EXPECT_EQ(get(*m, "R0.2"), 1);
  EXPECT_EQ(get(*m, "R0.3"), 0);
  set(*m, "F10", 0x15);
  m->tick();
  EXPECT_EQ(get(*m, "R0.3"), 1);
  set(*m, "F7.0", 0);
  set(*m, "F10", 3);
  m->tick();
  EXPECT_EQ(get(*m, "R0.0"), 0);
}

// 7.13 DECB [L4041-L4085]: format 0001, spec 3, output R10: F10 = k in 3..10 -> only
// R10.(k - 3) = 1; other values -> R10 = 0; ACT = 0 -> all outputs 0 (6.2 [L3899]).
TEST_P(FanucData, DecbDecodesM3ToM10) {
  auto m = pmc("RD X0.0\nDECB 0001 F10 3 R10\nEND1\nEND2\nEND\n");
  ASSERT_TRUE(m);
  set(*m, "X0.0", 1);
  for (int k = 0; k <= 12; ++k) {
    set(*m, "F10", k);
    m->tick();
    EXPECT_EQ(byte(*m, "R10"), k >= 3 && k <= 10 ? 1 << (k - 3) : 0) << "F10 = " << k;
  }
  set(*m, "F10", 5);
  set(*m, "X0.0", 0);
  m->tick();
  EXPECT_EQ(byte(*m, "R10"), 0);
}

// 6.9 DECB with 2-byte data and nn = 02 groups: byte j bit k for value spec + 8j + k.
TEST_P(FanucData, DecbTwoGroupsOfWords) {
  auto m = pmc("RD R9091.1\nDECB 0022 D0 -4 R20\nEND1\nEND2\nEND\n");
  ASSERT_TRUE(m);
  set(*m, "D0:2", -4);
  m->tick();
  EXPECT_EQ(get(*m, "R20:2"), 0x0001);
  set(*m, "D0:2", 11); // -4 + 8 + 7
  m->tick();
  EXPECT_EQ(get(*m, "R20:2") & 0xFFFF, 0x8000);
  set(*m, "D0:2", 12);
  m->tick();
  EXPECT_EQ(get(*m, "R20:2"), 0);
}

// 7.14 data formats, 3.2 [L411-L427]: 63 is BCD 01100011; 1234 is 00110100 (34), 00010010 (12).
// DCNV converts both ways (BYT 0 one byte, 1 two bytes; CNV 0 binary -> BCD, 1 BCD -> binary).
TEST_P(FanucData, DcnvBcdSixtyThreeAndTwelveThirtyFour) {
  auto m = pmc("RD X0.3\nRD.STK X0.2\nRD.STK X0.1\nRD.STK X0.0\nDCNV D0 R10\nWRT R0.0\n"
               "END1\nEND2\nEND\n");
  ASSERT_TRUE(m);
  set(*m, "X0.0", 1);
  set(*m, "D0", 63);
  m->tick();
  EXPECT_EQ(byte(*m, "R10"), 0b01100011);
  EXPECT_EQ(get(*m, "R0.0"), 0);
  set(*m, "X0.3", 1); // two bytes
  set(*m, "D0:2", 1234);
  m->tick();
  EXPECT_EQ(byte(*m, "R10"), 0b00110100);
  EXPECT_EQ(byte(*m, "R11"), 0b00010010);
  set(*m, "X0.2", 1); // BCD -> binary
  set(*m, "D0", 0b00110100);
  set(*m, "D1", 0b00010010);
  m->tick();
  EXPECT_EQ(get(*m, "R10:2"), 1234);
  set(*m, "X0.3", 0);
  set(*m, "D0", 0b01100011);
  m->tick();
  EXPECT_EQ(get(*m, "R10"), 63);
  // W1 = 1 for input that is not BCD, or a binary value too big for the digits (6.9 L3691).
  set(*m, "D0", 0x0A);
  m->tick();
  EXPECT_EQ(get(*m, "R0.0"), 1);
  EXPECT_EQ(get(*m, "R10"), 63);
  set(*m, "X0.2", 0);
  set(*m, "D0", 100);
  m->tick();
  EXPECT_EQ(get(*m, "R0.0"), 1);
  set(*m, "D0", 99);
  m->tick();
  EXPECT_EQ(get(*m, "R0.0"), 0);
  EXPECT_EQ(byte(*m, "R10"), 0x99);
}

// 7.14 with 3.1 [L255-L289] and 6.9 DCNVB [L3703-L3793]: -100 (4 bytes 10011100 11111111
// 11111111 11111111) converts to BCD 100 with R9000.1 (N) = 1; BCD 100 with SIN = 1 converts
// back to those bytes; an overflow sets R9000.5 (V) and W1.
TEST_P(FanucData, DcnvbSignedHundred) {
  auto m = pmc("RD X0.3\nRD.STK X0.2\nRD.STK X0.1\nRD.STK X0.0\nDCNVB 4 D0 R10\nWRT R0.0\n"
               "RD X0.3\nRD.STK X0.2\nRD.STK X0.1\nRD.STK X0.0\nDCNVB 1 D8 R20\nWRT R0.1\n"
               "END1\nEND2\nEND\n");
  ASSERT_TRUE(m);
  set(*m, "X0.0", 1);
  set(*m, "D0", 0b10011100);
  for (int k = 1; k < 4; ++k) set(*m, d(k), 0b11111111);
  set(*m, "D8", 100); // one byte: 100 needs three digits
  m->tick();
  EXPECT_EQ(get(*m, "R10:4"), 0x100);
  EXPECT_EQ(get(*m, "R0.0"), 0);
  EXPECT_EQ(get(*m, "R9000.5"), 1); // the second DCNVB ran last: overflow
  EXPECT_EQ(get(*m, "R0.1"), 1);
  set(*m, "D8", 99);
  m->tick();
  EXPECT_EQ(get(*m, "R9000.1"), 0);
  EXPECT_EQ(get(*m, "R9000.5"), 0);
  EXPECT_EQ(byte(*m, "R20"), 0x99);
  set(*m, "D8", -7);
  m->tick();
  EXPECT_EQ(get(*m, "R9000.1"), 1);
  EXPECT_EQ(byte(*m, "R20"), 0x07);
  // BCD -> binary with SIN = 1.
  set(*m, "X0.2", 1);
  set(*m, "X0.3", 1);
  set(*m, "D0:4", 0x100);
  set(*m, "D8", 0x42);
  m->tick();
  EXPECT_EQ(byte(*m, "R10"), 0b10011100);
  for (int k = 11; k < 14; ++k) EXPECT_EQ(byte(*m, r(k)), 0b11111111);
  EXPECT_EQ(get(*m, "R20"), -42);
  EXPECT_EQ(get(*m, "R9000.1"), 1);
  set(*m, "D8", 0x4B); // not BCD
  m->tick();
  EXPECT_EQ(get(*m, "R0.1"), 1);
  EXPECT_EQ(get(*m, "R20"), -42);
}

// 6.7 DSCHB [L2989-L3051]: the index of the first equal item goes to the result; W1 = 1 when
// not found (result kept); RST clears W1.
TEST_P(FanucData, DschbFindsTheFirstEqualItem) {
  auto m = pmc("RD X0.1\nRD.STK X0.0\nDSCHB 2 R300 D100 R310 R320\nWRT R0.0\nEND1\nEND2\nEND\n");
  ASSERT_TRUE(m);
  const int items[6] = {5, -7, 300, -7, 42, 300};
  for (int k = 0; k < 6; ++k) set(*m, d(100 + 2 * k) + ":2", items[k]);
  set(*m, "R300:2", 6);
  set(*m, "X0.0", 1);
  set(*m, "R310:2", 300);
  m->tick();
  EXPECT_EQ(get(*m, "R320:2"), 2);
  EXPECT_EQ(get(*m, "R0.0"), 0);
  set(*m, "R310:2", -7);
  m->tick();
  EXPECT_EQ(get(*m, "R320:2"), 1);
  set(*m, "R310:2", 42);
  set(*m, "R300:2", 4); // item 4 is outside a capacity of 4
  m->tick();
  EXPECT_EQ(get(*m, "R0.0"), 1);
  EXPECT_EQ(get(*m, "R320:2"), 1);
  set(*m, "X0.1", 1);
  m->tick();
  EXPECT_EQ(get(*m, "R0.0"), 0);
}

// 4.2 COM [EXT]: with ACT = 0 the coils up to COME are written 0 (WRT and WRT.NOT; SET/RST
// see input 0); the instructions in between still run.
TEST_P(FanucData, ComWritesItsCoilsZeroWhenOff) {
  auto m = pmc("RD X0.0\nCOM\nRD X0.1\nWRT R0.0\nWRT.NOT R0.1\nSET R0.2\nRD X0.1\nMOVB X1 R10\n"
               "COME\nRD X0.1\nWRT R0.3\nEND1\nEND2\nEND\n");
  ASSERT_TRUE(m);
  set(*m, "X1", 0x5C);
  set(*m, "X0.1", 1);
  m->tick(); // COM off
  EXPECT_EQ(get(*m, "R0.0"), 0);
  EXPECT_EQ(get(*m, "R0.1"), 0);
  EXPECT_EQ(get(*m, "R0.2"), 0);
  EXPECT_EQ(byte(*m, "R10"), 0x5C); // MOVB still ran
  EXPECT_EQ(get(*m, "R0.3"), 1);    // after COME
  set(*m, "X0.0", 1);
  m->tick();
  EXPECT_EQ(get(*m, "R0.0"), 1);
  EXPECT_EQ(get(*m, "R0.1"), 0);
  EXPECT_EQ(get(*m, "R0.2"), 1);
  set(*m, "X0.1", 0);
  m->tick();
  EXPECT_EQ(get(*m, "R0.0"), 0);
  EXPECT_EQ(get(*m, "R0.1"), 1);
  EXPECT_EQ(get(*m, "R0.2"), 1); // SET holds
  set(*m, "X0.0", 0);
  m->tick();
  EXPECT_EQ(get(*m, "R0.1"), 0);
  EXPECT_EQ(get(*m, "R0.2"), 1);
}

// 4.2 JMP [EXT]: with ACT = 1 everything up to JMPE is skipped and those coils keep their state;
// NOP does nothing.
TEST_P(FanucData, JmpSkipsToJmpe) {
  auto m = pmc("RD X0.0\nJMP\nRD X0.1\nWRT R0.0\nRD X0.1\nMOVB X1 R10\nJMPE\nNOP\nRD X0.1\n"
               "WRT R0.1\nEND1\nEND2\nEND\n");
  ASSERT_TRUE(m);
  set(*m, "X0.1", 1);
  set(*m, "X1", 7);
  m->tick();
  EXPECT_EQ(get(*m, "R0.0"), 1);
  EXPECT_EQ(byte(*m, "R10"), 7);
  set(*m, "X0.0", 1);
  set(*m, "X0.1", 0);
  set(*m, "X1", 9);
  m->tick();
  EXPECT_EQ(get(*m, "R0.0"), 1); // kept
  EXPECT_EQ(byte(*m, "R10"), 7);
  EXPECT_EQ(get(*m, "R0.1"), 0); // after JMPE
}

// Located errors (docs/fanuc-pmc.md "Rules"): the CNC-service instructions say why they are not
// supported; region and input rules point at the instruction.
TEST(FanucDataRules, LocatedErrors) {
  struct Case {
    const char *text;
    const char *want;
    int line, col;
  };
  const Case cases[] = {
      {"RD X0.0\nDISPB 1\nEND1\nEND2\nEND\n", "DISPB is not supported by this build", 2, 1},
      {"RD X0.0\n  SUB 53\nEND1\nEND2\nEND\n", "SUB 53 (AXCTL) is not supported", 2, 3},
      {"RD X0.0\nWINDR 1\nEND1\nEND2\nEND\n", "window function codes", 2, 1},
      {"RD X0.0\nPSGN2\nEND1\nEND2\nEND\n", "position signal", 2, 1},
      {"RD X0.0\nPARI X10\nEND1\nEND2\nEND\n", "PARI needs its inputs O.E, RST, ACT", 2, 1},
      {"RD X0.0\nCOM\nEND1\nEND2\nEND\n", "COM on line 2 has no COME before END1", 3, 1},
      {"COME\nEND1\nEND2\nEND\n", "COME without COM", 1, 1},
      {"RD X0.0\nJMP\nRD X0.0\nJMP\nJMPE\nEND1\nEND2\nEND\n", "JMP inside JMP..JMPE", 4, 1},
      {"RD X0.0\nRD.STK X0.0\nRD.STK X0.1\nCOD 2 R100 R200 10\nEND1\nEND2\nEND\n",
       "takes 2 table entries", 4, 5},
      {"RD X0.0\nRD.STK X0.0\nRD.STK X0.1\nCOD 1 R100 R200 10000\nEND1\nEND2\nEND\n",
       "BCD table entry '10000' out of range", 4, 17},
      {"RD X0.0\nDEC F10 0312\nEND1\nEND2\nEND\n", "decode specification '0312'", 2, 9},
      {"RD X0.0\nDECB 0003 F10 3 R10\nEND1\nEND2\nEND\n", "data length 1, 2 or 4", 2, 6},
      {"RD X0.0\nRD.STK X0.0\nRD.STK X0.1\nXMOVB 0991 R0 D0 R7999 R1\nEND1\nEND2\nEND\n",
       "runs past the end", 4, 18},
      {"RD X0.0\nRD.STK X0.0\nDSCHB 3 R0 D0 R2 R4\nEND1\nEND2\nEND\n", "expected 1, 2 or 4", 3, 7},
  };
  for (const Case &c : cases) {
    Diagnostics d("t.pmc");
    EXPECT_FALSE(pipeline::compilePmc(c.text, "t.pmc", VerifyOptions{}, d, nullptr)) << c.text;
    const std::string out = d.render();
    EXPECT_NE(out.find(c.want), std::string::npos) << out;
    const std::string loc = "t.pmc:" + std::to_string(c.line) + ":" + std::to_string(c.col) + ":";
    EXPECT_NE(out.find(loc), std::string::npos) << out << " want " << loc;
  }
}

} // namespace
} // namespace lj::test

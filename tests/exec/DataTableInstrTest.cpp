// Data operations, tables and conversions: ENCO DECO COD SER ASSEM DISAS ACVT PTN NTP on every
// engine, with the test values of hnc8-functions-2.md 2.7-2.13, 2.17-2.18, and a lock-step run
// of all fourteen data instructions on changing inputs (whole state compared every tick).
#include "tests/exec/ExecTest.h"

#include <string>

namespace lj::test {
namespace {

class DataTableExec : public ExecTest {};
LJ_EXEC_SUITE(DataTableExec);

void setTable(Machine &m, const std::string &area, int start, std::initializer_list<int> v) {
  int k = start;
  for (int x : v) m.set(area + std::to_string(k++), x);
}

// functions-2 2.7, table D10..D14 = 3,5,7,8,9: D1=3 -> 1; 5 -> 2; 7 -> 4; 9 -> 16; 4 -> 0
// (not found); EN = 0 leaves D2 alone.
TEST_P(DataTableExec, EncoTests) {
  auto m = load("LD X1.0\nENCO D10 5 D1 D2\n");
  ASSERT_TRUE(m);
  setTable(*m, "D", 10, {3, 5, 7, 8, 9});
  m->set("X1.0", 1);
  for (auto [in, out] : {std::pair{3, 1}, {5, 2}, {7, 4}, {9, 16}, {4, 0}}) {
    m->set("D1", in);
    m->tick();
    EXPECT_EQ(m->get("D2"), out) << "D1=" << in;
  }
  m->set("X1.0", 0);
  m->set("D1", 9);
  m->tick();
  EXPECT_EQ(m->get("D2"), 0);
}

// functions-2 2.7 / resolution 10: the first equal entry wins; bit 31 of a full 32-entry table.
TEST_P(DataTableExec, EncoFirstMatchAndBit31) {
  auto m = load("LDT\nENCO W0 32 D1 D2\n");
  ASSERT_TRUE(m);
  for (int k = 0; k < 32; ++k) m->set("W" + std::to_string(k), k == 31 ? -5 : k);
  m->set("W20", 3); // duplicate of W3
  m->set("D1", 3);
  m->tick();
  EXPECT_EQ(m->get("D2"), 8);
  m->set("D1", -5);
  m->tick();
  EXPECT_EQ(m->get("D2"), INT32_MIN);
}

// functions-2 2.8, table D10..D14 = 3,5,7,8,9: D1=1 -> 3; 2 -> 5; 4 -> 7; 16 -> 9; several bits:
// the lowest wins (resolution 10); no bit among 0..n-1 -> 0 (resolution 9).
TEST_P(DataTableExec, DecoTests) {
  auto m = load("LD X1.0\nDECO D10 5 D1 D2\n");
  ASSERT_TRUE(m);
  setTable(*m, "D", 10, {3, 5, 7, 8, 9});
  m->set("X1.0", 1);
  for (auto [in, out] : {std::pair{1, 3}, {2, 5}, {4, 7}, {16, 9}, {6, 5}, {32, 0}, {0, 0}}) {
    m->set("D1", in);
    m->tick();
    EXPECT_EQ(m->get("D2"), out) << "D1=" << in;
  }
}

// functions-2 2.9, table D10..D17 = 50..120: D1=0 -> 50; 2 -> 70; 7 -> 120; 8 -> unchanged, and
// as an index fault (DIALECT.md 4): fault_index + 1, ST0 := 0; a negative index too.
TEST_P(DataTableExec, CodTests) {
  auto m = load("LD X1.0\nCOD D10 8 D1 D2\nOUT R4.0\n");
  ASSERT_TRUE(m);
  setTable(*m, "D", 10, {50, 60, 70, 80, 90, 100, 110, 120});
  m->set("X1.0", 1);
  for (auto [in, out] : {std::pair{0, 50}, {2, 70}, {7, 120}}) {
    m->set("D1", in);
    m->tick();
    EXPECT_EQ(m->get("D2"), out) << "D1=" << in;
    EXPECT_EQ(m->get("R4.0"), 1);
  }
  for (int bad : {8, -1}) {
    m->set("D1", bad);
    m->tick();
    EXPECT_EQ(m->get("D2"), 120) << "D1=" << bad;
    EXPECT_EQ(m->get("R4.0"), 0);
  }
  EXPECT_EQ(m->state().fault_index, 2u);
}

// functions-2 2.10, D0..D3 = 10,20,30,40: D4=30 -> D5=2, output 1; 10 -> 0; 35 -> D5
// unchanged, output 0; EN = 0 -> output 0.
TEST_P(DataTableExec, SerTests) {
  auto m = load("LD X1.0\nSER D0 4 D4 D5\nOUT R4.0\n");
  ASSERT_TRUE(m);
  setTable(*m, "D", 0, {10, 20, 30, 40});
  m->set("X1.0", 1);
  m->set("D4", 30);
  m->tick();
  EXPECT_EQ(m->get("D5"), 2);
  EXPECT_EQ(m->get("R4.0"), 1);
  m->set("D4", 10);
  m->tick();
  EXPECT_EQ(m->get("D5"), 0);
  EXPECT_EQ(m->get("R4.0"), 1);
  m->set("D4", 35);
  m->set("D5", 77);
  m->tick();
  EXPECT_EQ(m->get("D5"), 77);
  EXPECT_EQ(m->get("R4.0"), 0);
  m->set("D4", 40);
  m->set("X1.0", 0);
  m->tick();
  EXPECT_EQ(m->get("D5"), 77);
  EXPECT_EQ(m->get("R4.0"), 0);
}

// functions-2 2.10 on a long table (a loop in compiled code): the first match wins.
TEST_P(DataTableExec, SerLongTable) {
  auto m = load("LDT\nSER G0 100 W0 D5\nOUT R4.0\n");
  ASSERT_TRUE(m);
  for (int k = 0; k < 100; ++k) m->set("G" + std::to_string(k), 500 + k);
  m->set("G90", 573); // duplicate of G73
  m->set("W0", 573);
  m->tick();
  EXPECT_EQ(m->get("D5"), 73);
  EXPECT_EQ(m->get("R4.0"), 1);
  m->set("W0", 599);
  m->tick();
  EXPECT_EQ(m->get("D5"), 99);
  m->set("W0", 600);
  m->tick();
  EXPECT_EQ(m->get("D5"), 99);
  EXPECT_EQ(m->get("R4.0"), 0);
}

// functions-2 2.11: X0..X3 = 0x11,0x22,0x33,0x44 -> D4 = 0x44332211; X3=0xFF, X0..X2=0 ->
// D4 = 0xFF000000; ASSEM W0 2 D0 with W0=0x1234, W1=0xABCD -> D0 = 0xABCD1234 (raw bits).
TEST_P(DataTableExec, AssemTests) {
  auto m = load("LD X9.0\nASSEM X0 4 D4\nLDT\nASSEM W0 2 D0\nLDT\nASSEM R0 6 W5\n");
  ASSERT_TRUE(m);
  setTable(*m, "X", 0, {0x11, 0x22, 0x33, 0x44});
  m->set("X9.0", 1);
  m->set("W0", 0x1234);
  m->set("W1", 0xABCD);
  setTable(*m, "R", 0, {0x01, 0x02, 0x03});
  m->tick();
  EXPECT_EQ(m->get("D4"), 0x44332211);
  EXPECT_EQ(m->get("D0"), static_cast<int32_t>(0xABCD1234u));
  EXPECT_EQ(m->get("W5"), 0x0201); // truncated to the 16-bit destination
  setTable(*m, "X", 0, {0, 0, 0, 0xFF});
  m->tick();
  EXPECT_EQ(m->get("D4"), static_cast<int32_t>(0xFF000000u)); // -16777216
  m->set("X9.0", 0);                                          // EN = 0: nothing
  m->set("X0", 0x55);
  m->tick();
  EXPECT_EQ(m->get("D4"), static_cast<int32_t>(0xFF000000u));
}

// functions-2 2.12: D0=0x44332211 -> Y0..Y3 = 0x11..0x44; D0=-1 -> 0xFF each; DISAS D0 2 W0
// with D0=0xABCD1234 -> W0=0x1234, W1=0xABCD; pieces beyond bit 31 are 0; a W source gives
// its raw 16 bits (not sign-extended).
TEST_P(DataTableExec, DisasTests) {
  auto m = load("LDT\nDISAS D0 6 Y0\nLDT\nDISAS D0 2 W0\nLDT\nDISAS W9 3 R0\n");
  ASSERT_TRUE(m);
  m->set("D0", 0x44332211);
  m->set("Y4", 9);
  m->set("W9", -1);
  m->tick();
  EXPECT_EQ(m->get("Y0"), 0x11);
  EXPECT_EQ(m->get("Y1"), 0x22);
  EXPECT_EQ(m->get("Y2"), 0x33);
  EXPECT_EQ(m->get("Y3"), 0x44);
  EXPECT_EQ(m->get("Y4"), 0);
  EXPECT_EQ(m->get("Y5"), 0);
  EXPECT_EQ(m->get("W0"), 0x2211);
  EXPECT_EQ(m->get("W1"), 0x4433);
  EXPECT_EQ(m->get("R0"), 0xFF);
  EXPECT_EQ(m->get("R1"), 0xFF);
  EXPECT_EQ(m->get("R2"), 0);
  m->set("D0", -1);
  m->tick();
  for (int k = 0; k < 4; ++k) EXPECT_EQ(m->get("Y" + std::to_string(k)), 0xFF) << k;
  m->set("D0", static_cast<int32_t>(0xABCD1234u));
  m->tick();
  EXPECT_EQ(m->get("W0"), 0x1234);
  EXPECT_EQ(m->get("W1"), static_cast<int16_t>(0xABCD));
}

// functions-2 2.13 with P0=0, P1=1000, P2=0, P3=100: D0=500 -> 50; 1000 -> 100; 1500 -> 150;
// -10 -> -1 (truncation toward zero); P0=0, P1=4095, P2=0, P3=10000, D0=4095 -> 10000.
TEST_P(DataTableExec, AcvtTests) {
  auto m = load("LD X1.0\nACVT P0 D0 D1\nLDT\nACVT P4 D0 D2\n");
  ASSERT_TRUE(m);
  setTable(*m, "P", 0, {0, 1000, 0, 100, 0, 4095, 0, 10000});
  m->set("X1.0", 1);
  for (auto [in, out] : {std::pair{500, 50}, {1000, 100}, {1500, 150}, {-10, -1}}) {
    m->set("D0", in);
    m->tick();
    EXPECT_EQ(m->get("D1"), out) << "D0=" << in;
  }
  m->set("D0", 4095);
  m->tick();
  EXPECT_EQ(m->get("D2"), 10000);
}

// functions-2 resolution 6: the formula ends in +P[k+2] (target min), here P8..P11 = 0, 10,
// 100, 200: D0=5 -> 150. A zero source range (P13 = P12) writes nothing, counts fault_divzero
// and gives ST0 := 0 (DIALECT.md 4, dialect-notes "Data operations").
TEST_P(DataTableExec, AcvtTargetMinAndZeroRange) {
  auto m = load("LDT\nACVT P8 D0 D1\nLDT\nACVT P12 D0 D2\nOUT R4.0\n");
  ASSERT_TRUE(m);
  setTable(*m, "P", 8, {0, 10, 100, 200, 7, 7, 0, 1});
  m->set("D0", 5);
  m->set("D2", 33);
  m->tick();
  EXPECT_EQ(m->get("D1"), 150);
  EXPECT_EQ(m->get("D2"), 33);
  EXPECT_EQ(m->get("R4.0"), 0);
  EXPECT_EQ(m->state().fault_divzero, 1u);
}

// dialect-notes "Data operations": the int64 product wraps modulo 2^64 and the sum to int32.
// P = INT32_MIN, INT32_MAX, INT32_MIN, INT32_MAX and x = INT32_MAX: (2^32-1)^2 wraps to
// -2^33+1; / (2^32-1) = -2 (toward zero); -2 + INT32_MIN wraps to 2147483646. A narrow
// destination keeps the low bits: x = 0 gives (2^31)(2^32-1)/(2^32-1) + INT32_MIN = 0.
TEST_P(DataTableExec, AcvtWideRangesWrap) {
  auto m = load("LDT\nACVT P20 D0 D1\nLDT\nACVT P20 D3 W1\n");
  ASSERT_TRUE(m);
  setTable(*m, "P", 20, {INT32_MIN, INT32_MAX, INT32_MIN, INT32_MAX});
  m->set("D0", INT32_MAX);
  m->set("D3", 0);
  m->set("W1", 5);
  m->tick();
  EXPECT_EQ(m->get("D1"), 2147483646);
  EXPECT_EQ(m->get("W1"), 0);
}

// functions-2 2.17: Y30 = 0b0100 -> R0=2; only Y30.0 -> 0; Y30 = 0 -> R0 unchanged; several
// active points: the first pair wins (resolution 10).
TEST_P(DataTableExec, PtnTests) {
  auto m = load("LDT\nPTN R0 Y30.0 0 Y30.1 1 Y30.2 2 Y30.3 3\n");
  ASSERT_TRUE(m);
  for (auto [y, out] : {std::pair{0b0100, 2}, {0b0001, 0}, {0, 0}, {0b1010, 1}}) {
    m->set("R0", 77);
    m->set("Y30", y);
    m->tick();
    EXPECT_EQ(m->get("R0"), y == 0 ? 77 : out) << "Y30=" << y;
  }
}

// functions-2 2.18: R0=1 -> Y30.1=1, Y30.0=Y30.2=Y30.3=0, bits 4-7 untouched; R0=5 -> Y30.0..3
// all 0; EN = 0 leaves the points.
TEST_P(DataTableExec, NtpTests) {
  auto m = load("LD X1.0\nNTP R0 0 Y30.0 1 Y30.1 2 Y30.2 3 Y30.3\n");
  ASSERT_TRUE(m);
  m->set("X1.0", 1);
  m->set("Y30", 0xF5);
  m->set("R0", 1);
  m->tick();
  EXPECT_EQ(m->get("Y30"), 0xF2);
  m->set("R0", 5);
  m->tick();
  EXPECT_EQ(m->get("Y30"), 0xF0);
  m->set("X1.0", 0);
  m->set("Y30", 0x0F);
  m->set("R0", 2);
  m->tick();
  EXPECT_EQ(m->get("Y30"), 0x0F);
}

// dialect-notes "Data operations": PTN points may be timer/counter output bits; NTP writes its
// points in pair order, so a bit named twice gets the last pair's result.
TEST_P(DataTableExec, PointDetails) {
  auto m = load("LDT\nPTN D0 C5.0 7 R1.0 8 R1.1 9 R1.2 10\nLDT\nNTP W0 1 Y1.0 2 Y1.0 1 Y1.1 2 "
                "Y1.2\n");
  ASSERT_TRUE(m);
  m->set("C5.0", 1);
  m->set("R1.1", 1);
  m->set("W0", 1);
  m->tick();
  EXPECT_EQ(m->get("D0"), 7);
  EXPECT_EQ(m->get("Y1.0"), 0); // pair 1 sets it, pair 2 clears it
  EXPECT_EQ(m->get("Y1.1"), 1);
  EXPECT_EQ(m->get("Y1.2"), 0);
  m->set("C5.0", 0);
  m->set("W0", 2);
  m->tick();
  EXPECT_EQ(m->get("D0"), 9);
  EXPECT_EQ(m->get("Y1.0"), 1);
  EXPECT_EQ(m->get("Y1.1"), 0);
  EXPECT_EQ(m->get("Y1.2"), 1);
}

// All fourteen data instructions, including faults and long ranges, in lock-step on every engine
// with inputs that change every tick (the whole lj_state is compared after every tick).
constexpr const char *kAllData = R"(
LD X0.0
XMOV 1 D1 2 W2
OUT Y0.0
LD X0.1
XCH 0 R3 1 D4
OUT Y0.1
LD X0.2
BMOV W10 W12 40
LDI X0.2
BMOV D20 D21 5
LD X0.3
FMOV G0 G50 D6
LD X0.4
ZRST R100.3 R140.5
LD X0.5
ZRST D30 D31
LDT
ENCO W10 16 W5 D40
LD X0.6
DECO W10 20 D7 D41
LD X0.7
COD W10 60 R5 D42
OUT Y0.2
LDT
SER W10 70 W6 D43
OUT Y0.3
LD X1.0
ASSEM R3 4 D44
LD X1.1
DISAS D1 5 R10
LD X1.2
ACVT P0 D2 D45
OUT Y0.4
LD X1.3
PTN W7 X0.0 10 X0.1 11 X0.2 12 X0.3 13
LDT
NTP R6 1 Y1.0 2 Y1.1 3 Y1.2 1 Y1.3
)";

TEST(DataCrossEngine, AllDataInstructionsLockStep) {
  Scenario sc;
  sc.ticks = 120;
  sc.hostInputs = [](uint32_t tick, lj_state &s) {
    uint32_t r = tick * 2654435761u + 12345u; // deterministic, changes every tick
    s.img.X[0] = static_cast<uint8_t>(r >> 8);
    s.img.X[1] = static_cast<uint8_t>(r >> 16);
    s.img.D[1] = static_cast<int32_t>((r >> 4) % 60) - 5; // B index, sometimes out of range
    s.img.D[4] = static_cast<int32_t>((r >> 7) % 56) - 3;
    s.img.R[3] = static_cast<uint8_t>(r >> 3);
    s.img.R[5] = static_cast<uint8_t>((r >> 11) % 64);
    s.img.R[6] = static_cast<uint8_t>((r >> 13) % 4);
    s.img.W[5] = static_cast<int16_t>((r >> 5) % 24);
    s.img.W[6] = static_cast<int16_t>((r >> 9) % 90);
    s.img.D[2] = static_cast<int32_t>(r);
    s.img.D[6] = static_cast<int32_t>(r ^ 0x5A5A5A5Au);
    s.img.D[7] = static_cast<int32_t>(r >> (tick % 32));
    s.img.P[1] = static_cast<int32_t>(tick % 3); // P1 = P0 = 0 some ticks: zero range
    s.img.P[3] = static_cast<int32_t>(r >> 1);
  };
  sc.hostBefore = [](lj_state &s) {
    for (int k = 0; k < 80; ++k) s.img.W[10 + k] = static_cast<int16_t>(k * 37 % 23);
    for (int k = 0; k < 50; ++k) s.img.B[k] = k * 1000 - 7;
  };
  EXPECT_TRUE(sameStateOnAllEngines(kAllData, sc));
}

} // namespace
} // namespace lj::test

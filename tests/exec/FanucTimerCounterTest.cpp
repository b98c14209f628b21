// FANUC PMC timers, counters and compares (family PmcTc) on every engine: the test vectors of
// ../shared/reference/fanuc-pmc.md section 7 (1 TMR, 3 TMRC, 4 CTR, 9 COMPB) and the rules of
// 6.3, 6.4, 6.6; expected values are the reference's (cited per test), never what the code
// printed. [EXT]/[INF] readings are docs/fanuc-pmc.md rows.
#include "tests/exec/FanucExec.h"

namespace lj::test {
namespace {

class FanucTc : public FanucExecTest {
protected:
  /// One rising edge of `bit`: a tick with it 1, then a tick with it 0.
  static void pulse(Machine &m, std::string_view bit) {
    set(m, bit, 1);
    m.tick();
    set(m, bit, 0);
    m.tick();
  }
};
LJ_EXEC_SUITE(FanucTc);

// 7.1 TMR [L1659-L1669]: timer 1, T9000 = 3 (100 ms precision), set time 100 ms (one unit in
// T0..T1): R0.0 = 1 100 ms after X0.0 rises; X0.0 = 0 clears R0.0 at once.
TEST_P(FanucTc, TmrVector1HundredMsPrecision) {
  auto m = pmc("RD X0.0\nSUB 3\n(PRM) 1\nWRT R0.0\nEND1\nEND2\nEND\n");
  ASSERT_TRUE(m);
  set(*m, "T9000:2", 3);
  set(*m, "T0:2", 1);
  set(*m, "X0.0", 1);
  for (int t = 0; t <= 150; ++t) { // now_ms = t
    m->tick();
    ASSERT_EQ(get(*m, "R0.0"), t >= 100 ? 1 : 0) << "now_ms " << t;
  }
  set(*m, "X0.0", 0);
  m->tick();
  EXPECT_EQ(get(*m, "R0.0"), 0);
}

// 7.1 / 6.3 [L1555-L1559, L1663]: with T9000 = 0 timer 1 counts 48 ms units; timers 9 and up
// count 8 ms units.
TEST_P(FanucTc, TmrDefaultUnits48And8Ms) {
  auto m = pmc("RD X0.0\nTMR 1\nWRT R0.0\nRD X0.0\nTMR 9\nWRT R0.1\nEND1\nEND2\nEND\n");
  ASSERT_TRUE(m);
  set(*m, "T0:2", 2);  // timer 1: 2 x 48 ms = 96 ms
  set(*m, "T16:2", 5); // timer 9 (T16..T17): 5 x 8 ms = 40 ms
  set(*m, "X0.0", 1);
  for (int t = 0; t <= 120; ++t) {
    m->tick();
    ASSERT_EQ(get(*m, "R0.0"), t >= 96 ? 1 : 0) << "now_ms " << t;
    ASSERT_EQ(get(*m, "R0.1"), t >= 40 ? 1 : 0) << "now_ms " << t;
  }
}

// 6.3 [L1631-L1653]: precision 4 = 1 s; ACT = 0 resets the timer (it starts again from 0).
TEST_P(FanucTc, TmrOneSecondPrecisionRestartsAfterActDrops) {
  auto m = pmc("RD X0.0\nTMR 250\nWRT R0.0\nEND1\nEND2\nEND\n");
  ASSERT_TRUE(m);
  m->setPeriodMs(100);
  set(*m, "T9498:2", 4); // timer 250: T9000 + 2 * 249
  set(*m, "T498:2", 2);  // 2 s
  set(*m, "X0.0", 1);
  for (int t = 0; t < 10; ++t) m->tick(); // 0 .. 900 ms
  EXPECT_EQ(get(*m, "R0.0"), 0);
  set(*m, "X0.0", 0);
  m->tick(); // 1000 ms
  set(*m, "X0.0", 1);
  for (int t = 11; t <= 31; ++t) { // timing again from 1100 ms
    m->tick();
    ASSERT_EQ(get(*m, "R0.0"), 100 * t >= 1100 + 2000 ? 1 : 0) << "now_ms " << 100 * t;
  }
}

// 7.3 TMRC [L1873-L1881]: precision 0 = 8 ms, D100 = 100 -> 800 ms; work area R100..R103.
// R0.0 = 1 800 ms after X0.0 rises; X0.0 = 0 clears it at once.
TEST_P(FanucTc, TmrcVector3EightHundredMs) {
  auto m = pmc("RD X0.0\nSUB 54\n(PRM) 0\n(PRM) D100\n(PRM) R100\nWRT R0.0\nEND1\nEND2\nEND\n");
  ASSERT_TRUE(m);
  m->setPeriodMs(8);
  set(*m, "D100:2", 100);
  set(*m, "X0.0", 1);
  for (int t = 0; t <= 120; ++t) { // now_ms = 8 t
    m->tick();
    ASSERT_EQ(get(*m, "R0.0"), 8 * t >= 800 ? 1 : 0) << "now_ms " << 8 * t;
  }
  set(*m, "X0.0", 0);
  m->tick();
  EXPECT_EQ(get(*m, "R0.0"), 0);
}

// 6.3 [L1797-L1833]: TMRC precision 7 = 100 ms, 5 = 1 ms.
TEST_P(FanucTc, TmrcPrecisionCodes) {
  auto m = pmc("RD X0.0\nTMRC 7 D0 R100\nWRT R0.0\nRD X0.0\nTMRC 5 D2 R104\nWRT R0.1\n"
               "END1\nEND2\nEND\n");
  ASSERT_TRUE(m);
  set(*m, "D0:2", 3);  // 300 ms
  set(*m, "D2:2", 50); // 50 ms
  set(*m, "X0.0", 1);
  for (int t = 0; t <= 320; ++t) {
    m->tick();
    ASSERT_EQ(get(*m, "R0.0"), t >= 300 ? 1 : 0) << t;
    ASSERT_EQ(get(*m, "R0.1"), t >= 50 ? 1 : 0) << t;
  }
}

// CTR with CN0 = 1 (R9091.1, always 1), UPDOWN = 0 (R9091.0, always 0), RST = F1.1,
// ACT = X0.0 (reference 5: loaded top to bottom, ACT last), counter 1, W1 -> R0.0.
constexpr const char *kCtr1 = "RD R9091.1\nRD.STK R9091.0\nRD.STK F1.1\nRD.STK X0.0\nSUB 5\n"
                              "(PRM) 1\nWRT R0.0\nEND1\nEND2\nEND\n";

// 7.4 CTR [L2057-L2065]: counter 1 = C0..C3, preset C0..C1 = 20, current C2..C3. F1.1 = 1
// resets the current value to 1; each rising edge of X0.0 adds 1; at 20 R0.0 = 1.
TEST_P(FanucTc, CtrVector4CountsOneToTwenty) {
  auto m = pmc(kCtr1);
  ASSERT_TRUE(m);
  set(*m, "C0:2", 20);
  set(*m, "F1.1", 1);
  m->tick();
  EXPECT_EQ(get(*m, "C2:2"), 1);
  EXPECT_EQ(get(*m, "R0.0"), 0);
  set(*m, "F1.1", 0);
  for (int k = 1; k <= 19; ++k) {
    pulse(*m, "X0.0");
    ASSERT_EQ(get(*m, "C2:2"), 1 + k) << "edge " << k;
    ASSERT_EQ(get(*m, "R0.0"), k == 19 ? 1 : 0) << "edge " << k;
  }
  set(*m, "F1.1", 1);
  m->tick();
  EXPECT_EQ(get(*m, "C2:2"), 1);
  EXPECT_EQ(get(*m, "R0.0"), 0);
}

/// The counter data type system parameter (ref 6.4 [L1971-L1973], "chosen globally"), as
/// --params `COUNTER = BCD` writes it at power-up.
void counterType(Machine &m, uint8_t type) {
  reinterpret_cast<unsigned char *>(&m.state())[fanuc::profile().systemParams.counterFormat] = type;
}

// 7.4 again with the counter data type BCD: the preset 20 is the BCD digits 0x0020 and the
// count runs 1..20 in BCD (0x0001 .. 0x0009, 0x0010, .. 0x0020); W1 at 20. In binary 0x0020
// would be the preset 32.
TEST_P(FanucTc, CtrVector4InBcd) {
  auto m = pmc(kCtr1);
  ASSERT_TRUE(m);
  counterType(*m, TargetProfile::kCounterBcd);
  set(*m, "C0:2", 0x0020);
  set(*m, "F1.1", 1);
  m->tick();
  EXPECT_EQ(get(*m, "C2:2"), 0x0001);
  set(*m, "F1.1", 0);
  for (int k = 1; k <= 19; ++k) {
    pulse(*m, "X0.0");
    const int v = 1 + k; // the count in decimal, held as BCD digits
    ASSERT_EQ(get(*m, "C2:2"), (v / 10) << 4 | v % 10) << "edge " << k;
    ASSERT_EQ(get(*m, "R0.0"), k == 19 ? 1 : 0) << "edge " << k;
  }
  pulse(*m, "X0.0"); // ring: the edge after the preset gives the CN0 value again
  EXPECT_EQ(get(*m, "C2:2"), 0x0001);
  EXPECT_EQ(get(*m, "R0.0"), 0);
}

// BCD range 0..9999 (ref 6.4 [L2031]): an up count from 9998 with the preset 9999 reaches
// 0x9999 (read as a signed 2-byte value: -26215) and W1; a down counter (UPDOWN = X0.1) reset
// to the preset 1234 counts 1233 as 0x1233. CTRB stays binary whatever the parameter says
// (ref 6.4 [L2073]).
TEST_P(FanucTc, CtrBcdFourDigitsAndCtrbStaysBinary) {
  auto m = pmc("RD R9091.0\nRD.STK R9091.0\nRD.STK F1.1\nRD.STK X0.0\nCTR 1\nWRT R0.0\n"
               "RD R9091.0\nRD.STK X0.1\nRD.STK F1.1\nRD.STK X0.0\nCTR 2\nWRT R0.1\n"
               "RD R9091.0\nRD.STK R9091.0\nRD.STK F1.1\nRD.STK X0.0\nCTRB 1 12\nWRT R0.2\n"
               "END1\nEND2\nEND\n");
  ASSERT_TRUE(m);
  counterType(*m, TargetProfile::kCounterBcd);
  set(*m, "C0:2", 0x9999);
  set(*m, "C2:2", 0x9998);
  set(*m, "C4:2", 0x1234);
  set(*m, "X0.1", 1);
  set(*m, "F1.1", 1);
  m->tick(); // counter 2 (down) resets to its preset; counter 1 (up) to CN0 = 0
  EXPECT_EQ(get(*m, "C6:2"), 0x1234);
  EXPECT_EQ(get(*m, "C2:2"), 0);
  set(*m, "F1.1", 0);
  set(*m, "C2:2", 0x9998);
  pulse(*m, "X0.0");
  EXPECT_EQ(get(*m, "C2:2"), static_cast<int16_t>(0x9999));
  EXPECT_EQ(get(*m, "R0.0"), 1);
  EXPECT_EQ(get(*m, "C6:2"), 0x1233);
  EXPECT_EQ(get(*m, "C5000:2"), 1); // CTRB 1: binary count 1 of 12
  for (int k = 0; k < 9; ++k) pulse(*m, "X0.0");
  EXPECT_EQ(get(*m, "C5000:2"), 10); // binary 10, not BCD 0x10
  EXPECT_EQ(get(*m, "C6:2"), 0x1224);
}

// 6.4 [L1975-L1977, L2013]: it counts rising edges only (ACT held at 1 counts once) and, as a
// ring counter, the edge after the preset starts again at the CN0 value.
TEST_P(FanucTc, CtrCountsEdgesAndRings) {
  auto m = pmc(kCtr1);
  ASSERT_TRUE(m);
  set(*m, "C0:2", 3);
  set(*m, "F1.1", 1);
  m->tick();
  set(*m, "F1.1", 0);
  set(*m, "X0.0", 1);
  for (int t = 0; t < 5; ++t) m->tick();
  EXPECT_EQ(get(*m, "C2:2"), 2);
  set(*m, "X0.0", 0);
  m->tick();
  pulse(*m, "X0.0");
  EXPECT_EQ(get(*m, "C2:2"), 3);
  EXPECT_EQ(get(*m, "R0.0"), 1);
  pulse(*m, "X0.0");
  EXPECT_EQ(get(*m, "C2:2"), 1);
  EXPECT_EQ(get(*m, "R0.0"), 0);
}

// 6.4 CTRB [L2071-L2141]: constant preset, count in C5000.. (counter 2 -> C5002..C5003). Down
// counter (UPDOWN = X0.1 = 1), CN0 = 0: RST sets the preset; W1 at the minimum 0; then rings.
TEST_P(FanucTc, CtrbCountsDownFromThePreset) {
  auto m = pmc("RD R9091.0\nRD.STK X0.1\nRD.STK X0.2\nRD.STK X0.0\nCTRB 2 3\nWRT R0.0\n"
               "END1\nEND2\nEND\n");
  ASSERT_TRUE(m);
  set(*m, "X0.1", 1);
  set(*m, "X0.2", 1);
  m->tick();
  EXPECT_EQ(get(*m, "C5002:2"), 3);
  set(*m, "X0.2", 0);
  const int expect[] = {2, 1, 0, 3};
  for (int k = 0; k < 4; ++k) {
    pulse(*m, "X0.0");
    ASSERT_EQ(get(*m, "C5002:2"), expect[k]) << "edge " << k + 1;
    ASSERT_EQ(get(*m, "R0.0"), expect[k] == 0 ? 1 : 0) << "edge " << k + 1;
  }
}

// 6.4 CTRC [L2147-L2209]: preset at D10..D11, counter register R200..R203 (the count in
// R200..R201, docs/fanuc-pmc.md [INF]); up from CN0 = 0.
TEST_P(FanucTc, CtrcPresetAndRegisterAtAnyAddress) {
  auto m = pmc("RD R9091.0\nRD.STK R9091.0\nRD.STK X0.2\nRD.STK X0.0\nSUB 55\n(PRM) D10\n"
               "(PRM) R200\nWRT R0.0\nEND1\nEND2\nEND\n");
  ASSERT_TRUE(m);
  set(*m, "D10:2", 2);
  const int expect[] = {1, 2, 0, 1};
  for (int k = 0; k < 4; ++k) {
    pulse(*m, "X0.0");
    ASSERT_EQ(get(*m, "R200:2"), expect[k]) << "edge " << k + 1;
    ASSERT_EQ(get(*m, "R0.0"), expect[k] == 2 ? 1 : 0) << "edge " << k + 1;
  }
  set(*m, "X0.2", 1); // RST of an up counter: back to the CN0 value
  m->tick();
  EXPECT_EQ(get(*m, "R200:2"), 0);
}

// 7.9 COMPB [L2701, L2707]: D100 = 20, R100 = 25, X0.0 = 1 -> R9000.1 (N) = 1, R9000.0 (Z) = 0;
// 6.6 [EXT, standard]: equal -> Z = 1, N = 0; greater -> both 0; ACT = 0 leaves R9000 alone.
TEST_P(FanucTc, CompbVector9SetsR9000Flags) {
  auto m = pmc("RD X0.0\nSUB 32\n(PRM) 1001\n(PRM) D100\n(PRM) R100\nEND1\nEND2\nEND\n");
  ASSERT_TRUE(m);
  set(*m, "D100", 20);
  set(*m, "R100", 25);
  set(*m, "X0.0", 1);
  m->tick();
  EXPECT_EQ(get(*m, "R9000.1"), 1);
  EXPECT_EQ(get(*m, "R9000.0"), 0);
  set(*m, "R100", 20);
  m->tick();
  EXPECT_EQ(get(*m, "R9000.1"), 0);
  EXPECT_EQ(get(*m, "R9000.0"), 1);
  set(*m, "R100", 19);
  m->tick();
  EXPECT_EQ(get(*m, "R9000.1"), 0);
  EXPECT_EQ(get(*m, "R9000.0"), 0);
  set(*m, "X0.0", 0);
  set(*m, "R100", 20);
  m->tick();
  EXPECT_EQ(get(*m, "R9000.0"), 0);
}

// 6.6 COMPB with a constant input over 2 bytes (format 0002).
TEST_P(FanucTc, CompbConstantTwoBytes) {
  auto m = pmc("RD X0.0\nCOMPB 0002 300 D0\nEND1\nEND2\nEND\n");
  ASSERT_TRUE(m);
  set(*m, "X0.0", 1);
  set(*m, "D0:2", 301);
  m->tick();
  EXPECT_EQ(get(*m, "R9000") & 3, 2); // N: 300 < 301
  set(*m, "D0:2", 300);
  m->tick();
  EXPECT_EQ(get(*m, "R9000") & 3, 1); // Z
}

// 6.6 COMP [L2709-L2761]: BCD; W1 = 1 if input <= comparison. COIN [L2767-L2819]: W1 = 1 if
// input = comparison. BYT (ST1) 0 = 2 digits (1 byte), 1 = 4 digits (2 bytes, 3.2 layout).
TEST_P(FanucTc, CompAndCoinReadBcd) {
  auto m = pmc("RD X0.1\nRD.STK X0.0\nCOMP 0 25 R10\nWRT R0.0\n"
               "RD X0.1\nRD.STK X0.0\nCOIN 1 R20 R10\nWRT R0.1\nEND1\nEND2\nEND\n");
  ASSERT_TRUE(m);
  set(*m, "X0.0", 1);
  set(*m, "R10", 0x25); // BCD 25
  m->tick();
  EXPECT_EQ(get(*m, "R0.0"), 1); // 25 <= 25
  set(*m, "R10", 0x24);
  m->tick();
  EXPECT_EQ(get(*m, "R0.0"), 0); // 25 > 24
  set(*m, "R10", 0x30);
  m->tick();
  EXPECT_EQ(get(*m, "R0.0"), 1); // 25 <= 30 (BCD 0x30 is 30, binary 48)
  set(*m, "X0.1", 1);            // 4 digits: 1234 -> R10 = 0x34, R11 = 0x12 (3.2 [L411-L427])
  set(*m, "R10:2", 0x1234);
  set(*m, "R20:2", 0x1234);
  m->tick();
  EXPECT_EQ(get(*m, "R0.1"), 1);
  EXPECT_EQ(get(*m, "R0.0"), 1); // COMP reads BYT = X0.1 too: 25 <= BCD 1234
  set(*m, "X0.0", 0);            // ACT = 0: W1 = 0 (6.2 [EXT])
  m->tick();
  EXPECT_EQ(get(*m, "R0.1"), 0);
}

// 6.6 NEB/NEW/NED [L2897-L2923]: W1 = data1 != data2, signed 1/2/4 bytes; RNGx [L2929-L2983]:
// W1 = 1 when the input lies between the bounds in either order.
TEST_P(FanucTc, NeAndRangeCompares) {
  auto m = pmc("RD X0.0\nNEB R0 -1\nWRT R50.0\nRD X0.0\nNEW D0 D2\nWRT R50.1\n"
               "RD X0.0\nRNGW 100 -100 D4\nWRT R50.2\nRD X0.0\nRNGD D10 D14 D18\nWRT R50.3\n"
               "END1\nEND2\nEND\n");
  ASSERT_TRUE(m);
  set(*m, "X0.0", 1);
  set(*m, "R0", 0xFF); // -1 as a signed byte (3.1)
  set(*m, "D0:2", 7);
  set(*m, "D2:2", 7);
  set(*m, "D4:2", -100);
  set(*m, "D10:4", 5);
  set(*m, "D14:4", 1);
  set(*m, "D18:4", 6);
  m->tick();
  EXPECT_EQ(get(*m, "R50.0"), 0);
  EXPECT_EQ(get(*m, "R50.1"), 0);
  EXPECT_EQ(get(*m, "R50.2"), 1); // -100 <= -100 <= 100
  EXPECT_EQ(get(*m, "R50.3"), 0); // 6 not in 1..5
  set(*m, "R0", 3);
  set(*m, "D2:2", 8);
  set(*m, "D4:2", 101);
  set(*m, "D18:4", 1);
  m->tick();
  EXPECT_EQ(get(*m, "R50.0"), 1);
  EXPECT_EQ(get(*m, "R50.1"), 1);
  EXPECT_EQ(get(*m, "R50.2"), 0);
  EXPECT_EQ(get(*m, "R50.3"), 1);
  set(*m, "X0.0", 0); // ACT = 0: W1 = 0
  m->tick();
  EXPECT_EQ(get(*m, "R50.0"), 0);
  EXPECT_EQ(get(*m, "R50.3"), 0);
}

} // namespace
} // namespace lj::test

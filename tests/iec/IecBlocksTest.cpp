// The Neza function blocks (modicon-neza.md 3) and system bits (6, 11) on every registered
// engine: examples E21 / E22 of section 10 verbatim (the %C8 counter in the BLK form with and
// without OUT_BLK), the timers TON / TOF / TP with their preset and time base (3.3), the
// counter's inputs and outputs (3.2) in the instruction form, and the runtime's system bits.
// Rules the seed leaves to its missing pages follow docs/iec-il.md "Function blocks".
#include "tests/iec/IecTest.h"

namespace lj::test {
namespace {

class IecBlocks : public IecExec {
protected:
  /// One tick with `addr` := v first.
  void tickWith(Machine &m, std::string_view addr, int64_t v) {
    set(m, addr, v);
    EXPECT_EQ(m.tick(), uint32_t{LJ_FAULT_NONE});
  }
  /// A rising then a falling edge of `addr` (two ticks).
  void pulse(Machine &m, std::string_view addr) {
    tickWith(m, addr, 1);
    tickWith(m, addr, 0);
  }
  /// E21 / E22: %C8 with R on the falling edge of I1.1, CU = I1.2 . M0, Q0.4 = %C8.D . M1.
  void checkC8(Machine &m) {
    EXPECT_EQ(get(m, "%C8.P"), 9999) << "the default preset (L1098)";
    set(m, "%C8.P", 3); // ADJ Y: the preset from the data editor (L1098, L1285)
    set(m, "%M0", 1);
    set(m, "%M1", 1);
    for (int n = 1; n <= 3; ++n) {
      pulse(m, "%I1.2");
      EXPECT_EQ(get(m, "%C8.V"), n);
      EXPECT_EQ(get(m, "%C8.D"), n == 3);
      EXPECT_EQ(get(m, "%Q0.4"), n == 3) << "Q0.4 = %C8.D . M1 after " << n << " counts";
    }
    tickWith(m, "%M1", 0);
    EXPECT_EQ(get(m, "%Q0.4"), 0) << "M1 = 0";
    set(m, "%M1", 1);
    tickWith(m, "%M0", 0);
    pulse(m, "%I1.2");
    EXPECT_EQ(get(m, "%C8.V"), 3) << "CU = I1.2 . M0: no count with M0 = 0";
    EXPECT_EQ(get(m, "%Q0.4"), 1);
    set(m, "%M0", 1);
    pulse(m, "%I1.2");
    EXPECT_EQ(get(m, "%C8.V"), 4);
    EXPECT_EQ(get(m, "%Q0.4"), 0) << "D only at V = P";
    tickWith(m, "%I1.1", 1);
    EXPECT_EQ(get(m, "%C8.V"), 4) << "R on the falling edge of I1.1, not the rising one";
    tickWith(m, "%I1.1", 0);
    EXPECT_EQ(get(m, "%C8.V"), 0) << "reset on the falling edge of I1.1";
    tickWith(m, "%I1.1", 0);
    pulse(m, "%I1.2");
    EXPECT_EQ(get(m, "%C8.V"), 1) << "the reset lasted one scan";
  }
};
LJ_IEC_SUITE(IecBlocks);

// E21 (L1219-1229): the counter block with an output section.
TEST_P(IecBlocks, E21CounterBlockWithOutBlk) {
  auto m = load("BLK %C8\nLDF %I1.1\nR\nLD %I1.2\nAND %M0\nCU\nOUT_BLK\nLD D\nAND %M1\n"
                "ST %Q0.4\nEND_BLK\n");
  ASSERT_TRUE(m);
  checkC8(*m);
}

// E22 (L1230-1239): the same block without OUT_BLK, its output read after END_BLK.
TEST_P(IecBlocks, E22CounterBlockWithoutOutBlk) {
  auto m = load("BLK %C8\nLDF %I1.1\nR\nLD %I1.2\nAND %M0\nCU\nEND_BLK\nLD %C8.D\nAND %M1\n"
                "ST %Q0.4\n");
  ASSERT_TRUE(m);
  checkC8(*m);
}

// TON (L1249-1265, L1276-1289): starts on the rising edge of IN, V counts time-base units up
// to P, Q = 1 once V reaches P and while IN stays 1; IN = 0 stops it and clears V.
TEST_P(IecBlocks, OnDelayTimer) {
  auto m = load("CONFIG %TM0 TON TB=10MS P=5\nBLK %TM0\nLD %I0.0\nIN\nOUT_BLK\nLD Q\n"
                "ST %Q0.0\nEND_BLK\n");
  ASSERT_TRUE(m);
  m->setPeriodMs(10);
  EXPECT_EQ(get(*m, "%TM0.P"), 5);
  tickWith(*m, "%I0.0", 0); // now 0
  for (int k = 0; k <= 6; ++k) {
    tickWith(*m, "%I0.0", 1); // now 10 + 10 k: elapsed 10 k ms
    EXPECT_EQ(get(*m, "%TM0.V"), std::min(k, 5)) << "scan " << k;
    EXPECT_EQ(get(*m, "%TM0.Q"), k >= 5) << "delay = P x TB = 50 ms, scan " << k;
    EXPECT_EQ(get(*m, "%Q0.0"), k >= 5);
  }
  tickWith(*m, "%I0.0", 0);
  EXPECT_EQ(get(*m, "%TM0.Q"), 0);
  EXPECT_EQ(get(*m, "%TM0.V"), 0);
  for (int k = 0; k < 3; ++k) tickWith(*m, "%I0.0", 1);
  tickWith(*m, "%I0.0", 0);
  EXPECT_EQ(get(*m, "%TM0.V"), 0) << "IN = 0 before the preset: stopped, V = 0, no output";
  EXPECT_EQ(get(*m, "%TM0.Q"), 0);
}

// TOF (instruction form IN %TMi): Q = 1 with IN, timing starts on the falling edge of IN, Q
// drops when V reaches P; IN = 1 during the timing stops it (V = 0, Q stays 1).
TEST_P(IecBlocks, OffDelayTimer) {
  auto m = load("CONFIG %TM1 TOF TB=10MS P=3\nLD %I0.1\nIN %TM1\nST %Q0.2\nLD %TM1.Q\n"
                "ST %Q0.1\n");
  ASSERT_TRUE(m);
  m->setPeriodMs(10);
  tickWith(*m, "%I0.1", 0);
  EXPECT_EQ(get(*m, "%Q0.1"), 0);
  tickWith(*m, "%I0.1", 1);
  EXPECT_EQ(get(*m, "%Q0.1"), 1);
  EXPECT_EQ(get(*m, "%Q0.2"), 1) << "IN %TMi leaves the accumulator";
  for (int k = 0; k <= 3; ++k) {
    tickWith(*m, "%I0.1", 0);
    EXPECT_EQ(get(*m, "%TM1.V"), k) << "scan " << k;
    EXPECT_EQ(get(*m, "%Q0.1"), k < 3) << "off after P x TB = 30 ms, scan " << k;
  }
  tickWith(*m, "%I0.1", 1);
  tickWith(*m, "%I0.1", 0);
  tickWith(*m, "%I0.1", 0);
  EXPECT_EQ(get(*m, "%TM1.V"), 1);
  tickWith(*m, "%I0.1", 1);
  EXPECT_EQ(get(*m, "%TM1.V"), 0) << "a rising edge stops the timing";
  EXPECT_EQ(get(*m, "%Q0.1"), 1);
}

// TP: a pulse of exactly P x TB from the rising edge of IN, whatever IN does meanwhile; not
// restarted by IN during the pulse; V stays at P while IN is 1, 0 once IN and Q are 0.
TEST_P(IecBlocks, PulseTimer) {
  auto m = load("CONFIG %TM2 TP TB=10MS P=3\nBLK %TM2\nLD %I0.2\nIN\nEND_BLK\nLD %TM2.Q\n"
                "ST %Q0.3\n");
  ASSERT_TRUE(m);
  m->setPeriodMs(10);
  tickWith(*m, "%I0.2", 0);
  const int in[] = {1, 0, 1, 1, 1, 1, 0, 1, 1, 1, 1};
  const int q[] = {1, 1, 1, 0, 0, 0, 0, 1, 1, 1, 0};
  const int v[] = {0, 1, 2, 3, 3, 3, 0, 0, 1, 2, 3};
  for (int k = 0; k < 11; ++k) {
    tickWith(*m, "%I0.2", in[k]);
    EXPECT_EQ(get(*m, "%Q0.3"), q[k]) << "scan " << k;
    EXPECT_EQ(get(*m, "%TM2.V"), v[k]) << "scan " << k;
  }
}

// The preset is a word the program writes (L1276-1278); the time base is the block's.
TEST_P(IecBlocks, ProgramWritesThePreset) {
  auto m = load("CONFIG %TM3 TB=100MS\nLD 1\n[%TM3.P := %MW0]\nLD %I0.0\nIN %TM3\n"
                "LD 1\n[%MW1 := %TM3.V]\nLD [%TM3.V >= 2]\nST %Q0.0\n");
  ASSERT_TRUE(m);
  m->setPeriodMs(50);
  set(*m, "%MW0", 4);
  tickWith(*m, "%I0.0", 1); // now 0: timing starts
  EXPECT_EQ(get(*m, "%TM3.P"), 4);
  for (int k = 1; k <= 8; ++k) {
    tickWith(*m, "%I0.0", 1); // elapsed 50 k ms, TB 100 ms
    EXPECT_EQ(get(*m, "%MW1"), std::min(k / 2, 4)) << "scan " << k;
    EXPECT_EQ(get(*m, "%Q0.0"), k / 2 >= 2) << "scan " << k;
    EXPECT_EQ(get(*m, "%TM3.Q"), k >= 8) << "P x TB = 400 ms, scan " << k;
  }
}

// %Ci in the instruction form: CU / CD count rising edges, 9999 -> 0 sets F (overflow),
// 0 -> 9999 sets E (underflow), S loads P and sets D, R clears all and wins over S and CU.
TEST_P(IecBlocks, CounterInputsAndOutputs) {
  auto m = load("CONFIG %C0 P=2\nLD %I0.0\nCU %C0\nLD %I0.1\nCD %C0\nLD %I0.2\nS %C0\n"
                "LD %I0.3\nR %C0\n");
  ASSERT_TRUE(m);
  m->tick();
  pulse(*m, "%I0.1");
  EXPECT_EQ(get(*m, "%C0.V"), 9999);
  EXPECT_EQ(get(*m, "%C0.E"), 1) << "underflow";
  pulse(*m, "%I0.1");
  EXPECT_EQ(get(*m, "%C0.V"), 9998);
  EXPECT_EQ(get(*m, "%C0.E"), 0) << "cleared when counting down goes on";
  pulse(*m, "%I0.0");
  pulse(*m, "%I0.0");
  EXPECT_EQ(get(*m, "%C0.V"), 0);
  EXPECT_EQ(get(*m, "%C0.F"), 1) << "overflow 9999 -> 0";
  pulse(*m, "%I0.0");
  EXPECT_EQ(get(*m, "%C0.F"), 0);
  pulse(*m, "%I0.0");
  EXPECT_EQ(get(*m, "%C0.V"), 2);
  EXPECT_EQ(get(*m, "%C0.D"), 1) << "V = P";
  set(*m, "%I0.0", 1);
  tickWith(*m, "%I0.1", 1);
  EXPECT_EQ(get(*m, "%C0.V"), 2) << "CU and CD in one scan: CU +1, CD -1";
  set(*m, "%I0.0", 0);
  tickWith(*m, "%I0.1", 0);
  tickWith(*m, "%I0.3", 1);
  EXPECT_EQ(get(*m, "%C0.V"), 0);
  EXPECT_EQ(get(*m, "%C0.D"), 0);
  set(*m, "%I0.2", 1);
  tickWith(*m, "%I0.0", 1);
  EXPECT_EQ(get(*m, "%C0.V"), 0) << "R wins over S and CU";
  tickWith(*m, "%I0.3", 0);
  EXPECT_EQ(get(*m, "%C0.V"), 2) << "S loads P";
  EXPECT_EQ(get(*m, "%C0.D"), 1);
}

// In the BLK form the inputs act together: R wins over CU in the same scan, and CU and CD
// rising together leave V unchanged.
TEST_P(IecBlocks, CounterBlockInputsTogether) {
  auto m = load("BLK %C1\nLD %I0.3\nR\nLD %I0.0\nCU\nLD %I0.1\nCD\nEND_BLK\n");
  ASSERT_TRUE(m);
  m->tick();
  pulse(*m, "%I0.0");
  EXPECT_EQ(get(*m, "%C1.V"), 1);
  set(*m, "%I0.0", 1);
  tickWith(*m, "%I0.1", 1);
  EXPECT_EQ(get(*m, "%C1.V"), 1) << "CU and CD together";
  set(*m, "%I0.0", 0);
  tickWith(*m, "%I0.1", 0);
  set(*m, "%I0.3", 1);
  tickWith(*m, "%I0.0", 1);
  EXPECT_EQ(get(*m, "%C1.V"), 0) << "R has priority";
}

// System bits written by the runtime before every scan (profiles/iec): %S0 / %S1 / %S13 on
// the first scan only, %S5 the 100 ms square wave (50 ms at 1, 50 ms at 0).
TEST_P(IecBlocks, SystemBits) {
  auto m = load("LD %S0\nST %Q0.0\nLD %S1\nST %Q0.1\nLD %S13\nST %Q0.2\nLD %S5\nST %Q0.3\n"
                "LD %S6\nST %Q0.4\n");
  ASSERT_TRUE(m);
  m->setPeriodMs(10);
  for (int k = 0; k < 12; ++k) {
    EXPECT_EQ(m->tick(), uint32_t{LJ_FAULT_NONE});
    EXPECT_EQ(get(*m, "%Q0.0"), k == 0) << "scan " << k;
    EXPECT_EQ(get(*m, "%Q0.1"), k == 0) << "scan " << k;
    EXPECT_EQ(get(*m, "%Q0.2"), k == 0) << "scan " << k;
    EXPECT_EQ(get(*m, "%Q0.3"), (k / 5) % 2 == 0) << "scan " << k;
    EXPECT_EQ(get(*m, "%Q0.4"), 1) << "1 s clock: 1 for the first 500 ms";
  }
}

} // namespace
} // namespace lj::test

// Family Cnc blocks with more than a bit or a word (hnc8-cnc-interface.md section 2): mode set /
// get, MDI, user outputs, jog and step flags, spindle commands, runtime axis operands, a
// whole-state run of every block on all engines, and the CNC table's resolution of operands.
#include "profiles/hnc8/CncTable.h"
#include "tests/exec/ExecTest.h"

#include <cstdint>

namespace lj::test {
namespace {

class CncSpecialExec : public ExecTest {};
LJ_EXEC_SUITE(CncSpecialExec);

// MDST 1 (`MDST 0 R0`): one-hot 1,2,4,...,64 -> GC[60].0-6 and the code 1,7,2,3,5,4,6 in
// GC[0].0-3 (section 2 MDST, 1.4 G2620); 0, several bits or > 64: no request (docs/cnc-blocks.md).
TEST_P(CncSpecialExec, MdstWritesOneHotAndCode) {
  auto m = load("LD X0.0\nMDST 0 R0\n");
  ASSERT_TRUE(m);
  m->set("G2620", 0x0300); // increment multiplier bits 8-9 are kept
  m->set("X0.0", 1);
  const int codes[7] = {1, 7, 2, 3, 5, 4, 6};
  for (int k = 0; k < 7; ++k) {
    m->set("R0", 1 << k);
    m->tick();
    EXPECT_EQ(m->get("G2620"), 0x0300 | (1 << k)) << k;
    EXPECT_EQ(m->get("G2560"), codes[k]) << k;
  }
  for (int bad : {0, 3, 128, 255}) {
    m->set("R0", bad);
    m->tick();
    EXPECT_EQ(m->get("G2620"), 0x0300 | 64) << bad; // unchanged since PMC
    EXPECT_EQ(m->get("G2560"), 6) << bad;
  }
  m->set("X0.0", 0);
  m->set("R0", 4);
  m->tick();
  EXPECT_EQ(m->get("G2560"), 6); // value writer: nothing while ACT = 0
}

// MDGT 2 (`MDGT 0 R1`): FC[0].0-3 code -> one-hot; reset (0) and MDI (8) have no weight -> 0.
TEST_P(CncSpecialExec, MdgtReadsModeCode) {
  auto m = load("LDT\nMDGT 0 R1\nLDT\nMDGT 2 W3\n");
  ASSERT_TRUE(m);
  const int pairs[][2] = {{1, 1},  {7, 2},  {2, 4}, {3, 8}, {5, 16},
                          {4, 32}, {6, 64}, {0, 0}, {8, 0}};
  for (auto [code, hot] : pairs) {
    m->set("F2560", 0x1230 | code); // other bits of the status word do not matter
    m->set("F2720", code);
    m->tick();
    EXPECT_EQ(m->get("R1"), hot) << code;
    EXPECT_EQ(m->get("W3"), hot) << code;
  }
}

// MDI 3 (`MDI 0`, X36.4): requests code 8 and drops a one-hot request (docs/cnc-blocks.md).
TEST_P(CncSpecialExec, MdiRequestsCodeEight) {
  auto m = load("LD X36.4\nMDI 0\n");
  ASSERT_TRUE(m);
  m->set("G2560", 0x0021);
  m->set("G2620", 0x0381);
  m->set("X36.4", 1);
  m->tick();
  EXPECT_EQ(m->get("G2560"), 0x0028);
  EXPECT_EQ(m->get("G2620"), 0x0380);
}

// USEROUT 20 (`USEROUT 0 1 Y1`, X36.4): #1191 = 12 -> Y1.2 and Y1.3 on, every other bit of
// Y1..Y4 off; bit k -> byte k/8 bit k%8 of FC[44..45].
TEST_P(CncSpecialExec, UserOutExample) {
  auto m = load("LD X36.4\nUSEROUT 0 1 Y1\n");
  ASSERT_TRUE(m);
  m->set("Y2", 0xFF);
  m->set("F2604", 12);
  m->set("X36.4", 1);
  m->tick();
  EXPECT_EQ(m->get("Y1"), 12);
  EXPECT_EQ(m->get("Y2"), 0);
  m->set("F2604", static_cast<int16_t>(0x8001));
  m->set("F2605", 0x0102);
  m->tick();
  EXPECT_EQ(m->get("Y1"), 0x01);
  EXPECT_EQ(m->get("Y2"), 0x80);
  EXPECT_EQ(m->get("Y3"), 0x02);
  EXPECT_EQ(m->get("Y4"), 0x01);
  m->set("X36.4", 0);
  m->set("F2604", 0);
  m->tick();
  EXPECT_EQ(m->get("Y1"), 0x01); // not written while ACT = 0
}

// SPDLJOG 28 (`SPDLJOG 0 X32.4`, ACT X31.4): GA[1].6 forward = ACT and dir, GA[1].7 reverse =
// ACT and not dir.
TEST_P(CncSpecialExec, SpindleJog) {
  auto m = load("LD X31.4\nSPDLJOG 0 X32.4\n");
  ASSERT_TRUE(m);
  forAllInputs(*m, {"X31.4", "X32.4"}, [&](const Inputs &in) {
    EXPECT_EQ(m->get("G1.6"), in("X31.4") && in("X32.4"));
    EXPECT_EQ(m->get("G1.7"), in("X31.4") && !in("X32.4"));
  });
}

// JOGSW 38 (`JOGSW 0 X32.3`: 1 = +) and STEPAXIS 39 (`STEPAXIS 0 X32.3`: 0 = +): GA[4] / GA[5]
// := ACT ? +1 / -1 : 0 (docs/cnc-blocks.md "JOGSW encoding").
TEST_P(CncSpecialExec, JogAndStepFlags) {
  auto m = load("LD X0.0\nJOGSW 0 X32.3\nLD X0.0\nSTEPAXIS 1 X32.3\n");
  ASSERT_TRUE(m);
  forAllInputs(*m, {"X0.0", "X32.3"}, [&](const Inputs &in) {
    int plusJog = in("X32.3") ? 1 : -1;
    EXPECT_EQ(m->get("G4"), in("X0.0") ? plusJog : 0);
    EXPECT_EQ(m->get("G85"), in("X0.0") ? -plusJog : 0);
  });
}

// AXISMODE 55 (`AXISMODE 1 1`): GA[2].9/.10/.11 one-hot for mode 0/1/2 while ACT; ACT off
// clears the block's own bit.
TEST_P(CncSpecialExec, AxisModeOneHot) {
  auto m = load("LD X0.0\nAXISMODE 1 1\n");
  ASSERT_TRUE(m);
  m->set("G82", 0x0201); // .9 position mode and .0 (not ours)
  m->set("X0.0", 1);
  m->tick();
  EXPECT_EQ(m->get("G82"), 0x0401);
  m->set("X0.0", 0);
  m->tick();
  EXPECT_EQ(m->get("G82"), 0x0001);
}

// SPDLBUS 29 (`SPDLBUS 0 1`): GC[10+2sp] (32 bit) := S (FC[10+2sp], 0.001 rpm) * GC[6+sp] / 100
// while ACT; S ack GC[2].sp := ACT and FC[2].(12+sp) (section 1.6 "S codes").
TEST_P(CncSpecialExec, SpindleBusCommand) {
  auto m = load("LD X31.4\nSPDLBUS 0 1\n");
  ASSERT_TRUE(m);
  const int32_t s = 1500000; // 1500 rpm
  m->set("F2572", static_cast<int16_t>(s & 0xFFFF));
  m->set("F2573", s >> 16);
  m->set("G2567", 50);
  m->set("F2562.13", 1);
  m->set("X31.4", 1);
  m->tick();
  const int32_t cmd = 750000;
  EXPECT_EQ(m->get("G2572"), static_cast<int16_t>(cmd & 0xFFFF));
  EXPECT_EQ(m->get("G2573"), cmd >> 16);
  EXPECT_EQ(m->get("G2562.1"), 1);
  m->set("X31.4", 0);
  m->tick();
  EXPECT_EQ(m->get("G2562.1"), 0);
  EXPECT_EQ(m->get("G2573"), cmd >> 16);
}

// SPDLBUS1 30 (implied `SPDLBUS1 0 1 R1 P2`): gear g uses P[2+5(g-1) ..]: +0 motor maximum (rpm),
// +3/+4 ratio; out-of-range gear: nothing written, fault_index + 1 (docs/cnc-blocks.md).
TEST_P(CncSpecialExec, SpindleBusGeared) {
  auto m = load("LD X31.4\nSPDLBUS1 0 1 R1 P2\nOUT Y0.0\n");
  ASSERT_TRUE(m);
  auto setS = [&](int32_t v) {
    m->set("F2572", static_cast<int16_t>(v & 0xFFFF));
    m->set("F2573", v >> 16);
  };
  auto cmd = [&] {
    return static_cast<int32_t>((static_cast<uint32_t>(m->get("G2573")) << 16) |
                                static_cast<uint16_t>(m->get("G2572")));
  };
  m->set("P7", 3000); // gear 2: max 3000 rpm, ratio 2/1
  m->set("P10", 2);
  m->set("P11", 1);
  m->set("G2567", 100);
  m->set("R1", 2);
  m->set("X31.4", 1);
  setS(1000000);
  m->tick();
  EXPECT_EQ(cmd(), 2000000);
  EXPECT_EQ(m->get("Y0.0"), 1);
  setS(2000000); // 4000 rpm capped at 3000
  m->tick();
  EXPECT_EQ(cmd(), 3000000);
  m->set("R1", 0);
  setS(1000);
  m->tick();
  EXPECT_EQ(cmd(), 3000000);
  EXPECT_EQ(m->state().fault_index, 1u);
  EXPECT_EQ(m->get("Y0.0"), 0);
}

// Runtime axis operands (brief: JOGSW STEPAXIS JOGVEL AXEN AXISMOVE AXISMVTO AXLMF2): outside
// 0..31 nothing is written, fault_index + 1 when the block would write, output 0 (DIALECT.md 4).
TEST_P(CncSpecialExec, RuntimeAxisIndex) {
  auto m = load("LD X0.0\nAXEN R5\nOUT Y0.0\nLD X0.0\nJOGVEL R5 D0\nOUT Y0.1\n");
  ASSERT_TRUE(m);
  m->set("D0", 7);
  m->set("R5", 3);
  m->set("X0.0", 1);
  m->tick();
  EXPECT_EQ(m->get("G240.7"), 1);
  EXPECT_EQ(m->get("G246"), 7);
  EXPECT_EQ(m->get("Y0.0"), 1);
  EXPECT_EQ(m->state().fault_index, 0u);
  m->set("R5", 32);
  m->set("D0", 9);
  m->tick();
  EXPECT_EQ(m->state().fault_index, 2u);
  EXPECT_EQ(m->get("Y0.0"), 0);
  EXPECT_EQ(m->get("Y0.1"), 0);
  EXPECT_EQ(m->get("G240.7"), 1);
  EXPECT_EQ(m->get("G0"), 0);
  EXPECT_EQ(m->get("G6"), 0);
  // ACT = 0: AXEN still writes its level bit (one fault), JOGVEL writes nothing (no fault).
  m->set("X0.0", 0);
  m->tick();
  EXPECT_EQ(m->state().fault_index, 3u);
  m->set("R5", 3);
  m->tick();
  EXPECT_EQ(m->get("G240.7"), 0);
  EXPECT_EQ(m->get("G246"), 7);
}

// Whole-state lock-step run of every block of the family with random F words and inputs.
TEST(CncCrossEngine, EveryBlockSameStateEverywhere) {
  constexpr const char *kAll = R"(
LD X0.0
MDST 0 R0
LDT
MDGT 1 R1
LD X0.1
MDI 2
LD X0.2
MST 0
CYCLE 1
STOP 2
RESET 3
CHANSW 1
HOLD 0
LDT
CYCLED 0
OUT Y0.0
HOLDLED 1
OUT Y0.1
LD X0.3
ESCBLK 0 3
RPOVRD 1 R2
FEEDOVRD 2 W1
SPDLOVRD 3 2 D1
STEPMUL 4 R2
DRYRUN 0
SKIP 1
USERIN 2 0 19
USEROUT 1 0 R10
SELSTOP 3
LD X0.4
SPDLJOG 2 X0.5
SPDLBUS 0 2
SPDLBUS1 1 0 R3 P10
SPDLORI 3
SPDLOROK 3
OUT Y0.2
SPDLZERO 4
SPDLRCH 5
OUT Y0.3
LD X0.5
DESYN 6
JOGSW R4 X0.6
STEPAXIS R5 X0.7
JOGVEL R4 D2
HOMRUN 7
HOMERUN1 8 X0.6
HOMESW 9
HOMLED 9
OUT Y0.4
LD X0.6
AXEN R5
AXRDY 10
OUT Y0.5
AXISLOCK 11
AXISMOVE R4 D3
AXISMVTO R5 D2
AXLMF2 R4
AXISPLMT 12
AXISNLMT 13
SVSW 14
AXISMODE 15 2
REFPT 16 3
OUT Y0.6
AXISHOM2 17
AXMOVING 18
OUT Y0.7
LD X1.0
ALARM 77
ALARM 700
RSTCHK 3
OUT Y1.0
RSTCLR 3
)";
  Scenario sc;
  sc.ticks = 200;
  sc.preset("P10", 3000).preset("P13", 3).preset("P14", 2).preset("P15", 100);
  sc.hostInputs = [](uint32_t tick, lj_state &s) {
    uint32_t x = tick * 2654435761u + 12345u;
    auto next = [&x] {
      x ^= x << 13;
      x ^= x >> 17;
      x ^= x << 5;
      return x;
    };
    s.img.X[0] = static_cast<uint8_t>(next());
    s.img.X[1] = static_cast<uint8_t>(next());
    for (int w = 0; w < 1500; w += 1 + static_cast<int>(next() % 7))
      s.img.F[w] = static_cast<int16_t>(next());
    for (int w = 2560; w < 2880; ++w) s.img.F[w] = static_cast<int16_t>(next());
    s.img.R[0] = static_cast<uint8_t>(1u << (next() % 9));
    s.img.R[3] = static_cast<uint8_t>(next() % 4);                      // gear 0..3
    s.img.R[4] = static_cast<uint8_t>(next() % 40);                     // axis, sometimes bad
    s.img.R[5] = static_cast<uint8_t>(next() % 2 ? next() % 32 : 200u); // axis or bad
    s.img.D[2] = static_cast<int32_t>(next());
    s.img.D[3] = static_cast<int32_t>(next());
    s.img.W[1] = static_cast<int16_t>(next());
  };
  EXPECT_TRUE(sameStateOnAllEngines(kAll, sc));
}

// The table's operand resolution (shared by both engines, so tested on its own): word and bit
// of ALARM (section 2 #60), USERIN (#19), REFPT (#56), SPDLOVRD (#15), SPDLBUS (#29).
TEST(CncTable, ResolvesOperands) {
  auto prog = compileOrFail("ALARM 17\nALARM 884\nLDT\nUSERIN 0 0 17\nREFPT 1 3\nREFPT 1 5\n"
                            "SPDLOVRD 0 2 R0\nSPDLBUS 0 3\n");
  ASSERT_TRUE(prog);
  auto res = [&](size_t stmt, int action) {
    const Stmt &s = prog->stmts[stmt];
    return cnc::resolve(cnc::cncRow(s.op)->act[action], s);
  };
  EXPECT_EQ(res(0, 0).word, 3011); // alarm 17 -> G3011.0
  EXPECT_EQ(res(0, 0).bit, 0);
  EXPECT_FALSE(res(0, 1).applies);
  EXPECT_FALSE(res(1, 0).applies);
  EXPECT_EQ(res(1, 1).word, 3079); // prompt 884 -> G3079.15
  EXPECT_EQ(res(1, 1).bit, 15);
  EXPECT_EQ(res(3, 0).word, 25); // USERIN bit 17 -> GC[25].1
  EXPECT_EQ(res(3, 0).bit, 1);
  EXPECT_EQ(res(4, 0).bit, 10); // REFPT 3 -> FA[0].10
  EXPECT_FALSE(res(5, 0).applies);
  EXPECT_EQ(res(6, 0).word, 8);  // SPDLOVRD spindle 2 -> GC[8]
  EXPECT_EQ(res(7, 0).word, 16); // SPDLBUS spindle 3: command GC[16], S FC[16], override GC[9]
  EXPECT_EQ(res(7, 0).auxWord, 16);
  EXPECT_EQ(res(7, 0).aux2Word, 9);
  EXPECT_EQ(res(7, 1).word, 2); // ack GC[2].3 := FC[2].15
  EXPECT_EQ(res(7, 1).bit, 3);
  EXPECT_EQ(res(7, 1).auxBit, 15);
  EXPECT_EQ(cnc::cncTable().size(), 52u);
}

} // namespace
} // namespace lj::test

// FANUC 0i-D PMC programs on every engine: the worked examples and test vectors of
// ../shared/reference/fanuc-pmc.md section 7 (and 3.1, 3.4) that this build's instruction set
// covers; expected values are the reference's (cited per test), never what the code printed.
#include "tests/exec/FanucExec.h"

namespace lj::test {
namespace {

class FanucExec : public FanucExecTest {};
LJ_EXEC_SUITE(FanucExec);

// Reference 3.4 [L471-L511]: the Gray-code ladder (b3 = g3, b2 = b3 xor g2, ...), each rung
// reading the b bit the previous rung wrote in the same scan; the table [L513-L821] maps every
// value 0..15 to its Gray code. g3..g0 = X0.3..X0.0, b3..b0 = R0.3..R0.0.
TEST_P(FanucExec, GrayCodeLadderDecodesAllSixteenCodes) {
  auto m = pmc("END1\n"
               "RD X0.3\nWRT R0.3\n"
               "RD R0.3\nAND.NOT X0.2\nRD.NOT.STK R0.3\nAND X0.2\nOR.STK\nWRT R0.2\n"
               "RD R0.2\nAND.NOT X0.1\nRD.NOT.STK R0.2\nAND X0.1\nOR.STK\nWRT R0.1\n"
               "RD R0.1\nAND.NOT X0.0\nRD.NOT.STK R0.1\nAND X0.0\nOR.STK\nWRT R0.0\n"
               "END2\nEND\n");
  ASSERT_TRUE(m);
  // [L513-L821]: value -> Gray code.
  const int gray[16] = {0b0000, 0b0001, 0b0011, 0b0010, 0b0110, 0b0111, 0b0101, 0b0100,
                        0b1100, 0b1101, 0b1111, 0b1110, 0b1010, 0b1011, 0b1001, 0b1000};
  for (int v = 0; v < 16; ++v) {
    set(*m, "X0", gray[v]);
    m->tick();
    EXPECT_EQ(get(*m, "R0") & 0xF, v) << "gray " << gray[v];
  }
}

// 7.2 TMRB [L1757-L1759]: R0.0 = 1 after X0.0 has been 1 for 3 s; X0.0 = 0 clears it at once.
TEST_P(FanucExec, TmrbThreeSeconds) {
  auto m = pmc("RD X0.0\nSUB 24\n(PRM) 1\n(PRM) 3000\nWRT R0.0\nEND1\nEND2\nEND\n");
  ASSERT_TRUE(m);
  m->setPeriodMs(8); // level 1 every 8 ms (reference 4.1)
  set(*m, "X0.0", 1);
  for (int t = 0; t <= 400; ++t) { // now_ms = 8 t
    m->tick();
    ASSERT_EQ(get(*m, "R0.0"), 8 * t >= 3000 ? 1 : 0) << "now_ms " << 8 * t;
  }
  set(*m, "X0.0", 0);
  m->tick();
  EXPECT_EQ(get(*m, "R0.0"), 0);
}

// 6.3 TMRBF [L1959-L1963]: ACT = 1 -> W1 = 1 at once; after ACT falls, W1 = 0 once the set time
// has passed.
TEST_P(FanucExec, TmrbfOffDelay) {
  auto m = pmc("RD X0.0\nTMRBF 2 100\nWRT R0.0\nEND1\nEND2\nEND\n");
  ASSERT_TRUE(m);
  set(*m, "X0.0", 1);
  m->tick(); // t = 0
  EXPECT_EQ(get(*m, "R0.0"), 1);
  set(*m, "X0.0", 0);
  for (int t = 1; t <= 150; ++t) {
    m->tick();
    ASSERT_EQ(get(*m, "R0.0"), t - 1 < 100 ? 1 : 0) << "t=" << t;
  }
}

// 7.5 MOVB [L2245], MOVW [L2281], MOVN [L2345]: with X0.0 = 1, D100 -> R200 (1 byte),
// D100..D101 -> R200..R201, D100..D104 -> R100..R104; with X0.0 = 0 nothing moves (6.2 [INF]).
TEST_P(FanucExec, MovbMovwMovn) {
  auto m = pmc("RD X0.0\nMOVB D100 R200\nRD X0.0\nMOVW D100 R300\nRD X0.0\nSUB 45\n(PRM) 5\n"
               "(PRM) D100\n(PRM) R100\nEND1\nEND2\nEND\n");
  ASSERT_TRUE(m);
  for (int k = 0; k < 5; ++k) set(*m, "D" + std::to_string(100 + k), 0x11 * (k + 1));
  m->tick();
  EXPECT_EQ(get(*m, "R200"), 0);
  EXPECT_EQ(get(*m, "R100:4"), 0);
  set(*m, "X0.0", 1);
  m->tick();
  EXPECT_EQ(get(*m, "R200"), 0x11);
  EXPECT_EQ(get(*m, "R201"), 0);        // MOVB moves one byte
  EXPECT_EQ(get(*m, "R300:2"), 0x2211); // little-endian (3.1 [L235])
  for (int k = 0; k < 5; ++k) EXPECT_EQ(get(*m, "R" + std::to_string(100 + k)), 0x11 * (k + 1));
  EXPECT_EQ(get(*m, "R105"), 0);
}

// 7.6 MOVE [L2387-L2391]: X10 = 01001010, AND data 00011111 -> R100 = 00001010.
TEST_P(FanucExec, MoveAndMask) {
  auto m =
      pmc("RD R9091.1\nSUB 8\n(PRM) 0001\n(PRM) 1111\n(PRM) X10\n(PRM) R100\nEND1\nEND2\nEND\n");
  ASSERT_TRUE(m);
  set(*m, "X10", 0b01001010); // ACT = R9091.1, the always-on relay the runtime writes
  m->tick();
  EXPECT_EQ(get(*m, "R100"), 0b00001010);
}

// 7.7 MOVOR [L2433-L2443]: X10 = 01001010 OR R200 = 00011111 -> R100 = 01011111.
TEST_P(FanucExec, MovorOr) {
  auto m = pmc("RD X0.0\nMOVOR X10 R200 R100\nEND1\nEND2\nEND\n");
  ASSERT_TRUE(m);
  set(*m, "X0.0", 1);
  set(*m, "X10", 0b01001010);
  set(*m, "R200", 0b00011111);
  m->tick();
  EXPECT_EQ(get(*m, "R100"), 0b01011111);
}

// 3.1 [L255-L289]: -100 as 4 bytes little-endian two's complement is 10011100, 11111111 x3;
// +100 is 01100100, 0, 0, 0. MOVD moves the 4 bytes; EQD compares them as signed 4-byte data.
TEST_P(FanucExec, PlusMinusHundredLittleEndian) {
  auto m = pmc("RD X0.0\nMOVD D0 R100\nRD X0.0\nEQD R100 -100\nWRT R0.0\nRD X0.0\n"
               "EQD D4 100\nWRT R0.1\nEND1\nEND2\nEND\n");
  ASSERT_TRUE(m);
  set(*m, "D0:4", -100);
  set(*m, "D4:4", 100);
  set(*m, "X0.0", 1);
  m->tick();
  EXPECT_EQ(get(*m, "R100"), static_cast<int8_t>(0b10011100)); // bytes read signed
  EXPECT_EQ(get(*m, "R101"), -1);
  EXPECT_EQ(get(*m, "R102"), -1);
  EXPECT_EQ(get(*m, "R103"), -1);
  EXPECT_EQ(get(*m, "R0.0"), 1);
  EXPECT_EQ(get(*m, "D4"), 0b01100100);
  EXPECT_EQ(get(*m, "D5:2"), 0);
  EXPECT_EQ(get(*m, "R0.1"), 1);
}

// 6.6 EQx..LEx [L2825-L2923]: signed binary, B = 1 byte; W1 = data1 op data2. 0x80 as one byte
// is -128 (3.1 [L227-L243]), so it is less than 0 and greater than -129 is not expressible.
TEST_P(FanucExec, ByteComparesAreSigned) {
  auto m = pmc("RD X0.0\nLTB R10 0\nWRT R0.0\nRD X0.0\nGTB R10 -128\nWRT R0.1\nRD X0.0\n"
               "GEB R10 -128\nWRT R0.2\nRD X0.0\nLEW R12 R14\nWRT R0.3\nEND1\nEND2\nEND\n");
  ASSERT_TRUE(m);
  set(*m, "R10", 0x80);
  set(*m, "R12:2", -2);
  set(*m, "R14:2", -2);
  m->tick();
  EXPECT_EQ(get(*m, "R0"), 0); // ACT = 0: W1 = 0 (6.2 [EXT])
  set(*m, "X0.0", 1);
  m->tick();
  EXPECT_EQ(get(*m, "R0.0"), 1);
  EXPECT_EQ(get(*m, "R0.1"), 0);
  EXPECT_EQ(get(*m, "R0.2"), 1);
  EXPECT_EQ(get(*m, "R0.3"), 1);
}

// 6.8 DIFU / DIFD [L3127-L3145, L3165-L3203]: W1 = 1 for exactly one scan after a rising
// (falling) edge of ACT.
TEST_P(FanucExec, DifuDifdOneScan) {
  auto m = pmc("RD X0.0\nDIFU 1\nWRT R0.0\nRD X0.0\nDIFD 2\nWRT R0.1\nEND1\nEND2\nEND\n");
  ASSERT_TRUE(m);
  const int x[] = {0, 1, 1, 1, 0, 0, 1, 0};
  const int up[] = {0, 1, 0, 0, 0, 0, 1, 0};
  const int down[] = {0, 0, 0, 0, 1, 0, 0, 1};
  for (int t = 0; t < 8; ++t) {
    set(*m, "X0.0", x[t]);
    m->tick();
    EXPECT_EQ(get(*m, "R0.0"), up[t]) << "t=" << t;
    EXPECT_EQ(get(*m, "R0.1"), down[t]) << "t=" << t;
  }
}

// 6.8 EOR/AND/OR (SUB 59/60/61) with format 1002 (address, 2 bytes) and 0001 (constant, 1 byte);
// NOT (SUB 62) bit by bit [L3207-L3385].
TEST_P(FanucExec, WordLogic) {
  auto m = pmc("RD X0.0\nSUB 59\n(PRM) 1002\n(PRM) D0\n(PRM) D2\n(PRM) R0\n"
               "RD X0.0\nSUB 60\n(PRM) 0001\n(PRM) D0\n(PRM) 15\n(PRM) R2\n"
               "RD X0.0\nSUB 61\n(PRM) 0001\n(PRM) D0\n(PRM) 15\n(PRM) R3\n"
               "RD X0.0\nSUB 62\n(PRM) 0002\n(PRM) D0\n(PRM) R4\nEND1\nEND2\nEND\n");
  ASSERT_TRUE(m);
  set(*m, "D0:2", 0x1234);
  set(*m, "D2:2", 0x0FF0);
  set(*m, "X0.0", 1);
  m->tick();
  EXPECT_EQ(get(*m, "R0:2"), 0x1234 ^ 0x0FF0);
  EXPECT_EQ(get(*m, "R2"), 0x34 & 15);
  EXPECT_EQ(get(*m, "R3"), 0x34 | 15);
  EXPECT_EQ(static_cast<uint16_t>(get(*m, "R4:2")), static_cast<uint16_t>(~0x1234));
}

// 4.1 / 4.2 [L829-L925]: level 1 runs every tick, level 2 calls subroutine P10 (SP..SPE after
// END2), CALL is conditional on ACT, CALLU is not.
TEST_P(FanucExec, LevelsAndSubroutines) {
  auto m = pmc("RD X0.0\nWRT Y0.0\nEND1\nRD X0.1\nCALL P10\nCALLU P11\nEND2\n"
               "SP P10\nRD R9091.1\nWRT.NOT R0.0\nSPE\nSP P11\nRD X0.2\nWRT R0.1\nSPE\nEND\n");
  ASSERT_TRUE(m);
  set(*m, "R0.0", 1);
  set(*m, "X0.0", 1);
  set(*m, "X0.2", 1);
  m->tick();
  EXPECT_EQ(get(*m, "Y0.0"), 1);
  EXPECT_EQ(get(*m, "R0.0"), 1); // CALL with ACT = 0: P10 not run
  EXPECT_EQ(get(*m, "R0.1"), 1); // CALLU always
  set(*m, "X0.1", 1);
  m->tick();
  EXPECT_EQ(get(*m, "R0.0"), 0);
}

// 2 [L115-L211]: R9091.0 = 0, R9091.1 = 1, R9091.2 = 1 (running), R9091.5 a 0.2 s clock and
// R9091.6 a 1 s clock, both ON:OFF = 1:1; R9015.0 = 1 on the first scan only ([EXT]).
TEST_P(FanucExec, SystemRelays) {
  auto m =
      pmc("RD R9091.0\nWRT R0.0\nRD R9091.1\nWRT R0.1\nRD R9091.2\nWRT R0.2\n"
          "RD R9091.5\nWRT R0.5\nRD R9091.6\nWRT R0.6\nRD R9015.0\nWRT R1.0\nEND1\nEND2\nEND\n");
  ASSERT_TRUE(m);
  m->setPeriodMs(4);
  for (int t = 0; t < 600; ++t) { // now_ms = 4 t
    m->tick();
    const int ms = 4 * t;
    ASSERT_EQ(get(*m, "R0.0"), 0);
    ASSERT_EQ(get(*m, "R0.1"), 1);
    ASSERT_EQ(get(*m, "R0.2"), 1);
    ASSERT_EQ(get(*m, "R0.5"), (ms / 100) % 2 == 0 ? 1 : 0) << ms;
    ASSERT_EQ(get(*m, "R0.6"), (ms / 500) % 2 == 0 ? 1 : 0) << ms;
    ASSERT_EQ(get(*m, "R1.0"), t == 0 ? 1 : 0) << ms;
  }
}

// docs/fanuc-pmc.md "Symbols and comments": a mnemonic file whose operands are symbol names runs
// exactly like the plain program with their addresses written out (bit, byte and functional
// operands, (PRM) lines), tick by tick on every engine.
TEST_P(FanucExec, SymbolsRunLikeTheirAddresses) {
  auto named = pmc("%@A\n"
                   "%@2-E(SYM=1 ADR=2 CM1=3 CM2=4)\n"
                   "START,X0000.0,START KEY,\n"
                   "STOP,X0000.1,STOP KEY,\n"
                   "SETPOINT,X0001,SET POINT,BINARY\n"
                   "RUN,Y0000.0,RUN LAMP,\n"
                   "DONE,Y0000.1,\n"
                   "EDGE,R0000.0,START EDGE,\n"
                   "LATCH,R0000.1,\n"
                   "COPY,D0010,SET POINT COPY,\n"
                   "SUM,D0012,\n"
                   "%\n"
                   "%@3\n"
                   "RD START\nDIFU 1\nWRT EDGE\n"
                   "RD EDGE\nOR LATCH\nAND.NOT STOP\nWRT LATCH\nWRT RUN\n"
                   "RD LATCH\nSUB 24\n(PRM) 1\n(PRM) 40\nWRT DONE\n"
                   "RD LATCH\nMOVB SETPOINT COPY\n"
                   "RD STOP\nRD.STK LATCH\nADDB 1 COPY 3 SUM\n"
                   "END1\nEND2\nEND\n"
                   "%\n"
                   "%@E\n");
  auto plain = pmc("RD X0.0\nDIFU 1\nWRT R0.0\n"
                   "RD R0.0\nOR R0.1\nAND.NOT X0.1\nWRT R0.1\nWRT Y0.0\n"
                   "RD R0.1\nSUB 24\n(PRM) 1\n(PRM) 40\nWRT Y0.1\n"
                   "RD R0.1\nMOVB X1 D10\n"
                   "RD X0.1\nRD.STK R0.1\nADDB 1 D10 3 D12\n"
                   "END1\nEND2\nEND\n");
  ASSERT_TRUE(named && plain);
  for (Machine *m : {named.get(), plain.get()}) m->setPeriodMs(8);
  for (int t = 0; t < 60; ++t) {
    for (Machine *m : {named.get(), plain.get()}) {
      set(*m, "X0.0", t >= 3 && t < 6);
      set(*m, "X0.1", t >= 40 && t < 42);
      set(*m, "X1", 17 * t);
      m->tick();
    }
    for (const char *a : {"Y0", "R0", "D10", "D12"})
      ASSERT_EQ(get(*named, a), get(*plain, a)) << a << " tick " << t;
  }
  EXPECT_EQ(get(*plain, "Y0.1"), 0);                      // the stop key ended the run ...
  EXPECT_EQ(get(*plain, "D12"), 17 * 39 % 256 - 256 + 3); // ... after copying X1 at tick 39
}

} // namespace
} // namespace lj::test

// Family Cnc (chapter-6 CNC blocks on F/G words) on every engine: each block with the manual's
// STL example of hnc8-cnc-interface.md section 2, its F/G mapping from that section (axis A:
// word A*80+k, channel C: 2560+C*80+k, section 0) and the write rules of section 3.1; decisions
// of docs/cnc-blocks.md are cited where they matter. Plus the CNC table's own resolution tests.
#include "profiles/hnc8/CncTable.h"
#include "tests/exec/ExecTest.h"

#include <string>
#include <vector>

namespace lj::test {
namespace {

class CncExec : public ExecTest {};
LJ_EXEC_SUITE(CncExec);

struct LevelCase {
  const char *stl;   ///< contact + block, as in the manual's example
  const char *input; ///< the contact
  const char *gbit;  ///< the G bit that follows it
};

// Level setters (section 3.1.4: bit := ACT on every execution). Example and bit per block of
// section 2: MST 4, CYCLE 5, STOP 6, RESET 7, HOLD 9, ESCBLK 12, DRYRUN 17, SKIP 18, USERIN 19,
// SELSTOP 21, SPDLORI 31, DESYN 37, HOMRUN 41, HOMERUN1 42, HOMESW 43, AXEN 45, AXISLOCK 47,
// AXISMOVE 48, AXISMVTO 49, AXLMF2 50, AXISPLMT 51, AXISNLMT 52, SVSW 54, ALARM 60, RSTCLR 64.
const LevelCase kLevel[] = {
    {"LD X36.4\nMST 0\n", "X36.4", "G2562.11"},
    {"LD X36.4\nCYCLE 0\n", "X36.4", "G2560.5"},
    {"LD X1.2\nSTOP 0\n", "X1.2", "G2560.11"},
    {"LD X2.4\nRESET 0\n", "X2.4", "G2560.13"},
    {"LD X36.4\nHOLD 0\n", "X36.4", "G2560.4"},
    {"LD X36.4\nHOLD 3\n", "X36.4", "G2800.4"}, // channel 3: 2560 + 3*80
    {"LD X31.4\nESCBLK 0 1\n", "X31.4", "G2560.7"},
    {"LD Y32.2\nDRYRUN 2\n", "Y32.2", "G2720.6"},
    {"LD Y32.2\nSKIP 2\n", "Y32.2", "G2721.2"},
    {"LD X31.4\nUSERIN 0 1 1\n", "X31.4", "G2584.1"},  // #1190 = 2
    {"LD X31.4\nUSERIN 0 1 17\n", "X31.4", "G2585.1"}, // #1190 = 2^17: bit 17 of GC[24..25]
    {"LD Y32.2\nSELSTOP 0\n", "Y32.2", "G2561.3"},
    {"LD X31.4\nSPDLORI 0\n", "X31.4", "G2.12"},
    {"LD X32.6\nDESYN 0\n", "X32.6", "G0.11"},
    {"LD X1.1\nHOMRUN 1\n", "X1.1", "G80.4"},
    {"LD X1.1\nHOMERUN1 1 X23.3\n", "X1.1", "G80.4"},
    {"LD X1.4\nHOMESW 1\n", "X1.4", "G80.5"},
    {"LD X0.1\nAXEN 1\n", "X0.1", "G80.7"},
    {"LD X2.0\nAXISLOCK 2\n", "X2.0", "G160.6"},
    {"LD X2.0\nAXISMOVE 2 2\n", "X2.0", "G161.1"},
    {"LD X2.0\nAXISMVTO 2 2\n", "X2.0", "G161.0"},
    {"LD X2.0\nAXLMF2 2\n", "X2.0", "G161.2"},
    {"LD X1.1\nAXISPLMT 1\n", "X1.1", "G80.0"},
    {"LD X1.2\nAXISNLMT 1\n", "X1.2", "G80.1"},
    {"LD X1.1\nSVSW 1\n", "X1.1", "G83.0"},
    {"LD X3.4\nALARM 3\n", "X3.4", "G3010.2"}, // alarm n: G3010 bit n-1
    {"LD X3.4\nALARM 256\n", "X3.4", "G3025.15"},
    {"LD X3.4\nALARM 501\n", "X3.4", "G3056.0"}, // prompt n: G3056 bit n-501
    {"LD X3.4\nALARM 884\n", "X3.4", "G3079.15"},
    {"LD X30.5\nRSTCLR 0\n", "X30.5", "G2560.9"},
};

TEST_P(CncExec, LevelSettersFollowAct) {
  for (const LevelCase &c : kLevel) {
    SCOPED_TRACE(c.stl);
    auto m = load(c.stl);
    ASSERT_TRUE(m);
    for (int act : {1, 0, 1, 0}) {
      m->set(c.input, act);
      m->tick();
      EXPECT_EQ(m->get(c.gbit), act);
    }
  }
}

// Section 3.1.4: a setter writes only its bit; the other bits of the word keep their value.
TEST_P(CncExec, LevelSetterKeepsOtherBits) {
  auto m = load("LD X1.1\nHOMRUN 1\n");
  ASSERT_TRUE(m);
  m->set("G80", 0x7FEF); // every bit but .4 (and the sign)
  m->set("X1.1", 1);
  m->tick();
  EXPECT_EQ(m->get("G80"), 0x7FFF);
  m->set("X1.1", 0);
  m->tick();
  EXPECT_EQ(m->get("G80"), 0x7FEF);
}

struct StatusCase {
  const char *block; ///< the status block (output := ACT and F bit)
  const char *fbit;
};

// Status blocks: CYCLED 10, HOLDLED 11, SPDLOROK 32, SPDLZERO 34, SPDLRCH 35, HOMLED 44, REFPT 56,
// AXISHOM2 57 (documented F0.2), AXMOVING 58 (documented F0.0), RSTCHK 63.
const StatusCase kStatus[] = {
    {"CYCLED 0", "F2560.5"},  {"HOLDLED 0", "F2560.4"}, {"HOLDLED 1", "F2640.4"},
    {"SPDLOROK 0", "F3.8"},   {"SPDLZERO 1", "F82.15"}, {"SPDLRCH 1", "F82.14"},
    {"HOMLED 1", "F80.4"},    {"REFPT 1 2", "F80.9"},   {"REFPT 1 3", "F80.10"},
    {"REFPT 1 4", "F80.11"},  {"AXISHOM2 0", "F0.2"},   {"AXMOVING 0", "F0.0"},
    {"RSTCHK 0", "F2560.12"},
};

TEST_P(CncExec, StatusBlocksGiveActAndBit) {
  for (const StatusCase &c : kStatus) {
    SCOPED_TRACE(c.block);
    auto m = load(std::string("LD X0.0\n") + c.block + "\nOUT Y36.4\n");
    ASSERT_TRUE(m);
    forAllInputs(*m, {"X0.0", c.fbit},
                 [&](const Inputs &in) { EXPECT_EQ(m->get("Y36.4"), in("X0.0") && in(c.fbit)); });
  }
}

// Section 2 examples 10/11: `LDT / CYCLED 0 / OUT Y36.4`, `LDT / HOLDLED 0 / OUT Y36.5`.
TEST_P(CncExec, LampExamples) {
  auto m = load("LDT\nCYCLED 0\nOUT Y36.4\nLDT\nHOLDLED 0\nOUT Y36.5\n");
  ASSERT_TRUE(m);
  m->set("F2560", 0x20); // cycle running, no hold
  m->tick();
  EXPECT_EQ(m->get("Y36.4"), 1);
  EXPECT_EQ(m->get("Y36.5"), 0);
  m->set("F2560", 0x10);
  m->tick();
  EXPECT_EQ(m->get("Y36.4"), 0);
  EXPECT_EQ(m->get("Y36.5"), 1);
}

// REFPT n = 5 has no status bit (F0.12 is the overload bit): output 0 (docs/cnc-blocks.md).
TEST_P(CncExec, RefptFiveIsAlwaysOff) {
  auto m = load("LDT\nREFPT 1 5\nOUT R10.1\n");
  ASSERT_TRUE(m);
  m->set("F80", -1);
  m->tick();
  EXPECT_EQ(m->get("R10.1"), 0);
}

// AXRDY 46: no input, pushes FA[2].8 like a contact (`AXRDY 1` -> R10.1).
TEST_P(CncExec, AxrdyPushesReadyBit) {
  auto m = load("AXRDY 1\nOUT R10.1\nLD X0.0\nAXRDY 2\nANB\nOUT R10.2\n");
  ASSERT_TRUE(m);
  forAllInputs(*m, {"F82.8", "F162.8", "X0.0"}, [&](const Inputs &in) {
    EXPECT_EQ(m->get("R10.1"), in("F82.8"));
    EXPECT_EQ(m->get("R10.2"), in("X0.0") && in("F162.8"));
  });
}

// RSTCHK / RSTCLR handshake (section 1.6 "Reset", examples 63/64).
TEST_P(CncExec, ResetHandshake) {
  auto m = load("LDT\nRSTCHK 0\nOUT R5.0\nLD X30.5\nRSTCLR 0\n");
  ASSERT_TRUE(m);
  m->set("F2560.12", 1); // the NC resets channel 0
  m->tick();
  EXPECT_EQ(m->get("R5.0"), 1);
  EXPECT_EQ(m->get("G2560.9"), 0);
  m->set("X30.5", 1); // PLC reset work done
  m->tick();
  EXPECT_EQ(m->get("G2560.9"), 1);
  m->set("F2560.12", 0); // the NC clears its flag
  m->set("X30.5", 0);
  m->tick();
  EXPECT_EQ(m->get("R5.0"), 0);
  EXPECT_EQ(m->get("G2560.9"), 0);
}

struct WriteCase {
  const char *stl;
  const char *src; ///< register preset before the ticks
  int64_t value;
  std::vector<std::pair<const char *, int64_t>> expect; ///< words after the ACT tick
};

// Value writers (section 3.1.4: written only while ACT): RPOVRD 13 GC[5], FEEDOVRD 14 GC[4],
// SPDLOVRD 15 GC[6+sp], STEPMUL 16 GA[8], JOGVEL 40 GA[6/7] (low word first, each read as int16),
// CHANSW 8 G2970, ESCBLK 12 GC[22], AXISMOVE 48 GA[52..55], AXISMVTO 49 GA[48..51] (64 bit,
// docs/cnc-blocks.md).
const std::vector<WriteCase> kWrite = {
    {"LD X0.0\nRPOVRD 0 R7\n", "R7", 50, {{"G2565", 50}}},
    {"LD X0.0\nFEEDOVRD 0 R7\n", "R7", 120, {{"G2564", 120}}},
    {"LD X0.0\nSPDLOVRD 0 0 R7\n", "R7", 80, {{"G2566", 80}}},
    {"LD X0.0\nSPDLOVRD 1 3 W7\n", "W7", -3, {{"G2649", -3}}},
    {"LD X0.0\nSTEPMUL 3 R7\n", "R7", 100, {{"G248", 100}}},
    {"LD X0.0\nJOGVEL 0 D0\n", "D0", 100000, {{"G6", 100000 - 131072}, {"G7", 1}}},
    {"LD X0.0\nJOGVEL 1 D0\n", "D0", -2, {{"G86", -2}, {"G87", -1}}},
    {"LD X0.0\nCHANSW 2\n", "R0", 0, {{"G2970", 2}}},
    {"LD X0.0\nESCBLK 1 5\n", "R0", 0, {{"G2662", 5}, {"G2640.7", 1}}},
    {"LD X0.0\nAXISMOVE 2 D1\n",
     "D1",
     -5,
     {{"G212", -5}, {"G213", -1}, {"G214", -1}, {"G215", -1}, {"G161.1", 1}}},
    {"LD X0.0\nAXISMVTO 2 D1\n",
     "D1",
     0x12345678,
     {{"G208", 0x5678}, {"G209", 0x1234}, {"G210", 0}, {"G211", 0}, {"G161.0", 1}}},
    {"LD X0.0\nAXISMVTO 2 2\n", "R0", 0, {{"G208", 2}, {"G209", 0}}},
};

TEST_P(CncExec, ValueWritersWriteOnlyWhileAct) {
  for (const WriteCase &c : kWrite) {
    SCOPED_TRACE(c.stl);
    auto m = load(c.stl);
    ASSERT_TRUE(m);
    m->set(c.src, c.value);
    m->set("X0.0", 0);
    m->tick();
    for (auto [addr, v] : c.expect) EXPECT_EQ(m->get(addr), 0) << addr;
    m->set("X0.0", 1);
    m->tick();
    for (auto [addr, v] : c.expect) EXPECT_EQ(m->get(addr), v) << addr;
    // ACT off again: words keep the value (only level bits follow ACT).
    m->set("X0.0", 0);
    m->tick();
    for (auto [addr, v] : c.expect)
      if (std::string(addr).find('.') == std::string::npos) {
        EXPECT_EQ(m->get(addr), v) << addr;
      }
  }
}

} // namespace
} // namespace lj::test

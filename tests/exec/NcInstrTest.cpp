// Family Nc (NC services) on every engine: the test values of hnc8-functions-1.md 3.1 (MGET MACK
// TGET TACK RTOMPG TEMPSEN), hnc8-functions-2.md 2.19-2.23 (PARTCNT PARTCLR HEADSEN VARGET
// VARSET), hnc8-cnc-interface.md section 2 (the chapter-6 host blocks, ROT #59) and the
// decisions of docs/dialect-notes.md "NC services", with TestHost recording the host calls.
#include "hosts/TestHost.h"
#include "tests/exec/ExecTest.h"

namespace lj::test {
namespace {
using hosts::HostCall;
using hosts::TestHost;

class NcExec : public ExecTest {
protected:
  /// Load without init, attach `host` (null: no host), then init.
  std::unique_ptr<Machine> loadWith(std::string_view text, const TestHost *host) {
    return loadWithHost(text, host ? host->host() : nullptr);
  }
  static std::vector<HostCall> calls(std::initializer_list<HostCall> l) { return l; }
  /// Idle M/T slots of channel 0: FC[48..56] = -1 (hnc8-cnc-interface.md 1.6).
  static void idleChannel0(Machine &m) {
    for (int k = 0; k <= 8; ++k) m.set("F" + std::to_string(2608 + k), -1);
  }
};
LJ_EXEC_SUITE(NcExec);

// ---- chapter 4 (hnc8-functions-1.md 3.1) ----

// MGET example: X2.0=1 and F2608=3 -> R4.0=1; no slot holds 3 -> 0; X2.0=0 -> 0.
TEST_P(NcExec, MgetExample) {
  auto m = load("LD X2.0\nMGET 0 3\nWRT R4.0\n");
  ASSERT_TRUE(m);
  idleChannel0(*m);
  m->set("X2.0", 1);
  m->set("F2608", 3);
  m->tick();
  EXPECT_EQ(m->get("R4.0"), 1);
  m->set("F2608", 4);
  m->set("F2615", 33);
  m->tick();
  EXPECT_EQ(m->get("R4.0"), 0);
  m->set("F2613", 3); // any of the 8 slots FC[48..55]
  m->tick();
  EXPECT_EQ(m->get("R4.0"), 1);
  m->set("X2.0", 0);
  m->tick();
  EXPECT_EQ(m->get("R4.0"), 0);
  EXPECT_EQ(m->get("G2613"), 0); // MGET writes nothing
}

// Channel words are at 2560 + 80 ch: channel 2's first M slot is F2768.
TEST_P(NcExec, MgetOtherChannel) {
  auto m = load("LDT\nMGET 2 6\nOUT Y0.0\n");
  ASSERT_TRUE(m);
  m->set("F2608", 6);
  m->tick();
  EXPECT_EQ(m->get("Y0.0"), 0);
  m->set("F2768", 6);
  m->tick();
  EXPECT_EQ(m->get("Y0.0"), 1);
}

// MACK example: F2608=3, X3.6=1 -> G2608=3; X3.6=0 -> G2608 unchanged; only slots holding M.
TEST_P(NcExec, MackExample) {
  auto m = load("LD X3.6\nMACK 0 3\n");
  ASSERT_TRUE(m);
  idleChannel0(*m);
  m->set("G2608", -1);
  m->set("G2610", -1);
  m->set("F2608", 3);
  m->tick();
  EXPECT_EQ(m->get("G2608"), -1); // X3.6 = 0
  m->set("X3.6", 1);
  m->tick();
  EXPECT_EQ(m->get("G2608"), 3);
  EXPECT_EQ(m->get("G2610"), -1);
  m->set("F2608", 5);
  m->set("F2610", 3);
  m->set("G2608", -2);
  m->tick();
  EXPECT_EQ(m->get("G2608"), -2);
  EXPECT_EQ(m->get("G2610"), 3);
}

// TGET example: F2616=12 -> R5=12, R6.1=1; F2616=-1 -> R5 unchanged, R6.1=0.
TEST_P(NcExec, TgetExample) {
  auto m = load("LDT\nTGET 0 R5\nOUT R6.1\n");
  ASSERT_TRUE(m);
  m->set("F2616", 12);
  m->tick();
  EXPECT_EQ(m->get("R5"), 12);
  EXPECT_EQ(m->get("R6.1"), 1);
  m->set("F2616", -1);
  m->set("R5", 77);
  m->tick();
  EXPECT_EQ(m->get("R5"), 77);
  EXPECT_EQ(m->get("R6.1"), 0);
}

// TGET resolution: a constant destination is a compare with the pending T code.
TEST_P(NcExec, TgetConstantCompares) {
  auto m = load("LD X1.0\nTGET 0 12\nOUT Y0.0\n");
  ASSERT_TRUE(m);
  m->set("X1.0", 1);
  m->set("F2616", 12);
  m->tick();
  EXPECT_EQ(m->get("Y0.0"), 1);
  m->set("F2616", 13);
  m->tick();
  EXPECT_EQ(m->get("Y0.0"), 0);
  m->set("F2616", 12);
  m->set("X1.0", 0);
  m->tick();
  EXPECT_EQ(m->get("Y0.0"), 0);
}

// TACK example: F2616=12 and X3.4=1 -> G2616=12.
TEST_P(NcExec, TackExample) {
  auto m = load("LD X3.4\nTACK 0\n");
  ASSERT_TRUE(m);
  m->set("F2616", 12);
  m->set("G2616", -1);
  m->tick();
  EXPECT_EQ(m->get("G2616"), -1);
  m->set("X3.4", 1);
  m->tick();
  EXPECT_EQ(m->get("G2616"), 12);
}

// RTOMPG example: X3.4 on -> the host's handwheel 0 gets the pulse register X40.
TEST_P(NcExec, RtompgCallsHost) {
  TestHost h;
  auto m = loadWith("LD X3.4\nRTOMPG X40 0\n", &h);
  ASSERT_TRUE(m);
  m->set("X40", 200);
  m->tick();
  EXPECT_TRUE(h.calls().empty());
  m->set("X3.4", 1);
  m->tick();
  m->set("X40", 201);
  m->tick();
  EXPECT_EQ(h.calls(), calls({{"mpg_input", {0, 200}, {}, 0}, {"mpg_input", {0, 201}, {}, 0}}));
}

// TEMPSEN example (no load: input 1): the raw AD word X15 (low) / X16 (high) and P30..P33.
TEST_P(NcExec, TempsenCallsHost) {
  TestHost h;
  auto m = loadWith("TEMPSEN 0 X15 0 P30\nLD X1.0\nTEMPSEN 19 X20 4 P196\n", &h);
  ASSERT_TRUE(m);
  m->set("X15", 0x34);
  m->set("X16", 0x12);
  m->set("P30", 10);
  m->set("P31", 80);
  m->set("P32", -3);
  m->set("P33", 4);
  m->set("X20", 0xFE);
  m->set("X21", 0xFF);
  m->set("P199", 9);
  m->tick();
  m->set("X1.0", 1);
  m->tick();
  EXPECT_EQ(h.calls(), calls({{"temp_input", {0, 0x1234, 0, 10, 80, -3, 4}, {}, 0},
                              {"temp_input", {0, 0x1234, 0, 10, 80, -3, 4}, {}, 0},
                              {"temp_input", {19, -2, 4, 0, 0, 0, 9}, {}, 0}}));
}

// ---- hnc8-functions-2.md 2.19-2.23 ----

// PARTCNT: G2579=5, one scan -> 6, another -> 7 (level); output = EN.
TEST_P(NcExec, PartcntExample) {
  auto m = load("LD X32.1\nPARTCNT 0\nOUT R0.0\nLD X32.2\nPARTCNT 3\n");
  ASSERT_TRUE(m);
  m->set("G2579", 5);
  m->tick();
  EXPECT_EQ(m->get("G2579"), 5);
  EXPECT_EQ(m->get("R0.0"), 0);
  m->set("X32.1", 1);
  m->tick();
  EXPECT_EQ(m->get("G2579"), 6);
  EXPECT_EQ(m->get("R0.0"), 1);
  m->tick();
  EXPECT_EQ(m->get("G2579"), 7);
  m->set("G2819", 32767); // channel 3: G[2579 + 240]; 16-bit wrap
  m->set("X32.2", 1);
  m->tick();
  EXPECT_EQ(m->get("G2819"), -32768);
}

// PARTCLR: G2579=6, X32.1=1 -> 0.
TEST_P(NcExec, PartclrExample) {
  auto m = load("LD X32.1\nPARTCLR 0\nOUT R0.0\n");
  ASSERT_TRUE(m);
  m->set("G2579", 6);
  m->tick();
  EXPECT_EQ(m->get("G2579"), 6);
  m->set("X32.1", 1);
  m->tick();
  EXPECT_EQ(m->get("G2579"), 0);
  EXPECT_EQ(m->get("R0.0"), 1);
}

// HEADSEN example: temperatures t0..t9 = 20..29 (G3080..3089) -> D1..D10 = 20..29.
TEST_P(NcExec, HeadsenExample) {
  auto m = load("LD X32.1\nHEADSEN 10 0 D1\nLD X32.2\nHEADSEN 5 1 D50\n");
  ASSERT_TRUE(m);
  for (int i = 0; i < 20; ++i) m->set("G" + std::to_string(3080 + i), 20 + i);
  m->set("G3081", -5); // sign-extended like every G read
  m->set("D11", 99);
  m->tick();
  EXPECT_EQ(m->get("D1"), 0); // EN = 0
  m->set("X32.1", 1);
  m->set("X32.2", 1);
  m->tick();
  EXPECT_EQ(m->get("D1"), 20);
  EXPECT_EQ(m->get("D2"), -5);
  for (int i = 2; i < 10; ++i) EXPECT_EQ(m->get("D" + std::to_string(1 + i)), 20 + i);
  EXPECT_EQ(m->get("D11"), 99);
  EXPECT_EQ(m->get("D50"), 0); // enable switch 1 = off
}

// VARGET example: #501 (type 1, offset 1) = 42.0 -> R100 = 42; 3.7 with e=0 -> 3;
// `VARGET 1 1 2 D0` with 3.75 -> 375.
TEST_P(NcExec, VargetExample) {
  TestHost h;
  h.vars[{1, 1}] = 42.0;
  auto m = loadWith("LD X32.1\nVARGET 1 1 0 R100\nOUT Y0.0\nLD X32.1\nVARGET 1 1 2 D0\n", &h);
  ASSERT_TRUE(m);
  m->set("X32.1", 1);
  m->tick();
  EXPECT_EQ(m->get("R100"), 42);
  EXPECT_EQ(m->get("Y0.0"), 1);
  h.vars[{1, 1}] = 3.7;
  m->tick();
  EXPECT_EQ(m->get("R100"), 3);
  h.vars[{1, 1}] = 3.75;
  m->tick();
  EXPECT_EQ(m->get("D0"), 375);
  EXPECT_EQ(h.calls().size(), 6u);
  EXPECT_EQ(h.calls()[5], (HostCall{"var_get", {1, 1, 2}, {375}, 1}));
}

// VARGET: the offset comes from a register; a variable that does not exist writes nothing, the
// output stays EN; EN = 0 calls nothing.
TEST_P(NcExec, VargetOffsetRegisterAndMissingVariable) {
  TestHost h;
  h.vars[{2, 7}] = -123456;
  auto m = loadWith("LD X1.0\nVARGET 2 W3 4 D5\nOUT Y0.0\n", &h);
  ASSERT_TRUE(m);
  m->set("D5", 99);
  m->set("W3", 7);
  m->tick();
  EXPECT_TRUE(h.calls().empty());
  m->set("X1.0", 1);
  m->tick();
  EXPECT_EQ(m->get("D5"), -123456); // integer type: no scaling
  m->set("W3", 10000);              // type 2 has offsets 0..9999
  m->set("D5", 99);
  m->tick();
  EXPECT_EQ(m->get("D5"), 99);
  EXPECT_EQ(m->get("Y0.0"), 1);
  EXPECT_EQ(h.calls().back(), (HostCall{"var_get", {2, 10000, 4}, {}, 0}));
}

// VARSET example: R100 = 42 -> #501 = 42.0.
TEST_P(NcExec, VarsetExample) {
  TestHost h;
  auto m = loadWith("LD X32.1\nVARSET 1 1 0 R100\nOUT Y0.0\n", &h);
  ASSERT_TRUE(m);
  m->set("R100", 42);
  m->tick();
  EXPECT_TRUE(h.calls().empty());
  m->set("X32.1", 1);
  m->tick();
  EXPECT_DOUBLE_EQ(h.vars[std::make_pair(1, 1)], 42.0);
  EXPECT_EQ(m->get("Y0.0"), 1);
  EXPECT_EQ(h.calls(), calls({{"var_set", {1, 1, 0, 42}, {}, 1}}));
}

} // namespace
} // namespace lj::test

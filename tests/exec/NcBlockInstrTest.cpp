// Family Nc, chapter-6 blocks on every engine (hnc8-cnc-interface.md section 2: TOOLSET TOOLCLR
// NIXIE TOOLUSE TOOLLIFE TOOL SPDA SUBAXEN MPGSET ROT EVENT SAVEDATA), with the decisions of
// docs/dialect-notes.md "NC services" and TestHost's documented behaviour.
#include "hosts/TestHost.h"
#include "tests/exec/ExecTest.h"

namespace lj::test {
namespace {
using hosts::HostCall;
using hosts::TestHost;

class NcBlockExec : public ExecTest {
protected:
  /// Load without init, attach `host` (null: no host), then init.
  std::unique_ptr<Machine> loadWith(std::string_view text, const TestHost *host) {
    return loadWithHost(text, host ? host->host() : nullptr);
  }
  static std::vector<HostCall> calls(std::initializer_list<HostCall> l) { return l; }
};
LJ_EXEC_SUITE(NcBlockExec);

// TOOLSET / TOOLCLR (#22, #23): tool_vector(ch, 1 / 0) while the input is on; output = EN.
TEST_P(NcBlockExec, ToolsetToolclr) {
  TestHost h;
  auto m = loadWith("LD Y32.2\nTOOLSET 0\nOUT R0.0\nLD Y32.3\nTOOLCLR 3\nOUT R0.1\n", &h);
  ASSERT_TRUE(m);
  m->tick();
  EXPECT_TRUE(h.calls().empty());
  EXPECT_EQ(m->get("R0.0"), 0);
  m->set("Y32.2", 1);
  m->set("Y32.3", 1);
  m->tick();
  EXPECT_EQ(h.calls(), calls({{"tool_vector", {0, 1}, {}, 0}, {"tool_vector", {3, 0}, {}, 0}}));
  EXPECT_EQ(m->get("R0.0"), 1);
  EXPECT_EQ(m->get("R0.1"), 1);
}

// NIXIE (#24) example `NIXIE R23 0 Y37`: TestHost encodes BCD; width 1 into a byte area writes
// two bytes, low byte first; into a word element the masked value.
TEST_P(NcBlockExec, NixieEncodesThroughHost) {
  TestHost h;
  auto m = loadWith("LD X1.0\nNIXIE R23 0 Y37\nOUT R0.0\nLD X1.0\nNIXIE D5 1 R10\nLD X1.0\n"
                    "NIXIE D5 1 W3\n",
                    &h);
  ASSERT_TRUE(m);
  m->set("R23", 42);
  m->set("D5", 1234);
  m->tick();
  EXPECT_EQ(m->get("Y37"), 0);
  m->set("X1.0", 1);
  m->tick();
  EXPECT_EQ(m->get("Y37"), 0x42);
  EXPECT_EQ(m->get("R0.0"), 1);
  EXPECT_EQ(m->get("R10"), 0x34);
  EXPECT_EQ(m->get("R11"), 0x12);
  EXPECT_EQ(m->get("W3"), 0x1234);
  EXPECT_EQ(h.calls()[0], (HostCall{"nixie_encode", {42, 0}, {}, 0x42}));
}

// NIXIE without a host shows the raw value: its low 8 / 16 bits.
TEST_P(NcBlockExec, NixieWithoutHostIsRaw) {
  auto m = loadWith("LDT\nNIXIE R23 0 Y37\nLDT\nNIXIE D5 1 R10\nLDT\nNIXIE D5 1 D6\n", nullptr);
  ASSERT_TRUE(m);
  m->set("R23", 200);
  m->set("D5", 70000); // 0x11170
  m->set("D6", -1);
  m->tick();
  EXPECT_EQ(m->get("Y37"), 200);
  EXPECT_EQ(m->get("R10"), 0x70);
  EXPECT_EQ(m->get("R11"), 0x11);
  EXPECT_EQ(m->get("D6"), 0x1170);
}

// TOOLUSE (#25) `TOOLUSE 0 R23`: tool_in_use(ch, tool), both read from their operands.
TEST_P(NcBlockExec, TooluseCallsHost) {
  TestHost h;
  auto m = loadWith("LDT\nTOOLUSE 0 R23\nLD X1.0\nTOOLUSE W2 D4\n", &h);
  ASSERT_TRUE(m);
  m->set("R23", 17);
  m->set("W2", 1);
  m->set("D4", -9);
  m->tick();
  m->set("X1.0", 1);
  m->tick();
  EXPECT_EQ(h.calls(), calls({{"tool_in_use", {0, 17}, {}, 0},
                              {"tool_in_use", {0, 17}, {}, 0},
                              {"tool_in_use", {1, -9}, {}, 0}}));
}

// TOOLLIFE (#26) `TOOLLIFE 0 10 R23` with count 3: rising edges of ACT are counted; the third
// sets R23 = 1 for that execution only and restarts the count; a held input counts once.
TEST_P(NcBlockExec, ToollifeCountsRisingEdges) {
  auto m = load("LD X1.0\nTOOLLIFE 0 3 R23\n");
  ASSERT_TRUE(m);
  m->set("R23", 55);
  m->tick();
  EXPECT_EQ(m->get("R23"), 0); // written on every execution
  pulse(*m, "X1.0", 2);
  EXPECT_EQ(m->get("R23"), 0);
  m->set("X1.0", 1);
  m->tick(); // third rising edge
  EXPECT_EQ(m->get("R23"), 1);
  m->tick(); // still on: no edge
  EXPECT_EQ(m->get("R23"), 0);
  m->set("X1.0", 0);
  m->tick();
  pulse(*m, "X1.0", 2);
  m->set("X1.0", 1);
  m->tick();
  EXPECT_EQ(m->get("R23"), 1); // the count restarted after the first response
}

// TOOL (#27) `TOOL R40 R41 R42 R43` / OUT R181.1: pocket found -> R43, output 1; not found ->
// the host's error code in R42, output 0.
TEST_P(NcBlockExec, ToolSelectsPocket) {
  TestHost h;
  h.pockets[12] = 5;
  auto m = loadWith("LD R154.1\nTOOL R40 R41 R42 R43\nOUT R181.1\n", &h);
  ASSERT_TRUE(m);
  m->set("R40", 3);
  m->set("R41", 12);
  m->set("R154.1", 1);
  m->tick();
  EXPECT_EQ(m->get("R43"), 5);
  EXPECT_EQ(m->get("R42"), 0);
  EXPECT_EQ(m->get("R181.1"), 1);
  m->set("R41", 13);
  m->tick();
  EXPECT_EQ(m->get("R42"), 7);
  EXPECT_EQ(m->get("R43"), 5);
  EXPECT_EQ(m->get("R181.1"), 0);
  m->set("R154.1", 0);
  m->set("R41", 12);
  m->tick();
  EXPECT_EQ(m->get("R181.1"), 0);
  EXPECT_EQ(h.calls(), calls({{"tool_select", {3, 12}, {5}, 1}, {"tool_select", {3, 13}, {7}, 0}}));
}

// SPDA (#33) `SPDA 1 0 R1 R2 P5` (reference in D2 here): rpm = FC[10/11] of channel 1
// (F2650/F2651, low word first); TestHost's DA = rpm/10 + 1000 gear + 100 sp + 10 ch + pbase.
TEST_P(NcBlockExec, SpdaWritesDaValue) {
  TestHost h;
  auto m = loadWith("LDT\nSPDA 1 0 R1 D2 P5\n", &h);
  ASSERT_TRUE(m);
  m->set("F2650", static_cast<int16_t>(0xE360)); // 1500000 = 0x0016E360
  m->set("F2651", 0x16);
  m->set("R1", 2);
  m->tick();
  // 150000 + 2000 + 0 + 10 + 5 = 152015 = 0x251CF
  EXPECT_EQ(m->get("D2"), 152015);
  EXPECT_EQ(m->get("G2650"), 0x51CF);
  EXPECT_EQ(m->get("G2651"), 2);
  EXPECT_EQ(h.calls(), calls({{"spindle_da", {1, 0, 1500000, 2, 5}, {}, 152015}}));
}

// SUBAXEN (#36): level, like a coil: slave_home(axis, ACT) on every execution.
TEST_P(NcBlockExec, SubaxenReportsLevel) {
  TestHost h;
  auto m = loadWith("LD X32.6\nSUBAXEN 4\n", &h);
  ASSERT_TRUE(m);
  m->tick();
  m->set("X32.6", 1);
  m->tick();
  EXPECT_EQ(h.calls(), calls({{"slave_home", {4, 0}, {}, 0}, {"slave_home", {4, 1}, {}, 0}}));
}

// MPGSET (#53) `MPGSET 1 R6 R7`: GA[9] = multiplier, GA[10/11] = the handwheel's pulse delta
// (32 bits, low word first); axis 2 -> G169, G170, G171.
TEST_P(NcBlockExec, MpgsetRoutesPulses) {
  TestHost h;
  h.mpgDeltas[1] = {5, -3, 70000};
  auto m = loadWith("LD X1.0\nMPGSET 1 R6 R7\nOUT Y0.0\n", &h);
  ASSERT_TRUE(m);
  m->set("R6", 2);
  m->set("R7", 10);
  m->tick();
  EXPECT_TRUE(h.calls().empty());
  m->set("X1.0", 1);
  m->tick();
  EXPECT_EQ(m->get("G169"), 10);
  EXPECT_EQ(m->get("G170"), 5);
  EXPECT_EQ(m->get("G171"), 0);
  EXPECT_EQ(m->get("Y0.0"), 1);
  m->tick();
  EXPECT_EQ(m->get("G170"), -3);
  EXPECT_EQ(m->get("G171"), -1);
  m->tick();
  EXPECT_EQ(m->get("G170"), 4464); // 70000 = 0x00011170
  EXPECT_EQ(m->get("G171"), 1);
  EXPECT_EQ(h.calls().size(), 3u);
}

// MPGSET with an axis outside 0..31: nothing written, no host call, output 0, fault_index + 1.
TEST_P(NcBlockExec, MpgsetAxisOutOfRangeFaults) {
  TestHost h;
  auto m = loadWith("LD X1.0\nMPGSET 0 W6 R7\nOUT Y0.0\n", &h);
  ASSERT_TRUE(m);
  m->set("X1.0", 1);
  m->set("R7", 10);
  m->set("W6", 32);
  m->tick();
  EXPECT_EQ(m->get("Y0.0"), 0);
  EXPECT_EQ(m->state().fault_index, 1u);
  m->set("W6", -1);
  m->tick();
  EXPECT_EQ(m->state().fault_index, 2u);
  EXPECT_TRUE(h.calls().empty());
  m->set("W6", 31);
  m->tick();
  EXPECT_EQ(m->get("Y0.0"), 1);
  EXPECT_EQ(m->get("G2489"), 10); // 31 * 80 + 9
  EXPECT_EQ(m->state().fault_index, 2u);
}

// EVENT (#61) `EVENT 122`: G3047 bit 10 follows ACT; event(122) on each rising edge only.
TEST_P(NcBlockExec, EventBitAndRisingEdgeCall) {
  TestHost h;
  auto m = loadWith("LD X30.4\nEVENT 122\n", &h);
  ASSERT_TRUE(m);
  m->set("X30.4", 1);
  m->tick();
  EXPECT_EQ(m->get("G3047.10"), 1);
  m->tick();
  EXPECT_EQ(h.calls().size(), 1u);
  m->set("X30.4", 0);
  m->tick();
  EXPECT_EQ(m->get("G3047.10"), 0);
  m->set("X30.4", 1);
  m->tick();
  EXPECT_EQ(h.calls(), calls({{"event", {122}, {}, 0}, {"event", {122}, {}, 0}}));
}

// SAVEDATA (#62): save_data() on the rising edge of ACT.
TEST_P(NcBlockExec, SavedataOnRisingEdge) {
  TestHost h;
  auto m = loadWith("LD X30.4\nSAVEDATA\n", &h);
  ASSERT_TRUE(m);
  pulse(*m, "X30.4", 2);
  m->set("X30.4", 1);
  m->ticks(3);
  EXPECT_EQ(h.calls(),
            calls({{"save_data", {}, {}, 0}, {"save_data", {}, {}, 0}, {"save_data", {}, {}, 0}}));
}

} // namespace
} // namespace lj::test

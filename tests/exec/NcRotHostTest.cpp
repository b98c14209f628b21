// Family Nc: ROT (hnc8-cnc-interface.md 2 #59) with hand-computed values of its algorithm, the
// documented defaults without an NC host (abi.h lj_host, docs/dialect-notes.md "NC services")
// on every engine, and one program of every Nc mnemonic whose states AND host call logs must
// be equal on all engines.
#include "hosts/TestHost.h"
#include "tests/exec/ExecTest.h"

#include <cstring>

namespace lj::test {
namespace {
using hosts::HostCall;
using hosts::TestHost;

class NcRotHostExec : public ExecTest {};
LJ_EXEC_SUITE(NcRotHostExec);

/// One ROT case: inputs in1..in5, current and target position, expected result and output.
struct RotCase {
  int in[5];
  int cur, tgt;
  int result, out;
};

constexpr const char *kRot16 = "LD X1.0\nLD X1.1\nLD X1.2\nLD X1.3\nLD X1.4\nROT 16 B0 R27 R59\n"
                               "OUT Y0.0\n";
constexpr const char *kRot8 = "LD X1.0\nLD X1.1\nLD X1.2\nLD X1.3\nLD X1.4\nROT 8 B0 R27 R59\n"
                              "OUT Y0.0\n";

void runRot(Machine &m, const RotCase &c) {
  for (int k = 0; k < 5; ++k) m.set("X1." + std::to_string(k), c.in[k]);
  m.set("B0", c.cur);
  m.set("R27", c.tgt);
  m.set("R59", 99);
  m.tick();
  SCOPED_TRACE("cur " + std::to_string(c.cur) + " tgt " + std::to_string(c.tgt));
  EXPECT_EQ(m.get("R59"), c.result);
  EXPECT_EQ(m.get("Y0.0"), c.out);
}

// N = 16, the manual's settings (numbering from 1, shortest path, to the target, step count)
// and variations. Worked by hand from: base = in2; c = cur - base; t = tgt - base;
// fwd = (t - c) mod N; rev = (c - t) mod N; reverse = in3 && rev < fwd ...
TEST_P(NcRotHostExec, RotSixteenPositions) {
  auto m = load(kRot16);
  ASSERT_TRUE(m);
  const RotCase cases[] = {
      {{1, 1, 1, 0, 1}, 3, 7, 4, 0},   // c=2 t=6: fwd 4, rev 12 -> forward 4 steps
      {{1, 1, 1, 0, 1}, 2, 14, 4, 1},  // c=1 t=13: fwd 12, rev 4 -> reverse 4 steps
      {{1, 1, 1, 0, 1}, 1, 9, 8, 0},   // fwd 8 = rev 8: a tie goes forward
      {{1, 1, 0, 0, 1}, 2, 14, 12, 0}, // in3 = 0: always forward, 12 steps
      {{1, 1, 1, 0, 0}, 2, 14, 14, 1}, // position result: t' + base = 14
      {{1, 1, 1, 1, 0}, 2, 14, 15, 1}, // before the target in reverse: (13 + 1) mod 16 + 1
      {{1, 1, 1, 1, 1}, 2, 14, 3, 1},  // one step less
      {{0, 1, 1, 0, 1}, 2, 14, 99, 0}, // ACT = 0: nothing written, output 0
  };
  for (const RotCase &c : cases) runRot(*m, c);
}

// N = 8, numbering from 0.
TEST_P(NcRotHostExec, RotEightPositionsFromZero) {
  auto m = load(kRot8);
  ASSERT_TRUE(m);
  const RotCase cases[] = {
      {{1, 0, 1, 1, 0}, 0, 5, 6, 1},  // fwd 5, rev 3: reverse; before 5 is (5 + 1) mod 8 = 6
      {{1, 0, 0, 1, 0}, 0, 5, 4, 0},  // forward: before 5 is 4
      {{1, 0, 0, 1, 1}, 0, 5, 4, 0},  // forward 5 steps, one less = 4
      {{1, 0, 1, 1, 1}, 3, 3, 0, 0},  // at the target: steps max(0 - 1, 0) = 0
      {{1, 0, 1, 1, 0}, 3, 3, 2, 0},  // before 3 going forward is 2
      {{1, 0, 1, 0, 1}, 10, 1, 1, 1}, // positions taken mod N: fwd (1-10) mod 8 = 7, rev 1
  };
  for (const RotCase &c : cases) runRot(*m, c);
}

// Every host block with no host and with a host whose callbacks are all NULL: getters report
// "not available" (nothing written), notifications do nothing, NIXIE shows the raw value,
// MPGSET still writes GA[9], EVENT still writes its G bit.
constexpr const char *kAllHostBlocks = "LDT\nVARGET 1 1 0 R100\nLDT\nVARSET 1 1 0 R100\n"
                                       "LDT\nTOOL R40 R41 R42 R43\nOUT Y0.0\n"
                                       "LDT\nSPDA 0 0 R1 D2 P5\nLDT\nMPGSET 0 2 R7\nOUT Y0.1\n"
                                       "LDT\nNIXIE R23 0 Y37\nLDT\nEVENT 3\nLDT\nSAVEDATA\n"
                                       "LDT\nRTOMPG X40 0\nTEMPSEN 0 X15 0 P30\nLDT\nTOOLSET 0\n"
                                       "LDT\nTOOLCLR 0\nLDT\nTOOLUSE 0 R23\nLDT\nSUBAXEN 1\n";

void expectDefaults(Machine &m) {
  m.set("R100", 77);
  m.set("R42", 1);
  m.set("R43", 2);
  m.set("D2", 9);
  m.set("G2570", 4);
  m.set("R7", 10);
  m.set("G170", 5);
  m.set("G171", 6);
  m.set("R23", 0x95);
  m.set("F2570", 1000);
  m.tick();
  EXPECT_EQ(m.get("R100"), 77);
  EXPECT_EQ(m.get("R42"), 1);
  EXPECT_EQ(m.get("R43"), 2);
  EXPECT_EQ(m.get("Y0.0"), 0);
  EXPECT_EQ(m.get("D2"), 9);
  EXPECT_EQ(m.get("G2570"), 4);
  EXPECT_EQ(m.get("G169"), 10);
  EXPECT_EQ(m.get("G170"), 5);
  EXPECT_EQ(m.get("G171"), 6);
  EXPECT_EQ(m.get("Y0.1"), 1);
  EXPECT_EQ(m.get("Y37"), 0x95);
  EXPECT_EQ(m.get("G3040.3"), 1);
}

TEST_P(NcRotHostExec, NoHostGivesDefaults) {
  auto m = load(kAllHostBlocks);
  ASSERT_TRUE(m);
  ASSERT_EQ(m->state().host, nullptr);
  expectDefaults(*m);
}

TEST_P(NcRotHostExec, NullCallbacksGiveDefaults) {
  TestHost h;
  for (const char *cb :
       {"var_get", "var_set", "mpg_input", "mpg_delta", "temp_input", "event", "save_data",
        "tool_select", "tool_in_use", "tool_vector", "slave_home", "spindle_da", "nixie_encode"})
    ASSERT_TRUE(h.disable(cb)) << cb;
  auto m = loadNoInit(kAllHostBlocks);
  ASSERT_TRUE(m);
  h.attach(m->state());
  ASSERT_EQ(m->init(), uint32_t{LJ_FAULT_NONE});
  expectDefaults(*m);
  EXPECT_TRUE(h.calls().empty());
}

// Every Nc mnemonic in one program, pseudo-random inputs and F words each tick, a seeded
// TestHost per engine: the state (LJ_STATE_COMPARED_BYTES) and the call log after every tick
// must equal the interpreter's.
constexpr const char *kEveryNc =
    "LD X0.0\nMGET 0 3\nOUT Y1.0\nLD X0.1\nMACK 0 3\nLD X0.2\nTGET 0 R5\nOUT Y1.1\n"
    "LD X0.3\nTACK 0\nLD X0.4\nRTOMPG X40 1\nLD X0.5\nTEMPSEN 3 X41 1 P10\n"
    "LDP X0.6\nPARTCNT 1\nOUT Y1.2\nLD X0.7\nPARTCLR 1\nLD X1.0\nHEADSEN 20 0 D60\n"
    "LD X1.1\nVARGET 0 R8 2 D1\nOUT Y1.3\nLD X1.2\nVARSET 4 R9 1 D1\nLD X1.3\nTOOLSET 2\n"
    "LD X1.4\nTOOLCLR 2\nLD X1.5\nNIXIE D1 1 R20\nLD X1.6\nTOOLUSE R10 R11\n"
    "LD X1.7\nTOOLLIFE 1 2 R30\nLD X2.0\nTOOL R11 R12 R13 R14\nOUT Y1.4\n"
    "LD X2.1\nSPDA 0 1 R15 D3 P20\nLD X2.2\nSUBAXEN 7\nLD X2.3\nMPGSET 1 R16 R17\nOUT Y1.5\n"
    "LD X2.4\nLD X2.5\nLD X2.6\nLD X2.7\nLD X3.0\nROT 12 R18 R19 D4\nOUT Y1.6\n"
    "LD X3.1\nEVENT 200\nLD X3.2\nSAVEDATA\n";

void stimulate(uint32_t tick, lj_state &s) {
  uint32_t r = tick * 2654435761u + 12345u;
  auto next = [&r]() {
    r = r * 1664525u + 1013904223u;
    return r >> 8;
  };
  for (int x = 0; x < 4; ++x) s.img.X[x] = static_cast<uint8_t>(next());
  s.img.X[40] = static_cast<uint8_t>(next());
  static constexpr int16_t kCodes[] = {-1, 3, 12, 5};
  for (int k = 0; k <= 8; ++k) s.img.F[2608 + k] = kCodes[next() % 4];
  s.img.F[2572] = static_cast<int16_t>(next()); // channel 0 spindle 1 speed, low word
  s.img.R[8] = static_cast<uint8_t>(next() % 8);
  s.img.R[9] = static_cast<uint8_t>(next() % 8);
  s.img.R[12] = static_cast<uint8_t>(next() % 20);
  s.img.R[16] = static_cast<uint8_t>(next() % 40); // sometimes past axis 31
  s.img.R[18] = static_cast<uint8_t>(next() % 14);
  s.img.R[19] = static_cast<uint8_t>(next() % 14);
  s.img.G[3085] = static_cast<int16_t>(next());
}

TEST(NcCrossEngine, StatesAndCallLogsAgree) {
  std::optional<VerifiedProgram> prog = compileOrFail(kEveryNc);
  ASSERT_TRUE(prog);
  const std::vector<EngineFactory> &engines = registeredEngines();
  ASSERT_GE(engines.size(), 2u);
  std::vector<std::unique_ptr<Machine>> ms;
  std::vector<std::unique_ptr<TestHost>> hosts;
  for (const EngineFactory &e : engines) {
    ms.push_back(Machine::create(*prog, e));
    ASSERT_TRUE(ms.back()) << e.name;
    hosts.push_back(std::make_unique<TestHost>(20261125u));
    hosts.back()->attach(ms.back()->state());
    ASSERT_EQ(ms.back()->init(), uint32_t{LJ_FAULT_NONE});
  }
  size_t totalCalls = 0;
  for (uint32_t tick = 0; tick < 300; ++tick) {
    for (size_t k = 0; k < ms.size(); ++k) {
      stimulate(tick, ms[k]->state());
      ASSERT_EQ(ms[k]->tick(), uint32_t{LJ_FAULT_NONE});
    }
    for (size_t k = 1; k < ms.size(); ++k) {
      ASSERT_EQ(std::memcmp(&ms[0]->state(), &ms[k]->state(), LJ_STATE_COMPARED_BYTES), 0)
          << engines[k].name << " state differs after tick " << tick;
      ASSERT_EQ(hosts[0]->callText(), hosts[k]->callText())
          << engines[k].name << " call log differs after tick " << tick;
    }
  }
  totalCalls = hosts[0]->calls().size();
  EXPECT_GT(totalCalls, 1000u);              // the stimulus really exercises the host blocks
  EXPECT_GT(ms[0]->state().fault_index, 0u); // and MPGSET's range check
}

} // namespace
} // namespace lj::test

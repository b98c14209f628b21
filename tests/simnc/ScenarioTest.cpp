// End-to-end scenarios (issue 4 item 5) through `ladderjit run` and the simulated NC:
// examples/mcode_handshake (MGET/MACK) and examples/tool_change (TGET/TACK and a counter), on
// the interpreter and the JIT. Expected values are derived by hand from the program text, the
// handshake rules of hnc8-cnc-interface.md 1.6, the instruction resolutions of
// hnc8-functions-1.md / -2.md and the NC timing of docs/simulated-nc.md (reasoning inline).
#include "CliRunner.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

namespace lj::clitest {
namespace {

struct Expect {
  long long tick;
  const char *col;
  long long value;
};

std::vector<std::string> mcodeArgs(const char *engine) {
  return {"run",        sourcePath("examples/mcode_handshake.stl"),
          "--engine",   engine,
          "--ticks",    "25",
          "--stimulus", sourcePath("examples/mcode_handshake.stim"),
          "--watch",    "F2608,G2608,F2609,G2609,R0.0,G2570,F402.14,F402.15,Y0.0,Y0.1"};
}

std::vector<std::string> toolArgs(const char *engine) {
  return {"run",        sourcePath("examples/tool_change.stl"),
          "--engine",   engine,
          "--ticks",    "55",
          "--stimulus", sourcePath("examples/tool_change.stim"),
          "--watch",    "F2616,G2616,D5,D7,D6,R6.1,R6.2,C1,Y1.0"};
}

void check(const CliResult &r, size_t rows, const std::vector<Expect> &expects) {
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.err, "");
  ASSERT_EQ(lines(r.out).size(), rows + 1) << "header + ticks";
  for (const Expect &e : expects)
    EXPECT_EQ(csvValue(r.out, e.tick, e.col), e.value) << "tick " << e.tick << " " << e.col;
}

const std::vector<Expect> kMcode = {
    // Power-up: every M slot -1, the responses (G, the PLC's) zero; the spindle (axis 5)
    // stands: FA[2].15.
    {0, "F2608", -1},
    {0, "G2608", 0},
    {0, "F402.15", 1},
    {4, "R0.0", 0},
    // @5 M3: in slot 0 for the scan of tick 5; MGET -> R0.0, MOV 1000 G2570. Not acked yet.
    {5, "F2608", 3},
    {5, "R0.0", 1},
    {5, "G2570", 1000},
    {5, "G2608", -1},
    // Ramp 500/tick: 500 after tick 5, 1000 after tick 6, so FA[2].14 shows at tick 7.
    {6, "F402.14", 0},
    {6, "F402.15", 0},
    {7, "F402.14", 1},
    {7, "Y0.0", 1},
    // Tick 7: MACK 0 3 -> G2608 = 3; tick 8: the NC freed the slot and reset the response.
    {7, "G2608", 3},
    {8, "F2608", -1},
    {8, "G2608", -1},
    {8, "R0.0", 0},
    // @10 M8: acked in the same scan (coolant on), gone at tick 11.
    {10, "F2608", 8},
    {10, "G2608", 8},
    {10, "Y0.1", 1},
    {11, "F2608", -1},
    {11, "Y0.1", 1},
    // @20 M5 + M9: slots 0 and 1. M9 is acked at once (coolant off); M5 waits for zero speed.
    {20, "F2608", 5},
    {20, "F2609", 9},
    {20, "G2609", 9},
    {20, "Y0.1", 0},
    {20, "G2570", 0},
    {20, "Y0.0", 1},
    {21, "F2609", -1},
    {21, "G2609", -1},
    {21, "F2608", 5},
    {21, "Y0.0", 0},
    {21, "F402.15", 0},
    // 1000 -> 500 (after 20) -> 0 (after 21): zero speed at tick 22, MACK 0 5, free at 23.
    {22, "F402.15", 1},
    {22, "G2608", 5},
    {23, "F2608", -1},
    {23, "G2608", -1},
};

const std::vector<Expect> kTool = {
    // init: MOV 1 D7. No T code: F2616 = -1, TGET output 0, D5 untouched.
    {0, "D7", 1},
    {4, "F2616", -1},
    {4, "R6.1", 0},
    {4, "D5", 0},
    // @5 T4: D5 = 4; COIN 4 1 false -> INC D7 each tick: 2 (t5), 3 (t6), 4 (t7).
    {5, "D5", 4},
    {5, "R6.1", 1},
    {5, "D7", 2},
    {7, "D7", 4},
    {7, "R6.2", 0},
    // Tick 8: at the pocket -> D6 = 4, TACK (G2616 = 4), C1 counts its first rising edge.
    {8, "R6.2", 1},
    {8, "D6", 4},
    {8, "G2616", 4},
    {8, "C1", 1},
    {8, "Y1.0", 0},
    // Tick 9: the NC closed the T code and reset the response (1.6).
    {9, "F2616", -1},
    {9, "G2616", -1},
    {9, "R6.1", 0},
    // @20 T2: D7 5..12 (t20..t27), 13 -> wraps to 1 (t28), 2 (t29); at the pocket at t30.
    {20, "D7", 5},
    {27, "D7", 12},
    {28, "D7", 1},
    {29, "D7", 2},
    {29, "R6.2", 0},
    {30, "D6", 2},
    {30, "C1", 2},
    {30, "Y1.0", 1},
    {31, "F2616", -1},
    // @40 T3 (pocket 2 -> 3 at t40, reached t41); the ring counter wraps 2 -> 0.
    {40, "F2616", 3},
    {41, "D6", 3},
    {41, "C1", 0},
    {41, "Y1.0", 0},
    // T5 queued at 41: -1 for one tick (t42), then shown at t43; reached at t45.
    {42, "F2616", -1},
    {43, "F2616", 5},
    {43, "D7", 4},
    {45, "D6", 5},
    {45, "C1", 1},
    {46, "F2616", -1},
    // @50 X0.0: CTRC reset (level) -> C1 = 0.
    {49, "C1", 1},
    {50, "C1", 0},
};

TEST(Scenario, McodeHandshakeInterp) { check(runCli(mcodeArgs("interp")), 25, kMcode); }

TEST(Scenario, ToolChangeInterp) { check(runCli(toolArgs("interp")), 55, kTool); }

TEST(Scenario, BothScenariosOnTheJit) {
  for (auto args : {mcodeArgs("jit"), toolArgs("jit")}) {
    CliResult jit = runCli(args);
    args[3] = "interp";
    CliResult interp = runCli(args);
    EXPECT_EQ(jit.exitCode, 0) << jit.err;
    EXPECT_EQ(jit.out, interp.out) << args[1]; // bit for bit the interpreter's table
  }
  check(runCli(mcodeArgs("jit")), 25, kMcode);
}

TEST(Scenario, DumpHasTheNcObject) {
  std::string path = scratchDir() + "/tool.json";
  std::vector<std::string> args = toolArgs("interp");
  args.push_back("--dump");
  args.push_back(path);
  CliResult r = runCli(args);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  nlohmann::json j = nlohmann::json::parse(slurp(path));
  ASSERT_TRUE(j.contains("nc"));
  std::vector<std::pair<long long, std::string>> events;
  for (const auto &e : j["nc"]["events"]) events.push_back({e["tick"], e["what"]});
  // The NC logs each T code when requested and when acknowledged (ticks as above).
  auto has = [&](long long t, const char *what) {
    for (const auto &e : events)
      if (e.first == t && e.second == what) return true;
    return false;
  };
  EXPECT_TRUE(has(5, "tcode ch0 t4 requested"));
  EXPECT_TRUE(has(8, "tcode ch0 t4 done"));
  EXPECT_TRUE(has(30, "tcode ch0 t2 done"));
  EXPECT_TRUE(has(45, "tcode ch0 t5 done"));
  EXPECT_EQ(j["nc"]["channels"][0]["t_code"], -1);
  EXPECT_EQ(j["areas"]["D"][6], 5);
}

TEST(Scenario, BadNcCommandIsAUsageError) {
  std::string stim = writeScratch("bad.stim", "@1 nc.mcode ch=0\n");
  CliResult r = runCli({"run", sourcePath("examples/mcode_handshake.stl"), "--stimulus", stim});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find(stim + ":1: nc.mcode: missing m="), std::string::npos) << r.err;
}

} // namespace
} // namespace lj::clitest

// End-to-end tests of the `ladderjit` driver: exit codes (CLI.md: 0 clean, 1 program errors,
// 2 usage/IO), diagnostics, the watch table formats, --set, --params, --dump and faults.
#include "CliRunner.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <random>
#include <regex>

namespace lj::clitest {
namespace {

// A one-rung program: Y1.0 follows X1.0 (hnc8-core.md 4.2: LD pushes the bit, OUT writes ST0).
const char *kFollow = "LD X1.0\nOUT Y1.0\n";

int countMatches(const std::string &text, const std::regex &re) {
  return static_cast<int>(
      std::distance(std::sregex_iterator(text.begin(), text.end(), re), std::sregex_iterator()));
}

TEST(Usage, NoArgumentsOrUnknownCommandIsUsageError) {
  CliResult r = runCli({});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_FALSE(r.err.empty());
  r = runCli({"frobnicate"});
  EXPECT_EQ(r.exitCode, 2);
  r = runCli({"run"}); // PROGRAM is required
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("PROGRAM"), std::string::npos);
  r = runCli({"run", writeScratch("u.stl", kFollow), "--ticks", "many"});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("--ticks"), std::string::npos);
  // A negative count is a usage error, not 2^64 - 5 ticks.
  r = runCli({"run", writeScratch("u.stl", kFollow), "--engine", "interp", "--ticks", "-5"});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("--ticks: expected a non-negative integer, got '-5'"), std::string::npos)
      << r.err;
}

TEST(Usage, HelpExitsZero) {
  CliResult r = runCli({"--help"});
  EXPECT_EQ(r.exitCode, 0);
  for (const char *cmd : {"check", "run", "emit-llvm", "fuzz", "compile", "serve"})
    EXPECT_NE(r.out.find(cmd), std::string::npos) << cmd;
  r = runCli({"run", "--help"});
  EXPECT_EQ(r.exitCode, 0);
  for (const char *opt : {"--engine", "--ticks", "--period-ms", "--plc2-nvalue", "--set",
                          "--stimulus", "--watch", "--format", "--dump", "--params"})
    EXPECT_NE(r.out.find(opt), std::string::npos) << opt;
  // Every dialect and the extension that means it (CLI.md: PROGRAM's dialect by extension), in
  // the tool's description and --dialect's help; the help once named three of the four.
  for (const char *d : {"hnc8", ".stl", "fanuc", ".pmc", "iec", ".il", "classicladder", ".clp"})
    EXPECT_NE(r.out.find(d), std::string::npos) << d << "\n" << r.out;
  EXPECT_NE(runCli({"--help"}).out.find("ClassicLadder projects (.clp)"), std::string::npos);
}

TEST(Usage, ServeValidatesBeforeRunning) {
  std::string prog = writeScratch("na.stl", kFollow);
  // `compile` is available since issue 5 (docs/aot.md; tested in tests/aot), `serve` since
  // issue 6 (docs/serve.md; end to end in tests/runtime): a bad option exits 2 before it runs.
  CliResult r = runCli({"serve", prog, "--engine", "aot"});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("--engine"), std::string::npos) << r.err;
}

TEST(Check, CleanProgramExitsZeroSilently) {
  CliResult r = runCli({"check", writeScratch("clean.stl", kFollow)});
  EXPECT_EQ(r.exitCode, 0);
  EXPECT_EQ(r.err, "");
}

TEST(Check, WarningsOnlyExitZero) {
  // DIALECT.md 6: a double coil is a warning, not an error.
  std::string p = writeScratch("dc.stl", "LD X1.0\nOUT Y1.0\nLD X1.1\nOUT Y1.0\n");
  CliResult r = runCli({"check", p});
  EXPECT_EQ(r.exitCode, 0);
  EXPECT_TRUE(std::regex_search(r.err, std::regex(":4:[0-9]+: warning: ")))
      << "the second OUT (line 4) is the double coil\n"
      << r.err;
}

TEST(Check, ErrorsAreLocatedAndExitOne) {
  // DIALECT.md 6: unknown mnemonic and a bit beyond the element width are errors, all reported.
  std::string p = writeScratch("err.stl", "LD X1.0\nFOO Y1.0\nLD X1.8\nOUT Y1.0\n");
  CliResult r = runCli({"check", p});
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find(p + ":2:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(p + ":3:"), std::string::npos) << r.err;
  EXPECT_EQ(countMatches(r.err, std::regex(":[0-9]+:[0-9]+: error: ")), 2) << r.err;
  EXPECT_EQ(r.out, "");
}

TEST(Check, TenMistakes) {
  // tests/frontend/data/ten_mistakes.stl holds ten independent errors (front-end test data);
  // all of them are reported, each with file:line:col (DIALECT.md 6).
  std::string p = sourcePath("tests/frontend/data/ten_mistakes.stl");
  CliResult r = runCli({"check", p});
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_EQ(countMatches(r.err, std::regex("ten_mistakes\\.stl:[0-9]+:[0-9]+: error: ")), 10)
      << r.err;
}

TEST(Check, MissingFileIsUsageError) {
  CliResult r = runCli({"check", "/nonexistent/prog.stl"});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("/nonexistent/prog.stl"), std::string::npos);
}

TEST(Check, PrintDumpsTheVerifiedProgram) {
  CliResult r = runCli({"check", "--print", writeScratch("pr.stl", kFollow)});
  EXPECT_EQ(r.exitCode, 0);
  EXPECT_NE(r.out.find("X1.0"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("Y1.0"), std::string::npos) << r.out;
}

TEST(Check, RandomBytesGiveErrorsNotCrashes) {
  std::mt19937 rng(12345);
  for (int round = 0; round < 8; ++round) {
    std::string bytes(2048, '\0');
    for (char &c : bytes) c = static_cast<char>(rng() & 0xFF);
    std::string p = writeScratch("random" + std::to_string(round) + ".bin", bytes);
    CliResult r = runCli({"check", p});
    EXPECT_EQ(r.signal, 0) << p;
    EXPECT_EQ(r.exitCode, 1) << p << "\n" << r.err.substr(0, 500);
    EXPECT_NE(r.err.find("error:"), std::string::npos);
    r = runCli({"run", p, "--engine", "interp"});
    EXPECT_EQ(r.signal, 0) << p;
    EXPECT_EQ(r.exitCode, 1) << p;
  }
}

TEST(Run, CsvTable) {
  std::string prog = writeScratch("follow.stl", kFollow);
  std::string stim = writeScratch("follow.stim", "@1 X1.0=1\n@2 X1.0=0\n");
  CliResult r = runCli({"run", prog, "--engine", "interp", "--ticks", "3", "--stimulus", stim,
                        "--watch", "Y1.0,x001.0"});
  EXPECT_EQ(r.exitCode, 0) << r.err;
  // Column names exactly as written; ticks from 0; stimulus applied before its tick's scan.
  EXPECT_EQ(r.out, "tick,Y1.0,x001.0\n0,0,0\n1,1,1\n2,0,0\n");
}

TEST(Run, JsonlTableAndRepeatedWatch) {
  // MOV writes the source to the destination (hnc8-functions-2.md 2.1); D5 = -3 every tick.
  std::string prog = writeScratch("mov.stl", "LDT\nMOV -3 D5\nLD X1.0\nOUT Y1.0\n");
  CliResult r = runCli({"run", prog, "--engine", "interp", "--ticks", "2", "--format", "jsonl",
                        "--set", "X1.0=1", "--watch", "X1.0", "--watch", "D5,W0"});
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.out, "{\"tick\":0,\"X1.0\":1,\"D5\":-3,\"W0\":0}\n"
                   "{\"tick\":1,\"X1.0\":1,\"D5\":-3,\"W0\":0}\n");
  for (const std::string &line : lines(r.out)) EXPECT_TRUE(nlohmann::json::accept(line)) << line;
}

TEST(Run, SetIsAppliedBeforeInit) {
  // The init part copies X1 to D1; --set is applied before init (README "Simulation order").
  std::string prog = writeScratch("init.stl", "LDT\nMOV X1 D1\nIEND\nLD X1.3\nOUT Y0.0\n");
  CliResult r = runCli({"run", prog, "--engine", "interp", "--set", "X1=196", "--set", "X1.3=1",
                        "--watch", "D1,Y0.0,X1"});
  EXPECT_EQ(r.exitCode, 0) << r.err;
  // Both items in order: X1 = 196 = 0b11000100, then only bit 3 is set: 204. Init copies 204
  // to D1 (X is zero-extended, DIALECT.md 1); PLC1 copies X1.3 = 1 to Y0.0.
  EXPECT_EQ(r.out, "tick,D1,Y0.0,X1\n0,204,1,204\n");
}

TEST(Run, ParamsFile) {
  std::string prog = writeScratch("par.stl", "LDT\nMOV P12 D0\nLDT\nADD P0 P199 D1\n");
  std::string params = writeScratch("m.params", "# parameters\nP12=345\nP0=-5\nP199=0x10\n");
  CliResult r =
      runCli({"run", prog, "--engine", "interp", "--params", params, "--watch", "D0,D1,P12"});
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.out, "tick,D0,D1,P12\n0,345,11,345\n");
}

TEST(Run, DumpIsCompleteJson) {
  // TMRB on-delay (docs/dialect-notes.md "Timers"): input on from tick 0, preset 5 ms, period
  // 2 ms: tick t has now = 2t, elapsed = 2t; at tick 3 elapsed 6 >= 5: out = 1, T3 = 5.
  std::string prog = writeScratch("dump.stl", "LD X0.0\nTMRB 3 0 5\nOUT Y0.1\nLDT\nMOV 7 B2\n");
  std::string dump = scratchDir() + "/state.json";
  CliResult r = runCli({"run", prog, "--engine", "interp", "--ticks", "4", "--period-ms", "2",
                        "--set", "X0.0=1", "--dump", dump});
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.out, ""); // no --watch: no table
  std::ifstream in(dump);
  nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
  ASSERT_FALSE(j.is_discarded()) << "the dump is valid JSON";
  EXPECT_EQ(j["now_ms"], 6);
  EXPECT_EQ(j["plc2_next_slice"], 0); // empty PLC2 = one slice
  EXPECT_EQ(j["areas"]["Y"][0], 2);   // Y0.1
  EXPECT_EQ(j["areas"]["X"][0], 1);
  EXPECT_EQ(j["areas"]["B"][2], 7);
  EXPECT_EQ(j["timers"][3]["n"], 3);
  EXPECT_EQ(j["timers"][3]["out"], 1);
  EXPECT_EQ(j["timers"][3]["elapsed_ms"], 5);
  EXPECT_EQ(j["timers"][3]["start_ms"], 0);
  EXPECT_EQ(j["faults"]["watchdog"], 0);
  for (const char *key : {"counters", "pls_prev", "plf_prev", "alt_prev", "alt_state", "edge"})
    EXPECT_TRUE(j.contains(key)) << key;
}

TEST(Run, WatchdogFaultIsReportedAndTheRunGoesOn) {
  // A backward JMP taken forever trips the watchdog (DIALECT.md 4): each faulted tick is
  // reported on stderr, the run continues; once X1.0 = 0 the loop ends and Y1.0 = 1.
  std::string prog = writeScratch("loop.stl", "LBL L1\nLD X1.0\nJMP L1\nLDT\nOUT Y1.0\n");
  std::string stim = writeScratch("loop.stim", "@2 X1.0=0\n");
  std::string dump = scratchDir() + "/loop.json";
  CliResult r = runCli({"run", prog, "--engine", "interp", "--ticks", "4", "--set", "X1.0=1",
                        "--max-backward-steps", "100", "--stimulus", stim, "--watch", "Y1.0",
                        "--dump", dump});
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.out, "tick,Y1.0\n0,0\n1,0\n2,1\n3,1\n");
  EXPECT_NE(r.err.find("tick 0: fault: watchdog"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("tick 1: fault: watchdog"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("tick 2:"), std::string::npos) << r.err;
  std::ifstream in(dump);
  nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_EQ(j["faults"]["watchdog"], 2);
  EXPECT_EQ(j["max_backward_steps"], 100);
}

struct BadRun {
  std::vector<std::string> extra;
  const char *message; // must appear on stderr
};

TEST(Run, UsageErrorsExitTwoWithAMessage) {
  std::string prog = writeScratch("ok.stl", kFollow);
  std::string badStim = writeScratch("bad.stim", "@0 X1.0=1\n\n@1 X1.9=1\n");
  std::string backStim = writeScratch("back.stim", "@5 X1.0=1\n@4 X1.0=0\n");
  std::string badParams = writeScratch("bad.params", "P1=2\nD3=4\n");
  std::vector<BadRun> cases = {
      {{"--watch", "X999"}, "bad address 'X999'"},
      {{"--watch", "X1.0,,Y1.0"}, "empty address"},
      {{"--watch", "Z1"}, "bad address 'Z1'"},
      {{"--set", "X1.0=2"}, "expected 0 or 1"},
      {{"--set", "D1=abc"}, "bad value 'abc'"},
      {{"--set", "D1"}, "expected ADDR=VALUE"},
      {{"--set", "T1=5"}, "cannot write timer 'T1'"},
      {{"--stimulus", "/nonexistent/s.stim"}, "cannot read '/nonexistent/s.stim'"},
      {{"--stimulus", badStim}, "bad.stim:3: bad address 'X1.9'"},
      {{"--stimulus", backStim}, "back.stim:2: tick 4 comes after tick 5"},
      {{"--params", badParams}, "bad.params:2: 'D3' is not a parameter"},
      {{"--params", "/nonexistent/p"}, "cannot read '/nonexistent/p'"},
      {{"--format", "xml"}, "--format"},
      {{"--engine", "llvm"}, "--engine"},
      {{"--engine", "aot:/nonexistent.so"}, "aot"},
      {{"--dump", "/nonexistent/dir/state.json"}, "cannot write '/nonexistent/dir/state.json'"},
  };
  for (const BadRun &c : cases) {
    std::vector<std::string> args = {"run", prog, "--engine", "interp"};
    args.insert(args.end(), c.extra.begin(), c.extra.end());
    CliResult r = runCli(args);
    EXPECT_EQ(r.exitCode, 2) << c.extra.back() << "\n" << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << "expected '" << c.message << "' in:\n"
                                                        << r.err;
    EXPECT_EQ(r.signal, 0);
  }
}

TEST(Run, ProgramWithErrorsExitsOne) {
  std::string prog = writeScratch("bad.stl", "LD X1.0\nOUT X1.1\n"); // X is read-only
  CliResult r = runCli({"run", prog, "--engine", "interp", "--watch", "Y1.0"});
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_TRUE(std::regex_search(r.err, std::regex("bad\\.stl:2:[0-9]+: error: "))) << r.err;
  EXPECT_EQ(r.out, "");
}

TEST(Run, Plc2NvalueSlicesPlc2) {
  // PLC2 of three rungs of two statements. docs/dialect-notes.md "PLC2 slicing": with
  // --plc2-nvalue 1 a slice ends at the first rung boundary after >= 1 statement, so each rung
  // is one slice and tick t runs rung t % 3; with 0 the whole PLC2 runs every tick.
  std::string prog =
      writeScratch("slices.stl", "1END\nLDT\nINC D0\nLDT\nINC D1\nLDT\nINC D2\n2END\n");
  CliResult r = runCli({"run", prog, "--engine", "interp", "--ticks", "4", "--plc2-nvalue", "1",
                        "--watch", "D0,D1,D2"});
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.out, "tick,D0,D1,D2\n0,1,0,0\n1,1,1,0\n2,1,1,1\n3,2,1,1\n");
  r = runCli({"run", prog, "--engine", "interp", "--ticks", "2", "--plc2-nvalue", "0", "--watch",
              "D0,D1,D2"});
  EXPECT_EQ(r.out, "tick,D0,D1,D2\n0,1,1,1\n1,2,2,2\n");
}

TEST(Run, StimulusBeyondTheLastTickIsAWarning) {
  std::string prog = writeScratch("late.stl", kFollow);
  std::string stim = writeScratch("late.stim", "@0 X1.0=1\n@10 X1.0=0\n");
  CliResult r = runCli(
      {"run", prog, "--engine", "interp", "--ticks", "2", "--stimulus", stim, "--watch", "Y1.0"});
  EXPECT_EQ(r.exitCode, 0);
  EXPECT_EQ(r.out, "tick,Y1.0\n0,1\n1,1\n");
  EXPECT_NE(r.err.find("late.stim:2: tick 10 is never reached"), std::string::npos) << r.err;
}

TEST(JitCommands, EmitLlvmAndFuzzRun) {
  std::string prog = writeScratch("emit.stl", kFollow);
  CliResult r = runCli({"emit-llvm", prog, "-O1"});
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("define "), std::string::npos) << "LLVM IR with a function";
  r = runCli({"emit-llvm", prog, "-O5"}); // CLI.md: -O0..-O3 only
  EXPECT_EQ(r.exitCode, 2);
  r = runCli({"emit-llvm", writeScratch("emit-bad.stl", "FOO\n")});
  EXPECT_EQ(r.exitCode, 1) << r.err;

  r = runCli({"fuzz", "--seed", "7", "--programs", "3", "--ticks", "5"});
  EXPECT_EQ(r.exitCode, 0) << r.out << r.err;
  EXPECT_FALSE(r.out.empty()) << "a summary";
}

} // namespace
} // namespace lj::clitest

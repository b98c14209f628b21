// `ladderjit dit` and plc.dit containers on the command line (docs/plc-dit.md "Command line"):
// a container runs exactly like its STL file with the same options, its parameters are defaults
// that options override, and a damaged container is a clear input error (exit 2).
#include "CliRunner.h"
#include "formats/PlcDit.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace lj::clitest {
namespace {

const std::vector<std::string> kLatheRun = {
    "--engine",   "interp",
    "--ticks",    "100",
    "--stimulus", sourcePath("examples/lathe_panel.stim"),
    "--watch",    "R0,G2620,G2564,Y480.0,Y480.2,Y480.3,Y0.0,Y0.1,G2622.0,Y0.2,R1"};

std::vector<std::string> cat(std::vector<std::string> a, const std::vector<std::string> &b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

CliResult ok(const std::vector<std::string> &args) {
  CliResult r = runCli(args);
  EXPECT_EQ(r.exitCode, 0) << r.err;
  return r;
}

// The example container is what `ladderjit dit` makes of the example files (docs "Writing").
TEST(DitCli, ExampleContainerIsFresh) {
  std::string out = scratchDir() + "/lathe_fresh.dit";
  ok({"dit", sourcePath("examples/lathe_panel.stl"), "--symbols",
      sourcePath("examples/lathe_panel.symbols"), "-o", out});
  EXPECT_EQ(slurp(out), slurp(sourcePath("examples/lathe_panel.dit")));
}

TEST(DitCli, ExampleContainerRunsLikeItsStl) {
  CliResult dit = ok(cat({"run", sourcePath("examples/lathe_panel.dit")}, kLatheRun));
  CliResult stl = ok(cat({"run", sourcePath("examples/lathe_panel.stl")}, kLatheRun));
  EXPECT_EQ(lines(dit.out).size(), 101u);
  EXPECT_EQ(dit.out, stl.out);
  EXPECT_EQ(dit.err, "");
  ok({"check", sourcePath("examples/lathe_panel.dit")});
}

// Replace whole operand tokens (preceded by a blank, followed by a blank, ';' or line end).
std::string replaceToken(std::string text, const std::string &from, const std::string &to) {
  size_t at = 0;
  while ((at = text.find(from, at)) != std::string::npos) {
    size_t end = at + from.size();
    bool before = at > 0 && (text[at - 1] == ' ' || text[at - 1] == '\t');
    bool after = end == text.size() || text[end] == ' ' || text[end] == '\n' || text[end] == ';';
    if (before && after) {
      text.replace(at, from.size(), to);
      at += to.size();
    } else {
      at = end;
    }
  }
  return text;
}

// Symbols in contacts (LDP/ANI), coils (OUT), blocks (WAND, COIN) and CALL/SP, in mixed case:
// the symbolic program behaves exactly like the one with addresses.
TEST(DitCli, SymbolicProgramRunsLikeTheAddresses) {
  std::string stl = slurp(sourcePath("examples/lathe_panel.stl"));
  for (auto [addr, name] :
       std::vector<std::pair<std::string, std::string>>{{"X484.5", "CW_KEY"},
                                                        {"X484.6", "stop_key"},
                                                        {"X483.0", "GUARD_OPEN"},
                                                        {"Y0.0", "CW_CONTACTOR"},
                                                        {"W0", "MODE_WORD"},
                                                        {"R1.0", "主轴正转"},
                                                        {"R1.1", "主轴反转"},
                                                        {"S1", "Clear_Modes"}})
    stl = replaceToken(stl, addr, name);
  ASSERT_NE(stl.find("COIN 2 MODE_WORD"), std::string::npos);
  ASSERT_NE(stl.find("CALL Clear_Modes"), std::string::npos);
  std::string src = writeScratch("symbolic.stl", stl);
  // Without its symbols the program does not even parse.
  EXPECT_EQ(runCli({"check", src}).exitCode, 1);
  std::string out = scratchDir() + "/symbolic.dit";
  ok({"dit", src, "--symbols", sourcePath("examples/lathe_panel.symbols"), "-o", out});
  CliResult dit = ok(cat({"run", out}, kLatheRun));
  CliResult stlRun = ok(cat({"run", sourcePath("examples/lathe_panel.stl")}, kLatheRun));
  EXPECT_EQ(dit.out, stlRun.out);
}

// docs "Command line": P values and period of the container are defaults.
TEST(DitCli, ContainerParamsAreDefaults) {
  std::string dit = scratchDir() + "/coolant.dit";
  std::string params = sourcePath("examples/coolant_lube.params");
  ok({"dit", sourcePath("examples/coolant_lube.stl"), "--params", params, "--period-ms", "10", "-o",
      dit});
  std::vector<std::string> common = {"--engine",   "interp",
                                     "--ticks",    "100",
                                     "--stimulus", sourcePath("examples/coolant_lube.stim"),
                                     "--watch",    "P10,P11,D10,D11,Y0.3,Y0.4,T2,T11"};
  std::string stl = sourcePath("examples/coolant_lube.stl");
  CliResult a = ok(cat({"run", dit}, common));
  CliResult b = ok(cat({"run", stl, "--params", params, "--period-ms", "10"}, common));
  EXPECT_EQ(a.out, b.out);
  // The container's P10=100 and P11=250 (examples/coolant_lube.params) are in place at tick 0.
  EXPECT_EQ(csvValue(a.out, 0, "P10"), 100);
  EXPECT_EQ(csvValue(a.out, 0, "P11"), 250);
  // --period-ms and --set override the container.
  CliResult c = ok(cat({"run", dit, "--period-ms", "1", "--set", "P10=40"}, common));
  CliResult d =
      ok(cat({"run", stl, "--params", params, "--period-ms", "1", "--set", "P10=40"}, common));
  EXPECT_EQ(c.out, d.out);
  EXPECT_NE(c.out, a.out);
  EXPECT_EQ(csvValue(c.out, 0, "P10"), 40);
  EXPECT_EQ(csvValue(c.out, 0, "P11"), 250);
  // --params overrides too: a file setting P11 only.
  std::string p11 = writeScratch("p11.params", "P11=30\n");
  CliResult e = ok(cat({"run", dit, "--params", p11}, common));
  EXPECT_EQ(csvValue(e.out, 0, "P10"), 100);
  EXPECT_EQ(csvValue(e.out, 0, "P11"), 30);
}

// The container's plc2_nvalue plans the PLC2 slices unless --plc2-nvalue is given.
TEST(DitCli, ContainerNvalueIsTheDefault) {
  std::string dit = scratchDir() + "/nv1.dit";
  std::string stl = sourcePath("examples/lathe_panel.stl");
  ok({"dit", stl, "--plc2-nvalue", "1", "-o", dit});
  CliResult a = ok(cat({"run", dit}, kLatheRun));
  CliResult one = ok(cat({"run", stl, "--plc2-nvalue", "1"}, kLatheRun));
  CliResult dflt = ok(cat({"run", stl}, kLatheRun));
  EXPECT_EQ(a.out, one.out);
  EXPECT_NE(a.out, dflt.out); // one PLC2 statement per tick delays the lamps
  CliResult b = ok(cat({"run", dit, "--plc2-nvalue", "200"}, kLatheRun));
  EXPECT_EQ(b.out, dflt.out);
}

std::string damaged(const std::string &name, const std::string &from, const std::string &to) {
  std::string t = slurp(sourcePath("examples/lathe_panel.dit"));
  size_t at = t.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) t.replace(at, from.size(), to);
  return writeScratch(name, t);
}

// docs "Command line": a container that cannot be read is an input error, exit 2.
TEST(DitCli, DamagedContainersExit2) {
  std::string edited = damaged("edited.dit", "OUT Y0.0", "OUT Y0.1");
  CliResult r = runCli({"check", edited});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find(edited + ":2: content hash does not match: file was modified or truncated"),
            std::string::npos)
      << r.err;
  std::string full = slurp(sourcePath("examples/lathe_panel.dit"));
  std::string cut = writeScratch("cut.dit", full.substr(0, full.size() / 2));
  r = runCli({"run", cut, "--engine", "interp"});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("truncated file"), std::string::npos) << r.err;
  EXPECT_EQ(r.out, "");
  std::string v2 = damaged("v2.dit", "ladderjit-plc-dit 1", "ladderjit-plc-dit 2");
  r = runCli({"check", v2});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find(v2 + ":1: unsupported plc.dit version 2"), std::string::npos) << r.err;
  // Named .dit without the magic line: a damaged container, not STL (docs "Detection").
  std::string noMagic = damaged("nomagic.dit", "ladderjit-plc-dit 1", "ladderjit plc dit 1");
  r = runCli({"check", noMagic});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find(noMagic + ":1: wrong magic"), std::string::npos) << r.err;
}

// Errors of the program inside a valid container: exit 1, located in the container.
TEST(DitCli, ProgramErrorsInAContainerExit1) {
  std::string body = "ladderjit-plc-dit 1\n[params]\nplc2_nvalue = 200\nperiod_ms = 1\n"
                     "[symbols]\nSTART X1.0\n[program]\nLD START\nOUT LAMP\n[end]\n";
  std::string text =
      body.substr(0, 20) + "hash = " + formats::sha256Hash(body) + "\n" + body.substr(20);
  std::string path = writeScratch("bad_program.dit", text);
  CliResult r = runCli({"check", path});
  EXPECT_EQ(r.exitCode, 1);
  // Line 10 of the container: magic, hash, 3 params lines, 2 symbols lines, [program], LD, OUT.
  EXPECT_EQ(r.err, path + ":10:5: error: unknown symbol 'LAMP' [LJ3004]\n");
}

TEST(DitCli, DitRefusesBadInputs) {
  std::string out = scratchDir() + "/never.dit";
  std::string bad = writeScratch("bad.stl", "LD START\nOUT Y0.0\n");
  CliResult r = runCli({"dit", bad, "-o", out});
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find(bad + ":1:4: error: unknown symbol 'START'"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out));
  std::string syms = writeScratch("bad.symbols", "# ok\nSTART X1.0\nSTART X2.0\n");
  r = runCli({"dit", bad, "--symbols", syms, "-o", out});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find(syms + ":3: duplicate symbol 'START'"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(out));
  std::string bracket = writeScratch("bracket.stl", "LD X1.0\n[x]\n");
  r = runCli({"dit", bracket, "-o", out});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find(bracket + ":2: a line starting with '['"), std::string::npos) << r.err;
  r = runCli({"dit", sourcePath("examples/lathe_panel.stl")});
  EXPECT_EQ(r.exitCode, 2) << "-o is required";
}

} // namespace
} // namespace lj::clitest

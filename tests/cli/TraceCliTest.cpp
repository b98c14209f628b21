// Issue 32 on the command line: `run --vcd` (its file and its usage errors; the round trip of
// every example through sigrok-cli is tests/cli/vcd_sigrok.py) and item 6, the noise: outside
// `check`, the verifier's warnings are one line with their count and the command that lists
// them, and --quiet drops even that.
#include "CliRunner.h"

#include <gtest/gtest.h>

namespace lj::clitest {
namespace {

// 68 shared timers (the realistic 10k program's count): each second TMRB of a number warns
// "timer Tn is also used on line m; both instructions share its state" (verify/StateSlots.cpp).
std::string sharedTimers(int n) {
  std::string text;
  for (int i = 0; i < n; ++i) {
    const std::string t = std::to_string(i);
    text += "LD X0.0\nTMRB " + t + " 0 100\nLD X0.1\nTMRB " + t + " 1 2\n";
  }
  return text + "LD X1.0\nOUT Y1.0\n";
}

size_t count(const std::string &text, const std::string &what) {
  size_t n = 0;
  for (size_t p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
  return n;
}

TEST(TraceCli, WarningsAreOneLineOutsideCheck) {
  const std::string prog = writeScratch("noisy.stl", sharedTimers(68));
  const std::string line =
      "ladderjit: " + prog + ": 68 verifier warnings; `ladderjit check " + prog + "` lists them\n";
  CliResult r = runCli({"run", prog, "--engine", "interp", "--ticks", "2", "--watch", "Y1.0"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.err, line);
  EXPECT_EQ(lines(r.out).size(), 3u) << "the table is unchanged";
  r = runCli({"run", prog, "--engine", "interp", "--quiet"});
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.err, "");
  r = runCli({"ladder", prog});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.err, line);
  r = runCli({"ladder", prog, "--quiet"});
  EXPECT_EQ(r.err, "");
  // bench too (its table goes to stdout), and --quiet drops the line.
  r = runCli({"bench", prog, "--engine", "interp", "--scans", "5"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.err, line);
  r = runCli({"bench", prog, "--engine", "interp", "--scans", "5", "--quiet"});
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.err, "");
  // With --dialect, the command that lists them says it too.
  r = runCli({"run", prog, "--dialect", "hnc8", "--engine", "interp"});
  EXPECT_NE(r.err.find("`ladderjit check --dialect hnc8 " + prog + "`"), std::string::npos)
      << r.err;
  // check lists every one of them.
  r = runCli({"check", prog});
  EXPECT_EQ(r.exitCode, 0);
  EXPECT_EQ(count(r.err, ": warning: timer T"), 68u) << r.err;
  // One warning is "1 verifier warning".
  const std::string one = writeScratch("one.stl", sharedTimers(1));
  r = runCli({"run", one, "--engine", "interp"});
  EXPECT_EQ(r.err, "ladderjit: " + one + ": 1 verifier warning; `ladderjit check " + one +
                       "` lists them\n");
  // A program with errors still shows everything, warnings included.
  const std::string bad = writeScratch("bad.stl", sharedTimers(2) + "OUT\n");
  r = runCli({"run", bad, "--engine", "interp"});
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_EQ(count(r.err, ": warning: timer T"), 2u) << r.err;
  EXPECT_NE(r.err.find(": error:"), std::string::npos) << r.err;
}

TEST(TraceCli, ServePrintsTheCountOnce) {
  const std::string prog = writeScratch("noisy-serve.stl", sharedTimers(68));
  const std::string sock = scratchDir() + "/noisy.sock";
  CliResult r = runCli({"serve", prog, "--engine", "interp", "--duration", "1", "--control", sock});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(count(r.err, "68 verifier warnings; `ladderjit check " + prog + "` lists them"), 1u)
      << r.err;
  EXPECT_EQ(count(r.err, "warning: timer"), 0u) << r.err;
  r = runCli(
      {"serve", prog, "--engine", "interp", "--duration", "1", "--control", sock, "--quiet"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(count(r.err, "verifier warning"), 0u) << r.err;
}

TEST(TraceCli, RunVcdWritesTheWatchAddresses) {
  const std::string prog =
      writeScratch("vcd.stl", "LD X1.0\nOUT Y1.0\nLDT\nADD D1 1 D1\n1END\n2END\n");
  const std::string stim = writeScratch("vcd.stim", "@2 X1.0=1\n@3 X1.0=0\n");
  const std::string vcd = scratchDir() + "/out.vcd";
  CliResult r = runCli({"run", prog, "--engine", "interp", "--ticks", "4", "--period-ms", "10",
                        "--stimulus", stim, "--watch", "Y1.0,D1", "--vcd", vcd});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  // Y1.0 follows X1.0 (1 at tick 2 only); D1 counts the ticks (1..4); 10 ms ticks: "10ms".
  EXPECT_EQ(slurp(vcd), "$version ladderjit $end\n"
                        "$comment ladderjit run " +
                            prog +
                            " $end\n"
                            "$timescale 10ms $end\n"
                            "$scope module ladderjit $end\n"
                            "$var wire 1 ! Y1.0 $end\n"
                            "$var wire 32 \" D1 $end\n"
                            "$upscope $end\n"
                            "$enddefinitions $end\n"
                            "#0\n0!\nb1 \"\n#1\nb10 \"\n#2\n1!\nb11 \"\n#3\n0!\nb100 \"\n#4\n");
  r = runCli({"run", prog, "--engine", "interp", "--ticks", "2", "--watch", "D1", "--vcd", vcd,
              "--vcd-bits"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(slurp(vcd).find("$var wire 1 ! D1[0] $end\n"), std::string::npos);
  EXPECT_NE(slurp(vcd).find("$var wire 1 @ D1[31] $end\n"), std::string::npos);
  // Usage errors exit 2 before anything runs.
  r = runCli({"run", prog, "--engine", "interp", "--vcd", vcd});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("--vcd: records the --watch addresses"), std::string::npos) << r.err;
  r = runCli({"run", prog, "--engine", "interp", "--watch", "D1", "--vcd", "-"});
  EXPECT_EQ(r.exitCode, 2);
  r = runCli({"run", prog, "--engine", "interp", "--watch", "D1", "--vcd-bits"});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("--vcd-bits needs --vcd FILE"), std::string::npos) << r.err;
  r = runCli({"run", prog, "--engine", "interp", "--watch", "D1", "--vcd", scratchDir()});
  EXPECT_EQ(r.exitCode, 2) << "a directory is not replaced";
}

} // namespace
} // namespace lj::clitest

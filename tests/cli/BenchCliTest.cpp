// `ladderjit bench` (docs/bench.md) and the progress line of `bench` / `fuzz`: output structure,
// the JSON schema, option errors, the C baseline's subset, and the progress line appearing on a
// terminal only. No timing is asserted (the machine is shared); only structure and order
// relations that hold for any timing (min <= median <= p99).
#include "CliRunner.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <pty.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <set>

namespace lj::clitest {
namespace {

// AOT lanes sign with the default key: keep it in the scratch directory, not the user's.
class Bench : public ::testing::Test {
protected:
  void SetUp() override { ::setenv("LADDERJIT_KEY_DIR", (scratchDir() + "/keys").c_str(), 1); }
};

const char *kCore = "LD X1.0\nOR Y1.0\nANI X1.1\nOUT Y1.0\n"
                    "LD X2.0\nMOV F10 D3\nLD X2.1\nADD D3 7 D4\nLD X2.2\nCMP D4 100\nOUT R5.1\n";

TEST_F(Bench, TextReportHasEverySection) {
  CliResult r = runCli({"bench", sourcePath("examples/lathe_panel.stl"), "--scans", "50"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  // stderr is not a terminal: no progress line (a first run may say it created the key pair).
  EXPECT_EQ(r.err.find('\r'), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("bench:"), std::string::npos) << r.err;
  for (const char *s :
       {"front end: read", "parse", "verify", "compile (wall)", "lower", "optimize", "codegen",
        "link", "cache", "code bytes", "full scan", "median", "p99", "ratios of median scan times",
        "jit-opt/interp", "aot/jit-opt", "jit-opt/jit-fast",
        "final states: every engine equals the interpreter after 50 scans"})
    EXPECT_NE(r.out.find(s), std::string::npos) << s << "\n" << r.out;
  for (const char *lane : {"\n  interp ", "\n  jit-fast ", "\n  jit-opt ", "\n  aot "})
    EXPECT_NE(r.out.find(lane), std::string::npos) << lane;
}

TEST_F(Bench, JsonSchema) {
  CliResult r = runCli(
      {"bench", sourcePath("examples/lathe_panel.stl"), "--scans", "40", "--format", "json"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["schema"], "ladderjit-bench 1");
  EXPECT_EQ(j["scans"], 40);
  EXPECT_EQ(j["inputs"], "random");
  EXPECT_GT(j["statements"].get<int>(), 0);
  for (const char *k : {"read_us", "parse_us", "verify_us"})
    EXPECT_TRUE(j["front_end"][k].is_number()) << k;
  std::vector<std::string> names;
  for (const auto &e : j["engines"]) {
    names.push_back(e["name"]);
    const auto &s = e["scan_ns"];
    EXPECT_LE(s["min"].get<double>(), s["median"].get<double>());
    EXPECT_LE(s["median"].get<double>(), s["p99"].get<double>());
    EXPECT_EQ(e["state_matches_interp"], true);
    if (e["engine"] == "interp") continue;
    for (const char *k : {"lower_us", "optimize_us", "codegen_us", "link_us", "cache_us", "load_us",
                          "total_us", "code_bytes", "cache_hit"})
      EXPECT_TRUE(e["compile"].contains(k)) << k;
    EXPECT_GT(e["compile"]["code_bytes"].get<uint64_t>(), 0u);
    EXPECT_EQ(e["compile"]["cache_hit"], false); // the cache is off unless --cache
  }
  EXPECT_EQ(names, (std::vector<std::string>{"interp", "jit-fast", "jit-opt", "aot"}));
  for (const char *k :
       {"jit-fast/interp", "jit-opt/interp", "aot/interp", "jit-opt/jit-fast", "aot/jit-opt"})
    EXPECT_TRUE(j["ratios"][k].is_number()) << k;
}

TEST_F(Bench, EngineAndTierSelectLanes) {
  CliResult r = runCli({"bench", sourcePath("examples/lathe_panel.stl"), "--scans", "10",
                        "--engine", "jit", "--tier", "fast", "--format", "json"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  nlohmann::json j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["engines"].size(), 2u); // the interpreter always runs: it is the reference
  EXPECT_EQ(j["engines"][0]["name"], "interp");
  EXPECT_EQ(j["engines"][1]["name"], "jit-fast");
  EXPECT_EQ(j["ratios"].size(), 1u);
}

TEST_F(Bench, StimulusFileDrivesTheInputs) {
  CliResult r =
      runCli({"bench", sourcePath("examples/lathe_panel.stl"), "--scans", "30", "--engine",
              "interp", "--stimulus", sourcePath("examples/lathe_panel.stim"), "--format", "json"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(nlohmann::json::parse(r.out)["inputs"], "stimulus");
}

TEST_F(Bench, OptionErrorsAreUsageErrors) {
  const std::string p = sourcePath("examples/lathe_panel.stl");
  struct Case {
    std::vector<std::string> args;
    const char *message;
  } cases[] = {
      {{"--engine", "fast"}, "--engine: expected interp, jit, aot or all, got 'fast'"},
      {{"--tier", "o2"}, "--tier: expected fast, opt or both, got 'o2'"},
      {{"--format", "csv"}, "--format: expected text or json, got 'csv'"},
      {{"--scans", "0"}, "--scans: expected 1..10000000, got 0"},
      {{"--scans", "-3"}, "--scans"},
      {{"--engine", "aot", "--tier", "fast"}, "aot has only the optimizing tier"},
      {{"--stimulus", "/nonexistent/x.stim"}, "/nonexistent/x.stim"},
      {{"--c-timeout", "0"}, "--c-timeout"},
  };
  for (const Case &c : cases) {
    std::vector<std::string> args{"bench", p};
    args.insert(args.end(), c.args.begin(), c.args.end());
    CliResult r = runCli(args);
    EXPECT_EQ(r.exitCode, 2) << c.message;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
    EXPECT_EQ(r.out, "");
  }
  CliResult r = runCli({"bench", "/nonexistent/p.stl"});
  EXPECT_EQ(r.exitCode, 2);
  r = runCli({"bench", writeScratch("bad.stl", "LD X1.0\nFROB 1\n")});
  EXPECT_EQ(r.exitCode, 1); // program errors, as `check`
}

TEST_F(Bench, CBaselineRefusesWhatItCannotExpress) {
  CliResult r =
      runCli({"bench", writeScratch("jmp.stl", "LD X1.0\nJMP L1\nLD X1.1\nOUT Y1.0\nLBL L1\n"),
              "--c-baseline", "--scans", "5"});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("jmp.stl:2: 'JMP' is outside the C baseline's subset"), std::string::npos)
      << r.err;
}

// Every shape of the benchmark corpus (gen/ShapeCorpus.h), small: its C translation, the JIT
// and the AOT build end in the interpreter's state (bench exits 1 on any difference), so the
// C baseline does the same work as the engines on every shape.
TEST_F(Bench, CorpusShapesMatchTheInterpreter) {
  ASSERT_EQ(::access("/usr/bin/gcc", X_OK), 0) << "the C baseline needs /usr/bin/gcc";
  CliResult r = runCli({"bench", "--corpus", "--statements", "300", "--scans", "64", "--rounds",
                        "2", "--format", "json"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  nlohmann::json j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["shapes"].size(), 8u) << r.out;
  for (const auto &s : j["shapes"]) {
    EXPECT_TRUE(s["engines"].contains("jit-opt")) << s;
    EXPECT_TRUE(s["engines"].contains("aot")) << s;
    EXPECT_TRUE(s["engines"].contains("gcc-O2")) << s;
    EXPECT_FALSE(s["best_c"].get<std::string>().empty()) << s;
  }
}

TEST_F(Bench, CBaselineMatchesTheInterpreter) {
  ASSERT_EQ(::access("/usr/bin/gcc", X_OK), 0) << "the C baseline needs /usr/bin/gcc";
  CliResult r = runCli({"bench", writeScratch("core.stl", kCore), "--c-baseline", "--scans", "200",
                        "--engine", "interp", "--format", "json"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  nlohmann::json j = nlohmann::json::parse(r.out);
  std::set<std::string> names;
  for (const auto &e : j["engines"]) {
    names.insert(e["name"].get<std::string>());
    EXPECT_EQ(e["state_matches_interp"], true);
  }
  EXPECT_TRUE(names.count("gcc-O1") && names.count("gcc-O2")) << r.out;
}

/// Run `ladderjit args` on a pseudo-terminal; returns what it wrote there (stdout and stderr).
std::string runOnTerminal(const std::vector<std::string> &args) {
  int master = -1;
  pid_t pid = ::forkpty(&master, nullptr, nullptr, nullptr);
  if (pid == 0) {
    std::vector<char *> argv{const_cast<char *>(LADDERJIT_BIN)};
    for (const std::string &a : args) argv.push_back(const_cast<char *>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(LADDERJIT_BIN, argv.data());
    ::_exit(127);
  }
  std::string out;
  char buf[4096];
  for (;;) {
    ssize_t n = ::read(master, buf, sizeof buf);
    if (n <= 0) break; // EIO once the child has exited
    out.append(buf, static_cast<size_t>(n));
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  ::close(master);
  return out;
}

// A campaign of a few seconds: the progress line shows on a terminal and never in a pipe. The
// line starts after one second, so the terminal campaign grows until it runs longer than that
// (the check is never skipped on a fast machine).
TEST(FuzzProgress, OnlyOnATerminal) {
  auto argsFor = [](int programs) {
    return std::vector<std::string>{"fuzz", "--programs", std::to_string(programs), "--ticks",
                                    "20"};
  };
  CliResult r = runCli(argsFor(120));
  ASSERT_EQ(r.exitCode, 0) << r.out;
  EXPECT_EQ(r.err, "");
  EXPECT_EQ(r.out.find("fuzz: programs"), std::string::npos);
  std::string tty;
  double s = 0;
  for (int programs = 120; programs <= 120 * 64 && s < 1.5; programs *= 4) {
    auto t0 = std::chrono::steady_clock::now();
    tty = runOnTerminal(argsFor(programs));
    s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
  ASSERT_GE(s, 1.5) << "no campaign ran long enough for a progress line";
  EXPECT_NE(tty.find("fuzz: programs "), std::string::npos) << tty;
  EXPECT_NE(tty.find("mismatches 0"), std::string::npos) << tty;
  EXPECT_NE(tty.find("PASS"), std::string::npos) << tty;
}

} // namespace
} // namespace lj::clitest

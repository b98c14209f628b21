// `run --tier` (docs/serve.md "Tiering"): a run that starts on the interpreter and switches to
// the JIT tiers at pinned ticks prints the watch table and dump of an unswitched run, byte for
// byte; bad tier options are usage errors (exit 2) naming the option.
#include "CliRunner.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace lj::clitest {
namespace {

std::vector<std::string> latheRun(std::vector<std::string> extra, const std::string &dump) {
  std::vector<std::string> a = {"run",        sourcePath("examples/lathe_panel.stl"),
                                "--ticks",    "100",
                                "--stimulus", sourcePath("examples/lathe_panel.stim"),
                                "--watch",    "X484.5,X484.6,R0,G2620,Y0.0,Y0.1,G2622.0",
                                "--dump",     dump};
  a.insert(a.end(), extra.begin(), extra.end());
  return a;
}

TEST(Tier, SwitchedRunPrintsTheUnswitchedTable) {
  const std::string d0 = scratchDir() + "/tier_interp.json";
  CliResult ref = runCli(latheRun({"--engine", "interp"}, d0));
  ASSERT_EQ(ref.exitCode, 0) << ref.err;
  ASSERT_GT(lines(ref.out).size(), 100u);
  // Switches inside the stimulus (it acts from tick 0 on) and at the two tiers' boundaries.
  for (const std::vector<std::string> &tier : std::vector<std::vector<std::string>>{
           {"--tier", "interp-first", "--tier-switch-tick", "1"},
           {"--tier", "interp-first", "--tier-switch-tick", "37"},
           {"--tier", "interp-fast-opt", "--tier-switch-tick", "5,60"},
           {"--tier", "interp-fast-opt"}}) {
    const std::string d1 = scratchDir() + "/tier_switched.json";
    std::vector<std::string> extra = {"--engine", "jit"};
    extra.insert(extra.end(), tier.begin(), tier.end());
    CliResult r = runCli(latheRun(extra, d1));
    SCOPED_TRACE(tier[1] + (tier.size() > 2 ? " " + tier[3] : std::string()));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.out, ref.out);
    EXPECT_EQ(slurp(d1), slurp(d0));
    if (tier.size() > 2) { // pinned: stderr names the ticks
      EXPECT_NE(r.err.find("from tick " + tier[3].substr(0, tier[3].find(','))), std::string::npos)
          << r.err;
    }
  }
}

TEST(Tier, BadTierOptionsAreUsageErrors) {
  const std::string stl = sourcePath("examples/lathe_panel.stl");
  CliResult r = runCli({"run", stl, "--tier", "sometimes"});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("--tier: expected direct, interp-first or interp-fast-opt"),
            std::string::npos)
      << r.err;
  r = runCli({"run", stl, "--engine", "interp", "--tier", "interp-first"});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("needs --engine jit"), std::string::npos) << r.err;
  r = runCli({"run", stl, "--tier-switch-tick", "3"});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("--tier-switch-tick needs"), std::string::npos) << r.err;
  r = runCli({"run", stl, "--tier", "interp-first", "--tier-switch-tick", "3,4"});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("--tier-switch-tick: 2 ticks"), std::string::npos) << r.err;
  r = runCli({"run", stl, "--tier", "interp-fast-opt", "--tier-switch-tick", "9,4"});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("must not decrease"), std::string::npos) << r.err;
  r = runCli({"serve", stl, "--engine", "interp", "--tier", "interp-first", "--duration", "1"});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("needs --engine jit"), std::string::npos) << r.err;
}

// serve's default with --engine jit is interp-fast-opt: the statistics name the interpreter as
// the first engine, the switches (tick, engines) and the time to JIT speed
// (docs/serve.md "Time to first tick").
TEST(Tier, ServeStatisticsShowTheSwitches) {
  const std::string stats = scratchDir() + "/tier_stats.json";
  CliResult r = runCli({"serve", sourcePath("examples/lathe_panel.stl"), "--duration", "3",
                        "--stats", stats, "--control", scratchDir() + "/tier.sock"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("tier interp-fast-opt"), std::string::npos) << r.out;
  nlohmann::json j = nlohmann::json::parse(slurp(stats));
  const nlohmann::json &st = j["startup"];
  EXPECT_EQ(j["tier"], "interp-fast-opt");
  EXPECT_EQ(st["tiering"]["mode"], "interp-fast-opt");
  EXPECT_EQ(st["tiering"]["first_engine"], "interp");
  EXPECT_GT(st["first_tick_ms"].get<double>(), 0.0);
  EXPECT_GE(st["first_tick_ms"].get<double>(), st["ready_ms"].get<double>());
  // An 82-statement program compiles in milliseconds: both switches happen within 3 s.
  ASSERT_EQ(st["tiering"]["switch_count"], 2) << st.dump();
  const nlohmann::json &sw = st["tiering"]["switches"];
  EXPECT_EQ(sw[0]["from"], "interp");
  EXPECT_EQ(sw[0]["to"], "jit-fast");
  EXPECT_EQ(sw[1]["from"], "jit-fast");
  EXPECT_EQ(sw[1]["to"], "jit-opt");
  EXPECT_LE(sw[0]["tick"].get<uint64_t>(), sw[1]["tick"].get<uint64_t>());
  EXPECT_EQ(st["tiering"]["engine"], "jit-opt");
  EXPECT_EQ(st["tiering"]["time_to_jit_ms"], sw[0]["at_ms"]);
  EXPECT_GE(sw[0]["at_ms"].get<double>(), st["first_tick_ms"].get<double>());
  EXPECT_EQ(j["swaps"], 0); // tier switches are no online changes
  EXPECT_NE(r.out.find("engine switch interp -> jit-fast at tick"), std::string::npos) << r.out;
}

} // namespace
} // namespace lj::clitest

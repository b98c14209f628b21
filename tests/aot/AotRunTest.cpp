// AOT against the interpreter beyond the exec tests (which run AOT through the engine registry):
// a differential fuzzing batch, and the acceptance command on every example.
#include "tests/aot/AotTestUtil.h"

#include "engines/AotLoader.h"
#include "fuzz/Fuzz.h"
#include "ir/Engine.h"
#include "tests/support/EngineRegistry.h"

#include <gtest/gtest.h>

#include <atomic>
#include <sstream>

namespace lj::test::aot {
namespace {

TEST(AotFuzz, BatchMatchesTheInterpreter) {
  TempDir dir;
  std::atomic<int> built{0};
  fuzz::EngineFactory aot = [&](const VerifiedProgram &p, bool, std::string &error) {
    std::string so = dir.path("p" + std::to_string(built++) + ".so");
    std::unique_ptr<Engine> e;
    if (buildSo(p, so)) e = engines::loadAot(so, {testHash(p)}, testTrust(), error);
    std::remove(so.c_str());
    return e;
  };
  fuzz::FuzzOptions o;
  o.seed = 5; // any seed: the generated programs are valid by construction
  o.programs = 24;
  o.ticks = 40;
  o.minimize = false;
  std::ostringstream out;
  fuzz::FuzzStats st = fuzz::runWith(o, out, aot);
  EXPECT_EQ(st.programs, 24u) << out.str();
  EXPECT_EQ(st.failures(), 0u) << out.str();
  EXPECT_EQ(built.load(), 24);
}

struct Example {
  const char *program;
  const char *args;
  const char *watch;
};

class AotCli : public ::testing::TestWithParam<Example> {};

TEST_P(AotCli, CompiledExampleRunsExactlyLikeTheInterpreter) {
  // Issue 5 acceptance: `ladderjit compile X -o x.so && ladderjit run X --engine aot:x.so ...`
  // prints what `--engine interp` prints (watch table and complete final state).
  const Example &ex = GetParam();
  TempDir dir;
  std::string src = std::string(LADDERJIT_SOURCE_DIR) + "/examples/";
  std::string prog = src + ex.program, so = dir.path("x.so");
  std::string args = std::string(ex.args);
  for (size_t p; (p = args.find("EX/")) != std::string::npos;) args.replace(p, 3, src);
  int rc = 0;
  runCommand(cli() + " compile " + prog + " -o " + so, rc);
  ASSERT_EQ(rc, 0);
  std::string tail = " " + args + " --watch " + ex.watch + " --dump -";
  std::string interp = runCommand(cli() + " run " + prog + " --engine interp" + tail, rc);
  ASSERT_EQ(rc, 0);
  std::string aot = runCommand(cli() + " run " + prog + " --engine aot:" + so + tail, rc);
  ASSERT_EQ(rc, 0);
  EXPECT_GT(interp.size(), 1000u);
  EXPECT_EQ(aot, interp);

  // Another --plc2-nvalue needs another build (docs/aot.md "Program hash"): exit 2, and the
  // message names both nvalues (the examples' own is 200: no container sets another).
  std::string err =
      runCommand(cli() + " run " + prog + " --plc2-nvalue 7 --engine aot:" + so + " 2>&1", rc);
  EXPECT_EQ(rc, 2);
  EXPECT_NE(err.find("built from this program with plc2 nvalue 200, but plc2 nvalue 7 was asked "
                     "for"),
            std::string::npos)
      << err;
}

INSTANTIATE_TEST_SUITE_P(
    Examples, AotCli,
    ::testing::Values(
        Example{"part_counter.stl",
                "--ticks 100 --params EX/part_counter.params --stimulus EX/part_counter.stim",
                "G2579,Y481,B0,D41"},
        Example{"coolant_lube.stl",
                "--ticks 100 --period-ms 10 --params EX/coolant_lube.params --stimulus "
                "EX/coolant_lube.stim",
                "Y0,R10,T2,D10"},
        Example{"lathe_panel.stl", "--ticks 100 --stimulus EX/lathe_panel.stim", "Y0,R0,G2620"},
        Example{"lathe_panel.dit", "--ticks 100 --stimulus EX/lathe_panel.stim", "Y0,R0,G2620"}),
    [](const ::testing::TestParamInfo<Example> &info) {
      std::string n = info.param.program;
      for (char &c : n)
        if (c == '.') c = '_';
      return n;
    });

TEST(AotCliErrors, BadSharedObjectsExitWithTwo) {
  TempDir dir;
  std::string prog = std::string(LADDERJIT_SOURCE_DIR) + "/examples/part_counter.stl";
  std::string so = dir.path("x.so");
  int rc = 0;
  runCommand(cli() + " compile " + prog + " -o " + so, rc);
  ASSERT_EQ(rc, 0);
  std::string bytes = readBytes(so);
  writeBytes(dir.path("t.so"), bytes.substr(0, bytes.size() / 3));
  std::string err =
      runCommand(cli() + " run " + prog + " --engine aot:" + dir.path("t.so") + " 2>&1", rc);
  EXPECT_EQ(rc, 2);
  EXPECT_NE(err.find("ladderjit: error: --engine aot: '" + dir.path("t.so") + "'"),
            std::string::npos)
      << err;
  // Built from another program: the coolant example's .so for the part counter.
  std::string other = std::string(LADDERJIT_SOURCE_DIR) + "/examples/coolant_lube.stl";
  runCommand(cli() + " compile " + other + " -o " + dir.path("o.so"), rc);
  ASSERT_EQ(rc, 0);
  err = runCommand(cli() + " run " + prog + " --engine aot:" + dir.path("o.so") + " 2>&1", rc);
  EXPECT_EQ(rc, 2);
  EXPECT_NE(err.find("built from another program"), std::string::npos) << err;
  // compile usage errors: unknown --cpu, unwritable output.
  runCommand(cli() + " compile " + prog + " --cpu pentium -o " + so + " 2>&1", rc);
  EXPECT_EQ(rc, 2);
  runCommand(cli() + " compile " + prog + " -o " + dir.path("no/such/dir/x.so") + " 2>&1", rc);
  EXPECT_EQ(rc, 2);
  // --cpu generic builds a .so that runs the same.
  runCommand(cli() + " compile " + prog + " --cpu generic -o " + dir.path("g.so"), rc);
  ASSERT_EQ(rc, 0);
  std::string tail = " --ticks 100 --stimulus " + std::string(LADDERJIT_SOURCE_DIR) +
                     "/examples/part_counter.stim --dump -";
  std::string a =
      runCommand(cli() + " run " + prog + " --engine aot:" + dir.path("g.so") + tail, rc);
  EXPECT_EQ(rc, 0);
  EXPECT_EQ(a, runCommand(cli() + " run " + prog + " --engine interp" + tail, rc));
}

} // namespace
} // namespace lj::test::aot

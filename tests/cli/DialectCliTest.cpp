// `--dialect` on every command that takes PROGRAM (and fuzz): a dialect this build lacks, an
// unknown name and a `.pmc` / `.il` file are usage errors (exit 2) naming the dialect and the
// known ones; hnc8 and an unknown extension read HNC-8 STL as before (CLI.md, formats/Dialects.h).
#include "CliRunner.h"

#include <gtest/gtest.h>

namespace lj::clitest {
namespace {

const char *kFollow = "LD X1.0\nOUT Y1.0\n";
const char *kFanuc = "dialect 'fanuc' is not available in this build (known: hnc8, iec)";

bool says(const CliResult &r, const std::string &text) {
  return r.err.find(text) != std::string::npos;
}

TEST(Dialect, EveryProgramCommandRefusesAnUnavailableDialect) {
  const std::string stl = writeScratch("d.stl", kFollow);
  const std::string so = scratchDir() + "/d.so";
  const std::vector<std::vector<std::string>> commands = {
      {"check", stl},
      {"run", stl, "--engine", "interp"},
      {"emit-llvm", stl},
      {"compile", stl, "-o", so},
      {"ladder", stl},
      {"dit", stl, "-o", "-"},
      {"serve", stl, "--duration", "1"},
      {"fuzz", "--programs", "1"},
  };
  for (std::vector<std::string> args : commands) {
    args.push_back("--dialect");
    args.push_back("fanuc");
    CliResult r = runCli(args);
    EXPECT_EQ(r.exitCode, 2) << args[0] << ": " << r.err;
    EXPECT_TRUE(says(r, kFanuc)) << args[0] << ": " << r.err;
    args.back() = "cobol";
    r = runCli(args);
    EXPECT_EQ(r.exitCode, 2) << args[0] << ": " << r.err;
    EXPECT_TRUE(says(r, "unknown dialect 'cobol' (known: hnc8, iec)")) << args[0] << ": " << r.err;
  }
}

TEST(Dialect, Hnc8ByOptionOrExtensionRunsAsBefore) {
  const std::string stl = writeScratch("h.stl", kFollow);
  CliResult r = runCli({"check", stl, "--dialect", "hnc8"});
  EXPECT_EQ(r.exitCode, 0) << r.err;
  // DIALECT.md 3: LD X1.0 / OUT Y1.0 copies the input, with either choice of dialect.
  CliResult byExt =
      runCli({"run", stl, "--engine", "interp", "--set", "X1.0=1", "--watch", "Y1.0"});
  CliResult byOpt = runCli({"run", stl, "--engine", "interp", "--set", "X1.0=1", "--watch", "Y1.0",
                            "--dialect", "hnc8"});
  ASSERT_EQ(byExt.exitCode, 0) << byExt.err;
  ASSERT_EQ(byOpt.exitCode, 0) << byOpt.err;
  EXPECT_EQ(byExt.out, byOpt.out);
  EXPECT_EQ(csvValue(byOpt.out, 0, "Y1.0"), 1);
  // An unknown extension is HNC-8 STL, as before dialects existed.
  r = runCli({"check", writeScratch("h.prog", kFollow)});
  EXPECT_EQ(r.exitCode, 0) << r.err;
}

TEST(Dialect, PlannedExtensionsAreUsageErrorsUnlessTheOptionSaysOtherwise) {
  const std::string pmc = writeScratch("spindle.pmc", kFollow);
  CliResult r = runCli({"check", pmc});
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_TRUE(says(r, "spindle.pmc: a .pmc file is dialect 'fanuc', which is not available in "
                      "this build (known: hnc8, iec"))
      << r.err;
  // A .il file is IEC IL: STL text in it is not IL.
  r = runCli({"run", writeScratch("x.il", kFollow), "--engine", "interp"});
  EXPECT_NE(r.exitCode, 0) << r.err;
  EXPECT_TRUE(says(r, "x.il:1:4: error: LD: 'X1.0': expected an object")) << r.err;
  r = runCli({"check", pmc, "--dialect", "hnc8"});
  EXPECT_EQ(r.exitCode, 0) << r.err;
}

TEST(Dialect, LadderJsonNamesItsDialect) {
  const std::string stl = writeScratch("j.stl", kFollow);
  CliResult lad = runCli({"ladder", stl, "--format", "json"});
  ASSERT_EQ(lad.exitCode, 0) << lad.err;
  ASSERT_NE(lad.out.find("\"dialect\": \"hnc8\""), std::string::npos) << lad.out;
  CliResult r = runCli({"check", writeScratch("j.json", lad.out)});
  EXPECT_EQ(r.exitCode, 0) << r.err;
  std::string fanuc = lad.out;
  fanuc.replace(fanuc.find("\"dialect\": \"hnc8\""), 17, "\"dialect\": \"fanuc\"");
  r = runCli({"check", writeScratch("f.json", fanuc)});
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_TRUE(says(r, "f.json: ladder JSON: dialect 'fanuc' is not available in this build "
                      "(known: hnc8, iec)"))
      << r.err;
}

} // namespace
} // namespace lj::clitest

// `--dialect` on every command that takes PROGRAM (and fuzz): an unknown name is a usage error
// (exit 2) naming the known dialects (hnc8, fanuc, iec); a `.pmc` file is FANUC PMC text, a `.il`
// file IEC IL; hnc8 and an unknown extension read HNC-8 STL as before (CLI.md,
// pipeline/Dialects.h).
#include "CliRunner.h"

#include <gtest/gtest.h>

namespace lj::clitest {
namespace {

const char *kFollow = "LD X1.0\nOUT Y1.0\n";

bool says(const CliResult &r, const std::string &text) {
  return r.err.find(text) != std::string::npos;
}

TEST(Dialect, EveryProgramCommandRefusesAnUnknownDialect) {
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
    args.push_back("cobol");
    CliResult r = runCli(args);
    EXPECT_EQ(r.exitCode, 2) << args[0] << ": " << r.err;
    EXPECT_TRUE(says(r, "unknown dialect 'cobol' (known: hnc8, fanuc, iec, classicladder)"))
        << args[0] << ": " << r.err;
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

TEST(Dialect, ExtensionsChooseTheDialectUnlessTheOptionSaysOtherwise) {
  // A .pmc file is FANUC PMC text (docs/fanuc-pmc.md): HNC-8's LD is no PMC instruction.
  const std::string pmc = writeScratch("spindle.pmc", kFollow);
  CliResult r = runCli({"check", pmc});
  EXPECT_EQ(r.exitCode, 1) << r.err;
  EXPECT_TRUE(says(r, "spindle.pmc:1:1: error: unknown instruction 'LD'")) << r.err;
  // A .il file is IEC IL (docs/iec-il.md): STL text in it is not IL.
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
  std::string other = lad.out;
  other.replace(other.find("\"dialect\": \"hnc8\""), 17, "\"dialect\": \"cobol\"");
  r = runCli({"check", writeScratch("f.json", other)});
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_TRUE(says(
      r, "f.json: ladder JSON: unknown dialect 'cobol' (known: hnc8, fanuc, iec, classicladder)"))
      << r.err;
}

// A FANUC program's ladder JSON (CLI.md: accepted back as PROGRAM) carries its program text: the
// same JSON runs like the .pmc; an edited rung is printed as FANUC text (ladder::programText) and
// runs as edited; a JSON without its text is refused with the reason (docs/ladder-json.md
// "Other dialects").
TEST(Dialect, FanucLadderJsonIsReadBackThroughItsText) {
  const std::string pmc = writeScratch("and.pmc", "RD X0.0\nAND X0.1\nWRT Y0.0\nEND1\nEND2\nEND\n");
  CliResult lad = runCli({"ladder", pmc, "--format", "json"});
  ASSERT_EQ(lad.exitCode, 0) << lad.err;
  ASSERT_NE(lad.out.find("\"dialect\": \"fanuc\""), std::string::npos) << lad.out;
  ASSERT_NE(lad.out.find("\"source\": \"RD X0.0\\nAND X0.1\\nWRT Y0.0"), std::string::npos)
      << lad.out;
  const std::string json = writeScratch("and.json", lad.out);
  // Y0.0 = X0.0 AND X0.1 (fanuc-pmc.md 5): 1 only with both inputs on.
  for (const char *x1 : {"X0.1=0", "X0.1=1"}) {
    CliResult r =
        runCli({"run", json, "--engine", "jit", "--set", "X0.0=1", "--set", x1, "--watch", "Y0.0"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(csvValue(r.out, 0, "Y0.0"), x1[5] == '1' ? 1 : 0) << x1;
  }
  std::string edited = lad.out;
  edited.replace(edited.find("\"text\": \"X0.1\""), 16, "\"text\": \"X0.2\"");
  const std::string editedJson = writeScratch("edited.json", edited);
  // Y0.0 = X0.0 AND X0.2 now: X0.1 no longer matters.
  for (const char *x2 : {"X0.2=0", "X0.2=1"}) {
    CliResult r = runCli({"run", editedJson, "--engine", "jit", "--set", "X0.0=1", "--set",
                          "X0.1=0", "--set", x2, "--watch", "Y0.0"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(csvValue(r.out, 0, "Y0.0"), x2[5] == '1' ? 1 : 0) << x2;
  }
  CliResult r = runCli({"check", editedJson});
  EXPECT_EQ(r.exitCode, 0) << r.err;
  std::string bare = lad.out;
  const size_t at = bare.find("\"source\"");
  bare.erase(at, bare.find('\n', at) + 1 - at);
  r = runCli({"check", writeScratch("bare.json", bare)});
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_TRUE(says(r, "bare.json: a fanuc ladder JSON keeps its untouched rungs from the program "
                      "text it carries (\"source\", written by `ladderjit ladder --format json`); "
                      "this one has none"))
      << r.err;
}

// A control byte in a program (a NUL inside an operand) is shown escaped in its diagnostic and
// ends nothing: before, the FANUC and IEC front ends quoted it raw, the NUL cut the printed
// diagnostics there, and every later error was lost.
TEST(Dialect, ControlBytesInDiagnosticsAreEscaped) {
  using namespace std::string_literals; // the NUL stays in the text
  CliResult r =
      runCli({"check", writeScratch("nul.pmc", "RD X0.0\0x\nWRT Y0.0\nEND1\nEND2\nEND\n"s)});
  EXPECT_EQ(r.exitCode, 1) << r.err;
  EXPECT_TRUE(says(r, "nul.pmc:1:4: error: malformed address 'X0.0\\x00x'")) << r.err;
  EXPECT_TRUE(says(r, "nul.pmc:2:1: error: WRT without a logic line (start it with RD)")) << r.err;
  r = runCli({"check", writeScratch("nul.il", "LD %I0.0\0x\nST %Q0.0\n"s)});
  EXPECT_EQ(r.exitCode, 1) << r.err;
  EXPECT_TRUE(
      says(r, "nul.il:1:4: error: LD: '%I0.0\\x00x': expected a point number after the '.'"))
      << r.err;
  EXPECT_EQ(r.err.find('\0'), std::string::npos);
}

// A FANUC program by extension: run with FANUC addresses on --set / --watch (docs/fanuc-pmc.md
// "Addresses"); RD X0.0 / WRT Y0.0 copies the input bit.
TEST(Dialect, FanucProgramRunsWithFanucAddresses) {
  const std::string pmc = writeScratch("copy.pmc", "RD X0.0\nWRT Y0.0\nEND1\nEND2\nEND\n");
  CliResult r =
      runCli({"run", pmc, "--engine", "interp", "--set", "X0.0=1", "--watch", "Y0.0,Y0,D0:4"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(csvValue(r.out, 0, "Y0.0"), 1);
  EXPECT_EQ(csvValue(r.out, 0, "Y0"), 1);
  r = runCli({"run", pmc, "--engine", "interp", "--watch", "Y0.8"});
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_TRUE(says(r, "bad address 'Y0.8': bit out of range (0..7)")) << r.err;
  r = runCli({"run", pmc, "--engine", "interp", "--watch", "D9999:2"});
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_TRUE(says(r, "bad address 'D9999:2': element out of range (D0..D9999)")) << r.err;
}

} // namespace
} // namespace lj::clitest

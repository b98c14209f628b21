// The LLVM module (engines/LlvmBackend.h, docs/architecture.md "The LLVM module"): the driver
// does not link libLLVM, the module beside it does; a command that needs no compile runs without
// the module, and one that does fails with a usage error naming the module file when it is
// missing, not loadable or from another build.
#include "CliRunner.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

namespace lj::clitest {
namespace {

namespace fs = std::filesystem;

std::string ldd(const std::string &path) {
  std::string out;
  FILE *p = ::popen(("ldd '" + path + "' 2>&1").c_str(), "r");
  if (!p) return out;
  char buf[512];
  while (size_t n = std::fread(buf, 1, sizeof buf, p)) out.append(buf, n);
  ::pclose(p);
  return out;
}

std::string moduleBeside(const std::string &bin) {
  return (fs::path(bin).parent_path() / "libladderjit_llvm.so").string();
}

/// A copy of the driver alone in directory `name` of the scratch directory.
std::string lonelyDriver(const std::string &name) {
  fs::path dir = fs::path(scratchDir()) / name;
  fs::create_directories(dir);
  fs::copy_file(LADDERJIT_BIN, dir / "ladderjit", fs::copy_options::overwrite_existing);
  return (dir / "ladderjit").string();
}

const std::string kLathe = sourcePath("examples/lathe_panel.stl");

TEST(LlvmModule, DriverDoesNotLinkLibLlvmTheModuleDoes) {
  const std::string driver = ldd(LADDERJIT_BIN);
  ASSERT_NE(driver.find("libc.so"), std::string::npos) << driver; // ldd worked
  EXPECT_EQ(driver.find("libLLVM"), std::string::npos) << driver;
  const std::string module = moduleBeside(LADDERJIT_BIN);
  ASSERT_TRUE(fs::exists(module)) << module;
  EXPECT_NE(ldd(module).find("libLLVM"), std::string::npos);
}

TEST(LlvmModule, MissingModuleOnlyStopsWhatCompiles) {
  const std::string bin = lonelyDriver("nomodule");
  const std::string expected = moduleBeside(bin);
  CliResult interp = runBinary(bin, {"run", kLathe, "--engine", "interp", "--ticks", "3"});
  EXPECT_EQ(interp.exitCode, 0) << interp.err;
  CliResult check = runBinary(bin, {"check", kLathe});
  EXPECT_EQ(check.exitCode, 0) << check.err;
  const std::vector<std::vector<std::string>> needLlvm = {
      {"run", kLathe, "--engine", "jit", "--ticks", "3"},
      {"emit-llvm", kLathe},
      {"compile", kLathe, "-o", scratchDir() + "/nomodule/p.so"},
      {"bench", kLathe, "--engine", "jit", "--scans", "10"}};
  for (const std::vector<std::string> &args : needLlvm) {
    SCOPED_TRACE(args[0] + " " + args.back());
    CliResult r = runBinary(bin, args);
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find("ladderjit: error: "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("the LLVM module libladderjit_llvm.so is missing (looked for " + expected),
              std::string::npos)
        << r.err;
    EXPECT_TRUE(r.out.empty()) << r.out;
  }
  EXPECT_FALSE(fs::exists(scratchDir() + "/nomodule/p.so"));
}

TEST(LlvmModule, UnloadableModuleIsNamed) {
  const std::string bin = lonelyDriver("badmodule");
  const std::string module = moduleBeside(bin);
  std::ofstream(module) << "not a shared object\n";
  CliResult r = runBinary(bin, {"run", kLathe, "--engine", "jit", "--ticks", "3"});
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find("cannot load the LLVM module " + module + ": "), std::string::npos) << r.err;
}

TEST(LlvmModule, ModuleOfAnotherBuildIsRefused) {
  const std::string bin = lonelyDriver("othermodule");
  const std::string module = moduleBeside(bin);
  fs::copy_file(FAKE_LLVM_MODULE, module, fs::copy_options::overwrite_existing);
  CliResult r = runBinary(bin, {"emit-llvm", kLathe});
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find("the LLVM module " + module +
                       " belongs to another build of ladderjit "
                       "(module: 'ladderjit 0.0.0 build of another tree'"),
            std::string::npos)
      << r.err;
  EXPECT_TRUE(r.out.empty()) << r.out;
}

TEST(LlvmModule, ModuleBesideTheDriverRunsTheJit) {
  CliResult jit = runCli({"run", kLathe, "--engine", "jit", "--ticks", "20", "--watch", "Y0"});
  CliResult interp =
      runCli({"run", kLathe, "--engine", "interp", "--ticks", "20", "--watch", "Y0"});
  ASSERT_EQ(jit.exitCode, 0) << jit.err;
  ASSERT_EQ(interp.exitCode, 0) << interp.err;
  EXPECT_EQ(jit.out, interp.out);
  EXPECT_EQ(lines(jit.out).size(), 21u);
}

} // namespace
} // namespace lj::clitest

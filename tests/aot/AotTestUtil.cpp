// Helpers of the AOT tests (AotTestUtil.h).
#include "tests/aot/AotTestUtil.h"

#include "jit/Aot.h"
#include "jit/ObjectCache.h"
#include "tests/support/EngineRegistry.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sys/wait.h>
#include <vector>

namespace lj::test::aot {

TempDir::TempDir() {
  const char *base = std::getenv("TMPDIR");
  std::string templ = std::string(base && *base ? base : "/tmp") + "/ladderjit-aottest-XXXXXX";
  std::vector<char> buf(templ.begin(), templ.end());
  buf.push_back('\0');
  if (mkdtemp(buf.data())) dir_ = buf.data();
  EXPECT_FALSE(dir_.empty()) << "mkdtemp failed for " << templ;
}

TempDir::~TempDir() {
  std::error_code ec;
  if (!dir_.empty()) std::filesystem::remove_all(dir_, ec);
}

std::string testHash(const VerifiedProgram &prog) { return "sha256:" + jit::programDigest(prog); }

bool buildSo(const VerifiedProgram &prog, const std::string &soPath) {
  jit::AotOptions o;
  o.output = soPath;
  o.programHash = testHash(prog);
  o.plc2Nvalue = prog.plc2Nvalue;
  o.signingKey = &testSigningKey();
  std::string error;
  bool ok = jit::compileSharedObject(prog, o, error);
  EXPECT_TRUE(ok) << error;
  return ok;
}

std::string cli() {
  static TempDir keys; // this test process's default key pair, never the real ~/.config
  return "LADDERJIT_CACHE=off LADDERJIT_KEY_DIR=" + keys.path("keys") + " " + LADDERJIT_BINARY;
}

std::string runCommand(const std::string &cmd, int &exitCode) {
  std::string out;
  FILE *p = popen(cmd.c_str(), "r");
  if (!p) {
    exitCode = -1;
    return out;
  }
  std::array<char, 4096> buf{};
  size_t n = 0;
  while ((n = fread(buf.data(), 1, buf.size(), p)) > 0) out.append(buf.data(), n);
  int status = pclose(p);
  exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return out;
}

std::string readBytes(const std::string &path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

void writeBytes(const std::string &path, const std::string &bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

} // namespace lj::test::aot

// Shared helpers of the AOT tests: temp directories, building a .so from STL, running commands.
#pragma once

#include "ir/Program.h"

#include <string>

namespace lj::test::aot {

/// A fresh directory under $TMPDIR (or /tmp), removed with its contents at destruction.
class TempDir {
public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir &) = delete;
  TempDir &operator=(const TempDir &) = delete;
  std::string path(const std::string &name) const { return dir_ + "/" + name; }
  const std::string &dir() const { return dir_; }

private:
  std::string dir_;
};

/// The hash the tests give a .so built from `prog` (the registry's AOT engine uses the same).
std::string testHash(const VerifiedProgram &prog);

/// Build `prog` into `soPath` with `ladderjit compile`'s code path, signed by the test key
/// (tests/support/EngineRegistry.h); records a failure if it fails.
bool buildSo(const VerifiedProgram &prog, const std::string &soPath);

/// `ladderjit` with the object cache off and LADDERJIT_KEY_DIR in a temp directory of this
/// process (its default key pair is made by the first `compile`).
std::string cli();

/// Run a command through the shell and return its stdout; `exitCode` gets its exit status.
std::string runCommand(const std::string &cmd, int &exitCode);

std::string readBytes(const std::string &path);
void writeBytes(const std::string &path, const std::string &bytes);

} // namespace lj::test::aot

// Loading an AOT shared object built by `ladderjit compile` (docs/aot.md "Loading"): integrity
// and ELF checks before dlopen, then ABI version and program hash. Plain dlopen/dlsym, no LLVM.
#pragma once

#include "instructions/Engine.h"

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>

namespace lj::io {

/// Load `path` and check it is a ladderjit program of this ABI whose ljprog_hash() equals
/// `expectedHash`. Null with `error` set (one line, naming the file) on any problem: unreadable,
/// truncated, damaged (integrity trailer), not an ELF shared object for this machine, dlopen
/// failure, missing symbols, other ABI version or state size, other program.
std::unique_ptr<Engine> loadAot(const std::string &path, const std::string &expectedHash,
                                std::string &error);

} // namespace lj::io

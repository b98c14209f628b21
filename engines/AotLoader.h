// Loading an AOT shared object built by `ladderjit compile` (docs/aot.md "Loading"): integrity
// and ELF checks before dlopen, then ABI version and program hash. Plain dlopen/dlsym, no LLVM.
#pragma once

#include "instructions/Engine.h"
#include "io/PlcDit.h"

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>

namespace lj::io {

/// The program hash a .so carries (docs/aot.md "Program hash"). For a plc.dit built with its
/// own plc2_nvalue: the container's hash line. Otherwise SHA-256 over
/// `ladderjit-program 1\nplc2_nvalue = N\n` followed by `container = <dit hash>\n` (a container
/// with another nvalue) or `[program]\n` and the STL text with CR before LF dropped and a final
/// LF added (an STL file). `stl` is the STL file's text; ignored when `dit` is given.
std::string programHash(std::string_view stl, const DitFile *dit, int32_t plc2Nvalue);

/// Load `path` and check it is a ladderjit program of this ABI whose ljprog_hash() equals
/// `expectedHash`. Null with `error` set (one line, naming the file) on any problem: unreadable,
/// truncated, damaged (integrity trailer), not an ELF shared object for this machine, dlopen
/// failure, missing symbols, other ABI version or state size, other program.
std::unique_ptr<Engine> loadAot(const std::string &path, const std::string &expectedHash,
                                std::string &error);

} // namespace lj::io

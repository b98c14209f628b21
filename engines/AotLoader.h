// Loading an AOT shared object built by `ladderjit compile` (docs/aot.md "Loading"): signature,
// identity, ABI and ELF checks on the bytes read once, then dlopen of exactly those bytes.
#pragma once

#include "formats/PlcDit.h"
#include "ir/Engine.h"
#include "pipeline/ProgramFile.h"
#include "signing/AotTrust.h"

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <utility>

namespace lj::engines {

/// The program hash a .so carries: pipeline/ProgramFile.h programHash.

/// The program's identity without the nvalue: the container's hash line, or SHA-256 over
/// `ladderjit-source 1\n[program]\n` and the STL text canonicalized as for programHash. Lets the
/// loader tell "another program" from "this program with another plc2 nvalue".
std::string sourceHash(std::string_view stl, const formats::DitFile *dit);

/// What a caller expects a .so to be: the program hash, optionally the source hash and the
/// nvalue it plans with (for the message when only the nvalue differs).
struct AotExpect {
  AotExpect(std::string prog, std::string src = {}, int32_t nvalue = -1)
      : program(std::move(prog)), source(std::move(src)), plc2Nvalue(nvalue) {}
  std::string program;
  std::string source;      ///< empty: not known
  int32_t plc2Nvalue = -1; ///< < 0: not known
};
AotExpect aotExpectOf(const pipeline::ProgramSource &src, int32_t plc2Nvalue);

/// Load `path` if it is a ladderjit program signed by a key of `trust`, built for this ABI and
/// state layout from the expected program. Every check runs on the bytes read once from the
/// file, before any of them is mapped; the verified bytes are then dlopened from a sealed
/// memfd. Null with `error` set (one line, naming the file) on any problem.
std::unique_ptr<Engine> loadAot(const std::string &path, const AotExpect &expect,
                                const signing::TrustedKeys &trust, std::string &error);

} // namespace lj::engines

// PROGRAM as the CLI and serve take it: an STL file or a plc.dit container (recognized by its
// magic line), read, verified with the container's symbols, and hashed the way AOT .so files
// record it. One implementation for `check`/`run`/`compile`/`emit-llvm` and for serve's loader.
#pragma once

#include "instructions/Program.h"
#include "io/PlcDit.h"

#include <cstdint>
#include <optional>
#include <string>

namespace lj::io {

/// PROGRAM as read.
struct ProgramSource {
  std::string path;
  std::string text;           ///< what the STL parser reads (container: padded program)
  std::optional<DitFile> dit; ///< the container, when PROGRAM is one
  std::string fileHash;       ///< "sha256:..." of the file's bytes (serve's program identity)
};

/// Read PROGRAM into `src`. False (with `error`) for an unreadable file or a damaged container;
/// a `.dit` name without the magic line is a damaged container, not STL.
bool readProgramFile(const std::string &path, ProgramSource &src, std::string &error);

/// The PLC2 nvalue to plan with: the option when given, else the container's, else `option`.
int32_t effectiveNvalue(const ProgramSource &src, int32_t option, bool optionGiven);

/// Verify a read PROGRAM (with its symbols, for a container). `diagnostics` receives every
/// rendered diagnostic (warnings too). Nothing is returned when there are errors; then
/// `diagnostics` is never empty.
std::optional<VerifiedProgram> verifyProgram(const ProgramSource &src, int32_t plc2Nvalue,
                                             std::string &diagnostics);

/// The program hash an AOT .so built from `src` with `plc2Nvalue` carries (io/AotLoader.h).
std::string programHashOf(const ProgramSource &src, int32_t plc2Nvalue);

} // namespace lj::io

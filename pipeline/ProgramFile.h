// PROGRAM as the CLI and serve take it: an STL file or a plc.dit container (recognized by its
// magic line), read, verified with the container's symbols, and hashed the way AOT .so files
// record it. One implementation for `check`/`run`/`compile`/`emit-llvm` and for serve's loader.
#pragma once

#include "formats/PlcDit.h"
#include "ir/Program.h"
#include "ir/Status.h"
#include "pipeline/Dialects.h"

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

namespace lj::ladder {
struct StlFromJson;
struct Networks;
} // namespace lj::ladder

namespace lj::pipeline {

/// PROGRAM as read.
struct ProgramSource {
  std::string path;
  std::string text;                    ///< what the STL parser reads (container: padded program)
  std::optional<formats::DitFile> dit; ///< the container, when PROGRAM is one
  std::string fileHash; ///< "sha256:..." of the file's bytes (serve's program identity)
  /// A `.json` PROGRAM (ladder networks, docs/ladder-json.md): its symbols and line map; `text`
  /// is the STL made from it.
  std::shared_ptr<const ladder::StlFromJson> ladder;
  /// A `.json` PROGRAM of another dialect (FANUC, IEC): its networks, which must hold the
  /// statements of `text`: the program text it carries ("source") with the rungs the networks
  /// edited printed anew (docs/ladder-json.md "Other dialects").
  std::shared_ptr<const ladder::Networks> carried;
  /// `carried` networks were edited: `text` is the program text made from them
  /// (ladder::programText), not the "source" they carry.
  bool edited = false;
  /// The dialect it is written in (pipeline/Dialects.h): --dialect, else the extension, else
  /// the JSON's "dialect" member, else HNC-8.
  const Dialect *dialect = &defaultDialect();
};

/// Read PROGRAM into `src` (a `.json` name: ladder network JSON). `dialect`: the --dialect
/// option (empty: chosen by the file name, dialectForPath). An error whose message is the
/// whole line CLI.md prints: InvalidArgument for an unknown or unavailable dialect (or a JSON
/// of another dialect than --dialect), NotFound for an unreadable file, BadFormat for a damaged
/// container or network JSON, Rejected when a network JSON's carried program text does not
/// verify; a `.dit` name without the magic line is a damaged container, not STL. `bytes`, when
/// given, are the file's content (a ladder edit not yet written, runtime/EditSession.h): read
/// as if `path` held them.
Status readProgramFile(const std::string &path, ProgramSource &src, std::string_view dialect = {},
                       const std::string *bytes = nullptr);

/// The PLC2 nvalue to plan with: the option when given, else the container's, else `option`.
int32_t effectiveNvalue(const ProgramSource &src, int32_t option, bool optionGiven);

/// Verify a read PROGRAM (with its symbols, for a container). `diagnostics` receives every
/// rendered diagnostic (warnings too). Nothing is returned when there are errors; then
/// `diagnostics` is never empty. `warnings`, when given, receives the number of warnings (all
/// of them, also those past the cap on rendered lines).
std::optional<VerifiedProgram> verifyProgram(const ProgramSource &src, int32_t plc2Nvalue,
                                             std::string &diagnostics, size_t *warnings = nullptr);

/// The program hash a .so carries (docs/aot.md "Program hash"). For a plc.dit built with its
/// own plc2_nvalue: the container's hash line. Otherwise SHA-256 over
/// `ladderjit-program 1\nplc2_nvalue = N\n` followed by `container = <dit hash>\n` (a container
/// with another nvalue) or `[program]\n` and the STL text with CR before LF dropped and a final
/// LF added (an STL file). `stl` is the STL file's text; ignored when `dit` is given.
std::string programHash(std::string_view stl, const formats::DitFile *dit, int32_t plc2Nvalue);

/// The program hash an AOT .so built from `src` with `plc2Nvalue` carries (programHash).
std::string programHashOf(const ProgramSource &src, int32_t plc2Nvalue);

} // namespace lj::pipeline

// The dialect registry: one entry per dialect this build reads, and the choice of a PROGRAM's
// dialect (`--dialect NAME`, else the file's extension, else HNC-8 STL; CLI.md, docs/plc-dit.md,
// docs/ladder-json.md). A dialect is its front end, its target profile, and the address syntax
// of the command line, stimulus files, --watch and --dump.
#pragma once

#include "formats/Address.h"
#include "ir/Diagnostics.h"
#include "ir/Program.h"
#include "ir/Status.h"
#include "verify/Verify.h"

#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace lj::pipeline {

/// One dialect of this build.
struct Dialect {
  const char *name;                        ///< "hnc8", what --dialect and ladder JSON say
  std::span<const char *const> extensions; ///< PROGRAM file names that mean it (".stl")
  const TargetProfile *profile;            ///< the target its programs run on
  /// The front end alone: program text -> ParsedProgram (never fails as a whole).
  ParsedProgram (*parse)(std::string_view text, std::string file, Diagnostics &diags,
                         const SymbolTable *symbols);
  /// Parse and verify program text (symbols: a container's or a ladder JSON's, may be null).
  std::optional<VerifiedProgram> (*compile)(std::string_view text, std::string file,
                                            const VerifyOptions &opts, Diagnostics &diags,
                                            const SymbolTable *symbols);
  /// Command-line / stimulus / --watch / --dump addresses and `addr=value` items.
  std::optional<formats::CliAddress> (*parseAddress)(std::string_view text, std::string &error);
  std::optional<formats::Assignment> (*parseAssignment)(std::string_view item, std::string &error);
  std::string (*formatAddress)(const formats::CliAddress &addr);
  /// The front end's words and text (spelling, operand text, networks -> program text): what
  /// the ladder stage reads and writes the network JSON with.
  const DialectText &(*text)();
};

/// Every dialect of this build ("hnc8" first, the default).
std::span<const Dialect *const> allDialects();

/// The dialect called `name` (case-sensitive, as --dialect takes it), or nullptr.
const Dialect *dialectNamed(std::string_view name);

/// The default dialect (HNC-8): plc.dit containers and files with an unknown extension.
const Dialect &defaultDialect();

/// The dialect for --dialect `name`, or an InvalidArgument error: "dialect 'NAME' is not
/// available in this build (known: hnc8, fanuc, iec, classicladder)" for a dialect ladderjit plans
/// but this build lacks (none today: kPlanned is empty), "unknown dialect 'x' (known: ...)"
/// otherwise.
Result<const Dialect *> dialectForOption(std::string_view name);

/// The dialect PROGRAM `path` is written in, by its extension: `.stl` and `.dit` hnc8, `.pmc`
/// fanuc, `.il` iec, `.clp` classicladder; any other name is HNC-8 STL (as before dialects
/// existed). A `.json` file is not decided here: it names its dialect (dialectOfJson). An
/// InvalidArgument error when the extension's dialect is not in this build.
Result<const Dialect *> dialectForPath(std::string_view path);

/// The dialect a ladder JSON document names in its "dialect" member (docs/ladder-json.md), or an
/// InvalidArgument error "ladder JSON: unknown dialect ..." (missing member: the JSON reader
/// reports it; then hnc8 is returned).
Result<const Dialect *> dialectOfJson(std::string_view text);

/// All dialect names this build has, "hnc8, ..." (for messages and --help).
std::string knownDialects();

} // namespace lj::pipeline

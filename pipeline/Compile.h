// Program text -> verified program: a dialect's front end parses, the verifier checks
// (DIALECT.md 6). The one place where parse and verify meet, so no front end includes verify/
// and every command, the fuzzer, the benchmarks and the tests compile a program the same way.
// Every compile refuses a text with a line that ends in a CR alone (LJ0001) before its front end.
#pragma once

#include "ir/Diagnostics.h"
#include "ir/Program.h"
#include "verify/Verify.h"

#include <optional>
#include <string>
#include <string_view>

namespace lj::pipeline {

struct Dialect;

/// HNC-8 STL (DIALECT.md): parseStl (with `symbols`, may be null: a plc.dit's or a ladder
/// JSON's) + verify; nothing on any error. Parsing stops at the statement limit
/// (opts.maxStatements, else the profile's) and a program cut short there is not verified; the
/// verifier also runs on a program with parse errors, so one run reports both.
std::optional<VerifiedProgram> compileStl(std::string_view text, std::string file,
                                          const VerifyOptions &opts, Diagnostics &diags,
                                          const SymbolTable *symbols = nullptr);

/// FANUC PMC mnemonics (docs/fanuc-pmc.md): parsePmc (with `symbols`, may be null, checked
/// under FANUC's symbol rules) + verify; nothing on any error, and no verify after a parse error.
std::optional<VerifiedProgram> compilePmc(std::string_view text, std::string file,
                                          const VerifyOptions &opts, Diagnostics &diags,
                                          const SymbolTable *symbols = nullptr);

/// IEC IL (docs/iec-il.md): parseIl + verify; nothing on any error, and no verify after a parse
/// error. An IL program takes no symbol table: a non-empty `symbols` is an error.
std::optional<VerifiedProgram> compileIl(std::string_view text, std::string file,
                                         const VerifyOptions &opts, Diagnostics &diags,
                                         const SymbolTable *symbols = nullptr);

/// A ClassicLadder `.clp` project (docs/classicladder.md): classicladder::parseClp + verify;
/// nothing on any error, and no verify after a read error or a refused element. A project takes
/// no symbol table from outside (its symbols.csv is its own): a non-empty `symbols` is an error.
std::optional<VerifiedProgram> compileClp(std::string_view text, std::string file,
                                          const VerifyOptions &opts, Diagnostics &diags,
                                          const SymbolTable *symbols = nullptr);

/// Parse + verify in `dialect` (its Dialect::compile).
std::optional<VerifiedProgram> compile(const pipeline::Dialect &dialect, std::string_view text,
                                       std::string file, const VerifyOptions &opts,
                                       Diagnostics &diags, const SymbolTable *symbols = nullptr);

/// The front end of `dialect` alone (its Dialect::parse): never fails as a whole, bad lines
/// become diagnostics. For timing the stages apart (`bench`).
ParsedProgram parse(const pipeline::Dialect &dialect, std::string_view text, std::string file,
                    Diagnostics &diags, const SymbolTable *symbols = nullptr);

/// Human-readable dump of a verified program in its own dialect's spelling (one statement per
/// line with depth, slot, slice): `ladderjit check --print` and golden tests.
std::string printProgram(const VerifiedProgram &prog);

} // namespace lj::pipeline

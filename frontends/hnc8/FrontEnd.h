// The STL front end: text -> ParsedProgram -> VerifiedProgram, with located diagnostics.
#pragma once

#include "ir/Diagnostics.h"
#include "ir/Program.h"
#include "frontends/hnc8/Symbols.h"

#include <optional>
#include <string_view>

namespace lj {

/// Options the verifier plans with.
struct VerifyOptions {
  int32_t plc2Nvalue = 200;      ///< PLC2 statements per tick (0 = one slice)
  int32_t maxStatements = 10000; ///< program size limit (DIALECT.md 6)
  int32_t maxCallDepth = 32;     ///< nesting of CALL
};

/// Parse STL text (DIALECT.md 2). Never fails as a whole: bad lines become diagnostics and are
/// left out of the result.
ParsedProgram parseStl(std::string_view text, std::string file, Diagnostics &diags);

/// parseStl with symbols (docs/plc-dit.md "Symbols"): an operand token shaped like a name
/// (SymbolTable::isNameShaped) is replaced by its symbol's address, then checked like that
/// address; an unknown name is the error "unknown symbol 'NAME'". `symbols` may be null.
ParsedProgram parseStl(std::string_view text, std::string file, Diagnostics &diags,
                       const SymbolTable *symbols);

/// Check every rule of DIALECT.md 6 and compute stack depths, scopes, jump/call targets, state
/// slots and PLC2 slices. Returns nothing when an error was reported.
std::optional<VerifiedProgram> verify(const ParsedProgram &parsed, const VerifyOptions &opts,
                                      Diagnostics &diags);

/// parseStl + verify; returns nothing on any error.
std::optional<VerifiedProgram> compileFrontEnd(std::string_view text, std::string file,
                                               const VerifyOptions &opts, Diagnostics &diags);

/// parseStl (with symbols, may be null) + verify; returns nothing on any error.
std::optional<VerifiedProgram> compileFrontEnd(std::string_view text, std::string file,
                                               const VerifyOptions &opts, Diagnostics &diags,
                                               const SymbolTable *symbols);

/// Human-readable dump of a verified program (one statement per line with depth, slot, slice),
/// used by `ladderjit check --print` and golden tests.
std::string printProgram(const VerifiedProgram &prog);

/// An operand as STL text: `X1.0`, `D5`, `L3`, `S7`, `-12`.
std::string formatOperand(const Operand &op);

} // namespace lj

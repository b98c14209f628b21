// The HNC-8 STL front end: text -> ParsedProgram, with located diagnostics in HNC-8 wording
// (parse + verify: pipeline/Compile.h).
#pragma once

#include "ir/Diagnostics.h"
#include "ir/Program.h"
#include "ir/SymbolTable.h"

#include <climits>
#include <optional>
#include <string_view>

namespace lj {

/// Parse STL text (DIALECT.md 2). Never fails as a whole: bad lines become diagnostics and are
/// left out of the result.
ParsedProgram parseStl(std::string_view text, std::string file, Diagnostics &diags);

/// parseStl with symbols (docs/plc-dit.md "Symbols"): an operand token shaped like a name
/// (SymbolTable::isNameShaped) is replaced by its symbol's address, then checked like that
/// address; an unknown name is the error "unknown symbol 'NAME'". `symbols` may be null.
/// Parsing stops with an error at statement `maxStatements` + 1, after 100 errors, and when the
/// first 3 non-empty lines start with no mnemonic (not a program).
ParsedProgram parseStl(std::string_view text, std::string file, Diagnostics &diags,
                       const SymbolTable *symbols, int32_t maxStatements = INT32_MAX);

/// Human-readable dump of a verified program (one statement per line with depth, slot, slice),
/// used by `ladderjit check --print` and golden tests.
std::string printProgram(const VerifiedProgram &prog);

/// An operand as STL text: `X1.0`, `D5`, `L3`, `S7`, `-12`.
std::string formatOperand(const Operand &op);

namespace hnc8 {
/// The HNC-8 wording of operations and operands, which the parser stores in every program.
const DialectText &dialectText();
} // namespace hnc8

} // namespace lj

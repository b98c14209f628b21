// The FANUC 0i-D PMC mnemonic front end (FANUC PMC manual ref 5, 6; docs/fanuc-pmc.md):
// text -> ParsedProgram on the FANUC profile, with located diagnostics in FANUC wording.
#pragma once

#include "ir/Diagnostics.h"
#include "ir/Program.h"
#include "ir/SymbolTable.h"

#include <optional>
#include <string>
#include <string_view>

namespace lj::fanuc {

/// Parse a `.pmc` text: plain mnemonic lines, or a FANUC mnemonic file whose %@3 section holds
/// them and whose %@2-E sections define symbols (docs/fanuc-pmc.md "Symbols and comments").
/// Never fails as a whole: bad lines become diagnostics.
ParsedProgram parsePmc(std::string_view text, std::string file, Diagnostics &diags);

/// parsePmc with `symbols` (may be null) defined before the file's own (a name defined in both
/// is an error). With any symbols or a %@2-E section, an operand token shaped like a name
/// (SymbolTable::isNameShaped) is replaced by its symbol's address and checked like that
/// address (Operand::symbol records it); an unknown name is the error "unknown symbol 'NAME'".
ParsedProgram parsePmc(std::string_view text, std::string file, Diagnostics &diags,
                       const SymbolTable *symbols);

/// The rules of a FANUC symbol table: names of at most 40 bytes (0i-D extended symbols),
/// comments of at most 255, FANUC bit or byte addresses (not L or P) written canonically
/// (`F0000.0` -> `F0.0`).
const SymbolRules &symbolRules();

/// An operand as PMC text: `X0.0`, `R100`, `D100` (width shown by the instruction), `P10`.
std::string formatOperand(const Operand &op);

/// The FANUC wording of operations and operands.
const DialectText &dialectText();

} // namespace lj::fanuc

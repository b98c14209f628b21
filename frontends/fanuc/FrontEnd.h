// The FANUC 0i-D PMC mnemonic front end (../shared/reference/fanuc-pmc.md 5, 6; docs/fanuc-pmc.md):
// text -> ParsedProgram on the FANUC profile, with located diagnostics in FANUC wording.
#pragma once

#include "frontends/hnc8/Symbols.h"
#include "ir/Diagnostics.h"
#include "ir/Program.h"
#include "verify/Verify.h"

#include <optional>
#include <string>
#include <string_view>

namespace lj::fanuc {

/// Parse PMC mnemonic text. Never fails as a whole: bad lines become diagnostics.
ParsedProgram parsePmc(std::string_view text, std::string file, Diagnostics &diags);

/// parsePmc + verify; nothing on any error. `symbols` is not supported yet (must be null).
std::optional<VerifiedProgram> compilePmc(std::string_view text, std::string file,
                                          const VerifyOptions &opts, Diagnostics &diags,
                                          const SymbolTable *symbols);

/// An operand as PMC text: `X0.0`, `R100`, `D100` (width shown by the instruction), `P10`.
std::string formatOperand(const Operand &op);

/// The FANUC wording of operations and operands.
const DialectText &dialectText();

} // namespace lj::fanuc

// The IEC 61131-3 Instruction List front end (Modicon TSX Neza dialect, modicon-neza.md;
// docs/iec-il.md): text -> ParsedProgram on the IEC profile, with located diagnostics in IL
// wording (parse + verify: pipeline/Compile.h).
#pragma once

#include "ir/Diagnostics.h"
#include "ir/Program.h"

#include <optional>
#include <string_view>

namespace lj::iec {

/// Parse IL text. Never fails as a whole: every broken line and every seed restriction broken
/// (ST inside parentheses, a 9th nesting level, an edge on %M32...) is a located error.
ParsedProgram parseIl(std::string_view text, std::string file, Diagnostics &diags);

/// The IL wording of operations and operands, which the parser stores in every program.
const DialectText &dialectText();

} // namespace lj::iec

// The ClassicLadder front end (docs/classicladder.md "Rungs on the IR"): a project (Reader.h)
// -> ParsedProgram on the classicladder profile. Each rung's grid becomes IR statements that
// keep ClassicLadder 2.9's scan literally: cells evaluated column by column, a cell's power
// (DynamicOutput) held in a state bit, a vertical group of the column before ORed, coils written
// at once, sections in number order and rungs in #NEXTRUNG order. Elements not mapped yet are
// refused with one located error naming the element. Parse + verify: pipeline/Compile.h.
#pragma once

#include "frontends/classicladder/Project.h"
#include "ir/Diagnostics.h"
#include "ir/Program.h"

#include <optional>
#include <string>
#include <string_view>

namespace lj::classicladder {

/// A `.clp` container held in memory: read (Reader.h) then mapped (toProgram). Never fails as a
/// whole: a read error or a refused element is a diagnostic.
ParsedProgram parseClp(std::string_view text, std::string file, Diagnostics &diags);

/// A project read by Reader.h mapped onto the IR.
ParsedProgram toProgram(const Project &project, std::string file, Diagnostics &diags);

/// The operand of ClassicLadder variable `type`/`num` (`%I3`, `%Q0`, `%B7`, `%W2`) on the
/// classicladder profile, or nullopt with `why` set when the profile has no such variable.
std::optional<Operand> varOperand(int32_t type, int32_t num, std::string &why);

/// The ClassicLadder wording of operations and operands, stored in every program it parses.
const DialectText &dialectText();

} // namespace lj::classicladder

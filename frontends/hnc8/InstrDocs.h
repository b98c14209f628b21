// Per-mnemonic documentation (behaviour, example, effect) and the renderer of the user-facing
// instruction reference docs/instructions.md, generated from the instruction table plus these
// texts (regenerate: `build/tools/gen-instr-doc/gen-instr-doc -o docs/instructions.md`).
#pragma once

#include "ir/OpTable.h"

#include <span>
#include <string>

namespace lj {

/// The documentation of one mnemonic that the table does not hold.
struct InstrDoc {
  Op op;
  const char *behaviour; ///< what it does, with the reference section deciding it
  const char *example;   ///< a small STL program using it (passes parse + verify alone)
  const char *effect;    ///< what the example does, with concrete values
};

/// The documentation of `op`, or nullptr when HNC-8 does not spell it.
const InstrDoc *instrDoc(Op op);

/// All entries, in Op order (one per operation HNC-8 spells).
std::span<const InstrDoc> instrDocs();

/// The whole docs/instructions.md text (deterministic).
std::string renderInstructionReference();

} // namespace lj

// Worst-case compile programs: for every instruction-table row, the longest valid repetition of
// it that keeps one rung alive (ST/MS entries live across the whole body), and the flow shapes
// that defeat naive chunking (nested loops, one long loop body, nested JMP spans).
#pragma once

#include "gen/ProgramGenerator.h"

#include <string>
#include <vector>

namespace lj::gen {

/// One worst case: a name (the row's mnemonic, or a flow shape such as "LOOP-nested") and the
/// program of about `statements` statements it stands for.
struct WorstCase {
  std::string name;
  GenProgram program;
};

/// Names of every worst case, in table order then the flow shapes. Markers (IEND 1END 2END),
/// SP and SPE cannot be repeated inside one body and have none.
std::vector<std::string> worstCaseNames();

/// The worst case `name` with about `statements` statements (exact shapes in WorstPrograms.cpp).
/// Empty lines when `name` is unknown.
GenProgram generateWorst(const std::string &name, int32_t statements);

} // namespace lj::gen

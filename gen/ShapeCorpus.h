// The shape corpus of `ladderjit bench --corpus` (docs/bench.md, docs/BENCHMARKS.md "Shape
// corpus"): programs of ~10,000 statements, each of one typical shape (plain PLC1 bit logic,
// edge-heavy, deep ANB/ORB nesting, long MPS fans, word-heavy, timer/counter-heavy, a FANUC PMC
// program, an IEC IL program), all inside the C baseline's subset (gen/CTranslate.h), so each
// is measured against gcc and clang on its faithful translation to C.
#pragma once

#include "gen/ProgramGenerator.h"

#include <cstdint>
#include <string>
#include <vector>

namespace lj::gen {

/// One shape of the corpus.
struct CorpusShape {
  std::string name;      ///< "plc1-mixed", "edge-heavy", ...
  std::string extension; ///< ".stl" (HNC-8), ".pmc" (FANUC), ".il" (IEC): picks the dialect
  std::string summary;   ///< one line: what the shape is
};

/// The shapes, in the order the corpus table lists them.
const std::vector<CorpusShape> &corpusShapes();

/// The program of shape `name` with about `statements` statements (exact for HNC-8), from
/// `seed`. Empty lines when `name` is not a shape.
GenProgram generateShape(const std::string &name, uint64_t seed, int32_t statements);

} // namespace lj::gen

// `ladderjit fuzz --edit` (docs/ladder-edit.md "Grid and oracle"): random editor grids and
// random edit sequences (gen/GridGen.h); each valid grid turned into program text of its
// dialect (ladder::gridProgramText), parsed and verified by the dialect's pipeline, run on the
// interpreter with random inputs and compared with the grid evaluator (ladder/GridEval.h) bit
// by bit after every tick; its program read back as networks and placed as a grid again must
// be the same grid (generated grids) or print the same program (edited grids).
#pragma once

#include <cstdint>
#include <functional>
#include <iosfwd>
#include <string>

namespace lj::fuzz {

struct EditFuzzOptions {
  std::string dialect = "hnc8"; ///< hnc8 | fanuc | iec
  uint64_t seed = 1;
  uint64_t programs = 1000; ///< random grid programs (each then edited)
  uint32_t ticks = 50;
  int maxRungs = 4;        ///< rungs per program, 1..maxRungs
  int maxEdits = 4;        ///< edits per program, 1..maxEdits
  uint32_t maxReports = 3; ///< mismatches printed in full (minimized)
  uint32_t minimizeBudget = 400;
  std::function<void(uint64_t done, uint64_t failures, double seconds)> progress;
};

struct EditFuzzStats {
  uint64_t programs = 0;
  uint64_t rungs = 0;
  uint64_t edits = 0;     ///< edits tried
  uint64_t editsKept = 0; ///< edits after which the grid was still valid
  uint64_t refused = 0;   ///< edits refused with a located error (and undone)
  uint64_t checked = 0;   ///< grid programs run against the evaluator
  uint64_t ticks = 0;
  uint64_t mismatches = 0;    ///< evaluator and interpreter differed
  uint64_t roundTrip = 0;     ///< grid -> program -> networks -> grid differed
  uint64_t notVerified = 0;   ///< a valid grid whose program the pipeline refused
  uint64_t unlocated = 0;     ///< a refusal whose cell is outside the grid
  uint64_t refusedBy[9] = {}; ///< by reason (editFuzzReason)
  double seconds = 0;
  uint64_t failures() const { return mismatches + roundTrip + notVerified + unlocated; }
};

/// The reason names of EditFuzzStats::refusedBy, in order.
const char *editFuzzReason(int k);

/// Run the campaign, printing a summary (and minimized failures) to `out`.
EditFuzzStats runEdit(const EditFuzzOptions &opts, std::ostream &out);

} // namespace lj::fuzz

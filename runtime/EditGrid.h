// The page editor's grid route (docs/ladder-edit.md "The page editor"): POST /api/edit/grid
// turns the running program's rungs into editor grids (ladder/Grid.h gridOfRung) with the
// dialect's box catalogue, turns edited grids back into networks for the draft (gridToNetwork,
// every refusal on its cell), and checks one operand as the user types it. It reads the running
// version only: no draft, no program, no state changes here.
#pragma once

#include "runtime/EditSession.h"
#include "runtime/Executive.h"

#include <nlohmann/json.hpp>

namespace lj::rt {

/// POST /api/edit/grid with `body` on the running version `v` (null: none runs). Bodies:
/// `{"open":true}`, `{"rungs":[{"part","rung","grid"}]}`, `{"operand","kind"[,"box","index"]}`,
/// `{"subroutine":"S7"}` (列表编辑: the markers of a new subroutine part in the dialect).
EditAnswer editGrid(const ProgramVersion *v, const nlohmann::json &body);

} // namespace lj::rt

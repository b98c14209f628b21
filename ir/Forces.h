// Online-monitor forces of contacts (hnc8-core.md 6.1 RESOLUTION (a), docs/serve.md "Forcing").
// They are runtime state: `ladderjit serve` owns the table (runtime/ProgramLoader.h) and hands
// it to each engine build as an override value; the VerifiedProgram never holds it.
#pragma once

#include "ir/OpTable.h"
#include "ir/Program.h"

#include <cstdint>
#include <map>
#include <vector>

namespace lj {

/// Statement id (Stmt::id) -> the constant the forced contact conducts: 0 = 禁止 (off),
/// 1 = 允许 (on). NO/NC and edge are ignored; an edge contact still updates its memory with the
/// real bit.
using ContactForces = std::map<StmtId, int8_t>;

/// The forces as a table parallel to `prog.stmts`: -1 = not forced, else 0/1. Empty when no
/// statement of `prog` is forced (the engines then do exactly what they do without forces).
/// Ids `prog` lacks and statements that are not contacts are skipped; the runtime refuses them
/// before a build (runtime/ProgramLoader.h checkForces).
inline std::vector<int8_t> forceTable(const VerifiedProgram &prog, const ContactForces &forces) {
  std::vector<int8_t> t;
  if (forces.empty()) return t;
  for (size_t i = 0; i < prog.stmts.size(); ++i) {
    const Stmt &st = prog.stmts[i];
    auto it = forces.find(st.id);
    if (it == forces.end() || !isContact(st.op)) continue;
    if (t.empty()) t.assign(prog.stmts.size(), -1);
    t[i] = it->second != 0 ? 1 : 0;
  }
  return t;
}

} // namespace lj

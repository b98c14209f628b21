// The instruction as the ladder view draws it, in the program's dialect (docs/ladder-view.md
// "Dialects"): each front end's DialectText says how its user writes a statement (HNC-8
// mnemonics; FANUC RD/WRT and the functional instructions by name with their width, MOVW, EQB;
// IL LD/ST/S/R and the operation blocks' operators). ladder/ knows no dialect by name.
#include "ladder/Network.h"

namespace lj::ladder {

const char *const kBlockJoinWord = "ANB";
const char *const kFanWords[3] = {"MPS", "MRD", "MPP"};

std::string drawnMnemonic(const DialectText *d, const Stmt &s) {
  if (d && d->spellStmt) return d->spellStmt(s);
  return spelling(d, s.op);
}

} // namespace lj::ladder

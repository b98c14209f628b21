// HNC-8 STL as networks print it (docs/ladder-json.md): one statement per line, the mnemonic
// and its operands (a symbol's name where one was used), comments after `;`.
#include "frontends/hnc8/FrontEnd.h"
#include "frontends/hnc8/Mnemonics.h"

namespace lj::hnc8::detail {

bool printStatements(std::span<const StmtText> stmts, std::string &out, std::string &) {
  for (const StmtText &s : stmts) {
    for (const std::string &c : s.before) out += "; " + c + "\n";
    std::string t = mnemonicOf(s.op);
    for (const std::string &o : s.operands) t += " " + o;
    if (s.hasComment) t += " ; " + s.comment;
    out += t + "\n";
  }
  return true;
}

} // namespace lj::hnc8::detail

// Worst-case compile programs (gen/WorstPrograms.h): each table row repeated in the shape that
// keeps its rung alive, with the operands the random generator's snippet of the row chose.
#include "gen/WorstPrograms.h"

#include "frontends/hnc8/Mnemonics.h"
#include "ir/OpTable.h"

#include <algorithm>

namespace lj::gen {

namespace {

/// Rows that cannot repeat inside one body: the part markers and the subroutine brackets.
bool unrepeatable(Op op) {
  return op == Op::EndInit || op == Op::EndCyclic || op == Op::EndSliced || op == Op::SubBegin ||
         op == Op::SubEnd;
}

/// The row's statement in its snippet: the snippet is the feed (LDTs, an MPS) then the row.
std::string rowLine(const InstrInfo &in) {
  GenProgram s = generateSnippet(in.op, 1);
  size_t feed = 0;
  switch (in.stack) {
  case StackRule::Push:
    feed = 0;
    break;
  case StackRule::BlockPop:
  case StackRule::MsRead:
  case StackRule::MsPop:
    feed = 2;
    break;
  default:
    feed = static_cast<size_t>(std::max<int>(in.inputs, 1));
    break;
  }
  return feed < s.lines.size() ? s.lines[feed] : std::string();
}

void repeat(std::vector<std::string> &out, int32_t n, const std::string &line) {
  for (int32_t k = 0; k < n; ++k) out.push_back(line);
}

/// Flow shapes, named after the row they stress.
bool flowShape(Op op, int32_t n, std::vector<std::string> &l) {
  switch (op) {
  case Op::Jump: // nested forward spans, each on its own input: no cut is outside all of them
    for (int32_t k = 1; k <= n / 3; ++k) {
      l.push_back("LD X" + std::to_string(k / 8 % 64) + "." + std::to_string(k % 8));
      l.push_back("JMP L" + std::to_string(k));
    }
    for (int32_t k = n / 3; k >= 1; --k) l.push_back("LBL L" + std::to_string(k));
    return true;
  case Op::Label: // a forward jump to every label
    for (int32_t k = 1; k <= n / 3; ++k) {
      l.push_back("LDT");
      l.push_back("JMP L" + std::to_string(k));
      l.push_back("LBL L" + std::to_string(k));
    }
    return true;
  case Op::LoopBegin: // nested loops (the 3,000 nested LOOP 2)
    repeat(l, n / 2, "LOOP 2");
    l.push_back("LDT");
    l.push_back("INC D0");
    repeat(l, n / 2, "NEXT");
    return true;
  case Op::LoopEnd: // one loop with a long body on one live rung
    l.push_back("LOOP 2");
    l.push_back("LDT");
    repeat(l, n, "OUT Y0.0");
    l.push_back("NEXT");
    return true;
  case Op::Call:
    l.push_back("LDT");
    repeat(l, n, "CALL S1");
    for (const char *x : {"1END", "2END", "SP S1", "LDT", "OUT R0.0", "SPE"}) l.push_back(x);
    return true;
  case Op::Return:
    for (const char *x : {"LDF X0.0", "CALL S1", "1END", "2END", "SP S1", "LDF X0.1"})
      l.push_back(x);
    repeat(l, n, "RETN");
    l.push_back("SPE");
    return true;
  default:
    return false;
  }
}

} // namespace

std::vector<std::string> worstCaseNames() {
  std::vector<std::string> names;
  for (const InstrInfo &in : instrTable())
    if (hnc8::spells(in.op) && !unrepeatable(in.op)) names.push_back(hnc8::mnemonicOf(in.op));
  return names;
}

GenProgram generateWorst(const std::string &name, int32_t n) {
  GenProgram p;
  p.plc2Nvalue = 0;
  Op op;
  if (!hnc8::lookupMnemonic(name, op) || unrepeatable(op)) return p;
  std::vector<std::string> &l = p.lines;
  if (flowShape(op, n, l)) return p;
  const InstrInfo &in = instrInfo(op);
  const std::string row = rowLine(in);
  if (op == Op::ToolLife) n = std::min(n, 500); // the verifier allows 512 TOOLLIFE instances
  switch (in.stack) {
  case StackRule::Push: // a deep stack: every entry is live until the ORB chain folds it
    repeat(l, n / 2, row);
    repeat(l, n / 2 - 1, "ORB");
    l.push_back("OUT Y0.0");
    break;
  case StackRule::BlockPop: // one rung that keeps combining
    l.push_back("LDT");
    for (int32_t k = 0; k < n / 2; ++k) {
      l.push_back("LDT");
      l.push_back(row);
    }
    l.push_back("OUT Y0.0");
    break;
  case StackRule::MpsPush:
  case StackRule::MsPop: // a deep MS
    l.push_back("LDT");
    repeat(l, n / 2, "MPS");
    repeat(l, n / 2, "MPP");
    break;
  case StackRule::MsRead:
    l.push_back("LDT");
    l.push_back("MPS");
    repeat(l, n, row);
    l.push_back("MPP");
    break;
  default:
    if (in.stack == StackRule::Block && in.inputs > 1) {
      // The output of each block is input 1 of the next: one chain of live entries.
      repeat(l, in.inputs, "LDT");
      l.push_back(row);
      for (int32_t k = 0; k < n / in.inputs; ++k) {
        repeat(l, in.inputs - 1, "LDT");
        l.push_back(row);
      }
    } else { // contacts, coils and one-input blocks: all read the one LDT
      l.push_back("LDT");
      repeat(l, n, row);
    }
    break;
  }
  return p;
}

} // namespace lj::gen

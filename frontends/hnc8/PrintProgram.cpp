// Text dump of a verified program (`ladderjit check --print`, golden tests): a summary of parts,
// subroutines and PLC2 slices, then one line per statement with the verifier's facts.
#include "frontends/common/OperandText.h"
#include "frontends/hnc8/FrontEnd.h"
#include "frontends/hnc8/Mnemonics.h"
#include "profiles/hnc8/Hnc8Profile.h"

#include <cstdio>

namespace lj {

std::string formatOperand(const Operand &op) { return frontend::operandText(hnc8::profile(), op); }

namespace {

std::string rangeText(StmtRange r) {
  return "[" + std::to_string(r.begin) + "," + std::to_string(r.end) + ")";
}

bool inRange(StmtRange r, int32_t i) { return i >= r.begin && i < r.end; }

/// "init", "plc1", "plc2", "S7", or "-" for markers and SP/SPE lines.
std::string partOf(const VerifiedProgram &p, int32_t i) {
  if (inRange(p.init, i)) return "init";
  if (inRange(p.plc1, i)) return "plc1";
  if (inRange(p.plc2, i)) return "plc2";
  for (const Subroutine &s : p.subs)
    if (inRange(s.body, i)) return "S" + std::to_string(s.number);
  return "-";
}

} // namespace

std::string printProgram(const VerifiedProgram &p) {
  std::string out;
  out += "; program " + p.file + ": " + std::to_string(p.stmts.size()) + " statements, " +
         std::to_string(p.edgeSlots) + " edge slots, max ST depth " + std::to_string(p.maxDepth) +
         ", max MS depth " + std::to_string(p.maxMsDepth) + "\n";
  out += "; init " + rangeText(p.init) + " plc1 " + rangeText(p.plc1) + " plc2 " +
         rangeText(p.plc2) + "\n";
  for (const Subroutine &s : p.subs)
    out += "; sub S" + std::to_string(s.number) + " sp " + std::to_string(s.spIndex) + " body " +
           rangeText(s.body) + "\n";
  out += "; plc2 nvalue " + std::to_string(p.plc2Nvalue) + ", " + std::to_string(p.slices.size()) +
         " slice(s)\n";
  for (size_t k = 0; k < p.slices.size(); ++k)
    out += "; slice " + std::to_string(k) + " " + rangeText(p.slices[k]) + " st " +
           std::to_string(k < p.sliceDepth.size() ? p.sliceDepth[k] : 0) + "\n";

  size_t slice = 0;
  char buf[64];
  for (size_t i = 0; i < p.stmts.size(); ++i) {
    const Stmt &s = p.stmts[i];
    const StmtInfo &in = p.info[i];
    auto idx = static_cast<int32_t>(i);
    std::string ops;
    // In the program's own dialect (a FANUC program prints RD, R100, D100).
    auto operandText = p.dialect ? p.dialect->formatOperand : &formatOperand;
    for (int k = 0; k < s.operandCount; ++k) ops += (k ? " " : "") + operandText(s.ops[k]);
    std::snprintf(buf, sizeof buf, "%5zu %5d:%-3d %-5s %-6s ", i, s.loc.line, s.loc.col,
                  partOf(p, idx).c_str(), spelling(p.dialect, s.op));
    std::string line = buf;
    line += ops;
    if (line.size() < 48) line.resize(48, ' ');
    line += " st=" + std::to_string(in.depth) + " ms=" + std::to_string(in.msDepth);
    if (in.slot >= 0) line += " slot=" + std::to_string(in.slot);
    if (in.target >= 0) line += " target=" + std::to_string(in.target);
    if (instrInfo(s.op).stack == StackRule::Block && in.hasInput) line += " in";
    if (in.backward) line += " back";
    if (inRange(p.plc2, idx)) {
      while (slice + 1 < p.slices.size() && idx >= p.slices[slice].end) ++slice;
      line += " slice=" + std::to_string(slice);
    }
    out += line + "\n";
  }
  return out;
}

} // namespace lj

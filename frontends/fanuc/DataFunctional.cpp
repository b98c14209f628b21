// The FANUC transfer, search, conversion and flow instructions (fanuc-b; reference 4.2, 6.5, 6.7,
// 6.8, 6.9, 6.10; docs/fanuc-pmc.md) and the rotation control ROT/ROTB (6.10 [EXT]): parameters
// checked with located errors and mapped onto the fanuc-b IR operations (ir/OpTable.h). Control
// inputs are loaded top to bottom, so ACT is ST0, RST ST1 and so on (reference 5); an instruction
// with k inputs pops k - 1 and leaves W1 in ST0.
#include "frontends/fanuc/ParserInternal.h"

#include <string>

namespace lj::fanuc::detail {

namespace {

/// A `0nnd` format (XMOVB, DECB): d = 1/2/4 bytes, nn = 0..99.
bool formatNnd(Emitter &e, const Token &t, int &nn, int &d) {
  int64_t v;
  if (!e.constant(t, 0, 999, "format", v)) return false;
  d = static_cast<int>(v % 10);
  nn = static_cast<int>(v / 10);
  if (d != 1 && d != 2 && d != 4) {
    e.error(t.loc, "LJ4066",
            "format '" + std::string(t.text) +
                "': the last digit is the data length 1, 2 or 4 (0nnd, like 0021)");
    return false;
  }
  return true;
}

/// A data length parameter 1, 2 or 4 (DSCHB, DCNVB, CODB).
bool length(Emitter &e, const Token &t, const char *role, int &d) {
  int64_t v;
  if (!e.constant(t, 1, 4, role, v)) return false;
  if (v == 3) {
    e.error(t.loc, "LJ4067", std::string(role) + " '3': expected 1, 2 or 4");
    return false;
  }
  d = static_cast<int>(v);
  return true;
}

/// A byte address covering `span` bytes, accessed `width` bytes at a time.
bool spanOperand(Emitter &e, const Token &t, int span, int width, bool writes, Operand &out) {
  if (!e.dataOperand(t, span, false, writes, out)) return false;
  out.width = static_cast<uint8_t>(width);
  return true;
}

/// The inputs an instruction takes from ST, top to bottom (the last is ACT in ST0).
const char *inputsOf(std::string_view n) {
  if (n == "XMOVB") return "RW, RST, ACT";
  if (n == "XMOV") return "BYT, RW, RST, ACT";
  if (n == "DSCH") return "BYT, RST, ACT";
  if (n == "ROT") return "RN0, BYT, DIR, POS, INC, ACT";
  if (n == "ROTB") return "RN0, DIR, POS, INC, ACT";
  if (n == "DSCHB" || n == "CODB") return "RST, ACT";
  if (n == "PARI") return "O.E, RST, ACT";
  if (n == "SFT") return "DIR, CONT, RST, ACT";
  if (n == "COD") return "BYT, RST, ACT";
  if (n == "DCNV") return "BYT, CNV, RST, ACT";
  if (n == "DCNVB") return "SIN, CNV, RST, ACT";
  return "ACT";
}

int inputCount(std::string_view n) {
  std::string_view s = inputsOf(n);
  int k = 1;
  for (char c : s) k += c == ',';
  return k;
}

/// Why the CNC-service instructions are not in this build (reference 6.10 names them only).
const char *cncService(std::string_view n) {
  if (n == "DISPB") return "the CNC's message display (A-area requests shown on the CNC screen)";
  if (n == "EXIN") return "the CNC's external data input";
  if (n == "WINDR" || n == "WINDW") return "the CNC's window function codes (CNC data read/write)";
  if (n == "AXCTL") return "the CNC's PMC axis control";
  if (n == "PSGNL" || n == "PSGN2") return "the CNC's axis positions (position signal output)";
  return nullptr;
}

/// The table entries of COD / CODB: parameters [first, end) as `TableRows` of 9 constants.
void emitRows(Emitter &e, const Functional &f, size_t first, SourceLoc at,
              const std::vector<int32_t> &values) {
  for (size_t k = 0; k < values.size(); k += kMaxOperands) {
    std::vector<Operand> ops;
    for (size_t j = k; j < values.size() && j < k + kMaxOperands; ++j)
      ops.push_back(konst(values[j], f.params[first + j].loc));
    // emit() takes an initializer list: spell out the row's operands (1..9).
    switch (ops.size()) {
    case 1:
      e.emit(Op::TableRows, at, {ops[0]});
      break;
    case 2:
      e.emit(Op::TableRows, at, {ops[0], ops[1]});
      break;
    case 3:
      e.emit(Op::TableRows, at, {ops[0], ops[1], ops[2]});
      break;
    case 4:
      e.emit(Op::TableRows, at, {ops[0], ops[1], ops[2], ops[3]});
      break;
    case 5:
      e.emit(Op::TableRows, at, {ops[0], ops[1], ops[2], ops[3], ops[4]});
      break;
    case 6:
      e.emit(Op::TableRows, at, {ops[0], ops[1], ops[2], ops[3], ops[4], ops[5]});
      break;
    case 7:
      e.emit(Op::TableRows, at, {ops[0], ops[1], ops[2], ops[3], ops[4], ops[5], ops[6]});
      break;
    case 8:
      e.emit(Op::TableRows, at, {ops[0], ops[1], ops[2], ops[3], ops[4], ops[5], ops[6], ops[7]});
      break;
    default:
      e.emit(Op::TableRows, at,
             {ops[0], ops[1], ops[2], ops[3], ops[4], ops[5], ops[6], ops[7], ops[8]});
      break;
    }
  }
}

bool paramCount(Emitter &e, const Functional &f, const std::string &what, size_t n,
                const char *roles) {
  if (f.params.size() == n) return true;
  e.error(f.head.loc, "LJ4068",
          what + " takes " + std::to_string(n) + " parameters (" + roles + "), got " +
              std::to_string(f.params.size()));
  return false;
}

/// COD / CODB: [format (CODB)] size, input, output, then `size` entries.
void codeTable(Emitter &e, const Functional &f, const std::string &what, bool binary,
               SourceLoc at) {
  const size_t head = binary ? 4 : 3;
  const char *roles = binary ? "format, table size, input address, output address, table entries"
                             : "table size, input address, output address, table entries";
  if (f.params.size() < head) {
    e.error(at, "LJ4069",
            what + " takes " + std::to_string(head) + " parameters and its table entries (" +
                roles + "), got " + std::to_string(f.params.size()));
    return;
  }
  const auto &p = f.params;
  int w = 2;
  size_t k = 0;
  if (binary && !length(e, p[k++], "format", w)) return;
  int64_t size;
  if (!e.constant(p[k], 0, binary ? 256 : 99, "table size", size)) return;
  const Token &sizeTok = p[k++];
  if (p.size() != head + static_cast<size_t>(size)) {
    e.error(sizeTok.loc, "LJ4070",
            what + " with table size " + std::to_string(size) + " takes " + std::to_string(size) +
                " table entries after its " + std::to_string(head) + " parameters, got " +
                std::to_string(p.size() - head));
    return;
  }
  Operand in, out;
  if (!e.dataOperand(p[k++], 1, false, false, in)) return;
  if (!spanOperand(e, p[k++], w, binary ? w : 1, true, out)) return;
  std::vector<int32_t> values;
  for (size_t j = head; j < p.size(); ++j) {
    int64_t v;
    if (binary) {
      const int64_t lo = w == 1 ? -128 : w == 2 ? -32768 : INT32_MIN;
      const int64_t hi = w == 1 ? 255 : w == 2 ? 65535 : INT32_MAX;
      if (!e.constant(p[j], lo, hi, "table entry", v)) return;
      values.push_back(w == 1   ? static_cast<int8_t>(v)
                       : w == 2 ? static_cast<int16_t>(v)
                                : static_cast<int32_t>(v));
    } else {
      if (!e.constant(p[j], 0, 9999, "BCD table entry", v)) return;
      values.push_back(detail::toBcd(v));
    }
  }
  e.emit(binary ? Op::CodeTableBinary : Op::CodeTable, at, {konst(size, sizeTok.loc), in, out});
  emitRows(e, f, head, at, values);
}

} // namespace

bool emitDataFunctional(Emitter &e, const Functional &f, std::string_view name,
                        const std::string &what) {
  const SourceLoc at = f.head.loc;
  if (const char *svc = cncService(name)) {
    e.error(at, "LJ4071",
            what + " is not supported by this build: it needs " + svc +
                ", a CNC service the FANUC 0i-D PMC manual (6.10) names but does not "
                "describe (docs/fanuc-pmc.md \"Not supported\")");
    return true;
  }
  static constexpr std::string_view kMine[] = {
      "XMOVB", "DSCHB", "PARI", "SFT",  "COD", "CODB", "DCNV", "DCNVB", "DEC", "DECB",
      "COM",   "COME",  "JMP",  "JMPE", "NOP", "XMOV", "DSCH", "ROT",   "ROTB"};
  bool mine = false;
  for (std::string_view m : kMine) mine = mine || m == name;
  if (!mine) return false;
  FlowRegions &rg = e.regions();
  // Region ends and NOP take no ACT.
  if (name == "NOP") {
    paramCount(e, f, what, 0, "none");
    return true;
  }
  if (name == "COME") {
    if (!paramCount(e, f, what, 0, "none")) return true;
    if (rg.comStmt < 0) {
      e.error(at, "LJ4072", what + " without COM");
    } else if (rg.jmpLabel >= 0 && rg.jmpInsideCom) {
      e.error(at, "LJ4073",
              what + " inside JMP..JMPE (JMP on line " + std::to_string(rg.jmpLine) +
                  "): close the JMP first");
    } else {
      rg.comStmt = -1;
    }
    return true;
  }
  if (name == "JMPE") {
    if (!paramCount(e, f, what, 0, "none")) return true;
    if (rg.jmpLabel < 0) {
      e.error(at, "LJ4074", what + " without JMP");
    } else if (rg.comStmt >= 0 && !rg.jmpInsideCom) {
      e.error(at, "LJ4075",
              what + " inside COM..COME (COM on line " + std::to_string(rg.comLine) +
                  "): close the COM first");
    } else {
      Operand l;
      l.kind = Operand::Kind::Reg;
      l.area = Area::Label;
      l.index = rg.jmpLabel;
      l.loc = at;
      e.setDepth(0);
      e.emit(Op::Label, at, {l});
      rg.jmpLabel = -1;
    }
    return true;
  }
  const int inputs = inputCount(name);
  if (e.depth() < inputs) {
    e.error(at, "LJ4076",
            what + " needs its inputs " + inputsOf(name) + " in ST" + std::to_string(inputs - 1) +
                "..ST0 (" +
                (inputs == 1 ? "an RD before it" : "RD, then RD.STK for each further input") +
                "), found " + std::to_string(e.depth()));
    return true;
  }
  const auto &p = f.params;
  Operand a, b, c, d;
  bool ok = false;
  if (name == "COM") {
    if (!paramCount(e, f, what, 0, "none")) return true;
    if (rg.comStmt >= 0) {
      e.error(at, "LJ4077",
              what + " inside COM..COME (COM on line " + std::to_string(rg.comLine) + ")");
      return true;
    }
    rg.comStmt = e.stmtCount();
    rg.comLine = at.line;
    rg.jmpInsideCom = false;
    e.emit(Op::CommonBegin, at, {});
    return true;
  }
  if (name == "JMP") {
    if (!paramCount(e, f, what, 0, "none")) return true;
    if (rg.jmpLabel >= 0) {
      e.error(at, "LJ4078",
              what + " inside JMP..JMPE (JMP on line " + std::to_string(rg.jmpLine) + ")");
      return true;
    }
    rg.jmpLabel = rg.nextLabel++;
    rg.jmpLine = at.line;
    rg.jmpInsideCom = rg.comStmt >= 0;
    Operand l;
    l.kind = Operand::Kind::Reg;
    l.area = Area::Label;
    l.index = rg.jmpLabel;
    l.loc = at;
    e.emit(Op::Jump, at, {l});
    return true;
  }
  if (name == "PARI") {
    ok = paramCount(e, f, what, 1, "check data address") && e.dataOperand(p[0], 1, false, false, a);
    if (ok) e.emit(Op::ParityCheck, at, {a});
  } else if (name == "SFT") {
    ok = paramCount(e, f, what, 1, "shift data address (2 bytes)") &&
         e.dataOperand(p[0], 2, false, true, a);
    if (ok) e.emit(Op::ShiftWord, at, {a});
  } else if (name == "DEC") {
    int64_t spec;
    ok = paramCount(e, f, what, 2, "decode data address, decode specification nndd") &&
         e.dataOperand(p[0], 1, false, false, a) &&
         e.constant(p[1], 0, 9999, "decode specification", spec);
    if (ok) {
      const int64_t nn = spec / 100, dd = spec % 100;
      if (dd != 1 && dd != 10 && dd != 11) {
        e.error(p[1].loc, "LJ4079",
                "decode specification '" + std::string(p[1].text) +
                    "': the last two digits are 01 (low digit), 10 (high digit) or 11 "
                    "(both), like 0311");
        return true;
      }
      const int mask = dd == 1 ? 0x0F : dd == 10 ? 0xF0 : 0xFF;
      e.emit(Op::BcdDecode, at, {a, konst((nn / 10) << 4 | nn % 10), konst(mask)});
    }
  } else if (name == "DECB") {
    int nn, w;
    int64_t first;
    ok = paramCount(e, f, what, 4,
                    "format 0nnd, decode data address, first value, output address") &&
         formatNnd(e, p[0], nn, w) && e.dataOperand(p[1], w, false, false, a);
    if (!ok) return true;
    const int groups = nn == 0 ? 1 : nn;
    const int64_t lim = w == 1 ? 127 : w == 2 ? 32767 : INT32_MAX;
    const int64_t lo = w == 1 ? -128 : w == 2 ? -32768 : INT32_MIN;
    if (!e.constant(p[2], lo, lim, "first decode value", first) ||
        !spanOperand(e, p[3], groups, 1, true, c))
      return true;
    e.emit(Op::GroupDecode, at, {a, konst(first, p[2].loc), konst(groups), c});
  } else if (name == "DCNV") {
    ok = paramCount(e, f, what, 2, "input address, output address (1 or 2 bytes by BYT)") &&
         spanOperand(e, p[0], 2, 1, false, a) && spanOperand(e, p[1], 2, 1, true, b);
    if (ok) e.emit(Op::BcdConvert, at, {a, b});
  } else if (name == "DCNVB") {
    int w;
    ok = paramCount(e, f, what, 3, "data length 1/2/4, input address, output address") &&
         length(e, p[0], "data length", w) && e.dataOperand(p[1], w, false, false, a) &&
         e.dataOperand(p[2], w, false, true, b);
    if (ok) {
      // The result flags N (#1) and V (#5) go to R9000 (reference 2, 6.9).
      c.kind = Operand::Kind::Reg;
      c.area = Area::Relay;
      c.index = 9000;
      c.width = 1;
      c.loc = at;
      e.emit(Op::BcdConvertExt, at, {a, b, c});
    }
  } else if (name == "COD" || name == "CODB") {
    codeTable(e, f, what, name == "CODB", at);
    ok = true;
  } else if (name == "XMOVB") {
    int nn, w;
    ok = paramCount(e, f, what, 5,
                    "format 0nnd, capacity address, table head, data address, index address") &&
         formatNnd(e, p[0], nn, w);
    if (!ok) return true;
    const int items = nn <= 1 ? 1 : nn; // 00 / 01: basic specification, one item (6.5)
    ok = e.dataOperand(p[1], w, false, false, a) && spanOperand(e, p[2], w, w, true, b) &&
         spanOperand(e, p[3], items * w, w, true, c) && e.dataOperand(p[4], w, false, false, d);
    if (ok) e.emit(Op::IndexedTable, at, {konst(items, p[0].loc), a, b, c, d});
  } else if (name == "DSCHB" || name == "ROTB") {
    // A data length and four addresses of that many bytes, the last one written: DSCHB (ref
    // 6.7) and the binary rotation control (ref 6.10 [EXT]; n read from memory at run time).
    const bool rot = name == "ROTB";
    int w;
    Operand r;
    ok = paramCount(e, f, what, 5,
                    rot ? "format 1/2/4, rotor index count address, current position address, "
                          "goal position address, result address"
                        : "data length 1/2/4, capacity address, table head, search data address, "
                          "result address") &&
         length(e, p[0], rot ? "format" : "data length", w) &&
         e.dataOperand(p[1], w, false, false, a) && e.dataOperand(p[2], w, false, false, b) &&
         e.dataOperand(p[3], w, false, false, c) && e.dataOperand(p[4], w, false, true, r);
    if (ok && rot) e.emit(Op::BinaryRotation, at, {konst(w, p[0].loc), a, b, c, r});
    if (ok && !rot) e.emit(Op::SearchTable, at, {a, b, c, r});
  } else if (name == "XMOV" || name == "DSCH") {
    // BCD tables (ref 6.5, 6.7): capacity = n + 1 for a table 0..n, a constant; entries of 1 or
    // 2 bytes by BYT at run time, so the addresses are checked for 2 bytes.
    const bool search = name == "DSCH";
    int64_t cap;
    ok =
        paramCount(e, f, what, 4,
                   search ? "table capacity (constant), table head, search data address, result "
                            "address"
                          : "table capacity (constant), table head, data address, index address") &&
        e.constant(p[0], 1, 9999, "table capacity", cap) &&
        spanOperand(e, p[1], 1, 1, !search, b) && spanOperand(e, p[2], 2, 1, !search, c) &&
        spanOperand(e, p[3], 2, 1, search, d);
    if (!ok) return true;
    if (search && b.area != Area::DataTable) {
      e.error(p[1].loc, "LJ4080",
              "table head '" + std::string(p[1].text) +
                  "': DSCH searches the data table only (a D address, ref 6.7)");
      return true;
    }
    e.emit(search ? Op::BcdSearchTable : Op::BcdIndexedTable, at, {konst(cap, p[0].loc), b, c, d});
  } else if (name == "ROT") {
    // Rotation control, BCD (ref 6.10 [EXT]): n a constant; positions and the result of 1 or 2
    // bytes by BYT at run time, so the addresses are checked for 2 bytes (as XMOV's).
    int64_t n;
    ok = paramCount(e, f, what, 4,
                    "rotor index count n (constant 2..9999), current position address, goal "
                    "position address, result address") &&
         e.constant(p[0], 2, 9999, "rotor index count", n) &&
         spanOperand(e, p[1], 2, 1, false, b) && spanOperand(e, p[2], 2, 1, false, c) &&
         spanOperand(e, p[3], 2, 1, true, d);
    if (ok) e.emit(Op::BcdRotation, at, {konst(n, p[0].loc), b, c, d});
  }
  if (ok) e.setDepth(e.depth() - (inputs - 1));
  return true;
}

bool emitCommonCoil(Emitter &e, Op op, const Operand &bit, SourceLoc at) {
  const FlowRegions &rg = e.regions();
  if (rg.comStmt < 0) return false;
  const int kind = op == Op::Coil ? 0 : op == Op::CoilNot ? 1 : op == Op::Set ? 2 : 3;
  e.emit(Op::CommonCoil, at, {bit, konst(e.stmtCount() - rg.comStmt), konst(kind)});
  return true;
}

void closeRegions(Emitter &e, std::string_view marker, SourceLoc at) {
  FlowRegions &rg = e.regions();
  if (rg.comStmt >= 0)
    e.error(at, "LJ4081",
            "COM on line " + std::to_string(rg.comLine) + " has no COME before " +
                std::string(marker));
  if (rg.jmpLabel >= 0)
    e.error(at, "LJ4082",
            "JMP on line " + std::to_string(rg.jmpLine) + " has no JMPE before " +
                std::string(marker));
  rg.comStmt = -1;
  rg.jmpLabel = -1;
}

const char *spellData(Op op) {
  switch (op) {
  case Op::ParityCheck:
    return "PARI";
  case Op::ShiftWord:
    return "SFT";
  case Op::BcdDecode:
    return "DEC";
  case Op::GroupDecode:
    return "DECB";
  case Op::BcdConvert:
    return "DCNV";
  case Op::BcdConvertExt:
    return "DCNVB";
  case Op::CodeTable:
    return "COD";
  case Op::CodeTableBinary:
    return "CODB";
  case Op::TableRows:
    return "(COD/CODB table)";
  case Op::IndexedTable:
    return "XMOVB";
  case Op::SearchTable:
    return "DSCHB";
  case Op::BcdIndexedTable:
    return "XMOV";
  case Op::BcdSearchTable:
    return "DSCH";
  case Op::BcdRotation:
    return "ROT";
  case Op::BinaryRotation:
    return "ROTB";
  case Op::CommonBegin:
    return "COM";
  case Op::CommonCoil:
    return "WRT/WRT.NOT/SET/RST (COM)";
  default:
    return nullptr;
  }
}

} // namespace lj::fanuc::detail

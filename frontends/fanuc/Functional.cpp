// The functional instructions of the FANUC front end (reference 6; docs/fanuc-pmc.md): written
// `SUB n` or by name, parameters on the same line or on `(PRM)` lines, each mapped onto IR
// operations whose semantics are the reference's. ACT is ST0 (reference 5, [EXT]); W1 is left in
// ST0 for a WRT to store.
#include "frontends/fanuc/ParserInternal.h"
#include "profiles/fanuc/FanucProfile.h"

#include <array>

namespace lj::fanuc::detail {

namespace {

enum class Fn : uint8_t {
  Tmrb,
  Tmrbf,
  Difu,
  Difd,
  Movb,
  Movw,
  Movd,
  Movn,
  Move,
  Movor,
  Eor,
  And,
  Or,
  Not,
  Eq,
  Ne,
  Gt,
  Lt,
  Ge,
  Le,
  Jmpb,
  Jmpc,
  Lbl,
  Call,
  Callu,
  Cs,
  Cm,
  Ce,
  Unsupported
};

struct FnRow {
  const char *name;
  int sub;
  Fn fn;
  int width; ///< data width of the compare family (1, 2, 4), else 0
};

constexpr FnRow kRows[] = {
    {"TMRB", 24, Fn::Tmrb, 0},
    {"TMRBF", 77, Fn::Tmrbf, 0},
    {"DIFU", 57, Fn::Difu, 0},
    {"DIFD", 58, Fn::Difd, 0},
    {"MOVB", 43, Fn::Movb, 1},
    {"MOVW", 44, Fn::Movw, 2},
    {"MOVD", 47, Fn::Movd, 4},
    {"MOVN", 45, Fn::Movn, 1},
    {"MOVE", 8, Fn::Move, 1},
    {"MOVOR", 28, Fn::Movor, 1},
    {"EOR", 59, Fn::Eor, 0},
    {"AND", 60, Fn::And, 0},
    {"OR", 61, Fn::Or, 0},
    {"NOT", 62, Fn::Not, 0},
    {"EQB", 200, Fn::Eq, 1},
    {"EQW", 201, Fn::Eq, 2},
    {"EQD", 202, Fn::Eq, 4},
    {"NEB", 203, Fn::Ne, 1},
    {"NEW", 204, Fn::Ne, 2},
    {"NED", 205, Fn::Ne, 4},
    {"GTB", 206, Fn::Gt, 1},
    {"GTW", 207, Fn::Gt, 2},
    {"GTD", 208, Fn::Gt, 4},
    {"LTB", 209, Fn::Lt, 1},
    {"LTW", 210, Fn::Lt, 2},
    {"LTD", 211, Fn::Lt, 4},
    {"GEB", 212, Fn::Ge, 1},
    {"GEW", 213, Fn::Ge, 2},
    {"GED", 214, Fn::Ge, 4},
    {"LEB", 215, Fn::Le, 1},
    {"LEW", 216, Fn::Le, 2},
    {"LED", 217, Fn::Le, 4},
    {"JMPB", 68, Fn::Jmpb, 0},
    {"LBL", 69, Fn::Lbl, 0},
    {"CALL", 65, Fn::Call, 0},
    {"CALLU", 66, Fn::Callu, 0},
    // Rows whose checks and statements live in the family files (TimerCounter.cpp,
    // DataFunctional.cpp, ArithFunctional.cpp), reached through emitFunctional's hooks.
    {"TMR", 3, Fn::Unsupported, 0},
    {"TMRC", 54, Fn::Unsupported, 0},
    {"CTR", 5, Fn::Unsupported, 0},
    {"CTRB", 56, Fn::Unsupported, 0},
    {"CTRC", 55, Fn::Unsupported, 0},
    {"XMOVB", 35, Fn::Unsupported, 0},
    {"XMOV", 18, Fn::Unsupported, 0},
    {"COMPB", 32, Fn::Unsupported, 0},
    {"COMP", 15, Fn::Unsupported, 0},
    {"COIN", 16, Fn::Unsupported, 0},
    {"RNGB", 218, Fn::Unsupported, 0},
    {"RNGW", 219, Fn::Unsupported, 0},
    {"RNGD", 220, Fn::Unsupported, 0},
    {"DSCHB", 34, Fn::Unsupported, 0},
    {"DSCH", 17, Fn::Unsupported, 0},
    {"PARI", 11, Fn::Unsupported, 0},
    {"SFT", 33, Fn::Unsupported, 0},
    {"COD", 7, Fn::Unsupported, 0},
    {"CODB", 27, Fn::Unsupported, 0},
    {"DCNV", 14, Fn::Unsupported, 0},
    {"DCNVB", 31, Fn::Unsupported, 0},
    {"DEC", 4, Fn::Unsupported, 0},
    {"DECB", 25, Fn::Unsupported, 0},
    {"ADDB", 36, Fn::Unsupported, 0},
    {"SUBB", 37, Fn::Unsupported, 0},
    {"MULB", 38, Fn::Unsupported, 0},
    {"DIVB", 39, Fn::Unsupported, 0},
    {"ADD", 19, Fn::Unsupported, 0},
    {"SUB", 20, Fn::Unsupported, 0},
    {"MUL", 21, Fn::Unsupported, 0},
    {"DIV", 22, Fn::Unsupported, 0},
    {"NUMEB", 40, Fn::Unsupported, 0},
    {"NUME", 23, Fn::Unsupported, 0},
    {"COM", 9, Fn::Unsupported, 0},
    {"COME", 29, Fn::Unsupported, 0},
    {"JMP", 10, Fn::Unsupported, 0},
    {"JMPE", 30, Fn::Unsupported, 0},
    {"JMPC", 73, Fn::Jmpc, 0},
    {"ROT", 6, Fn::Unsupported, 0},
    {"ROTB", 26, Fn::Unsupported, 0},
    {"DISPB", 41, Fn::Unsupported, 0},
    {"EXIN", 42, Fn::Unsupported, 0},
    {"WINDR", 51, Fn::Unsupported, 0},
    {"WINDW", 52, Fn::Unsupported, 0},
    {"AXCTL", 53, Fn::Unsupported, 0},
    {"PSGNL", 50, Fn::Unsupported, 0},
    {"PSGN2", 63, Fn::Unsupported, 0},
    {"CS", 74, Fn::Cs, 0},
    {"CM", 75, Fn::Cm, 0},
    {"CE", 76, Fn::Ce, 0},
    {"NOP", -1, Fn::Unsupported, 0}, // no SUB number (reference 6.1, L1451)
};

// Names that are also basic instructions (AND, OR) or SUB itself are functional only as SUB n:
// `SUB` followed by a number is always that syntax, so the BCD subtract is written `SUB 20`.
bool byNameOk(std::string_view n) { return n != "AND" && n != "OR" && n != "SUB"; }

const FnRow *rowByName(std::string_view n) {
  if (!byNameOk(n)) return nullptr;
  for (const FnRow &r : kRows)
    if (n == r.name) return &r;
  return nullptr;
}

const FnRow *rowBySub(int64_t sub) {
  for (const FnRow &r : kRows)
    if (r.sub == sub) return &r;
  return nullptr;
}

/// The parameter count each instruction takes, and what they are.
struct Shape {
  int count;
  const char *roles;
};
Shape shapeOf(Fn f) {
  switch (f) {
  case Fn::Tmrb:
  case Fn::Tmrbf:
    return {2, "timer number, set time (ms)"};
  case Fn::Difu:
  case Fn::Difd:
    return {1, "edge number"};
  case Fn::Movb:
  case Fn::Movw:
  case Fn::Movd:
    return {2, "source address, destination address"};
  case Fn::Movn:
    return {3, "byte count, source address, destination address"};
  case Fn::Move:
    return {4, "mask high 4 bits, mask low 4 bits, input address, output address"};
  case Fn::Movor:
    return {3, "input address, OR-data address, output address"};
  case Fn::Eor:
  case Fn::And:
  case Fn::Or:
    return {4, "format, input address, operand, output address"};
  case Fn::Not:
    return {3, "format, input address, output address"};
  case Fn::Jmpb:
  case Fn::Jmpc:
  case Fn::Lbl:
    return {1, "label"};
  case Fn::Call:
  case Fn::Callu:
    return {1, "subroutine"};
  case Fn::Cs:
    return {1, "index address"};
  case Fn::Cm:
    return {1, "subroutine"};
  case Fn::Ce:
    return {0, ""};
  case Fn::Unsupported:
    break;
  default:
    return {2, "data 1, data 2"};
  }
  return {0, ""};
}

/// A 4-digit nibble written in binary (`0001`) as MOVE's mask halves are (reference 6.5).
bool nibble(Emitter &e, const Token &t, int &out) {
  out = 0;
  auto bad = [&] {
    e.error(t.loc, "LJ4002",
            "a MOVE mask half is 4 binary digits (like 0001), got '" + std::string(t.text) + "'");
    return false;
  };
  if (t.text.size() != 4) return bad();
  for (char c : t.text) {
    if (c != '0' && c != '1') return bad();
    out = out * 2 + (c - '0');
  }
  return true;
}

/// The `□00△` format of EOR/AND/OR (and `000△` of NOT): operand kind and width.
bool format(Emitter &e, const Token &t, bool allowAddress, bool &isAddr, int &width) {
  int64_t v;
  if (!e.constant(t, 0, 9999, "format", v)) return false;
  width = static_cast<int>(v % 10);
  const int64_t kind = v / 1000, middle = (v / 10) % 100;
  if ((width != 1 && width != 2 && width != 4) || middle != 0 || kind > (allowAddress ? 1 : 0)) {
    e.error(t.loc, "LJ4046",
            std::string("format '") + std::string(t.text) + "': expected " +
                (allowAddress ? "0001/0002/0004 (constant) or 1001/1002/1004 (address)"
                              : "0001, 0002 or 0004"));
    return false;
  }
  isAddr = kind == 1;
  return true;
}

/// CS / CM / CE (docs/fanuc-pmc.md [EXT] select-call): CS pushes ACT on MS; each CM k re-reads
/// it, ANDs "index = k" (CompareEq, 2-byte) and calls its subroutine when the result is 1; CE
/// pops MS. Built from existing operations, so every engine runs it the same way.
void selectCall(Emitter &e, Fn fn, const std::string &what, SourceLoc at,
                const std::vector<Token> &p) {
  FlowRegions &rg = e.regions();
  Operand a;
  if (fn == Fn::Cs) {
    if (rg.csLine != at.line || rg.csOk) {
      e.error(at, "LJ4047",
              what + " inside the CS list opened on line " + std::to_string(rg.csLine) +
                  " (CS..CE lists do not nest; close it with CE first)");
      return;
    }
    if (!e.dataOperand(p[0], 2, false, false, a)) return;
    rg.csCount = 0;
    rg.csIndex = a;
    rg.csOk = true;
    e.emit(Op::BranchPush, at, {});
    return;
  }
  if (rg.csLine == 0) {
    e.error(at, "LJ4048", what + " outside a CS..CE list (it must follow a CS)");
    return;
  }
  if (fn == Fn::Ce) {
    rg.csLine = 0;
    if (!rg.csOk) return;
    e.emit(Op::BranchPop, at, {});
    e.setDepth(1);
    return;
  }
  if (!e.labelOperand(p[0], Area::Subroutine, a) || !rg.csOk) return;
  Operand k;
  k.kind = Operand::Kind::Const;
  k.value = rg.csCount++;
  k.loc = p[0].loc;
  e.emit(Op::BranchRead, at, {});
  e.emit(Op::CompareEq, at, {rg.csIndex, k});
  e.emit(Op::Call, at, {a});
  e.setDepth(1);
}

} // namespace

const char *functionalName(int64_t sub) {
  for (const FnRow &r : kRows)
    if (r.sub == sub && sub >= 0) return r.name;
  return nullptr;
}

void closeSelect(Emitter &e, std::string_view marker, SourceLoc at) {
  FlowRegions &rg = e.regions();
  if (rg.csLine > 0)
    e.error(at, "LJ4049",
            "CS on line " + std::to_string(rg.csLine) + " has no CE before " + std::string(marker));
  rg.csLine = 0;
}

bool insideSelect(Emitter &e, std::string_view head, int64_t sub, SourceLoc at) {
  FlowRegions &rg = e.regions();
  if (rg.csLine == 0 || head == "CS" || head == "CM" || head == "CE" || sub == 74 || sub == 75 ||
      sub == 76)
    return false;
  e.error(at, "LJ4050",
          "only CM lines may stand between CS (line " + std::to_string(rg.csLine) +
              ") and CE, got " + std::string(head));
  return true;
}

bool isFunctionalName(std::string_view name) { return rowByName(name) != nullptr; }

void emitFunctional(Emitter &e, const Functional &f) {
  const FnRow *row = nullptr;
  std::string what;
  if (!f.number.text.empty()) {
    int64_t n;
    if (!e.constant(f.number, 0, 9999, "SUB number", n)) return;
    row = rowBySub(n);
    if (!row) {
      e.error(f.number.loc, "LJ4051", "unknown functional instruction SUB " + std::to_string(n));
      return;
    }
    what = "SUB " + std::to_string(n) + " (" + row->name + ")";
  } else {
    row = rowByName(upper(f.head.text));
    what = row->name;
  }
  const SourceLoc at = f.head.loc;
  auto notYet = [&] {
    e.error(at, "LJ4003",
            what + " is not implemented in this build (docs/fanuc-pmc.md \"Not yet\")");
  };
  if (emitTimerCounter(e, f, row->sub, what)) return; // TimerCounter.cpp
  if (row->fn == Fn::Unsupported && emitDataFunctional(e, f, row->name, what)) return;
  if (row->fn == Fn::Unsupported && emitArithFunctional(e, f, row->sub, what)) return;
  if (row->fn == Fn::Unsupported) return notYet();
  if (row->fn == Fn::Cs && e.regions().csLine == 0) {
    // Open the list before CS's own checks so its CM/CE lines do not report again.
    e.regions().csLine = at.line;
    e.regions().csOk = false;
  }
  const Shape shape = shapeOf(row->fn);
  if (static_cast<int>(f.params.size()) != shape.count) {
    e.error(at, "LJ4052",
            what + " takes " + std::to_string(shape.count) + " parameters (" + shape.roles +
                "), got " + std::to_string(f.params.size()));
    return;
  }
  const auto &p = f.params;
  const bool needsAct =
      row->fn != Fn::Callu && row->fn != Fn::Lbl && row->fn != Fn::Cm && row->fn != Fn::Ce;
  if (needsAct && e.depth() < 1) {
    e.error(at, "LJ4053", what + " needs its ACT input in ST0 (an RD before it)");
    return;
  }
  if ((row->fn == Fn::Call || row->fn == Fn::Callu || row->fn == Fn::Cs) && e.level() == 1) {
    e.error(at, "LJ4054", what + ": level 1 cannot call subroutines (reference 4.2, L877)");
    return;
  }
  Operand a, b, c;
  auto konst = [](int64_t v) {
    Operand o;
    o.kind = Operand::Kind::Const;
    o.value = static_cast<int32_t>(v);
    return o;
  };
  switch (row->fn) {
  case Fn::Tmrb:
  case Fn::Tmrbf: {
    int64_t n, ms;
    if (!e.constant(p[0], 1, kTmrbTimers, "timer number", n) ||
        !e.constant(p[1], 1, 32767000, "set time (ms)", ms) || !e.claimNumber('T', n, p[0].loc))
      return;
    Operand num = konst(n);
    num.loc = p[0].loc;
    Operand t = konst(ms);
    t.loc = p[1].loc;
    e.emit(row->fn == Fn::Tmrb ? Op::OnDelayTimer : Op::OffDelayTimer, at, {num, konst(0), t});
    return;
  }
  case Fn::Difu:
  case Fn::Difd: {
    int64_t n;
    // Edge numbers 1..1000 (reference 1 specification table, 6.8).
    if (!e.constant(p[0], 1, kDifEdges, "edge number", n) || !e.claimNumber('E', n, p[0].loc))
      return;
    Operand num = konst(n);
    num.loc = p[0].loc;
    e.emit(row->fn == Fn::Difu ? Op::RisePulse : Op::FallPulse, at, {num});
    return;
  }
  case Fn::Movb:
  case Fn::Movw:
  case Fn::Movd:
    if (!e.dataOperand(p[0], row->width, false, false, a) ||
        !e.dataOperand(p[1], row->width, false, true, b))
      return;
    e.emit(Op::Move, at, {a, b});
    return;
  case Fn::Movn: {
    int64_t n;
    if (!e.constant(p[0], 1, 200, "byte count", n) ||
        !e.dataOperand(p[1], static_cast<int>(n), false, false, a) ||
        !e.dataOperand(p[2], static_cast<int>(n), false, true, b))
      return;
    // n one-byte moves in ascending address order (docs/fanuc-pmc.md [INF] MOVN).
    for (int64_t k = 0; k < n; ++k) {
      Operand s = a, d = b;
      s.index += static_cast<int32_t>(k);
      s.width = 1;
      d.index += static_cast<int32_t>(k);
      d.width = 1;
      e.emit(Op::Move, at, {s, d});
    }
    return;
  }
  case Fn::Move: {
    int hi, lo;
    if (!nibble(e, p[0], hi) || !nibble(e, p[1], lo) || !e.dataOperand(p[2], 1, false, false, a) ||
        !e.dataOperand(p[3], 1, false, true, c))
      return;
    e.emit(Op::BitAnd, at, {a, konst(hi << 4 | lo), c});
    return;
  }
  case Fn::Movor:
    if (!e.dataOperand(p[0], 1, false, false, a) || !e.dataOperand(p[1], 1, false, false, b) ||
        !e.dataOperand(p[2], 1, false, true, c))
      return;
    e.emit(Op::BitOr, at, {a, b, c});
    return;
  case Fn::Eor:
  case Fn::And:
  case Fn::Or: {
    bool isAddr;
    int w;
    if (!format(e, p[0], true, isAddr, w) || !e.dataOperand(p[1], w, false, false, a)) return;
    if (isAddr ? !e.dataOperand(p[2], w, false, false, b) : !e.dataOperand(p[2], w, true, false, b))
      return;
    if (!isAddr && b.kind != Operand::Kind::Const) {
      e.error(p[2].loc, "LJ4055",
              "format " + std::string(p[0].text) + " says the operand is a constant");
      return;
    }
    if (!e.dataOperand(p[3], w, false, true, c)) return;
    const Op op = row->fn == Fn::Eor ? Op::BitXor : row->fn == Fn::And ? Op::BitAnd : Op::BitOr;
    e.emit(op, at, {a, b, c});
    return;
  }
  case Fn::Not: {
    bool isAddr;
    int w;
    if (!format(e, p[0], false, isAddr, w) || !e.dataOperand(p[1], w, false, false, a) ||
        !e.dataOperand(p[2], w, false, true, c))
      return;
    e.emit(Op::BitXor, at, {a, konst(-1), c}); // bit by bit: x ^ all ones
    return;
  }
  case Fn::Eq:
  case Fn::Gt:
  case Fn::Lt:
  case Fn::Ge:
  case Fn::Le:
    if (!e.dataOperand(p[0], row->width, true, false, a) ||
        !e.dataOperand(p[1], row->width, true, false, b))
      return;
    switch (row->fn) {
    case Fn::Eq:
      e.emit(Op::CompareEq, at, {a, b});
      break;
    case Fn::Lt:
      e.emit(Op::CompareLt, at, {a, b});
      break;
    case Fn::Le:
      e.emit(Op::CompareLe, at, {a, b});
      break;
    case Fn::Gt: // data1 > data2  <=>  data2 < data1
      e.emit(Op::CompareLt, at, {b, a});
      break;
    default: // Ge: data2 <= data1
      e.emit(Op::CompareLe, at, {b, a});
      break;
    }
    return;
  case Fn::Ne:
    return notYet();
  case Fn::Jmpb:
    if (!e.labelOperand(p[0], Area::Label, a)) return;
    e.emit(Op::Jump, at, {a});
    return;
  case Fn::Jmpc:
    // From a subroutine to a level-2 label (reference 4.2 [EXT]); the verifier finds the
    // label among level 2's and checks that JMPC stands in a subroutine.
    if (!e.labelOperand(p[0], Area::Label, a)) return;
    e.emit(Op::JumpOut, at, {a});
    return;
  case Fn::Lbl:
    if (!e.labelOperand(p[0], Area::Label, a)) return;
    e.setDepth(0);
    e.emit(Op::Label, at, {a});
    return;
  case Fn::Call:
  case Fn::Callu:
    if (!e.labelOperand(p[0], Area::Subroutine, a)) return;
    if (row->fn == Fn::Callu) e.emit(Op::LoadTrue, at, {});
    e.emit(Op::Call, at, {a});
    return;
  case Fn::Cs:
  case Fn::Cm:
  case Fn::Ce:
    selectCall(e, row->fn, what, at, p);
    return;
  case Fn::Unsupported:
    break;
  }
}

} // namespace lj::fanuc::detail

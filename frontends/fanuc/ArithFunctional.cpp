// The FANUC arithmetic and constant instructions (fanuc-c; reference 6.10 [EXT], 6.2, 3.1, 3.2;
// docs/fanuc-pmc.md "Arithmetic"): ADDB/SUBB/MULB/DIVB (binary, R9000 flags, DIVB remainder in
// R9002..), ADD/SUB/MUL/DIV (BCD, BYT at run time), NUMEB (binary constant, mapped onto a move
// of a constant) and NUME (BCD constant). Parameters are checked with located errors and mapped
// onto the fanuc-c rows of ir/OpTable.h. Control inputs are loaded top to bottom, so ACT is
// ST0, RST ST1, BYT ST2 (reference 5); an instruction with k inputs pops k - 1 and leaves W1
// (NUME: ACT) in ST0. The BCD subtract is reachable only as `SUB 20`: `SUB` followed by a
// number is always the functional-instruction syntax (Functional.cpp).
#include "frontends/fanuc/ParserInternal.h"
#include "ir/PmcArith.h"

#include <string>

namespace lj::fanuc::detail {

namespace {

struct Spec {
  int sub;
  const char *name;
  int op;     ///< pmc::kArith* (NUMEB, NUME: -1)
  bool bcd;   ///< the BCD family (BYT input)
  int params; ///< parameter count
  const char *roles;
  const char *inputs; ///< control inputs, top to bottom
  int inputCount;
};

constexpr Spec kSpecs[] = {
    {36, "ADDB", pmc::kArithAdd, false, 4,
     "format, operand 1 address, operand 2 (constant or address), result address", "RST, ACT", 2},
    {37, "SUBB", pmc::kArithSub, false, 4,
     "format, operand 1 address, operand 2 (constant or address), result address", "RST, ACT", 2},
    {38, "MULB", pmc::kArithMul, false, 4,
     "format, operand 1 address, operand 2 (constant or address), result address", "RST, ACT", 2},
    {39, "DIVB", pmc::kArithDiv, false, 4,
     "format, operand 1 address, operand 2 (constant or address), result address", "RST, ACT", 2},
    {19, "ADD", pmc::kArithAdd, true, 4,
     "operand 2 format (0 constant, 1 address), operand 1 address, operand 2, result address",
     "BYT, RST, ACT", 3},
    {20, "SUB", pmc::kArithSub, true, 4,
     "operand 2 format (0 constant, 1 address), operand 1 address, operand 2, result address",
     "BYT, RST, ACT", 3},
    {21, "MUL", pmc::kArithMul, true, 4,
     "operand 2 format (0 constant, 1 address), operand 1 address, operand 2, result address",
     "BYT, RST, ACT", 3},
    {22, "DIV", pmc::kArithDiv, true, 4,
     "operand 2 format (0 constant, 1 address), operand 1 address, operand 2, result address",
     "BYT, RST, ACT", 3},
    {40, "NUMEB", -1, false, 3, "format 1/2/4, constant, output address", "ACT", 1},
    {23, "NUME", -1, true, 2, "BCD constant 0..9999, output address", "BYT, ACT", 2},
};

/// The `□00△` format of the binary arithmetic: operand 2's kind (thousands digit: 0 constant,
/// 1 address) and the data length (units digit: 1, 2, 4 bytes), reference 6.2.
bool arithFormat(Emitter &e, const Token &t, bool &isAddr, int &width) {
  int64_t v;
  if (!e.constant(t, 0, 9999, "format", v)) return false;
  width = static_cast<int>(v % 10);
  if ((width != 1 && width != 2 && width != 4) || (v / 10) % 100 != 0 || v / 1000 > 1) {
    e.error(t.loc, "LJ4059",
            "format '" + std::string(t.text) +
                "': expected 0001/0002/0004 (operand 2 a constant) or 1001/1002/1004 "
                "(an address)");
    return false;
  }
  isAddr = v >= 1000;
  return true;
}

/// Whether token `t` is written as a number (a constant rather than an address).
bool numeric(const Token &t) {
  const std::string_view s = t.text;
  return !s.empty() && ((s[0] >= '0' && s[0] <= '9') || s[0] == '-' || s[0] == '+');
}

/// ADDB..DIVB: [format □00△ | operand 1 | operand 2 | result] -> BinaryArith.
bool binary(Emitter &e, const Spec &sp, const Functional &f, SourceLoc at) {
  const auto &p = f.params;
  bool isAddr;
  int w;
  Operand a, b, c;
  if (!arithFormat(e, p[0], isAddr, w) || !e.dataOperand(p[1], w, false, false, a)) return false;
  if (!isAddr && !numeric(p[2])) {
    e.error(p[2].loc, "LJ4060",
            "format " + std::string(p[0].text) + " says operand 2 is a constant, got '" +
                std::string(p[2].text) + "'");
    return false;
  }
  if (!e.dataOperand(p[2], w, !isAddr, false, b) || !e.dataOperand(p[3], w, false, true, c))
    return false;
  e.emit(Op::BinaryArith, at,
         {konst(sp.op, p[0].loc), a, b, c, implied(Area::Relay, pmc::kFlagsRelay, 1, at),
          implied(Area::Relay, pmc::kRemainderRelay, w, at)});
  return true;
}

/// ADD..DIV: [format 0/1 | operand 1 | operand 2 | result], 2 bytes each in the program (BYT
/// picks 1 or 2 at run time, as COMP does) -> BcdArith.
bool bcd(Emitter &e, const Spec &sp, const Functional &f, SourceLoc at) {
  const auto &p = f.params;
  int64_t fmt, v;
  Operand a, b, c;
  if (!e.constant(p[0], 0, 1, "operand 2 format (0 constant, 1 address)", fmt) ||
      !e.dataOperand(p[1], 2, false, false, a))
    return false;
  if (fmt == 0) {
    if (!e.constant(p[2], 0, 9999, "operand 2 (decimal constant, format 0)", v)) return false;
    b = konst(v, p[2].loc);
  } else if (!e.dataOperand(p[2], 2, false, false, b)) {
    return false;
  }
  if (!e.dataOperand(p[3], 2, false, true, c)) return false;
  e.emit(Op::BcdArith, at, {konst(sp.op, p[0].loc), a, b, c});
  return true;
}

/// NUMEB: [length 1/2/4 | constant | output] -> a move of the constant.
bool numeb(Emitter &e, const Functional &f, SourceLoc at) {
  const auto &p = f.params;
  int64_t w, v;
  if (!e.constant(p[0], 1, 4, "format (data length)", w)) return false;
  if (w == 3) {
    e.error(p[0].loc, "LJ4061", "format '3': expected 1, 2 or 4");
    return false;
  }
  const int width = static_cast<int>(w);
  // A signed value of the length's bytes (reference 3.1).
  const std::string role =
      "constant for " + std::to_string(width) + " byte" + (width == 1 ? "" : "s");
  if (!numeric(p[1])) {
    e.error(p[1].loc, "LJ4062", "NUMEB writes a constant, got '" + std::string(p[1].text) + "'");
    return false;
  }
  Operand c;
  if (!e.constant(p[1], pmc::minOf(width), pmc::maxOf(width), role.c_str(), v) ||
      !e.dataOperand(p[2], width, false, true, c))
    return false;
  e.emit(Op::Move, at, {konst(v, p[1].loc), c});
  return true;
}

/// NUME: [BCD constant | output] -> BcdConstant with the constant's BCD pattern.
bool nume(Emitter &e, const Functional &f, SourceLoc at) {
  const auto &p = f.params;
  int64_t v;
  Operand c;
  if (!e.constant(p[0], 0, 9999, "BCD constant (at most 4 digits)", v) ||
      !e.dataOperand(p[1], 2, false, true, c))
    return false;
  e.emit(Op::BcdConstant, at, {konst(detail::toBcd(v), p[0].loc), c});
  return true;
}

} // namespace

bool emitArithFunctional(Emitter &e, const Functional &f, int sub, const std::string &what) {
  const Spec *sp = nullptr;
  for (const Spec &s : kSpecs)
    if (s.sub == sub) sp = &s;
  if (!sp) return false;
  const SourceLoc at = f.head.loc;
  if (static_cast<int>(f.params.size()) != sp->params) {
    e.error(at, "LJ4063",
            what + " takes " + std::to_string(sp->params) + " parameters (" + sp->roles +
                "), got " + std::to_string(f.params.size()));
    return true;
  }
  if (e.depth() < sp->inputCount) {
    if (sp->inputCount == 1)
      e.error(at, "LJ4064", what + " needs its ACT input in ST0 (an RD before it)");
    else
      e.error(
          at, "LJ4065",
          what + " needs its inputs " + sp->inputs + " in ST" + std::to_string(sp->inputCount - 1) +
              "..ST0 (RD, then RD.STK for each further input), found " + std::to_string(e.depth()));
    return true;
  }
  bool ok;
  if (sp->op < 0)
    ok = sp->bcd ? nume(e, f, at) : numeb(e, f, at);
  else
    ok = sp->bcd ? bcd(e, *sp, f, at) : binary(e, *sp, f, at);
  if (ok) e.setDepth(e.depth() - (sp->inputCount - 1));
  return true;
}

const char *spellArith(Op op) {
  switch (op) {
  case Op::BinaryArith:
    return "ADDB/SUBB/MULB/DIVB";
  case Op::BcdArith:
    return "ADD/SUB/MUL/DIV";
  case Op::BcdConstant:
    return "NUME";
  default:
    return nullptr;
  }
}

} // namespace lj::fanuc::detail

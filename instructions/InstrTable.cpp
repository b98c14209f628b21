// The rows of the instruction table, one per mnemonic, from hnc8-core.md and
// hnc8-functions-1/-2.md (summary tables). Adding an instruction = one row here + its two
// semantics (interpreter, lowering) + tests.
#include "instructions/InstrTable.h"

#include <cctype>
#include <cstring>

namespace lj {

namespace {

constexpr int64_t kI32Min = INT32_MIN;
constexpr int64_t kI32Max = INT32_MAX;

// Operand position builders.
constexpr OperandSpec bitRead(const char *role) {
  return {role, kContactAreas, true, false, 0, 0, false};
}
constexpr OperandSpec bitWrite(const char *role) {
  return {role, kCoilAreas, true, false, 0, 0, true};
}
constexpr OperandSpec src(const char *role) {
  return {role, kSrcAreas, false, true, kI32Min, kI32Max, false};
}
constexpr OperandSpec dst(const char *role) { return {role, kDstAreas, false, false, 0, 0, true}; }
/// Read and written in place (INC, DEC, NEG): the destination areas.
constexpr OperandSpec inout(const char *role) { return dst(role); }
constexpr OperandSpec konst(const char *role, int64_t lo, int64_t hi) {
  return {role, 0, false, true, lo, hi, false};
}
constexpr OperandSpec label() { return {"label", areas(Area::L), false, false, 0, 0, false}; }
constexpr OperandSpec sub() { return {"subroutine", areas(Area::S), false, false, 0, 0, false}; }
constexpr OperandSpec preset() {
  return {
      "preset", areas(Area::R, Area::W, Area::D, Area::B, Area::P), false, true, kI32Min, kI32Max,
      false};
}
constexpr OperandSpec none() { return {nullptr, 0, false, false, 0, 0, false}; }

// Timer/counter numbers are constants 0..427; the gap 128..299 is rejected by the verifier.
constexpr OperandSpec tcNumber(const char *role) { return konst(role, 0, 427); }

using SR = StackRule;
using IR = InputRule;
using OR_ = OutputRule;
using SK = StateKind;

#define ROW(op, stack, in, k, out, st, n, o0, o1, o2, o3, text)                                    \
  InstrInfo { Op::op, #op, SR::stack, IR::in, k, OR_::out, SK::st, n, {o0, o1, o2, o3}, text }
#define ROWN(op, name, stack, in, k, out, st, n, o0, o1, o2, o3, text)                             \
  InstrInfo { Op::op, name, SR::stack, IR::in, k, OR_::out, SK::st, n, {o0, o1, o2, o3}, text }

constexpr InstrInfo kTable[] = {
    ROW(LD, Push, None, 0, None, None, 1, bitRead("contact"), none(), none(), none(),
        "push the bit"),
    ROW(LDI, Push, None, 0, None, None, 1, bitRead("contact"), none(), none(), none(),
        "push the inverted bit"),
    ROW(LDT, Push, None, 0, None, None, 0, none(), none(), none(), none(), "push 1"),
    ROW(LDP, Push, None, 0, None, Edge, 1, bitRead("contact"), none(), none(), none(),
        "push the rising edge of the bit"),
    ROW(LDF, Push, None, 0, None, Edge, 1, bitRead("contact"), none(), none(), none(),
        "push the falling edge of the bit"),
    ROW(AND, Combine, None, 0, None, None, 1, bitRead("contact"), none(), none(), none(),
        "ST0 := ST0 and bit"),
    ROW(ANI, Combine, None, 0, None, None, 1, bitRead("contact"), none(), none(), none(),
        "ST0 := ST0 and not bit"),
    ROW(OR, Combine, None, 0, None, None, 1, bitRead("contact"), none(), none(), none(),
        "ST0 := ST0 or bit"),
    ROW(ORI, Combine, None, 0, None, None, 1, bitRead("contact"), none(), none(), none(),
        "ST0 := ST0 or not bit"),
    ROW(ANDP, Combine, None, 0, None, Edge, 1, bitRead("contact"), none(), none(), none(),
        "ST0 := ST0 and rising edge"),
    ROW(ANDF, Combine, None, 0, None, Edge, 1, bitRead("contact"), none(), none(), none(),
        "ST0 := ST0 and falling edge"),
    ROW(ORP, Combine, None, 0, None, Edge, 1, bitRead("contact"), none(), none(), none(),
        "ST0 := ST0 or rising edge"),
    ROW(ORF, Combine, None, 0, None, Edge, 1, bitRead("contact"), none(), none(), none(),
        "ST0 := ST0 or falling edge"),
    ROW(ANB, BlockPop, None, 0, None, None, 0, none(), none(), none(), none(),
        "pop, ST0 := ST1 and ST0"),
    ROW(ORB, BlockPop, None, 0, None, None, 0, none(), none(), none(), none(),
        "pop, ST0 := ST1 or ST0"),
    ROW(MPS, MpsPush, None, 0, None, None, 0, none(), none(), none(), none(), "MS push ST0"),
    ROW(MRD, MsRead, None, 0, None, None, 0, none(), none(), none(), none(), "ST0 := top(MS)"),
    ROW(MPP, MsPop, None, 0, None, None, 0, none(), none(), none(), none(), "ST0 := pop(MS)"),
    ROW(OUT, Coil, None, 0, None, None, 1, bitWrite("coil"), none(), none(), none(), "bit := ST0"),
    ROW(OOUT, Coil, None, 0, None, None, 1, bitWrite("coil"), none(), none(), none(),
        "bit := not ST0"),
    ROW(SET, Coil, None, 0, None, None, 1, bitWrite("coil"), none(), none(), none(),
        "bit := bit or ST0"),
    ROW(RST, Coil, None, 0, None, None, 1, bitWrite("coil"), none(), none(), none(),
        "bit := bit and not ST0"),

    ROW(IEND, Structural, None, 0, None, None, 0, none(), none(), none(), none(),
        "end of the init part"),
    ROWN(END1, "1END", Structural, None, 0, None, None, 0, none(), none(), none(), none(),
         "end of PLC1"),
    ROWN(END2, "2END", Structural, None, 0, None, None, 0, none(), none(), none(), none(),
         "end of PLC2"),
    ROW(JMP, Block, Required, 1, None, None, 1, label(), none(), none(), none(),
        "jump to the label when ST0 = 1"),
    ROW(LBL, Structural, None, 0, None, None, 1, label(), none(), none(), none(), "jump target"),
    ROW(CALL, Block, Optional, 1, None, None, 1, sub(), none(), none(), none(),
        "call the subroutine when ST0 = 1"),
    ROW(SP, Structural, None, 0, None, None, 1, sub(), none(), none(), none(),
        "start of a subroutine"),
    ROW(SPE, Structural, None, 0, None, None, 0, none(), none(), none(), none(),
        "end of a subroutine"),
    ROW(RETN, Block, Optional, 1, None, None, 0, none(), none(), none(), none(),
        "return from the subroutine when ST0 = 1"),
    ROW(LOOP, Structural, None, 0, None, None, 1, src("loop count"), none(), none(), none(),
        "repeat the body up to NEXT count times"),
    ROW(NEXT, Structural, None, 0, None, None, 0, none(), none(), none(), none(),
        "end of a loop body"),

    ROW(ADD, Block, Required, 1, Enable, None, 3, src("augend"), src("addend"), dst("destination"),
        none(), "dst := a + b"),
    ROW(SUB, Block, Required, 1, Enable, None, 3, src("minuend"), src("subtrahend"),
        dst("destination"), none(), "dst := a - b"),
    ROW(MUL, Block, Required, 1, Enable, None, 3, src("multiplicand"), src("multiplier"),
        dst("destination"), none(), "dst := a * b"),
    ROW(DIV, Block, Required, 1, Enable, None, 3, src("dividend"), src("divisor"),
        dst("destination"), none(), "dst := a / b (b = 0: nothing written, output 0)"),
    ROW(INC, Block, Required, 1, Enable, None, 1, inout("operand"), none(), none(), none(),
        "x := x + 1"),
    ROW(DEC, Block, Required, 1, Enable, None, 1, inout("operand"), none(), none(), none(),
        "x := x - 1"),
    ROW(WAND, Block, Required, 1, Enable, None, 3, src("operand 1"), src("operand 2"),
        dst("destination"), none(), "dst := a & b"),
    ROW(WOR, Block, Required, 1, Enable, None, 3, src("operand 1"), src("operand 2"),
        dst("destination"), none(), "dst := a | b"),
    ROW(WXOR, Block, Required, 1, Enable, None, 3, src("operand 1"), src("operand 2"),
        dst("destination"), none(), "dst := a ^ b"),
    ROW(NEG, Block, Required, 1, Enable, None, 1, inout("operand"), none(), none(), none(),
        "x := -x"),

    ROW(CMP, Block, Optional, 1, Compare, None, 2, src("compared data"), src("reference"), none(),
        none(), "out := EN and a <= b"),
    ROW(LT, Block, Optional, 1, Compare, None, 2, src("compared data"), src("reference"), none(),
        none(), "out := EN and a < b"),
    ROW(ACMP, Block, Optional, 1, Compare, None, 3, src("lower limit"), src("upper limit"),
        src("compared data"), none(), "out := EN and lo < x < hi"),
    ROW(COIN, Block, Optional, 1, Compare, None, 2, src("reference"), src("compared data"), none(),
        none(), "out := EN and a == b"),

    ROW(MOV, Block, Optional, 1, Enable, None, 2, src("source"), dst("destination"), none(), none(),
        "dst := src"),

    ROW(CTR, Block, Required, 4, Result, Edge, 2,
        (OperandSpec{"count register", areas(Area::R, Area::W, Area::D, Area::B), false, false, 0,
                     0, true}),
        preset(), none(), none(), "up/down ring counter, value in a register"),
    ROW(CTRC, Block, Required, 2, Result, Counter, 2, tcNumber("counter number"), preset(), none(),
        none(), "ring counter Cn counting up from 0"),
    ROW(CTUD, Block, Required, 4, Result, Counter, 2, tcNumber("counter number"), preset(), none(),
        none(), "up/down ring counter Cn with start value 0/1"),
    ROW(TMRB, Block, Required, 1, Result, Timer, 3, tcNumber("timer number"),
        konst("time unit", 0, 3),
        (OperandSpec{"time length", areas(Area::R, Area::W, Area::D, Area::P), false, true, kI32Min,
                     kI32Max, false}),
        none(), "on-delay timer Tn"),
    ROW(STMR, Block, Required, 1, Result, Timer, 3, tcNumber("timer number"),
        konst("time unit", 0, 3),
        (OperandSpec{"time length", areas(Area::R, Area::W, Area::D, Area::P), false, true, kI32Min,
                     kI32Max, false}),
        none(), "off-delay timer Tn"),

    ROW(PLS, Block, Optional, 1, Result, Pls, 1, konst("edge block number", 0, 511), none(), none(),
        none(), "out := EN and not previous EN"),
    ROW(PLF, Block, Optional, 1, Result, Plf, 1, konst("edge block number", 0, 511), none(), none(),
        none(), "out := not EN and previous EN"),
    ROW(ALT, Block, Required, 1, Result, Alt, 1, konst("toggle block number", 0, 511), none(),
        none(), none(), "toggle the held output on each rising edge of EN"),
};

#undef ROW
#undef ROWN

static_assert(sizeof(kTable) / sizeof(kTable[0]) == kOpCount, "one row per Op");

constexpr bool rowsInOrder() {
  for (int i = 0; i < kOpCount; ++i)
    if (static_cast<int>(kTable[i].op) != i) return false;
  return true;
}
static_assert(rowsInOrder(), "rows are in Op order");

bool equalsNoCase(std::string_view a, const char *b) {
  size_t n = std::strlen(b);
  if (a.size() != n) return false;
  for (size_t i = 0; i < n; ++i)
    if (std::toupper(static_cast<unsigned char>(a[i])) != b[i]) return false;
  return true;
}

} // namespace

const InstrInfo &instrInfo(Op op) { return kTable[static_cast<int>(op)]; }

std::span<const InstrInfo> instrTable() { return {kTable, static_cast<size_t>(kOpCount)}; }

bool lookupMnemonic(std::string_view m, Op &out) {
  for (const InstrInfo &row : kTable) {
    if (equalsNoCase(m, row.mnemonic)) {
      out = row.op;
      return true;
    }
  }
  struct Alias {
    const char *name;
    Op op;
  };
  static constexpr Alias kAliases[] = {{"WRT", Op::OUT}, {"END1", Op::END1}, {"END2", Op::END2}};
  for (const Alias &a : kAliases) {
    if (equalsNoCase(m, a.name)) {
      out = a.op;
      return true;
    }
  }
  return false;
}

} // namespace lj

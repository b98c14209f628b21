// The instruction set as a table (STYLE.md 7): read by the parser, the verifier, the
// interpreter, the lowering and the fuzzer's program generator.
#pragma once

#include "instructions/Area.h"

#include <cstdint>
#include <span>
#include <string_view>

namespace lj {

/// Every mnemonic the engine knows. Aliases (WRT, END1, END2) map onto these.
enum class Op : uint8_t {
  // basic (hnc8-core.md 4.2)
  LD,
  LDI,
  LDT,
  LDP,
  LDF,
  AND,
  ANI,
  OR,
  ORI,
  ANDP,
  ANDF,
  ORP,
  ORF,
  ANB,
  ORB,
  MPS,
  MRD,
  MPP,
  OUT,
  OOUT,
  SET,
  RST,
  // flow (hnc8-functions-1.md 3.5)
  IEND,
  END1,
  END2,
  JMP,
  LBL,
  CALL,
  SP,
  SPE,
  RETN,
  LOOP,
  NEXT,
  // math (3.2)
  ADD,
  SUB,
  MUL,
  DIV,
  INC,
  DEC,
  WAND,
  WOR,
  WXOR,
  NEG,
  // compare (3.6, functions-2 1.x)
  CMP,
  LT,
  ACMP,
  COIN,
  // moves (functions-2 2.1)
  MOV,
  // counters (3.3), timers (3.4)
  CTR,
  CTRC,
  CTUD,
  TMRB,
  STMR,
  // edge and toggle blocks (functions-2 2.14-2.16)
  PLS,
  PLF,
  ALT,
  Count_
};

constexpr int kOpCount = static_cast<int>(Op::Count_);

/// How an instruction moves the ST / MS stacks (DIALECT.md 3 and 5).
enum class StackRule : uint8_t {
  Push,       ///< LD-type: push a bit
  Combine,    ///< AND/OR-type: ST0 := ST0 op bit; needs depth >= 1
  BlockPop,   ///< ANB/ORB: pop one, combine into ST0; needs depth >= 2
  MpsPush,    ///< MPS: MS push ST0
  MsRead,     ///< MRD: ST0 := top(MS)
  MsPop,      ///< MPP: ST0 := pop(MS)
  Coil,       ///< OUT/OOUT/SET/RST: read ST0, leave ST; needs depth >= 1
  Structural, ///< IEND/1END/2END/SP/SPE/LBL/LOOP/NEXT: both stacks emptied
  Block,      ///< function block: input(s) from ST, output by OutputRule
};

/// Whether a block needs a power-flow input (前置).
enum class InputRule : uint8_t { None, Optional, Required };

/// What a block leaves in ST (后置), applied after popping its `inputs`.
enum class OutputRule : uint8_t {
  None,    ///< leaves ST unchanged (后置 ×); with an empty ST nothing is pushed
  Enable,  ///< ST0 := EN (math/move pass-through; DIV by zero gives 0)
  Compare, ///< ST0 := EN and condition
  Result,  ///< ST0 := the block's own result (timers, PLS/PLF/ALT)
};

/// Kind of persistent state an instruction instance owns.
enum class StateKind : uint8_t { None, Edge, Timer, Counter, Pls, Plf, Alt };

/// Operand position: which syntactic forms and areas are accepted.
struct OperandSpec {
  const char *role;   ///< shown in diagnostics ("destination", "preset"...)
  AreaMask areas;     ///< registers (or bit addresses) allowed; L / S for labels, subroutines
  bool isBit;         ///< a bit address `A12.3` (contacts, coils)
  bool constOk;       ///< a decimal/hex constant is accepted
  int64_t cmin, cmax; ///< constant range (inclusive)
  bool writes;        ///< the instruction writes this operand (areas must be writable)
};

/// One row of the instruction table.
struct InstrInfo {
  Op op;
  const char *mnemonic;
  StackRule stack;
  InputRule input;
  uint8_t inputs; ///< ST entries a block consumes (1, or 2/4 for counters)
  OutputRule output;
  StateKind state;
  uint8_t operandCount;
  OperandSpec operands[4];
  const char *summary;
};

/// The row of `op`.
const InstrInfo &instrInfo(Op op);

/// All rows, in Op order.
std::span<const InstrInfo> instrTable();

/// Op named by `mnemonic` (case-insensitive, aliases WRT/END1/END2 included).
bool lookupMnemonic(std::string_view mnemonic, Op &out);

// Area groups used by the table and by tests.
constexpr AreaMask kContactAreas = areas(Area::X, Area::Y, Area::F, Area::G, Area::R, Area::W,
                                         Area::D, Area::B, Area::P, Area::T, Area::C);
constexpr AreaMask kCoilAreas = areas(Area::Y, Area::G, Area::R, Area::W, Area::D, Area::B);
constexpr AreaMask kSrcAreas =
    areas(Area::X, Area::Y, Area::F, Area::G, Area::R, Area::W, Area::D, Area::B, Area::P);
constexpr AreaMask kDstAreas = kCoilAreas;

} // namespace lj

// The instruction set as a table (STYLE.md 7): read by the parser, the verifier, the
// interpreter, the lowering and the fuzzer's program generator.
#pragma once

#include "ir/Area.h"

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
  // data operations (functions-2 2.2-2.13, 2.17-2.18): family Data
  XMOV,
  BMOV,
  FMOV,
  XCH,
  ZRST,
  ENCO,
  DECO,
  COD,
  SER,
  ASSEM,
  DISAS,
  ACVT,
  PTN,
  NTP,
  // NC services: chapter-4 CNC blocks (functions-1 3.1, functions-2 2.19-2.23) and the chapter-6
  // blocks that call the host or keep state (cnc-interface 3.4): family Nc
  MGET,
  MACK,
  TGET,
  TACK,
  RTOMPG,
  TEMPSEN,
  PARTCNT,
  PARTCLR,
  HEADSEN,
  VARGET,
  VARSET,
  TOOLSET,
  TOOLCLR,
  NIXIE,
  TOOLUSE,
  TOOLLIFE,
  TOOL,
  SPDA,
  SUBAXEN,
  MPGSET,
  ROT,
  EVENT,
  SAVEDATA,
  // chapter-6 CNC blocks acting on F/G words through the CNC table (cnc-interface 2): family Cnc
  MDST,
  MDGT,
  MDI,
  MST,
  CYCLE,
  STOP,
  RESET,
  CHANSW,
  HOLD,
  CYCLED,
  HOLDLED,
  ESCBLK,
  RPOVRD,
  FEEDOVRD,
  SPDLOVRD,
  STEPMUL,
  DRYRUN,
  SKIP,
  USERIN,
  USEROUT,
  SELSTOP,
  SPDLJOG,
  SPDLBUS,
  SPDLBUS1,
  SPDLORI,
  SPDLOROK,
  SPDLZERO,
  SPDLRCH,
  DESYN,
  JOGSW,
  STEPAXIS,
  JOGVEL,
  HOMRUN,
  HOMERUN1,
  HOMESW,
  HOMLED,
  AXEN,
  AXRDY,
  AXISLOCK,
  AXISMOVE,
  AXISMVTO,
  AXLMF2,
  AXISPLMT,
  AXISNLMT,
  SVSW,
  AXISMODE,
  REFPT,
  AXISHOM2,
  AXMOVING,
  ALARM,
  RSTCHK,
  RSTCLR,
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

/// Kind of persistent state an instruction instance owns. Words: two consecutive
/// lj_state.inst_word entries per instance (slot, slot + 1).
enum class StateKind : uint8_t { None, Edge, Timer, Counter, Pls, Plf, Alt, Words };

/// Which part of the engines implements an instruction (interpreter and lowering dispatch on
/// it): Core = the original set, Data = data operations, Nc = NC services (host callbacks,
/// chapter-4 CNC blocks), Cnc = chapter-6 blocks driven by the CNC F/G table.
enum class Family : uint8_t { Core, Data, Nc, Cnc };

/// Most operands an instruction takes (PTN / NTP).
constexpr int kMaxOperands = 9;

/// Operand position: which syntactic forms and areas are accepted.
struct OperandSpec {
  const char *role;    ///< shown in diagnostics ("destination", "preset"...)
  AreaMask areas;      ///< registers (or bit addresses) allowed; L / S for labels, subroutines
  bool isBit;          ///< a bit address `A12.3` (contacts, coils)
  bool constOk;        ///< a decimal/hex constant is accepted
  int64_t cmin, cmax;  ///< constant range (inclusive)
  bool writes;         ///< the instruction writes this operand (areas must be writable)
  bool wordOk = false; ///< isBit positions only: a whole register is accepted too (ZRST)
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
  OperandSpec operands[kMaxOperands];
  const char *summary;
};

/// Family of `op` (by its position in the Op enum).
constexpr Family opFamily(Op op) {
  if (op >= Op::XMOV && op <= Op::NTP) return Family::Data;
  if (op >= Op::MGET && op <= Op::SAVEDATA) return Family::Nc;
  if (op >= Op::MDST && op < Op::Count_) return Family::Cnc;
  return Family::Core;
}

/// The row of `op`.
const InstrInfo &instrInfo(Op op);

/// All rows, in Op order.
std::span<const InstrInfo> instrTable();

/// Whether `op` is a contact (LD LDI AND ANI OR ORI and the edge contacts): the instructions an
/// online-monitor force applies to (hnc8-core.md 6.1 RESOLUTION (a), Stmt::force).
constexpr bool isContact(Op op) { return (op >= Op::LD && op <= Op::ORF) && op != Op::LDT; }

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

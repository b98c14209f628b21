// The semantic instruction set as a table (STYLE.md 7): what each operation does to the stacks,
// its operands and state, read by the verifier, the interpreter, the lowering, the generator and
// the front ends. No dialect spelling here: a front end maps its mnemonics onto these rows
// (frontends/hnc8/Mnemonics.cpp for HNC-8) and spells them through its DialectText (ir/Program.h).
//
// Dialect-only rows: a row is spelled by at least one dialect, not necessarily HNC-8
// (tests/catalogue checks "every row is spelled by some front end; the HNC-8 ones are in the
// HNC-8 manual"). To add an operation only FANUC or IEC has: append the enumerator and its row
// (InstrInfo::name is the neutral name every dump and diagnostic falls back to), return its
// mnemonic from that front end's DialectText::spell, and leave the HNC-8 mnemonic table, its
// docs and its generator alone (they cover only what hnc8::spells()). A dialect's spelling of any
// op: spelling(&dialect, op) (never null); whether it has one: spells(dialect, op).
#pragma once

#include "ir/Area.h"

#include <cstdint>
#include <span>

namespace lj {

/// Every operation the engines run, named by what it does (the HNC-8 spelling of each HNC-8 op is
/// in frontends/hnc8/Mnemonics.cpp; dialect-only ops are appended in blocks after ResetClear).
enum class Op : uint8_t {
  // basic (hnc8-core.md 4.2)
  Load,
  LoadNot,
  LoadTrue,
  LoadRise,
  LoadFall,
  And,
  AndNot,
  Or,
  OrNot,
  AndRise,
  AndFall,
  OrRise,
  OrFall,
  AndBlock,
  OrBlock,
  BranchPush,
  BranchRead,
  BranchPop,
  Coil,
  CoilNot,
  Set,
  Reset,
  // flow (hnc8-functions-1.md 3.5)
  EndInit,
  EndCyclic,
  EndSliced,
  Jump,
  Label,
  Call,
  SubBegin,
  SubEnd,
  Return,
  LoopBegin,
  LoopEnd,
  // math (3.2)
  Add,
  Subtract,
  Multiply,
  Divide,
  Increment,
  Decrement,
  BitAnd,
  BitOr,
  BitXor,
  Negate,
  // compare (3.6, functions-2 1.x)
  CompareLe,
  CompareLt,
  CompareRange,
  CompareEq,
  // moves (functions-2 2.1)
  Move,
  // counters (3.3), timers (3.4)
  RegisterCounter,
  RingCounter,
  UpDownCounter,
  OnDelayTimer,
  OffDelayTimer,
  // edge and toggle blocks (functions-2 2.14-2.16)
  RisePulse,
  FallPulse,
  Toggle,
  // data operations (functions-2 2.2-2.13, 2.17-2.18): family Data
  IndexedMove,
  BlockMove,
  Fill,
  Exchange,
  ZoneReset,
  TableEncode,
  TableDecode,
  TableLookup,
  TableSearch,
  Pack,
  Unpack,
  RangeConvert,
  PointToNumber,
  NumberToPoint,
  // NC services: chapter-4 CNC blocks (functions-1 3.1, functions-2 2.19-2.23) and the chapter-6
  // blocks that call the host or keep state (cnc-interface 3.4): family Nc
  MCodeGet,
  MCodeAck,
  TCodeGet,
  TCodeAck,
  HandwheelPulse,
  TempSensor,
  PartCount,
  PartClear,
  HeadSensors,
  VarGet,
  VarSet,
  ToolVectorOn,
  ToolVectorOff,
  PanelDisplay,
  ToolInUse,
  ToolLife,
  ToolSelect,
  SpindleAnalog,
  SlaveHomingEnable,
  HandwheelSet,
  MagazineRotate,
  RaiseEvent,
  SaveRetained,
  // chapter-6 CNC blocks acting on F/G words through the CNC table (cnc-interface 2): family Cnc
  ChannelModeSet,
  ChannelModeGet,
  MdiMode,
  MstLock,
  CycleStart,
  EmergencyStop,
  ChannelReset,
  ChannelSwitch,
  FeedHold,
  CycleStartLamp,
  FeedHoldLamp,
  SkipG31,
  RapidOverride,
  FeedOverride,
  SpindleOverride,
  StepMultiplier,
  DryRun,
  BlockSkip,
  UserInput,
  UserOutput,
  OptionalStop,
  SpindleJog,
  BusSpindle,
  BusSpindleGeared,
  SpindleOrient,
  SpindleOrientDone,
  SpindleZeroSpeed,
  SpindleSpeedReached,
  SlaveRelease,
  AxisJog,
  AxisStep,
  JogSpeed,
  HomingStart,
  HomingStartDir,
  HomeDog,
  HomingDoneLamp,
  AxisEnable,
  AxisReady,
  AxisLock,
  AxisMoveRelative,
  AxisMoveAbsolute,
  SecondSoftLimit,
  PositiveLimitDog,
  NegativeLimitDog,
  ServoEnable,
  AxisControlMode,
  ReferencePoint,
  AxisHoming,
  AxisMoving,
  Alarm,
  ResetRequested,
  ResetClear,
  // iec3 (issue 16): the Neza function blocks %TMi / %Ci (modicon-neza.md 3, docs/iec-il.md
  // "Function blocks"); their whole state lives in the block's words (TimerData / CounterData)
  IecTimer,
  IecCounter,
  // ---- fanuc-a: FANUC PMC timers, counters, compares (family PmcTc; no HNC-8 spelling) ----
  PmcTimer,        ///< TMR: on-delay, preset and precision in the T area
  PmcTimerAddr,    ///< TMRC: on-delay, preset and work register at any address
  PmcCounter,      ///< CTR / CTRB / CTRC: CN0, UPDOWN, RST, ACT; preset and value operands
  PmcCompareFlags, ///< COMPB: Z / N bits of a flags byte (R9000)
  BcdCompare,      ///< COMP (<=) / COIN (==) on BCD data
  CompareNe,       ///< NEB / NEW / NED
  CompareBetween,  ///< RNGB / RNGW / RNGD: between two bounds in either order
  // ---- fanuc-b: FANUC PMC transfer, search, conversion and flow (docs/fanuc-pmc.md) ----
  ParityCheck,     ///< PARI: W1 = parity error of a byte
  ShiftWord,       ///< SFT: 16-bit shift by one bit
  BcdDecode,       ///< DEC: W1 = ACT and the BCD byte matches
  GroupDecode,     ///< DECB: one bit per value of 8 n consecutive values
  BcdConvert,      ///< DCNV: binary <-> BCD, 1 or 2 bytes (BYT at run time)
  BcdConvertExt,   ///< DCNVB: binary <-> BCD, 1/2/4 bytes, sign and R9000 flags
  CodeTable,       ///< COD: BCD index into a BCD constant table
  CodeTableBinary, ///< CODB: binary index into a binary constant table
  TableRows,       ///< the constant rows after a COD/CODB (no effect of their own)
  IndexedTable,    ///< XMOVB: read/write nn items of a table in memory
  SearchTable,     ///< DSCHB: index of the first table item equal to the search data
  CommonBegin,     ///< COM: the coils up to COME are written 0 while ACT = 0
  CommonCoil,      ///< WRT/WRT.NOT/SET/RST between COM and COME
  // ---- fanuc-c: FANUC PMC arithmetic (docs/fanuc-pmc.md "Arithmetic"; ir/PmcArith.h) ----
  BinaryArith,     ///< ADDB..DIVB: signed 1/2/4-byte arithmetic, R9000 flags, W1 = error
  BcdArith,        ///< ADD..DIV: 2- or 4-digit BCD arithmetic (BYT at run time), W1 = error
  BcdConstant,     ///< NUME: a BCD constant written as 1 or 2 bytes (BYT at run time)
  BcdIndexedTable, ///< XMOV: read/write one BCD table item at a BCD index (width by BYT)
  BcdSearchTable,  ///< DSCH: BCD index of the first table item equal to the search data
  // ---- FANUC PMC flow (docs/fanuc-pmc.md "JMPC (SUB 73)") ----
  JumpOut, ///< JMPC: leave the subroutine and its callers, go on at a label of the sliced part
  // ---- rot: FANUC PMC rotation control (docs/fanuc-pmc.md "Rotation control") ----
  BcdRotation,    ///< ROT: direction and goal/steps of a rotor, BCD positions (width by BYT)
  BinaryRotation, ///< ROTB: the same with binary positions and the position count in memory
  // ---- cl31: ClassicLadder timers, monostables, counters (family ClassicLadder; ir/ClBlocks.h)
  ClClock,      ///< the scan clock: the ms this scan advances ClassicLadder's timers
  ClTimer,      ///< old timer %Tn (E, C inputs; D, R outputs)
  ClMonostable, ///< monostable %Mn
  ClCounter,    ///< counter %Cn (R, P, U, D inputs; E, D, F outputs)
  ClIecTimer,   ///< IEC timer %TMn (TON, TOF, TP)
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
enum class Family : uint8_t {
  Core,
  Data,
  Nc,
  Cnc,
  PmcTc, ///< fanuc-a: FANUC timers/counters/compares (interp/InterpPmcTc.cpp, EmitPmcTc.cpp)
  ClassicLadder, ///< cl31: ClassicLadder's blocks (InterpClassicLadder.cpp, EmitClassicLadder.cpp)
};

/// Most operands an instruction takes (PTN / NTP).
constexpr int kMaxOperands = 9;

/// An inclusive range of constant values.
struct ValueRange {
  int32_t lo, hi;
};

/// Operand position: which syntactic forms and areas are accepted.
struct OperandSpec {
  const char *role;    ///< shown in diagnostics ("destination", "preset"...)
  AreaMask areas;      ///< registers (or bit addresses) allowed; L / S for labels, subroutines
  bool isBit;          ///< a bit address `A12.3` (contacts, coils)
  bool constOk;        ///< a decimal/hex constant is accepted
  int64_t cmin, cmax;  ///< constant range (inclusive)
  bool writes;         ///< the instruction writes this operand (areas must be writable)
  bool wordOk = false; ///< isBit positions only: a whole register is accepted too (ZRST)
  /// Register operands: consecutive elements the operand touches (a P parameter block, a byte
  /// pair); the verifier checks the last one exists, the generator keeps room for them.
  uint8_t span = 1;
  /// Constants: when not empty, the only values accepted (cmin..cmax has gaps).
  std::span<const ValueRange> values = {};
};

/// Whether constant `v` is one of `spec`'s values (always, when the spec has no value set).
inline bool inValueSet(const OperandSpec &spec, int64_t v) {
  if (spec.values.empty()) return true;
  for (const ValueRange &r : spec.values)
    if (v >= r.lo && v <= r.hi) return true;
  return false;
}

/// One row of the instruction table.
struct InstrInfo {
  Op op;
  const char *name; ///< the neutral name (the enumerator), for dumps and messages of a dialect
                    ///< without a spelling of the op
  Family family;    ///< which part of the engines implements it
  StackRule stack;
  InputRule input;
  uint8_t inputs; ///< ST entries a block consumes (1, or 2/4 for counters)
  OutputRule output;
  StateKind state;
  uint8_t operandCount;
  OperandSpec operands[kMaxOperands];
  const char *summary;
};

/// The row of `op`.
const InstrInfo &instrInfo(Op op);

/// All rows, in Op order.
std::span<const InstrInfo> instrTable();

/// Family of `op` (the row's column).
inline Family opFamily(Op op) { return instrInfo(op).family; }

/// Whether `op` is a contact (a basic push or combine of one bit operand, edge contacts
/// included): the instructions an online-monitor force applies to (hnc8-core.md 6.1 RESOLUTION
/// (a), ir/Forces.h).
inline bool isContact(Op op) {
  const InstrInfo &r = instrInfo(op);
  return r.family == Family::Core &&
         (r.stack == StackRule::Push || r.stack == StackRule::Combine) && r.operandCount == 1 &&
         r.operands[0].isBit;
}

// Area groups used by the table and by tests. The roles only byte-addressed targets have
// (kByteRoles) are in every group: a profile without them gives them count 0, so no operand of
// its programs can name them; whether one is writable is the profile's AreaInfo::writable.
constexpr AreaMask kByteRoles =
    areas(Area::KeepRelay, Area::ExtraRelay, Area::MessageBits, Area::TimerData, Area::CounterData,
          Area::DataTable, Area::SystemBits, Area::SystemWords, Area::ConstWords);
constexpr AreaMask kContactAreas =
    areas(Area::Input, Area::Output, Area::NcStatus, Area::NcControl, Area::Relay, Area::Word,
          Area::DWord, Area::Retained, Area::Param, Area::Timer, Area::Counter) |
    kByteRoles;
constexpr AreaMask kCoilAreas =
    areas(Area::Output, Area::NcControl, Area::Relay, Area::Word, Area::DWord, Area::Retained) |
    kByteRoles;
constexpr AreaMask kSrcAreas =
    areas(Area::Input, Area::Output, Area::NcStatus, Area::NcControl, Area::Relay, Area::Word,
          Area::DWord, Area::Retained, Area::Param) |
    kByteRoles;
constexpr AreaMask kDstAreas = kCoilAreas;

} // namespace lj

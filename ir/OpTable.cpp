// The rows of the instruction table, one per mnemonic, from hnc8-core.md and
// hnc8-functions-1/-2.md (summary tables). Adding an instruction = one row here + its two
// semantics (interpreter, lowering) + tests.
#include "ir/OpTable.h"

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
constexpr OperandSpec label() { return {"label", areas(Area::Label), false, false, 0, 0, false}; }
constexpr OperandSpec sub() {
  return {"subroutine", areas(Area::Subroutine), false, false, 0, 0, false};
}
constexpr OperandSpec preset() {
  return {"preset", areas(Area::Relay, Area::Word, Area::DWord, Area::Retained, Area::Param),
          false,    true,
          kI32Min,  kI32Max,
          false};
}
constexpr OperandSpec none() { return {nullptr, 0, false, false, 0, 0, false}; }

// Builders of the data, NC and CNC rows.
constexpr AreaMask kIndirectAreas =
    areas(Area::NcControl, Area::Relay, Area::Word, Area::DWord, Area::Retained);
constexpr AreaMask kBitSrcAreas =
    areas(Area::Input, Area::Output, Area::NcStatus, Area::NcControl, Area::Relay, Area::Word,
          Area::DWord, Area::Param, Area::Retained);
/// A register (never a constant) from `mask`.
constexpr OperandSpec reg(const char *role, AreaMask mask, bool writes) {
  return {role, mask, false, false, 0, 0, writes};
}
/// A constant or a register from `mask`, written by the instruction when `writes`.
constexpr OperandSpec regOrConst(const char *role, AreaMask mask, bool writes) {
  return {role, mask, false, true, kI32Min, kI32Max, writes};
}
constexpr OperandSpec i32Const(const char *role) { return konst(role, kI32Min, kI32Max); }
constexpr OperandSpec bitDir(const char *role) {
  return {role, kBitSrcAreas, true, false, 0, 0, false};
}
/// ZRST bounds: a bit address or a whole register of a writable area.
constexpr OperandSpec zoneBound(const char *role) {
  return {role, kDstAreas, true, false, 0, 0, true, true};
}
constexpr OperandSpec chan() { return konst("channel", 0, 3); }
constexpr OperandSpec axis() { return konst("axis", 0, 31); }
constexpr OperandSpec spindle() { return konst("spindle", 0, 3); }
/// A constant 0..31 or any readable register holding the axis number.
constexpr OperandSpec axisAny() { return {"axis", kSrcAreas, false, true, 0, 31, false}; }
constexpr OperandSpec gear() {
  return regOrConst(
      "gear",
      areas(Area::Output, Area::NcControl, Area::Relay, Area::Word, Area::DWord, Area::Retained),
      false);
}
constexpr OperandSpec pblock() { return reg("parameter block", areas(Area::Param), false); }

// Timer/counter numbers are constants 0..427; the gap 128..299 is rejected by the verifier.
constexpr OperandSpec tcNumber(const char *role) { return konst(role, 0, 427); }

using SR = StackRule;
using IR = InputRule;
using OR_ = OutputRule;
using SK = StateKind;

#define ROW(op, name, stack, in, k, out, st, n, o0, o1, o2, o3, text)                              \
  InstrInfo { Op::op, name, SR::stack, IR::in, k, OR_::out, SK::st, n, {o0, o1, o2, o3}, text }

// Rows with more than four operands.
#define ROWX(op, name, stack, in, k, out, st, n, text, ...)                                        \
  InstrInfo { Op::op, name, SR::stack, IR::in, k, OR_::out, SK::st, n, {__VA_ARGS__}, text }

constexpr InstrInfo kTable[] = {
    ROW(Load, "LD", Push, None, 0, None, None, 1, bitRead("contact"), none(), none(), none(),
        "push the bit"),
    ROW(LoadNot, "LDI", Push, None, 0, None, None, 1, bitRead("contact"), none(), none(), none(),
        "push the inverted bit"),
    ROW(LoadTrue, "LDT", Push, None, 0, None, None, 0, none(), none(), none(), none(), "push 1"),
    ROW(LoadRise, "LDP", Push, None, 0, None, Edge, 1, bitRead("contact"), none(), none(), none(),
        "push the rising edge of the bit"),
    ROW(LoadFall, "LDF", Push, None, 0, None, Edge, 1, bitRead("contact"), none(), none(), none(),
        "push the falling edge of the bit"),
    ROW(And, "AND", Combine, None, 0, None, None, 1, bitRead("contact"), none(), none(), none(),
        "ST0 := ST0 and bit"),
    ROW(AndNot, "ANI", Combine, None, 0, None, None, 1, bitRead("contact"), none(), none(), none(),
        "ST0 := ST0 and not bit"),
    ROW(Or, "OR", Combine, None, 0, None, None, 1, bitRead("contact"), none(), none(), none(),
        "ST0 := ST0 or bit"),
    ROW(OrNot, "ORI", Combine, None, 0, None, None, 1, bitRead("contact"), none(), none(), none(),
        "ST0 := ST0 or not bit"),
    ROW(AndRise, "ANDP", Combine, None, 0, None, Edge, 1, bitRead("contact"), none(), none(),
        none(), "ST0 := ST0 and rising edge"),
    ROW(AndFall, "ANDF", Combine, None, 0, None, Edge, 1, bitRead("contact"), none(), none(),
        none(), "ST0 := ST0 and falling edge"),
    ROW(OrRise, "ORP", Combine, None, 0, None, Edge, 1, bitRead("contact"), none(), none(), none(),
        "ST0 := ST0 or rising edge"),
    ROW(OrFall, "ORF", Combine, None, 0, None, Edge, 1, bitRead("contact"), none(), none(), none(),
        "ST0 := ST0 or falling edge"),
    ROW(AndBlock, "ANB", BlockPop, None, 0, None, None, 0, none(), none(), none(), none(),
        "pop, ST0 := ST1 and ST0"),
    ROW(OrBlock, "ORB", BlockPop, None, 0, None, None, 0, none(), none(), none(), none(),
        "pop, ST0 := ST1 or ST0"),
    ROW(BranchPush, "MPS", MpsPush, None, 0, None, None, 0, none(), none(), none(), none(),
        "MS push ST0"),
    ROW(BranchRead, "MRD", MsRead, None, 0, None, None, 0, none(), none(), none(), none(),
        "ST0 := top(MS)"),
    ROW(BranchPop, "MPP", MsPop, None, 0, None, None, 0, none(), none(), none(), none(),
        "ST0 := pop(MS)"),
    ROW(Coil, "OUT", Coil, None, 0, None, None, 1, bitWrite("coil"), none(), none(), none(),
        "bit := ST0"),
    ROW(CoilNot, "OOUT", Coil, None, 0, None, None, 1, bitWrite("coil"), none(), none(), none(),
        "bit := not ST0"),
    ROW(Set, "SET", Coil, None, 0, None, None, 1, bitWrite("coil"), none(), none(), none(),
        "bit := bit or ST0"),
    ROW(Reset, "RST", Coil, None, 0, None, None, 1, bitWrite("coil"), none(), none(), none(),
        "bit := bit and not ST0"),

    ROW(EndInit, "IEND", Structural, None, 0, None, None, 0, none(), none(), none(), none(),
        "end of the init part"),
    ROW(EndCyclic, "1END", Structural, None, 0, None, None, 0, none(), none(), none(), none(),
        "end of PLC1"),
    ROW(EndSliced, "2END", Structural, None, 0, None, None, 0, none(), none(), none(), none(),
        "end of PLC2"),
    ROW(Jump, "JMP", Block, Required, 1, None, None, 1, label(), none(), none(), none(),
        "jump to the label when ST0 = 1"),
    ROW(Label, "LBL", Structural, None, 0, None, None, 1, label(), none(), none(), none(),
        "jump target"),
    ROW(Call, "CALL", Block, Optional, 1, None, None, 1, sub(), none(), none(), none(),
        "call the subroutine when ST0 = 1"),
    ROW(SubBegin, "SP", Structural, None, 0, None, None, 1, sub(), none(), none(), none(),
        "start of a subroutine"),
    ROW(SubEnd, "SPE", Structural, None, 0, None, None, 0, none(), none(), none(), none(),
        "end of a subroutine"),
    ROW(Return, "RETN", Block, Optional, 1, None, None, 0, none(), none(), none(), none(),
        "return from the subroutine when ST0 = 1"),
    ROW(LoopBegin, "LOOP", Structural, None, 0, None, None, 1, src("loop count"), none(), none(),
        none(), "repeat the body up to NEXT count times"),
    ROW(LoopEnd, "NEXT", Structural, None, 0, None, None, 0, none(), none(), none(), none(),
        "end of a loop body"),

    ROW(Add, "ADD", Block, Required, 1, Enable, None, 3, src("augend"), src("addend"),
        dst("destination"), none(), "dst := a + b"),
    ROW(Subtract, "SUB", Block, Required, 1, Enable, None, 3, src("minuend"), src("subtrahend"),
        dst("destination"), none(), "dst := a - b"),
    ROW(Multiply, "MUL", Block, Required, 1, Enable, None, 3, src("multiplicand"),
        src("multiplier"), dst("destination"), none(), "dst := a * b"),
    ROW(Divide, "DIV", Block, Required, 1, Enable, None, 3, src("dividend"), src("divisor"),
        dst("destination"), none(), "dst := a / b (b = 0: nothing written, output 0)"),
    ROW(Increment, "INC", Block, Required, 1, Enable, None, 1, inout("operand"), none(), none(),
        none(), "x := x + 1"),
    ROW(Decrement, "DEC", Block, Required, 1, Enable, None, 1, inout("operand"), none(), none(),
        none(), "x := x - 1"),
    ROW(BitAnd, "WAND", Block, Required, 1, Enable, None, 3, src("operand 1"), src("operand 2"),
        dst("destination"), none(), "dst := a & b"),
    ROW(BitOr, "WOR", Block, Required, 1, Enable, None, 3, src("operand 1"), src("operand 2"),
        dst("destination"), none(), "dst := a | b"),
    ROW(BitXor, "WXOR", Block, Required, 1, Enable, None, 3, src("operand 1"), src("operand 2"),
        dst("destination"), none(), "dst := a ^ b"),
    ROW(Negate, "NEG", Block, Required, 1, Enable, None, 1, inout("operand"), none(), none(),
        none(), "x := -x"),

    ROW(CompareLe, "CMP", Block, Optional, 1, Compare, None, 2, src("compared data"),
        src("reference"), none(), none(), "out := EN and a <= b"),
    ROW(CompareLt, "LT", Block, Optional, 1, Compare, None, 2, src("compared data"),
        src("reference"), none(), none(), "out := EN and a < b"),
    ROW(CompareRange, "ACMP", Block, Optional, 1, Compare, None, 3, src("lower limit"),
        src("upper limit"), src("compared data"), none(), "out := EN and lo < x < hi"),
    ROW(CompareEq, "COIN", Block, Optional, 1, Compare, None, 2, src("reference"),
        src("compared data"), none(), none(), "out := EN and a == b"),

    ROW(Move, "MOV", Block, Optional, 1, Enable, None, 2, src("source"), dst("destination"), none(),
        none(), "dst := src"),

    ROW(RegisterCounter, "CTR", Block, Required, 4, Result, Edge, 2,
        (OperandSpec{"count register", areas(Area::Relay, Area::Word, Area::DWord, Area::Retained),
                     false, false, 0, 0, true}),
        preset(), none(), none(), "up/down ring counter, value in a register"),
    ROW(RingCounter, "CTRC", Block, Required, 2, Result, Counter, 2, tcNumber("counter number"),
        preset(), none(), none(), "ring counter Cn counting up from 0"),
    ROW(UpDownCounter, "CTUD", Block, Required, 4, Result, Counter, 2, tcNumber("counter number"),
        preset(), none(), none(), "up/down ring counter Cn with start value 0/1"),
    ROW(OnDelayTimer, "TMRB", Block, Required, 1, Result, Timer, 3, tcNumber("timer number"),
        konst("time unit", 0, 3),
        (OperandSpec{"time length", areas(Area::Relay, Area::Word, Area::DWord, Area::Param), false,
                     true, kI32Min, kI32Max, false}),
        none(), "on-delay timer Tn"),
    ROW(OffDelayTimer, "STMR", Block, Required, 1, Result, Timer, 3, tcNumber("timer number"),
        konst("time unit", 0, 3),
        (OperandSpec{"time length", areas(Area::Relay, Area::Word, Area::DWord, Area::Param), false,
                     true, kI32Min, kI32Max, false}),
        none(), "off-delay timer Tn"),

    ROW(RisePulse, "PLS", Block, Optional, 1, Result, Pls, 1, konst("edge block number", 0, 511),
        none(), none(), none(), "out := EN and not previous EN"),
    ROW(FallPulse, "PLF", Block, Optional, 1, Result, Plf, 1, konst("edge block number", 0, 511),
        none(), none(), none(), "out := not EN and previous EN"),
    ROW(Toggle, "ALT", Block, Required, 1, Result, Alt, 1, konst("toggle block number", 0, 511),
        none(), none(), none(), "toggle the held output on each rising edge of EN"),

    // ---- Data operations (hnc8-functions-2.md 2.2-2.13, 2.17-2.18; summary section 5) ----
    ROW(IndexedMove, "XMOV", Block, Optional, 1, Enable, None, 4, konst("format 1", 0, 2),
        reg("address 1", kIndirectAreas, false), konst("format 2", 0, 2),
        reg("address 2", kIndirectAreas, true),
        "operand 2 := operand 1 (formats 0 reg, 1 B[], 2 P[])"),
    ROW(BlockMove, "BMOV", Block, Optional, 1, Enable, None, 3,
        reg("source start", kSrcAreas, false), dst("destination start"), konst("count", 1, 1000),
        none(), "copy count elements (memmove)"),
    ROW(Fill, "FMOV", Block, Optional, 1, None, None, 3, dst("destination start"),
        dst("destination end"), src("value"), none(), "fill start..end with the value"),
    ROW(Exchange, "XCH", Block, Optional, 1, None, None, 4, konst("format 1", 0, 2),
        reg("address 1", kIndirectAreas, true), konst("format 2", 0, 2),
        reg("address 2", kIndirectAreas, true), "exchange operand 1 and operand 2"),
    ROW(ZoneReset, "ZRST", Block, Optional, 1, Enable, None, 2, zoneBound("start"),
        zoneBound("end"), none(), none(), "reset the registers or bits start..end"),
    ROW(TableEncode, "ENCO", Block, Optional, 1, None, None, 4,
        reg("table start", kSrcAreas, false), konst("table length", 1, 32), src("value"),
        dst("destination"), "one-hot bit of the first table entry equal to the value"),
    ROW(TableDecode, "DECO", Block, Required, 1, None, None, 4,
        reg("table start", kSrcAreas, false), konst("table length", 1, 32), src("value"),
        dst("destination"), "table entry of the lowest set bit of the value"),
    ROW(TableLookup, "COD", Block, Required, 1, None, None, 4, reg("table start", kSrcAreas, false),
        konst("table length", 1, 1000), src("index"), dst("destination"),
        "destination := table[index]"),
    ROW(TableSearch, "SER", Block, Required, 1, Compare, None, 4,
        reg("table start", kSrcAreas, false), konst("table length", 1, 1000), src("value"),
        dst("index destination"),
        "index of the first table entry equal to the value; output = found"),
    ROW(Pack, "ASSEM", Block, Required, 1, None, None, 3, reg("source start", kSrcAreas, false),
        konst("count", 1, 32),
        reg("destination", areas(Area::NcControl, Area::Word, Area::DWord, Area::Retained), true),
        none(), "pack count registers into one"),
    ROW(Unpack, "DISAS", Block, Required, 1, None, None, 3,
        reg("source",
            areas(Area::NcStatus, Area::NcControl, Area::Word, Area::DWord, Area::Param,
                  Area::Retained),
            false),
        konst("count", 1, 32),
        reg("destination start", areas(Area::Output, Area::NcControl, Area::Relay, Area::Word),
            true),
        none(), "split one register into count registers"),
    ROW(RangeConvert, "ACVT", Block, Required, 1, None, None, 3, pblock(), src("value"),
        dst("destination"), none(), "linear range conversion with the P parameter block"),
    ROWX(PointToNumber, "PTN", Block, Optional, 1, None, None, 9,
         "destination := number of the first active point", dst("destination"), bitRead("point 1"),
         i32Const("number 1"), bitRead("point 2"), i32Const("number 2"), bitRead("point 3"),
         i32Const("number 3"), bitRead("point 4"), i32Const("number 4")),
    ROWX(NumberToPoint, "NTP", Block, Optional, 1, None, None, 9, "point i := (source == number i)",
         reg("source", kSrcAreas, false), i32Const("number 1"), bitWrite("point 1"),
         i32Const("number 2"), bitWrite("point 2"), i32Const("number 3"), bitWrite("point 3"),
         i32Const("number 4"), bitWrite("point 4")),

    // ---- NC services (functions-1 3.1, functions-2 2.19-2.23, cnc-interface 2 / 3.4) ----
    ROW(MCodeGet, "MGET", Block, Optional, 1, Compare, None, 2, chan(), konst("M code", 0, 32767),
        none(), none(), "out := EN and the channel requests the M code"),
    ROW(MCodeAck, "MACK", Block, Optional, 1, None, None, 2, chan(), konst("M code", 0, 32767),
        none(), none(), "acknowledge the M code"),
    ROW(TCodeGet, "TGET", Block, Optional, 1, Compare, None, 2, chan(),
        regOrConst("T code destination", kDstAreas, true), none(), none(),
        "out := EN and a T code is pending (stored in the destination)"),
    ROW(TCodeAck, "TACK", Block, Optional, 1, None, None, 1, chan(), none(), none(), none(),
        "acknowledge the channel's T code"),
    ROW(HandwheelPulse, "RTOMPG", Block, Optional, 1, None, None, 2, src("pulse register"),
        konst("handwheel", 0, 9), none(), none(),
        "pass the pulse register to the handwheel (host)"),
    ROW(TempSensor, "TEMPSEN", Block, Optional, 1, None, None, 4, konst("sensor", 0, 19),
        reg("X group", areas(Area::Input), false), konst("board type", 0, 4), pblock(),
        "temperature sensor input (host)"),
    ROW(PartCount, "PARTCNT", Block, Optional, 1, Enable, None, 1, chan(), none(), none(), none(),
        "part count of the channel + 1"),
    ROW(PartClear, "PARTCLR", Block, Optional, 1, Enable, None, 1, chan(), none(), none(), none(),
        "part count of the channel := 0"),
    ROW(HeadSensors, "HEADSEN", Block, Optional, 1, None, None, 3, konst("count", 1, 20),
        i32Const("enable"), reg("storage start", areas(Area::DWord), true), none(),
        "copy count temperatures to D registers when enable = 0"),
    ROW(VarGet, "VARGET", Block, Required, 1, Enable, None, 4, konst("variable type", 0, 9),
        src("offset"), konst("exponent", 0, 4), dst("result"), "read a CNC variable (host)"),
    ROW(VarSet, "VARSET", Block, Required, 1, Enable, None, 4, konst("variable type", 0, 9),
        src("offset"), konst("exponent", 0, 4), src("data source"), "write a CNC variable (host)"),
    ROW(ToolVectorOn, "TOOLSET", Block, Optional, 1, Enable, None, 1, chan(), none(), none(),
        none(), "tool-vector direction on (host)"),
    ROW(ToolVectorOff, "TOOLCLR", Block, Optional, 1, Enable, None, 1, chan(), none(), none(),
        none(), "tool-vector direction off (host)"),
    ROW(PanelDisplay, "NIXIE", Block, Required, 1, Enable, None, 3, src("value"),
        konst("width", 0, 1),
        reg("display", areas(Area::Output, Area::Relay, Area::Word, Area::DWord, Area::Retained),
            true),
        none(), "show the value on the panel display"),
    ROW(ToolInUse, "TOOLUSE", Block, Optional, 1, None, None, 2, src("channel"), src("tool"),
        none(), none(), "tool in use (host)"),
    ROW(ToolLife, "TOOLLIFE", Block, Optional, 1, None, Words, 3, chan(),
        konst("count", 1, kI32Max), reg("response", areas(Area::Relay), true), none(),
        "tool-install counter"),
    ROW(ToolSelect, "TOOL", Block, Optional, 1, Result, None, 4, src("spindle tool"),
        src("commanded tool"), dst("error"), dst("target pocket"),
        "select the pocket of the commanded tool (host)"),
    ROWX(SpindleAnalog, "SPDA", Block, Optional, 1, None, None, 5,
         "analog (DA) spindle (host scaling)", chan(), spindle(), gear(),
         reg("reference",
             areas(Area::Output, Area::NcControl, Area::Relay, Area::Word, Area::DWord,
                   Area::Retained),
             true),
         pblock()),
    ROW(SlaveHomingEnable, "SUBAXEN", Block, Required, 1, None, None, 1, axis(), none(), none(),
        none(), "slave-axis homing enable (host)"),
    ROW(HandwheelSet, "MPGSET", Block, Required, 1, None, None, 3, konst("handwheel", 0, 9),
        axisAny(), src("override"), none(), "handwheel axis and multiplier"),
    ROW(MagazineRotate, "ROT", Block, Optional, 5, Result, None, 4, konst("positions", 1, 32767),
        reg("current position", kSrcAreas, false), reg("target position", kSrcAreas, false),
        dst("result"), "rotary magazine direction and steps"),
    ROW(RaiseEvent, "EVENT", Block, Required, 1, None, Edge, 1, konst("event", 0, 255), none(),
        none(), none(), "raise a PLC event"),
    ROW(SaveRetained, "SAVEDATA", Block, Required, 1, None, Edge, 0, none(), none(), none(), none(),
        "save the retentive data (host)"),

    // ---- Chapter-6 blocks on F/G words (cnc-interface 2, summary section 4) ----
    ROW(ChannelModeSet, "MDST", Block, Optional, 1, None, None, 2, chan(), src("mode"), none(),
        none(), "channel mode set"),
    ROW(ChannelModeGet, "MDGT", Block, Optional, 1, None, None, 2, chan(), dst("mode destination"),
        none(), none(), "channel mode get"),
    ROW(MdiMode, "MDI", Block, Optional, 1, None, None, 1, chan(), none(), none(), none(),
        "MDI mode"),
    ROW(MstLock, "MST", Block, Required, 1, None, None, 1, chan(), none(), none(), none(),
        "lock MST"),
    ROW(CycleStart, "CYCLE", Block, Required, 1, None, None, 1, chan(), none(), none(), none(),
        "cycle start"),
    ROW(EmergencyStop, "STOP", Block, Required, 1, None, None, 1, chan(), none(), none(), none(),
        "emergency stop"),
    ROW(ChannelReset, "RESET", Block, Required, 1, None, None, 1, chan(), none(), none(), none(),
        "reset"),
    ROW(ChannelSwitch, "CHANSW", Block, Required, 1, None, None, 1, chan(), none(), none(), none(),
        "channel switch"),
    ROW(FeedHold, "HOLD", Block, Required, 1, None, None, 1, chan(), none(), none(), none(),
        "feed hold"),
    ROW(CycleStartLamp, "CYCLED", Block, Optional, 1, Compare, None, 1, chan(), none(), none(),
        none(), "cycle-start lamp"),
    ROW(FeedHoldLamp, "HOLDLED", Block, Optional, 1, Compare, None, 1, chan(), none(), none(),
        none(), "feed-hold lamp"),
    ROW(SkipG31, "ESCBLK", Block, Optional, 1, None, None, 2, chan(), konst("G31 number", 0, 32767),
        none(), none(), "G31 skip"),
    ROW(RapidOverride, "RPOVRD", Block, Optional, 1, None, None, 2, chan(), src("override"), none(),
        none(), "rapid override set"),
    ROW(FeedOverride, "FEEDOVRD", Block, Optional, 1, None, None, 2, chan(), src("override"),
        none(), none(), "feed override set"),
    ROW(SpindleOverride, "SPDLOVRD", Block, Optional, 1, None, None, 3, chan(), spindle(),
        src("override"), none(), "spindle override set"),
    ROW(StepMultiplier, "STEPMUL", Block, Optional, 1, None, None, 2, axis(), src("multiplier"),
        none(), none(), "increment multiplier set"),
    ROW(DryRun, "DRYRUN", Block, Required, 1, None, None, 1, chan(), none(), none(), none(),
        "dry run"),
    ROW(BlockSkip, "SKIP", Block, Required, 1, None, None, 1, chan(), none(), none(), none(),
        "block skip"),
    ROW(UserInput, "USERIN", Block, Required, 1, None, None, 3, chan(), i32Const("group"),
        konst("bit", 0, 31), none(), "user input bit"),
    ROW(UserOutput, "USEROUT", Block, Optional, 1, None, None, 3, chan(), i32Const("unused"),
        reg("output start", areas(Area::Output, Area::Relay), true), none(),
        "user outputs to 4 bytes"),
    ROW(OptionalStop, "SELSTOP", Block, Required, 1, None, None, 1, chan(), none(), none(), none(),
        "optional stop"),
    ROW(SpindleJog, "SPDLJOG", Block, Optional, 1, None, None, 2, spindle(), bitDir("forward"),
        none(), none(), "spindle jog"),
    ROW(BusSpindle, "SPDLBUS", Block, Optional, 1, None, None, 2, chan(), spindle(), none(), none(),
        "bus spindle control"),
    ROW(BusSpindleGeared, "SPDLBUS1", Block, Optional, 1, None, None, 4, chan(), spindle(), gear(),
        pblock(), "geared bus spindle control"),
    ROW(SpindleOrient, "SPDLORI", Block, Optional, 1, None, None, 1, axis(), none(), none(), none(),
        "spindle orient enable"),
    ROW(SpindleOrientDone, "SPDLOROK", Block, Optional, 1, Compare, None, 1, axis(), none(), none(),
        none(), "spindle orient done"),
    ROW(SpindleZeroSpeed, "SPDLZERO", Block, Optional, 1, Compare, None, 1, axis(), none(), none(),
        none(), "spindle zero speed"),
    ROW(SpindleSpeedReached, "SPDLRCH", Block, Optional, 1, Compare, None, 1, axis(), none(),
        none(), none(), "spindle speed reached"),
    ROW(SlaveRelease, "DESYN", Block, Required, 1, None, None, 1, axis(), none(), none(), none(),
        "release slave axis"),
    ROW(AxisJog, "JOGSW", Block, Optional, 1, None, None, 2, axisAny(), bitDir("direction (1 = +)"),
        none(), none(), "axis jog"),
    ROW(AxisStep, "STEPAXIS", Block, Optional, 1, None, None, 2, axisAny(),
        bitDir("direction (0 = +)"), none(), none(), "axis step"),
    ROW(JogSpeed, "JOGVEL", Block, Required, 1, None, None, 2, axisAny(), src("speed"), none(),
        none(), "jog speed select"),
    ROW(HomingStart, "HOMRUN", Block, Required, 1, None, None, 1, axis(), none(), none(), none(),
        "homing start"),
    ROW(HomingStartDir, "HOMERUN1", Block, Required, 1, None, None, 2, axis(), bitDir("direction"),
        none(), none(), "homing start with direction"),
    ROW(HomeDog, "HOMESW", Block, Required, 1, None, None, 1, axis(), none(), none(), none(),
        "home dog"),
    ROW(HomingDoneLamp, "HOMLED", Block, Required, 1, Compare, None, 1, axis(), none(), none(),
        none(), "homing done lamp"),
    ROW(AxisEnable, "AXEN", Block, Required, 1, None, None, 1, axisAny(), none(), none(), none(),
        "axis enable"),
    ROW(AxisReady, "AXRDY", Push, None, 0, None, None, 1, axis(), none(), none(), none(),
        "push the axis-ready bit"),
    ROW(AxisLock, "AXISLOCK", Block, Required, 1, None, None, 1, axis(), none(), none(), none(),
        "axis lock"),
    ROW(AxisMoveRelative, "AXISMOVE", Block, Required, 1, None, None, 2, axisAny(), src("distance"),
        none(), none(), "PMC axis relative move"),
    ROW(AxisMoveAbsolute, "AXISMVTO", Block, Required, 1, None, None, 2, axisAny(), src("position"),
        none(), none(), "PMC axis absolute move"),
    ROW(SecondSoftLimit, "AXLMF2", Block, Required, 1, None, None, 1, axisAny(), none(), none(),
        none(), "second soft limit"),
    ROW(PositiveLimitDog, "AXISPLMT", Block, Required, 1, None, None, 1, axis(), none(), none(),
        none(), "positive limit dog"),
    ROW(NegativeLimitDog, "AXISNLMT", Block, Required, 1, None, None, 1, axis(), none(), none(),
        none(), "negative limit dog"),
    ROW(ServoEnable, "SVSW", Block, Optional, 1, None, None, 1, axis(), none(), none(), none(),
        "servo enable"),
    ROW(AxisControlMode, "AXISMODE", Block, Optional, 1, None, None, 2, axis(), konst("mode", 0, 2),
        none(), none(), "axis control mode"),
    ROW(ReferencePoint, "REFPT", Block, Optional, 1, Compare, None, 2, axis(),
        konst("reference point", 2, 5), none(), none(), "reference point reached"),
    ROW(AxisHoming, "AXISHOM2", Block, Optional, 1, Compare, None, 1, axis(), none(), none(),
        none(), "axis homing in progress"),
    ROW(AxisMoving, "AXMOVING", Block, Optional, 1, Compare, None, 1, axis(), none(), none(),
        none(), "axis moving"),
    ROW(Alarm, "ALARM", Block, Optional, 1, None, None, 1, konst("alarm", 1, 884), none(), none(),
        none(), "PLC alarm (1..256) or prompt (501..884)"),
    ROW(ResetRequested, "RSTCHK", Block, Required, 1, Compare, None, 1, chan(), none(), none(),
        none(), "reset requested"),
    ROW(ResetClear, "RSTCLR", Block, Required, 1, None, None, 1, chan(), none(), none(), none(),
        "reset clear"),
};

#undef ROW
#undef ROWX

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
  static constexpr Alias kAliases[] = {
      {"WRT", Op::Coil}, {"END1", Op::EndCyclic}, {"END2", Op::EndSliced}};
  for (const Alias &a : kAliases) {
    if (equalsNoCase(m, a.name)) {
      out = a.op;
      return true;
    }
  }
  return false;
}

} // namespace lj

// The rows of the semantic instruction table, one per operation, from hnc8-core.md and
// hnc8-functions-1/-2.md (summary tables), then the dialect-only rows (ir/OpTable.h). Adding an
// instruction = one row here + its spelling in the front ends that have it + its two semantics
// (interpreter, lowering) + tests.
#include "ir/OpTable.h"

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
/// `s` touching `n` consecutive elements (OperandSpec::span).
constexpr OperandSpec spanning(OperandSpec s, uint8_t n) {
  s.span = n;
  return s;
}
/// `s` accepting only the constants in `v` (OperandSpec::values).
constexpr OperandSpec onlyValues(OperandSpec s, std::span<const ValueRange> v) {
  s.values = v;
  return s;
}
/// Alarms 1..256 (G3010-3025) and prompts 501..884 (G3056-3079; hnc8-cnc-interface.md 2).
constexpr ValueRange kAlarmNumbers[] = {{1, 256}, {501, 884}};
/// A FANUC data length (ROTB's format): 1, 2 or 4 bytes.
constexpr ValueRange kDataLengths[] = {{1, 2}, {4, 4}};

// Timer/counter numbers are constants 0..427; the gap 128..299 is rejected by the verifier.
constexpr OperandSpec tcNumber(const char *role) { return konst(role, 0, 427); }

using SR = StackRule;
using IR = InputRule;
using OR_ = OutputRule;
using SK = StateKind;

#define ROW(op, fam, stack, in, k, out, st, n, o0, o1, o2, o3, text)                               \
  InstrInfo {                                                                                      \
    Op::op, #op, Family::fam, SR::stack, IR::in, k, OR_::out, SK::st, n, {o0, o1, o2, o3}, text    \
  }

// Rows with more than four operands.
#define ROWX(op, fam, stack, in, k, out, st, n, text, ...)                                         \
  InstrInfo {                                                                                      \
    Op::op, #op, Family::fam, SR::stack, IR::in, k, OR_::out, SK::st, n, {__VA_ARGS__}, text       \
  }

constexpr InstrInfo kTable[] = {
    ROW(Load, Core, Push, None, 0, None, None, 1, bitRead("contact"), none(), none(), none(),
        "push the bit"),
    ROW(LoadNot, Core, Push, None, 0, None, None, 1, bitRead("contact"), none(), none(), none(),
        "push the inverted bit"),
    ROW(LoadTrue, Core, Push, None, 0, None, None, 0, none(), none(), none(), none(), "push 1"),
    ROW(LoadRise, Core, Push, None, 0, None, Edge, 1, bitRead("contact"), none(), none(), none(),
        "push the rising edge of the bit"),
    ROW(LoadFall, Core, Push, None, 0, None, Edge, 1, bitRead("contact"), none(), none(), none(),
        "push the falling edge of the bit"),
    ROW(And, Core, Combine, None, 0, None, None, 1, bitRead("contact"), none(), none(), none(),
        "ST0 := ST0 and bit"),
    ROW(AndNot, Core, Combine, None, 0, None, None, 1, bitRead("contact"), none(), none(), none(),
        "ST0 := ST0 and not bit"),
    ROW(Or, Core, Combine, None, 0, None, None, 1, bitRead("contact"), none(), none(), none(),
        "ST0 := ST0 or bit"),
    ROW(OrNot, Core, Combine, None, 0, None, None, 1, bitRead("contact"), none(), none(), none(),
        "ST0 := ST0 or not bit"),
    ROW(AndRise, Core, Combine, None, 0, None, Edge, 1, bitRead("contact"), none(), none(), none(),
        "ST0 := ST0 and rising edge"),
    ROW(AndFall, Core, Combine, None, 0, None, Edge, 1, bitRead("contact"), none(), none(), none(),
        "ST0 := ST0 and falling edge"),
    ROW(OrRise, Core, Combine, None, 0, None, Edge, 1, bitRead("contact"), none(), none(), none(),
        "ST0 := ST0 or rising edge"),
    ROW(OrFall, Core, Combine, None, 0, None, Edge, 1, bitRead("contact"), none(), none(), none(),
        "ST0 := ST0 or falling edge"),
    ROW(AndBlock, Core, BlockPop, None, 0, None, None, 0, none(), none(), none(), none(),
        "pop, ST0 := ST1 and ST0"),
    ROW(OrBlock, Core, BlockPop, None, 0, None, None, 0, none(), none(), none(), none(),
        "pop, ST0 := ST1 or ST0"),
    ROW(BranchPush, Core, MpsPush, None, 0, None, None, 0, none(), none(), none(), none(),
        "MS push ST0"),
    ROW(BranchRead, Core, MsRead, None, 0, None, None, 0, none(), none(), none(), none(),
        "ST0 := top(MS)"),
    ROW(BranchPop, Core, MsPop, None, 0, None, None, 0, none(), none(), none(), none(),
        "ST0 := pop(MS)"),
    ROW(Coil, Core, Coil, None, 0, None, None, 1, bitWrite("coil"), none(), none(), none(),
        "bit := ST0"),
    ROW(CoilNot, Core, Coil, None, 0, None, None, 1, bitWrite("coil"), none(), none(), none(),
        "bit := not ST0"),
    ROW(Set, Core, Coil, None, 0, None, None, 1, bitWrite("coil"), none(), none(), none(),
        "bit := bit or ST0"),
    ROW(Reset, Core, Coil, None, 0, None, None, 1, bitWrite("coil"), none(), none(), none(),
        "bit := bit and not ST0"),

    ROW(EndInit, Core, Structural, None, 0, None, None, 0, none(), none(), none(), none(),
        "end of the init part"),
    ROW(EndCyclic, Core, Structural, None, 0, None, None, 0, none(), none(), none(), none(),
        "end of PLC1"),
    ROW(EndSliced, Core, Structural, None, 0, None, None, 0, none(), none(), none(), none(),
        "end of PLC2"),
    ROW(Jump, Core, Block, Required, 1, None, None, 1, label(), none(), none(), none(),
        "jump to the label when ST0 = 1"),
    ROW(Label, Core, Structural, None, 0, None, None, 1, label(), none(), none(), none(),
        "jump target"),
    ROW(Call, Core, Block, Optional, 1, None, None, 1, sub(), none(), none(), none(),
        "call the subroutine when ST0 = 1"),
    ROW(SubBegin, Core, Structural, None, 0, None, None, 1, sub(), none(), none(), none(),
        "start of a subroutine"),
    ROW(SubEnd, Core, Structural, None, 0, None, None, 0, none(), none(), none(), none(),
        "end of a subroutine"),
    ROW(Return, Core, Block, Optional, 1, None, None, 0, none(), none(), none(), none(),
        "return from the subroutine when ST0 = 1"),
    ROW(LoopBegin, Core, Structural, None, 0, None, None, 1, src("loop count"), none(), none(),
        none(), "repeat the body up to NEXT count times"), // dialect-ok
    ROW(LoopEnd, Core, Structural, None, 0, None, None, 0, none(), none(), none(), none(),
        "end of a loop body"),

    ROW(Add, Core, Block, Required, 1, Enable, None, 3, src("augend"), src("addend"),
        dst("destination"), none(), "dst := a + b"),
    ROW(Subtract, Core, Block, Required, 1, Enable, None, 3, src("minuend"), src("subtrahend"),
        dst("destination"), none(), "dst := a - b"),
    ROW(Multiply, Core, Block, Required, 1, Enable, None, 3, src("multiplicand"), src("multiplier"),
        dst("destination"), none(), "dst := a * b"),
    ROW(Divide, Core, Block, Required, 1, Enable, None, 3, src("dividend"), src("divisor"),
        dst("destination"), none(), "dst := a / b (b = 0: nothing written, output 0)"),
    ROW(Increment, Core, Block, Required, 1, Enable, None, 1, inout("operand"), none(), none(),
        none(), "x := x + 1"),
    ROW(Decrement, Core, Block, Required, 1, Enable, None, 1, inout("operand"), none(), none(),
        none(), "x := x - 1"),
    ROW(BitAnd, Core, Block, Required, 1, Enable, None, 3, src("operand 1"), src("operand 2"),
        dst("destination"), none(), "dst := a & b"),
    ROW(BitOr, Core, Block, Required, 1, Enable, None, 3, src("operand 1"), src("operand 2"),
        dst("destination"), none(), "dst := a | b"),
    ROW(BitXor, Core, Block, Required, 1, Enable, None, 3, src("operand 1"), src("operand 2"),
        dst("destination"), none(), "dst := a ^ b"),
    ROW(Negate, Core, Block, Required, 1, Enable, None, 1, inout("operand"), none(), none(), none(),
        "x := -x"),

    ROW(CompareLe, Core, Block, Optional, 1, Compare, None, 2, src("compared data"),
        src("reference"), none(), none(), "out := EN and a <= b"),
    ROW(CompareLt, Core, Block, Optional, 1, Compare, None, 2, src("compared data"),
        src("reference"), none(), none(), "out := EN and a < b"),
    ROW(CompareRange, Core, Block, Optional, 1, Compare, None, 3, src("lower limit"),
        src("upper limit"), src("compared data"), none(), "out := EN and lo < x < hi"),
    ROW(CompareEq, Core, Block, Optional, 1, Compare, None, 2, src("reference"),
        src("compared data"), none(), none(), "out := EN and a == b"),

    ROW(Move, Core, Block, Optional, 1, Enable, None, 2, src("source"), dst("destination"), none(),
        none(), "dst := src"),

    ROW(RegisterCounter, Core, Block, Required, 4, Result, Edge, 2,
        (OperandSpec{"count register", areas(Area::Relay, Area::Word, Area::DWord, Area::Retained),
                     false, false, 0, 0, true}),
        preset(), none(), none(), "up/down ring counter, value in a register"),
    ROW(RingCounter, Core, Block, Required, 2, Result, Counter, 2, tcNumber("counter number"),
        preset(), none(), none(), "ring counter Cn counting up from 0"),
    ROW(UpDownCounter, Core, Block, Required, 4, Result, Counter, 2, tcNumber("counter number"),
        preset(), none(), none(), "up/down ring counter Cn with start value 0/1"),
    ROW(OnDelayTimer, Core, Block, Required, 1, Result, Timer, 3, tcNumber("timer number"),
        konst("time unit", 0, 3),
        (OperandSpec{"time length", areas(Area::Relay, Area::Word, Area::DWord, Area::Param), false,
                     true, kI32Min, kI32Max, false}),
        none(), "on-delay timer Tn"),
    ROW(OffDelayTimer, Core, Block, Required, 1, Result, Timer, 3, tcNumber("timer number"),
        konst("time unit", 0, 3),
        (OperandSpec{"time length", areas(Area::Relay, Area::Word, Area::DWord, Area::Param), false,
                     true, kI32Min, kI32Max, false}),
        none(), "off-delay timer Tn"),

    ROW(RisePulse, Core, Block, Optional, 1, Result, Pls, 1, konst("edge block number", 0, 511),
        none(), none(), none(), "out := EN and not previous EN"),
    ROW(FallPulse, Core, Block, Optional, 1, Result, Plf, 1, konst("edge block number", 0, 511),
        none(), none(), none(), "out := not EN and previous EN"),
    ROW(Toggle, Core, Block, Required, 1, Result, Alt, 1, konst("toggle block number", 0, 511),
        none(), none(), none(), "toggle the held output on each rising edge of EN"),

    // ---- Data operations (hnc8-functions-2.md 2.2-2.13, 2.17-2.18; summary section 5) ----
    ROW(IndexedMove, Data, Block, Optional, 1, Enable, None, 4, konst("format 1", 0, 2),
        reg("address 1", kIndirectAreas, false), konst("format 2", 0, 2),
        reg("address 2", kIndirectAreas, true),
        "operand 2 := operand 1 (formats 0 reg, 1 B[], 2 P[])"),
    ROW(BlockMove, Data, Block, Optional, 1, Enable, None, 3, reg("source start", kSrcAreas, false),
        dst("destination start"), konst("count", 1, 1000), none(), "copy count elements (memmove)"),
    ROW(Fill, Data, Block, Optional, 1, None, None, 3, dst("destination start"),
        dst("destination end"), src("value"), none(), "fill start..end with the value"),
    ROW(Exchange, Data, Block, Optional, 1, None, None, 4, konst("format 1", 0, 2),
        reg("address 1", kIndirectAreas, true), konst("format 2", 0, 2),
        reg("address 2", kIndirectAreas, true), "exchange operand 1 and operand 2"),
    ROW(ZoneReset, Data, Block, Optional, 1, Enable, None, 2, zoneBound("start"), zoneBound("end"),
        none(), none(), "reset the registers or bits start..end"),
    ROW(TableEncode, Data, Block, Optional, 1, None, None, 4, reg("table start", kSrcAreas, false),
        konst("table length", 1, 32), src("value"), dst("destination"),
        "one-hot bit of the first table entry equal to the value"),
    ROW(TableDecode, Data, Block, Required, 1, None, None, 4, reg("table start", kSrcAreas, false),
        konst("table length", 1, 32), src("value"), dst("destination"),
        "table entry of the lowest set bit of the value"),
    ROW(TableLookup, Data, Block, Required, 1, None, None, 4, reg("table start", kSrcAreas, false),
        konst("table length", 1, 1000), src("index"), dst("destination"),
        "destination := table[index]"),
    ROW(TableSearch, Data, Block, Required, 1, Compare, None, 4,
        reg("table start", kSrcAreas, false), konst("table length", 1, 1000), src("value"),
        dst("index destination"),
        "index of the first table entry equal to the value; output = found"),
    ROW(Pack, Data, Block, Required, 1, None, None, 3, reg("source start", kSrcAreas, false),
        konst("count", 1, 32),
        reg("destination", areas(Area::NcControl, Area::Word, Area::DWord, Area::Retained), true),
        none(), "pack count registers into one"),
    ROW(Unpack, Data, Block, Required, 1, None, None, 3,
        reg("source",
            areas(Area::NcStatus, Area::NcControl, Area::Word, Area::DWord, Area::Param,
                  Area::Retained),
            false),
        konst("count", 1, 32),
        reg("destination start", areas(Area::Output, Area::NcControl, Area::Relay, Area::Word),
            true),
        none(), "split one register into count registers"),
    ROW(RangeConvert, Data, Block, Required, 1, None, None, 3, spanning(pblock(), 4), src("value"),
        dst("destination"), none(), "linear range conversion with the P parameter block"),
    ROWX(PointToNumber, Data, Block, Optional, 1, None, None, 9,
         "destination := number of the first active point", dst("destination"), bitRead("point 1"),
         i32Const("number 1"), bitRead("point 2"), i32Const("number 2"), bitRead("point 3"),
         i32Const("number 3"), bitRead("point 4"), i32Const("number 4")),
    ROWX(NumberToPoint, Data, Block, Optional, 1, None, None, 9, "point i := (source == number i)",
         reg("source", kSrcAreas, false), i32Const("number 1"), bitWrite("point 1"),
         i32Const("number 2"), bitWrite("point 2"), i32Const("number 3"), bitWrite("point 3"),
         i32Const("number 4"), bitWrite("point 4")),

    // ---- NC services (functions-1 3.1, functions-2 2.19-2.23, cnc-interface 2 / 3.4) ----
    ROW(MCodeGet, Nc, Block, Optional, 1, Compare, None, 2, chan(), konst("M code", 0, 32767),
        none(), none(), "out := EN and the channel requests the M code"),
    ROW(MCodeAck, Nc, Block, Optional, 1, None, None, 2, chan(), konst("M code", 0, 32767), none(),
        none(), "acknowledge the M code"),
    ROW(TCodeGet, Nc, Block, Optional, 1, Compare, None, 2, chan(),
        regOrConst("T code destination", kDstAreas, true), none(), none(),
        "out := EN and a T code is pending (stored in the destination)"),
    ROW(TCodeAck, Nc, Block, Optional, 1, None, None, 1, chan(), none(), none(), none(),
        "acknowledge the channel's T code"),
    ROW(HandwheelPulse, Nc, Block, Optional, 1, None, None, 2, src("pulse register"),
        konst("handwheel", 0, 9), none(), none(),
        "pass the pulse register to the handwheel (host)"),
    ROW(TempSensor, Nc, Block, Optional, 1, None, None, 4, konst("sensor", 0, 19),
        spanning(reg("X group", areas(Area::Input), false), 2), konst("board type", 0, 4),
        spanning(pblock(), 4), "temperature sensor input (host)"),
    ROW(PartCount, Nc, Block, Optional, 1, Enable, None, 1, chan(), none(), none(), none(),
        "part count of the channel + 1"),
    ROW(PartClear, Nc, Block, Optional, 1, Enable, None, 1, chan(), none(), none(), none(),
        "part count of the channel := 0"),
    ROW(HeadSensors, Nc, Block, Optional, 1, None, None, 3, konst("count", 1, 20),
        i32Const("enable"), reg("storage start", areas(Area::DWord), true), none(),
        "copy count temperatures to D registers when enable = 0"),
    ROW(VarGet, Nc, Block, Required, 1, Enable, None, 4, konst("variable type", 0, 9),
        src("offset"), konst("exponent", 0, 4), dst("result"), "read a CNC variable (host)"),
    ROW(VarSet, Nc, Block, Required, 1, Enable, None, 4, konst("variable type", 0, 9),
        src("offset"), konst("exponent", 0, 4), src("data source"), "write a CNC variable (host)"),
    ROW(ToolVectorOn, Nc, Block, Optional, 1, Enable, None, 1, chan(), none(), none(), none(),
        "tool-vector direction on (host)"),
    ROW(ToolVectorOff, Nc, Block, Optional, 1, Enable, None, 1, chan(), none(), none(), none(),
        "tool-vector direction off (host)"),
    ROW(PanelDisplay, Nc, Block, Required, 1, Enable, None, 3, src("value"), konst("width", 0, 1),
        spanning(reg("display",
                     areas(Area::Output, Area::Relay, Area::Word, Area::DWord, Area::Retained),
                     true),
                 2), // two bytes when the width is 1 and the area's elements are bytes
        none(), "show the value on the panel display"),
    ROW(ToolInUse, Nc, Block, Optional, 1, None, None, 2, src("channel"), src("tool"), none(),
        none(), "tool in use (host)"),
    ROW(ToolLife, Nc, Block, Optional, 1, None, Words, 3, chan(), konst("count", 1, kI32Max),
        reg("response", areas(Area::Relay), true), none(), "tool-install counter"),
    ROW(ToolSelect, Nc, Block, Optional, 1, Result, None, 4, src("spindle tool"),
        src("commanded tool"), dst("error"), dst("target pocket"),
        "select the pocket of the commanded tool (host)"),
    ROWX(SpindleAnalog, Nc, Block, Optional, 1, None, None, 5, "analog (DA) spindle (host scaling)",
         chan(), spindle(), gear(),
         reg("reference",
             areas(Area::Output, Area::NcControl, Area::Relay, Area::Word, Area::DWord,
                   Area::Retained),
             true),
         spanning(pblock(), 5)),
    ROW(SlaveHomingEnable, Nc, Block, Required, 1, None, None, 1, axis(), none(), none(), none(),
        "slave-axis homing enable (host)"),
    ROW(HandwheelSet, Nc, Block, Required, 1, None, None, 3, konst("handwheel", 0, 9), axisAny(),
        src("override"), none(), "handwheel axis and multiplier"),
    ROW(MagazineRotate, Nc, Block, Optional, 5, Result, None, 4, konst("positions", 1, 32767),
        reg("current position", kSrcAreas, false), reg("target position", kSrcAreas, false),
        dst("result"), "rotary magazine direction and steps"),
    ROW(RaiseEvent, Nc, Block, Required, 1, None, Edge, 1, konst("event", 0, 255), none(), none(),
        none(), "raise a PLC event"),
    ROW(SaveRetained, Nc, Block, Required, 1, None, Edge, 0, none(), none(), none(), none(),
        "save the retentive data (host)"),

    // ---- Chapter-6 blocks on F/G words (cnc-interface 2, summary section 4) ----
    ROW(ChannelModeSet, Cnc, Block, Optional, 1, None, None, 2, chan(), src("mode"), none(), none(),
        "channel mode set"),
    ROW(ChannelModeGet, Cnc, Block, Optional, 1, None, None, 2, chan(), dst("mode destination"),
        none(), none(), "channel mode get"),
    ROW(MdiMode, Cnc, Block, Optional, 1, None, None, 1, chan(), none(), none(), none(),
        "MDI mode"), // dialect-ok
    ROW(MstLock, Cnc, Block, Required, 1, None, None, 1, chan(), none(), none(), none(),
        "lock MST"), // dialect-ok
    ROW(CycleStart, Cnc, Block, Required, 1, None, None, 1, chan(), none(), none(), none(),
        "cycle start"),
    ROW(EmergencyStop, Cnc, Block, Required, 1, None, None, 1, chan(), none(), none(), none(),
        "emergency stop"),
    ROW(ChannelReset, Cnc, Block, Required, 1, None, None, 1, chan(), none(), none(), none(),
        "reset"),
    ROW(ChannelSwitch, Cnc, Block, Required, 1, None, None, 1, chan(), none(), none(), none(),
        "channel switch"),
    ROW(FeedHold, Cnc, Block, Required, 1, None, None, 1, chan(), none(), none(), none(),
        "feed hold"),
    ROW(CycleStartLamp, Cnc, Block, Optional, 1, Compare, None, 1, chan(), none(), none(), none(),
        "cycle-start lamp"),
    ROW(FeedHoldLamp, Cnc, Block, Optional, 1, Compare, None, 1, chan(), none(), none(), none(),
        "feed-hold lamp"),
    ROW(SkipG31, Cnc, Block, Optional, 1, None, None, 2, chan(), konst("G31 number", 0, 32767),
        none(), none(), "G31 skip"),
    ROW(RapidOverride, Cnc, Block, Optional, 1, None, None, 2, chan(), src("override"), none(),
        none(), "rapid override set"),
    ROW(FeedOverride, Cnc, Block, Optional, 1, None, None, 2, chan(), src("override"), none(),
        none(), "feed override set"),
    ROW(SpindleOverride, Cnc, Block, Optional, 1, None, None, 3, chan(), spindle(), src("override"),
        none(), "spindle override set"),
    ROW(StepMultiplier, Cnc, Block, Optional, 1, None, None, 2, axis(), src("multiplier"), none(),
        none(), "increment multiplier set"),
    ROW(DryRun, Cnc, Block, Required, 1, None, None, 1, chan(), none(), none(), none(), "dry run"),
    ROW(BlockSkip, Cnc, Block, Required, 1, None, None, 1, chan(), none(), none(), none(),
        "block skip"),
    ROW(UserInput, Cnc, Block, Required, 1, None, None, 3, chan(), i32Const("group"),
        konst("bit", 0, 31), none(), "user input bit"),
    ROW(UserOutput, Cnc, Block, Optional, 1, None, None, 3, chan(), i32Const("unused"),
        spanning(reg("output start", areas(Area::Output, Area::Relay), true), 4), none(),
        "user outputs to 4 bytes"),
    ROW(OptionalStop, Cnc, Block, Required, 1, None, None, 1, chan(), none(), none(), none(),
        "optional stop"),
    ROW(SpindleJog, Cnc, Block, Optional, 1, None, None, 2, spindle(), bitDir("forward"), none(),
        none(), "spindle jog"),
    ROW(BusSpindle, Cnc, Block, Optional, 1, None, None, 2, chan(), spindle(), none(), none(),
        "bus spindle control"),
    ROW(BusSpindleGeared, Cnc, Block, Optional, 1, None, None, 4, chan(), spindle(), gear(),
        spanning(pblock(), 5), "geared bus spindle control"),
    ROW(SpindleOrient, Cnc, Block, Optional, 1, None, None, 1, axis(), none(), none(), none(),
        "spindle orient enable"),
    ROW(SpindleOrientDone, Cnc, Block, Optional, 1, Compare, None, 1, axis(), none(), none(),
        none(), "spindle orient done"),
    ROW(SpindleZeroSpeed, Cnc, Block, Optional, 1, Compare, None, 1, axis(), none(), none(), none(),
        "spindle zero speed"),
    ROW(SpindleSpeedReached, Cnc, Block, Optional, 1, Compare, None, 1, axis(), none(), none(),
        none(), "spindle speed reached"),
    ROW(SlaveRelease, Cnc, Block, Required, 1, None, None, 1, axis(), none(), none(), none(),
        "release slave axis"),
    ROW(AxisJog, Cnc, Block, Optional, 1, None, None, 2, axisAny(), bitDir("direction (1 = +)"),
        none(), none(), "axis jog"),
    ROW(AxisStep, Cnc, Block, Optional, 1, None, None, 2, axisAny(), bitDir("direction (0 = +)"),
        none(), none(), "axis step"),
    ROW(JogSpeed, Cnc, Block, Required, 1, None, None, 2, axisAny(), src("speed"), none(), none(),
        "jog speed select"),
    ROW(HomingStart, Cnc, Block, Required, 1, None, None, 1, axis(), none(), none(), none(),
        "homing start"),
    ROW(HomingStartDir, Cnc, Block, Required, 1, None, None, 2, axis(), bitDir("direction"), none(),
        none(), "homing start with direction"),
    ROW(HomeDog, Cnc, Block, Required, 1, None, None, 1, axis(), none(), none(), none(),
        "home dog"),
    ROW(HomingDoneLamp, Cnc, Block, Required, 1, Compare, None, 1, axis(), none(), none(), none(),
        "homing done lamp"),
    ROW(AxisEnable, Cnc, Block, Required, 1, None, None, 1, axisAny(), none(), none(), none(),
        "axis enable"),
    ROW(AxisReady, Cnc, Push, None, 0, None, None, 1, axis(), none(), none(), none(),
        "push the axis-ready bit"),
    ROW(AxisLock, Cnc, Block, Required, 1, None, None, 1, axis(), none(), none(), none(),
        "axis lock"),
    ROW(AxisMoveRelative, Cnc, Block, Required, 1, None, None, 2, axisAny(), src("distance"),
        none(), none(), "PMC axis relative move"),
    ROW(AxisMoveAbsolute, Cnc, Block, Required, 1, None, None, 2, axisAny(), src("position"),
        none(), none(), "PMC axis absolute move"),
    ROW(SecondSoftLimit, Cnc, Block, Required, 1, None, None, 1, axisAny(), none(), none(), none(),
        "second soft limit"),
    ROW(PositiveLimitDog, Cnc, Block, Required, 1, None, None, 1, axis(), none(), none(), none(),
        "positive limit dog"),
    ROW(NegativeLimitDog, Cnc, Block, Required, 1, None, None, 1, axis(), none(), none(), none(),
        "negative limit dog"),
    ROW(ServoEnable, Cnc, Block, Optional, 1, None, None, 1, axis(), none(), none(), none(),
        "servo enable"),
    ROW(AxisControlMode, Cnc, Block, Optional, 1, None, None, 2, axis(), konst("mode", 0, 2),
        none(), none(), "axis control mode"),
    ROW(ReferencePoint, Cnc, Block, Optional, 1, Compare, None, 2, axis(),
        konst("reference point", 2, 5), none(), none(), "reference point reached"),
    ROW(AxisHoming, Cnc, Block, Optional, 1, Compare, None, 1, axis(), none(), none(), none(),
        "axis homing in progress"),
    ROW(AxisMoving, Cnc, Block, Optional, 1, Compare, None, 1, axis(), none(), none(), none(),
        "axis moving"),
    ROW(Alarm, Cnc, Block, Optional, 1, None, None, 1,
        onlyValues(konst("alarm", 1, 884), kAlarmNumbers), none(), none(), none(),
        "PLC alarm (1..256) or prompt (501..884)"),
    ROW(ResetRequested, Cnc, Block, Required, 1, Compare, None, 1, chan(), none(), none(), none(),
        "reset requested"),
    ROW(ResetClear, Cnc, Block, Required, 1, None, None, 1, chan(), none(), none(), none(),
        "reset clear"),

    // ---- iec3 (issue 16): the Neza %TMi / %Ci blocks (modicon-neza.md 3; semantics in
    // docs/iec-il.md "Function blocks"). Their state is in the block's words: a timer's five
    // (V, P, status, start low, start high), a counter's three (V, P, status) ----
    ROW(IecTimer, Core, Block, Required, 1, Enable, None, 3,
        spanning(reg("timer words", areas(Area::TimerData), true), 5),
        konst("timer type (0 TON, 1 TOF, 2 TP)", 0, 2),
        konst("time base (0 1 min, 1 1 s, 2 100 ms, 3 10 ms, 4 1 ms)", 0, 4), none(),
        "Neza timer %TMi: IN from ST0, which it leaves; Q and V in its words"),
    ROW(IecCounter, Core, Block, Required, 4, Result, None, 2,
        spanning(reg("counter words", areas(Area::CounterData), true), 3),
        konst("driven inputs (1 R, 2 S, 4 CU, 8 CD)", 1, 15), none(), none(),
        "Neza up/down counter %Ci: inputs R, S, CU, CD; out := D"),
    // ---- fanuc-a: FANUC PMC timers, counters, compares (fanuc-pmc.md 6.3, 6.4, 6.6) ----
    ROW(PmcTimer, PmcTc, Block, Required, 1, Result, Words, 3, konst("timer number", 1, 250),
        reg("preset", areas(Area::TimerData), false),
        reg("precision", areas(Area::TimerData), false), none(),
        "on-delay timer: preset count x the precision's unit"),
    ROW(PmcTimerAddr, PmcTc, Block, Required, 1, Result, Words, 3, konst("precision", 0, 7),
        reg("preset", kSrcAreas, false), reg("timer register", kDstAreas, true), none(),
        "on-delay timer with the preset and elapsed ms at any address"),
    ROW(PmcCounter, PmcTc, Block, Required, 4, Result, Edge, 3,
        regOrConst("preset", kSrcAreas, false), reg("current value", kDstAreas, true),
        konst("data type", 0, 1), none(),
        "preset/ring counter, up or down, counting rising edges of ACT; data type 0 binary, 1 "
        "the counter data type system parameter (BCD or binary)"),
    ROW(PmcCompareFlags, PmcTc, Block, Required, 1, None, None, 3, src("input data"),
        reg("comparison data", kSrcAreas, false), reg("flags", kDstAreas, true), none(),
        "flags.Z := input == comparison, flags.N := input < comparison"),
    ROW(BcdCompare, PmcTc, Block, Required, 2, Compare, None, 3, konst("relation", 0, 1),
        src("input data"), reg("comparison data", kSrcAreas, false), none(),
        "out := ACT and input <= / == comparison, BCD of 2 (BYT 0) or 4 digits (BYT 1)"),
    ROW(CompareNe, PmcTc, Block, Optional, 1, Compare, None, 2, src("data 1"), src("data 2"),
        none(), none(), "out := EN and a != b"),
    ROW(CompareBetween, PmcTc, Block, Optional, 1, Compare, None, 3, src("data 1"), src("data 2"),
        src("input"), none(), "out := EN and x between a and b (either order)"),
    // ---- fanuc-b: FANUC PMC transfer, search, conversion and flow (fanuc-pmc.md 4.2, 6.5, 6.7,
    // 6.8, 6.9; docs/fanuc-pmc.md). Control inputs are ST entries (ACT = ST0), W1 the Result;
    // the Edge slot holds W1 between executions of the instructions with a reset input. ----
    ROW(ParityCheck, Data, Block, Required, 3, Result, Edge, 1, reg("check data", kSrcAreas, false),
        none(), none(), none(), "W1 := parity error of the byte (odd/even select, reset, enable)"),
    ROW(ShiftWord, Data, Block, Required, 4, Result, Edge, 1, reg("shift data", kDstAreas, true),
        none(), none(), none(),
        "shift 16 bits by one (direction, continue, reset, enable); W1 := a 1 was shifted out"),
    ROW(BcdDecode, Data, Block, Required, 1, Result, None, 3, reg("decode data", kSrcAreas, false),
        konst("pattern", 0, 0x99), konst("digit mask", 0, 0xFF), none(),
        "W1 := ACT and (byte & mask) == pattern"),
    ROW(GroupDecode, Data, Block, Required, 1, None, None, 4, reg("decode data", kSrcAreas, false),
        i32Const("first value"), konst("groups", 1, 99), reg("output", kDstAreas, true),
        "output byte j bit k := ACT and data == first + 8 j + k"),
    ROW(BcdConvert, Data, Block, Required, 4, Result, Edge, 2,
        spanning(reg("input", kSrcAreas, false), 2), spanning(reg("output", kDstAreas, true), 2),
        none(), none(),
        "binary <-> BCD over 1 or 2 bytes (width, direction, reset, enable); W1 := error"),
    ROW(BcdConvertExt, Data, Block, Required, 4, Result, Edge, 3, reg("input", kSrcAreas, false),
        reg("output", kDstAreas, true), reg("flags", kDstAreas, true), none(),
        "binary <-> BCD over 1/2/4 bytes (sign, direction, reset, enable); R9000 N/V; W1 := error"),
    ROW(CodeTable, Data, Block, Required, 3, Result, Edge, 3, konst("table size", 0, 99),
        reg("index", kSrcAreas, false), spanning(reg("output", kDstAreas, true), 2), none(),
        "output := BCD table[BCD index] (width, reset, enable); W1 := bad index"),
    ROW(CodeTableBinary, Data, Block, Required, 2, Result, Edge, 3, konst("table size", 0, 256),
        reg("index", kSrcAreas, false), reg("output", kDstAreas, true), none(),
        "output := table[index] (reset, enable); W1 := bad index"),
    ROWX(TableRows, Data, Block, Required, 1, Enable, None, 9,
         "constant rows of the code-table block before them", i32Const("entry"), i32Const("entry"),
         i32Const("entry"), i32Const("entry"), i32Const("entry"), i32Const("entry"),
         i32Const("entry"), i32Const("entry"), i32Const("entry")),
    ROWX(
        IndexedTable, Data, Block, Required, 3, Result, Edge, 5,
        "nn items table[index] <-> data (read/write, reset, enable); W1 := index past the capacity",
        konst("items", 1, 99), reg("capacity", kSrcAreas, false),
        reg("table head", kDstAreas, true), reg("data", kDstAreas, true),
        reg("index", kSrcAreas, false)),
    ROW(SearchTable, Data, Block, Required, 2, Result, Edge, 4, reg("capacity", kSrcAreas, false),
        reg("table head", kSrcAreas, false), reg("search data", kSrcAreas, false),
        reg("result", kDstAreas, true), "result := index of the first equal item; W1 := not found"),
    ROW(CommonBegin, Data, Block, Required, 1, None, Edge, 0, none(), none(), none(), none(),
        "remember ACT for the coils up to COME"),
    ROW(CommonCoil, Data, Coil, None, 0, None, None, 3, bitWrite("coil"),
        konst("statements back to COM", 1, kI32Max), konst("kind", 0, 3), none(),
        "coil, negated coil, set or reset with input ST0 and the common line's enable (the two "
        "coils write 0 when it is off)"),
    // ---- fanuc-c: FANUC PMC arithmetic (fanuc-pmc.md 6.10 [EXT]; docs/fanuc-pmc.md
    // "Arithmetic"; the operation codes and flag bits are ir/PmcArith.h's). Inputs are ST
    // entries (ACT = ST0, RST = ST1, BYT = ST2); the Edge slot holds W1 between executions. ----
    ROWX(BinaryArith, PmcTc, Block, Required, 2, Result, Edge, 6,
         "result := operand 1 op operand 2 over 1/2/4 signed bytes (reset, enable); flags Z/N/V; "
         "the quotient's remainder; W1 := overflow or division by zero",
         konst("operation", 0, 3), reg("operand 1", kSrcAreas, false), src("operand 2"),
         reg("result", kDstAreas, true), reg("flags", kDstAreas, true),
         reg("remainder", kDstAreas, true)),
    ROW(BcdArith, PmcTc, Block, Required, 3, Result, Edge, 4, konst("operation", 0, 3),
        spanning(reg("operand 1", kSrcAreas, false), 2),
        spanning(regOrConst("operand 2", kSrcAreas, false), 2),
        spanning(reg("result", kDstAreas, true), 2),
        "result := operand 1 op operand 2 in BCD of 2 or 4 digits (width, reset, enable); "
        "W1 := a digit above 9, a result outside the digits or division by zero"),
    ROW(BcdConstant, PmcTc, Block, Required, 2, Result, None, 2, konst("BCD pattern", 0, 0x9999),
        spanning(reg("output", kDstAreas, true), 2), none(), none(),
        "output := the BCD pattern's low byte (width 0) or both bytes (width 1) when enabled; "
        "leaves the enable"),
    ROWX(BcdIndexedTable, Data, Block, Required, 4, Result, Edge, 4,
         "table[index] <-> data, 1 or 2 bytes, BCD index (width, read/write, reset, enable); W1 := "
         "bad index",
         konst("capacity", 1, 9999), reg("table head", kDstAreas, true),
         spanning(reg("data", kDstAreas, true), 2), spanning(reg("index", kSrcAreas, false), 2)),
    ROWX(BcdSearchTable, Data, Block, Required, 3, Result, Edge, 4,
         "result := BCD index of the first equal item, 1 or 2 bytes (width, reset, enable); W1 := "
         "not found",
         konst("capacity", 1, 9999), reg("table head", kSrcAreas, false),
         spanning(reg("search data", kSrcAreas, false), 2),
         spanning(reg("result", kDstAreas, true), 2)),
    // ---- FANUC PMC flow ----
    ROW(JumpOut, Core, Block, Required, 1, None, None, 1, label(), none(), none(), none(),
        "when ST0 = 1: leave this subroutine and every caller up to the sliced part, and go on "
        "there at the label"),
    // ---- rot: FANUC PMC rotation control (fanuc-pmc.md 6.10 [EXT]; docs/fanuc-pmc.md
    // "Rotation control"). Inputs are ST entries, ACT = ST0, INC, POS, DIR, [BYT,] RN0 above it;
    // the Edge slot holds W1 (the direction) between executions. ----
    ROW(BcdRotation, Data, Block, Required, 6, Result, Edge, 4, konst("rotor index count", 2, 9999),
        spanning(reg("current position", kSrcAreas, false), 2),
        spanning(reg("goal position", kSrcAreas, false), 2),
        spanning(reg("result", kDstAreas, true), 2),
        "result := the goal, the position before it or the steps to it, BCD of 2 or 4 digits "
        "(positions from 0 or 1, width, shortest way, position before, steps, enable); W1 := "
        "reverse"),
    ROWX(BinaryRotation, Data, Block, Required, 5, Result, Edge, 5,
         "result := the goal, the position before it or the steps to it, 1/2/4 signed bytes "
         "(positions from 0 or 1, shortest way, position before, steps, enable); W1 := reverse",
         onlyValues(konst("format (data length)", 1, 4), kDataLengths),
         reg("rotor index count", kSrcAreas, false), reg("current position", kSrcAreas, false),
         reg("goal position", kSrcAreas, false), reg("result", kDstAreas, true)),
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

} // namespace

const InstrInfo &instrInfo(Op op) { return kTable[static_cast<int>(op)]; }

std::span<const InstrInfo> instrTable() { return {kTable, static_cast<size_t>(kOpCount)}; }

} // namespace lj

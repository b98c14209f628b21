// The rows of the CNC interface table: hnc8-cnc-interface.md section 2 ("Effect" of each block)
// with the write rules of section 3.1 and the decisions of docs/cnc-blocks.md. Axis words are
// GA[k] = G[A*80+k], channel words GC[k] = G[2560+C*80+k] (section 0).
#include "profiles/hnc8/CncTable.h"

namespace lj::cnc {

namespace {

// Action builders: one line of the table each.
constexpr Action level(int16_t w, int8_t b) { return {Do::Level, w, b}; }
/// G bit := ACT and (dir operand == pol).
constexpr Action levelDir(int16_t w, int8_t b, int8_t dirOp, bool pol) {
  Action a{Do::Level, w, b};
  a.dirOp = dirOp;
  a.pol = pol;
  return a;
}
/// G bit `bit + (operand - lo)` := ACT, for lo <= operand <= hi.
constexpr Action levelAt(int16_t w, int8_t b, int8_t op, int32_t lo, int32_t hi) {
  Action a{Do::Level, w, b};
  a.bitOp = op;
  a.lo = lo;
  a.hi = hi;
  return a;
}
constexpr Action jog(int16_t w, int8_t dirOp, bool plusWhen) {
  Action a{Do::Jog, w};
  a.dirOp = dirOp;
  a.pol = plusWhen;
  return a;
}
/// `words` G words := operand `op` while ACT.
constexpr Action write(int16_t w, int8_t words, int8_t op) {
  Action a{Do::Write, w, 0, words};
  a.src = Src::Operand;
  a.srcOp = op;
  return a;
}
constexpr Action field(int16_t w, int8_t b, int8_t bits, int32_t v) {
  Action a{Do::Field, w, b, bits};
  a.src = Src::Const;
  a.value = v;
  return a;
}
constexpr Action status(int16_t w, int8_t b) { return {Do::Status, w, b}; }
constexpr Action statusAt(int16_t w, int8_t b, int8_t op, int32_t lo, int32_t hi) {
  Action a{Do::Status, w, b};
  a.bitOp = op;
  a.lo = lo;
  a.hi = hi;
  return a;
}
constexpr Action spindle(int8_t gearOp, int8_t pOp) {
  // G[10+2sp] (32 bit) := S value F[10+2sp] * override G[6+sp] / 100 (section 1.4 G2570).
  Action a{Do::Spindle, 10};
  a.aux = 10;
  a.aux2 = 6;
  a.spOp = 1;
  a.gearOp = gearOp;
  a.pOp = pOp;
  return a;
}
/// S acknowledge GC[2].sp := ACT and FC[2].(12+sp) (section 1.6 "S codes").
constexpr Action spindleAck() {
  Action a{Do::Ack, 2, 0};
  a.bitOp = 1;
  a.lo = 0;
  a.hi = 3;
  a.aux = 2;
  a.auxBit = 12;
  return a;
}

/// G[word+operand wordOp] := operand `op` while ACT.
constexpr Action writeAt(int16_t w, int8_t wordOp, int8_t op) {
  Action a = write(w, 1, op);
  a.wordOp = wordOp;
  return a;
}
/// G bits [b, b + bits) := 1 << (constant operand `op`) while ACT.
constexpr Action fieldShl(int16_t w, int8_t b, int8_t bits, int8_t op) {
  Action a{Do::Field, w, b, bits};
  a.src = Src::OneShl;
  a.srcOp = op;
  return a;
}
constexpr Action modeSet(int16_t codeWord, int16_t oneHotWord, int8_t op) {
  Action a{Do::ModeSet, codeWord, 0, 4};
  a.src = Src::Operand;
  a.srcOp = op;
  a.aux = oneHotWord;
  return a;
}
constexpr Action modeGet(int16_t codeWord, int8_t dstOp) {
  Action a{Do::ModeGet, codeWord, 0, 4};
  a.srcOp = dstOp;
  return a;
}
constexpr Action userOut(int16_t fWord, int8_t dstOp) {
  Action a{Do::UserOut, fWord, 0, 2};
  a.srcOp = dstOp;
  return a;
}
constexpr Action push(int16_t w, int8_t b) { return {Do::Push, w, b}; }

constexpr Action kNone{Do::Status, 0};

#define ROW(op, base, where, doc, n, a0, a1, a2, text)                                             \
  CncRow { Op::op, Base::base, where, doc, n, {a0, a1, a2}, text }
#define ROW1(op, base, where, doc, a0, text) ROW(op, base, where, doc, 1, a0, kNone, kNone, text)

// clang-format off
} // namespace

constexpr CncRow kRows[kRowCount] = {
    // ---- 6.1 NC functions (channel C = operand 0 unless noted) ----
    ROW1(ChannelModeSet, Channel, 0, false,
         modeSet(0, 60, 1),
         "one-hot mode 1..64 -> GC[60].0-6 and its code -> GC[0].0-3 (while ACT)"),
    ROW1(ChannelModeGet, Channel, 0, false, modeGet(0, 1),
         "destination := one-hot of the mode code FC[0].0-3 (while ACT)"),
    ROW(MdiMode, Channel, 0, false, 2, field(0, 0, 4, 8), field(60, 0, 7, 0), kNone,
        "GC[0].0-3 := 8 (MDI) and GC[60].0-6 := 0 (while ACT)"),
    ROW1(MstLock, Channel, 0, false, level(2, 11), "GC[2].11 MST lock := ACT"),
    ROW1(CycleStart, Channel, 0, false, level(0, 5), "GC[0].5 cycle start := ACT"),
    ROW1(EmergencyStop, Channel, 0, false, level(0, 11), "GC[0].11 emergency stop := ACT"),
    ROW1(ChannelReset, Channel, 0, false, level(0, 13), "GC[0].13 machine reset := ACT"),
    ROW1(ChannelSwitch, System, 0, false, write(2970, 1, 0), "G2970 active channel := C (while ACT)"),
    ROW1(FeedHold, Channel, 0, false, level(0, 4), "GC[0].4 feed hold := ACT"),
    ROW1(CycleStartLamp, Channel, 0, false, status(0, 5), "output := ACT and FC[0].5 (cycle running)"),
    ROW1(FeedHoldLamp, Channel, 0, false, status(0, 4), "output := ACT and FC[0].4 (feed hold)"),
    ROW(SkipG31, Channel, 0, false, 2, write(22, 1, 1), level(0, 7), kNone,
        "GC[22] := G31 number (while ACT); GC[0].7 measurement interrupt := ACT"),
    ROW1(RapidOverride, Channel, 0, false, write(5, 1, 1), "GC[5] rapid override := value (while ACT)"),
    ROW1(FeedOverride, Channel, 0, false, write(4, 1, 1), "GC[4] feed override := value (while ACT)"),
    ROW1(SpindleOverride, Channel, 0, false,
         writeAt(6, 1, 2),
         "GC[6+sp] spindle override := value (while ACT)"),
    ROW1(StepMultiplier, Axis, 0, false, write(8, 1, 1), "GA[8] increment multiplier := value (while ACT)"),
    ROW1(DryRun, Channel, 0, false, level(0, 6), "GC[0].6 dry run := ACT"),
    ROW1(BlockSkip, Channel, 0, false, level(1, 2), "GC[1].2 block skip := ACT"),
    ROW1(UserInput, Channel, 0, false, levelAt(24, 0, 2, 0, 31),
         "bit p of the 32-bit user input GC[24..25] := ACT (macro #1190)"),
    ROW1(UserOutput, Channel, 0, true, userOut(44, 2),
         "4 bytes from the destination := the 32-bit user output FC[44..45] (while ACT)"),
    ROW1(OptionalStop, Channel, 0, false, level(1, 3), "GC[1].3 optional stop := ACT"),
    // ---- 6.2 axis function units (axis A = operand 0) ----
    ROW(SpindleJog, Axis, 0, false, 2, levelDir(1, 6, 1, true), levelDir(1, 7, 1, false), kNone,
        "GA[1].6 forward := ACT and dir; GA[1].7 reverse := ACT and not dir"),
    ROW(BusSpindle, Channel, 0, false, 2, spindle(-1, -1), spindleAck(), kNone,
        "GC[10+2sp] := S * GC[6+sp] / 100 (while ACT); GC[2].sp := ACT and FC[2].(12+sp)"),
    ROW(BusSpindleGeared, Channel, 0, false, 2, spindle(2, 3), spindleAck(), kNone,
        "as SPDLBUS, scaled by the gear's P block (ratio, motor maximum)"),
    ROW1(SpindleOrient, Axis, 0, false, level(2, 12), "GA[2].12 spindle orientation := ACT"),
    ROW1(SpindleOrientDone, Axis, 0, false, status(3, 8), "output := ACT and FA[3].8 (orientation done)"),
    ROW1(SpindleZeroSpeed, Axis, 0, false, status(2, 15), "output := ACT and FA[2].15 (zero speed)"),
    ROW1(SpindleSpeedReached, Axis, 0, false, status(2, 14), "output := ACT and FA[2].14 (speed reached)"),
    ROW1(SlaveRelease, Axis, 0, false, level(0, 11), "GA[0].11 release slave := ACT"),
    ROW1(AxisJog, Axis, 0, false, jog(4, 1, true), "GA[4] := ACT ? (dir ? +1 : -1) : 0"),
    ROW1(AxisStep, Axis, 0, false, jog(5, 1, false), "GA[5] := ACT ? (dir ? -1 : +1) : 0"),
    ROW1(JogSpeed, Axis, 0, false, write(6, 2, 1), "GA[6/7] jog speed := value (while ACT)"),
    ROW1(HomingStart, Axis, 0, false, level(0, 4), "GA[0].4 homing start := ACT"),
    ROW1(HomingStartDir, Axis, 0, false, level(0, 4),
         "GA[0].4 homing start := ACT (the direction has no G bit)"),
    ROW1(HomeDog, Axis, 0, false, level(0, 5), "GA[0].5 home dog := ACT"),
    ROW1(HomingDoneLamp, Axis, 0, false, status(0, 4), "output := ACT and FA[0].4 (homing done)"),
    ROW1(AxisEnable, Axis, 0, false, level(0, 7), "GA[0].7 axis enable := ACT"),
    ROW1(AxisReady, Axis, 0, false, push(2, 8), "push FA[2].8 (bus servo ready)"),
    ROW1(AxisLock, Axis, 0, false, level(0, 6), "GA[0].6 axis lock := ACT"),
    ROW(AxisMoveRelative, Axis, 0, false, 2, write(52, 4, 1), level(1, 1), kNone,
        "GA[52..55] (64 bit) := distance (while ACT); GA[1].1 relative move := ACT"),
    ROW(AxisMoveAbsolute, Axis, 0, false, 2, write(48, 4, 1), level(1, 0), kNone,
        "GA[48..51] (64 bit) := target (while ACT); GA[1].0 absolute move := ACT"),
    ROW1(SecondSoftLimit, Axis, 0, false, level(1, 2), "GA[1].2 second soft limit := ACT"),
    ROW1(PositiveLimitDog, Axis, 0, false, level(0, 0), "GA[0].0 positive limit := ACT"),
    ROW1(NegativeLimitDog, Axis, 0, false, level(0, 1), "GA[0].1 negative limit := ACT"),
    ROW1(ServoEnable, Axis, 0, false, level(3, 0), "GA[3].0 servo enable := ACT"),
    ROW(AxisControlMode, Axis, 0, false, 2,
        fieldShl(2, 9, 3, 1), levelAt(2, 9, 1, 0, 2), kNone,
        "GA[2].9-11 := one-hot of mode (while ACT); GA[2].(9+mode) := ACT"),
    ROW1(ReferencePoint, Axis, 0, false, statusAt(0, 9, 1, 2, 4),
         "output := ACT and FA[0].(7+n) for n = 2..4; n = 5 has no bit: output 0"),
    ROW1(AxisHoming, Axis, 0, true, status(0, 2), "output := ACT and FA[0].2 (homing phase 2)"),
    ROW1(AxisMoving, Axis, 0, true, status(0, 0), "output := ACT and FA[0].0 (axis moving)"),
    // ---- 6.3 system functions ----
    ROW(Alarm, System, -1, false, 2, levelAt(3010, 0, 0, 1, 256), levelAt(3056, 0, 0, 501, 884),
        kNone, "alarm n: G3010 bit n-1 := ACT; prompt n: G3056 bit n-501 := ACT"),
    ROW1(ResetRequested, Channel, 0, false, status(0, 12), "output := ACT and FC[0].12 (reset flag)"),
    ROW1(ResetClear, Channel, 0, false, level(0, 9), "GC[0].9 PLC reset acknowledge := ACT"),
};
// clang-format on

#undef ROW
#undef ROW1

namespace {

constexpr bool rowsComplete() {
  // One row per Cnc-family Op, in Op order.
  int n = 0;
  for (const CncRow &r : kRows) {
    if (static_cast<int>(r.op) != static_cast<int>(Op::ChannelModeSet) + n) return false;
    ++n;
  }
  // ResetClear is the last Cnc op; dialect-only ops follow it (ir/OpTable.h).
  return n == static_cast<int>(Op::ResetClear) - static_cast<int>(Op::ChannelModeSet) + 1;
}
static_assert(rowsComplete(), "one CNC row per family-Cnc Op, in Op order");

} // namespace

const CncRow *cncRow(Op op) {
  if (opFamily(op) != Family::Cnc) return nullptr;
  return &kRows[static_cast<int>(op) - static_cast<int>(Op::ChannelModeSet)];
}

std::span<const CncRow> cncTable() { return kRows; }

} // namespace lj::cnc

// FANUC rotation control (ROT SUB 6, ROTB SUB 26) on every engine. The reference names them only
// (../shared/reference/fanuc-pmc.md 6.10: inputs RN0, BYT or format, DIR, POS, INC, ACT;
// parameters number of positions, current, target, result; W1 = rotation direction), so the
// rules are the [EXT] rows of docs/fanuc-pmc.md ("Rotation control"), with the data formats of
// 3.1 (signed little-endian binary) and 3.2 (BCD). Every expected value below is worked out by
// hand from those rules in the comment before it, never taken from what the code printed:
//   s = RN0 (positions s..s+n-1), c' = c - s, g' = g - s, fwd = (g' - c') mod n,
//   rev = (c' - g') mod n; DIR = 0 forward; DIR = 1 the shorter way, a tie forward;
//   result POS 0 INC 0 the goal g, POS 1 INC 0 the position before the goal in the direction
//   of rotation (forward ((g' - 1) mod n) + s, reverse ((g' + 1) mod n) + s), POS 0 INC 1 the
//   steps, POS 1 INC 1 the steps - 1 (0 when the steps are 0); W1 0 forward, 1 reverse;
//   an error (invalid BCD, a position out of range, n < 2, a result too wide) writes nothing
//   and keeps W1, as ACT = 0 does.
#include "tests/exec/FanucExec.h"

namespace lj::test {
namespace {

class FanucRot : public FanucExecTest {
protected:
  static int64_t byte(Machine &m, std::string_view a) { return get(m, a) & 0xFF; }
  /// The control inputs, ST5..ST0 as loaded (RN0 X0.5, BYT X0.4, DIR X0.3, POS X0.2, INC X0.1,
  /// ACT X0.0); ROTB has no BYT.
  static void inputs(Machine &m, int rn0, int byt, int dir, int pos, int inc, int act) {
    set(m, "X0.5", rn0);
    set(m, "X0.4", byt);
    set(m, "X0.3", dir);
    set(m, "X0.2", pos);
    set(m, "X0.1", inc);
    set(m, "X0.0", act);
  }
  /// One tick of ROT with the given DIR/POS/INC (ACT = 1, RN0 and BYT as given).
  static void rot(Machine &m, int rn0, int byt, int dir, int pos, int inc) {
    inputs(m, rn0, byt, dir, pos, inc, 1);
    m.tick();
  }
};
LJ_EXEC_SUITE(FanucRot);

constexpr const char *kIn6 = "RD X0.5\nRD.STK X0.4\nRD.STK X0.3\nRD.STK X0.2\nRD.STK X0.1\n"
                             "RD.STK X0.0\n";
constexpr const char *kIn5 = "RD X0.5\nRD.STK X0.3\nRD.STK X0.2\nRD.STK X0.1\nRD.STK X0.0\n";
constexpr const char *kEnd = "WRT R0.0\nEND1\nEND2\nEND\n";

// The worked magazine: 12 positions numbered 1..12 (RN0 = 1), current R10 = BCD 02, goal R12 =
// BCD 10, result R14 (BYT = 0: 2 digits, 1 byte). c' = 1, g' = 9: fwd = 8, rev = (1 - 9) mod 12
// = 4.
//   DIR = 1: rev 4 < fwd 8, reverse, W1 = 1: INC 1 POS 0 -> 4, INC 1 POS 1 -> 3, INC 0 POS 1 ->
//   ((9 + 1) mod 12) + 1 = 11, INC 0 POS 0 -> 10.
//   DIR = 0: forward, W1 = 0: INC 1 POS 0 -> 8, INC 1 POS 1 -> 7, INC 0 POS 1 -> ((9 - 1) mod
//   12) + 1 = 9, INC 0 POS 0 -> 10.
TEST_P(FanucRot, MagazineShortestWay) {
  auto m = pmc(std::string(kIn6) + "ROT 12 R10 R12 R14\n" + kEnd);
  ASSERT_TRUE(m);
  set(*m, "R10", 0x02);
  set(*m, "R12", 0x10);
  set(*m, "R14", 0x77);
  m->tick(); // ACT = 0: nothing; W1 starts at 0
  EXPECT_EQ(byte(*m, "R14"), 0x77);
  EXPECT_EQ(get(*m, "R0.0"), 0);
  rot(*m, 1, 0, 1, 0, 1);
  EXPECT_EQ(byte(*m, "R14"), 0x04);
  EXPECT_EQ(get(*m, "R0.0"), 1);
  rot(*m, 1, 0, 1, 1, 1);
  EXPECT_EQ(byte(*m, "R14"), 0x03);
  EXPECT_EQ(get(*m, "R0.0"), 1);
  rot(*m, 1, 0, 1, 1, 0);
  EXPECT_EQ(byte(*m, "R14"), 0x11);
  EXPECT_EQ(get(*m, "R0.0"), 1);
  rot(*m, 1, 0, 1, 0, 0);
  EXPECT_EQ(byte(*m, "R14"), 0x10);
  EXPECT_EQ(get(*m, "R0.0"), 1);
  rot(*m, 1, 0, 0, 0, 1);
  EXPECT_EQ(byte(*m, "R14"), 0x08);
  EXPECT_EQ(get(*m, "R0.0"), 0);
  rot(*m, 1, 0, 0, 1, 1);
  EXPECT_EQ(byte(*m, "R14"), 0x07);
  rot(*m, 1, 0, 0, 1, 0);
  EXPECT_EQ(byte(*m, "R14"), 0x09);
  EXPECT_EQ(get(*m, "R0.0"), 0);
  rot(*m, 1, 0, 0, 0, 0);
  EXPECT_EQ(byte(*m, "R14"), 0x10);
  EXPECT_EQ(byte(*m, "R15"), 0); // BYT = 0 writes one byte
}

// ACT = 0 keeps W1 and the result: after the reverse move above (W1 = 1, result 4), a new goal
// with ACT = 0 changes nothing; with ACT = 1 again the goal BCD 03 gives c' = 1, g' = 2:
// fwd = 1, rev = 11, forward, W1 = 0, steps 1.
TEST_P(FanucRot, ActOffKeepsW1AndResult) {
  auto m = pmc(std::string(kIn6) + "ROT 12 R10 R12 R14\n" + kEnd);
  ASSERT_TRUE(m);
  set(*m, "R10", 0x02);
  set(*m, "R12", 0x10);
  rot(*m, 1, 0, 1, 0, 1);
  EXPECT_EQ(byte(*m, "R14"), 0x04);
  EXPECT_EQ(get(*m, "R0.0"), 1);
  set(*m, "R12", 0x03);
  inputs(*m, 1, 0, 1, 0, 1, 0);
  m->tick();
  m->tick();
  EXPECT_EQ(byte(*m, "R14"), 0x04);
  EXPECT_EQ(get(*m, "R0.0"), 1);
  rot(*m, 1, 0, 1, 0, 1);
  EXPECT_EQ(byte(*m, "R14"), 0x01);
  EXPECT_EQ(get(*m, "R0.0"), 0);
}

// RN0 = 0: positions 0..11. Current 0, goal 11: c' = 0, g' = 11, fwd = 11, rev = 1.
//   DIR = 1: reverse, W1 = 1: INC 0 POS 1 -> ((11 + 1) mod 12) + 0 = 0; INC 1 POS 1 -> 0.
//   DIR = 0: forward, W1 = 0: INC 0 POS 1 -> ((11 - 1) mod 12) + 0 = 10; INC 1 POS 0 -> 11.
// Goal 12 is outside 0..11 with RN0 = 0 (an error: result and W1 kept); with RN0 = 1 it is
// position 12 (g' = 11) and current 0 is outside 1..12.
TEST_P(FanucRot, PositionsFromZero) {
  auto m = pmc(std::string(kIn6) + "ROT 12 R10 R12 R14\n" + kEnd);
  ASSERT_TRUE(m);
  set(*m, "R10", 0x00);
  set(*m, "R12", 0x11);
  set(*m, "R14", 0x77);
  rot(*m, 0, 0, 1, 1, 0);
  EXPECT_EQ(byte(*m, "R14"), 0x00);
  EXPECT_EQ(get(*m, "R0.0"), 1);
  set(*m, "R14", 0x77);
  rot(*m, 0, 0, 1, 1, 1);
  EXPECT_EQ(byte(*m, "R14"), 0x00);
  rot(*m, 0, 0, 0, 1, 0);
  EXPECT_EQ(byte(*m, "R14"), 0x10);
  EXPECT_EQ(get(*m, "R0.0"), 0);
  rot(*m, 0, 0, 0, 0, 1);
  EXPECT_EQ(byte(*m, "R14"), 0x11);
  set(*m, "R12", 0x12);
  rot(*m, 0, 0, 1, 0, 0); // goal 12 with positions 0..11: error
  EXPECT_EQ(byte(*m, "R14"), 0x11);
  EXPECT_EQ(get(*m, "R0.0"), 0);
  rot(*m, 1, 0, 1, 0, 0); // current 0 with positions 1..12: error
  EXPECT_EQ(byte(*m, "R14"), 0x11);
  EXPECT_EQ(get(*m, "R0.0"), 0);
}

// The position before the goal wraps: RN0 = 1, current 5, goal 1, DIR = 0: forward, g' = 0,
// ((0 - 1) mod 12) + 1 = 12.
TEST_P(FanucRot, PositionBeforeWraps) {
  auto m = pmc(std::string(kIn6) + "ROT 12 R10 R12 R14\n" + kEnd);
  ASSERT_TRUE(m);
  set(*m, "R10", 0x05);
  set(*m, "R12", 0x01);
  rot(*m, 1, 0, 0, 1, 0);
  EXPECT_EQ(byte(*m, "R14"), 0x12);
  EXPECT_EQ(get(*m, "R0.0"), 0);
}

// A tie goes forward: n = 8, RN0 = 0, DIR = 1, INC = 1, current 0.
//   goal 5: fwd 5, rev 3: reverse, W1 = 1, steps 3.
//   goal 4: fwd 4, rev 4: a tie, forward, W1 = 0, steps 4; POS = 1 INC = 0: ((4 - 1) mod 8) = 3.
//   goal 3: fwd 3, rev 5: forward, W1 = 0, steps 3.
TEST_P(FanucRot, TieGoesForward) {
  auto m = pmc(std::string(kIn6) + "ROT 8 R10 R12 R14\n" + kEnd);
  ASSERT_TRUE(m);
  set(*m, "R10", 0x00);
  set(*m, "R12", 0x05);
  rot(*m, 0, 0, 1, 0, 1);
  EXPECT_EQ(byte(*m, "R14"), 0x03);
  EXPECT_EQ(get(*m, "R0.0"), 1);
  set(*m, "R12", 0x04);
  rot(*m, 0, 0, 1, 0, 1);
  EXPECT_EQ(byte(*m, "R14"), 0x04);
  EXPECT_EQ(get(*m, "R0.0"), 0);
  rot(*m, 0, 0, 1, 1, 0);
  EXPECT_EQ(byte(*m, "R14"), 0x03);
  EXPECT_EQ(get(*m, "R0.0"), 0);
  set(*m, "R12", 0x03);
  rot(*m, 0, 0, 1, 0, 1);
  EXPECT_EQ(byte(*m, "R14"), 0x03);
  EXPECT_EQ(get(*m, "R0.0"), 0);
}

// Current = goal (RN0 = 1, n = 12, both 7): fwd = rev = 0, a tie, forward, W1 = 0 (after a
// reverse move set it to 1): INC 1 POS 0 -> 0, INC 1 POS 1 -> 0 (steps 0), INC 0 POS 0 -> 7,
// INC 0 POS 1 -> ((6 - 1) mod 12) + 1 = 6.
TEST_P(FanucRot, CurrentIsGoal) {
  auto m = pmc(std::string(kIn6) + "ROT 12 R10 R12 R14\n" + kEnd);
  ASSERT_TRUE(m);
  set(*m, "R10", 0x02);
  set(*m, "R12", 0x10);
  rot(*m, 1, 0, 1, 0, 1); // the worked reverse move: W1 = 1
  ASSERT_EQ(get(*m, "R0.0"), 1);
  set(*m, "R10", 0x07);
  set(*m, "R12", 0x07);
  rot(*m, 1, 0, 1, 0, 1);
  EXPECT_EQ(byte(*m, "R14"), 0x00);
  EXPECT_EQ(get(*m, "R0.0"), 0);
  set(*m, "R14", 0x77);
  rot(*m, 1, 0, 1, 1, 1);
  EXPECT_EQ(byte(*m, "R14"), 0x00);
  rot(*m, 1, 0, 1, 0, 0);
  EXPECT_EQ(byte(*m, "R14"), 0x07);
  rot(*m, 1, 0, 1, 1, 0);
  EXPECT_EQ(byte(*m, "R14"), 0x06);
  EXPECT_EQ(get(*m, "R0.0"), 0);
}

// Invalid BCD (a nibble above 9) and out-of-range positions write nothing and keep W1: after
// the worked reverse move (W1 = 1, result 4), current 0x1A, goal 0xA1, goal BCD 13 (outside
// 1..12) and goal 00 (outside 1..12) each leave R14 = 4 and W1 = 1.
TEST_P(FanucRot, ErrorsKeepResultAndW1) {
  auto m = pmc(std::string(kIn6) + "ROT 12 R10 R12 R14\n" + kEnd);
  ASSERT_TRUE(m);
  set(*m, "R10", 0x02);
  set(*m, "R12", 0x10);
  rot(*m, 1, 0, 1, 0, 1);
  ASSERT_EQ(byte(*m, "R14"), 0x04);
  ASSERT_EQ(get(*m, "R0.0"), 1);
  const std::pair<const char *, int> bad[] = {
      {"R10", 0x1A}, {"R12", 0xA1}, {"R12", 0x13}, {"R12", 0x00}};
  for (const auto &[a, v] : bad) {
    set(*m, "R10", 0x02);
    set(*m, "R12", 0x10);
    set(*m, a, v);
    rot(*m, 1, 0, 0, 0, 1); // DIR = 0 would give W1 = 0, steps 8
    EXPECT_EQ(byte(*m, "R14"), 0x04) << a << " = " << v;
    EXPECT_EQ(get(*m, "R0.0"), 1) << a << " = " << v;
  }
}

// BYT = 1: 4-digit BCD in 2 bytes, n = 200, RN0 = 1 (positions 1..200).
//   current 150 (R10 0x50, R11 0x01), goal 3 (R12 0x03, R13 0x00): c' = 149, g' = 2,
//   fwd = (2 - 149) mod 200 = 53, rev = 147. DIR = 1: forward, W1 = 0: INC 1 -> 53 (R14 0x53,
//   R15 0x00); INC 0 POS 1 -> ((2 - 1) mod 200) + 1 = 2; INC 0 POS 0 -> 3.
//   current 3, goal 150: fwd 147, rev 53: reverse, W1 = 1: INC 0 POS 1 -> ((149 + 1) mod 200)
//   + 1 = 151 (R14 0x51, R15 0x01); INC 0 POS 0 -> 150.
//   A nibble above 9 in the high byte (R13 0xA0) with BYT = 1 is invalid BCD: nothing written.
TEST_P(FanucRot, FourDigitBcd) {
  auto m = pmc(std::string(kIn6) + "ROT 200 R10 R12 R14\n" + kEnd);
  ASSERT_TRUE(m);
  set(*m, "R10", 0x50);
  set(*m, "R11", 0x01);
  set(*m, "R12", 0x03);
  set(*m, "R15", 0x77);
  rot(*m, 1, 1, 1, 0, 1);
  EXPECT_EQ(byte(*m, "R14"), 0x53);
  EXPECT_EQ(byte(*m, "R15"), 0x00);
  EXPECT_EQ(get(*m, "R0.0"), 0);
  rot(*m, 1, 1, 1, 1, 0);
  EXPECT_EQ(byte(*m, "R14"), 0x02);
  rot(*m, 1, 1, 1, 0, 0);
  EXPECT_EQ(byte(*m, "R14"), 0x03);
  EXPECT_EQ(byte(*m, "R15"), 0x00);
  set(*m, "R10", 0x03);
  set(*m, "R11", 0x00);
  set(*m, "R12", 0x50);
  set(*m, "R13", 0x01);
  rot(*m, 1, 1, 1, 1, 0);
  EXPECT_EQ(byte(*m, "R14"), 0x51);
  EXPECT_EQ(byte(*m, "R15"), 0x01);
  EXPECT_EQ(get(*m, "R0.0"), 1);
  rot(*m, 1, 1, 1, 0, 0);
  EXPECT_EQ(byte(*m, "R14"), 0x50);
  EXPECT_EQ(byte(*m, "R15"), 0x01);
  set(*m, "R13", 0xA0);
  rot(*m, 1, 1, 0, 0, 1);
  EXPECT_EQ(byte(*m, "R14"), 0x50);
  EXPECT_EQ(get(*m, "R0.0"), 1);
}

// BYT = 0 with n = 200: the positions are the low bytes' 2 digits and the result must fit 2
// digits. Current R10 0x03, goal R12 0x50 (high bytes 0x01 ignored): c' = 2, g' = 49, fwd = 47,
// rev = 153: DIR = 1 forward, steps 47 (R14 only; R15 kept). Swapped (current 50, goal 3):
// fwd = (2 - 49) mod 200 = 153; DIR = 0 gives steps 153, more than 2 digits: nothing written,
// W1 kept; DIR = 1 gives rev 47, reverse, W1 = 1. Goal 1, DIR = 0, POS = 1: the position
// before is ((0 - 1) mod 200) + 1 = 200, too wide as well.
TEST_P(FanucRot, TwoDigitResultLimit) {
  auto m = pmc(std::string(kIn6) + "ROT 200 R10 R12 R14\n" + kEnd);
  ASSERT_TRUE(m);
  set(*m, "R10", 0x03);
  set(*m, "R11", 0x01);
  set(*m, "R12", 0x50);
  set(*m, "R13", 0x01);
  set(*m, "R15", 0x77);
  rot(*m, 1, 0, 1, 0, 1);
  EXPECT_EQ(byte(*m, "R14"), 0x47);
  EXPECT_EQ(byte(*m, "R15"), 0x77);
  EXPECT_EQ(get(*m, "R0.0"), 0);
  set(*m, "R10", 0x50);
  set(*m, "R12", 0x03);
  rot(*m, 1, 0, 0, 0, 1);
  EXPECT_EQ(byte(*m, "R14"), 0x47);
  EXPECT_EQ(get(*m, "R0.0"), 0);
  rot(*m, 1, 0, 1, 0, 1);
  EXPECT_EQ(byte(*m, "R14"), 0x47);
  EXPECT_EQ(get(*m, "R0.0"), 1);
  set(*m, "R12", 0x01);
  rot(*m, 1, 0, 0, 1, 0);
  EXPECT_EQ(byte(*m, "R14"), 0x47);
  EXPECT_EQ(get(*m, "R0.0"), 1);
}

// ROTB format 1 in the SUB 26 form: n at R20 (1 byte), current R21, goal R22, result R23.
// The worked magazine in binary (n = 12, RN0 = 1, current 2, goal 10): DIR = 1 reverse, W1 = 1,
// steps 4; DIR = 0 forward, W1 = 0, steps 8.
// n changes between scans: n = 8 puts goal 10 outside 1..8 (error: R23 and W1 kept); n = 16
// gives c' = 1, g' = 9, fwd = 8, rev = (1 - 9) mod 16 = 8, a tie, forward, W1 = 0, steps 8
// (after W1 was set to 1 again); n = 1 and n = -5 (0xFB) are errors (n < 2); a current of -1
// (0xFF, signed 3.1) is outside 1..16.
TEST_P(FanucRot, RotbByteCountFromMemory) {
  auto m = pmc(std::string(kIn5) + "SUB 26\n(PRM) 1\n(PRM) R20\n(PRM) R21\n(PRM) R22\n(PRM) R23\n" +
               kEnd);
  ASSERT_TRUE(m);
  set(*m, "R20", 12);
  set(*m, "R21", 2);
  set(*m, "R22", 10);
  rot(*m, 1, 0, 1, 0, 1);
  EXPECT_EQ(get(*m, "R23"), 4);
  EXPECT_EQ(get(*m, "R0.0"), 1);
  rot(*m, 1, 0, 0, 0, 1);
  EXPECT_EQ(get(*m, "R23"), 8);
  EXPECT_EQ(get(*m, "R0.0"), 0);
  rot(*m, 1, 0, 1, 0, 1); // W1 = 1 again, R23 = 4
  set(*m, "R20", 8);
  rot(*m, 1, 0, 0, 0, 1);
  EXPECT_EQ(get(*m, "R23"), 4);
  EXPECT_EQ(get(*m, "R0.0"), 1);
  set(*m, "R20", 16);
  rot(*m, 1, 0, 1, 0, 1);
  EXPECT_EQ(get(*m, "R23"), 8);
  EXPECT_EQ(get(*m, "R0.0"), 0);
  rot(*m, 1, 0, 1, 1, 0); // forward: ((9 - 1) mod 16) + 1 = 9
  EXPECT_EQ(get(*m, "R23"), 9);
  for (int n : {1, -5}) {
    set(*m, "R20", n);
    rot(*m, 1, 0, 1, 0, 0);
    EXPECT_EQ(get(*m, "R23"), 9) << n;
  }
  set(*m, "R20", 16);
  set(*m, "R21", -1);
  rot(*m, 1, 0, 1, 0, 0);
  EXPECT_EQ(get(*m, "R23"), 9);
  EXPECT_EQ(get(*m, "R0.0"), 0);
}

// ROTB with the result written over n (R30): n = 12, RN0 = 1, current 2, goal 10, DIR = 1,
// INC = 1: steps 4 -> R30 = 4 (W1 = 1). Next scan n = 4: goal 10 outside 1..4, an error
// (R30 stays 4, W1 stays 1). Goal 3: c' = 1, g' = 2, n = 4: fwd 1, rev 3, forward, W1 = 0,
// R30 = 1. Next scan n = 1 < 2: an error, R30 = 1 and W1 = 0 kept.
TEST_P(FanucRot, RotbResultOverCount) {
  auto m = pmc(std::string(kIn5) + "ROTB 1 R30 R31 R32 R30\n" + kEnd);
  ASSERT_TRUE(m);
  set(*m, "R30", 12);
  set(*m, "R31", 2);
  set(*m, "R32", 10);
  rot(*m, 1, 0, 1, 0, 1);
  EXPECT_EQ(get(*m, "R30"), 4);
  EXPECT_EQ(get(*m, "R0.0"), 1);
  m->tick();
  EXPECT_EQ(get(*m, "R30"), 4);
  EXPECT_EQ(get(*m, "R0.0"), 1);
  set(*m, "R32", 3);
  m->tick();
  EXPECT_EQ(get(*m, "R30"), 1);
  EXPECT_EQ(get(*m, "R0.0"), 0);
  m->tick();
  EXPECT_EQ(get(*m, "R30"), 1);
  EXPECT_EQ(get(*m, "R0.0"), 0);
}

// ROTB format 2: n = 1000 at D0 (0x03E8, both bytes count), RN0 = 0, current 10, goal 990:
// c' = 10, g' = 990, fwd = 980, rev = (10 - 990) mod 1000 = 20. DIR = 1: reverse, W1 = 1:
// INC 1 POS 0 -> 20; INC 1 POS 1 -> 19; INC 0 POS 1 -> (990 + 1) mod 1000 = 991. DIR = 0:
// INC 1 -> 980, W1 = 0. ACT = 0 keeps D6 and W1.
TEST_P(FanucRot, RotbTwoBytes) {
  auto m = pmc(std::string(kIn5) + "ROTB 2 D0 D2 D4 D6\n" + kEnd);
  ASSERT_TRUE(m);
  set(*m, "D0:2", 1000);
  set(*m, "D2:2", 10);
  set(*m, "D4:2", 990);
  rot(*m, 0, 0, 1, 0, 1);
  EXPECT_EQ(get(*m, "D6:2"), 20);
  EXPECT_EQ(get(*m, "R0.0"), 1);
  rot(*m, 0, 0, 1, 1, 1);
  EXPECT_EQ(get(*m, "D6:2"), 19);
  rot(*m, 0, 0, 1, 1, 0);
  EXPECT_EQ(get(*m, "D6:2"), 991);
  EXPECT_EQ(get(*m, "R0.0"), 1);
  rot(*m, 0, 0, 0, 0, 1);
  EXPECT_EQ(get(*m, "D6:2"), 980);
  EXPECT_EQ(get(*m, "R0.0"), 0);
  rot(*m, 0, 0, 1, 0, 1); // W1 = 1, D6 = 20
  inputs(*m, 0, 0, 0, 0, 1, 0);
  m->tick();
  EXPECT_EQ(get(*m, "D6:2"), 20);
  EXPECT_EQ(get(*m, "R0.0"), 1);
}

// ROTB format 4: n = 100000 at D10, RN0 = 1, current 1, goal 100000: c' = 0, g' = 99999,
// fwd = 99999, rev = 1. DIR = 1: reverse, W1 = 1: INC 1 POS 0 -> 1; INC 1 POS 1 -> 0; INC 0 POS 1
// -> ((99999 + 1) mod 100000) + 1 = 1; INC 0 POS 0 -> 100000. DIR = 0: INC 1 -> 99999, W1 = 0;
// INC 0 POS 1 -> ((99999 - 1) mod 100000) + 1 = 99999.
TEST_P(FanucRot, RotbFourBytes) {
  auto m = pmc(std::string(kIn5) + "ROTB 4 D10 D14 D18 D22\n" + kEnd);
  ASSERT_TRUE(m);
  set(*m, "D10:4", 100000);
  set(*m, "D14:4", 1);
  set(*m, "D18:4", 100000);
  set(*m, "D22:4", -7);
  rot(*m, 1, 0, 1, 0, 1);
  EXPECT_EQ(get(*m, "D22:4"), 1);
  EXPECT_EQ(get(*m, "R0.0"), 1);
  rot(*m, 1, 0, 1, 1, 1);
  EXPECT_EQ(get(*m, "D22:4"), 0);
  rot(*m, 1, 0, 1, 1, 0);
  EXPECT_EQ(get(*m, "D22:4"), 1);
  rot(*m, 1, 0, 1, 0, 0);
  EXPECT_EQ(get(*m, "D22:4"), 100000);
  EXPECT_EQ(get(*m, "R0.0"), 1);
  rot(*m, 1, 0, 0, 0, 1);
  EXPECT_EQ(get(*m, "D22:4"), 99999);
  EXPECT_EQ(get(*m, "R0.0"), 0);
  rot(*m, 1, 0, 0, 1, 0);
  EXPECT_EQ(get(*m, "D22:4"), 99999);
}

// ROT in the SUB 6 form with (PRM) lines, n = 2 (the smallest): RN0 = 0, current 1, goal 0:
// fwd = (0 - 1) mod 2 = 1, rev = 1, a tie, forward (W1 = 0) even with DIR = 1; steps 1.
TEST_P(FanucRot, SubSixForm) {
  auto m = pmc(std::string(kIn6) + "SUB 6\n(PRM) 2\n(PRM) D0\n(PRM) D2\n(PRM) D4\n" + kEnd);
  ASSERT_TRUE(m);
  set(*m, "D0", 0x01);
  set(*m, "D2", 0x00);
  set(*m, "D4", 0x77);
  rot(*m, 0, 0, 1, 0, 1);
  EXPECT_EQ(byte(*m, "D4"), 0x01);
  EXPECT_EQ(get(*m, "R0.0"), 0);
}

} // namespace
} // namespace lj::test

// FANUC level 2 reads X and F through its synchronized input memory (FANUC 0i-D PMC manual 4.1
// [L841-L843]: "level 2 has a synchronized input signal memory, so an input pulse must be wider
// than the scan"; the latch point, the first slice of each level-2 scan, is the reading in
// docs/fanuc-pmc.md "Level 2 and its inputs"). Level 1 reads the live inputs every tick.
// Expected values follow from that model and the schedule of DIALECT.md 4 (tick t runs level 1,
// then slice t mod n of level 2), never from what an engine printed.
#include "pipeline/Compile.h"
#include "tests/exec/FanucExec.h"

#include "tests/support/Machine.h"

#include <optional>
#include <string>

namespace lj::test {
namespace {

class FanucSyncInput : public FanucExecTest {};
LJ_EXEC_SUITE(FanucSyncInput);

// The program: level 2 is four rungs of two statements, so --plc2-nvalue 2 gives four
// slices and a level-2 scan takes ticks 4k .. 4k+3 (slice 0 = R1.0, 1 = R1.3, 2 = R1.1,
// 3 = R1.2).
constexpr const char *kThreeReads = "RD X0.0\nWRT R2.0\nEND1\n"
                                    "RD X0.0\nWRT R1.0\n"
                                    "RD F1.0\nWRT R1.3\n"
                                    "RD X0.0\nWRT R1.1\n"
                                    "RD X0.0\nWRT R1.2\n"
                                    "END2\nEND\n";

// X0.0 = 1 at tick 4 only, the tick the second level-2 scan starts: the three reads of X0.0 in
// that scan (ticks 4, 6, 7) all see the latched 1, so R1.0, R1.1 and R1.2 are all 1 in it; the
// next scan (tick 8) latches 0 again. Level 1 (R2.0) follows the live input: 1 at tick 4 only.
TEST_P(FanucSyncInput, ThreeReadsOfOneInputAgreeInOneScan) {
  auto m = pmc(kThreeReads, optionsWithNvalue(2));
  ASSERT_TRUE(m);
  ASSERT_EQ(m->engine().entries().plc2_slice_count, 4u);
  //                        tick: 0  1  2  3  4  5  6  7  8  9 10 11
  const int x00[12] = /*     */ {0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0};
  const int r20[12] = /* live */ {0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0};
  const int r10[12] = /* s0   */ {0, 0, 0, 0, 1, 1, 1, 1, 0, 0, 0, 0};
  const int r11[12] = /* s2   */ {0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 0, 0};
  const int r12[12] = /* s3   */ {0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 0};
  for (int t = 0; t < 12; ++t) {
    set(*m, "X0.0", x00[t]);
    m->tick();
    SCOPED_TRACE("after tick " + std::to_string(t));
    EXPECT_EQ(get(*m, "R2.0"), r20[t]);
    EXPECT_EQ(get(*m, "R1.0"), r10[t]);
    EXPECT_EQ(get(*m, "R1.1"), r11[t]);
    EXPECT_EQ(get(*m, "R1.2"), r12[t]);
    EXPECT_EQ(get(*m, "R1.3"), 0);
  }
}

// Inputs that change in the middle of a level-2 scan: X0.0 goes 0 -> 1 at tick 5 (after the
// scan of ticks 4..7 latched 0) and stays 1; F1.0 is 1 at tick 4 only (latched) and 0 when slice
// 1 reads it at tick 5. Level 2 sees X0.0 = 0 for the whole scan and only from the scan of tick
// 8 on sees 1; it sees F1.0 = 1 in the scan of tick 4 and 0 from tick 8. Level 1 sees X0.0 = 1
// from tick 5.
TEST_P(FanucSyncInput, InputChangedMidScanWaitsForTheNextScan) {
  auto m = pmc(kThreeReads, optionsWithNvalue(2));
  ASSERT_TRUE(m);
  //                        tick: 0  1  2  3  4  5  6  7  8  9 10 11 12
  const int x00[13] = /*     */ {0, 0, 0, 0, 0, 1, 1, 1, 1, 1, 1, 1, 1};
  const int f10[13] = /*     */ {0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0};
  const int r20[13] = /* live */ {0, 0, 0, 0, 0, 1, 1, 1, 1, 1, 1, 1, 1};
  const int r10[13] = /* s0   */ {0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 1};
  const int r13[13] = /* s1   */ {0, 0, 0, 0, 0, 1, 1, 1, 1, 0, 0, 0, 0};
  const int r11[13] = /* s2   */ {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 1, 1};
  const int r12[13] = /* s3   */ {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 1};
  for (int t = 0; t < 13; ++t) {
    set(*m, "X0.0", x00[t]);
    set(*m, "F1.0", f10[t]);
    m->tick();
    SCOPED_TRACE("after tick " + std::to_string(t));
    EXPECT_EQ(get(*m, "R2.0"), r20[t]);
    EXPECT_EQ(get(*m, "R1.0"), r10[t]);
    EXPECT_EQ(get(*m, "R1.3"), r13[t]);
    EXPECT_EQ(get(*m, "R1.1"), r11[t]);
    EXPECT_EQ(get(*m, "R1.2"), r12[t]);
  }
}

// Byte and word reads of X and F by functional instructions, in level 2 and in a subroutine it
// calls, read the latch too. Level 2 (nvalue 2): slice 0 RD X0.0 / WRT R1.0, slice 1 MOVB X0 ->
// R10, slice 2 CALLU P1 (P1: X0.1 -> R14.1, MOVB F2 -> R15), slice 3 MOVW F0 -> R12. Inputs
// X0 = 3, F0..F1 = 0x1234, F2 = 0x56 at tick 4 only, then X0 = 0x40 and F0..F2 = 0: the scan of
// ticks 4..7 moves the tick-4 values although they changed at tick 5; the scan from tick 8 moves
// the new ones. Level 1 copies X0 live to R30.
TEST_P(FanucSyncInput, ByteWordAndSubroutineReadsUseTheLatch) {
  auto m = pmc("RD R9091.1\nMOVB X0 R30\nEND1\n"
               "RD X0.0\nWRT R1.0\n"
               "RD R9091.1\nMOVB X0 R10\n"
               "CALLU P1\n"
               "RD R9091.1\nMOVW F0 R12\n"
               "END2\n"
               "SP P1\nRD X0.1\nWRT R14.1\nRD R9091.1\nMOVB F2 R15\nSPE\n"
               "END\n",
               optionsWithNvalue(2));
  ASSERT_TRUE(m);
  ASSERT_EQ(m->engine().entries().plc2_slice_count, 4u);
  for (int t = 0; t < 12; ++t) {
    const bool pulse = t == 4;
    set(*m, "X0", pulse ? 3 : 0x40);
    set(*m, "F0:2", pulse ? 0x1234 : 0);
    set(*m, "F2", pulse ? 0x56 : 0);
    m->tick();
    SCOPED_TRACE("after tick " + std::to_string(t));
    EXPECT_EQ(get(*m, "R30"), pulse ? 3 : 0x40); // level 1: live
    if (t == 7) {                                // the end of the scan that latched tick 4's inputs
      EXPECT_EQ(get(*m, "R1.0"), 1);
      EXPECT_EQ(get(*m, "R10"), 3);
      EXPECT_EQ(get(*m, "R14.1"), 1);
      EXPECT_EQ(get(*m, "R15"), 0x56);
      EXPECT_EQ(get(*m, "R12:2"), 0x1234);
    }
    if (t == 11) { // the next scan latched X0 = 0x40, F = 0 at tick 8
      EXPECT_EQ(get(*m, "R1.0"), 0);
      EXPECT_EQ(get(*m, "R10"), 0x40);
      EXPECT_EQ(get(*m, "R14.1"), 0);
      EXPECT_EQ(get(*m, "R15"), 0);
      EXPECT_EQ(get(*m, "R12:2"), 0);
    }
  }
}

// Level 2 not divided (--plc2-nvalue 0: one slice, the whole of level 2 every tick): every scan
// starts in the tick it runs, right after level 1, so level 2 reads that tick's inputs (a pulse
// of one tick is seen by every read of it).
TEST_P(FanucSyncInput, UndividedLevel2ReadsTheInputsOfItsTick) {
  auto m = pmc(kThreeReads, optionsWithNvalue(0));
  ASSERT_TRUE(m);
  ASSERT_EQ(m->engine().entries().plc2_slice_count, 1u);
  for (int t = 0; t < 6; ++t) {
    set(*m, "X0.0", t == 3 ? 1 : 0);
    m->tick();
    SCOPED_TRACE("after tick " + std::to_string(t));
    for (const char *r : {"R2.0", "R1.0", "R1.1", "R1.2"})
      EXPECT_EQ(get(*m, r), t == 3 ? 1 : 0) << r;
  }
}

// What --plc2-nvalue counts (docs/fanuc-pmc.md "Dividing level 2"): the statements each
// instruction becomes, read here as the size of level 2 (one slice) and where slices end.
std::optional<VerifiedProgram> level2(const std::string &body, int32_t nvalue,
                                      const std::string &subs = "") {
  Diagnostics d("t.pmc");
  const std::string text = "END1\n" + body + "END2\n" + subs + "END\n";
  std::optional<VerifiedProgram> p =
      pipeline::compilePmc(text, "t.pmc", optionsWithNvalue(nvalue), d, nullptr);
  EXPECT_TRUE(p) << d.render();
  return p;
}
int32_t size(const VerifiedProgram &p) { return p.plc2.end - p.plc2.begin; }

TEST(FanucSliceCounts, EachInstructionCountsTheStatementsItBecomes) {
  const std::string sub = "SP P1\nSPE\nSP P2\nSPE\n";
  // Basic instructions 1 each; CALLU 2 (ACT = 1, CALL); CALL 1 (its ACT is the RD before it).
  EXPECT_EQ(size(*level2("RD X0.0\nAND X0.1\nWRT R1.0\nWRT R1.1\n", 0)), 4);
  EXPECT_EQ(size(*level2("CALLU P1\n", 0, sub)), 2);
  EXPECT_EQ(size(*level2("RD X0.0\nCALL P1\n", 0, sub)), 2);
  // MOVN n: n byte moves.
  EXPECT_EQ(size(*level2("RD R9091.1\nMOVN 5 D0 R0\n", 0)), 6);
  // CODB with 10 entries: 1 + ceil(10 / 9) = 3.
  EXPECT_EQ(size(*level2("RD R9091.0\nRD.STK R9091.1\nCODB 1 10 X0 R20 0 1 2 3 4 5 6 7 8 9\n", 0)),
            5);
  // COM 1, COME 0; JMP 1, JMPE 1.
  EXPECT_EQ(size(*level2("RD X0.0\nCOM\nRD X0.1\nWRT R1.1\nCOME\n", 0)), 4);
  EXPECT_EQ(size(*level2("RD X0.0\nJMP\nRD X0.1\nWRT R1.1\nJMPE\n", 0)), 5);
  // CS 1, each CM 3, CE 1.
  EXPECT_EQ(size(*level2("RD R9091.1\nCS D0\nCM P1\nCM P2\nCE\n", 0, sub)), 9);
}

TEST(FanucSliceCounts, ASliceMayEndBeforeCalluButNotInsideIt) {
  const std::string sub = "SP P1\nSPE\n";
  const std::string body = "RD X0.0\nWRT R1.0\nCALLU P1\nRD X0.1\nWRT R1.1\n";
  // nvalue 2: [RD, WRT] [CALLU = ACT, CALL] [RD, WRT].
  EXPECT_EQ(level2(body, 2, sub)->slices.size(), 3u);
  // nvalue 3: the third statement is CALLU's CALL, which reads CALLU's ACT: no boundary there,
  // the slice goes on to the next RD: [RD, WRT, CALLU] [RD, WRT].
  std::optional<VerifiedProgram> p = level2(body, 3, sub);
  ASSERT_EQ(p->slices.size(), 2u);
  EXPECT_EQ(p->slices[0].end - p->slices[0].begin, 4);
}

TEST(FanucSliceCounts, MovnCountsItsBytes) {
  // nvalue 8: the MOVN rung counts 6 (RD + 5 moves), so the first slice takes one more rung
  // (8) and the last two rungs make the second slice. Were MOVN 1, the four rungs (8) would
  // be one slice.
  std::optional<VerifiedProgram> p =
      level2("RD R9091.1\nMOVN 5 D0 R0\nRD X0.0\nWRT R1.0\nRD X0.1\nWRT R1.1\n"
             "RD X0.2\nWRT R1.2\n",
             8);
  ASSERT_EQ(p->slices.size(), 2u);
  EXPECT_EQ(p->slices[0].end - p->slices[0].begin, 8);
}

} // namespace
} // namespace lj::test

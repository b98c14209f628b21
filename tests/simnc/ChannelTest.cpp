// Channel model of the simulated NC: power-up values, M/T/S handshakes (hnc8-cnc-interface.md
// 1.6), reset handshake, mode switching, cycle start / feed hold, part count, alarm diffs and
// the words left to the host. Timing rules: docs/simulated-nc.md "Tick protocol".
#include "SimNcRig.h"

#include <gtest/gtest.h>

namespace lj::hosts::testing {
namespace {

TEST(Channel, PowerUpIdleValues) {
  Rig r;
  // 1.3: F2616 = -1 when no T runs; the free M slots are -1 as well (docs "Power-up"). G is the
  // PLC's area and stays zero at power-up (DIALECT.md 1).
  for (int c = 0; c < 4; ++c) {
    for (int k = 0; k < 8; ++k) {
      EXPECT_EQ(r.F(FC(c, 48 + k)), -1);
      EXPECT_EQ(r.G(FC(c, 48 + k)), 0);
    }
    EXPECT_EQ(r.F(FC(c, 56)), -1);
    EXPECT_EQ(r.G(FC(c, 56)), 0);
  }
  EXPECT_EQ(r.s->host, r.nc.host());
  EXPECT_EQ(r.nc.host()->ctx, &r.nc);
  // Default machine: channel 0 has axes 0, 1, 2 (FC[21..23]) and spindle axis 5 (FC[30]).
  EXPECT_EQ(r.F(FC(0, 21)), 0);
  EXPECT_EQ(r.F(FC(0, 23)), 2);
  EXPECT_EQ(r.F(FC(0, 24)), -1);
  EXPECT_EQ(r.F(FC(0, 30)), 5);
  EXPECT_EQ(r.F(FA(1, 4)), 0); // axis 1 belongs to channel 0
  // A stopped spindle reports zero speed (FA[2].15).
  EXPECT_TRUE(r.Fbit(FA(5, 2), 15));
  EXPECT_FALSE(r.Fbit(FA(5, 2), 14));
}

TEST(Channel, MCodeHandshake) {
  Rig r;
  r.nc.apply(mcode(0, 3));
  r.before();
  EXPECT_EQ(r.F(2608), 3); // 1.6: the NC puts the M code in a slot
  r.after();               // the PLC has not answered yet
  r.before();
  EXPECT_EQ(r.F(2608), 3);
  r.G(2608) = 3; // MACK: response = the M number (1.4 G2608)
  r.after();
  r.before();
  // Done: the slot is free again and the NC returns the response to -1.
  EXPECT_EQ(r.F(2608), -1);
  EXPECT_EQ(r.G(2608), -1);
  r.after();
  EXPECT_EQ(r.eventTick("mcode ch0 m3 done"), 1);
}

TEST(Channel, PostingACodeResetsItsResponseSoAStaleZeroIsNoAck) {
  // G is zero at power-up (DIALECT.md 1); an M0 / T0 must not count as acknowledged by that
  // stale 0: posting the code sets the response to -1 "no code handled" (1.4 G2608/G2616).
  Rig r;
  r.nc.apply(mcode(0, 0));
  r.nc.apply(tcode(0, 0));
  r.before();
  EXPECT_EQ(r.F(2608), 0);
  EXPECT_EQ(r.G(2608), -1);
  EXPECT_EQ(r.F(2616), 0);
  EXPECT_EQ(r.G(2616), -1);
  r.after(); // the PLC did not answer
  r.before();
  EXPECT_EQ(r.F(2608), 0); // still pending
  EXPECT_EQ(r.F(2616), 0);
  r.G(2608) = 0; // MACK 0 0, TACK 0
  r.G(2616) = 0;
  r.after();
  r.before();
  EXPECT_EQ(r.F(2608), -1);
  EXPECT_EQ(r.F(2616), -1);
  r.after();
}

TEST(Channel, MCodeExecutingResponseIsNotDone) {
  Rig r;
  r.nc.apply(mcode(0, 8));
  r.before();
  r.G(2608) = -2; // 1.4: -2 = executing
  r.after();
  r.before();
  EXPECT_EQ(r.F(2608), 8);
  EXPECT_EQ(r.G(2608), -2);
  r.after();
}

TEST(Channel, EightSlotsThenQueue) {
  Rig r;
  for (int m = 10; m < 19; ++m) r.nc.apply(mcode(0, m)); // 9 codes, 8 slots
  r.before();
  for (int k = 0; k < 8; ++k) EXPECT_EQ(r.F(2608 + k), 10 + k);
  r.G(2610) = 12; // acknowledge the third slot
  r.after();
  r.before();
  EXPECT_EQ(r.F(2610), -1); // a freed slot shows -1 for one tick
  r.after();
  r.before();
  EXPECT_EQ(r.F(2610), 18); // then the queued code takes it
  EXPECT_EQ(r.G(2610), -1);
  r.after();
}

TEST(Channel, TCodeHandshakeAndQueue) {
  Rig r;
  r.nc.apply(tcode(1, 12));
  r.nc.apply(tcode(1, 7)); // waits for T12
  r.before();
  EXPECT_EQ(r.F(FC(1, 56)), 12); // 1.6: FC[56] = T while pending
  r.G(FC(1, 56)) = 12;           // TACK: GC[56] = FC[56]
  r.after();
  r.before();
  EXPECT_EQ(r.F(FC(1, 56)), -1);
  EXPECT_EQ(r.G(FC(1, 56)), -1);
  r.after();
  r.before();
  EXPECT_EQ(r.F(FC(1, 56)), 7);
  r.after();
  EXPECT_TRUE(r.hasEvent("tcode ch1 t12 done"));
  EXPECT_FALSE(r.hasEvent("tcode ch1 t7 done"));
}

TEST(Channel, SCodeFlagValueAndAck) {
  Rig r;
  formats::NcCommand c;
  c.kind = formats::NcCommandKind::SCode;
  c.ch = 0;
  c.code = 1;         // spindle 2 of the manual's 1..4 numbering
  c.ivalue = 1500000; // 1500 rpm in 0.001 rpm (1.3 F2572/73)
  r.nc.apply(c);
  r.before();
  EXPECT_TRUE(r.Fbit(2562, 13)); // FC[2].13: S command for the second spindle
  EXPECT_EQ(static_cast<uint16_t>(r.F(2572)) | (static_cast<uint16_t>(r.F(2573)) << 16),
            1500000u);   // low word first (hnc8-cnc-interface.md 0)
  r.setG(2562, 1, true); // GC[2].1: ack
  r.after();
  r.before();
  EXPECT_FALSE(r.Fbit(2562, 13));
  EXPECT_EQ(r.F(2572) & 0xFFFF, 1500000 & 0xFFFF); // the value stays
  r.after();
}

TEST(Channel, ResetHandshake) {
  Rig r;
  r.nc.apply(simple(formats::NcCommandKind::Reset, 0)); // panel Reset key
  r.before();
  EXPECT_TRUE(r.Fbit(2560, 12)); // 1.6: FC[0].12 until the PLC's ack
  r.after();
  r.before();
  EXPECT_TRUE(r.Fbit(2560, 12));
  r.setG(2560, 9, true); // RSTCLR: GC[0].9
  r.after();
  r.before();
  EXPECT_FALSE(r.Fbit(2560, 12));
  r.setG(2560, 9, false);
  r.setG(2560, 13, true); // RESET block: GC[0].13 requests a reset too
  r.after();
  r.before();
  EXPECT_TRUE(r.Fbit(2560, 12));
  r.after();
}

TEST(Channel, ResetClearsPendingCodes) {
  Rig r;
  r.nc.apply(mcode(0, 3));
  r.nc.apply(tcode(0, 4));
  r.idle();
  r.nc.apply(simple(formats::NcCommandKind::Reset, 0));
  r.before();
  EXPECT_EQ(r.F(2608), -1);
  EXPECT_EQ(r.F(2616), -1);
  r.after();
}

TEST(Channel, ModeFromOneHotAndCode) {
  Rig r;
  r.before();
  r.setG(2620, 2, true); // GC[60].2 manual (one-hot weight 4, MDST)
  r.after();
  r.before();
  EXPECT_EQ(r.F(2560) & 0xF, 2); // FC[0].0-3 = 2 manual
  r.G(2620) = 0;
  r.G(2560) = 1; // GC[0].0-3 = 1 auto
  r.after();
  r.before();
  EXPECT_EQ(r.F(2560) & 0xF, 1);
  r.after();
}

TEST(Channel, ModeSwitchRefusedDuringZSearch) {
  Rig r;
  r.before();
  r.setG(FA(0, 0), 4, true); // homing start of axis 0 (channel 0)
  r.after();
  r.before();
  r.setG(FA(0, 0), 5, true); // on the dog: phase 2 next
  r.after();
  r.before();
  EXPECT_TRUE(r.Fbit(2560, 15)); // 1.3 FC[0].15: Z search, mode switch forbidden
  r.G(2560) = 2;                 // request manual
  r.after();
  r.before();
  EXPECT_EQ(r.F(2560) & 0xF, 0); // refused
  r.after();
}

TEST(Channel, CycleStartOnlyInAutoAndFeedHold) {
  Rig r;
  r.before();
  r.setG(2560, 5, true); // cycle start in reset mode 0: refused (1.7: auto/single only)
  r.after();
  r.before();
  EXPECT_FALSE(r.Fbit(2560, 5));
  r.G(2560) = 1; // auto, cycle start bit low: the edge comes next tick
  r.after();
  r.before();
  r.setG(2560, 5, true);
  r.after();
  r.before();
  EXPECT_TRUE(r.Fbit(2560, 5)); // running
  r.setG(2560, 5, false);
  r.setG(2560, 4, true); // HOLD
  r.after();
  r.before();
  EXPECT_TRUE(r.Fbit(2560, 4));
  EXPECT_FALSE(r.Fbit(2560, 5));
  r.after();
}

TEST(Channel, ProgramEndAndPartCount) {
  Rig r;
  r.nc.apply(simple(formats::NcCommandKind::End, 0));
  r.before();
  EXPECT_TRUE(r.Fbit(2561, 2)); // FC[1].2 program finished
  r.G(2579) = 6;                // PARTCNT (hnc8-functions-2.md 2.19)
  r.after();
  EXPECT_EQ(r.nc.partCount(0), 6);
  EXPECT_TRUE(r.hasEvent("partcount ch0 6"));
}

TEST(Channel, AlarmEventPromptDiffs) {
  Rig r;
  r.before();
  r.setG(3010, 2, true);  // alarm 3 = G3010 bit 2 (6.3 ALARM)
  r.setG(3047, 10, true); // event 122 = bit 122 of G3040.. (6.3 EVENT)
  r.setG(3056, 0, true);  // prompt 501
  r.after();
  r.before();
  r.setG(3010, 2, false);
  r.after();
  EXPECT_EQ(r.eventTick("alarm 3 on"), 0);
  EXPECT_EQ(r.eventTick("event 122 on"), 0);
  EXPECT_EQ(r.eventTick("prompt 501 on"), 0);
  EXPECT_EQ(r.eventTick("alarm 3 off"), 1);
}

TEST(Channel, WordsLeftToTheHostAreNeverWritten) {
  SimNc nc;
  auto s = std::make_unique<lj_state>();
  lj_state_reset(s.get());
  nc.leaveWord(true, 2560);
  nc.leaveWord(true, 2608);
  nc.powerUp(*s);
  s->img.F[2560] = 2; // the stimulus plays the NC
  nc.apply(mcode(0, 3));
  nc.beforeTick(*s, 0);
  EXPECT_EQ(s->img.F[2560], 2);
  EXPECT_EQ(s->img.F[2608], 0); // left alone since power-up
  EXPECT_EQ(s->img.F[2609], -1);
}

} // namespace
} // namespace lj::hosts::testing

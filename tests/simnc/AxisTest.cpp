// Axis and spindle model of the simulated NC: enable delays, homing state machine, jog, PMC
// moves, lock/limits, control mode, spindle ramp and orientation (hnc8-cnc-interface.md 1.1,
// 1.2, 3.2; the delays and rates are SimNcConfig values, docs/simulated-nc.md "Axes").
#include "SimNcRig.h"

#include <gtest/gtest.h>

namespace lj::hosts::testing {
namespace {

TEST(Axis, EnableAndServoAfterTheDelay) {
  SimNcConfig cfg;
  cfg.enableDelay = 3;
  Rig r(cfg);
  r.before();
  r.setG(FA(1, 0), 7, true); // AXEN: GA[0].7 at tick 0
  r.setG(FA(1, 3), 0, true); // SVSW: GA[3].0
  r.after();
  for (int t = 1; t <= 3; ++t) {
    r.before();
    // Shown from tick 0 + 3 on.
    EXPECT_EQ(r.Fbit(FA(1, 2), 8), t >= 3) << "FA[2].8 at tick " << t;
    EXPECT_EQ(r.Fbit(FA(1, 3), 0), t >= 3) << "FA[3].0 at tick " << t;
    r.after();
  }
  r.before();
  r.setG(FA(1, 0), 7, false);
  r.after();
  r.before();
  EXPECT_FALSE(r.Fbit(FA(1, 2), 8));
  r.after();
}

TEST(Axis, HomingStateMachine) {
  SimNcConfig cfg;
  cfg.homeZDelay = 2;
  Rig r(cfg);
  r.before();
  r.setG(FA(2, 0), 4, true); // HOMRUN: GA[0].4
  r.after();
  r.before();
  EXPECT_TRUE(r.Fbit(FA(2, 0), 1));  // phase 1: looking for the dog
  EXPECT_TRUE(r.Fbit(FA(2, 0), 0));  // moving
  EXPECT_FALSE(r.Fbit(FA(2, 0), 4)); // not homed
  r.setG(FA(2, 0), 5, true);         // HOMESW: GA[0].5 on the dog
  r.after();
  for (int i = 0; i < 2; ++i) { // phase 2 for homeZDelay ticks
    r.before();
    EXPECT_TRUE(r.Fbit(FA(2, 0), 2)) << i; // AXISHOM2 reads FA[0].2 (6.2 #57)
    EXPECT_TRUE(r.Fbit(2560, 15)) << i;    // and the channel reports the Z search
    r.after();
  }
  r.before();
  EXPECT_FALSE(r.Fbit(FA(2, 0), 2));
  EXPECT_TRUE(r.Fbit(FA(2, 0), 4)); // done (HOMLED)
  EXPECT_TRUE(r.Fbit(FA(2, 0), 8)); // at reference point 1
  EXPECT_FALSE(r.Fbit(FA(2, 0), 0));
  EXPECT_FALSE(r.Fbit(2560, 15));
  r.after();
  EXPECT_EQ(r.nc.axisPosition(2), 0);
}

TEST(Axis, ZPulseEndsPhaseTwoEarly) {
  SimNcConfig cfg;
  cfg.homeZDelay = 50;
  Rig r(cfg);
  r.before();
  r.setG(FA(0, 0), 4, true);
  r.setG(FA(0, 0), 5, true); // start on the dog: phase 2 after this tick
  r.after();
  r.idle();
  formats::NcCommand z = simple(formats::NcCommandKind::ZPulse, 0);
  r.nc.apply(z);
  r.idle();
  r.before();
  EXPECT_TRUE(r.Fbit(FA(0, 0), 4));
  r.after();
}

TEST(Axis, JogMovesAndLockStops) {
  SimNcConfig cfg;
  cfg.jogStep = 7;
  Rig r(cfg);
  r.before();
  r.G(FA(0, 4)) = 1; // JOGSW +: GA[4] > 0 at the parameter speed (GA[6/7] = 0)
  r.after();
  EXPECT_EQ(r.nc.axisPosition(0), 7);
  r.before();
  EXPECT_TRUE(r.Fbit(FA(0, 0), 0)); // AXMOVING reads FA[0].0 (6.2 #58)
  EXPECT_EQ(r.F(FA(0, 32)), 7);     // machine actual position, low word
  r.G(FA(0, 4)) = -1;
  r.G(FA(0, 6)) = 3; // JOGVEL: 3 units per tick
  r.after();
  EXPECT_EQ(r.nc.axisPosition(0), 4);
  r.before();
  r.setG(FA(0, 0), 6, true); // AXISLOCK
  r.after();
  EXPECT_EQ(r.nc.axisPosition(0), 4);
  r.before();
  EXPECT_TRUE(r.Fbit(FA(0, 0), 14)); // locked
  EXPECT_FALSE(r.Fbit(FA(0, 0), 0));
  r.after();
}

TEST(Axis, LimitSwitchBlocksItsDirection) {
  Rig r;
  r.before();
  r.G(FA(1, 4)) = 1;
  r.setG(FA(1, 0), 0, true); // AXISPLMT: positive limit
  r.after();
  EXPECT_EQ(r.nc.axisPosition(1), 0);
  r.before();
  EXPECT_TRUE(r.Fbit(FA(1, 36), 2)); // FA[36].2 on the positive limit dog
  r.G(FA(1, 4)) = -1;
  r.after();
  EXPECT_EQ(r.nc.axisPosition(1), -SimNcConfig{}.jogStep);
}

TEST(Axis, PmcRelativeAndAbsoluteMoves) {
  SimNcConfig cfg;
  cfg.pmcStep = 400;
  Rig r(cfg);
  r.before();
  r.G(FA(2, 52)) = 1000; // AXISMOVE distance (GA[52..55])
  r.setG(FA(2, 1), 1, true);
  r.after();
  r.before();
  EXPECT_TRUE(r.Fbit(FA(2, 1), 0)); // PMC move active
  r.after();
  r.idle();
  EXPECT_EQ(r.nc.axisPosition(2), 1000); // 400 + 400 + 200
  r.before();
  EXPECT_FALSE(r.Fbit(FA(2, 1), 0));
  r.G(FA(2, 48)) = 100; // AXISMVTO target (GA[48..51])
  r.setG(FA(2, 1), 0, true);
  r.after(); // held GA[1].1 does not restart the relative move (rising edge only)
  r.idle(2);
  EXPECT_EQ(r.nc.axisPosition(2), 100);
}

TEST(Axis, ControlModeMirrored) {
  Rig r;
  r.before();
  r.setG(FA(3, 2), 10, true); // AXISMODE 3 1: speed mode
  r.after();
  r.before();
  EXPECT_TRUE(r.Fbit(FA(3, 2), 10));
  EXPECT_FALSE(r.Fbit(FA(3, 2), 9));
  r.after();
}

TEST(Axis, SpindleRampReachedAndZeroSpeed) {
  SimNcConfig cfg;
  cfg.spindleRamp = 400;
  Rig r(cfg);
  r.before();
  r.G(FC(0, 10)) = 1000; // spindle 0 command (GC[10/11]); axis 5 is spindle 0
  r.after();
  r.before();
  EXPECT_FALSE(r.Fbit(FA(5, 2), 15)); // 400: turning
  EXPECT_FALSE(r.Fbit(FA(5, 2), 14));
  r.after();
  r.idle();
  r.before();
  EXPECT_TRUE(r.Fbit(FA(5, 2), 14)); // 1000 reached (SPDLRCH)
  EXPECT_EQ(r.nc.spindleSpeed(5), 1000);
  r.G(FC(0, 10)) = 0;
  r.after();
  r.idle(2);
  r.before();
  EXPECT_TRUE(r.Fbit(FA(5, 2), 15)); // zero speed (SPDLZERO)
  r.after();
}

TEST(Axis, OrientationAfterTheDelay) {
  SimNcConfig cfg;
  cfg.orientDelay = 2;
  Rig r(cfg);
  r.before();
  r.setG(FA(5, 2), 12, true); // SPDLORI
  r.after();
  r.before();
  EXPECT_FALSE(r.Fbit(FA(5, 3), 8));
  r.after();
  r.before();
  EXPECT_TRUE(r.Fbit(FA(5, 3), 8)); // SPDLOROK reads FA[3].8
  r.after();
}

} // namespace
} // namespace lj::hosts::testing

// The highest numbers of the 0i-D PMC resources on every engine: TMRB/TMRBF 500 and 499, DIFU /
// DIFD 1000 and 999, subroutine P5000 (reference 1 specification table, 4.2 [L869], 6.3
// [L1715, L1727-L1737], 6.8 [L3149-L3159], 7 "Resource counts"). Their state lives past abi.h's
// own timer / PLS / PLF arrays (TargetProfile::BlockState), so each test also runs the lowest
// number beside the highest to show the two do not share state.
#include "tests/exec/FanucExec.h"

namespace lj::test {
namespace {

class FanucLimits : public FanucExecTest {};
LJ_EXEC_SUITE(FanucLimits);

// 6.3 TMRB [L1681, L1757-L1759]: W1 = 1 once ACT has been 1 for the set time, ACT = 0 -> W1 = 0
// at once. TMRBF [L1959-L1963]: ACT = 1 -> W1 = 1 at once, W1 = 0 once ACT has been 0 for the
// set time. Timer numbers 1..500 (TMRB and TMRBF share them).
TEST_P(FanucLimits, TimersFiveHundredAndFourNinetyNine) {
  auto m = pmc("RD X0.0\nTMRB 500 100\nWRT R0.0\nRD X0.1\nTMRBF 499 50\nWRT R0.1\n"
               "RD X0.2\nTMRB 1 20\nWRT R0.2\nEND1\nEND2\nEND\n");
  ASSERT_TRUE(m);
  set(*m, "X0.0", 1);
  set(*m, "X0.1", 1);
  m->tick(); // now_ms = 0
  EXPECT_EQ(get(*m, "R0.0"), 0);
  EXPECT_EQ(get(*m, "R0.1"), 1);
  EXPECT_EQ(get(*m, "R0.2"), 0);
  set(*m, "X0.1", 0);              // TMRBF 499 starts its 50 ms at now_ms = 1
  for (int t = 1; t <= 150; ++t) { // now_ms = t
    m->tick();
    ASSERT_EQ(get(*m, "R0.0"), t >= 100 ? 1 : 0) << "t=" << t;
    ASSERT_EQ(get(*m, "R0.1"), t - 1 < 50 ? 1 : 0) << "t=" << t;
    ASSERT_EQ(get(*m, "R0.2"), 0) << "t=" << t; // TMRB 1's ACT stayed 0
  }
  set(*m, "X0.0", 0);
  m->tick();
  EXPECT_EQ(get(*m, "R0.0"), 0);
}

// 6.8 DIFU / DIFD [L3127-L3145, L3165-L3203]: W1 = 1 for exactly one scan after a rising
// (falling) edge of ACT; edge numbers 1..1000 [L3149-L3159], DIFU and DIFD share them.
TEST_P(FanucLimits, EdgesThousandAndNineNinetyNine) {
  auto m = pmc("RD X0.0\nDIFU 1000\nWRT R0.0\nRD X0.0\nDIFD 999\nWRT R0.1\n"
               "RD X0.1\nDIFU 1\nWRT R0.2\nRD X0.1\nDIFD 2\nWRT R0.3\nEND1\nEND2\nEND\n");
  ASSERT_TRUE(m);
  const int x0[] = {0, 1, 1, 1, 0, 0, 1, 0}, x1[] = {0, 0, 0, 0, 1, 1, 0, 1};
  const int up0[] = {0, 1, 0, 0, 0, 0, 1, 0}, down0[] = {0, 0, 0, 0, 1, 0, 0, 1};
  const int up1[] = {0, 0, 0, 0, 1, 0, 0, 1}, down1[] = {0, 0, 0, 0, 0, 0, 1, 0};
  for (int t = 0; t < 8; ++t) {
    set(*m, "X0.0", x0[t]);
    set(*m, "X0.1", x1[t]);
    m->tick();
    EXPECT_EQ(get(*m, "R0.0"), up0[t]) << "t=" << t;
    EXPECT_EQ(get(*m, "R0.1"), down0[t]) << "t=" << t;
    EXPECT_EQ(get(*m, "R0.2"), up1[t]) << "t=" << t;
    EXPECT_EQ(get(*m, "R0.3"), down1[t]) << "t=" << t;
  }
}

// 4.2 [L869, L875]: up to 5000 subroutines; CALL is conditional on ACT, CALLU is not.
TEST_P(FanucLimits, SubroutineFiveThousand) {
  auto m = pmc("END1\nRD X0.0\nCALL P5000\nCALLU P1\nEND2\n"
               "SP P1\nRD X0.2\nWRT R0.1\nSPE\nSP P5000\nRD X0.1\nWRT R0.0\nSPE\nEND\n");
  ASSERT_TRUE(m);
  set(*m, "X0.1", 1);
  set(*m, "X0.2", 1);
  m->tick();
  EXPECT_EQ(get(*m, "R0.0"), 0); // ACT = 0: P5000 not run
  EXPECT_EQ(get(*m, "R0.1"), 1);
  set(*m, "X0.0", 1);
  m->tick();
  EXPECT_EQ(get(*m, "R0.0"), 1);
  set(*m, "X0.1", 0);
  m->tick();
  EXPECT_EQ(get(*m, "R0.0"), 0);
}

} // namespace
} // namespace lj::test

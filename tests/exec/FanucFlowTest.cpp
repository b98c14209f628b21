// FANUC select-call CS / CM / CE (fanuc-e) on every engine. The reference (../shared/reference/
// fanuc-pmc.md 4.2, [EXT]) says only "CS takes an index value and calls the CM entry it
// selects; CE closes the list"; the reading (2-byte binary index, 0 selects the first CM, out of
// range or ACT = 0 calls nothing) is docs/fanuc-pmc.md [EXT] "select-call". Expected values are
// derived by hand from that reading.
#include "tests/exec/FanucExec.h"

namespace lj::test {
namespace {

class FanucFlow : public FanucExecTest {};
LJ_EXEC_SUITE(FanucFlow);

// Each subroutine Pn sets R0.(n-1) (SET, so one tick shows every call made); the tick before
// clears R0 so each case starts from 0.
constexpr const char *kSelect =
    "END1\nRD X0.0\nCS R100\nCM P1\nCM P2\nCM P3\nCE\nRD R9091.1\nWRT R1.0\nEND2\n"
    "SP P1\nRD R9091.1\nSET R0.0\nSPE\nSP P2\nRD R9091.1\nSET R0.1\nSPE\n"
    "SP P3\nRD R9091.1\nSET R0.2\nSPE\nEND\n";

TEST_P(FanucFlow, SelectCallCallsTheIndexedEntry) {
  auto m = pmc(kSelect);
  ASSERT_TRUE(m);
  set(*m, "X0.0", 1);
  // index -> R0 bit pattern: 0 -> P1 (bit 0), 1 -> P2 (bit 1), 2 -> P3 (bit 2), 3 and -1 none.
  const int64_t expect[][2] = {{0, 0x1}, {1, 0x2}, {2, 0x4}, {3, 0}, {-1, 0}, {256, 0}};
  for (const auto &e : expect) {
    set(*m, "R0", 0);
    set(*m, "R100:2", e[0]);
    m->tick();
    EXPECT_EQ(get(*m, "R0") & 0xFF, e[1]) << "index " << e[0];
    EXPECT_EQ(get(*m, "R1.0"), 1); // the rung after CE runs
  }
}

TEST_P(FanucFlow, SelectCallWithActZeroCallsNothing) {
  auto m = pmc(kSelect);
  ASSERT_TRUE(m);
  for (int idx = 0; idx < 3; ++idx) {
    set(*m, "R0", 0);
    set(*m, "R100:2", idx);
    m->tick();
    EXPECT_EQ(get(*m, "R0") & 0xFF, 0) << "index " << idx;
  }
}

// The index is two bytes: R101 = 1 with R100 = 0 is index 256, not 0 (3.1 little-endian).
TEST_P(FanucFlow, SelectCallIndexIsTwoBytes) {
  auto m = pmc(kSelect);
  ASSERT_TRUE(m);
  set(*m, "X0.0", 1);
  set(*m, "R100", 0);
  set(*m, "R101", 1);
  m->tick();
  EXPECT_EQ(get(*m, "R0") & 0xFF, 0);
}

// A select-call inside a subroutine, and the same subroutine listed twice: index 1 calls P2
// once (its counter-like SET pattern is one bit), index 2 calls P2 again through the third CM.
TEST_P(FanucFlow, SelectCallFromASubroutine) {
  auto m =
      pmc("END1\nRD X0.0\nCALL P9\nEND2\nSP P9\nRD R9091.1\nCS D10\nCM P1\nCM P2\nCM P2\n"
          "CE\nSPE\nSP P1\nRD R9091.1\nSET R0.0\nSPE\nSP P2\nRD R9091.1\nSET R0.1\nSPE\nEND\n");
  ASSERT_TRUE(m);
  set(*m, "X0.0", 1);
  set(*m, "D10:2", 2);
  m->tick();
  EXPECT_EQ(get(*m, "R0") & 0xFF, 0x2);
  set(*m, "R0", 0);
  set(*m, "D10:2", 0);
  m->tick();
  EXPECT_EQ(get(*m, "R0") & 0xFF, 0x1);
  set(*m, "R0", 0);
  set(*m, "X0.0", 0); // P9 not called: nothing
  m->tick();
  EXPECT_EQ(get(*m, "R0") & 0xFF, 0);
}

} // namespace
} // namespace lj::test

// Edge memory per object (modicon-neza.md 2.1 inference, 12.1; ir/Profile.h
// EdgePolicy::PerObject): one previous-scan image per %I / %M0-31 object, sampled at the end of
// every scan, shared by every edge instruction on that object. Every registered engine.
#include "tests/iec/IecTest.h"

namespace lj::test {
namespace {

class IecEdge : public IecExec {};
LJ_IEC_SUITE(IecEdge);

// "two LDR %M5 in the same scan would both see the edge" (2.1).
TEST_P(IecEdge, TwoLdrOfOneObjectShareTheEdge) {
  auto m = load("LD %I0.0\nST %M5\nLDR %M5\nST %Q0.0\nLDR %M5\nST %Q0.1\n");
  ASSERT_TRUE(m);
  set(*m, "%I0.0", 1);
  m->tick();
  EXPECT_EQ(get(*m, "%Q0.0"), 1);
  EXPECT_EQ(get(*m, "%Q0.1"), 1);
  m->tick();
  EXPECT_EQ(get(*m, "%Q0.0"), 0);
  EXPECT_EQ(get(*m, "%Q0.1"), 0);
}

// The edge compares with the object's value at the end of the previous scan, not with what
// the instruction saw last: %M5 is written between two LDR %M5. Scan 1: the first LDR sees 0
// (no edge), the second sees the new 1 (edge). Scan 2: the image is 1, so neither sees an edge
// (an edge memory per instruction would give the first LDR its edge now).
TEST_P(IecEdge, ImageIsTheEndOfThePreviousScan) {
  auto m = load("LDR %M5\nST %Q0.0\nLD %I0.0\nST %M5\nLDR %M5\nST %Q0.1\n");
  ASSERT_TRUE(m);
  set(*m, "%I0.0", 1);
  m->tick();
  EXPECT_EQ(get(*m, "%Q0.0"), 0);
  EXPECT_EQ(get(*m, "%Q0.1"), 1);
  m->tick();
  EXPECT_EQ(get(*m, "%Q0.0"), 0);
  EXPECT_EQ(get(*m, "%Q0.1"), 0);
}

// A skipped edge instruction does not lose the edge's memory: the image is sampled every scan,
// so after a jump over LDR the edge that happened during the skipped scan is gone.
TEST_P(IecEdge, ImageIsSampledEvenWhenTheInstructionIsSkipped) {
  auto m = load("LD %I0.1\nJMPC %L1\nLDR %I0.0\nST %Q0.0\n%L1 :\nLD 1\nST %Q0.7\n");
  ASSERT_TRUE(m);
  set(*m, "%I0.1", 1);
  set(*m, "%I0.0", 1);
  m->tick(); // LDR skipped; the image of I0.0 becomes 1
  set(*m, "%I0.1", 0);
  m->tick();
  EXPECT_EQ(get(*m, "%Q0.0"), 0) << "the rise happened in the skipped scan";
  EXPECT_EQ(get(*m, "%Q0.7"), 1);
}

// Falling edges and edge forms inside parentheses share the image too.
TEST_P(IecEdge, FallingAndParenthesisForms) {
  auto m = load("LDF %I0.0\nST %Q0.0\nLD 0\nOR(F %I0.0\n)\nST %Q0.1\nLD 1\nXORF %I0.0\nST %Q0.2\n");
  ASSERT_TRUE(m);
  set(*m, "%I0.0", 1);
  m->tick();
  set(*m, "%I0.0", 0);
  m->tick();
  EXPECT_EQ(get(*m, "%Q0.0"), 1);
  EXPECT_EQ(get(*m, "%Q0.1"), 1);
  EXPECT_EQ(get(*m, "%Q0.2"), 0) << "1 xor falling edge";
  m->tick();
  EXPECT_EQ(get(*m, "%Q0.0"), 0);
  EXPECT_EQ(get(*m, "%Q0.1"), 0);
  EXPECT_EQ(get(*m, "%Q0.2"), 1);
}

} // namespace
} // namespace lj::test

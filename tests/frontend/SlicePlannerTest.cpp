// PLC2 slice planning per dialect-notes "PLC2 slicing": rung boundaries with ST liveness, no
// boundary inside loop bodies or between a JMP and its label, nvalue 0 and empty PLC2.
#include "FrontEndTestUtil.h"
#include "frontends/fanuc/FrontEnd.h"
#include "pipeline/Compile.h"

#include <gtest/gtest.h>

#include <vector>

namespace lj {
namespace {

using test::compile;

/// Compiles `plc2` as the PLC2 part (after one PLC1 statement pair and 1END, so PLC2 starts at
/// statement index 3) and returns its slices relative to the start of PLC2.
struct Plan {
  std::vector<std::pair<int32_t, int32_t>> slices;
  std::vector<int32_t> depths;
};

Plan plan(const std::string &plc2, int32_t nvalue) {
  VerifyOptions o;
  o.plc2Nvalue = nvalue;
  auto c = compile("LDT\nOUT Y9.0\n1END\n" + plc2 + "2END\n", o);
  Plan p;
  EXPECT_TRUE(c.prog.has_value()) << c.diags;
  if (!c.prog) return p;
  EXPECT_EQ(c.prog->plc2.begin, 3);
  EXPECT_EQ(c.prog->slices.size(), c.prog->sliceDepth.size());
  for (const StmtRange &r : c.prog->slices) p.slices.emplace_back(r.begin - 3, r.end - 3);
  p.depths = c.prog->sliceDepth;
  return p;
}

using Slices = std::vector<std::pair<int32_t, int32_t>>;

const std::string kFourRungs = "LD X0.0\nOUT Y0.0\nLD X0.1\nOUT Y0.1\nLD X0.2\nOUT Y0.2\n"
                               "LD X0.3\nOUT Y0.3\n";

// Each LD/OUT rung leaves a dead entry: boundaries before every LD; the next slice records the
// depth of the dead entries it starts with.
TEST(SlicePlanner, OneRungPerSlice) {
  Plan p = plan(kFourRungs, 2);
  EXPECT_EQ(p.slices, (Slices{{0, 2}, {2, 4}, {4, 6}, {6, 8}}));
  EXPECT_EQ(p.depths, (std::vector<int32_t>{0, 1, 2, 3}));
}

// A slice ends at the first boundary after at least nvalue statements.
TEST(SlicePlanner, AtLeastNvalueStatements) {
  EXPECT_EQ(plan(kFourRungs, 3).slices, (Slices{{0, 4}, {4, 8}}));
  EXPECT_EQ(plan(kFourRungs, 1).slices, (Slices{{0, 2}, {2, 4}, {4, 6}, {6, 8}}));
  EXPECT_EQ(plan(kFourRungs, 8).slices, (Slices{{0, 8}}));
  EXPECT_EQ(plan(kFourRungs, 200).slices, (Slices{{0, 8}}));
}

// nvalue 0: no slicing, one slice.
TEST(SlicePlanner, NvalueZeroIsOneSlice) {
  Plan p = plan(kFourRungs, 0);
  EXPECT_EQ(p.slices, (Slices{{0, 8}}));
  EXPECT_EQ(p.depths, (std::vector<int32_t>{0}));
}

// An empty PLC2 is one empty slice.
TEST(SlicePlanner, EmptyPlc2) {
  Plan p = plan("", 1);
  EXPECT_EQ(p.slices, (Slices{{0, 0}}));
  EXPECT_EQ(p.depths, (std::vector<int32_t>{0}));
}

// hnc8-core.md 4.10 MPS-1: the LD X2.3 after OUT Y0.3 is still live (ANB consumes the older
// value), and MS is non-empty between MPS and MPP, so the whole listing is one rung.
TEST(SlicePlanner, Mps1IsOneRung) {
  std::string mps1 = "LD X1.0\nMPS\nLD X1.1\nOR X1.2\nANB\nOUT Y1.0\nMRD\nLD X1.3\nAND X1.4\n"
                     "LD X1.5\nAND X1.6\nORB\nANB\nOUT Y0.2\nMPP\nAND X1.7\nOUT Y0.3\nLD X2.3\n"
                     "OR X2.4\nANB\nOUT Y0.4\n";
  Plan p = plan(mps1 + "LD X3.0\nOUT Y3.0\n", 1);
  EXPECT_EQ(p.slices, (Slices{{0, 21}, {21, 23}}));
  EXPECT_EQ(p.depths, (std::vector<int32_t>{0, 1}));
}

// A stale entry consumed later by a 4-input block is live: no boundary before the block's
// other inputs.
TEST(SlicePlanner, EntryReadByMultiInputBlockIsLive) {
  Plan p = plan("LD X0.0\nOUT Y0.0\nLD X0.1\nLD X0.2\nLD X0.3\nCTUD 0 5\nOUT Y0.1\n", 1);
  EXPECT_EQ(p.slices, (Slices{{0, 7}}));
}

// No boundary inside a loop body; the first one is after NEXT (stacks empty).
TEST(SlicePlanner, NoBoundaryInLoopBody) {
  Plan p = plan("LOOP 3\nLD X0.0\nOUT Y0.0\nLD X0.1\nOUT Y0.1\nNEXT\nLD X0.2\nOUT Y0.2\n", 1);
  EXPECT_EQ(p.slices, (Slices{{0, 6}, {6, 8}}));
}

// No boundary between a forward JMP and its label (the label itself included).
TEST(SlicePlanner, NoBoundaryInsideForwardJump) {
  Plan p = plan("LD X0.0\nJMP L1\nLD X0.1\nOUT Y0.1\nLBL L1\nLD X0.2\nOUT Y0.2\n", 1);
  EXPECT_EQ(p.slices, (Slices{{0, 5}, {5, 7}}));
}

// Backward jump: boundaries after the label up to the JMP are forbidden; before the LBL and
// after the JMP they are allowed.
TEST(SlicePlanner, NoBoundaryInsideBackwardJump) {
  Plan p = plan("LD X0.5\nOUT Y0.5\nLBL L1\nLD X0.0\nOUT Y0.0\nLD X0.1\nJMP L1\nLD X0.2\n"
                "OUT Y0.2\n",
                1);
  EXPECT_EQ(p.slices, (Slices{{0, 2}, {2, 7}, {7, 9}}));
  EXPECT_EQ(p.depths, (std::vector<int32_t>{0, 1, 2}));
}

// An open MPS forbids a boundary even where no ST entry is live.
TEST(SlicePlanner, OpenMpsForbidsBoundary) {
  Plan p = plan("LD X0.0\nMPS\nOUT Y0.0\nLD X0.1\nOUT Y0.1\nMPP\nOUT Y0.2\nLD X0.3\nOUT Y0.3\n", 1);
  EXPECT_EQ(p.slices, (Slices{{0, 7}, {7, 9}}));
}

// Subroutine statements are not counted and never sliced.
TEST(SlicePlanner, SubroutinesNotCounted) {
  VerifyOptions o;
  o.plc2Nvalue = 2;
  auto c = compile("1END\nLDT\nCALL S1\nLDT\nOUT Y0.0\n2END\nSP S1\nLDT\nOUT Y1.0\nLDT\n"
                   "OUT Y1.1\nSPE\n",
                   o);
  ASSERT_TRUE(c.prog.has_value()) << c.diags;
  ASSERT_EQ(c.prog->slices.size(), 2u);
  EXPECT_EQ(c.prog->slices[0].begin, 1);
  EXPECT_EQ(c.prog->slices[0].end, 3);
  EXPECT_EQ(c.prog->slices[1].begin, 3);
  EXPECT_EQ(c.prog->slices[1].end, 5);
}

// FANUC JMPC (docs/fanuc-pmc.md "JMPC"): a CALL whose subroutine can leave for a level-2 label
// and that label are one span, like a JMP and its LBL: with nvalue 1 every other rung start is
// a boundary, none in (CALL, LBL]. Level 2 starts at statement 1 (after END1).
Slices pmcSlices(const std::string &level2, const std::string &sub) {
  VerifyOptions o;
  o.plc2Nvalue = 1;
  Diagnostics d("t.pmc");
  auto p = pipeline::compilePmc("END1\n" + level2 + "END2\nSP P1\n" + sub + "SPE\nEND\n", "t.pmc",
                                o, d, nullptr);
  EXPECT_TRUE(p.has_value()) << d.render();
  Slices out;
  if (!p) return out;
  EXPECT_EQ(p->plc2.begin, 1);
  for (const StmtRange &r : p->slices) out.emplace_back(r.begin - 1, r.end - 1);
  return out;
}

TEST(SlicePlanner, FanucCallAndItsJmpcLabelStayInOneSlice) {
  // 0 RD X0.0, 1 WRT Y0.0, 2 RD X0.1, 3 CALL P1, 4 RD X0.2, 5 WRT Y0.2, 6 LBL L1, 7 RD X0.3,
  // 8 WRT Y0.3.
  const std::string level2 = "RD X0.0\nWRT Y0.0\nRD X0.1\nCALL P1\nRD X0.2\nWRT Y0.2\nLBL L1\n"
                             "RD X0.3\nWRT Y0.3\n";
  EXPECT_EQ(pmcSlices(level2, "RD X1.0\nWRT Y1.0\n"),
            (Slices{{0, 2}, {2, 4}, {4, 6}, {6, 7}, {7, 9}}));
  EXPECT_EQ(pmcSlices(level2, "RD X1.0\nJMPC L1\n"), (Slices{{0, 2}, {2, 7}, {7, 9}}));
  // A label before the CALL: (LBL, CALL] has no boundary. 0 RD, 1 WRT, 2 LBL L1, 3 RD X0.1,
  // 4 CALL P1, 5 RD X0.2, 6 WRT Y0.2.
  EXPECT_EQ(pmcSlices("RD X0.0\nWRT Y0.0\nLBL L1\nRD X0.1\nCALL P1\nRD X0.2\nWRT Y0.2\n",
                      "RD X1.0\nJMPC L1\n"),
            (Slices{{0, 2}, {2, 5}, {5, 7}}));
}

} // namespace
} // namespace lj

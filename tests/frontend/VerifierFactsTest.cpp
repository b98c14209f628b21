// Verifier facts on valid programs: stack depths on the manual's examples, parts, subroutines,
// jump/loop/call targets, state slots and input flags (DIALECT.md 2-3, hnc8-core.md 4.9-4.10).
#include "FrontEndTestUtil.h"
#include "verify/Verify.h"

#include "ladderjit/abi.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

namespace lj {
namespace {

using test::compile;

VerifiedProgram ok(std::string_view text, VerifyOptions opts = {}) {
  auto c = compile(text, opts);
  EXPECT_TRUE(c.prog.has_value()) << c.diags;
  return c.prog ? *c.prog : VerifiedProgram{};
}

std::vector<int32_t> depths(const VerifiedProgram &p) {
  std::vector<int32_t> d;
  for (const StmtInfo &i : p.info) d.push_back(i.depth);
  return d;
}
std::vector<int32_t> msDepths(const VerifiedProgram &p) {
  std::vector<int32_t> d;
  for (const StmtInfo &i : p.info) d.push_back(i.msDepth);
  return d;
}

// hnc8-core.md 4.9 ORB example: the ST1/ST0 columns give the depth before each step.
TEST(VerifierFacts, OrbExampleDepths) {
  auto p = ok("LD X1.0\nAND X2.0\nLD X1.1\nAND X2.1\nORB\nLD X1.2\nAND X2.2\nORB\nOUT R10.1\n");
  EXPECT_EQ(depths(p), (std::vector<int32_t>{0, 1, 1, 2, 2, 1, 2, 2, 1}));
  EXPECT_EQ(p.maxDepth, 2);
}

// hnc8-core.md 4.9 ANB example (the only one using ST2).
TEST(VerifierFacts, AnbExampleDepths) {
  auto p = ok("LD X1.0\nOR X1.1\nLD X2.0\nAND X4.4\nLD X1.2\nAND X2.1\nORB\nOR X1.3\nANB\n"
              "OR X2.2\nOUT R10.0\n");
  EXPECT_EQ(depths(p), (std::vector<int32_t>{0, 1, 1, 2, 2, 3, 3, 2, 2, 1, 1}));
  EXPECT_EQ(p.maxDepth, 3);
  EXPECT_EQ(p.maxMsDepth, 0);
}

// hnc8-core.md 4.10 MPS-1: MPS does not pop, MRD/MPP replace ST0, the LD after OUT Y0.3 is
// combined with the older value by ANB (so the depth before it is 1, not 0).
TEST(VerifierFacts, Mps1Depths) {
  auto p = ok("LD X1.0\nMPS\nLD X1.1\nOR X1.2\nANB\nOUT Y1.0\nMRD\nLD X1.3\nAND X1.4\n"
              "LD X1.5\nAND X1.6\nORB\nANB\nOUT Y0.2\nMPP\nAND X1.7\nOUT Y0.3\nLD X2.3\n"
              "OR X2.4\nANB\nOUT Y0.4\n");
  EXPECT_EQ(depths(p),
            (std::vector<int32_t>{0, 1, 1, 2, 2, 1, 1, 1, 2, 2, 3, 3, 2, 1, 1, 1, 1, 1, 2, 2, 1}));
  EXPECT_EQ(msDepths(p),
            (std::vector<int32_t>{0, 0, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 0, 0, 0, 0, 0, 0}));
}

// hnc8-core.md 4.10 MPS-3: nesting four deep.
TEST(VerifierFacts, Mps3Depths) {
  auto p = ok("LD X1.0\nMPS\nAND X1.1\nMPS\nAND X1.2\nMPS\nAND X1.3\nMPS\nAND X1.4\nOUT Y1.0\n"
              "MPP\nOUT Y1.1\nMPP\nOUT Y0.2\nMPP\nOUT Y2.0\nMPP\nOUT Y2.1\n");
  EXPECT_EQ(msDepths(p),
            (std::vector<int32_t>{0, 0, 1, 1, 2, 2, 3, 3, 4, 4, 4, 3, 3, 2, 2, 1, 1, 0}));
  for (int32_t d : depths(p)) EXPECT_LE(d, 1);
  EXPECT_EQ(p.maxMsDepth, 4);
}

// dialect-notes "Stacks and blocks": single-input blocks replace ST0, or push when ST is empty;
// multi-input blocks pop k and push 1.
TEST(VerifierFacts, BlockStackEffects) {
  auto p = ok("CMP R0 100\nOUT R1.0\nLD X1.0\nADD D0 1 D0\nLD X2.5\nLD X2.6\nLD X2.7\n"
              "LD X2.0\nCTUD 0 100\nOUT Y1.4\nLD X1.1\nLD X1.2\nCTRC 1 5\nOUT Y1.5\n");
  EXPECT_EQ(depths(p), (std::vector<int32_t>{0, 1, 1, 2, 2, 3, 4, 5, 6, 3, 3, 4, 5, 4}));
  EXPECT_FALSE(p.info[0].hasInput); // CMP with empty ST: input is 1
  EXPECT_TRUE(p.info[3].hasInput);
  EXPECT_TRUE(p.info[8].hasInput);
  EXPECT_EQ(p.maxDepth, 6);
}

// DIALECT.md 3: stacks are emptied at LBL, LOOP and NEXT.
TEST(VerifierFacts, ResetsAtLabelsAndLoops) {
  auto p = ok("LD X1.0\nJMP L1\nLD X1.1\nLBL L1\nLD X1.2\nLOOP 3\nLD X0.0\nOUT Y0.0\nNEXT\n"
              "LD X0.1\nOUT Y0.1\n");
  EXPECT_EQ(depths(p), (std::vector<int32_t>{0, 1, 1, 2, 0, 1, 0, 1, 1, 0, 1}));
}

// DIALECT.md 2 / dialect-notes "Program parts": ranges exclude markers.
TEST(VerifierFacts, PartRanges) {
  auto p = ok("LDT\nOUT Y0.0\nIEND\nLDT\nOUT Y0.1\n1END\nLDT\nOUT Y0.2\n2END\nSP S7\nLDT\n"
              "OUT Y0.3\nSPE\n");
  EXPECT_EQ(p.init.begin, 0);
  EXPECT_EQ(p.init.end, 2);
  EXPECT_EQ(p.plc1.begin, 3);
  EXPECT_EQ(p.plc1.end, 5);
  EXPECT_EQ(p.plc2.begin, 6);
  EXPECT_EQ(p.plc2.end, 8);
  ASSERT_EQ(p.subs.size(), 1u);
  EXPECT_EQ(p.subs[0].number, 7);
  EXPECT_EQ(p.subs[0].spIndex, 9);
  EXPECT_EQ(p.subs[0].body.begin, 10);
  EXPECT_EQ(p.subs[0].body.end, 12);
  EXPECT_EQ(p.subByNumber[7], 0);
  EXPECT_EQ(p.subByNumber[0], -1);
  EXPECT_EQ(p.subByNumber[511], -1);
}

// DIALECT.md 2: a program with no marker is one PLC1 part.
TEST(VerifierFacts, NoMarkerIsPlc1) {
  auto p = ok("LDT\nOUT Y0.0\n");
  EXPECT_TRUE(p.init.empty());
  EXPECT_EQ(p.plc1.begin, 0);
  EXPECT_EQ(p.plc1.end, 2);
  EXPECT_TRUE(p.plc2.empty());
  ASSERT_EQ(p.slices.size(), 1u);
  EXPECT_TRUE(p.slices[0].empty());
}

// dialect-notes "Program parts": `... IEND ... 2END` has an empty PLC2.
TEST(VerifierFacts, IendThen2EndHasEmptyPlc2) {
  auto p = ok("LDT\nOUT Y0.0\nIEND\nLDT\nOUT Y0.1\n2END\n");
  EXPECT_EQ(p.init.end, 2);
  EXPECT_EQ(p.plc1.begin, 3);
  EXPECT_EQ(p.plc1.end, 5);
  EXPECT_TRUE(p.plc2.empty());
}

// DIALECT.md 2: statements before the first marker belong to the part it ends.
TEST(VerifierFacts, OnlyPlc2Marker) {
  auto p = ok("LDT\nOUT Y0.0\n2END\n");
  EXPECT_TRUE(p.plc1.empty());
  EXPECT_EQ(p.plc2.begin, 0);
  EXPECT_EQ(p.plc2.end, 2);
}

// Targets (Program.h): JMP -> its LBL, LOOP <-> NEXT, CALL -> index into subs.
TEST(VerifierFacts, Targets) {
  auto p = ok("LBL L1\nLD X0.0\nJMP L2\nLOOP 2\nLOOP D0\nNEXT\nNEXT\nLD X0.1\nJMP L1\n"
              "LBL L2\nCALL S3\nLDT\nCALL S1\n2END\nSP S1\nSPE\nSP S3\nCALL S1\nSPE\n");
  EXPECT_EQ(p.info[2].target, 9);
  EXPECT_FALSE(p.info[2].backward);
  EXPECT_EQ(p.info[8].target, 0);
  EXPECT_TRUE(p.info[8].backward);
  EXPECT_EQ(p.info[3].target, 6);
  EXPECT_EQ(p.info[6].target, 3);
  EXPECT_EQ(p.info[4].target, 5);
  EXPECT_EQ(p.info[5].target, 4);
  EXPECT_EQ(p.info[10].target, 1); // S3 is subs[1]
  EXPECT_FALSE(p.info[10].hasInput);
  EXPECT_EQ(p.info[12].target, 0);
  EXPECT_TRUE(p.info[12].hasInput);
  EXPECT_EQ(p.info[17].target, 0);
  EXPECT_EQ(p.subByNumber[1], 0);
  EXPECT_EQ(p.subByNumber[3], 1);
}

// Slots (Program.h): edge slots in statement order for LDP..ORF and CTR instances;
// lj_tc_slot(n) for timers/counters; the block number for PLS/PLF/ALT.
TEST(VerifierFacts, Slots) {
  auto p = ok("LDP R1.0\nORF X5.0\nANDP R2.0\nANDF R4.0\nOUT R10.1\nLD X0.0\nLD X0.1\n"
              "LD X0.2\nLD X0.3\nCTR D0 10\nOUT Y0.0\nLDF X1.0\nORP X1.1\nOUT Y0.1\n"
              "LD X2.0\nTMRB 305 0 100\nOUT Y0.2\nLD X2.1\nLD X2.2\nCTRC 127 5\nOUT Y0.3\n"
              "LD X3.0\nPLS 511\nOUT Y0.4\nLD X3.1\nPLF 0\nOUT Y0.5\nLD X3.2\nALT 9\nOUT Y0.6\n");
  EXPECT_EQ(p.info[0].slot, 0);
  EXPECT_EQ(p.info[1].slot, 1);
  EXPECT_EQ(p.info[2].slot, 2);
  EXPECT_EQ(p.info[3].slot, 3);
  EXPECT_EQ(p.info[9].slot, 4); // CTR owns an edge slot
  EXPECT_EQ(p.info[11].slot, 5);
  EXPECT_EQ(p.info[12].slot, 6);
  EXPECT_EQ(p.edgeSlots, 7);
  EXPECT_EQ(p.info[15].slot, lj_tc_slot(305));
  EXPECT_EQ(p.info[15].slot, 133);
  EXPECT_EQ(p.info[19].slot, 127);
  EXPECT_EQ(p.info[22].slot, 511);
  EXPECT_EQ(p.info[25].slot, 0);
  EXPECT_EQ(p.info[28].slot, 9);
  EXPECT_EQ(p.info[4].slot, -1);
}

// Edge slots are numbered across parts and subroutines in statement order.
TEST(VerifierFacts, EdgeSlotsAcrossParts) {
  auto p = ok("LDP X0.0\nOUT Y0.0\nIEND\nLDF X0.1\nOUT Y0.1\nCALL S0\n2END\nSP S0\nLDP X0.2\n"
              "OUT Y0.2\nSPE\n");
  EXPECT_EQ(p.info[0].slot, 0);
  EXPECT_EQ(p.info[3].slot, 1);
  EXPECT_EQ(p.info[8].slot, 2);
  EXPECT_EQ(p.edgeSlots, 3);
}

// The plc2Nvalue the slices were planned with is recorded.
TEST(VerifierFacts, RecordsNvalue) {
  VerifyOptions o;
  o.plc2Nvalue = 17;
  EXPECT_EQ(ok("LDT\nOUT Y0.0\n", o).plc2Nvalue, 17);
}

// dialect-notes "Flow": calls nest up to 32 deep counting the main part as depth 0.
TEST(VerifierFacts, CallDepthLimitExact) {
  std::string text = "CALL S1\n2END\n";
  for (int s = 1; s <= 32; ++s) {
    text += "SP S" + std::to_string(s) + "\n";
    if (s < 32) text += "CALL S" + std::to_string(s + 1) + "\n";
    text += "SPE\n";
  }
  auto c = compile(text);
  EXPECT_TRUE(c.prog.has_value()) << c.diags;
}

// A program at the statement limit (10,000 statements) parses and verifies. How fast is
// measured in bench/BenchFrontend.cpp (BM_ParseVerify), never in a timed unit test.
TEST(VerifierFacts, TenThousandStatementsVerify) {
  std::string text;
  for (int i = 0; i < 2500; ++i)
    text += "LD X" + std::to_string(i % 500) + ".1\nAND R3.0\nOUT Y" + std::to_string(i % 500) +
            "." + std::to_string(i % 8) + "\nLDP X1.0\n";
  auto c = compile(text);
  ASSERT_TRUE(c.prog.has_value()) << c.diags;
  EXPECT_EQ(c.prog->stmts.size(), 10000u);
}

} // namespace
} // namespace lj

// The table-driven stack effect (ir/StackEffect.h) against DIALECT.md 3/5 and
// hnc8-core.md 4.2, and against the verifier's own depth walk on whole programs.
#include "ir/StackEffect.h"
#include "frontends/hnc8/FrontEnd.h"
#include "frontends/hnc8/Mnemonics.h"
#include "pipeline/Compile.h"

#include <gtest/gtest.h>

namespace lj {
namespace {

StackEffect at(Op op, int32_t depth) { return stackEffect(instrInfo(op), depth); }

TEST(StackEffect, ContactsAndBlocks) {
  // LD pushes one entry and reads none; AND/OR read ST0 and leave the depth.
  EXPECT_EQ(at(Op::Load, 3).reads, 0);
  EXPECT_EQ(at(Op::Load, 3).after(3), 4);
  EXPECT_EQ(at(Op::And, 2).reads, 1);
  EXPECT_EQ(at(Op::And, 2).after(2), 2);
  EXPECT_EQ(at(Op::OrNot, 1).after(1), 1);
  // ANB/ORB read ST1 and ST0, pop both, push the result: depth - 1 (hnc8-core.md 4.9 ANB step 9:
  // three entries become two).
  EXPECT_EQ(at(Op::AndBlock, 3).reads, 2);
  EXPECT_EQ(at(Op::AndBlock, 3).after(3), 2);
  EXPECT_EQ(at(Op::OrBlock, 2).after(2), 1);
}

TEST(StackEffect, CoilsLeaveSt) {
  // OUT leaves ST0 in place (hnc8-core.md 4.10 MPS-1: "OUT leaves ST0").
  for (Op op : {Op::Coil, Op::CoilNot, Op::Set, Op::Reset}) {
    EXPECT_EQ(at(op, 1).reads, 1) << hnc8::mnemonicOf(op);
    EXPECT_EQ(at(op, 1).after(1), 1) << hnc8::mnemonicOf(op);
    EXPECT_EQ(at(op, 1).msDelta, 0);
  }
}

TEST(StackEffect, MultiOutputStack) {
  // MPS saves ST0 on MS; MRD/MPP overwrite ST0 without reading it; MPP pops MS.
  EXPECT_EQ(at(Op::BranchPush, 2).msDelta, 1);
  EXPECT_EQ(at(Op::BranchPush, 2).after(2), 2);
  EXPECT_EQ(at(Op::BranchPush, 2).reads, 1);
  EXPECT_EQ(at(Op::BranchRead, 2).reads, 0);
  EXPECT_EQ(at(Op::BranchRead, 2).msDelta, 0);
  EXPECT_EQ(at(Op::BranchRead, 2).after(2), 2);
  EXPECT_EQ(at(Op::BranchPop, 1).msDelta, -1);
  EXPECT_EQ(at(Op::BranchPop, 1).after(1), 1);
}

TEST(StackEffect, StructuralResets) {
  for (Op op : {Op::EndInit, Op::EndCyclic, Op::EndSliced, Op::SubBegin, Op::SubEnd, Op::Label,
                Op::LoopBegin, Op::LoopEnd}) {
    EXPECT_TRUE(at(op, 5).resets) << hnc8::mnemonicOf(op);
    EXPECT_EQ(at(op, 5).after(5), 0);
  }
}

TEST(StackEffect, FunctionBlocks) {
  // A single-input block with an output replaces ST0 (MOV: EN passes through); on an empty ST it
  // pushes its output (input is 1) and reads nothing.
  EXPECT_EQ(at(Op::Move, 2).reads, 1);
  EXPECT_EQ(at(Op::Move, 2).after(2), 2);
  EXPECT_EQ(at(Op::Move, 0).reads, 0);
  EXPECT_EQ(at(Op::Move, 0).after(0), 1);
  // A block without an output (JMP, CALL) reads ST0 and leaves ST; on an empty ST nothing.
  EXPECT_EQ(at(Op::Call, 1).after(1), 1);
  EXPECT_EQ(at(Op::Call, 0).after(0), 0);
  // CTR takes 4 inputs (hnc8-functions-1 3.3: count, start, down, reset) and pushes its output.
  EXPECT_EQ(instrInfo(Op::RegisterCounter).inputs, 4);
  EXPECT_EQ(at(Op::RegisterCounter, 5).reads, 4);
  EXPECT_EQ(at(Op::RegisterCounter, 5).after(5), 2);
  EXPECT_EQ(at(Op::RingCounter, 2).after(2), 1);
}

/// The verifier's depth walk (Scopes.cpp) and the table function agree statement by statement.
void expectWalkAgrees(const std::string &text) {
  Diagnostics d("t.stl");
  std::optional<VerifiedProgram> p = pipeline::compileStl(text, "t.stl", VerifyOptions{}, d);
  ASSERT_TRUE(p) << d.render();
  for (size_t i = 0; i + 1 < p->stmts.size(); ++i) {
    const InstrInfo &ii = instrInfo(p->stmts[i].op);
    // Part markers (2END, SP, SPE) lie outside every unit: the walk gives them no depth.
    if (instrInfo(p->stmts[i + 1].op).stack == StackRule::Structural) continue;
    StackEffect e = stackEffect(ii, p->info[i].depth);
    EXPECT_EQ(e.after(p->info[i].depth), p->info[i + 1].depth)
        << "after " << hnc8::mnemonicOf(ii.op) << " (statement " << i << ")";
    if (!e.resets) {
      EXPECT_EQ(p->info[i].msDepth + e.msDelta, p->info[i + 1].msDepth);
    }
  }
}

TEST(StackEffect, AgreesWithVerifierWalk) {
  expectWalkAgrees("LD X1.0\nOR X1.1\nLD X2.0\nAND X4.4\nLD X1.2\nAND X2.1\nORB\nOR X1.3\nANB\n"
                   "OR X2.2\nOUT R10.0\n");
  expectWalkAgrees("LD X1.0\nMPS\nLD X1.1\nOR X1.2\nANB\nOUT Y1.0\nMRD\nAND X1.3\nOUT Y0.2\n"
                   "MPP\nAND X1.7\nOUT Y0.3\nLD X2.3\nOR X2.4\nANB\nOUT Y0.4\n");
  expectWalkAgrees("MOV 5 D1\nLD X0.0\nLD X0.1\nLD X0.2\nLD X0.3\nCTR D0 5\nOUT Y0.0\nLD X1.0\n"
                   "CALL S1\nOUT Y1.0\n2END\nSP S1\nLDT\nOUT Y2.0\nSPE\n");
}

} // namespace
} // namespace lj

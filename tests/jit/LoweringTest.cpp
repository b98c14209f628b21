// Unit tests of the lowering and the facade: ABI layout mirror, where bodies are cut into
// functions, the shape of the emitted IR, phase times, sessions with several versions, and
// internal errors reported instead of crashes.
#include "jit/Jit.h"
#include "lowering/AbiTypes.h"
#include "lowering/FunctionEmitter.h"
#include "tests/support/Machine.h"

#include <gtest/gtest.h>

#include <llvm/IR/LLVMContext.h>
#include <llvm/IR/Module.h>

#include <algorithm>
#include <cstddef>
#include <regex>

namespace lj::test {
namespace {

// x86-64 SysV layout, as the JIT's host DataLayout reports it.
const char *kDataLayout = "e-m:e-p270:32:32-p271:32:32-p272:64:64-i64:64-i128:128-f80:128-n8:16:"
                          "32:64-S128";

TEST(AbiTypes, OffsetsMatchTheCHeader) {
  llvm::LLVMContext ctx;
  auto layout = lower::StateLayout::create(ctx, llvm::DataLayout(kDataLayout));
  ASSERT_TRUE(static_cast<bool>(layout)) << llvm::toString(layout.takeError());
  lj_state s{};
  auto off = [&](const void *p) {
    return static_cast<uint32_t>(reinterpret_cast<const char *>(p) -
                                 reinterpret_cast<const char *>(&s));
  };
  EXPECT_EQ(layout->area(Area::Relay, 10).offset, off(&s.img.R[10]));
  EXPECT_EQ(layout->area(Area::Word, 3).offset, off(&s.img.W[3]));
  EXPECT_EQ(layout->area(Area::Param, 199).offset, off(&s.img.P[199]));
  EXPECT_EQ(layout->area(Area::NcControl, 3119).offset, off(&s.img.G[3119]));
  EXPECT_EQ(layout->timer(255, lower::TimerField::Running).offset, off(&s.T[255].running));
  EXPECT_EQ(layout->counter(7, lower::CounterField::Prev).offset, off(&s.C[7].prev));
  EXPECT_EQ(layout->block(lower::BlockArray::AltState, 511).offset, off(&s.alt_state[511]));
  EXPECT_EQ(layout->edge(16383).offset, off(&s.edge[16383]));
  EXPECT_EQ(layout->scalar(lower::Scalar::Steps).offset, off(&s.steps));
  EXPECT_EQ(layout->scalar(lower::Scalar::FaultDivzero).offset, off(&s.fault_divzero));
  EXPECT_EQ(layout->area(Area::NcStatus, 1).type->getIntegerBitWidth(), 16u);
}

TEST(AbiTypes, RejectsAForeignLayout) {
  // A target that aligns i64 to 16 bytes would grow lj_timer to 32 bytes: must fail loudly.
  // (abi.h pads explicitly, so i386's 4-byte i64 alignment still matches.)
  llvm::LLVMContext ctx;
  auto layout = lower::StateLayout::create(ctx, llvm::DataLayout("e-i64:128-n8:16:32:64"));
  EXPECT_FALSE(static_cast<bool>(layout));
  llvm::consumeError(layout.takeError());
}

TEST(Chunking, CutsOnlyWhereNothingIsLive) {
  // 40 rungs `LD / OUT` (depth grows: no stack reset between rungs) are cuttable before every
  // LD; the ANB rung keeps X0.0 live across `LD X0.1 / OUT`, the MPS rung keeps MS non-empty,
  // and the loop body and the JMP..LBL span must stay whole.
  std::string text;
  for (int i = 0; i < 40; ++i) text += "LD X1." + std::to_string(i % 8) + "\nOUT Y1.0\n";
  text += "LD X0.0\nLD X0.1\nOUT Y2.0\nANB\nOUT Y2.1\n";
  text += "LD X0.2\nMPS\nAND X0.3\nOUT Y3.0\nMPP\nOUT Y3.1\n";
  text += "LOOP 2\nLDT\nINC D0\nLDT\nINC D1\nNEXT\nLD X0.4\nJMP L1\nLDT\nINC D2\nLDT\nINC D3\n"
          "LBL L1\nLDT\nOUT Y4.0\n";
  auto prog = compileOrFail(text);
  ASSERT_TRUE(prog);
  std::vector<lower::ChunkPlan> chunks = lower::planChunkFunctions(*prog, prog->plc1, 1);
  ASSERT_GT(chunks.size(), 30u);
  EXPECT_EQ(chunks.front().r.begin, prog->plc1.begin);
  EXPECT_EQ(chunks.back().r.end, prog->plc1.end);
  const int32_t base = prog->plc1.begin, anb = base + 80, mps = base + 85, loop = base + 91;
  for (size_t k = 1; k < chunks.size(); ++k) {
    int32_t cut = chunks[k].r.begin;
    EXPECT_EQ(chunks[k - 1].r.end, cut);
    EXPECT_EQ(chunks[k - 1].carriedOut, chunks[k].carriedIn);
    // A cut where an entry is live must hand it over (a carried cut), elsewhere it is clean.
    const bool live = (cut > anb && cut <= anb + 4)       // X0.0, then the ANB's result
                      || (cut > mps && cut <= mps + 5);   // MS holds an entry
    EXPECT_FALSE(cut > loop && cut <= loop + 5) << cut;   // inside LOOP..NEXT
    const bool span = cut > loop + 7 && cut <= loop + 12; // between JMP and its LBL
    if (!span) {
      EXPECT_EQ(chunks[k].carriedIn, live) << cut;
    }
    // A cut inside a JMP span is the last resort (3 x target without another cut) and makes
    // the label start a chunk, to which the JMP's chunk hands over by status.
    if (span) {
      EXPECT_TRUE(chunks[k].jumps) << cut;
      EXPECT_TRUE(std::any_of(chunks.begin(), chunks.end(),
                              [&](const lower::ChunkPlan &c) { return c.r.begin == loop + 12; }));
    }
  }
  // The carried cuts load and store only the positions their chunk touches: the chunk
  // `OUT Y2.0 / ANB` (depth 42 on entry) reads positions 41 and 40, nothing below.
  for (const lower::ChunkPlan &c : chunks)
    if (c.r.begin == anb + 2) {
      EXPECT_TRUE(c.carriedIn);
      EXPECT_EQ(c.r.end, anb + 4);
      EXPECT_EQ(c.stLoad, prog->info[anb + 2].depth - 2);
      EXPECT_EQ(c.stStore, prog->info[anb + 2].depth - 2);
    }
  EXPECT_EQ(lower::planChunks(*prog, prog->plc1, 0).size(), 1u);
}

TEST(EmitLlvm, NoMemoryStackAndStatesArePointers) {
  auto prog = compileOrFail("LD X1.0\nOR X1.1\nLD X2.0\nAND X4.4\nLD X1.2\nAND X2.1\nORB\n"
                            "OR X1.3\nANB\nOR X2.2\nOUT R10.0\n");
  ASSERT_TRUE(prog);
  for (int level = 0; level <= 3; ++level) {
    std::string ir, error;
    ASSERT_TRUE(jit::emitLlvm(*prog, level, ir, error)) << error;
    EXPECT_EQ(ir.find("alloca"), std::string::npos) << "-O" << level << "\n" << ir;
    EXPECT_TRUE(std::regex_search(ir, std::regex("define (noundef )?i32 @lj_plc1\\(ptr"))) << ir;
    EXPECT_NE(ir.find("@lj_plc2("), std::string::npos);
    EXPECT_NE(ir.find("noalias"), std::string::npos);
  }
  std::string ir, error;
  EXPECT_FALSE(jit::emitLlvm(*prog, 4, ir, error));
  EXPECT_FALSE(error.empty());
}

TEST(EmitLlvm, OneStoreForSeveralCoilsOfOneByte) {
  // The image cache writes Y0 once although three coils change it (MPS-1, hnc8-core.md 4.10).
  auto prog = compileOrFail("LD X1.0\nMPS\nAND X1.7\nOUT Y0.3\nMRD\nOUT Y0.2\nMPP\nOOUT Y0.4\n");
  ASSERT_TRUE(prog);
  std::string ir, error;
  ASSERT_TRUE(jit::emitLlvm(*prog, 0, ir, error)) << error;
  std::regex store("store i8 [^,]+, ptr %Y0\\.addr");
  auto n = std::distance(std::sregex_iterator(ir.begin(), ir.end(), store), std::sregex_iterator());
  EXPECT_EQ(n, 1) << ir;
}

TEST(Facade, PhaseTimesAndVersionsInOneSession) {
  auto v1 = compileOrFail("LDT\nMOV 1 D0\n");
  auto v2 = compileOrFail("LDT\nMOV 2 D0\n");
  ASSERT_TRUE(v1 && v2);
  for (jit::Tier tier : {jit::Tier::Fast, jit::Tier::Optimizing}) {
    std::string error;
    std::shared_ptr<jit::Session> session = jit::Session::create(tier, error);
    ASSERT_TRUE(session) << error;
    EXPECT_EQ(session->tier(), tier);
    jit::CompileTimes t1, t2;
    std::unique_ptr<Engine> e1 = session->compile(*v1, {tier, 150}, error, &t1);
    ASSERT_TRUE(e1) << error;
    std::unique_ptr<Engine> e2 = session->compile(*v2, {tier, 150}, error, &t2);
    ASSERT_TRUE(e2) << error;
    EXPECT_GT(t1.lowerUs, 0);
    EXPECT_GT(t1.codegenUs, 0);
    if (tier == jit::Tier::Optimizing) {
      EXPECT_GT(t2.optimizeUs, 0);
    }
    // Both versions are live in one JIT (a JITDylib each); dropping v1 leaves v2 running.
    lj_state s;
    lj_state_reset(&s);
    lj_tick(&s, &e1->entries());
    EXPECT_EQ(s.img.D[0], 1);
    lj_tick(&s, &e2->entries());
    EXPECT_EQ(s.img.D[0], 2);
    e1.reset();
    s.img.D[0] = 0;
    lj_tick(&s, &e2->entries());
    EXPECT_EQ(s.img.D[0], 2);
    std::unique_ptr<Engine> e3 = session->compile(*v1, {tier, 150}, error);
    ASSERT_TRUE(e3) << error;
    lj_tick(&s, &e3->entries());
    EXPECT_EQ(s.img.D[0], 1);
    EXPECT_STREQ(e3->name(), "jit");
    EXPECT_EQ(e3->entries().plc2_slice_count, 1u);
  }
}

TEST(Facade, InconsistentProgramIsAnErrorNotACrash) {
  // A verified program whose facts contradict its statements (a front-end bug) is reported.
  auto prog = compileOrFail("LD X0.0\nLD X0.1\nANB\nOUT Y0.0\n");
  ASSERT_TRUE(prog);
  prog->info[prog->plc1.begin + 2].depth = 5;
  std::string error;
  EXPECT_EQ(jit::compile(*prog, {}, error), nullptr);
  EXPECT_NE(error.find("internal error"), std::string::npos) << error;
  EXPECT_NE(error.find("test.stl:3:"), std::string::npos) << error;
}

} // namespace
} // namespace lj::test

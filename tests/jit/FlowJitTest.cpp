// Flow on the JIT (both tiers): JMP/LBL, LOOP/NEXT, CALL/RETN, the watchdog and PLC2 slices
// (hnc8-functions-1.md 3.5, docs/dialect-notes.md "Flow" and "PLC2 slicing").
#include "tests/jit/JitHarness.h"

namespace lj::test {
namespace {

class FlowJit : public ::testing::TestWithParam<jit::Tier> {};

TEST_P(FlowJit, JmpExample) {
  // 3.5 JMP test: X35.5=1 -> Y0.0 unchanged, Y0.1=1; X35.5=0 -> both 1. The edge contact in
  // the skipped code keeps its memory (DIALECT.md 3): skipped code does not update m.
  auto prog = compileOrFail("LD X35.5\nJMP L1111\nLDT\nOUT Y0.0\nLDP X1.0\nOUT Y0.2\n"
                            "LBL L1111\nLDT\nOUT Y0.1\n");
  ASSERT_TRUE(prog);
  Scenario d;
  d.ticks = 4;
  d.hostInputs = [](uint32_t t, lj_state &s) {
    s.img.X[35] = t < 2 ? 0x20 : 0;
    s.img.X[1] = 1;
  };
  EXPECT_TRUE(
      jitMatchesInterpreter(*prog, GetParam(), d, [](uint32_t t, const lj_state &s, uint32_t) {
        EXPECT_EQ(bitOf(s.img.Y[0], 0), t >= 2 ? 1 : 0);
        EXPECT_EQ(bitOf(s.img.Y[0], 1), 1);
        // X1.0 has been 1 since tick 0, but the LDP first runs at tick 2: a rising edge then.
        EXPECT_EQ(bitOf(s.img.Y[0], 2), t == 2 ? 1 : 0);
      }));
}

TEST_P(FlowJit, IendLoopAndNestedLoops) {
  // 3.5: `LDT / INC D0 / IEND` -> D0 = 1 after any number of scans; `LOOP 5 / LDT / INC D1 /
  // NEXT` -> +5 per scan. Nested LOOP 3 / LOOP R8: the register count is read once on entry
  // (the inner body clears R8, the outer body restores it from R9), so the inner body runs
  // 3 * R9 times; each iteration is one watchdog step; LOOP -2 skips its body.
  auto prog = compileOrFail("LDT\nINC D0\nIEND\nLOOP 5\nLDT\nINC D1\nNEXT\nLOOP 3\nLOOP R8\n"
                            "LDT\nINC D2\nLDT\nMOV 0 R8\nNEXT\nLDT\nMOV R9 R8\nNEXT\nLOOP -2\n"
                            "LDT\nINC D3\nNEXT\n");
  ASSERT_TRUE(prog);
  Scenario d;
  d.ticks = 4;
  d.hostInputs = [](uint32_t t, lj_state &s) {
    s.img.R[8] = s.img.R[9] = static_cast<uint8_t>(2 * t);
    s.img.D[2] = 0;
  };
  EXPECT_TRUE(
      jitMatchesInterpreter(*prog, GetParam(), d, [](uint32_t t, const lj_state &s, uint32_t) {
        EXPECT_EQ(s.img.D[0], 1);
        EXPECT_EQ(s.img.D[1], 5 * static_cast<int32_t>(t + 1));
        EXPECT_EQ(s.img.D[2], 6 * static_cast<int32_t>(t));
        EXPECT_EQ(s.img.D[3], 0);
        EXPECT_EQ(s.steps, 5u + 3u + 6u * t);
      }));
}

TEST_P(FlowJit, CallRetnAndCallerStack) {
  // 3.5 RETN test: SP S1 / LDI R100.0 / RETN / LDT / OUT Y0.0 / SPE: with R100.0=0 Y0.0 is not
  // written, with R100.0=1 Y0.0=1. The caller's ST survives the call (depth 2 across CALL),
  // and nested calls S2 -> S3 run with their own stacks.
  auto prog = compileOrFail("LD X0.1\nLD X0.0\nCALL S1\nANB\nOUT Y1.0\nLDT\nCALL S2\nOUT Y1.1\n"
                            "1END\n2END\nSP S1\nLDI R100.0\nRETN\nLDT\nOUT Y0.0\nSPE\n"
                            "SP S2\nLD X0.2\nCALL S3\nOUT Y2.0\nSPE\n"
                            "SP S3\nLDT\nINC D0\nLDT\nRETN\nSPE\n");
  ASSERT_TRUE(prog);
  Scenario d;
  d.ticks = 16;
  d.hostInputs = [](uint32_t t, lj_state &s) {
    s.img.X[0] = static_cast<uint8_t>(t & 7);
    s.img.R[100] = (t >> 3) & 1;
    s.img.Y[0] = 0;
  };
  EXPECT_TRUE(
      jitMatchesInterpreter(*prog, GetParam(), d, [](uint32_t t, const lj_state &s, uint32_t) {
        int x0 = t & 1, x1 = (t >> 1) & 1, x2 = (t >> 2) & 1, r100 = (t >> 3) & 1;
        EXPECT_EQ(bitOf(s.img.Y[0], 0), x0 & r100);
        EXPECT_EQ(bitOf(s.img.Y[1], 0), x0 & x1);
        EXPECT_EQ(bitOf(s.img.Y[1], 1), 1);
        EXPECT_EQ(bitOf(s.img.Y[2], 0), x2);
      }));
}

TEST_P(FlowJit, WatchdogOnBackwardJump) {
  // dialect-notes: `if (++steps > max) abort` before each taken backward JMP; the image keeps
  // what was written so far. With max 10 an endless loop runs its body 11 times per tick.
  auto prog = compileOrFail("LDT\nINC D1\nLBL L1\nLDT\nINC D0\nLDT\nJMP L1\n1END\nLDT\nINC D2\n");
  ASSERT_TRUE(prog);
  Scenario d;
  d.ticks = 3;
  d.maxBackwardSteps = 10;
  EXPECT_TRUE(jitMatchesInterpreter(
      *prog, GetParam(), d, [](uint32_t t, const lj_state &s, uint32_t fault) {
        EXPECT_EQ(fault, static_cast<uint32_t>(LJ_FAULT_WATCHDOG));
        EXPECT_EQ(s.img.D[0], 11 * static_cast<int32_t>(t + 1));
        EXPECT_EQ(s.img.D[1], static_cast<int32_t>(t + 1));
        EXPECT_EQ(s.img.D[2], 0); // the PLC2 slice is skipped after a PLC1 abort
        EXPECT_EQ(s.steps, 11u);
        EXPECT_EQ(s.fault_watchdog, t + 1);
      }));
}

TEST_P(FlowJit, WatchdogPropagatesThroughCallsAndLoops) {
  // max 50 steps. Even ticks: R8 = 0, PLC1 takes 10 loop steps, then PLC2 jumps back twice
  // (steps 11, 12) and ends with D8 = 3. Odd ticks: R8 = 30, the subroutine's loop exhausts the
  // budget at step 51 in the second outer iteration; the abort returns through S1 and the
  // caller's loop, INC D1 of that iteration and everything after it do not run, PLC2 is skipped.
  auto prog = compileOrFail("LOOP 10\nLDT\nCALL S1\nLDT\nINC D1\nNEXT\nLDT\nINC D2\n1END\n"
                            "LDT\nMOV 0 D7\nLBL L5\nLDT\nINC D7\nLT D7 3\nJMP L5\nLDT\nMOV D7 D8\n"
                            "2END\nSP S1\nLOOP R8\nLDT\nINC D0\nNEXT\nSPE\n");
  ASSERT_TRUE(prog);
  Scenario d;
  d.ticks = 4;
  d.maxBackwardSteps = 50;
  d.hostInputs = [](uint32_t t, lj_state &s) {
    s.img.R[8] = (t & 1) ? 30 : 0;
    s.img.D[8] = 0;
  };
  EXPECT_TRUE(jitMatchesInterpreter(
      *prog, GetParam(), d, [](uint32_t t, const lj_state &s, uint32_t fault) {
        static const int32_t kD0[] = {0, 48, 48, 96}, kD1[] = {10, 11, 21, 22},
                             kD2[] = {1, 1, 2, 2};
        bool odd = t & 1;
        EXPECT_EQ(fault, odd ? uint32_t(LJ_FAULT_WATCHDOG) : uint32_t(LJ_FAULT_NONE));
        EXPECT_EQ(s.steps, odd ? 51u : 12u);
        EXPECT_EQ(s.img.D[8], odd ? 0 : 3);
        EXPECT_EQ(s.img.D[0], kD0[t]);
        EXPECT_EQ(s.img.D[1], kD1[t]);
        EXPECT_EQ(s.img.D[2], kD2[t]);
      }));
}

TEST_P(FlowJit, SlicesRunRoundRobinWithDeadEntries) {
  // DIALECT.md 4: PLC2 is cut into slices of >= plc2_nvalue statements at rung boundaries; the
  // stacks keep growing across rungs (no reset), so later slices start with dead entries.
  std::string text = "LDT\nINC D0\n1END\n";
  for (int i = 0; i < 12; ++i)
    text += "LD X1." + std::to_string(i % 8) + "\nOUT Y" + std::to_string(i) + "." +
            std::to_string(i % 8) + "\nLDT\nINC D" + std::to_string(1 + i) + "\n";
  text += "2END\n";
  auto prog = compileOrFail(text, optionsWithNvalue(4));
  ASSERT_TRUE(prog);
  ASSERT_GT(prog->slices.size(), 2u);
  Scenario d;
  d.ticks = 40;
  d.hostInputs = [](uint32_t t, lj_state &s) { s.img.X[1] = static_cast<uint8_t>(t * 29); };
  EXPECT_TRUE(jitMatchesInterpreter(*prog, GetParam(), d));
}

TEST_P(FlowJit, ChunkedBodiesMatch) {
  // Cutting long bodies into functions (chunkStatements) must not change anything: run a
  // program with JMPs, loops, MPS, calls and a RETN in a long subroutine at chunk size 3.
  std::string body;
  for (int i = 0; i < 10; ++i) {
    std::string n = std::to_string(i);
    body += "LD X2." + std::to_string(i % 8) + "\nMPS\nAND X3.1\nOUT Y" + n +
            ".1\nMPP\n"
            "ANI X3.2\nOUT Y" +
            n + ".2\nLD X3.3\nJMP L" + n + "\nLDT\nINC D" + n + "\nLBL L" + n +
            "\nLOOP 2\nLDP X4." + std::to_string(i % 8) + "\nOUT R" + n + ".0\nNEXT\n";
  }
  std::string sub;
  for (int i = 0; i < 8; ++i)
    sub += "LD X5." + std::to_string(i) + "\nRETN\nLDT\nINC W" + std::to_string(i) + "\n";
  std::string text = body + "LD X6.0\nOR X6.1\nLD X6.2\nCALL S1\nANB\nOUT Y20.0\n1END\n" + body +
                     "2END\nSP S1\n" + sub + "SPE\n";
  auto prog = compileOrFail(text, optionsWithNvalue(10));
  ASSERT_TRUE(prog);
  Scenario d;
  d.ticks = 30;
  d.hostInputs = [](uint32_t t, lj_state &s) {
    for (int n = 2; n <= 6; ++n) s.img.X[n] = static_cast<uint8_t>((t + 1) * (n * 37 + 11) >> 2);
  };
  for (int chunk : {0, 3, 7}) {
    SCOPED_TRACE("chunkStatements " + std::to_string(chunk));
    EXPECT_TRUE(jitMatchesInterpreter(*prog, GetParam(), d, {}, chunk));
  }
}

INSTANTIATE_TEST_SUITE_P(Tiers, FlowJit, ::testing::Values(jit::Tier::Fast, jit::Tier::Optimizing),
                         tierName);

} // namespace
} // namespace lj::test

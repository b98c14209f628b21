// Function blocks on the JIT (both tiers): the reference's test values for math, compare, MOV,
// counters, timers and PLS/PLF/ALT, each run in lock-step with the interpreter.
#include "tests/jit/JitHarness.h"

#include <algorithm>
#include <climits>

namespace lj::test {
namespace {

class BlocksJit : public ::testing::TestWithParam<jit::Tier> {};

void setX(lj_state &s, int n, int b, bool v) {
  uint8_t m = static_cast<uint8_t>(1u << b);
  s.img.X[n] = v ? (s.img.X[n] | m) : (s.img.X[n] & ~m);
}

TEST_P(BlocksJit, MathExamples32) {
  // hnc8-functions-1.md 3.2: ADD D0 100 D1 with X3.4=1, D0=5 -> D1=105, R4.0=1; X3.4=0 ->
  // D1 unchanged, R4.0=0. SUB -> -95. DIV: 250 -> 2, -250 -> -2. WAND 0xFF & 100 = 100.
  auto prog = compileOrFail("LD X3.4\nADD D0 100 D1\nOUT R4.0\nLD X3.4\nSUB D0 100 D2\n"
                            "LD X3.4\nMUL D0 100 D3\nLD X3.4\nDIV D4 100 D5\nLD X3.4\n"
                            "WAND D6 100 D7\nLD X3.4\nWOR D6 100 D8\nLD X3.4\nWXOR D6 100 D9\n");
  ASSERT_TRUE(prog);
  Scenario d;
  d.ticks = 4;
  d.hostBefore = [](lj_state &s) {
    s.img.D[0] = 5;
    s.img.D[1] = 77;
    s.img.D[6] = 0xFF;
  };
  d.hostInputs = [](uint32_t t, lj_state &s) {
    setX(s, 3, 4, t != 2);
    s.img.D[4] = t == 0 ? 250 : -250;
  };
  EXPECT_TRUE(
      jitMatchesInterpreter(*prog, GetParam(), d, [](uint32_t t, const lj_state &s, uint32_t) {
        EXPECT_EQ(s.img.D[1], 105);
        EXPECT_EQ(bitOf(s.img.R[4], 0), t != 2 ? 1 : 0);
        EXPECT_EQ(s.img.D[2], -95);
        EXPECT_EQ(s.img.D[3], 500);
        if (t == 0) {
          EXPECT_EQ(s.img.D[5], 2);
        }
        if (t == 1 || t == 3) {
          EXPECT_EQ(s.img.D[5], -2);
        }
        EXPECT_EQ(s.img.D[7], 100);
        EXPECT_EQ(s.img.D[8], 0xFF);
        EXPECT_EQ(s.img.D[9], 0xFF ^ 100);
      }));
}

TEST_P(BlocksJit, DivisionFaults) {
  // dialect-notes: DIV by zero writes nothing, output 0, fault_divzero counts it (EN = 1 only);
  // INT32_MIN / -1 = INT32_MIN; truncation toward zero.
  auto prog = compileOrFail("LD X0.0\nDIV D0 D1 D2\nOUT Y0.0\nLD X0.1\nDIV D3 -1 D4\nOUT Y0.1\n"
                            "LDT\nDIV -7 2 D5\n");
  ASSERT_TRUE(prog);
  Scenario d;
  d.ticks = 4;
  d.hostBefore = [](lj_state &s) {
    s.img.D[0] = 10;
    s.img.D[2] = 1234;
    s.img.D[3] = INT32_MIN;
  };
  d.hostInputs = [](uint32_t t, lj_state &s) {
    s.img.X[0] = t == 3 ? 0 : 3; // tick 3: both blocks disabled
    s.img.D[1] = t == 1 ? 3 : 0;
  };
  EXPECT_TRUE(
      jitMatchesInterpreter(*prog, GetParam(), d, [](uint32_t t, const lj_state &s, uint32_t) {
        static const uint32_t kDivZero[] = {1, 1, 2, 2};
        EXPECT_EQ(s.fault_divzero, kDivZero[t]);
        EXPECT_EQ(s.img.D[2], t == 0 ? 1234 : 3);
        EXPECT_EQ(bitOf(s.img.Y[0], 0), t == 1 ? 1 : 0);
        EXPECT_EQ(s.img.D[4], INT32_MIN);
        EXPECT_EQ(bitOf(s.img.Y[0], 1), t == 3 ? 0 : 1);
        EXPECT_EQ(s.img.D[5], -3);
      }));
}

TEST_P(BlocksJit, WidthsAndWrap) {
  // functions-1 2.2 / 3.2: ADD R0 200 R1 with R0 = 100 -> 44; INC R 255 -> 0; INC W 32767 ->
  // -32768; DEC R 0 -> 255; NEG R 5 -> 251; NEG INT32_MIN stays; MUL wraps at 32 bits.
  // functions-2 2.1: MOV 300 R5 -> 44, MOV -1 W3 -> -1, MOV W3 D2 -> -1, MOV F1 D3 sign-extends,
  // MOV X1 D4 zero-extends.
  auto prog = compileOrFail("LDT\nADD R0 200 R1\nLDT\nINC R2\nLDT\nINC W0\nLDT\nDEC R3\nLDT\n"
                            "NEG R4\nLDT\nNEG D0\nLDT\nMUL D1 65536 D6\nLDT\nMOV 300 R5\nLDT\n"
                            "MOV -1 W3\nLDT\nMOV W3 D2\nLDT\nMOV F1 D3\nLDT\nMOV X1 D4\n");
  ASSERT_TRUE(prog);
  Scenario d;
  d.ticks = 1;
  d.hostBefore = [](lj_state &s) {
    s.img.R[0] = 100;
    s.img.R[2] = 255;
    s.img.W[0] = 32767;
    s.img.R[3] = 0;
    s.img.R[4] = 5;
    s.img.D[0] = INT32_MIN;
    s.img.D[1] = 65537;
    s.img.F[1] = -300;
    s.img.X[1] = 200;
  };
  EXPECT_TRUE(
      jitMatchesInterpreter(*prog, GetParam(), d, [](uint32_t, const lj_state &s, uint32_t) {
        EXPECT_EQ(s.img.R[1], 44);
        EXPECT_EQ(s.img.R[2], 0);
        EXPECT_EQ(s.img.W[0], -32768);
        EXPECT_EQ(s.img.R[3], 255);
        EXPECT_EQ(s.img.R[4], 251);
        EXPECT_EQ(s.img.D[0], INT32_MIN);
        EXPECT_EQ(s.img.D[6], 65536); // 65537 * 65536 mod 2^32
        EXPECT_EQ(s.img.R[5], 44);
        EXPECT_EQ(s.img.W[3], -1);
        EXPECT_EQ(s.img.D[2], -1);
        EXPECT_EQ(s.img.D[3], -300);
        EXPECT_EQ(s.img.D[4], 200);
      }));
}

TEST_P(BlocksJit, CompareExamples) {
  // functions-2 1.1-1.4 test values: CMP R0 100, LT R0 100, ACMP 0 100 R0, COIN R0 100,
  // COIN W5 -1 (0xFFFF sign-extends), and a compare in series with X1.0 (output = EN & cond).
  auto prog = compileOrFail("LDT\nCMP R0 100\nOUT R10.0\nLDT\nLT R0 100\nOUT R10.1\n"
                            "LDT\nACMP 0 100 R0\nOUT R10.2\nLDT\nCOIN R0 100\nOUT R10.3\n"
                            "LDT\nCOIN W5 -1\nOUT R10.4\nLD X1.0\nCOIN R0 100\nOUT Y1.0\n");
  ASSERT_TRUE(prog);
  static const int kR0[] = {0, 1, 99, 100, 101, 150};
  Scenario d;
  d.ticks = 12;
  d.hostBefore = [](lj_state &s) { s.img.W[5] = -1; };
  d.hostInputs = [](uint32_t t, lj_state &s) {
    s.img.R[0] = static_cast<uint8_t>(kR0[t % 6]);
    s.img.X[1] = t >= 6 ? 1 : 0;
  };
  EXPECT_TRUE(
      jitMatchesInterpreter(*prog, GetParam(), d, [](uint32_t t, const lj_state &s, uint32_t) {
        int r0 = kR0[t % 6];
        EXPECT_EQ(bitOf(s.img.R[10], 0), r0 <= 100);
        EXPECT_EQ(bitOf(s.img.R[10], 1), r0 < 100);
        EXPECT_EQ(bitOf(s.img.R[10], 2), r0 > 0 && r0 < 100);
        EXPECT_EQ(bitOf(s.img.R[10], 3), r0 == 100);
        EXPECT_EQ(bitOf(s.img.R[10], 4), 1);
        EXPECT_EQ(bitOf(s.img.Y[1], 0), t >= 6 && r0 == 100);
      }));
}

TEST_P(BlocksJit, CtrExample33) {
  // functions-1 3.3 CTR: X4.0=1 (start 1), X4.1=0 (up); reset -> R0=1; 5 pulses -> R0=6,
  // Y1.4=0; 15 pulses from 1 -> R0=16, Y1.4=1; one more -> R0=1 (ring).
  auto prog = compileOrFail("LD X2.5\nLD X4.0\nLD X4.1\nLD X4.2\nCTR R0 16\nOUT Y1.4\n");
  ASSERT_TRUE(prog);
  Scenario d;
  d.ticks = 2 + 2 * 16;
  d.hostInputs = [](uint32_t t, lj_state &s) {
    s.img.X[4] = t == 0 ? 0x5 : 0x1; // X4.0 = 1 always, X4.2 = reset only at tick 0
    setX(s, 2, 5, t >= 2 && (t % 2) == 0);
  };
  EXPECT_TRUE(
      jitMatchesInterpreter(*prog, GetParam(), d, [](uint32_t t, const lj_state &s, uint32_t) {
        uint32_t pulses = t < 2 ? 0 : (t - 2) / 2 + 1;
        if (t == 0) {
          EXPECT_EQ(s.img.R[0], 1);
        }
        if (pulses == 5) {
          EXPECT_EQ(s.img.R[0], 6);
        }
        if (pulses == 15) {
          EXPECT_EQ(s.img.R[0], 16);
          EXPECT_EQ(bitOf(s.img.Y[1], 4), 1);
        }
        if (pulses == 16) {
          EXPECT_EQ(s.img.R[0], 1);
        }
        if (pulses < 15) {
          EXPECT_EQ(bitOf(s.img.Y[1], 4), 0);
        }
      }));
}

TEST_P(BlocksJit, CtrcAndCtudExamples33) {
  // CTRC 0 100: 99 pulses -> Y1.4=0, 100 -> 1; X4.0=1 -> reset, count 0. CTUD 1 100 down
  // (X3.2=1 as input 3, X3.3 reset) reloads 100, 100 pulses -> 0 and Y1.5=1.
  auto prog = compileOrFail("LD X2.5\nLD X4.0\nCTRC 0 100\nOUT Y1.4\n"
                            "LD X2.5\nLD X3.1\nLD X3.2\nLD X3.3\nCTUD 1 100\nOUT Y1.5\n");
  ASSERT_TRUE(prog);
  Scenario d;
  d.ticks = 1 + 200 + 2;
  d.hostInputs = [](uint32_t t, lj_state &s) {
    s.img.X[3] = t == 0 ? 0xC : 0x4; // down counting; reset at tick 0
    setX(s, 2, 5, t >= 1 && t <= 200 && (t % 2) == 1);
    setX(s, 4, 0, t == 202);
  };
  EXPECT_TRUE(
      jitMatchesInterpreter(*prog, GetParam(), d, [](uint32_t t, const lj_state &s, uint32_t) {
        uint32_t pulses = t == 0 ? 0 : std::min<uint32_t>((t + 1) / 2, 100);
        if (t == 0) {
          EXPECT_EQ(s.C[1].value, 100);
        }
        if (t <= 200) {
          EXPECT_EQ(s.C[0].value, static_cast<int32_t>(pulses));
        }
        if (pulses == 99) {
          EXPECT_EQ(bitOf(s.img.Y[1], 4), 0);
        }
        if (t == 200) {
          EXPECT_EQ(bitOf(s.img.Y[1], 4), 1);
          EXPECT_EQ(s.C[1].value, 0);
          EXPECT_EQ(bitOf(s.img.Y[1], 5), 1);
        }
        if (t == 202) {
          EXPECT_EQ(s.C[0].value, 0);
          EXPECT_EQ(bitOf(s.img.Y[1], 4), 0);
        }
      }));
}

TEST_P(BlocksJit, TimerExamples34) {
  // functions-1 3.4: TMRB 1 0 100 with X35.5 on from t=0: Y4.2=0 at t=99, 1 at t>=100.
  // STMR 2 0 100 with X35.6 on for t<10: Y4.3=1 until t=109, 0 from t=110.
  // TMRB 3 1 D0 in seconds with D0 = 2; T5 (STMR) with a negative preset counts as 0.
  auto prog = compileOrFail("LD X35.5\nTMRB 1 0 100\nOUT Y4.2\nLD X35.6\nSTMR 2 0 100\nOUT Y4.3\n"
                            "LD X35.5\nTMRB 3 1 D0\nOUT Y4.4\nLD X35.6\nSTMR 5 0 -5\nOUT Y4.5\n");
  ASSERT_TRUE(prog);
  Scenario d;
  d.ticks = 2100;
  d.hostBefore = [](lj_state &s) { s.img.D[0] = 2; };
  d.hostInputs = [](uint32_t t, lj_state &s) {
    setX(s, 35, 5, true);
    setX(s, 35, 6, t < 10);
  };
  EXPECT_TRUE(
      jitMatchesInterpreter(*prog, GetParam(), d, [](uint32_t t, const lj_state &s, uint32_t) {
        EXPECT_EQ(bitOf(s.img.Y[4], 2), t >= 100 ? 1 : 0) << t;
        EXPECT_EQ(bitOf(s.img.Y[4], 3), t <= 109 ? 1 : 0) << t;
        EXPECT_EQ(bitOf(s.img.Y[4], 4), t >= 2000 ? 1 : 0) << t;
        EXPECT_EQ(bitOf(s.img.Y[4], 5), t < 10 ? 1 : 0) << t;
        EXPECT_EQ(s.T[1].elapsed_ms, std::min<int64_t>(t, 100));
      }));
}

TEST_P(BlocksJit, PulseAndToggleExamples) {
  // functions-2 2.14-2.16 scan sequences (R100.0 -> R10.x): PLS 0,1,1,0,1 -> 0,1,0,0,1;
  // PLF 0,1,0,0 -> 0,0,1,0; ALT 0,1,1,0,1,0 -> 0,1,1,1,0,0.
  auto prog = compileOrFail("LD R100.0\nPLS 1\nOUT R10.0\nLD R100.1\nPLF 1\nOUT R10.1\n"
                            "LD R100.2\nALT 1\nOUT R10.2\n");
  ASSERT_TRUE(prog);
  static const int kPlsIn[] = {0, 1, 1, 0, 1, 0}, kPlsOut[] = {0, 1, 0, 0, 1, 0};
  static const int kPlfIn[] = {0, 1, 0, 0, 0, 0}, kPlfOut[] = {0, 0, 1, 0, 0, 0};
  static const int kAltIn[] = {0, 1, 1, 0, 1, 0}, kAltOut[] = {0, 1, 1, 1, 0, 0};
  Scenario d;
  d.ticks = 6;
  d.hostInputs = [](uint32_t t, lj_state &s) {
    s.img.R[100] = static_cast<uint8_t>(kPlsIn[t] | kPlfIn[t] << 1 | kAltIn[t] << 2);
  };
  EXPECT_TRUE(
      jitMatchesInterpreter(*prog, GetParam(), d, [](uint32_t t, const lj_state &s, uint32_t) {
        EXPECT_EQ(bitOf(s.img.R[10], 0), kPlsOut[t]) << t;
        EXPECT_EQ(bitOf(s.img.R[10], 1), kPlfOut[t]) << t;
        EXPECT_EQ(bitOf(s.img.R[10], 2), kAltOut[t]) << t;
      }));
}

TEST_P(BlocksJit, BlocksWithoutInputPushTheirOutput) {
  // dialect-notes: with an empty ST a block's input is 1 and its output is pushed, so
  // `CMP R0 100 / OUT R1.0` works; T/C output bits are readable contacts.
  auto prog = compileOrFail("CMP R0 100\nOUT R1.0\nMOV 7 D0\nOUT R1.1\nPLS 3\nOUT R1.2\n"
                            "LD T1.0\nOUT R1.3\nLD C2.0\nOUT R1.4\nLDT\nTMRB 1 0 0\nLDT\nLD R99.0\n"
                            "CTRC 2 1\n");
  ASSERT_TRUE(prog);
  Scenario d;
  d.ticks = 3;
  EXPECT_TRUE(
      jitMatchesInterpreter(*prog, GetParam(), d, [](uint32_t t, const lj_state &s, uint32_t) {
        EXPECT_EQ(bitOf(s.img.R[1], 0), 1);
        EXPECT_EQ(bitOf(s.img.R[1], 1), 1);
        EXPECT_EQ(s.img.D[0], 7);
        EXPECT_EQ(bitOf(s.img.R[1], 2), t == 0 ? 1 : 0);
        EXPECT_EQ(bitOf(s.img.R[1], 3), t >= 1 ? 1 : 0); // TMRB with preset 0 is on at once
        EXPECT_EQ(bitOf(s.img.R[1], 4), t >= 1 ? 1 : 0); // CTRC 2 1 reached on the first edge
      }));
}

INSTANTIATE_TEST_SUITE_P(Tiers, BlocksJit,
                         ::testing::Values(jit::Tier::Fast, jit::Tier::Optimizing), tierName);

} // namespace
} // namespace lj::test

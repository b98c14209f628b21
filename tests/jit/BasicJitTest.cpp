// The manual's basic-instruction examples (hnc8-core.md 4.3-4.10) on the JIT, both tiers:
// full state equal to the interpreter after every tick, and the documented outputs.
#include "tests/jit/JitHarness.h"

#include <utility>
#include <vector>

namespace lj::test {
namespace {

using Pin = std::pair<int, int>; // (X byte, bit)

// Drives the listed X bits from the bits of the tick number, so 2^n ticks see every input
// combination exactly once.
Scenario exhaustive(std::vector<Pin> pins) {
  Scenario d;
  d.ticks = 1u << pins.size();
  d.hostInputs = [pins](uint32_t t, lj_state &s) {
    for (size_t i = 0; i < pins.size(); ++i) {
      uint8_t &byte = s.img.X[pins[i].first];
      uint8_t mask = static_cast<uint8_t>(1u << pins[i].second);
      byte = ((t >> i) & 1) ? (byte | mask) : (byte & ~mask);
    }
  };
  return d;
}

int x(const lj_state &s, int n, int b) { return bitOf(s.img.X[n], b); }

class BasicJit : public ::testing::TestWithParam<jit::Tier> {};

TEST_P(BasicJit, LdExample43) {
  // hnc8-core.md 4.3: the second OUT R10.0 wins: R10.0 = (X5.0 | !X5.1 | X5.3) & X5.4.
  auto prog = compileOrFail("LDI X1.0\nANI X2.0\nANI R1.0\nOUT R10.0\nLD X5.0\nORI X5.1\n"
                            "OR X5.3\nAND X5.4\nOUT R10.0\n");
  ASSERT_TRUE(prog);
  Scenario d = exhaustive({{1, 0}, {2, 0}, {5, 0}, {5, 1}, {5, 3}, {5, 4}});
  EXPECT_TRUE(
      jitMatchesInterpreter(*prog, GetParam(), d, [](uint32_t, const lj_state &s, uint32_t) {
        int w2 = (x(s, 5, 0) | !x(s, 5, 1) | x(s, 5, 3)) & x(s, 5, 4);
        EXPECT_EQ(bitOf(s.img.R[10], 0), w2);
      }));
}

TEST_P(BasicJit, OutAndOoutExamples45And46) {
  // 4.5: R10.0 = R10.1 = (!R1.0 | !X5.0) & !G1.1; 4.6 (into R11): OUT (R1.0|X5.0)&G1.1,
  // OOUT its negation.
  auto prog = compileOrFail("LDI R1.0\nORI X5.0\nANI G1.1\nOUT R10.0\nOUT R10.1\n"
                            "LD R1.0\nOR X5.0\nAND G1.1\nOUT R11.0\nOOUT R11.1\n");
  ASSERT_TRUE(prog);
  Scenario d = exhaustive({{5, 0}});
  d.ticks = 16;
  auto inputs = d.hostInputs;
  d.hostInputs = [inputs](uint32_t t, lj_state &s) {
    inputs(t, s);
    s.img.R[1] = (t >> 1) & 1;                              // R1.0
    s.img.G[1] = static_cast<int16_t>(((t >> 2) & 1) << 1); // G1.1
  };
  EXPECT_TRUE(
      jitMatchesInterpreter(*prog, GetParam(), d, [](uint32_t, const lj_state &s, uint32_t) {
        int a = s.img.R[1] & 1, c = x(s, 5, 0), b = (s.img.G[1] >> 1) & 1;
        int w = (!a | !c) & !b;
        EXPECT_EQ(bitOf(s.img.R[10], 0), w);
        EXPECT_EQ(bitOf(s.img.R[10], 1), w);
        int v = (a | c) & b;
        EXPECT_EQ(bitOf(s.img.R[11], 0), v);
        EXPECT_EQ(bitOf(s.img.R[11], 1), !v);
      }));
}

TEST_P(BasicJit, SetAndRstExample47) {
  // 4.7: SET R10.0 := R10.0 | (R1.0 | X5.0); RST R10.1 := R10.1 & !(R1.0 | X5.0). Preset R10
  // to 0 and to 1 (through the tick pattern) as the reference asks.
  auto prog = compileOrFail("LD R1.0\nOR X5.0\nSET R10.0\nRST R10.1\n");
  ASSERT_TRUE(prog);
  Scenario d;
  d.ticks = 16;
  d.hostInputs = [](uint32_t t, lj_state &s) {
    s.img.R[1] = t & 1;
    s.img.X[5] = (t >> 1) & 1;
    s.img.R[10] = ((t >> 2) & 1) ? 0x3 : 0x0;
  };
  EXPECT_TRUE(
      jitMatchesInterpreter(*prog, GetParam(), d, [](uint32_t t, const lj_state &s, uint32_t) {
        int in = (t & 1) | ((t >> 1) & 1), old = (t >> 2) & 1;
        EXPECT_EQ(bitOf(s.img.R[10], 0), old | in);
        EXPECT_EQ(bitOf(s.img.R[10], 1), old & !in);
      }));
}

TEST_P(BasicJit, EdgeExample48) {
  // 4.8 multi-scan table: R10.1 = (rise R1.0 | fall X5.0) & rise R2.0 & fall R4.0.
  auto prog = compileOrFail("LDP R1.0\nORF X5.0\nANDP R2.0\nANDF R4.0\nOUT R10.1\n");
  ASSERT_TRUE(prog);
  struct Row {
    int r1, x5, r2, r4, out;
  };
  static const Row kTable[] = {
      {0, 0, 0, 1, 0}, {1, 0, 1, 0, 1}, {1, 0, 1, 0, 0}, {1, 1, 0, 1, 0}, {1, 0, 1, 0, 1}};
  Scenario d;
  d.ticks = 5;
  d.hostInputs = [](uint32_t t, lj_state &s) {
    s.img.R[1] = static_cast<uint8_t>(kTable[t].r1);
    s.img.X[5] = static_cast<uint8_t>(kTable[t].x5);
    s.img.R[2] = static_cast<uint8_t>(kTable[t].r2);
    s.img.R[4] = static_cast<uint8_t>(kTable[t].r4);
  };
  EXPECT_TRUE(
      jitMatchesInterpreter(*prog, GetParam(), d, [](uint32_t t, const lj_state &s, uint32_t) {
        EXPECT_EQ(bitOf(s.img.R[10], 1), kTable[t].out) << "scan " << t;
      }));
}

TEST_P(BasicJit, OrbExample49) {
  auto prog = compileOrFail("LD X1.0\nAND X2.0\nLD X1.1\nAND X2.1\nORB\nLD X1.2\nAND X2.2\n"
                            "ORB\nOUT R10.1\n");
  ASSERT_TRUE(prog);
  Scenario d = exhaustive({{1, 0}, {2, 0}, {1, 1}, {2, 1}, {1, 2}, {2, 2}});
  EXPECT_TRUE(
      jitMatchesInterpreter(*prog, GetParam(), d, [](uint32_t, const lj_state &s, uint32_t) {
        int want =
            (x(s, 1, 0) & x(s, 2, 0)) | (x(s, 1, 1) & x(s, 2, 1)) | (x(s, 1, 2) & x(s, 2, 2));
        EXPECT_EQ(bitOf(s.img.R[10], 1), want);
      }));
}

TEST_P(BasicJit, AnbExample49) {
  auto prog = compileOrFail("LD X1.0\nOR X1.1\nLD X2.0\nAND X4.4\nLD X1.2\nAND X2.1\nORB\n"
                            "OR X1.3\nANB\nOR X2.2\nOUT R10.0\n");
  ASSERT_TRUE(prog);
  Scenario d = exhaustive({{1, 0}, {1, 1}, {2, 0}, {4, 4}, {1, 2}, {2, 1}, {1, 3}, {2, 2}});
  EXPECT_TRUE(
      jitMatchesInterpreter(*prog, GetParam(), d, [](uint32_t, const lj_state &s, uint32_t) {
        int want = ((x(s, 1, 0) | x(s, 1, 1)) &
                    ((x(s, 2, 0) & x(s, 4, 4)) | (x(s, 1, 2) & x(s, 2, 1)) | x(s, 1, 3))) |
                   x(s, 2, 2);
        EXPECT_EQ(bitOf(s.img.R[10], 0), want);
      }));
}

TEST_P(BasicJit, MpsExample1) {
  auto prog = compileOrFail("LD X1.0\nMPS\nLD X1.1\nOR X1.2\nANB\nOUT Y1.0\nMRD\nLD X1.3\n"
                            "AND X1.4\nLD X1.5\nAND X1.6\nORB\nANB\nOUT Y0.2\nMPP\nAND X1.7\n"
                            "OUT Y0.3\nLD X2.3\nOR X2.4\nANB\nOUT Y0.4\n");
  ASSERT_TRUE(prog);
  Scenario d;
  d.ticks = 1024;
  d.hostInputs = [](uint32_t t, lj_state &s) {
    s.img.X[1] = static_cast<uint8_t>(t & 0xFF);
    s.img.X[2] = static_cast<uint8_t>(((t >> 8) & 3) << 3);
  };
  EXPECT_TRUE(
      jitMatchesInterpreter(*prog, GetParam(), d, [](uint32_t, const lj_state &s, uint32_t) {
        int a = x(s, 1, 0);
        EXPECT_EQ(bitOf(s.img.Y[1], 0), a & (x(s, 1, 1) | x(s, 1, 2)));
        EXPECT_EQ(bitOf(s.img.Y[0], 2),
                  a & ((x(s, 1, 3) & x(s, 1, 4)) | (x(s, 1, 5) & x(s, 1, 6))));
        EXPECT_EQ(bitOf(s.img.Y[0], 3), a & x(s, 1, 7));
        EXPECT_EQ(bitOf(s.img.Y[0], 4), a & x(s, 1, 7) & (x(s, 2, 3) | x(s, 2, 4)));
      }));
}

TEST_P(BasicJit, MpsExamples2And3) {
  auto prog = compileOrFail(
      "LD X1.0\nMPS\nAND X1.1\nMPS\nAND X1.2\nOUT Y1.0\nMPP\nAND X1.3\nOUT Y1.1\nMPP\n"
      "AND X1.4\nMPS\nAND X1.5\nOUT Y0.2\nMPP\nAND X1.6\nOUT Y2.0\n"
      // MPS-3 on X3 into Y3/Y4
      "LD X3.0\nMPS\nAND X3.1\nMPS\nAND X3.2\nMPS\nAND X3.3\nMPS\nAND X3.4\nOUT Y3.0\nMPP\n"
      "OUT Y3.1\nMPP\nOUT Y3.2\nMPP\nOUT Y4.0\nMPP\nOUT Y4.1\n");
  ASSERT_TRUE(prog);
  Scenario d;
  d.ticks = 128;
  d.hostInputs = [](uint32_t t, lj_state &s) {
    s.img.X[1] = static_cast<uint8_t>(t & 0x7F);
    s.img.X[3] = static_cast<uint8_t>((t * 37) & 0x1F);
  };
  EXPECT_TRUE(
      jitMatchesInterpreter(*prog, GetParam(), d, [](uint32_t, const lj_state &s, uint32_t) {
        int a = x(s, 1, 0);
        EXPECT_EQ(bitOf(s.img.Y[1], 0), a & x(s, 1, 1) & x(s, 1, 2));
        EXPECT_EQ(bitOf(s.img.Y[1], 1), a & x(s, 1, 1) & x(s, 1, 3));
        EXPECT_EQ(bitOf(s.img.Y[0], 2), a & x(s, 1, 4) & x(s, 1, 5));
        EXPECT_EQ(bitOf(s.img.Y[2], 0), a & x(s, 1, 4) & x(s, 1, 6));
        int c0 = x(s, 3, 0), c1 = c0 & x(s, 3, 1), c2 = c1 & x(s, 3, 2), c3 = c2 & x(s, 3, 3);
        EXPECT_EQ(bitOf(s.img.Y[3], 0), c3 & x(s, 3, 4));
        EXPECT_EQ(bitOf(s.img.Y[3], 1), c3);
        EXPECT_EQ(bitOf(s.img.Y[3], 2), c2);
        EXPECT_EQ(bitOf(s.img.Y[4], 0), c1);
        EXPECT_EQ(bitOf(s.img.Y[4], 1), c0);
      }));
}

TEST_P(BasicJit, ScanOrderTSeq) {
  // hnc8-core.md 4.10 T-SEQ (A): scan 1 gives R0.1 = R0.2 = 1, later scans R0.1 = 0, R0.2 = 1.
  auto prog = compileOrFail("LD X0.0\nANI R0.2\nOUT R0.1\nLD X0.0\nOUT R0.2\n");
  ASSERT_TRUE(prog);
  Scenario d;
  d.ticks = 4;
  d.hostInputs = [](uint32_t t, lj_state &s) { s.img.X[0] = t >= 1 ? 1 : 0; };
  EXPECT_TRUE(
      jitMatchesInterpreter(*prog, GetParam(), d, [](uint32_t t, const lj_state &s, uint32_t) {
        if (t == 1) {
          EXPECT_EQ(s.img.R[0], 0x6);
        }
        if (t >= 2) {
          EXPECT_EQ(s.img.R[0], 0x4);
        }
      }));
}

TEST_P(BasicJit, BitsOfEveryAreaWidth) {
  // DIALECT.md 1: bit k of element n is (value >> k) & 1, little-endian multi-byte elements;
  // coils write one bit of W/D/B/G and keep the others.
  auto prog = compileOrFail("LD F7.15\nOUT W3.15\nLD D2.31\nOUT B1.0\nLD P4.17\nOUT D9.30\n"
                            "LD W5.8\nOOUT G100.3\nLD Y2.7\nOUT R3.7\n");
  ASSERT_TRUE(prog);
  Scenario d;
  d.ticks = 64;
  d.hostBefore = [](lj_state &s) {
    s.img.W[3] = 0x1234;
    s.img.B[1] = -2;
    s.img.D[9] = 0x0F0F0F0F;
    s.img.G[100] = 0x00F0;
  };
  d.hostInputs = [](uint32_t t, lj_state &s) {
    s.img.F[7] = static_cast<int16_t>((t & 1) ? -1 : 1);
    s.img.D[2] = (t & 2) ? INT32_MIN : 5;
    s.img.P[4] = (t & 4) ? (1 << 17) : 0;
    s.img.W[5] = static_cast<int16_t>((t & 8) ? 0x100 : 0xFF);
    s.img.Y[2] = static_cast<uint8_t>((t & 16) ? 0x80 : 0x7F);
  };
  EXPECT_TRUE(
      jitMatchesInterpreter(*prog, GetParam(), d, [](uint32_t t, const lj_state &s, uint32_t) {
        EXPECT_EQ(static_cast<uint16_t>(s.img.W[3]), (t & 1) ? 0x9234 : 0x1234);
        EXPECT_EQ(s.img.B[1], (t & 2) ? -1 : -2);
        EXPECT_EQ(static_cast<uint32_t>(s.img.D[9]), (t & 4) ? 0x4F0F0F0Fu : 0x0F0F0F0Fu);
        EXPECT_EQ(s.img.G[100], (t & 8) ? 0x00F0 : 0x00F8);
        EXPECT_EQ(bitOf(s.img.R[3], 7), (t & 16) ? 1 : 0);
      }));
}

INSTANTIATE_TEST_SUITE_P(Tiers, BasicJit, ::testing::Values(jit::Tier::Fast, jit::Tier::Optimizing),
                         tierName);

} // namespace
} // namespace lj::test

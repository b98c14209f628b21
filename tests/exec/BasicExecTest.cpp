// hnc8-core.md section 4 worked examples (LD, LDI, OUT, OOUT, SET, RST, ORB, ANB, MPS-1/2/3,
// T-NO, T-NC, T-SEQ) over all input combinations. Every expected value is the formula printed
// next to the listing in the reference, evaluated here on the inputs.
#include "tests/exec/ExecTest.h"

namespace lj::test {
namespace {

class BasicExec : public ExecTest {};
LJ_EXEC_SUITE(BasicExec);

// hnc8-core.md 4.3, literal listing: R10.0 is written twice, the last write (W2) wins.
TEST_P(BasicExec, LdExampleLiteral) {
  auto m = load(R"(
LDI X1.0
ANI X2.0
ANI R1.0
OUT R10.0
LD  X5.0
ORI X5.1
OR  X5.3
AND X5.4
OUT R10.0
)");
  ASSERT_TRUE(m);
  forAllInputs(*m, {"X1.0", "X2.0", "R1.0", "X5.0", "X5.1", "X5.3", "X5.4"}, [&](const Inputs &v) {
    bool w2 = (v("X5.0") || !v("X5.1") || v("X5.3")) && v("X5.4");
    EXPECT_EQ(m->get("R10.0"), w2);
  });
}

// hnc8-core.md 4.3 with the second coil moved to R10.1 (the probable typo), so W1 is visible.
TEST_P(BasicExec, LdExampleBothOutputs) {
  auto m = load(R"(
LDI X1.0
ANI X2.0
ANI R1.0
OUT R10.0
LD  X5.0
ORI X5.1
OR  X5.3
AND X5.4
OUT R10.1
)");
  ASSERT_TRUE(m);
  forAllInputs(*m, {"X1.0", "X2.0", "R1.0", "X5.0", "X5.1", "X5.3", "X5.4"}, [&](const Inputs &v) {
    EXPECT_EQ(m->get("R10.0"), !v("X1.0") && !v("X2.0") && !v("R1.0"));
    EXPECT_EQ(m->get("R10.1"), (v("X5.0") || !v("X5.1") || v("X5.3")) && v("X5.4"));
  });
}

// hnc8-core.md 4.4.
TEST_P(BasicExec, LdiExample) {
  auto m = load(R"(
LDI R1.0
ANI R2.0
ANI R1.1
OUT R10.0
LDI X5.0
ORI X5.1
OR  X5.3
AND R5.4
OUT R10.1
)");
  ASSERT_TRUE(m);
  forAllInputs(*m, {"R1.0", "R2.0", "R1.1", "X5.0", "X5.1", "X5.3", "R5.4"}, [&](const Inputs &v) {
    EXPECT_EQ(m->get("R10.0"), !v("R1.0") && !v("R2.0") && !v("R1.1"));
    EXPECT_EQ(m->get("R10.1"), (!v("X5.0") || !v("X5.1") || v("X5.3")) && v("R5.4"));
  });
}

// hnc8-core.md 4.5: two coils on one result.
TEST_P(BasicExec, OutExample) {
  auto m = load(R"(
LDI R1.0
ORI X5.0
ANI G1.1
OUT R10.0
OUT R10.1
)");
  ASSERT_TRUE(m);
  forAllInputs(*m, {"R1.0", "X5.0", "G1.1"}, [&](const Inputs &v) {
    bool w = (!v("R1.0") || !v("X5.0")) && !v("G1.1");
    EXPECT_EQ(m->get("R10.0"), w);
    EXPECT_EQ(m->get("R10.1"), w);
  });
}

// hnc8-core.md 4.6: OOUT writes the inverse and does not invert ST0.
TEST_P(BasicExec, OoutExample) {
  auto m = load(R"(
LD   R1.0
OR   X5.0
AND  G1.1
OUT  R10.0
OOUT R10.1
OUT  R10.2
)");
  ASSERT_TRUE(m);
  forAllInputs(*m, {"R1.0", "X5.0", "G1.1"}, [&](const Inputs &v) {
    bool w = (v("R1.0") || v("X5.0")) && v("G1.1");
    EXPECT_EQ(m->get("R10.0"), w);
    EXPECT_EQ(m->get("R10.1"), !w);
    EXPECT_EQ(m->get("R10.2"), w); // ST0 unchanged after OOUT (4.6 table, row 5)
  });
}

// hnc8-core.md 4.7: SET and RST, each with R10.0 preset to 0 and to 1 and every combination of
// A = R1.0, B = X5.0; `expect(preset, A or B)` is the coil's value after the scan.
template <typename Expect> void coilExample(Machine &m, Expect expect) {
  for (int preset = 0; preset <= 1; ++preset) {
    for (uint32_t combo = 0; combo < 4; ++combo) {
      bool a = combo & 1, b = combo & 2;
      m.set("R1.0", a);
      m.set("X5.0", b);
      m.set("R10.0", preset);
      m.tick();
      SCOPED_TRACE("preset=" + std::to_string(preset) + " A=" + std::to_string(a) +
                   " B=" + std::to_string(b));
      EXPECT_EQ(m.get("R10.0"), expect(preset != 0, a || b));
    }
  }
}

TEST_P(BasicExec, SetExample) {
  auto m = load("LD R1.0\nOR X5.0\nSET R10.0\n");
  ASSERT_TRUE(m);
  coilExample(*m, [](bool preset, bool st0) { return preset || st0; });
}

TEST_P(BasicExec, RstExample) {
  auto m = load("LD R1.0\nOR X5.0\nRST R10.0\n");
  ASSERT_TRUE(m);
  coilExample(*m, [](bool preset, bool st0) { return preset && !st0; });
}

// hnc8-core.md 4.9, ORB example.
TEST_P(BasicExec, OrbExample) {
  auto m = load(R"(
LD  X1.0
AND X2.0
LD  X1.1
AND X2.1
ORB
LD  X1.2
AND X2.2
ORB
OUT R10.1
)");
  ASSERT_TRUE(m);
  forAllInputs(*m, {"X1.0", "X2.0", "X1.1", "X2.1", "X1.2", "X2.2"}, [&](const Inputs &v) {
    EXPECT_EQ(m->get("R10.1"),
              (v("X1.0") && v("X2.0")) || (v("X1.1") && v("X2.1")) || (v("X1.2") && v("X2.2")));
  });
}

// hnc8-core.md 4.9, ANB example (the only one using ST2).
TEST_P(BasicExec, AnbExample) {
  auto m = load(R"(
LD  X1.0
OR  X1.1
LD  X2.0
AND X4.4
LD  X1.2
AND X2.1
ORB
OR  X1.3
ANB
OR  X2.2
OUT R10.0
)");
  ASSERT_TRUE(m);
  forAllInputs(*m, {"X1.0", "X1.1", "X2.0", "X4.4", "X1.2", "X2.1", "X1.3", "X2.2"},
               [&](const Inputs &v) {
                 bool ab = v("X1.0") || v("X1.1");
                 bool rest = (v("X2.0") && v("X4.4")) || (v("X1.2") && v("X2.1")) || v("X1.3");
                 EXPECT_EQ(m->get("R10.0"), (ab && rest) || v("X2.2"));
               });
}

// hnc8-core.md 4.10 MPS-1: OUT leaves ST0, and the LD after OUT Y0.3 is combined with it.
TEST_P(BasicExec, Mps1Example) {
  auto m = load(R"(
LD  X1.0
MPS
LD  X1.1
OR  X1.2
ANB
OUT Y1.0
MRD
LD  X1.3
AND X1.4
LD  X1.5
AND X1.6
ORB
ANB
OUT Y0.2
MPP
AND X1.7
OUT Y0.3
LD  X2.3
OR  X2.4
ANB
OUT Y0.4
)");
  ASSERT_TRUE(m);
  forAllInputs(*m, {"X1.0", "X1.1", "X1.2", "X1.3", "X1.4", "X1.5", "X1.6", "X1.7", "X2.3", "X2.4"},
               [&](const Inputs &v) {
                 EXPECT_EQ(m->get("Y1.0"), v("X1.0") && (v("X1.1") || v("X1.2")));
                 EXPECT_EQ(m->get("Y0.2"),
                           v("X1.0") && ((v("X1.3") && v("X1.4")) || (v("X1.5") && v("X1.6"))));
                 EXPECT_EQ(m->get("Y0.3"), v("X1.0") && v("X1.7"));
                 EXPECT_EQ(m->get("Y0.4"), v("X1.0") && v("X1.7") && (v("X2.3") || v("X2.4")));
               });
}

// hnc8-core.md 4.10 MPS-2.
TEST_P(BasicExec, Mps2Example) {
  auto m = load(R"(
LD  X1.0
MPS
AND X1.1
MPS
AND X1.2
OUT Y1.0
MPP
AND X1.3
OUT Y1.1
MPP
AND X1.4
MPS
AND X1.5
OUT Y0.2
MPP
AND X1.6
OUT Y2.0
)");
  ASSERT_TRUE(m);
  forAllInputs(*m, {"X1.0", "X1.1", "X1.2", "X1.3", "X1.4", "X1.5", "X1.6"}, [&](const Inputs &v) {
    EXPECT_EQ(m->get("Y1.0"), v("X1.0") && v("X1.1") && v("X1.2"));
    EXPECT_EQ(m->get("Y1.1"), v("X1.0") && v("X1.1") && v("X1.3"));
    EXPECT_EQ(m->get("Y0.2"), v("X1.0") && v("X1.4") && v("X1.5"));
    EXPECT_EQ(m->get("Y2.0"), v("X1.0") && v("X1.4") && v("X1.6"));
  });
}

// hnc8-core.md 4.10 MPS-3: MS nested 4 deep.
TEST_P(BasicExec, Mps3Example) {
  auto m = load(R"(
LD  X1.0
MPS
AND X1.1
MPS
AND X1.2
MPS
AND X1.3
MPS
AND X1.4
OUT Y1.0
MPP
OUT Y1.1
MPP
OUT Y0.2
MPP
OUT Y2.0
MPP
OUT Y2.1
)");
  ASSERT_TRUE(m);
  forAllInputs(*m, {"X1.0", "X1.1", "X1.2", "X1.3", "X1.4"}, [&](const Inputs &v) {
    EXPECT_EQ(m->get("Y1.0"), v("X1.0") && v("X1.1") && v("X1.2") && v("X1.3") && v("X1.4"));
    EXPECT_EQ(m->get("Y1.1"), v("X1.0") && v("X1.1") && v("X1.2") && v("X1.3"));
    EXPECT_EQ(m->get("Y0.2"), v("X1.0") && v("X1.1") && v("X1.2"));
    EXPECT_EQ(m->get("Y2.0"), v("X1.0") && v("X1.1"));
    EXPECT_EQ(m->get("Y2.1"), v("X1.0"));
  });
}

// hnc8-core.md 4.10 T-NO and T-NC (element-page examples).
TEST_P(BasicExec, NormallyOpenContacts) {
  auto m = load("LD X0.1\nOR X0.4\nAND X0.2\nOUT R10.1\n");
  ASSERT_TRUE(m);
  forAllInputs(*m, {"X0.1", "X0.4", "X0.2"}, [&](const Inputs &v) {
    EXPECT_EQ(m->get("R10.1"), (v("X0.1") || v("X0.4")) && v("X0.2"));
  });
}

TEST_P(BasicExec, NormallyClosedContacts) {
  auto m = load("LDI X0.1\nORI X0.4\nAND X0.2\nOUT R10.1\n");
  ASSERT_TRUE(m);
  forAllInputs(*m, {"X0.1", "X0.4", "X0.2"}, [&](const Inputs &v) {
    EXPECT_EQ(m->get("R10.1"), (!v("X0.1") || !v("X0.4")) && v("X0.2"));
  });
}

// hnc8-core.md 4.10 T-SEQ (A): a coil is visible at once to later rungs and to earlier rungs
// on the next scan. Scan 0 all inputs 0; X0.0 = 1 from scan 1 on.
TEST_P(BasicExec, SequenceA) {
  auto m = load("LD X0.0\nANI R0.2\nOUT R0.1\nLD X0.0\nOUT R0.2\n");
  ASSERT_TRUE(m);
  m->tick();
  EXPECT_EQ(m->get("R0.1"), 0);
  EXPECT_EQ(m->get("R0.2"), 0);
  m->set("X0.0", 1);
  m->tick(); // scan 1
  EXPECT_EQ(m->get("R0.1"), 1);
  EXPECT_EQ(m->get("R0.2"), 1);
  for (int scan = 2; scan < 6; ++scan) {
    m->tick();
    EXPECT_EQ(m->get("R0.1"), 0) << "scan " << scan;
    EXPECT_EQ(m->get("R0.2"), 1) << "scan " << scan;
  }
}

// hnc8-core.md 4.10 T-SEQ (B): R0.1 never turns on.
TEST_P(BasicExec, SequenceB) {
  auto m = load("LD X0.0\nOUT R0.2\nLD X0.0\nANI R0.2\nOUT R0.1\n");
  ASSERT_TRUE(m);
  m->tick();
  m->set("X0.0", 1);
  for (int scan = 1; scan < 6; ++scan) {
    m->tick();
    EXPECT_EQ(m->get("R0.1"), 0) << "scan " << scan;
    EXPECT_EQ(m->get("R0.2"), 1) << "scan " << scan;
  }
}

// DIALECT.md 1: bit k of a multi-byte element is (value >> k) & 1, little-endian; contacts and
// coils work on W/D/B bits above the first byte.
TEST_P(BasicExec, WideElementBits) {
  auto m = load("LD W3.15\nOUT D7.31\nLD D2.9\nOUT W4.8\nLD B1.31\nOOUT B2.17\n");
  ASSERT_TRUE(m);
  m->set("W3", -32768); // 0x8000: bit 15
  m->set("D2", 1 << 9);
  m->set("B1", INT32_MIN);
  m->tick();
  EXPECT_EQ(m->get("D7"), INT32_MIN);
  EXPECT_EQ(m->get("W4"), 1 << 8);
  EXPECT_EQ(m->get("B2"), 0);
  m->set("B1", 0);
  m->tick();
  EXPECT_EQ(m->get("B2"), 1 << 17);
}

} // namespace
} // namespace lj::test

// The worked IL examples of modicon-neza.md section 10 (E1-E20, E23), each with the expected
// result the reference states, on every registered engine (interp, jit, aot). Line numbers
// "Lnnn" are the seed's, as the reference cites them. E21/E22 (the %C8 counter block) are in
// IecBlocksTest.cpp.
#include "tests/iec/IecTest.h"

namespace lj::test {
namespace {

class IecExamples : public IecExec {};
LJ_IEC_SUITE(IecExamples);

// E1 (L447-449): Q0.4 = I0.5 + I0.4.
TEST_P(IecExamples, E1Or) {
  auto m = load("LD %I0.5\nOR %I0.4\nST %Q0.4\n");
  ASSERT_TRUE(m);
  forAll(*m, {"%I0.5", "%I0.4"},
         [&](auto in) { EXPECT_EQ(get(*m, "%Q0.4"), in("%I0.5") || in("%I0.4")); });
}

// E2 (L485-489): unconditional coil and operation with LD 1, then JMP %L6 every scan.
TEST_P(IecExamples, E2UnconditionalRungsAndJump) {
  auto m = load("LD 1\nST %Q0.4\nLD 1\n[%MW5 := 0]\nJMP %L6\nLD 1\nST %Q0.0\n%L6 :\n"
                "LD %I0.0\nST %Q0.1\n");
  ASSERT_TRUE(m);
  set(*m, "%MW5", 7);
  set(*m, "%I0.0", 1);
  m->tick();
  EXPECT_EQ(get(*m, "%Q0.4"), 1);
  EXPECT_EQ(get(*m, "%MW5"), 0);
  EXPECT_EQ(get(*m, "%Q0.0"), 0) << "the rung between JMP and %L6 is skipped";
  EXPECT_EQ(get(*m, "%Q0.1"), 1);
}

// E3 (L553-555): Q0.0 = I0.0 . I0.1.
TEST_P(IecExamples, E3And) {
  auto m = load("LD %I0.0\nAND %I0.1\nST %Q0.0\n");
  ASSERT_TRUE(m);
  forAll(*m, {"%I0.0", "%I0.1"},
         [&](auto in) { EXPECT_EQ(get(*m, "%Q0.0"), in("%I0.0") && in("%I0.1")); });
}

// E4 (L591-594, L599) as printed: with M0 held at 1, (M11, M10) per scan = (1,1), (0,0),
// (1,1), (0,0): M11 oscillates every other scan (the reference's oracle test, 12.5).
TEST_P(IecExamples, E4PrintedEdgeExampleOscillates) {
  auto m = load("LD %M0\nANDN %M10\nST %M11\nLD %M11\nST %M10\n");
  ASSERT_TRUE(m);
  set(*m, "%M0", 1);
  const int expected[][2] = {{1, 1}, {0, 0}, {1, 1}, {0, 0}, {1, 1}, {0, 0}};
  for (int scan = 0; scan < 6; ++scan) {
    m->tick();
    EXPECT_EQ(get(*m, "%M11"), expected[scan][0]) << "scan " << scan;
    EXPECT_EQ(get(*m, "%M10"), expected[scan][1]) << "scan " << scan;
  }
}

// E4 with the fix of the reference (LD %M0 in the second rung): (1,1), (0,1), (0,1)...
TEST_P(IecExamples, E4FixedDetectsTheEdgeOnce) {
  auto m = load("LD %M0\nANDN %M10\nST %M11\nLD %M0\nST %M10\n");
  ASSERT_TRUE(m);
  set(*m, "%M0", 1);
  const int expected[][2] = {{1, 1}, {0, 1}, {0, 1}, {0, 1}};
  for (int scan = 0; scan < 4; ++scan) {
    m->tick();
    EXPECT_EQ(get(*m, "%M11"), expected[scan][0]) << "scan " << scan;
    EXPECT_EQ(get(*m, "%M10"), expected[scan][1]) << "scan " << scan;
  }
}

// E5 (L644-651): Q0.3 = I0.1; Q0.2 = not M0; Q0.4 = rising I0.2 for one scan; Q0.5 = falling
// I0.3 for one scan (L556-558, timing diagrams L570-590).
TEST_P(IecExamples, E5Loads) {
  auto m = load("LD %I0.1\nST %Q0.3\nLDN %M0\nST %Q0.2\nLDR %I0.2\nST %Q0.4\nLDF %I0.3\n"
                "ST %Q0.5\n");
  ASSERT_TRUE(m);
  // I0.2: 0 1 1 0 1; I0.3: 0 1 1 0 0 -> Q0.4: 0 1 0 0 1; Q0.5: 0 0 0 1 0.
  const int i02[] = {0, 1, 1, 0, 1}, i03[] = {0, 1, 1, 0, 0};
  const int q04[] = {0, 1, 0, 0, 1}, q05[] = {0, 0, 0, 1, 0};
  for (int scan = 0; scan < 5; ++scan) {
    set(*m, "%I0.2", i02[scan]);
    set(*m, "%I0.3", i03[scan]);
    set(*m, "%I0.1", scan & 1);
    set(*m, "%M0", scan == 2);
    m->tick();
    SCOPED_TRACE("scan " + std::to_string(scan));
    EXPECT_EQ(get(*m, "%Q0.4"), q04[scan]);
    EXPECT_EQ(get(*m, "%Q0.5"), q05[scan]);
    EXPECT_EQ(get(*m, "%Q0.3"), scan & 1);
    EXPECT_EQ(get(*m, "%Q0.2"), scan != 2);
  }
}

// L581-582: after a cold or warm start a rising edge is seen even if the input stayed at 1
// (the previous-scan image starts at 0).
TEST_P(IecExamples, ColdStartSeesARisingEdge) {
  auto m = load("LDR %I0.2\nST %Q0.4\n");
  ASSERT_TRUE(m);
  set(*m, "%I0.2", 1);
  m->tick();
  EXPECT_EQ(get(*m, "%Q0.4"), 1);
  m->tick();
  EXPECT_EQ(get(*m, "%Q0.4"), 0);
}

// E6 (L718-723): Q0.3 = I0.1; Q0.2 = not I0.1; Q0.4 set by I0.1, reset by I0.2; reset wins.
TEST_P(IecExamples, E6Stores) {
  auto m = load("LD %I0.1\nST %Q0.3\nSTN %Q0.2\nS %Q0.4\nLD %I0.2\nR %Q0.4\n");
  ASSERT_TRUE(m);
  struct Step {
    int i01, i02, q04;
  };
  const Step steps[] = {{0, 0, 0}, {1, 0, 1}, {0, 0, 1}, {0, 1, 0},
                        {0, 0, 0}, {1, 1, 0}, {1, 0, 1}};
  for (const Step &s : steps) {
    set(*m, "%I0.1", s.i01);
    set(*m, "%I0.2", s.i02);
    m->tick();
    EXPECT_EQ(get(*m, "%Q0.3"), s.i01);
    EXPECT_EQ(get(*m, "%Q0.2"), !s.i01);
    EXPECT_EQ(get(*m, "%Q0.4"), s.q04) << "I0.1=" << s.i01 << " I0.2=" << s.i02;
  }
}

// E7 (L749-760): Q0.3 = I0.1.M1; Q0.2 = M2.not I0.2; Q0.4 set on I0.3.rising I0.4; Q0.5 set on
// M3.falling I0.5.
TEST_P(IecExamples, E7AndFamily) {
  auto m = load("LD %I0.1\nAND %M1\nST %Q0.3\nLD %M2\nANDN %I0.2\nST %Q0.2\nLD %I0.3\n"
                "ANDR %I0.4\nS %Q0.4\nLD %M3\nANDF %I0.5\nS %Q0.5\n");
  ASSERT_TRUE(m);
  forAll(*m, {"%I0.1", "%M1", "%M2", "%I0.2"}, [&](auto in) {
    EXPECT_EQ(get(*m, "%Q0.3"), in("%I0.1") && in("%M1"));
    EXPECT_EQ(get(*m, "%Q0.2"), in("%M2") && !in("%I0.2"));
  });
  // Rising I0.4 without I0.3 sets nothing; with I0.3 it sets Q0.4.
  set(*m, "%I0.4", 1);
  m->tick();
  EXPECT_EQ(get(*m, "%Q0.4"), 0);
  set(*m, "%I0.4", 0);
  m->tick();
  set(*m, "%I0.3", 1);
  m->tick();
  EXPECT_EQ(get(*m, "%Q0.4"), 0) << "I0.3 alone is no edge of I0.4";
  set(*m, "%I0.4", 1);
  m->tick();
  EXPECT_EQ(get(*m, "%Q0.4"), 1);
  // Falling I0.5 with M3 sets Q0.5.
  set(*m, "%M3", 1);
  set(*m, "%I0.5", 1);
  m->tick();
  EXPECT_EQ(get(*m, "%Q0.5"), 0);
  set(*m, "%I0.5", 0);
  m->tick();
  EXPECT_EQ(get(*m, "%Q0.5"), 1);
}

// E8 (L794-805): Q0.3 = I0.1+M1; Q0.2 = M2+not I0.2; Q0.4 set on M3+rising I0.4; Q0.5 set on
// falling I0.5 + falling I0.6.
TEST_P(IecExamples, E8OrFamily) {
  auto m = load("LD %I0.1\nOR %M1\nST %Q0.3\nLD %M2\nORN %I0.2\nST %Q0.2\nLD %M3\nORR %I0.4\n"
                "S %Q0.4\nLDF %I0.5\nORF %I0.6\nS %Q0.5\n");
  ASSERT_TRUE(m);
  forAll(*m, {"%I0.1", "%M1", "%M2", "%I0.2"}, [&](auto in) {
    EXPECT_EQ(get(*m, "%Q0.3"), in("%I0.1") || in("%M1"));
    EXPECT_EQ(get(*m, "%Q0.2"), in("%M2") || !in("%I0.2"));
  });
  EXPECT_EQ(get(*m, "%Q0.4"), 0);
  set(*m, "%I0.4", 1);
  m->tick();
  EXPECT_EQ(get(*m, "%Q0.4"), 1) << "rising I0.4 sets Q0.4 without M3";
  set(*m, "%I0.6", 1);
  m->tick();
  EXPECT_EQ(get(*m, "%Q0.5"), 0);
  set(*m, "%I0.6", 0);
  m->tick();
  EXPECT_EQ(get(*m, "%Q0.5"), 1) << "falling I0.6 alone sets Q0.5";
}

// E9 (L816, L821-822) and E10 (L839-844, the seed's expansion of XOR): Q0.3 = I0.1 xor M1.
TEST_P(IecExamples, E9Xor) {
  auto m = load("LD %I0.1\nXOR %M1\nST %Q0.3\n");
  ASSERT_TRUE(m);
  forAll(*m, {"%I0.1", "%M1"},
         [&](auto in) { EXPECT_EQ(get(*m, "%Q0.3"), in("%I0.1") != in("%M1")); });
}

TEST_P(IecExamples, E10XorExpansion) {
  auto m = load("LD %I0.1\nANDN %M1\nOR( %M1\nANDN %I0.1\n)\nST %Q0.3\n");
  ASSERT_TRUE(m);
  forAll(*m, {"%I0.1", "%M1"},
         [&](auto in) { EXPECT_EQ(get(*m, "%Q0.3"), in("%I0.1") != in("%M1")); });
}

// E11 (L860-865): Q0.2 = I0.1+M2; Q0.3 = not(I0.1+M2).M3.
TEST_P(IecExamples, E11Negate) {
  auto m = load("LD %I0.1\nOR %M2\nST %Q0.2\nN\nAND %M3\nST %Q0.3\n");
  ASSERT_TRUE(m);
  forAll(*m, {"%I0.1", "%M2", "%M3"}, [&](auto in) {
    EXPECT_EQ(get(*m, "%Q0.2"), in("%I0.1") || in("%M2"));
    EXPECT_EQ(get(*m, "%Q0.3"), !(in("%I0.1") || in("%M2")) && in("%M3"));
  });
}

// E12 (L893-896): no precedence, (I0.0.I0.1)+I0.2.
TEST_P(IecExamples, E12LeftToRight) {
  auto m = load("LD %I0.0\nAND %I0.1\nOR %I0.2\nST %Q0.0\n");
  ASSERT_TRUE(m);
  forAll(*m, {"%I0.0", "%I0.1", "%I0.2"}, [&](auto in) {
    EXPECT_EQ(get(*m, "%Q0.0"), (in("%I0.0") && in("%I0.1")) || in("%I0.2"));
  });
}

// E13 (L897-901): I0.0.(I0.1+I0.2).
TEST_P(IecExamples, E13AndParen) {
  auto m = load("LD %I0.0\nAND( %I0.1\nOR %I0.2\n)\nST %Q0.0\n");
  ASSERT_TRUE(m);
  forAll(*m, {"%I0.0", "%I0.1", "%I0.2"}, [&](auto in) {
    EXPECT_EQ(get(*m, "%Q0.0"), in("%I0.0") && (in("%I0.1") || in("%I0.2")));
  });
}

// E14 (L902-907): (I0.0.I0.1)+(I0.2.I0.3).
TEST_P(IecExamples, E14OrParen) {
  auto m = load("LD %I0.0\nAND %I0.1\nOR( %I0.2\nAND %I0.3\n)\nST %Q0.0\n");
  ASSERT_TRUE(m);
  forAll(*m, {"%I0.0", "%I0.1", "%I0.2", "%I0.3"}, [&](auto in) {
    EXPECT_EQ(get(*m, "%Q0.0"), (in("%I0.0") && in("%I0.1")) || (in("%I0.2") && in("%I0.3")));
  });
}

// E15 (L928-933): (I0.0.I0.1)+(not I0.2.I0.3).
TEST_P(IecExamples, E15OrNParen) {
  auto m = load("LD %I0.0\nAND %I0.1\nOR(N %I0.2\nAND %I0.3\n)\nST %Q0.0\n");
  ASSERT_TRUE(m);
  forAll(*m, {"%I0.0", "%I0.1", "%I0.2", "%I0.3"}, [&](auto in) {
    EXPECT_EQ(get(*m, "%Q0.0"), (in("%I0.0") && in("%I0.1")) || (!in("%I0.2") && in("%I0.3")));
  });
}

// E16 (L934, L941-946): I0.0.(I0.1+(not I0.2.M3)).
TEST_P(IecExamples, E16NestedParen) {
  auto m = load("LD %I0.0\nAND( %I0.1\nOR(N %I0.2\nAND %M3\n)\n)\nST %Q0.0\n");
  ASSERT_TRUE(m);
  forAll(*m, {"%I0.0", "%I0.1", "%I0.2", "%M3"}, [&](auto in) {
    EXPECT_EQ(get(*m, "%Q0.0"), in("%I0.0") && (in("%I0.1") || (!in("%I0.2") && in("%M3"))));
  });
}

// E17 (L948, L954-964): I0.1.(((I0.2.I0.3 + I0.5.I0.6).I0.4) + I0.7.I0.8).
TEST_P(IecExamples, E17DeepParen) {
  auto m = load("LD %I0.1\nAND( %I0.2\nAND %I0.3\nOR( %I0.5\nAND %I0.6\n)\nAND %I0.4\n"
                "OR( %I0.7\nAND %I0.8\n)\n)\nST %Q0.0\n");
  ASSERT_TRUE(m);
  forAll(*m, {"%I0.1", "%I0.2", "%I0.3", "%I0.4", "%I0.5", "%I0.6", "%I0.7", "%I0.8"},
         [&](auto in) {
           const bool inner =
               ((in("%I0.2") && in("%I0.3")) || (in("%I0.5") && in("%I0.6"))) && in("%I0.4");
           EXPECT_EQ(get(*m, "%Q0.0"), in("%I0.1") && (inner || (in("%I0.7") && in("%I0.8"))));
         });
}

// E18 (L1015-1028): Q0.k = I0.0.M0.I0.(k+1).
TEST_P(IecExamples, E18Mps) {
  auto m = load("LD %I0.0\nAND %M0\nMPS\nAND %I0.1\nST %Q0.0\nMRD\nAND %I0.2\nST %Q0.1\nMRD\n"
                "AND %I0.3\nST %Q0.2\nMPP\nAND %I0.4\nST %Q0.3\n");
  ASSERT_TRUE(m);
  forAll(*m, {"%I0.0", "%M0", "%I0.1", "%I0.2", "%I0.3", "%I0.4"}, [&](auto in) {
    const bool pre = in("%I0.0") && in("%M0");
    EXPECT_EQ(get(*m, "%Q0.0"), pre && in("%I0.1"));
    EXPECT_EQ(get(*m, "%Q0.1"), pre && in("%I0.2"));
    EXPECT_EQ(get(*m, "%Q0.2"), pre && in("%I0.3"));
    EXPECT_EQ(get(*m, "%Q0.3"), pre && in("%I0.4"));
  });
}

// E19 (L1029-1045): a two-deep MPS stack.
TEST_P(IecExamples, E19TwoDeepMps) {
  auto m = load("LD %I0.0\nMPS\nAND %I0.1\nMPS\nAND( %I0.3\nOR %M0\n)\nST %Q0.0\nMPP\n"
                "ANDN %M1\nST %Q0.1\nMRD\nAND %I0.4\nST %Q0.2\nMPP\nAND %M10\nST %Q0.3\n");
  ASSERT_TRUE(m);
  forAll(*m, {"%I0.0", "%I0.1", "%I0.3", "%M0", "%M1", "%I0.4", "%M10"}, [&](auto in) {
    EXPECT_EQ(get(*m, "%Q0.0"), in("%I0.0") && in("%I0.1") && (in("%I0.3") || in("%M0")));
    EXPECT_EQ(get(*m, "%Q0.1"), in("%I0.0") && in("%I0.1") && !in("%M1"));
    EXPECT_EQ(get(*m, "%Q0.2"), in("%I0.0") && in("%I0.4"));
    EXPECT_EQ(get(*m, "%Q0.3"), in("%I0.0") && in("%M10"));
  });
}

// E20 (L1054, L1066-1072): OPEN (AND 0) gives Q0.1 = 0, SHORT (OR 1) gives Q1.6 = 1.
TEST_P(IecExamples, E20OpenShort) {
  auto m = load("LD %I0.0\nOR %Q1.5\nANDN %M3\nAND 0\nST %Q0.1\nLD %I0.9\nOR 1\nST %Q1.6\n");
  ASSERT_TRUE(m);
  forAll(*m, {"%I0.0", "%Q1.5", "%M3", "%I0.9"}, [&](auto) {
    EXPECT_EQ(get(*m, "%Q0.1"), 0);
    EXPECT_EQ(get(*m, "%Q1.6"), 1);
  });
}

// E23 (L581-582): `LD %S1 / ENDC` first suppresses the spurious rising edge of the first scan
// after a start: that scan ends at ENDC, the next one compares with the image it left.
TEST_P(IecExamples, E23StartBitSuppressesTheStartEdge) {
  auto m = load("LD %S1\nENDC\nLDR %I0.0\nST %Q0.0\nLD 1\nST %Q0.1\n");
  ASSERT_TRUE(m);
  set(*m, "%I0.0", 1);
  m->tick();
  EXPECT_EQ(get(*m, "%Q0.1"), 0) << "the first scan ended at ENDC";
  EXPECT_EQ(get(*m, "%S1"), 1) << "the runtime set %S1 for the first scan";
  m->tick();
  EXPECT_EQ(get(*m, "%S1"), 0) << "%S1 is 1 during the first scan only";
  EXPECT_EQ(get(*m, "%Q0.1"), 1);
  EXPECT_EQ(get(*m, "%Q0.0"), 0) << "I0.0 stayed at 1: no edge";
  set(*m, "%I0.0", 0);
  m->tick();
  set(*m, "%I0.0", 1);
  m->tick();
  EXPECT_EQ(get(*m, "%Q0.0"), 1);
}

} // namespace
} // namespace lj::test

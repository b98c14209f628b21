// Located errors for every restriction of the seed (modicon-neza.md 2.8, 2.9, 9, 12.2) and
// for broken IL; plus the warnings of the non-reversible forms (9 rule 3).
#include "pipeline/Compile.h"
#include "tests/iec/IecTest.h"

namespace lj::test {
namespace {

// Each case: program, the expected "line:col: error: text" fragment.
struct Case {
  const char *name, *program, *expected;
};

const Case kCases[] = {
    {"StInsideParentheses", "LD %I0.0\nAND( %I0.1\nST %Q0.0\n)\n",
     "test.il:3:1: error: ST inside parentheses (the AND( on line 2 is open)"},
    {"SetInsideParentheses", "LD %I0.0\nOR( %I0.1\nS %Q0.0\n)\n",
     "3:1: error: S inside parentheses"},
    {"NinthParenthesisLevel",
     "LD %I0.0\nAND( %I0.1\nAND( %I0.1\nAND( %I0.1\nAND( %I0.1\nAND( %I0.1\nAND( %I0.1\n"
     "AND( %I0.1\nAND( %I0.1\nAND( %I0.2\n)\n)\n)\n)\n)\n)\n)\n)\n)\nST %Q0.0\n",
     "10:1: error: AND( nests parentheses deeper than 8 levels"},
    {"NinthMps", "LD %I0.0\nMPS\nMPS\nMPS\nMPS\nMPS\nMPS\nMPS\nMPS\nMPS\nST %Q0.0\n",
     "10:1: error: MPS stack deeper than 8 entries"},
    {"MpsInsideParentheses", "LD %I0.0\nAND( %I0.1\nMPS\n)\nST %Q0.0\n",
     "3:1: error: MPS inside parentheses"},
    {"MrdWithoutMps", "LD %I0.0\nMRD\nST %Q0.0\n", "2:1: error: MRD without MPS"},
    {"MpsNotPopped", "LD %I0.0\nMPS\nST %Q0.0\nLD %I0.1\nST %Q0.1\n",
     "2:1: error: MPS has no MPP before LD (line 4)"},
    {"UnclosedParenthesis", "LD %I0.0\nAND( %I0.1\nLD %I0.2\nST %Q0.0\n",
     "3:1: error: LD inside parentheses"},
    {"UnclosedAtEnd", "LD %I0.0\nOR( %I0.1\n", "2:1: error: OR( is not closed by ')'"},
    {"CloseWithoutOpen", "LD %I0.0\n)\nST %Q0.0\n", "2:1: error: ')' without AND( or OR("},
    {"EdgeOnM32", "LDR %M32\nST %Q0.0\n",
     "1:5: error: LDR: edge instructions take only %I and %M0..%M31"},
    {"EdgeOnOutput", "LD %I0.0\nANDF %Q0.1\nST %Q0.0\n", "2:6: error: ANDF: edge instructions"},
    {"LdnImmediate", "LDN 1\nST %Q0.0\n", "1:5: error: LDN takes no immediate value"},
    {"XorImmediate", "LD %I0.0\nXOR 1\nST %Q0.0\n", "2:5: error: XOR takes no immediate value"},
    {"AndWithoutLd", "AND %I0.0\nST %Q0.0\n",
     "1:1: error: AND without a value to work on: a sequence starts with LD"},
    {"StoreToInput", "LD %M0\nST %I0.1\n", "2:4: error: ST needs a writable bit"},
    {"StoreToConstWord", "LD %M0\nST %KW1:X2\n", "2:4: error: ST needs a writable bit"},
    {"OperationWithoutCondition", "[%MW5 := 0]\n",
     "1:1: error: an operation block needs a condition: write LD 1"},
    {"LabelInsideParentheses", "LD %I0.0\nAND( %I0.1\n%L1 :\n)\n",
     "2:1: error: AND( is not closed by ')' before a label (line 3)"},
    {"JumpInsideParentheses", "LD %I0.0\nAND( %I0.1\nJMPC %L1\n)\n%L1 :\n",
     "3:1: error: JMPC inside parentheses"},
    {"CallInsideParentheses", "LD %I0.0\nOR( %I0.1\nSR1\n)\nEND\nSR1 :\nRET\n",
     "3:1: error: SR1 inside parentheses"},
    {"UnitOutOfRange", "LD %I4.0\nST %Q0.0\n", "1:4: error: LD: '%I4.0': unit 4 is out of range"},
    {"PointOutOfRange", "LD %I0.16\nST %Q0.0\n", "point 16 is out of range (0..15)"},
    {"MemoryOutOfRange", "LD %M128\nST %Q0.0\n", "bit number out of range (0..127)"},
    {"UnknownInstruction", "LDX %I0.0\n", "1:1: error: unknown instruction 'LDX'"},
    {"MissingLabel", "LD %I0.0\nJMPC %L3\n", "2:6: error: missing label %L3"},
    {"RegisterBlock", "LD %R0.F\nST %Q0.0\n", "1:4: error: LD: '%R0.F': the function blocks %Ri"},
    {"OrComparison", "LD %I0.0\nOR [%MW1<3]\nST %Q0.0\n", "2:4: error: OR takes no comparison"},
    {"CodeAfterEnd", "LD %I0.0\nST %Q0.0\nEND\nLD %I0.1\nST %Q0.1\n",
     "4:1: error: instruction after END outside a subroutine"},
    {"RetOutsideSub", "LD %I0.0\nRETC\n", "2:1: error: RETC outside a subroutine"},
    {"DuplicateLabel", "%L2 :\nLD %I0.0\nST %Q0.0\n%L2 :\n", "4:1: error: duplicate label %L2"},
    {"UnclosedComment", "LD %I0.0 (* open\nST %Q0.0\n", "1:10: error: comment '(*' is not closed"},
};

class IecErrors : public ::testing::TestWithParam<Case> {};

TEST_P(IecErrors, IsLocated) {
  const std::string out = ilErrors(GetParam().program);
  EXPECT_NE(out.find(GetParam().expected), std::string::npos) << out;
}

INSTANTIATE_TEST_SUITE_P(Seed, IecErrors, ::testing::ValuesIn(kCases),
                         [](const ::testing::TestParamInfo<Case> &i) { return i.param.name; });

// The non-reversible forms compile, with a warning each (modicon-neza.md 9 rule 3).
TEST(IecWarnings, NonReversibleForms) {
  Diagnostics diags("test.il");
  auto p =
      pipeline::compileIl("LD %I0.0\nN\nXORN %M1\nJMPCN %L1\nST %Q0.0\n%L1 :\nLD %I0.1\nENDCN\n",
                          "test.il", VerifyOptions{}, diags);
  ASSERT_TRUE(p.has_value()) << diags.render();
  const std::string out = diags.render();
  for (const char *w :
       {"2:1: warning: N is not reversible", "3:1: warning: XORN is not reversible",
        "4:1: warning: JMPCN is not reversible", "8:1: warning: ENDCN is not reversible"})
    EXPECT_NE(out.find(w), std::string::npos) << w << "\n" << out;
}

// Line numbers, comments and case: `003 ld %i0.1 (* start *)` is LD %I0.1.
TEST(IecSyntax, NumbersCommentsAndCase) {
  Diagnostics diags("test.il");
  auto p = pipeline::compileIl("(* title *)\n001 ld %i0.1 (* start *)\n002 st %q0.3\n", "test.il",
                               VerifyOptions{}, diags);
  ASSERT_TRUE(p.has_value()) << diags.render();
  EXPECT_EQ(diags.render(), "");
  ASSERT_EQ(p->comments.size(), 2u);
  EXPECT_EQ(p->comments[0].text, "title");
  EXPECT_EQ(p->comments[1].text, "start");
  EXPECT_TRUE(p->comments[1].trailing);
}

// A comment over several lines keeps every line's text (the last one, before `*)`, was lost).
TEST(IecSyntax, CommentOverSeveralLines) {
  Diagnostics diags("test.il");
  auto p =
      pipeline::compileIl("(* first\n   second\n   third *)\nLD %I0.0\nST %Q0.0 (* t1\nt2 *)\n",
                          "test.il", VerifyOptions{}, diags);
  ASSERT_TRUE(p.has_value()) << diags.render();
  ASSERT_EQ(p->comments.size(), 5u);
  const char *text[] = {"first", "second", "third", "t1", "t2"};
  for (size_t k = 0; k < 5; ++k) EXPECT_EQ(p->comments[k].text, text[k]) << k;
  EXPECT_TRUE(p->comments[3].trailing);
  EXPECT_FALSE(p->comments[4].trailing);
}

} // namespace
} // namespace lj::test

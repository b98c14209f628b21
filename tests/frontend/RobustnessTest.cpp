// Robustness: the front end never crashes or hangs on any byte input (DIALECT.md 6: "never a
// crash"), and every program it accepts satisfies the invariants of Program.h.
#include "FrontEndTestUtil.h"
#include "frontends/hnc8/Mnemonics.h"
#include "pipeline/Compile.h"

#include <gtest/gtest.h>

#include <random>

namespace lj {
namespace {

/// Structural invariants every verified program must satisfy (Program.h comments).
void checkInvariants(const VerifiedProgram &p, const std::string &text) {
  const auto n = static_cast<int32_t>(p.stmts.size());
  ASSERT_EQ(p.info.size(), p.stmts.size()) << text;
  ASSERT_FALSE(p.slices.empty()) << text;
  ASSERT_EQ(p.slices.size(), p.sliceDepth.size()) << text;
  EXPECT_EQ(p.slices.front().begin, p.plc2.begin) << text;
  EXPECT_EQ(p.slices.back().end, p.plc2.end) << text;
  for (size_t k = 1; k < p.slices.size(); ++k) {
    EXPECT_EQ(p.slices[k].begin, p.slices[k - 1].end) << text;
    EXPECT_FALSE(p.slices[k].empty()) << text;
  }
  EXPECT_LE(p.edgeSlots, 16384);
  for (int32_t i = 0; i < n; ++i) {
    const StmtInfo &in = p.info[static_cast<size_t>(i)];
    const Stmt &s = p.stmts[static_cast<size_t>(i)];
    EXPECT_GE(in.depth, 0);
    EXPECT_GE(in.msDepth, 0);
    EXPECT_LE(in.depth, p.maxDepth);
    EXPECT_LE(in.msDepth, p.maxMsDepth);
    if (s.op == Op::Jump) {
      ASSERT_GE(in.target, 0) << text;
      ASSERT_LT(in.target, n);
      EXPECT_EQ(p.stmts[static_cast<size_t>(in.target)].op, Op::Label);
      EXPECT_EQ(in.backward, in.target < i);
    }
    if (s.op == Op::LoopBegin || s.op == Op::LoopEnd) {
      ASSERT_GE(in.target, 0) << text;
      EXPECT_EQ(p.info[static_cast<size_t>(in.target)].target, i);
    }
    if (s.op == Op::Call) {
      ASSERT_GE(in.target, 0);
      ASSERT_LT(in.target, static_cast<int32_t>(p.subs.size()));
    }
  }
}

void runOne(const std::string &text) {
  Diagnostics d("r.stl");
  auto prog = pipeline::compileStl(text, "r.stl", {}, d);
  for (const Diagnostic &x : d.all()) {
    EXPECT_GE(x.loc.line, 1);
    EXPECT_GE(x.loc.col, 1);
  }
  EXPECT_EQ(prog.has_value(), !d.hasErrors());
  if (prog) {
    checkInvariants(*prog, text);
    (void)printProgram(*prog);
  }
  (void)d.render();
}

// Arbitrary bytes, biased toward characters the lexer cares about.
TEST(Robustness, RandomBytes) {
  std::mt19937_64 rng(0x5eed1234);
  static const char kAlphabet[] = "LDANOTXYRWDS0123456789.-+x \t\n;/\r\0\xff\xc3";
  const std::string alphabet(kAlphabet, sizeof kAlphabet - 1);
  for (int iter = 0; iter < 3000; ++iter) {
    std::string text(rng() % 400, '\0');
    bool raw = iter % 3 == 0;
    for (char &c : text) c = raw ? static_cast<char>(rng()) : alphabet[rng() % alphabet.size()];
    runOne(text);
  }
}

// Random statements from the instruction table with plausible operands: exercises the verifier
// on many structurally different programs, valid and invalid.
TEST(Robustness, RandomTokenPrograms) {
  std::mt19937_64 rng(42);
  const char *operands[] = {"X1.0", "Y0.1", "R3.7", "D5", "D6", "L1",   "L2",   "S1",
                            "S2",   "S3",   "5",    "0",  "-1", "T5.0", "C1.0", "W2",
                            "0x10", "300",  "2",    "1",  "P3", "G7.15"};
  auto table = hnc8::mnemonicTable();
  for (int iter = 0; iter < 3000; ++iter) {
    std::string text;
    int lines = static_cast<int>(rng() % 40);
    for (int l = 0; l < lines; ++l) {
      const hnc8::MnemonicRow &row = table[rng() % table.size()];
      text += row.spelling;
      int ops = instrInfo(row.op).operandCount + (rng() % 10 == 0 ? 1 : 0);
      for (int k = 0; k < ops; ++k) {
        text += ' ';
        text += operands[rng() % std::size(operands)];
      }
      text += '\n';
    }
    runOne(text);
  }
}

TEST(Robustness, EmbeddedNulsAndInvalidUtf8) {
  runOne(std::string("LD X1.0\0\nOUT Y0.0\n", 18));
  runOne("\xc3\x28 \xa0\xa1\n\xf0\x28\x8c\xbc LD\n");
  runOne(std::string(1000, '\0'));
}

TEST(Robustness, HugeNumbersAndLongLines) {
  runOne("LD X99999999999999999999999999999999999999.99999999999999999999\n");
  runOne("MOV -99999999999999999999999999999999 D0\n");
  runOne("MOV 0x" + std::string(10000, 'F') + " D0\n");
  runOne("LD X1.0 " + std::string(1 << 20, ' ') + "X2.0\n");
  runOne(std::string(1 << 20, 'A'));
  std::string many;
  for (int i = 0; i < 2000; ++i) many += "LD X1.0 X1.0 X1.0\n";
  runOne(many);
}

// Deep structures must not recurse natively: 5000 nested loops, 512 chained subroutines.
TEST(Robustness, DeepNesting) {
  std::string loops;
  for (int i = 0; i < 5000; ++i) loops += "LOOP 1\n";
  for (int i = 0; i < 5000; ++i) loops += "NEXT\n";
  runOne(loops);
  std::string subs = "CALL S0\n2END\n";
  for (int s = 0; s < 512; ++s)
    subs += "SP S" + std::to_string(s) + "\nCALL S" + std::to_string((s + 1) % 512) + "\nSPE\n";
  runOne(subs);
}

} // namespace
} // namespace lj

namespace lj {
namespace {

// A line that ends in a CR alone is refused by every dialect's compile (LJ0001), not only by the
// commands' file reading: libFuzzer's fuzz_il found `LD <CR><CR>...0` accepted by
// pipeline::compileIl as one line whose network JSON did not read back.
TEST(Robustness, BareCarriageReturnRefusedByEveryCompile) {
  const VerifyOptions opts;
  struct Case {
    std::optional<VerifiedProgram> (*compile)(std::string_view, std::string, const VerifyOptions &,
                                              Diagnostics &, const SymbolTable *);
    const char *text;
  };
  for (const Case &c : {Case{pipeline::compileStl, "LD X0.0\rOUT Y0.0\n"},
                        Case{pipeline::compilePmc, "RD X0.0\rWRT Y0.0\nEND1\nEND2\nEND\n"},
                        Case{pipeline::compileIl, "LD \r\r0\nLDR %I0.4\n"},
                        Case{pipeline::compileClp, "_FILES_CLASSICLADDER\r\n\r_END\n"}}) {
    Diagnostics d("t");
    EXPECT_FALSE(c.compile(c.text, "t", opts, d, nullptr)) << c.text;
    EXPECT_NE(d.render().find(
                  "a carriage return (CR) without a line feed: lines must end with LF or CRLF, "
                  "not with CR alone [LJ0001]"),
              std::string::npos)
        << d.render();
  }
  // CRLF line ends are fine.
  Diagnostics d("t");
  EXPECT_TRUE(pipeline::compileStl("LD X0.0\r\nOUT Y0.0\r\n", "t", opts, d, nullptr)) << d.render();
}

} // namespace
} // namespace lj

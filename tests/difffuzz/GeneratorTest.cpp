// The program generators: every generated program verifies, a batch of random programs uses
// every row of the instruction table, generation is deterministic, the realistic mix matches its
// description, and the stimulus applies and prints in the CLI format.
#include "frontends/hnc8/FrontEnd.h"
#include "frontends/hnc8/Mnemonics.h"
#include "gen/ProgramGenerator.h"
#include "ir/OpTable.h"
#include "pipeline/Compile.h"

#include <gtest/gtest.h>

#include <set>

namespace lj::gen {
namespace {

std::optional<VerifiedProgram> frontEnd(const GenProgram &p, Diagnostics &d,
                                        int32_t maxStatements = 10000) {
  VerifyOptions vo;
  vo.plc2Nvalue = p.plc2Nvalue;
  vo.maxStatements = maxStatements;
  return pipeline::compileStl(p.text(), "gen.stl", vo, d);
}

TEST(RealisticGenerator, EverySizeVerifiesWithTheExactStatementCount) {
  for (int n : {1000, 5000, 10000}) {
    for (uint64_t seed : {1u, 2u, 3u}) {
      RealisticOptions o;
      o.seed = seed;
      o.statements = n;
      GenProgram p = generateRealistic(o);
      EXPECT_EQ(static_cast<int>(p.lines.size()), n);
      Diagnostics d;
      // DIALECT.md 6: the 10,000-statement limit counts every statement, so 10k still fits.
      auto v = frontEnd(p, d);
      ASSERT_TRUE(v.has_value()) << "n=" << n << " seed=" << seed << "\n" << d.render();
      EXPECT_EQ(static_cast<int>(v->stmts.size()), n);
    }
  }
}

TEST(RealisticGenerator, MixAndPartsAsSpecified) {
  RealisticOptions o;
  o.statements = 10000;
  GenProgram p = generateRealistic(o);
  Diagnostics d;
  auto v = frontEnd(p, d);
  ASSERT_TRUE(v.has_value()) << d.render();
  int bit = 0, blocks = 0;
  for (const Stmt &s : v->stmts) {
    const InstrInfo &in = instrInfo(s.op);
    if (in.stack == StackRule::Structural) continue;
    (in.stack == StackRule::Block ? blocks : bit)++;
  }
  // The brief: about 70% bit logic, 30% function blocks.
  double share = static_cast<double>(bit) / (bit + blocks);
  EXPECT_GT(share, 0.62);
  EXPECT_LT(share, 0.78);
  // PLC1 ~10% and PLC2 ~90% of the cyclic code, plus an init part and subroutines.
  int plc1 = v->plc1.end - v->plc1.begin, plc2 = v->plc2.end - v->plc2.begin;
  EXPECT_NEAR(static_cast<double>(plc1) / (plc1 + plc2), 0.10, 0.02);
  EXPECT_FALSE(v->init.empty());
  EXPECT_GE(v->subs.size(), 2u);
  EXPECT_GT(v->slices.size(), 10u); // PLC2 of ~8,500 statements in slices of >= 200
}

TEST(RandomGenerator, EveryProgramVerifies) {
  int failures = 0;
  for (uint64_t seed = 1; seed <= 600; ++seed) {
    RandomOptions o;
    o.seed = seed;
    o.statements = static_cast<int32_t>(10 + seed % 150);
    GenProgram p = generateRandom(o);
    Diagnostics d;
    if (!frontEnd(p, d)) {
      if (++failures <= 3)
        ADD_FAILURE() << "seed " << seed << " does not verify:\n"
                      << d.render() << "--- program ---\n"
                      << p.text();
    }
  }
  EXPECT_EQ(failures, 0);
}

TEST(RandomGenerator, ABatchCoversEveryRowOfTheTable) {
  std::set<Op> seen;
  for (uint64_t seed = 1; seed <= 200; ++seed) {
    RandomOptions o;
    o.seed = seed * 7919;
    o.statements = 80;
    Diagnostics d;
    ParsedProgram pp = parseStl(generateRandom(o).text(), "gen.stl", d);
    EXPECT_FALSE(d.hasErrors()) << d.render();
    for (const Stmt &s : pp.stmts) seen.insert(s.op);
  }
  for (const InstrInfo &in : instrTable())
    if (hnc8::spells(in.op)) { // the HNC-8 generator: rows HNC-8 spells
      EXPECT_TRUE(seen.count(in.op)) << hnc8::mnemonicOf(in.op) << " never generated";
    }
}

TEST(RandomGenerator, LongRangesReachTheLoweringLoops) {
  // lowering/EmitData.cpp turns ranges of more than 32 elements into loops; the generator must
  // give every looping form now and then, and such programs must still verify (VerifyData.cpp).
  enum { BmovUp, BmovDown, BmovApart, Fmov, ZrstWord, ZrstBits, Ser, Cod, Kinds };
  const char *names[Kinds] = {"BMOV overlapping upward",
                              "BMOV overlapping downward",
                              "BMOV in separate ranges",
                              "FMOV",
                              "ZRST word form",
                              "ZRST bit form",
                              "SER",
                              "COD"};
  int count[Kinds] = {};
  int failures = 0;
  for (uint64_t seed = 1; seed <= 2000; ++seed) {
    RandomOptions o;
    o.seed = seed;
    o.statements = 40;
    GenProgram p = generateRandom(o);
    Diagnostics d;
    auto v = frontEnd(p, d);
    if (!v) {
      if (++failures <= 3) ADD_FAILURE() << "seed " << seed << ":\n" << d.render();
      continue;
    }
    for (const Stmt &s : v->stmts) {
      const Operand &a = s.ops[0], &b = s.ops[1];
      switch (s.op) {
      case Op::BlockMove: {
        const int32_t n = s.ops[2].value;
        if (n <= 32) break;
        const bool same = a.area == b.area;
        if (same && b.index > a.index && b.index - a.index < n)
          ++count[BmovUp];
        else if (same && b.index < a.index && a.index - b.index < n)
          ++count[BmovDown];
        else
          ++count[BmovApart];
        break;
      }
      case Op::Fill:
        count[Fmov] += b.index - a.index + 1 > 32;
        break;
      case Op::ZoneReset:
        // Bit form: the whole elements strictly between the two bounds' elements.
        if (a.kind == Operand::Kind::Bit)
          count[ZrstBits] += b.index - a.index - 1 > 32;
        else
          count[ZrstWord] += b.index - a.index + 1 > 32;
        break;
      case Op::TableSearch:
        count[Ser] += s.ops[1].value > 32;
        break;
      case Op::TableLookup:
        count[Cod] += s.ops[1].value > 32;
        break;
      default:
        break;
      }
    }
  }
  EXPECT_EQ(failures, 0);
  for (int k = 0; k < Kinds; ++k) EXPECT_GE(count[k], 2) << names[k] << " longer than 32";
}

TEST(RandomGenerator, SameSeedSameProgram) {
  RandomOptions o;
  o.seed = 42;
  EXPECT_EQ(generateRandom(o).text(), generateRandom(o).text());
  RandomOptions other = o;
  other.seed = 43;
  EXPECT_NE(generateRandom(o).text(), generateRandom(other).text());
  RealisticOptions r;
  EXPECT_EQ(generateRealistic(r).text(), generateRealistic(r).text());
}

TEST(Stimulus, DeterministicWithMonotonicTime) {
  Stimulus a = generateStimulus(7, 100), b = generateStimulus(7, 100);
  EXPECT_EQ(formatStimulus(a), formatStimulus(b));
  ASSERT_EQ(a.ticks(), 100u);
  for (uint32_t t = 1; t < a.ticks(); ++t) EXPECT_GT(a.nowMs[t], a.nowMs[t - 1]);
}

TEST(Stimulus, BitWritesChangeOnlyThatBitElementWritesTruncate) {
  // CLI.md "Addresses": writing a bit sets only that bit; an element write is truncated.
  lj_state s;
  lj_state_reset(&s);
  s.img.X[3] = 0xF0;
  applyWrites(s,
              {{Area::Input, 3, 1, 1}, {Area::Input, 3, 7, 0}, {Area::NcStatus, 2, -1, 0x12345}});
  EXPECT_EQ(s.img.X[3], 0x72);
  EXPECT_EQ(s.img.F[2], 0x2345);
  applyWrites(s, {{Area::NcStatus, 2, 15, 1}});
  EXPECT_EQ(s.img.F[2], static_cast<int16_t>(0xA345));
}

TEST(Stimulus, PrintsTheCliStimulusFormat) {
  // CLI.md `--stimulus`: lines `@TICK ADDR=VALUE [ADDR=VALUE ...]`, `#` comments.
  Stimulus st;
  st.nowMs = {0, 1, 2};
  st.writes = {{}, {{Area::Input, 1, 0, 1}, {Area::NcStatus, 7, -1, -3}}, {}};
  std::string text = formatStimulus(st);
  EXPECT_NE(text.find("\n@1 X1.0=1 F7=-3\n"), std::string::npos) << text;
  EXPECT_EQ(text.find("@0"), std::string::npos);
  for (size_t pos = 0; pos < text.size();) {
    size_t end = text.find('\n', pos);
    EXPECT_TRUE(text[pos] == '#' || text[pos] == '@') << text.substr(pos, end - pos);
    pos = end + 1;
  }
}

} // namespace
} // namespace lj::gen

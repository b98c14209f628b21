// Catalogue completeness (issue 4 item 4): every mnemonic of the manual's summary tables
// (manual-mnemonics.txt) is in the instruction table, has interpreter semantics, has a lowering,
// can be emitted by the fuzzer's generator and has an entry in docs/instructions.md; every
// table row is spelled by at least one dialect's front end, and the rows HNC-8 spells are
// mnemonics of the manual.
#include "frontends/classicladder/FrontEnd.h"
#include "frontends/fanuc/FrontEnd.h"
#include "frontends/hnc8/FrontEnd.h"
#include "frontends/hnc8/InstrDocs.h"
#include "frontends/hnc8/Mnemonics.h"
#include "frontends/iec/FrontEnd.h"
#include "gen/ProgramGenerator.h"
#include "interp/Interpreter.h"
#include "ir/OpTable.h"
#include "jit/Jit.h"
#include "pipeline/Compile.h"

#include <gtest/gtest.h>

#include <fstream>
#include <memory>
#include <optional>
#include <ostream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace lj {
namespace {

struct ManualName {
  std::string name;    ///< as in the manual (aliases included)
  std::string section; ///< summary table it comes from
};

/// Short parameter text in test listings (GoogleTest would dump the raw bytes).
void PrintTo(const ManualName &m, std::ostream *os) { *os << m.name << " (" << m.section << ")"; }

std::vector<ManualName> manualNames() {
  std::vector<ManualName> out;
  std::ifstream in(LJ_CATALOGUE_LIST);
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream ls(line);
    ManualName m;
    ls >> m.name;
    std::getline(ls, m.section);
    m.section.erase(0, m.section.find_first_not_of(' '));
    out.push_back(m);
  }
  return out;
}

std::string readFile(const char *path) {
  std::ifstream in(path);
  std::ostringstream o;
  o << in.rdbuf();
  return o.str();
}

/// The generator's snippet for `op` that verifies (the first of a few seeds), with its program.
struct Snippet {
  std::string text;
  std::optional<VerifiedProgram> prog;
  std::string diagnostics;
};

Snippet verifiedSnippet(Op op) {
  Snippet s;
  for (uint64_t seed = 1; seed <= 8; ++seed) {
    gen::GenProgram p = gen::generateSnippet(op, seed);
    Diagnostics d("snippet.stl");
    VerifyOptions vo;
    vo.plc2Nvalue = p.plc2Nvalue;
    s.text = p.text();
    s.prog = pipeline::compileStl(s.text, "snippet.stl", vo, d);
    s.diagnostics = d.render();
    if (s.prog) return s;
  }
  return s;
}

class Mnemonic : public ::testing::TestWithParam<ManualName> {
protected:
  Op op() const {
    Op o = Op::Count_;
    hnc8::lookupMnemonic(GetParam().name, o);
    return o;
  }
};

TEST(ManualList, HasEveryTable) {
  // 22 basic + 35 chapter-4 part 1 + 24 new of part 2 + 64 chapter-6 + WRT/END1/END2.
  EXPECT_EQ(manualNames().size(), 148u);
}

TEST_P(Mnemonic, IsInTheInstructionTable) {
  Op o;
  ASSERT_TRUE(hnc8::lookupMnemonic(GetParam().name, o))
      << GetParam().name << " (" << GetParam().section << ") is not in InstrTable.cpp";
}

/// The front ends whose spellings the catalogue knows (ir/OpTable.h "dialect-only rows").
const DialectText *const kDialects[] = {&hnc8::dialectText(), &fanuc::dialectText(),
                                        &iec::dialectText(), &classicladder::dialectText()};

TEST(Catalogue, EveryTableRowIsSpelledByADialect) {
  for (const InstrInfo &row : instrTable()) {
    bool any = false;
    for (const DialectText *d : kDialects) any = any || spells(*d, row.op);
    EXPECT_TRUE(any) << row.name << " is spelled by no dialect's front end";
  }
}

TEST(Catalogue, EveryHnc8RowIsAMnemonicOfTheManual) {
  std::set<std::string> names;
  for (const ManualName &m : manualNames()) names.insert(m.name);
  for (const InstrInfo &row : instrTable())
    if (hnc8::spells(row.op)) {
      EXPECT_TRUE(names.count(hnc8::mnemonicOf(row.op)))
          << hnc8::mnemonicOf(row.op) << " is not in the manual's tables";
    }
}

TEST(Catalogue, Hnc8SpellingsAreItsMnemonicTable) {
  // DialectText::spell, spells() and the mnemonic table agree; a row HNC-8 does not spell
  // prints as its neutral name (never null, never another row's mnemonic).
  size_t spelled = 0;
  for (const InstrInfo &row : instrTable()) {
    const hnc8::MnemonicRow *m = hnc8::mnemonicRow(row.op);
    EXPECT_EQ(m != nullptr, spells(hnc8::dialectText(), row.op)) << row.name;
    if (m) {
      ++spelled;
      EXPECT_EQ(m->op, row.op) << row.name;
      EXPECT_STREQ(hnc8::mnemonicOf(row.op), m->spelling);
      Op back = Op::Count_;
      EXPECT_TRUE(hnc8::lookupMnemonic(m->spelling, back) && back == row.op) << m->spelling;
    } else {
      EXPECT_STREQ(hnc8::mnemonicOf(row.op), row.name);
    }
  }
  EXPECT_EQ(spelled, hnc8::mnemonicTable().size());
}

TEST(Catalogue, EveryDialectPrintsEveryRow) {
  // Diagnostics and dumps name operations through spelling(): the dialect's mnemonic, or the
  // row's neutral name when that dialect has none.
  for (const InstrInfo &row : instrTable()) {
    EXPECT_STREQ(spelling(nullptr, row.op), row.name);
    for (const DialectText *d : kDialects) {
      const char *s = spelling(d, row.op);
      ASSERT_NE(s, nullptr) << d->name << " " << row.name;
      EXPECT_STRNE(s, "") << d->name << " " << row.name;
      if (!spells(*d, row.op)) {
        EXPECT_STREQ(s, row.name) << d->name;
      }
    }
  }
}

TEST_P(Mnemonic, GeneratorEmitsAStatementThatVerifies) {
  ASSERT_NE(op(), Op::Count_);
  Snippet s = verifiedSnippet(op());
  ASSERT_TRUE(s.prog.has_value()) << s.diagnostics << s.text;
  bool found = false;
  for (const Stmt &st : s.prog->stmts) found = found || st.op == op();
  EXPECT_TRUE(found) << s.text;
}

TEST_P(Mnemonic, InterpreterHasSemantics) {
  ASSERT_NE(op(), Op::Count_);
  Snippet s = verifiedSnippet(op());
  ASSERT_TRUE(s.prog.has_value()) << s.diagnostics;
  Interpreter interp(*s.prog);
  auto st = std::make_unique<lj_state>();
  lj_state_reset(st.get());
  lj_run_init(st.get(), &interp.entries());
  for (int t = 0; t < 2; ++t) {
    st->now_ms = static_cast<uint64_t>(t);
    lj_tick(st.get(), &interp.entries());
  }
  EXPECT_EQ(interp.unimplemented(), Op::Count_)
      << "no interpreter semantics for " << hnc8::mnemonicOf(interp.unimplemented()) << " in\n"
      << s.text;
}

TEST_P(Mnemonic, JitLowersIt) {
  ASSERT_NE(op(), Op::Count_);
  Snippet s = verifiedSnippet(op());
  ASSERT_TRUE(s.prog.has_value()) << s.diagnostics;
  std::string error;
  jit::JitOptions o;
  o.tier = jit::Tier::Fast;
  std::unique_ptr<Engine> e = jit::compile(*s.prog, o, error);
  EXPECT_TRUE(e != nullptr) << error << "\n" << s.text;
}

TEST_P(Mnemonic, HasAnEntryInTheInstructionReference) {
  ASSERT_NE(op(), Op::Count_);
  static const std::string doc = readFile(LJ_INSTRUCTIONS_DOC);
  const std::string row = hnc8::mnemonicOf(op());
  EXPECT_NE(doc.find("\n## " + row + "\n"), std::string::npos) << "no `## " << row << "` entry";
  if (row != GetParam().name) { // an alias is named in its instruction's entry
    EXPECT_NE(doc.find("`" + GetParam().name + "`"), std::string::npos);
  }
}

TEST(InstructionReference, CommittedFileIsTheGeneratorsOutput) {
  // Regenerate: build/tools/gen-instr-doc/gen-instr-doc -o docs/instructions.md
  EXPECT_TRUE(readFile(LJ_INSTRUCTIONS_DOC) == renderInstructionReference())
      << "docs/instructions.md is stale: regenerate it with tools/gen-instr-doc";
}

TEST(InstructionReference, EveryExamplePassesTheFrontEnd) {
  for (const InstrDoc &d : instrDocs()) {
    Diagnostics diags("example.stl");
    VerifyOptions vo;
    EXPECT_TRUE(pipeline::compileStl(d.example, "example.stl", vo, diags).has_value())
        << hnc8::mnemonicOf(d.op) << " example:\n"
        << d.example << "\n"
        << diags.render();
    bool uses = false;
    Diagnostics d2("example.stl");
    for (const Stmt &s : parseStl(d.example, "example.stl", d2).stmts) uses = uses || s.op == d.op;
    EXPECT_TRUE(uses) << hnc8::mnemonicOf(d.op) << " example does not use it";
  }
}

std::string paramName(const ::testing::TestParamInfo<ManualName> &i) {
  std::string n = i.param.name;
  return (n[0] >= '0' && n[0] <= '9') ? "M" + n : n;
}

INSTANTIATE_TEST_SUITE_P(Manual, Mnemonic, ::testing::ValuesIn(manualNames()), paramName);

} // namespace
} // namespace lj

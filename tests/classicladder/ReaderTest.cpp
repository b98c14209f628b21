// The ClassicLadder reader on small projects written here and on the real projects (expected
// values from ../shared/reference/classicladder.md sections 1, 2 and 6).
#include "frontends/classicladder/Reader.h"

#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>

using namespace lj::classicladder;

namespace {

const char *kEmptyRow = "0-0-0/0 , 0-0-0/0 , 0-0-0/0 , 0-0-0/0 , 0-0-0/0 , 0-0-0/0 , "
                        "0-0-0/0 , 0-0-0/0 , 0-0-0/0 , 0-0-0/0";

/// A one-rung project whose rung 0 has `row0` as its first row, plus `extra` blocks.
std::string project(const std::string &row0, const std::string &extra = "",
                    const std::string &next = "-1") {
  std::string s = "_FILES_CLASSICLADDER\n_FILE-sections.csv\n#VER=1.0\n#NAME000=Prog1\n"
                  "000,0,-1,0,0,0\n_/FILE-sections.csv\n_FILE-rung_0.csv\n#VER=2.0\n"
                  "#LABEL=R0\n#COMMENT=first\n#PREVRUNG=-1\n#NEXTRUNG=" +
                  next + "\n" + row0 + "\n";
  for (int i = 0; i < 5; ++i) s += std::string(kEmptyRow) + "\n";
  s += "_/FILE-rung_0.csv\n" + extra + "_/FILES_CLASSICLADDER\n";
  return s;
}

const char *kRow = "1-0-50/0 , 2-0-0/3 , 9-0-0/0 , 9-0-0/0 , 9-0-0/0 , 9-0-0/0 , 9-0-0/0 , "
                   "9-0-0/0 , 9-0-0/0 , 50-0-60/1";

std::string errorOf(const std::string &text, const std::string &name = "t.clp") {
  auto r = readProjectText(text, name);
  EXPECT_FALSE(r.ok());
  return r.ok() ? "" : r.status().message();
}

} // namespace

TEST(ClReader, OneRung) {
  auto r = readProjectText(project(kRow), "t.clp");
  ASSERT_TRUE(r.ok()) << r.status().message();
  const Project &p = *r;
  ASSERT_EQ(p.rungs.size(), 1u);
  const Rung &g = p.rungs.at(0);
  EXPECT_EQ(g.label, "R0");
  EXPECT_EQ(g.comment, "first");
  EXPECT_EQ(g.nextRung, -1);
  EXPECT_EQ(g.at(0, 0).type, 1);
  EXPECT_EQ(g.at(0, 0).varType, 50);
  EXPECT_EQ(g.at(1, 0).type, 2);
  EXPECT_EQ(g.at(1, 0).varNum, 3);
  EXPECT_EQ(g.at(9, 0).type, 50);
  EXPECT_EQ(g.at(9, 0).varType, 60);
  EXPECT_EQ(g.at(9, 0).varNum, 1);
  ASSERT_EQ(p.sections.size(), 1u);
  EXPECT_EQ(p.sections[0].name, "Prog1");
  EXPECT_EQ(p.sections[0].order, std::vector<int32_t>{0});
  EXPECT_EQ(p.sizes.physInputs, 15); // loadrt default without general.txt
}

TEST(ClReader, BadCellIsLocated) {
  std::string row = kRow;
  row.replace(row.find("2-0-0/3"), 7, "2-0-0x3");
  std::string m = errorOf(project(row));
  // line 13 of the container: the first grid row of rung 0; column 1
  EXPECT_NE(m.find("t.clp:13:"), std::string::npos) << m;
  EXPECT_NE(m.find("rung_0.csv rung 0 row 0 column 1"), std::string::npos) << m;
  EXPECT_NE(m.find("2-0-0x3"), std::string::npos) << m;
}

TEST(ClReader, CellErrors) {
  auto with = [&](const char *cell) {
    std::string row = kRow;
    row.replace(row.find("2-0-0/3"), 7, cell);
    return errorOf(project(row));
  };
  EXPECT_NE(with("7-0-0/3").find("unknown element type 7"), std::string::npos);
  EXPECT_NE(with("2-2-0/3").find("vertical-link field is 2"), std::string::npos);
  EXPECT_NE(with("2-0-123/3").find("unknown variable type 123"), std::string::npos);
  std::string row = kRow; // an indexed operand: read, with a warning (2.9 ignores the index)
  row.replace(row.find("2-0-0/3"), 7, "2-0-0/3[200/1]");
  auto idx = readProjectText(project(row), "t.clp");
  ASSERT_TRUE(idx.ok()) << idx.status().message();
  EXPECT_EQ(idx->rungs.at(0).at(1, 0).indexType, 200);
  ASSERT_EQ(idx->warnings.size(), 1u);
  EXPECT_NE(idx->warnings[0].find("2.9 (atoi) ignores it"), std::string::npos);
  // a compare block is 3 wide: its top-right cell cannot be in column 1
  EXPECT_NE(with("20-0-0/0").find("does not fit"), std::string::npos);
}

TEST(ClReader, BlocksAndExpressions) {
  // compare (3 wide) at column 2, expression 0; operate at column 9, expression 1
  std::string row = "1-0-50/0 , 99-0-0/0 , 20-0-0/0 , 9-0-0/0 , 9-0-0/0 , 9-0-0/0 , 9-0-0/0 , "
                    "99-0-0/0 , 99-0-0/0 , 60-0-0/1";
  std::string exprs = "_FILE-arithmetic_expressions.csv\n#VER=2.0\n0000,@270/0@>5\n"
                      "0001,@280/0@:=@270/0@*2\n_/FILE-arithmetic_expressions.csv\n";
  auto r = readProjectText(project(row, exprs), "t.clp");
  ASSERT_TRUE(r.ok()) << r.status().message();
  EXPECT_TRUE(r->expression(0)->expr.isCompare);
  EXPECT_TRUE(r->expression(1)->expr.isOperate);
  EXPECT_EQ(toString(*r->expression(1)->expr.value), "(* @270/0@ 2)");

  // the operate's expression has a syntax error: located at its line, naming the cell
  std::string bad = "_FILE-arithmetic_expressions.csv\n#VER=2.0\n0000,@270/0@>5\n"
                    "0001,@280/0@:=@270/0@*FOO(1)\n_/FILE-arithmetic_expressions.csv\n";
  std::string m = errorOf(project(row, bad));
  EXPECT_NE(m.find("t.clp:23:"), std::string::npos) << m;
  EXPECT_NE(m.find("expression 1 (used by the operate block at rung 0 row 0 column 9)"),
            std::string::npos)
      << m;
  EXPECT_NE(m.find("column 18: unknown function 'FOO'"), std::string::npos) << m;

  // a compare block on an assignment-only text
  std::string notCmp = "_FILE-arithmetic_expressions.csv\n0000,@280/0@+1\n0001,@280/0@:=1\n"
                       "_/FILE-arithmetic_expressions.csv\n";
  EXPECT_NE(errorOf(project(row, notCmp)).find("expression 0"), std::string::npos);
}

TEST(ClReader, SectionChains) {
  std::string twoSections =
      "_FILES_CLASSICLADDER\n_FILE-sections.csv\n000,0,-1,3,1,0\n_/FILE-sections.csv\n";
  auto rung = [](int n, int next) {
    std::string s = "_FILE-rung_" + std::to_string(n) +
                    ".csv\n#VER=2.0\n#NEXTRUNG=" + std::to_string(next) + "\n" + std::string(kRow) +
                    "\n";
    return s + "_/FILE-rung_" + std::to_string(n) + ".csv\n";
  };
  auto r = readProjectText(
      twoSections + rung(1, -1) + rung(3, 2) + rung(2, 1) + "_/FILES_CLASSICLADDER\n", "t.clp");
  ASSERT_TRUE(r.ok()) << r.status().message();
  EXPECT_EQ(r->sections[0].order, (std::vector<int32_t>{3, 2, 1}));
  auto loop = readProjectText(
      twoSections + rung(1, -1) + rung(3, 2) + rung(2, 3) + "_/FILES_CLASSICLADDER\n", "t.clp");
  ASSERT_FALSE(loop.ok());
  EXPECT_NE(loop.status().message().find("loops back to rung 3"), std::string::npos);
  auto ends = readProjectText(
      twoSections + rung(1, -1) + rung(3, 2) + rung(2, -1) + "_/FILES_CLASSICLADDER\n", "t.clp");
  ASSERT_FALSE(ends.ok());
  EXPECT_NE(ends.status().message().find("t.clp:3: error: sections.csv section 0: its chain ends"),
            std::string::npos)
      << ends.status().message();
  auto missing =
      readProjectText(twoSections + rung(1, -1) + rung(3, 5) + "_/FILES_CLASSICLADDER\n", "t.clp");
  ASSERT_FALSE(missing.ok());
  EXPECT_NE(missing.status().message().find("reaches rung 5"), std::string::npos);
}

TEST(ClReader, ContainerErrors) {
  EXPECT_NE(errorOf("hello\n").find("not a ClassicLadder project"), std::string::npos);
  EXPECT_NE(errorOf("_FILES_CLASSICLADDER\n_FILE-a.csv\nx\n").find("not closed"),
            std::string::npos);
  EXPECT_NE(errorOf("_FILES_CLASSICLADDER\n_FILE-a.csv\n_/FILE-a.csv\n").find("is empty"),
            std::string::npos);
  EXPECT_NE(errorOf("_FILES_CLASSICLADDER\nstray\n").find("outside a _FILE- block"),
            std::string::npos);
  EXPECT_NE(
      errorOf("_FILES_CLASSICLADDER\n_FILE-a.csv\n" + std::string(400, 'x') + "\n_/FILE-a.csv\n")
          .find("more than 299"),
      std::string::npos);
  // a 0.9 rung in a .clp
  std::string v3 = project(kRow);
  v3.replace(v3.find("#VER=2.0"), 8, "#VER=3.0");
  EXPECT_NE(errorOf(v3).find("ClassicLadder 0.9 rung"), std::string::npos);
}

TEST(ClReader, ParameterFiles) {
  std::string extra = "_FILE-timers.csv\n1,10\n1,20\n0,20\n2,1\n2,5\n_/FILE-timers.csv\n"
                      "_FILE-timers_iec.csv\n0,15,0\n1,2,0\n2,3,2\n_/FILE-timers_iec.csv\n"
                      "_FILE-counters.csv\n7\n0\n_/FILE-counters.csv\n"
                      "_FILE-general.txt\nPERIODIC_REFRESH=50\nSIZE_NBR_PHYS_INPUTS=40\n"
                      "_/FILE-general.txt\n"
                      "_FILE-symbols.csv\n#VER=1.0\n%I0,GUI-E,\n%B0,reset,reset off timer\n"
                      "%TM2.Q,toolongsymbol,x\n_/FILE-symbols.csv\n";
  auto r = readProjectText(project(kRow, extra), "t.clp");
  ASSERT_TRUE(r.ok()) << r.status().message();
  ASSERT_EQ(r->timers.size(), 5u);
  EXPECT_EQ(r->timers[2].baseMs, 60000); // estop.clp timer 2: 20 minutes
  EXPECT_EQ(r->timers[2].preset, 20);
  EXPECT_EQ(r->timers[3].baseMs, 100);
  ASSERT_EQ(r->timersIec.size(), 3u);
  EXPECT_EQ(r->timersIec[0].baseMs, 60000); // ec-sim %TM0: TON 15 minutes
  EXPECT_EQ(r->timersIec[0].preset, 15);
  EXPECT_EQ(r->timersIec[2].mode, IecMode::Tp);
  EXPECT_EQ(r->counterPresets, (std::vector<int32_t>{7, 0}));
  EXPECT_EQ(r->periodMs, 50);
  EXPECT_EQ(r->sizes.physInputs, 40);
  ASSERT_EQ(r->symbols.size(), 3u);
  EXPECT_EQ(r->symbols[1].symbol, "reset");
  EXPECT_EQ(r->symbols[1].comment, "reset off timer");
  ASSERT_TRUE(r->symbols[1].var.has_value());
  EXPECT_EQ(r->symbols[1].var->type, 0);
  EXPECT_EQ(r->symbols[2].symbol, ""); // longer than 9: left empty, as ClassicLadder does
  EXPECT_EQ(r->symbols[2].var->type, 15);
  EXPECT_EQ(r->symbols[2].var->num, 2);

  std::string badBase = "_FILE-timers.csv\n7,10\n_/FILE-timers.csv\n";
  EXPECT_NE(errorOf(project(kRow, badBase)).find("time base 7"), std::string::npos);
}

TEST(ClReader, VarNames) {
  EXPECT_EQ(varName(50, 3), "%I3");
  EXPECT_EQ(varName(15, 0), "%TM0.Q");
  EXPECT_EQ(varName(270, 2), "%IW2");
  EXPECT_EQ(parseVarName("%QW12")->type, 280);
  EXPECT_EQ(parseVarName("%T3.D")->type, 10);
  EXPECT_FALSE(parseVarName("%Z1").has_value());
  EXPECT_FALSE(parseVarName("%I").has_value());
}

TEST(ClReader, ProjectFolder) {
  // The same project as files of a folder (the "old" format): errors name the file's own line.
  std::string dir = ::testing::TempDir() + "/cl_folder_test";
  std::filesystem::create_directories(dir);
  auto put = [&](const std::string &name, const std::string &text) {
    std::ofstream(dir + "/" + name) << text;
  };
  put("sections.csv", "#VER=1.0\n#NAME000=Prog1\n000,0,-1,0,0,0\n");
  std::string rung = "#VER=2.0\n#NEXTRUNG=-1\n" + std::string(kRow) + "\n";
  put("rung_0.csv", rung);
  put("timers.csv", "1,10\n");
  auto r = readProject(dir);
  ASSERT_TRUE(r.ok()) << r.status().message();
  EXPECT_EQ(r->rungs.size(), 1u);
  EXPECT_EQ(r->timers.size(), 1u);
  EXPECT_EQ(r->rungs.at(0).at(9, 0).varNum, 1);
  put("rung_0.csv", "#VER=2.0\n#NEXTRUNG=-1\n" + std::string(kRow) + "\n1-0-50/0 , x\n");
  auto bad = readProject(dir);
  ASSERT_FALSE(bad.ok());
  EXPECT_NE(bad.status().message().find(":4: error: rung_0.csv rung 0 row 1: 2 cells"),
            std::string::npos)
      << bad.status().message();
  std::filesystem::remove_all(dir);
  EXPECT_EQ(readProject(dir).status().code(), lj::ErrorCode::NotFound);
}

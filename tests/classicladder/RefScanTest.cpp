// The reference ClassicLadder scan on small rungs, against the behaviour the reference measured
// with classicladder_rt (../shared/reference/classicladder.md 2.4, 4.3-4.7 and 5).
#include "oracle/classicladder/RefScan.h"
#include "frontends/classicladder/Reader.h"

#include <gtest/gtest.h>

using namespace lj::classicladder;
using lj::oracle::ClReferenceScan;
using lj::oracle::ClSizes;

namespace {

const char *kEmpty = "0-0-0/0";

/// A one-rung project: `rows` (up to 6) of 10 cells each, missing cells empty.
Project project(const std::vector<std::vector<std::string>> &rows, const std::string &extra = "") {
  std::string s = "_FILES_CLASSICLADDER\n_FILE-sections.csv\n000,0,-1,0,0,0\n"
                  "_/FILE-sections.csv\n_FILE-rung_0.csv\n#VER=2.0\n#NEXTRUNG=-1\n";
  for (size_t y = 0; y < 6; ++y) {
    for (size_t x = 0; x < 10; ++x) {
      const bool have = y < rows.size() && x < rows[y].size() && !rows[y][x].empty();
      s += (have ? rows[y][x] : std::string(kEmpty)) + (x < 9 ? " , " : "\n");
    }
  }
  s += "_/FILE-rung_0.csv\n" + extra + "_/FILES_CLASSICLADDER\n";
  auto r = readProjectText(s, "t.clp");
  EXPECT_TRUE(r.ok()) << r.status().message();
  return r.ok() ? std::move(r.value()) : Project();
}

std::vector<std::string> wire(const std::string &first, const std::string &coil) {
  std::vector<std::string> row(10, "9-0-0/0");
  row[0] = first;
  row[9] = coil;
  return row;
}

} // namespace

TEST(ClRefScan, EmptyCellsDoNotConduct) {
  // surprise 1: an NC contact followed by empty cells leaves the coil at 0; with connections, 1
  std::vector<std::string> gap(10, "");
  gap[0] = "2-0-50/0";
  gap[9] = "50-0-60/0";
  Project p = project({gap, wire("2-0-50/0", "50-0-60/1")});
  ClReferenceScan s(p, ClSizes{});
  s.refresh(1);
  EXPECT_EQ(s.out[0], 0);
  EXPECT_EQ(s.out[1], 1);
}

TEST(ClRefScan, VerticalLinkClosesAnOr) {
  // %I0 on row 0, %I1 on row 1, the link on the empty cell (9,1) ORs column 8 into the coil
  auto r1 = wire("1-0-50/1", "0-1-0/0");
  Project p = project({wire("1-0-50/0", "50-0-60/0"), r1});
  ClReferenceScan s(p, ClSizes{});
  s.in[1] = 1;
  s.refresh(1);
  EXPECT_EQ(s.out[0], 1);
  s.in[1] = 0;
  s.refresh(1);
  EXPECT_EQ(s.out[0], 0);
}

TEST(ClRefScan, JumpCancelsTheRestOfItsRung) {
  // measured: row 0 %I2 -> (J) to a rung, row 1 %I3 -> (%Q6); with I2=1 and I3=0, Q6 stays 1
  std::string extra = "_FILE-rung_1.csv\n#VER=2.0\n#NEXTRUNG=-1\n";
  for (int y = 0; y < 6; ++y)
    extra += "0-0-0/0 , 0-0-0/0 , 0-0-0/0 , 0-0-0/0 , 0-0-0/0 , "
             "0-0-0/0 , 0-0-0/0 , 0-0-0/0 , 0-0-0/0 , 0-0-0/0\n";
  extra += "_/FILE-rung_1.csv\n";
  Project p = project({wire("1-0-50/2", "54-0-0/1"), wire("1-0-50/3", "50-0-60/6")}, extra);
  p.sections[0].lastRung = 1; // main: rung 0, then the jump target
  ClReferenceScan s(p, ClSizes{});
  s.in[3] = 1;
  s.refresh(1);
  EXPECT_EQ(s.out[6], 1);
  s.in[2] = 1;
  s.in[3] = 0;
  s.refresh(1);
  EXPECT_EQ(s.out[6], 1); // the coil below the jump did not run
}

TEST(ClRefScan, IecTonIsOneScanLate) {
  // TON 2 s at 1 ms: V reaches 2 at scan 2000, Q rises at scan 2001
  std::vector<std::string> r0 = wire("1-0-50/0", "50-0-60/0");
  r0[1] = "99-0-0/0";
  r0[2] = "13-0-0/0";
  std::vector<std::string> r1(10, "");
  r1[1] = "99-0-0/0";
  r1[2] = "99-0-0/0";
  Project p = project({r0, r1}, "_FILE-timers_iec.csv\n1,2,0\n_/FILE-timers_iec.csv\n");
  ClReferenceScan s(p, ClSizes{});
  s.in[0] = 1;
  for (int k = 1; k <= 2000; ++k) {
    s.refresh(1);
    ASSERT_EQ(s.out[0], 0) << "scan " << k;
  }
  s.refresh(1);
  EXPECT_EQ(s.out[0], 1);
}

TEST(ClRefScan, CounterDoneIsEquality) {
  // counter 0, preset 2, U on %I0 at row 2; D output (row 1) -> %Q0
  std::vector<std::vector<std::string>> g(4, std::vector<std::string>(10, ""));
  for (int y = 0; y < 4; ++y) g[y][1] = "99-0-0/0";
  g[0][2] = "12-0-0/0";
  for (int y = 1; y < 4; ++y) g[y][2] = "99-0-0/0";
  g[2][0] = "1-0-50/0";
  for (int x = 3; x < 9; ++x) g[1][x] = "9-0-0/0";
  g[1][9] = "50-0-60/0";
  Project p = project(g, "_FILE-counters.csv\n2\n_/FILE-counters.csv\n");
  ClReferenceScan s(p, ClSizes{});
  int pulses = 0;
  std::vector<int> done;
  for (int k = 0; k < 4; ++k) {
    s.in[0] = 1;
    s.refresh(1);
    s.in[0] = 0;
    s.refresh(1);
    ++pulses;
    done.push_back(s.out[0]);
  }
  EXPECT_EQ(done, (std::vector<int>{0, 1, 0, 0})); // done only at V == P (2), not V >= P
}

TEST(ClRefScan, OperateIsLevelTriggeredAndWraps) {
  std::vector<std::string> r0 = wire("1-0-50/0", "60-0-0/0");
  r0[7] = r0[8] = "99-0-0/0";
  Project p = project({r0}, "_FILE-arithmetic_expressions.csv\n0000,@280/0@:=@280/0@+3^2\n"
                            "_/FILE-arithmetic_expressions.csv\n");
  ClReferenceScan s(p, ClSizes{});
  s.in[0] = 1;
  s.refresh(1);
  s.refresh(1);
  EXPECT_EQ(s.s32out[0], 162); // 81 a scan while powered (3^2 = 81)
}

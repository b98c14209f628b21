// The IEC IL examples (examples/*.il) through `ladderjit run` with their stimulus files, `%I0.1`
// addresses on the command line, and the ladder view of an IL program. Every expected value is
// derived by hand from the program text and docs/iec-il.md (the reasoning is next to it).
#include "CliRunner.h"

#include <gtest/gtest.h>

namespace lj::clitest {
namespace {

struct Expect {
  long long tick;
  const char *col;
  long long value;
};

void checkTable(const CliResult &r, size_t ticks, const std::vector<Expect> &expects) {
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.err, "");
  ASSERT_EQ(lines(r.out).size(), ticks + 1) << "header + ticks";
  for (const Expect &e : expects)
    EXPECT_EQ(csvValue(r.out, e.tick, e.col), e.value) << "tick " << e.tick << " " << e.col;
}

TEST(IecExamples, CheckCleanly) {
  for (const char *name : {"conveyor", "pump_station", "filler"}) {
    CliResult r = runCli({"check", sourcePath(std::string("examples/") + name + ".il")});
    EXPECT_EQ(r.exitCode, 0) << name << "\n" << r.err;
    EXPECT_EQ(r.err, "") << name << ": no warnings either";
  }
}

TEST(IecExamples, Conveyor) {
  for (const char *engine : {"interp", "jit"}) {
    SCOPED_TRACE(engine);
    CliResult r = runCli({"run", sourcePath("examples/conveyor.il"), "--engine", engine, "--ticks",
                          "18", "--stimulus", sourcePath("examples/conveyor.stim"), "--watch",
                          "%Q0.0,%Q0.1,%Q0.2,%MW0"});
    checkTable(r, 18,
               {
                   // tick 0 ends at LD %S1 / ENDC; tick 1 has no start.
                   {0, "%Q0.0", 0},
                   {1, "%Q0.0", 0},
                   // start pulse at 2 latches the motor (OR %M5), lamp follows.
                   {2, "%Q0.0", 1},
                   {2, "%Q0.1", 1},
                   {3, "%Q0.0", 1},
                   // parts at 4, 6, 8: ANDR counts each rising edge once.
                   {4, "%MW0", 1},
                   {5, "%MW0", 1},
                   {7, "%MW0", 2},
                   // the third part fills the box (3 >= %KW0 = 3) in tick 8; the motor rung
                   // ran before, so the motor stops in tick 9.
                   {8, "%MW0", 3},
                   {8, "%Q0.2", 1},
                   {8, "%Q0.0", 1},
                   {9, "%Q0.0", 0},
                   {9, "%Q0.1", 0},
                   // box away at 10, a new box at 11: the count clears (full still 1 in 11).
                   {10, "%MW0", 3},
                   {11, "%MW0", 0},
                   {11, "%Q0.2", 1},
                   {12, "%Q0.2", 0},
                   // start at 13, one part at 15, stop (NC opens) at 16.
                   {13, "%Q0.0", 1},
                   {15, "%MW0", 1},
                   {16, "%Q0.0", 0},
                   {17, "%Q0.0", 0},
               });
  }
}

// examples/filler.il: %TM1 TON 3 x 100 ms, %TM0 TP 10 x 100 ms, %C0 preset 2; one tick =
// one time-base unit (docs/iec-il.md A1-A3).
TEST(IecExamples, Filler) {
  for (const char *engine : {"interp", "jit"}) {
    SCOPED_TRACE(engine);
    CliResult r =
        runCli({"run", sourcePath("examples/filler.il"), "--engine", engine, "--ticks", "37",
                "--period-ms", "100", "--stimulus", sourcePath("examples/filler.stim"), "--watch",
                "%Q0.0,%Q0.1,%Q0.2,%TM0.V,%C0.V"});
    checkTable(r, 37,
               {
                   // start at 1: the line and the conveyor run.
                   {0, "%Q0.0", 0},
                   {1, "%Q0.0", 1},
                   // bottle at 3: the conveyor stops, %TM1 settles from 300 ms; Q at 600 ms.
                   {3, "%Q0.0", 0},
                   {5, "%Q0.1", 0},
                   {6, "%Q0.1", 1},
                   {6, "%TM0.V", 0},
                   // the TP pulse lasts 10 units: valve 1 in ticks 6..15, V counts up.
                   {10, "%TM0.V", 4},
                   {15, "%Q0.1", 1},
                   {15, "%Q0.0", 0},
                   {16, "%Q0.1", 0},
                   {16, "%TM0.V", 10},
                   // filled: the conveyor carries it on, the case counts it.
                   {16, "%Q0.0", 1},
                   {16, "%C0.V", 1},
                   // the bottle is gone at 17 (V = 0 once IN and Q are 0).
                   {17, "%TM0.V", 0},
                   {17, "%Q0.0", 1},
                   // bottle 2 at 19: settled at 22, filled at 32, the case is full.
                   {19, "%Q0.0", 0},
                   {22, "%Q0.1", 1},
                   {31, "%Q0.1", 1},
                   {32, "%Q0.1", 0},
                   {32, "%C0.V", 2},
                   {32, "%Q0.2", 1},
                   {32, "%Q0.0", 1},
                   // the line stops in the next scan (ANDN %C0.D) and stays off.
                   {33, "%Q0.0", 0},
                   {34, "%Q0.2", 1},
                   // the case is taken away at 35: the count clears.
                   {35, "%C0.V", 0},
                   {35, "%Q0.2", 0},
                   {36, "%Q0.0", 0},
               });
  }
}

TEST(IecExamples, PumpStation) {
  for (const char *engine : {"interp", "jit"}) {
    SCOPED_TRACE(engine);
    CliResult r = runCli({"run", sourcePath("examples/pump_station.il"), "--engine", engine,
                          "--ticks", "20", "--stimulus", sourcePath("examples/pump_station.stim"),
                          "--watch", "%M1,%M2,%Q0.0,%Q0.1,%Q0.2,%Q0.3,%MW1,%MW2"});
    checkTable(r, 20,
               {
                   // low level alone is no demand; high level at 3 starts pump 1 (lead, M2 = 0).
                   {2, "%M1", 0},
                   {3, "%M1", 1},
                   {3, "%Q0.0", 1},
                   {3, "%Q0.1", 0},
                   {3, "%MW1", 1},
                   // high drops at 5, the demand holds through the low switch.
                   {6, "%Q0.0", 1},
                   // low drops at 7: the demand ends, its falling edge toggles the lead.
                   {7, "%Q0.0", 0},
                   {7, "%M2", 1},
                   {8, "%M2", 1},
                   // cycle 2 at 10: pump 2 leads.
                   {10, "%Q0.0", 0},
                   {10, "%Q0.1", 1},
                   {10, "%MW2", 1},
                   // high-high at 12: both pumps, alarm lamp and horn.
                   {12, "%Q0.0", 1},
                   {12, "%Q0.1", 1},
                   {12, "%MW1", 2},
                   {12, "%Q0.3", 1},
                   {12, "%Q0.2", 1},
                   // acknowledge during high-high: horn silenced, lamp stays.
                   {13, "%Q0.2", 0},
                   {13, "%Q0.3", 1},
                   {14, "%Q0.3", 1},
                   {14, "%Q0.0", 0},
                   // acknowledge after the cause cleared: alarm reset.
                   {15, "%Q0.3", 0},
                   {15, "%Q0.2", 0},
                   // pump 2 faults at 17: pump 1 takes over.
                   {17, "%Q0.0", 1},
                   {17, "%Q0.1", 0},
                   {17, "%MW1", 3},
                   {19, "%MW2", 1},
               });
  }
}

// docs/iec-il.md "Command line": objects in --set and --watch; E1 (modicon-neza.md L447-449).
TEST(IecCli, SetAndWatchObjects) {
  const std::string il = writeScratch("e1.il", "LD %I0.5\nOR %I0.4\nST %Q0.4\n");
  CliResult r = runCli({"run", il, "--engine", "interp", "--set", "%I0.4=1", "--watch", "%Q0.4"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(csvValue(r.out, 0, "%Q0.4"), 1);
  r = runCli({"run", il, "--engine", "interp", "--set", "%I4.0=1"});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("unit 4 is out of range (0..3)"), std::string::npos) << r.err;
  // --dialect iec reads any file name as IL.
  const std::string txt = writeScratch("e1.txt", "LD %I0.5\nOR %I0.4\nST %Q0.4\n");
  r = runCli({"check", txt, "--dialect", "iec"});
  EXPECT_EQ(r.exitCode, 0) << r.err;
}

// The ladder view of an IL program: the objects are drawn as IL writes them.
TEST(IecCli, LadderHtml) {
  const std::string il =
      writeScratch("e13.il", "LD %I0.0\nAND( %I0.1\nOR %I0.2\n)\nST %Q0.0\n"); // E13, L897-901
  CliResult r = runCli({"ladder", il, "--format", "html"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  for (const char *obj : {"%I0.0", "%I0.1", "%I0.2", "%Q0.0"})
    EXPECT_NE(r.out.find(obj), std::string::npos) << obj;
  r = runCli({"ladder", il, "--format", "json"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("\"dialect\": \"iec\""), std::string::npos);
}

TEST(IecCli, FuzzIec) {
  CliResult r = runCli({"fuzz", "--dialect", "iec", "--programs", "20", "--seed", "3"});
  EXPECT_EQ(r.exitCode, 0) << r.out << r.err;
  EXPECT_NE(r.out.find("mismatches 0, engine errors 0, programs not verified 0"), std::string::npos)
      << r.out;
}

} // namespace
} // namespace lj::clitest

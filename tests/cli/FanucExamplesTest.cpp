// The FANUC examples (examples/fanuc_*.pmc) through `ladderjit run` with their stimulus files;
// expected values follow from each program's comments (what it is written to do) and the
// reference's timing (TMRB/TMRBF set times in ms, the 1 s clock R9091.6; fanuc-pmc.md 2, 6.3).
#include "CliRunner.h"

#include <gtest/gtest.h>

namespace lj::clitest {
namespace {

TEST(FanucExamples, CoolantLube) {
  for (const char *engine : {"interp", "jit"}) {
    CliResult r =
        runCli({"run", sourcePath("examples/fanuc_coolant.pmc"), "--engine", engine, "--ticks",
                "1300", "--period-ms", "8", "--stimulus", sourcePath("examples/fanuc_coolant.stim"),
                "--watch", "Y0.0,Y0.1,Y0.2,G4.3"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(csvValue(r.out, 99, "Y0.0"), 0);
    EXPECT_EQ(csvValue(r.out, 100, "Y0.0"), 1); // M08 strobe at tick 100
    EXPECT_EQ(csvValue(r.out, 100, "G4.3"), 1); // FIN while the strobe is on
    EXPECT_EQ(csvValue(r.out, 110, "G4.3"), 0); // strobe off
    EXPECT_EQ(csvValue(r.out, 899, "Y0.0"), 1);
    EXPECT_EQ(csvValue(r.out, 900, "Y0.0"), 0); // M09
    EXPECT_EQ(csvValue(r.out, 0, "Y0.1"), 1);   // lube pump with the E-stop chain closed
    // no lube pressure for 5 s (tick 625 = 5000 ms): the alarm lamp blinks with the 1 s clock
    EXPECT_EQ(csvValue(r.out, 624, "Y0.2"), 0);
    EXPECT_EQ(csvValue(r.out, 625, "Y0.2"), 1);  // 5000 ms: clock ON half
    EXPECT_EQ(csvValue(r.out, 688, "Y0.2"), 0);  // 5504 ms: OFF half
    EXPECT_EQ(csvValue(r.out, 1200, "Y0.0"), 1); // the coolant key toggles it on again
  }
}

TEST(FanucExamples, ToolChange) {
  for (const char *engine : {"interp", "jit"}) {
    CliResult r = runCli({"run", sourcePath("examples/fanuc_tool_change.pmc"), "--engine", engine,
                          "--ticks", "1000", "--period-ms", "8", "--set", "D14:2=255", "--stimulus",
                          sourcePath("examples/fanuc_tool_change.stim"), "--watch",
                          "Y1.0,Y1.1,G4.3,A0.0,R20,D12:2"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(csvValue(r.out, 10, "R20"), 3);  // T3 latched on the strobe's rising edge
    EXPECT_EQ(csvValue(r.out, 10, "Y1.0"), 1); // unclamp
    EXPECT_EQ(csvValue(r.out, 22, "Y1.1"), 0); // rotation waits 100 ms (tick 23 = 104 ms)
    EXPECT_EQ(csvValue(r.out, 23, "Y1.1"), 1);
    EXPECT_EQ(csvValue(r.out, 60, "Y1.1"), 0); // position 3 reached
    EXPECT_EQ(csvValue(r.out, 76, "G4.3"), 0); // FIN 50 ms after clamp confirmation at 70
    EXPECT_EQ(csvValue(r.out, 77, "G4.3"), 1);
    EXPECT_EQ(csvValue(r.out, 77, "D12:2"), 3); // recorded by subroutine P2
    EXPECT_EQ(csvValue(r.out, 774, "A0.0"), 0); // T5 at 150 never arrives: 5 s watchdog
    EXPECT_EQ(csvValue(r.out, 775, "A0.0"), 1);
    EXPECT_EQ(csvValue(r.out, 900, "A0.0"), 0); // cleared when the strobe drops
  }
}

// examples/fanuc_magazine.pmc: 12 pots numbered 1..12 (ROTB with RN0 = 1, DIR = 1), 8 ms ticks.
TEST(FanucExamples, Magazine) {
  for (const char *engine : {"interp", "jit"}) {
    CliResult r =
        runCli({"run", sourcePath("examples/fanuc_magazine.pmc"), "--engine", engine, "--ticks",
                "52", "--period-ms", "8", "--stimulus", sourcePath("examples/fanuc_magazine.stim"),
                "--watch", "R41,R42,R30.1,Y2.0,Y2.1,Y2.2,G4.3,A0.1"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(csvValue(r.out, 1, "Y2.1"), 0); // no T command yet
    // T10 at pot 2: forward 8 pots, reverse 4 -> reverse; 3 steps to the pot before (11).
    EXPECT_EQ(csvValue(r.out, 2, "R30.1"), 1);
    EXPECT_EQ(csvValue(r.out, 2, "R41"), 4);
    EXPECT_EQ(csvValue(r.out, 2, "R42"), 3);
    EXPECT_EQ(csvValue(r.out, 2, "Y2.1"), 1);
    EXPECT_EQ(csvValue(r.out, 2, "Y2.0"), 0);
    EXPECT_EQ(csvValue(r.out, 10, "R41"), 2); // pot 12
    EXPECT_EQ(csvValue(r.out, 13, "Y2.2"), 0);
    EXPECT_EQ(csvValue(r.out, 14, "Y2.2"), 1); // pot 11: the next one is 10, slow
    EXPECT_EQ(csvValue(r.out, 18, "Y2.1"), 0); // pot 10 at tick 18 (144 ms): stop
    EXPECT_EQ(csvValue(r.out, 18, "Y2.2"), 0);
    EXPECT_EQ(csvValue(r.out, 30, "G4.3"), 0); // 240 ms < 144 + 100
    EXPECT_EQ(csvValue(r.out, 31, "G4.3"), 1); // 248 ms
    EXPECT_EQ(csvValue(r.out, 36, "G4.3"), 0); // TF dropped
    // T3 with the door open: the message, P10 leaves by JMPC, ROTB does not run (R41 keeps 0).
    EXPECT_EQ(csvValue(r.out, 40, "A0.1"), 1);
    EXPECT_EQ(csvValue(r.out, 40, "R41"), 0);
    EXPECT_EQ(csvValue(r.out, 40, "Y2.0") + csvValue(r.out, 40, "Y2.1"), 0);
    // Door closed: 10 -> 3 is 5 forward or 7 reverse: forward.
    EXPECT_EQ(csvValue(r.out, 46, "A0.1"), 0);
    EXPECT_EQ(csvValue(r.out, 46, "R41"), 5);
    EXPECT_EQ(csvValue(r.out, 46, "R42"), 4);
    EXPECT_EQ(csvValue(r.out, 46, "Y2.0"), 1);
    EXPECT_EQ(csvValue(r.out, 46, "R30.1"), 0);
  }
}

// The issue's program through `run --plc2-nvalue 2` (docs/fanuc-pmc.md "Level 2 and its
// inputs"): X0.0 = 1 at tick 4 only, the first tick of a level-2 scan; its three level-2 reads
// (ticks 4, 6, 7) all see the latched 1; level 1 (R2.0) sees it at tick 4 only.
TEST(FanucCli, Level2ReadsTheLatchedInputs) {
  std::string prog = writeScratch("sync.pmc", "RD X0.0\nWRT R2.0\nEND1\nRD X0.0\nWRT R1.0\n"
                                              "RD F1.0\nWRT R1.3\nRD X0.0\nWRT R1.1\n"
                                              "RD X0.0\nWRT R1.2\nEND2\nEND\n");
  std::string stim = writeScratch("sync.stim", "@4 X0.0=1\n@5 X0.0=0\n");
  for (const char *engine : {"interp", "jit"}) {
    CliResult r = runCli({"run", prog, "--engine", engine, "--plc2-nvalue", "2", "--ticks", "9",
                          "--stimulus", stim, "--watch", "R2.0,R1.0,R1.1,R1.2"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(csvValue(r.out, 4, "R2.0"), 1);
    EXPECT_EQ(csvValue(r.out, 5, "R2.0"), 0);
    EXPECT_EQ(csvValue(r.out, 7, "R1.0"), 1);
    EXPECT_EQ(csvValue(r.out, 7, "R1.1"), 1);
    EXPECT_EQ(csvValue(r.out, 7, "R1.2"), 1);
    EXPECT_EQ(csvValue(r.out, 8, "R1.0"), 0); // the next scan latched X0.0 = 0
  }
}

// --params with the counter data type (docs/fanuc-pmc.md "System parameters", ref 6.4): CTR 1
// (CN0 = 0, up, ACT = X0.0) with the preset given as 12 on the parameter screen counts in BCD:
// after 10 rising edges its count is 0x0010 (16 as a binary number), at 12 W1 (R0.0) is 1.
TEST(FanucCli, ParamsCounterDataTypeBcd) {
  std::string prog = writeScratch("ctr.pmc", "RD R9091.0\nRD.STK R9091.0\nRD.STK R9091.0\n"
                                             "RD.STK X0.0\nCTR 1\nWRT R0.0\nEND1\nEND2\nEND\n");
  std::string params = writeScratch("ctr.params", "COUNTER = BCD\nC0:2 = 12 # preset\n");
  std::string stim;
  for (int k = 0; k < 12; ++k)
    stim += "@" + std::to_string(2 * k) + " X0.0=1\n@" + std::to_string(2 * k + 1) + " X0.0=0\n";
  std::string stimFile = writeScratch("ctr.stim", stim);
  for (const char *engine : {"interp", "jit"}) {
    CliResult r = runCli({"run", prog, "--engine", engine, "--ticks", "24", "--params", params,
                          "--stimulus", stimFile, "--watch", "C0:2,C2:2,R0.0"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(csvValue(r.out, 0, "C0:2"), 0x12);
    EXPECT_EQ(csvValue(r.out, 19, "C2:2"), 0x10); // the 10th edge (tick 18)
    EXPECT_EQ(csvValue(r.out, 19, "R0.0"), 0);
    EXPECT_EQ(csvValue(r.out, 23, "C2:2"), 0x12); // the 12th edge (tick 22)
    EXPECT_EQ(csvValue(r.out, 23, "R0.0"), 1);
  }
  std::string bad = writeScratch("bad.params", "COUNTER = BCD\nC0:2 = 12000\n");
  CliResult r = runCli({"run", prog, "--params", bad});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find(bad + ":2:8: counter value 12000 of C0:2 is not BCD"), std::string::npos)
      << r.err;
}

} // namespace
} // namespace lj::clitest

// The examples/ programs run through `ladderjit run --engine interp` with their stimulus files.
// Every expected value is derived by hand from the program text and DIALECT.md /
// docs/dialect-notes.md (the reasoning is next to each value), never copied from output.
#include "CliRunner.h"

#include <gtest/gtest.h>

namespace lj::clitest {
namespace {

struct Expect {
  long long tick;
  const char *col;
  long long value;
};

void checkTable(const CliResult &r, const std::vector<Expect> &expects) {
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.err, "");
  ASSERT_EQ(lines(r.out).size(), 101u) << "header + 100 ticks";
  for (const Expect &e : expects)
    EXPECT_EQ(csvValue(r.out, e.tick, e.col), e.value) << "tick " << e.tick << " " << e.col;
}

std::vector<std::string> lathe() {
  return {"run",        sourcePath("examples/lathe_panel.stl"),
          "--ticks",    "100",
          "--stimulus", sourcePath("examples/lathe_panel.stim"),
          "--watch",    "R0,G2620,G2564,Y480.0,Y480.2,Y480.3,Y0.0,Y0.1,G2622.0,Y0.2"};
}

std::vector<std::string> coolant() {
  return {"run",         sourcePath("examples/coolant_lube.stl"),
          "--ticks",     "100",
          "--period-ms", "10",
          "--params",    sourcePath("examples/coolant_lube.params"),
          "--stimulus",  sourcePath("examples/coolant_lube.stim"),
          "--watch",     "R10.0,Y0.3,T2,Y481.5,Y0.4,R20.2,T11,Y481.6,G3010.0,D10,D11,D12"};
}

std::vector<std::string> parts() {
  return {"run",        sourcePath("examples/part_counter.stl"),
          "--ticks",    "100",
          "--params",   sourcePath("examples/part_counter.params"),
          "--stimulus", sourcePath("examples/part_counter.stim"),
          "--watch",    "R32.0,R30.0,B0,G2579,C5,C6,Y481.2,Y481.3,D40,D41,Y481.5"};
}

std::vector<std::string> withEngine(std::vector<std::string> args, const char *engine) {
  args.insert(args.begin() + 2, {"--engine", engine});
  return args;
}

TEST(Examples, CheckCleanly) {
  for (const char *name : {"lathe_panel", "coolant_lube", "part_counter"}) {
    CliResult r = runCli({"check", sourcePath(std::string("examples/") + name + ".stl")});
    EXPECT_EQ(r.exitCode, 0) << name << "\n" << r.err;
    EXPECT_EQ(r.err, "") << name << ": no warnings either";
  }
}

TEST(Examples, LathePanel) {
  CliResult r = runCli(withEngine(lathe(), "interp"));
  checkTable(
      r,
      {
          // init: OUT R0.2 -> R0 = 4; MOV 100 G2564. PLC1 copies R0.2 to G2620.2 -> 4.
          {0, "R0", 4},
          {0, "G2620", 4},
          {0, "G2564", 100},
          // PLC2 lamps: WAND F2560 15 W0; COIN 2 W0 -> Y480.2 once the NC reports 2 (@2).
          {1, "Y480.2", 0},
          {2, "Y480.2", 1},
          {2, "Y480.0", 0},
          // CW key edge at 10 (LDP rises in the same execution, DIALECT.md 3) latches R1.0 -> Y0.0.
          {9, "Y0.0", 0},
          {10, "Y0.0", 1},
          {19, "Y0.0", 1},
          // CCW key at 20: ANI R1.0 blocks it, CW keeps running.
          {20, "Y0.1", 0},
          {20, "Y0.0", 1},
          // Stop key at 30 drops the self-holding CW rung.
          {29, "Y0.0", 1},
          {30, "Y0.0", 0},
          // CCW key at 40: spindle CCW.
          {40, "Y0.1", 1},
          {40, "Y0.0", 0},
          // +X held from 45 in manual mode: the MPS branch gives G2622.0.
          {44, "G2622.0", 0},
          {45, "G2622.0", 1},
          {49, "G2622.0", 1},
          {49, "Y0.1", 1},
          // Door opens at 50: ANI X483.0 drops jog and the spindle in the same tick.
          {50, "G2622.0", 0},
          {50, "Y0.1", 0},
          {51, "Y0.1", 0},
          // Auto key at 60: S1 clears R0.0-R0.4 (WAND R0 0xE0), SET R0.0 -> R0 = 1, G2620 = 1;
          // the manual lamp stays until the NC reports auto at 63.
          {59, "R0", 4},
          {60, "R0", 1},
          {60, "G2620", 1},
          {60, "Y480.2", 1},
          {60, "Y480.0", 0},
          {63, "Y480.0", 1},
          {63, "Y480.2", 0},
          // +X held again from 70, but auto mode: no jog.
          {70, "G2622.0", 0},
          {84, "G2622.0", 0},
          // Work light: ALT toggles on each rising edge of its input (functions-2 2.14).
          {74, "Y0.2", 0},
          {75, "Y0.2", 1},
          {79, "Y0.2", 1},
          {80, "Y0.2", 0},
          {99, "Y0.2", 0},
          // Increment key at 85 with +X still held: R0 = 8, G2620 = 8, and the jog rung (after
          // the mode rungs in PLC1) jogs in the same tick; +X released at 90.
          {85, "R0", 8},
          {85, "G2620", 8},
          {85, "G2622.0", 1},
          {89, "G2622.0", 1},
          {90, "G2622.0", 0},
          {87, "Y480.3", 0},
          {88, "Y480.3", 1},
          {99, "R0", 8},
      });
}

TEST(Examples, CoolantLube) {
  CliResult r = runCli(withEngine(coolant(), "interp"));
  checkTable(
      r,
      {
          // init: D10 = P10 = 100, D11 = P11 = 250 (params file); CMP ... <= 0 false: no default.
          {0, "D10", 100},
          {0, "D11", 250},
          {0, "D12", 0},
          // Coolant key at 5: ALT -> R10.0 = 1; STMR input on -> out = 1 at once -> Y0.3.
          {4, "Y0.3", 0},
          {5, "Y0.3", 1},
          {5, "R10.0", 1},
          {5, "Y481.5", 1},
          // Key again at 30 (now 300 ms): request off, off-delay starts, T2 = 0, pump runs on.
          {30, "R10.0", 0},
          {30, "Y481.5", 0},
          {30, "Y0.3", 1},
          {30, "T2", 0},
          // T2 = elapsed = now - 300: 200 at tick 50; 490 at tick 79; at 80 elapsed 500 >= 500:
          // out = 0 and T2 = preset (dialect-notes "Timers", STMR).
          {50, "T2", 200},
          {79, "Y0.3", 1},
          {79, "T2", 490},
          {80, "Y0.3", 0},
          {80, "T2", 500},
          // Lube oscillator (PLC2, one slice), period 10 ms. T10 (pause, 250 ms) starts at tick 0
          // and is done at tick 25 (now 250): R20.0 and Y0.4 on at 25. T11 (pulse, 100 ms)
          // starts at 26 (R20.0 is set after its rung at 25) and is done at 36 (now 360): R20.2
          // = 1, R20.0 off, Y0.4 off. Next pause starts at 37, done at 62 (620); pulse 63..73;
          // pause from 74, done at 99 (990).
          {24, "Y0.4", 0},
          {25, "Y0.4", 1},
          {35, "Y0.4", 1},
          {35, "T11", 90},
          {36, "Y0.4", 0},
          {36, "R20.2", 1},
          {36, "T11", 100},
          {37, "R20.2", 0},
          {37, "T11", 0},
          {61, "Y0.4", 0},
          {62, "Y0.4", 1},
          {72, "Y0.4", 1},
          {73, "Y0.4", 0},
          {98, "Y0.4", 0},
          {99, "Y0.4", 1},
          // Pressure switch on during the first pulse (28..37): no alarm at 36. Off during the
          // second: at 73 S3 latches R21.0 -> Y481.6, G3010.0, and D12 counts 1.
          {36, "Y481.6", 0},
          {72, "Y481.6", 0},
          {73, "Y481.6", 1},
          {73, "G3010.0", 1},
          {73, "D12", 1},
          {89, "Y481.6", 1},
          // Reset button at 90 clears the alarm; the failure count stays.
          {90, "Y481.6", 0},
          {90, "G3010.0", 0},
          {99, "D12", 1},
          // Level low from 85; key at 88: requested (lamp), STMR out = 1 (T2 back to 0), but ANI
          // X10.0 keeps the pump off until the level is back at 95.
          {88, "R10.0", 1},
          {88, "Y481.5", 1},
          {88, "T2", 0},
          {88, "Y0.3", 0},
          {94, "Y0.3", 0},
          {95, "Y0.3", 1},
      });
}

TEST(Examples, PartCounter) {
  CliResult r = runCli(withEngine(parts(), "interp"));
  checkTable(
      r, {
             // Tick 0: first-scan flag R33.0 resets CTUD C6 counting down: cv = preset P21 = 4.
             // PLC2: LT B0 D22 (0 < 1000) = 1, OOUT -> Y481.5 = 0.
             {0, "C6", 4},
             {0, "Y481.2", 0},
             {0, "B0", 0},
             {0, "C5", 0},
             {0, "Y481.5", 0},
             // Cycle 1 runs ticks 5..14: INC D40 ten times.
             {14, "D40", 10},
             {14, "D41", 0},
             // Tick 15: LDP F2561.2 -> R32.0; CTRC C5 1, CTR B0 1, CTUD C6 3 (counts rising edges,
             // hnc8-functions-1.md 3.3); LDF F2560.5 calls S2: D41 = 10, D40 = 0; PLC2 G2579 = B0.
             {15, "R32.0", 1},
             {15, "C5", 1},
             {15, "B0", 1},
             {15, "G2579", 1},
             {15, "C6", 3},
             {15, "D41", 10},
             {15, "D40", 0},
             {16, "R32.0", 0},
             // Cycle 2 (12 ticks), part 2.
             {31, "D40", 12},
             {32, "C5", 2},
             {32, "B0", 2},
             {32, "C6", 2},
             {32, "D41", 12},
             // Part 3 at 48: C5 reaches the preset D20 = 3 -> R30.0; PLS 0 sets the lamp Y481.3.
             {47, "D40", 8},
             {48, "C5", 3},
             {48, "R30.0", 1},
             {48, "Y481.3", 1},
             {48, "B0", 3},
             {48, "C6", 1},
             {48, "D41", 8},
             {49, "R30.0", 1},
             {49, "Y481.3", 1},
             // Scrap key at 52: R32.2 counts B0 down (input 3 on) to 2; C5 untouched.
             {52, "B0", 2},
             {52, "G2579", 2},
             {52, "C5", 3},
             // Manual part at 60 (ORP X12.6): C5 at its preset rings to 0 and R30.0 drops; the lamp
             // is latched. B0 up to 3. C6 1 -> 0 = start value: out = 1 -> Y481.2.
             {60, "R32.0", 1},
             {60, "C5", 0},
             {60, "R30.0", 0},
             {60, "Y481.3", 1},
             {60, "B0", 3},
             {60, "C6", 0},
             {60, "Y481.2", 1},
             // Part 5 at 75: C5 1, B0 4; C6 at the start value reloads the preset 4 (down counting
             // reloads, 3.3), out = 0.
             {74, "D40", 10},
             {75, "C5", 1},
             {75, "B0", 4},
             {75, "C6", 4},
             {75, "Y481.2", 0},
             {75, "D41", 10},
             // Batch reset at 85: C5 = 0 and the lamp is reset. Tool changed at 90: C6 = 4.
             {84, "Y481.3", 1},
             {85, "C5", 0},
             {85, "Y481.3", 0},
             {90, "C6", 4},
             {99, "B0", 4},
             {99, "G2579", 4},
             {99, "Y481.5", 0},
         });
}

TEST(Examples, JsonlMatchesCsv) {
  std::vector<std::string> args = withEngine(lathe(), "interp");
  CliResult csv = runCli(args);
  args.push_back("--format");
  args.push_back("jsonl");
  CliResult jsonl = runCli(args);
  ASSERT_EQ(jsonl.exitCode, 0) << jsonl.err;
  std::vector<std::string> rows = lines(jsonl.out);
  ASSERT_EQ(rows.size(), 100u);
  // Tick 85 of the lathe (see LathePanel): R0 = 8, G2620 = 8, G2622.0 = 1.
  EXPECT_NE(rows[85].find("{\"tick\":85,\"R0\":8,\"G2620\":8,\"G2564\":100,"), std::string::npos)
      << rows[85];
  EXPECT_NE(rows[85].find("\"G2622.0\":1,"), std::string::npos) << rows[85];
  EXPECT_EQ(csvValue(csv.out, 85, "G2622.0"), 1);
}

// The JIT must print exactly what the interpreter prints (STYLE.md 8/12).
TEST(Examples, JitMatchesInterpreter) {
  for (auto args : {lathe(), coolant(), parts()}) {
    CliResult interp = runCli(withEngine(args, "interp"));
    CliResult jit = runCli(withEngine(args, "jit"));
    EXPECT_EQ(jit.exitCode, 0) << jit.err;
    EXPECT_EQ(jit.out, interp.out) << args[1];
  }
}

} // namespace
} // namespace lj::clitest

// Symbols as command-line addresses (CLI.md "Addresses on the command line"): `--watch`,
// `--set` and stimulus items take a name wherever the program defines it, read as the address
// the symbol stands for (formats/Address.h parseAddressIn); the watch column keeps the name.
// HNC-8: a plc.dit's [symbols] (examples/lathe_panel.dit); FANUC: a mnemonic file's %@2-E
// section (examples/fanuc_coolant.pmc); IEC IL programs define no symbols.
#include "CliRunner.h"

#include <gtest/gtest.h>

namespace lj::clitest {
namespace {

bool says(const CliResult &r, const std::string &text) {
  return r.err.find(text) != std::string::npos;
}

// lathe_panel.symbols: CW_KEY X484.5, CW_CONTACTOR Y0.0. The program powers up in manual mode
// and the CW key starts the spindle there (examples/lathe_panel.stl, its .stim at tick 10).
TEST(SymbolAddress, Hnc8ContainerSymbolsInWatchSetAndStimulus) {
  const std::string dit = sourcePath("examples/lathe_panel.dit");
  const std::string stim = writeScratch("panel.stim", "@2 F2560=2\n@10 CW_KEY=1\n@12 cw_key=0\n");
  for (const char *engine : {"interp", "jit"}) {
    CliResult r = runCli({"run", dit, "--engine", engine, "--ticks", "20", "--stimulus", stim,
                          "--watch", "CW_CONTACTOR,Y0.0,CW_KEY"});
    ASSERT_EQ(r.exitCode, 0) << engine << ": " << r.err;
    EXPECT_EQ(lines(r.out).at(0), "tick,CW_CONTACTOR,Y0.0,CW_KEY");
    EXPECT_EQ(csvValue(r.out, 9, "CW_CONTACTOR"), 0);
    EXPECT_EQ(csvValue(r.out, 10, "CW_KEY"), 1);
    EXPECT_EQ(csvValue(r.out, 12, "CW_KEY"), 0); // names are case-insensitive
    EXPECT_EQ(csvValue(r.out, 15, "CW_CONTACTOR"), 1);
    for (long long t = 0; t < 20; ++t)
      EXPECT_EQ(csvValue(r.out, t, "CW_CONTACTOR"), csvValue(r.out, t, "Y0.0")) << t;
  }
  // --set with a symbol: the key held from power-up (a press needs its rising edge later).
  CliResult set = runCli({"run", dit, "--engine", "interp", "--ticks", "1", "--set", "GUARD_OPEN=1",
                          "--watch", "X483.0"});
  ASSERT_EQ(set.exitCode, 0) << set.err;
  EXPECT_EQ(csvValue(set.out, 0, "X483.0"), 1);
}

TEST(SymbolAddress, Hnc8UnknownNamesAndSymbolsOfNoValueAreUsageErrors) {
  const std::string dit = sourcePath("examples/lathe_panel.dit");
  // Not a symbol of the program: the address message as before.
  CliResult r = runCli({"run", dit, "--engine", "interp", "--watch", "COOLANT"});
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_TRUE(says(r, "--watch: bad address 'COOLANT'")) << r.err;
  // CLEAR_MODES names subroutine S1, which holds no value.
  r = runCli({"run", dit, "--engine", "interp", "--watch", "CLEAR_MODES"});
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_TRUE(says(r, "--watch: symbol 'CLEAR_MODES' = S1: bad address 'S1': unknown area"))
      << r.err;
  // A plain STL file has no symbols.
  const std::string stl = writeScratch("plain.stl", "LD X1.0\nOUT Y1.0\nEND1\nEND2\n");
  r = runCli({"run", stl, "--engine", "interp", "--set", "CW_KEY=1"});
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_TRUE(says(r, "--set: bad address 'CW_KEY'")) << r.err;
}

// fanuc_coolant.pmc %@2-E: ESP_OK X0.0, MF F7.0, M_CODE F10, COOLANT Y0.0, FIN G4.3; M08 turns
// the coolant on while the strobe is on (as FanucExamples.CoolantLube with addresses).
TEST(SymbolAddress, FanucMnemonicFileSymbolsInWatchSetAndStimulus) {
  const std::string pmc = sourcePath("examples/fanuc_coolant.pmc");
  const std::string stim = writeScratch("coolant.stim", "@100 M_CODE=8 MF=1\n@110 MF=0 M_CODE=0\n"
                                                        "@900 M_CODE=9 MF=1\n@910 MF=0\n");
  for (const char *engine : {"interp", "jit"}) {
    CliResult r = runCli({"run", pmc, "--engine", engine, "--ticks", "1000", "--period-ms", "8",
                          "--set", "ESP_OK=1", "--stimulus", stim, "--watch", "COOLANT,FIN,Y0.0"});
    ASSERT_EQ(r.exitCode, 0) << engine << ": " << r.err;
    EXPECT_EQ(lines(r.out).at(0), "tick,COOLANT,FIN,Y0.0");
    EXPECT_EQ(csvValue(r.out, 99, "COOLANT"), 0);
    EXPECT_EQ(csvValue(r.out, 100, "COOLANT"), 1); // M08 strobe at tick 100
    EXPECT_EQ(csvValue(r.out, 100, "FIN"), 1);     // FIN while the strobe is on
    EXPECT_EQ(csvValue(r.out, 110, "FIN"), 0);
    EXPECT_EQ(csvValue(r.out, 899, "COOLANT"), 1);
    EXPECT_EQ(csvValue(r.out, 900, "COOLANT"), 0); // M09
    for (long long t : {0, 100, 500, 950})
      EXPECT_EQ(csvValue(r.out, t, "COOLANT"), csvValue(r.out, t, "Y0.0")) << t;
  }
  // A name the file does not define: the address message as before.
  CliResult r = runCli({"run", pmc, "--engine", "interp", "--watch", "SPINDLE"});
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_TRUE(says(r, "--watch: bad address 'SPINDLE'")) << r.err;
}

// IEC IL names objects (`%Q0.0`); a program defines no symbols (docs/iec-il.md), so a name is
// refused as an object, as before.
TEST(SymbolAddress, IecNamesAreNoObjects) {
  CliResult r = runCli(
      {"run", sourcePath("examples/pump_station.il"), "--engine", "interp", "--watch", "PUMP1"});
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_TRUE(says(r, "--watch: bad address")) << r.err;
  r = runCli(
      {"run", sourcePath("examples/pump_station.il"), "--engine", "interp", "--watch", "%Q0.0"});
  EXPECT_EQ(r.exitCode, 0) << r.err;
}

} // namespace
} // namespace lj::clitest

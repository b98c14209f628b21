// The stimulus file's NC commands (`@TICK nc.NAME key=value ...`, docs/simulated-nc.md
// "Stimulus commands"): parsing, defaults, and `FILE:LINE: problem` errors; plus the order of a
// tick in the simulation driver (assignments, NC commands, beforeTick, scan, afterTick).
#include "formats/InputFiles.h"
#include "hosts/Simulation.h"

#include <gtest/gtest.h>

namespace lj::formats {
namespace {

std::string stimError(const std::string &text) {
  std::string error;
  EXPECT_FALSE(parseStimulus(text, "s.stim", error).has_value()) << text;
  return error;
}

TEST(NcStimulus, ParsesEveryCommand) {
  std::string error;
  auto st = parseStimulus("@0 nc.var type=1 offset=1 value=3.75\n"
                          "@0 nc.temp sensor=0 value=25\n"
                          "@0 nc.tool pocket=3 tool=12\n"
                          "@5 nc.reset ch=0\n"
                          "@10 nc.mcode ch=0 m=3\n"
                          "@10 X0.1=1\n"
                          "@20 nc.tcode t=12   # ch defaults to 0\n"
                          "@25 nc.scode ch=1 sp=2 s=1200.5\n"
                          "@30 nc.mpg n=0 delta=-5\n"
                          "@31 nc.end ch=3\n"
                          "@32 nc.zpulse axis=31\n"
                          "@33 nc.var type=3 offset=0 value=-9000000000\n",
                          "s.stim", error);
  ASSERT_TRUE(st.has_value()) << error;
  ASSERT_EQ(st->events.size(), 12u);
  const NcCommand &var = st->events[0].nc.at(0);
  EXPECT_EQ(var.kind, NcCommandKind::Var);
  EXPECT_EQ(var.index, 1);
  EXPECT_EQ(var.offset, 1);
  EXPECT_FALSE(var.isInteger);
  EXPECT_EQ(var.fvalue, 3.75);
  EXPECT_EQ(var.line, 1);
  EXPECT_EQ(st->events[1].nc.at(0).ivalue, 25);
  EXPECT_EQ(st->events[2].nc.at(0).index, 3);
  EXPECT_EQ(st->events[2].nc.at(0).ivalue, 12);
  EXPECT_EQ(st->events[3].nc.at(0).kind, NcCommandKind::Reset);
  EXPECT_EQ(st->events[4].tick, 10u);
  EXPECT_EQ(st->events[4].nc.at(0).code, 3);
  EXPECT_TRUE(st->events[4].sets.empty());
  EXPECT_TRUE(st->events[5].nc.empty());
  EXPECT_EQ(st->events[6].nc.at(0).ch, 0);
  EXPECT_EQ(st->events[6].nc.at(0).code, 12);
  const NcCommand &s = st->events[7].nc.at(0);
  EXPECT_EQ(s.ch, 1);
  EXPECT_EQ(s.code, 2);
  EXPECT_EQ(s.ivalue, 1200500); // 0.001 rpm (hnc8-cnc-interface.md 1.3)
  EXPECT_EQ(st->events[8].nc.at(0).ivalue, -5);
  EXPECT_EQ(st->events[9].nc.at(0).ch, 3);
  EXPECT_EQ(st->events[10].nc.at(0).index, 31);
  EXPECT_EQ(st->events[11].nc.at(0).ivalue, -9000000000LL); // type 3 is int64
}

TEST(NcStimulus, ErrorsNameFileLineAndProblem) {
  EXPECT_EQ(stimError("@1 nc.jump ch=0\n"),
            "s.stim:1: unknown NC command 'nc.jump' (expected nc.mcode, nc.tcode, nc.scode, "
            "nc.reset, nc.end, nc.var, nc.temp, nc.tool, nc.mpg, nc.zpulse)");
  EXPECT_EQ(stimError("\n@1 nc.mcode ch=0\n"), "s.stim:2: nc.mcode: missing m=");
  EXPECT_EQ(stimError("@1 nc.mcode ch=0 m=3 x=1\n"),
            "s.stim:1: nc.mcode: unknown key 'x' (expected ch= m=)");
  EXPECT_EQ(stimError("@1 nc.mcode m=3 m=4\n"), "s.stim:1: nc.mcode: key 'm' given twice");
  EXPECT_EQ(stimError("@1 nc.mcode ch=4 m=3\n"), "s.stim:1: nc.mcode: ch=4 is out of range 0..3");
  EXPECT_EQ(stimError("@1 nc.tcode t=abc\n"), "s.stim:1: nc.tcode: t=abc is not an integer");
  EXPECT_EQ(stimError("@1 nc.mcode 3\n"), "s.stim:1: nc.mcode: expected key=value, found '3'");
  EXPECT_EQ(stimError("@1 nc.var type=2 offset=0 value=1.5\n"),
            "s.stim:1: nc.var: type 2 holds integers, value=1.5 is not one");
  EXPECT_EQ(stimError("@1 nc.var type=5 offset=0 value=3000000000\n"),
            "s.stim:1: nc.var: value=3000000000 does not fit type 5 (32-bit integer)");
  EXPECT_EQ(stimError("@1 nc.var type=1 offset=0 value=x\n"),
            "s.stim:1: nc.var: value=x is not a number");
  EXPECT_EQ(stimError("@1 nc.scode sp=0 s=12.3456\n"),
            "s.stim:1: nc.scode: s=12.3456 is not a speed (rpm >= 0, at most 3 decimals, "
            "< 2147484)");
  EXPECT_EQ(stimError("@1 nc.temp sensor=20 value=1\n"),
            "s.stim:1: nc.temp: sensor=20 is out of range 0..19");
  EXPECT_EQ(stimError("@1 X0.0=1 nc.reset\n"),
            "s.stim:1: 'nc.reset': an NC command needs a line of its own (@TICK nc.COMMAND "
            "key=value ...)");
  // The tick order rule still applies to NC lines.
  EXPECT_EQ(stimError("@5 nc.reset\n@4 nc.reset\n"),
            "s.stim:2: tick 4 comes after tick 5 (line 1); ticks must not decrease");
}

// Tick order (docs/simulated-nc.md "Tick protocol"): the init part runs after the NC's
// power-up values, and a command at tick t is visible to the scan of tick t. A two-line
// "program" (init and PLC1 both copy F2608 into D0, D1) is built from plain entry functions.
uint32_t copyInit(void *, lj_state *s) {
  s->img.D[0] = s->img.F[2608];
  return LJ_FAULT_NONE;
}
uint32_t copyPlc1(void *, lj_state *s) {
  s->img.D[1] = s->img.F[2608];
  return LJ_FAULT_NONE;
}
uint32_t noSlice(void *, lj_state *, uint32_t) { return LJ_FAULT_NONE; }

TEST(NcStimulus, SimulationAppliesCommandsBeforeTheScan) {
  lj_entries e{nullptr, &copyInit, &copyPlc1, &noSlice, 1};
  std::string error;
  hosts::SimOptions opts;
  opts.ticks = 3;
  opts.stimulus = *parseStimulus("@1 nc.mcode ch=0 m=7\n", "s.stim", error);
  std::optional<CliAddress> d1 = parseAddress("D1", error);
  opts.watch.push_back(*d1);
  auto s = std::make_unique<lj_state>();
  hosts::SimNc nc;
  std::vector<int64_t> seen;
  simulate(
      e, *s, opts, [&](const hosts::WatchRow &r) { seen.push_back(r.values[0]); }, &nc);
  EXPECT_EQ(s->img.D[0], -1); // init saw the idle slot
  EXPECT_EQ(seen, (std::vector<int64_t>{-1, 7, 7}));
  EXPECT_EQ(s->host, nc.host());
}

TEST(NcStimulus, StimulusWordsAreLeftToTheStimulus) {
  lj_entries e{nullptr, &copyInit, &copyPlc1, &noSlice, 1};
  std::string error;
  hosts::SimOptions opts;
  opts.ticks = 2;
  opts.stimulus = *parseStimulus("@1 F2608=4\n@1 nc.mcode ch=0 m=7\n", "s.stim", error);
  auto s = std::make_unique<lj_state>();
  hosts::SimNc nc;
  hosts::simulate(e, *s, opts, nullptr, &nc);
  EXPECT_EQ(s->img.D[0], 0); // F2608 is the stimulus's: not even the idle -1 is written
  EXPECT_EQ(s->img.D[1], 4);
}

} // namespace
} // namespace lj::formats

// Unit tests of the stimulus and parameter file parsers and of the JSON state dump
// (formats: CLI.md `--stimulus`, `--params`, `--dump`; ordering rules: README "Stimulus files").
#include "formats/InputFiles.h"
#include "formats/StateJson.h"
#include "profiles/fanuc/FanucProfile.h"

#include <gtest/gtest.h>

#include <memory>

namespace lj::formats {
namespace {

TEST(Stimulus, LinesCommentsAndBlanks) {
  std::string e;
  std::optional<Stimulus> st = parseStimulus("# header comment\n"
                                             "\n"
                                             "@0 X1.0=1 D5=-3   # two assignments\n"
                                             "  @3\tx2=0x10\r\n"
                                             "@3 X1.0=0\n",
                                             "s.stim", e);
  ASSERT_TRUE(st) << e;
  ASSERT_EQ(st->events.size(), 3u);
  EXPECT_EQ(st->events[0].tick, 0u);
  EXPECT_EQ(st->events[0].line, 3);
  ASSERT_EQ(st->events[0].sets.size(), 2u);
  EXPECT_EQ(st->events[0].sets[1].addr.text, "D5");
  EXPECT_EQ(st->events[0].sets[1].value, -3);
  EXPECT_EQ(st->events[1].tick, 3u); // CRLF and leading blanks are fine
  EXPECT_EQ(st->events[1].sets[0].value, 16);
  EXPECT_EQ(st->events[2].tick, 3u); // equal ticks: kept in file order
}

std::string stimError(const char *text) {
  std::string e;
  EXPECT_FALSE(parseStimulus(text, "bad.stim", e).has_value()) << text;
  return e;
}

TEST(Stimulus, ErrorsNameFileLineAndProblem) {
  EXPECT_EQ(stimError("@1 X1.0=1\n@0 X1.0=0\n"),
            "bad.stim:2: tick 0 comes after tick 1 (line 1); ticks must not decrease");
  EXPECT_EQ(stimError("\nX1.0=1\n"),
            "bad.stim:2: expected '@TICK' at the start of the line, found 'X1.0=1'");
  EXPECT_EQ(stimError("@x X1.0=1\n"),
            "bad.stim:1: bad tick '@x': expected '@' and a decimal tick number");
  EXPECT_EQ(stimError("@-1 X1.0=1\n"),
            "bad.stim:1: bad tick '@-1': expected '@' and a decimal tick number");
  EXPECT_EQ(stimError("@4\n"), "bad.stim:1: no assignment after '@4' (expected ADDR=VALUE)");
  EXPECT_EQ(stimError("@4 X1.9=1\n"), "bad.stim:1: bad address 'X1.9': bit out of range (0..7)");
  EXPECT_EQ(stimError("@4 X1.0=5\n"), "bad.stim:1: bad value 5 for bit 'X1.0': expected 0 or 1");
  EXPECT_EQ(stimError("@4 X1.0 = 1\n"), "bad.stim:1: bad assignment 'X1.0': expected ADDR=VALUE");
  EXPECT_EQ(stimError("@1 T3=5\n").rfind("bad.stim:1: cannot write timer 'T3'", 0), 0u);
}

TEST(Params, OnePerLine) {
  std::string e;
  std::optional<std::vector<Assignment>> ps = parseParams(
      "# machine parameters\nP12=345\n p0 = -7  # spaces allowed\n\nP199=0x10\n", "m.params", e);
  ASSERT_TRUE(ps) << e;
  ASSERT_EQ(ps->size(), 3u);
  EXPECT_EQ((*ps)[0].addr.index, 12);
  EXPECT_EQ((*ps)[0].value, 345);
  EXPECT_EQ((*ps)[1].value, -7);
  EXPECT_EQ((*ps)[2].addr.index, 199);
  EXPECT_EQ((*ps)[2].value, 16);
}

TEST(Params, OnlyWholePElements) {
  std::string e;
  EXPECT_FALSE(parseParams("P1=1\nD1=2\n", "m.params", e));
  EXPECT_EQ(e, "m.params:2: 'D1' is not a parameter; expected Pn=VALUE (P0..P199)");
  EXPECT_FALSE(parseParams("P1.0=1\n", "m.params", e));
  EXPECT_EQ(e, "m.params:1: 'P1.0' is not a parameter; expected Pn=VALUE (P0..P199)");
  EXPECT_FALSE(parseParams("P200=1\n", "m.params", e));
  EXPECT_EQ(e, "m.params:1: bad address 'P200': element out of range (0..199)");
  EXPECT_FALSE(parseParams("P3=\n", "m.params", e));
  EXPECT_EQ(e, "m.params:1: bad value '': expected a number");
}

// A FANUC program's parameter file (docs/fanuc-pmc.md "System parameters"): the counter data
// type of the system parameter screen (ref 6.4 [L1971-L1973]) and PMC parameter values; with
// BCD, CTR's counter data is written as the decimal digits the screen shows.
TEST(Params, FanucCounterDataTypeAndValues) {
  const TargetProfile &tp = fanuc::profile();
  std::string e;
  std::optional<std::vector<Assignment>> ps = parseParams(
      "C0:2 = 20   # CTR 1 preset\nCOUNTER = bcd\nT0:2=30\nC5000:2 = 20\n", "f.params", e, &tp);
  ASSERT_TRUE(ps) << e;
  ASSERT_EQ(ps->size(), 4u);
  lj_state s;
  lj_state_reset(&s);
  for (const Assignment &a : *ps) writeAddress(s, a.addr, a.value);
  const auto *b = reinterpret_cast<const unsigned char *>(&s);
  EXPECT_EQ(b[tp.systemParams.counterFormat], TargetProfile::kCounterBcd);
  EXPECT_EQ(b[tp.elementOffset(Area::CounterData, 0)], 0x20); // BCD 20, low byte first
  EXPECT_EQ(b[tp.elementOffset(Area::CounterData, 1)], 0x00);
  EXPECT_EQ(b[tp.elementOffset(Area::TimerData, 0)], 30);      // T is not counter data
  EXPECT_EQ(b[tp.elementOffset(Area::CounterData, 5000)], 20); // CTRB's count: binary
  ps = parseParams("COUNTER = BINARY\nC0:2 = 20\n", "f.params", e, &tp);
  ASSERT_TRUE(ps) << e;
  EXPECT_EQ((*ps)[0].value, TargetProfile::kCounterBinary);
  EXPECT_EQ((*ps)[1].value, 20);
}

TEST(Params, FanucBcdCounterValueThatIsNotBcdIsALocatedError) {
  const TargetProfile &tp = fanuc::profile();
  std::string e;
  EXPECT_FALSE(parseParams("COUNTER = BCD\nC0:2 = 12000\n", "f.params", e, &tp));
  EXPECT_EQ(e, "f.params:2:8: counter value 12000 of C0:2 is not BCD: the counter data type is "
               "BCD and C0:2 holds 4 digits (0..9999)");
  EXPECT_FALSE(parseParams("C4 = 100\nCOUNTER=BCD\n", "f.params", e, &tp));
  EXPECT_EQ(e, "f.params:1:6: counter value 100 of C4 is not BCD: the counter data type is BCD "
               "and C4 holds 2 digits (0..99)");
  EXPECT_FALSE(parseParams("COUNTER = BCD\nC2:2 = -1\n", "f.params", e, &tp));
  EXPECT_EQ(e.substr(0, 12), "f.params:2:8");
  // In binary the same values are fine.
  EXPECT_TRUE(parseParams("C0:2 = 12000\n", "f.params", e, &tp)) << e;
  EXPECT_FALSE(parseParams("COUNTER = DECIMAL\n", "f.params", e, &tp));
  EXPECT_EQ(e, "f.params:1:11: the counter data type is BCD or BINARY, got 'DECIMAL' (COUNTER = "
               "BCD or COUNTER = BINARY)");
  EXPECT_FALSE(parseParams("  R0 = 1\n", "f.params", e, &tp));
  EXPECT_EQ(e, "f.params:1:3: 'R0' is not a PMC parameter (areas T, C, K, D)");
}

TEST(ReadFile, MissingFileNamed) {
  std::string text, e;
  EXPECT_FALSE(readFile("/nonexistent/dir/x.stim", text, e));
  EXPECT_NE(e.find("cannot read '/nonexistent/dir/x.stim'"), std::string::npos);
  EXPECT_FALSE(readFile("/", text, e));
  EXPECT_NE(e.find("is a directory"), std::string::npos);
}

TEST(StateJson, CompleteState) {
  auto s = std::make_unique<lj_state>();
  lj_state_reset(s.get());
  s->img.X[1] = 0x81;
  s->img.W[7] = -5;
  s->img.D[5] = -3;
  s->img.P[199] = 42;
  s->T[129].elapsed_ms = 77; // slot 129 = T301
  s->T[129].out = 1;
  s->C[3].value = 9;
  s->alt_state[511] = 1;
  s->edge[16383] = 1;
  s->now_ms = 123;
  s->plc2_next_slice = 2;
  s->fault_watchdog = 4;
  nlohmann::ordered_json j = stateToJson(*s);
  EXPECT_EQ(j["now_ms"], 123);
  EXPECT_EQ(j["plc2_next_slice"], 2);
  EXPECT_EQ(j["max_backward_steps"], 1000000); // lj_state_reset default (DIALECT.md 4)
  EXPECT_EQ(j["faults"]["watchdog"], 4);
  EXPECT_EQ(j["areas"]["X"].size(), 513u);
  EXPECT_EQ(j["areas"]["X"][1], 129); // u8 zero-extended
  EXPECT_EQ(j["areas"]["W"][7], -5);  // i16 sign-extended
  EXPECT_EQ(j["areas"]["D"][5], -3);
  EXPECT_EQ(j["areas"]["F"].size(), 3120u);
  EXPECT_EQ(j["areas"]["P"][199], 42);
  ASSERT_EQ(j["timers"].size(), 256u);
  EXPECT_EQ(j["timers"][129]["n"], 301);
  EXPECT_EQ(j["timers"][129]["elapsed_ms"], 77);
  EXPECT_EQ(j["timers"][129]["out"], 1);
  EXPECT_EQ(j["counters"][3]["value"], 9);
  EXPECT_EQ(j["counters"][255]["n"], 427);
  EXPECT_EQ(j["alt_state"][511], 1);
  EXPECT_EQ(j["edge"].size(), 16384u);
  EXPECT_EQ(j["edge"][16383], 1);
  EXPECT_EQ(j["pls_prev"].size(), 512u);
  // The dump round-trips through text.
  EXPECT_EQ(nlohmann::ordered_json::parse(j.dump()), j);
}

} // namespace
} // namespace lj::formats

// The pin plan of the HAL component (hosts/linuxcnc/HalPlan.h) without HAL: default pins from a
// program, the map file rules of docs/linuxcnc.md "Map file", HAL's name rules.
#include "hosts/linuxcnc/HalPlan.h"
#include "verify/Verify.h"

#include "pipeline/ProgramFile.h"

#include <gtest/gtest.h>

#include <cstring>
#include <memory>

namespace {

using lj::hal::PinSpec;
using lj::hal::PinType;

lj::VerifiedProgram verify(const std::string &text) {
  lj::pipeline::ProgramSource src;
  src.path = "t.stl";
  src.text = text;
  std::string diags;
  auto prog = lj::pipeline::verifyProgram(src, 200, diags);
  EXPECT_TRUE(prog.has_value()) << diags;
  return *prog;
}

std::vector<std::string> names(const std::vector<PinSpec> &pins) {
  std::vector<std::string> out;
  for (const PinSpec &p : pins) out.push_back((p.out ? "out " : "in ") + p.name);
  return out;
}

const char *kProgram = "LD X0.1\nOR Y2.0\nANI X0.0\nOUT Y2.0\nMOV X3 D0\nLD Y0.5\nOUT R1.0\n"
                       "1END\n2END\n";

TEST(HalPlan, DefaultPinsAreXBitsReadAndYBitsWritten) {
  // X0.0, X0.1 contacts; X3 read as a byte: its 8 bits; Y2.0 written; Y0.5 only read: no pin.
  std::vector<std::string> want = {"in x0.0", "in x0.1"};
  for (int b = 0; b < 8; ++b) want.push_back("in x3." + std::to_string(b));
  want.push_back("out y2.0");
  EXPECT_EQ(names(lj::hal::defaultPins(verify(kProgram))), want);
}

TEST(HalPlan, MapReplacesAddsAndDropsDefaults) {
  auto pins = lj::hal::defaultPins(verify(kProgram));
  std::string err;
  ASSERT_TRUE(lj::hal::applyMap("in bit X0.0 stop # comment\nout s32 D0 d0\n"
                                "out float D0 d0-tenth scale=0.1\n",
                                "m", pins, err))
      << err;
  EXPECT_EQ(pins[0].name, "stop");
  EXPECT_EQ(pins[0].addr.text, "X0.0");
  EXPECT_EQ(pins.back().name, "d0-tenth");
  EXPECT_EQ(pins.back().type, PinType::Float);
  EXPECT_DOUBLE_EQ(pins.back().scale, 0.1);
  EXPECT_EQ(pins.size(), 11u + 2u);

  auto only = lj::hal::defaultPins(verify(kProgram));
  ASSERT_TRUE(lj::hal::applyMap("nodefaults\nin s32 F2560 nc-mode\n", "m", only, err)) << err;
  ASSERT_EQ(only.size(), 1u);
  EXPECT_EQ(only[0].name, "nc-mode");
  EXPECT_FALSE(only[0].out);
}

TEST(HalPlan, BadMapLinesNameFileAndLine) {
  struct Case {
    const char *text, *want;
  } cases[] = {
      {"\nsideways bit X0.0\n", "m:2: direction 'sideways'"},
      {"in bool X0.0\n", "m:1: type 'bool'"},
      {"in bit D5\n", "a bit pin needs a bit address"},
      {"in s32 X0.1\n", "a s32 pin a whole element"},
      {"out s32 T5\n", "timers and counters cannot be mapped"},
      {"in bit X0.0 a\nin s32 X0\nin bit X0.0 b\n", "m:3: 'X0.0' is mapped as an input twice"},
      {"out s32 D0 d scale=2\n", "scale= is for float pins only"},
      {"out float D0 d scale=0\n", "the scale must be a non-zero number"},
      {"out bit Y0.0 9lives\n", "pin name '9lives' must start with a letter"},
      {"out bit Y0.0 a b\n", "unexpected 'b'"},
      {"in bit X999.0\n", "X999"},
      {"in\n", "expected `in|out"},
  };
  for (const Case &c : cases) {
    std::vector<PinSpec> pins;
    std::string err;
    EXPECT_FALSE(lj::hal::applyMap(c.text, "m", pins, err)) << c.text;
    EXPECT_NE(err.find(c.want), std::string::npos) << c.text << " -> " << err;
  }
}

TEST(HalPlan, NamesMustBeUniqueAndFitHal) {
  std::vector<PinSpec> pins;
  std::string err;
  ASSERT_TRUE(lj::hal::applyMap("in bit X0.0 same\nout bit Y0.0 same\n", "m", pins, err)) << err;
  EXPECT_FALSE(lj::hal::checkPins(pins, "ladderjit", err));
  EXPECT_NE(err.find("two pins are named 'ladderjit.same'"), std::string::npos) << err;

  std::vector<PinSpec> longName;
  std::string name(38, 'a'); // "ladderjit." + 38 = 48 > HAL_NAME_LEN 47
  ASSERT_TRUE(lj::hal::applyMap("in bit X0.0 " + name + "\n", "m", longName, err)) << err;
  EXPECT_FALSE(lj::hal::checkPins(longName, "ladderjit", err));
  EXPECT_NE(err.find("longer than HAL's 47 characters"), std::string::npos) << err;
  longName[0].name.pop_back(); // 47: accepted
  EXPECT_TRUE(lj::hal::checkPins(longName, "ladderjit", err)) << err;
}

TEST(HalPlan, SymbolsNameDefaultPinsWhenHalFriendly) {
  lj::VerifiedProgram prog = verify("LD X0.0\nLD X0.1\nANB\nOUT Y0.0\n1END\n2END\n");
  prog.symbols = {{"Start_Key", "X0.0", ""}, {"主轴", "X0.1", ""}, {"LAMP", "Y0.0", ""}};
  EXPECT_EQ(names(lj::hal::defaultPins(prog)),
            (std::vector<std::string>{"in start_key", "in x0.1", "out lamp"}));
}

} // namespace

namespace {

lj::VerifiedProgram verifyIn(const char *dialect, const char *path, const std::string &text) {
  lj::pipeline::ProgramSource src;
  src.path = path;
  src.text = text;
  src.dialect = lj::pipeline::dialectNamed(dialect);
  std::string diags;
  auto prog = lj::pipeline::verifyProgram(src, 200, diags);
  EXPECT_TRUE(prog.has_value()) << diags;
  return *prog;
}

TEST(HalPlan, FanucPinsAndMapUseFanucAddresses) {
  // Reads X0.0 and X200.3 (the second X range), writes Y0.1; R only internal: no pin.
  auto prog =
      verifyIn("fanuc", "t.pmc", "RD X0.0\nAND X200.3\nWRT Y0.1\nWRT R5.0\nEND1\nEND2\nEND\n");
  const lj::pipeline::Dialect &d = *lj::pipeline::dialectNamed("fanuc");
  std::vector<PinSpec> pins = lj::hal::defaultPins(prog, d);
  EXPECT_EQ(names(pins), (std::vector<std::string>{"in x0.0", "in x200.3", "out y0.1"}));
  // The pin writes the FANUC byte X200 in lj_state.mem, not HNC-8's X200 in lj_image.
  auto s = std::make_unique<lj_state>();
  lj_state_reset(s.get());
  lj::formats::writeAddress(*s, pins[1].addr, 1);
  std::string err;
  auto x200 = d.parseAddress("X200.3", err);
  ASSERT_TRUE(x200) << err;
  EXPECT_EQ(lj::formats::readAddress(*s, *x200), 1);
  EXPECT_EQ(s->img.X[200], 0);
  std::string error;
  ASSERT_TRUE(lj::hal::applyMap("in s32 D100:2 preset\nout bit K0.1\n", "m.map", pins, error, d))
      << error;
  EXPECT_EQ(pins[3].name, "preset");
  EXPECT_EQ(pins[3].addr.width, 2);
  EXPECT_EQ(pins[4].name, "k0.1");
  EXPECT_FALSE(lj::hal::applyMap("in s32 D9999:2\n", "m.map", pins, error, d));
  EXPECT_NE(error.find("m.map:1: bad address 'D9999:2'"), std::string::npos) << error;
}

TEST(HalPlan, IecPinsDropThePercentSign) {
  auto prog = verifyIn("iec", "t.il", "000 LD %I0.2\n001 ST %Q0.1\n");
  EXPECT_EQ(names(lj::hal::defaultPins(prog, *lj::pipeline::dialectNamed("iec"))),
            (std::vector<std::string>{"in i0.2", "out q0.1"}));
}

// The ClassicLadder drop-in (docs/linuxcnc.md "ClassicLadder drop-in"): classicladder_rt's pins
// for its sizes (classicladder.md 3.3: in-NN, out-NN, s32in-NN, s32out-NN, floatin-NN,
// floatout-NN; NN %02d; a value > 0 overrides the defaults 15, 15, 10, 10, 10, 10).
TEST(HalPlan, ClassicLadderPinsAreClassicladderRtsForItsSizes) {
  const lj::pipeline::Dialect &cl = *lj::pipeline::dialectNamed("classicladder");
  std::vector<PinSpec> pins;
  std::string error;
  ASSERT_TRUE(lj::hal::classicLadderPins({}, cl, pins, error)) << error;
  ASSERT_EQ(pins.size(), 70u); // the defaults: 15 + 15 + 10 + 10 + 10 + 10
  EXPECT_EQ(pins[0].name, "in-00");
  EXPECT_EQ(pins[14].name, "in-14");
  EXPECT_EQ(pins[15].name, "out-00");
  EXPECT_EQ(pins[30].name, "s32in-00");
  EXPECT_EQ(pins[69].name, "floatout-09");
  EXPECT_FALSE(pins[0].out);
  EXPECT_TRUE(pins[15].out);
  EXPECT_EQ(pins[0].type, PinType::Bit);
  EXPECT_EQ(pins[30].type, PinType::S32);
  EXPECT_EQ(pins[50].type, PinType::Float); // floatin-00
  EXPECT_TRUE(pins[50].truncate) << "ClassicLadder reads a float input truncated toward zero";
  EXPECT_FALSE(pins[60].truncate); // floatout-00
  EXPECT_EQ(cl.formatAddress(pins[14].addr), "%I14");
  EXPECT_EQ(cl.formatAddress(pins[30].addr), "%IW0");
  EXPECT_EQ(cl.formatAddress(pins[69].addr), "%QF9");

  // Sizes as loadrt gives them: 0 or negative keeps the default; past 99 the name has 3 digits.
  ASSERT_TRUE(lj::hal::classicLadderPins({120, 2, -1, 0, 1, 1}, cl, pins, error)) << error;
  EXPECT_EQ(pins.size(), 120u + 2 + 10 + 10 + 1 + 1);
  EXPECT_EQ(pins[119].name, "in-119");
  EXPECT_EQ(pins[120].name, "out-00");

  // Beyond the classicladder profile (%I0..%I511): refused, naming the parameter.
  EXPECT_FALSE(lj::hal::classicLadderPins({600, 0, 0, 0, 0, 0}, cl, pins, error));
  EXPECT_NE(error.find("numPhysInputs=600"), std::string::npos) << error;
  // The default set passes HAL's name rules under classicladder_rt's prefix.
  ASSERT_TRUE(lj::hal::classicLadderPins({}, cl, pins, error)) << error;
  EXPECT_TRUE(lj::hal::checkPins(pins, lj::hal::kClassicPrefix, error)) << error;
}

// The refresh's copy through resolved addresses (formats::resolveAddress) writes and reads
// exactly what writeAddress / readAddress do, for every kind of pin address of each dialect:
// bits in bytes and words, signed and unsigned elements of 1, 2 and 4 bytes, FANUC's second X
// range and `:2` words, a counter (not direct: the slow path).
TEST(HalPlan, ResolvedCopyEqualsWriteAndReadAddress) {
  const std::vector<std::pair<const char *, std::vector<const char *>>> cases = {
      {"hnc8", {"X0.0", "X3.7", "Y2.5", "R1.3", "G2620.15", "D5", "W3", "B2", "P1", "C3", "C3.0"}},
      {"fanuc", {"X0.1", "X200.3", "Y1.7", "R9000.2", "D100:2", "D200:4", "D9", "K0.1"}},
      {"iec", {"%I0.2", "%Q0.1", "%M5", "%MW3", "%KW0"}},
      {"classicladder", {"%I14", "%Q3", "%B7", "%IW0", "%QW9", "%W2"}}};
  uint32_t seed = 12345;
  auto next = [&seed] {
    seed = seed * 1103515245u + 12345u;
    return static_cast<int64_t>(static_cast<int32_t>(seed));
  };
  for (const auto &[dialect, addrs] : cases) {
    const lj::pipeline::Dialect &d = *lj::pipeline::dialectNamed(dialect);
    for (const char *text : addrs) {
      std::string err;
      auto a = d.parseAddress(text, err);
      ASSERT_TRUE(a) << dialect << " " << text << ": " << err;
      const lj::formats::ResolvedAddress r = lj::formats::resolveAddress(*a);
      EXPECT_EQ(r.direct, a->area != lj::Area::Counter && a->area != lj::Area::Timer) << text;
      auto s1 = std::make_unique<lj_state>(), s2 = std::make_unique<lj_state>();
      lj_state_reset(s1.get());
      lj_state_reset(s2.get());
      for (int k = 0; k < 40; ++k) {
        const int64_t v = a->isBit() ? (next() & 1) : next();
        lj::formats::writeAddress(*s1, *a, v);
        lj::formats::writeResolved(*s2, r, *a, v);
        ASSERT_EQ(std::memcmp(s1.get(), s2.get(), sizeof(lj_state)), 0) << dialect << " " << text;
        EXPECT_EQ(lj::formats::readResolved(*s2, r, *a), lj::formats::readAddress(*s1, *a))
            << dialect << " " << text;
        // Another value under the bit: the bit's neighbours are kept.
        if (a->isBit()) std::memset(reinterpret_cast<char *>(s1.get()) + r.offset, 0x5a, 1);
        if (a->isBit()) std::memset(reinterpret_cast<char *>(s2.get()) + r.offset, 0x5a, 1);
      }
    }
  }
}

} // namespace

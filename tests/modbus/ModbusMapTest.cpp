// Map files (docs/modbus-map.md "Map files"): FANUC and IEC addresses, the element layout of
// each table, what is writable and retained, and a clear error for every bad line.
#include "services/ModbusServer.h"

#include "pipeline/Dialects.h"

#include <gtest/gtest.h>

#include <memory>

using namespace lj;
using namespace lj::services;
namespace formats = lj::formats;

namespace {

std::unique_ptr<lj_state> fresh() {
  auto s = std::make_unique<lj_state>();
  lj_state_reset(s.get());
  return s;
}

ModbusMap parseOk(const char *dialect, const char *text) {
  std::string err;
  auto m = ModbusMap::parse(text, "m.map", *pipeline::dialectNamed(dialect), err);
  EXPECT_TRUE(m) << err;
  return m ? *m : ModbusMap{};
}

std::string parseErr(const char *dialect, const char *text) {
  std::string err;
  auto m = ModbusMap::parse(text, "m.map", *pipeline::dialectNamed(dialect), err);
  EXPECT_FALSE(m) << text;
  return err;
}

int64_t get(const lj_state &s, const char *dialect, const char *addr) {
  std::string err;
  auto a = pipeline::dialectNamed(dialect)->parseAddress(addr, err);
  EXPECT_TRUE(a) << err;
  return a ? formats::readAddress(s, *a) : -999;
}

void set(lj_state &s, const char *dialect, const char *item) {
  std::string err;
  auto a = pipeline::dialectNamed(dialect)->parseAssignment(item, err);
  ASSERT_TRUE(a) << err;
  formats::writeAddress(s, a->addr, a->value);
}

TEST(ModbusMapFile, FanucBitsBytesAndWords) {
  ModbusMap m = parseOk("fanuc", "# FANUC panel\n"
                                 "coils 0 Y0.0 16      # Y0.0..Y1.7\n"
                                 "discrete 0 X0.0 16\n"
                                 "coils 100 K0.0 8\n"
                                 "holding 0 R100 4     # bytes R100..R103\n"
                                 "holding 10 D100:2 3  # D100, D102, D104\n"
                                 "holding 20 D200:4 2  # two registers each\n"
                                 "input 0 F0 4\n");
  auto s = fresh();
  set(*s, "fanuc", "Y1.2=1");
  set(*s, "fanuc", "X0.7=1");
  set(*s, "fanuc", "R101=200");
  set(*s, "fanuc", "D102:2=-2");
  set(*s, "fanuc", "D204:4=0x12345678");
  std::vector<uint8_t> bits;
  ASSERT_EQ(mbmap::readBits(m, MbTable::Coils, 8, 8, *s, bits), 0);
  EXPECT_EQ(bits, (std::vector<uint8_t>{0, 0, 1, 0, 0, 0, 0, 0})); // Y1.0..Y1.7
  ASSERT_EQ(mbmap::readBits(m, MbTable::DiscreteInputs, 7, 1, *s, bits), 0);
  EXPECT_EQ(bits[0], 1);
  std::vector<uint16_t> regs;
  ASSERT_EQ(mbmap::readRegisters(m, MbTable::HoldingRegisters, 0, 4, *s, regs), 0);
  EXPECT_EQ(regs, (std::vector<uint16_t>{0, 200, 0, 0})); // a byte reads 0..255
  ASSERT_EQ(mbmap::readRegisters(m, MbTable::HoldingRegisters, 10, 3, *s, regs), 0);
  EXPECT_EQ(regs, (std::vector<uint16_t>{0, 0xFFFE, 0}));
  ASSERT_EQ(mbmap::readRegisters(m, MbTable::HoldingRegisters, 22, 2, *s, regs), 0);
  EXPECT_EQ(regs, (std::vector<uint16_t>{0x5678, 0x1234})); // low word first
  EXPECT_EQ(mbmap::readRegisters(m, MbTable::HoldingRegisters, 4, 1, *s, regs),
            kMbIllegalDataAddress);

  // Writes: D is retained (fanuc-pmc.md 1.3), R is not; X and F only with writeInputs.
  std::vector<formats::Assignment> w;
  bool retained = true;
  ASSERT_EQ(mbmap::planRegisterWrite(m, 0, {7}, false, w, retained), 0);
  EXPECT_FALSE(retained);
  ASSERT_EQ(mbmap::planRegisterWrite(m, 11, {0x8000}, false, w, retained), 0);
  EXPECT_TRUE(retained);
  ASSERT_EQ(w.size(), 1u);
  formats::writeAddress(*s, w[0].addr, w[0].value);
  EXPECT_EQ(get(*s, "fanuc", "D102:2"), -32768);
  EXPECT_EQ(mbmap::planRegisterWrite(m, 21, {1, 2}, false, w, retained), kMbIllegalDataAddress);
  EXPECT_EQ(mbmap::planRegisterWrite(m, 0, {256}, false, w, retained), kMbIllegalDataValue);
  ASSERT_EQ(mbmap::planCoilWrite(m, 103, {1}, false, w, retained), 0);
  EXPECT_TRUE(retained); // K is a keep relay
  EXPECT_EQ(w[0].addr.area, Area::KeepRelay);
  EXPECT_EQ(w[0].addr.bit, 3);
  EXPECT_EQ(mbmap::planCoilWrite(m, 0, {1}, false, w, retained), 0);
  EXPECT_FALSE(retained);
}

// A START ADDRESS may be a symbol of the program (examples/fanuc_coolant.pmc's %@2-E defines
// COOLANT Y0.0 and M_CODE F10); the map reads it as the address it stands for.
TEST(ModbusMapFile, SymbolsOfTheProgramAsStartAddresses) {
  const std::vector<Symbol> symbols = {
      {"COOLANT", "Y0.0", "COOLANT PUMP"}, {"M_CODE", "F10", "M CODE"}, {"CLEAR", "L3", ""}};
  std::string err;
  auto m = ModbusMap::parse("coils 0 coolant 8\ninput 0 M_CODE\n", "m.map",
                            *pipeline::dialectNamed("fanuc"), err, symbols);
  ASSERT_TRUE(m) << err;
  auto s = fresh();
  set(*s, "fanuc", "Y0.0=1");
  set(*s, "fanuc", "F10=8");
  std::vector<uint8_t> bits;
  ASSERT_EQ(mbmap::readBits(*m, MbTable::Coils, 0, 2, *s, bits), 0);
  EXPECT_EQ(bits, (std::vector<uint8_t>{1, 0})); // Y0.0, Y0.1
  std::vector<uint16_t> regs;
  ASSERT_EQ(mbmap::readRegisters(*m, MbTable::InputRegisters, 0, 1, *s, regs), 0);
  EXPECT_EQ(regs, (std::vector<uint16_t>{8}));
  // Without the symbols the name is no address; a symbol of a label names no value.
  EXPECT_FALSE(
      ModbusMap::parse("coils 0 COOLANT 8\n", "m.map", *pipeline::dialectNamed("fanuc"), err));
  EXPECT_NE(err.find("bad address 'COOLANT'"), std::string::npos) << err;
  EXPECT_FALSE(
      ModbusMap::parse("coils 0 CLEAR\n", "m.map", *pipeline::dialectNamed("fanuc"), err, symbols));
  EXPECT_NE(err.find("m.map:1: symbol 'CLEAR' = L3: bad address 'L3'"), std::string::npos) << err;
}

TEST(ModbusMapFile, IecObjects) {
  auto s = fresh();
  set(*s, "iec", "%M3=1");
  set(*s, "iec", "%M64=1");
  set(*s, "iec", "%MW11=-3");
  std::vector<uint8_t> bits;
  // %M0..%M63 (retained) and %M64.. are two areas: one line may not span both.
  std::string e = parseErr("iec", "coils 0 %M60 8\n");
  EXPECT_NE(e.find("m.map:1:"), std::string::npos) << e;
  EXPECT_NE(e.find("element 5 would be '%M64'"), std::string::npos) << e;
  ModbusMap m2 = parseOk("iec", "coils 0 %M0 64\ncoils 64 %M64 64\nholding 0 %MW10 4\n"
                                "discrete 0 %I0.0 8\ninput 0 %KW0 2\n");
  ASSERT_EQ(mbmap::readBits(m2, MbTable::Coils, 0, 5, *s, bits), 0);
  EXPECT_EQ(bits, (std::vector<uint8_t>{0, 0, 0, 1, 0}));
  ASSERT_EQ(mbmap::readBits(m2, MbTable::Coils, 64, 1, *s, bits), 0);
  EXPECT_EQ(bits[0], 1);
  std::vector<uint16_t> regs;
  ASSERT_EQ(mbmap::readRegisters(m2, MbTable::HoldingRegisters, 0, 2, *s, regs), 0);
  EXPECT_EQ(regs, (std::vector<uint16_t>{0, 0xFFFD}));
  std::vector<formats::Assignment> w;
  bool retained = false;
  ASSERT_EQ(mbmap::planCoilWrite(m2, 5, {1}, false, w, retained), 0);
  EXPECT_TRUE(retained); // %M0..%M63 survive a power failure (modicon-neza.md L542)
  ASSERT_EQ(mbmap::planCoilWrite(m2, 70, {1}, false, w, retained), 0);
  EXPECT_FALSE(retained);
}

TEST(ModbusMapFile, ConstantsAndInputsAreReadOnly) {
  ModbusMap m = parseOk("iec", "holding 0 %KW0 2\ncoils 0 %I0.0 8\n");
  std::vector<formats::Assignment> w;
  bool retained = false;
  EXPECT_EQ(mbmap::planRegisterWrite(m, 0, {1}, false, w, retained), kMbIllegalDataAddress);
  EXPECT_EQ(mbmap::planCoilWrite(m, 0, {1}, false, w, retained), kMbIllegalDataAddress);
  EXPECT_EQ(mbmap::planCoilWrite(m, 0, {1}, true, w, retained), 0); // --modbus-write-inputs
}

TEST(ModbusMapFile, BadLinesAreNamed) {
  struct Case {
    const char *dialect, *text, *want;
  } cases[] = {
      {"fanuc", "coils 0 Q0.0\n", "m.map:1: bad address"},
      {"fanuc", "registers 0 D0\n", "unknown table 'registers' (coils, discrete, holding, input)"},
      {"fanuc", "holding 70000 D0\n", "start '70000': expected 0..65535"},
      {"fanuc", "holding 0 D0 0\n", "count '0': expected 1..65536"},
      {"fanuc", "holding 0 D0 x\n", "count 'x'"},
      {"fanuc", "holding 0\n", "expected TABLE START ADDRESS [COUNT]"},
      {"fanuc", "coils 0 D100\n", "coils take bit addresses"},
      {"fanuc", "holding 0 X0.1\n", "holding take element addresses"},
      {"fanuc", "holding 0 D9999:2\n", "D9999:2"},
      {"fanuc", "holding 0 D9990:2 10\n", "run out of its area"},
      {"fanuc", "discrete 0 X120.0 128\n", "run out of its area"}, // X128..X199 do not exist
      {"fanuc", "holding 65530 D0:4 4\n", "run past Modbus address 65535"},
      {"fanuc", "holding 0 D0 10\n# x\nholding 5 R0\n", "m.map:3: holding 5..5 overlap line 1"},
      {"iec", "holding 0 %MW9999\n", "m.map:1: bad address"},
      {"iec", "coils 0 %Z1\n", "m.map:1: bad address"},
      {"fanuc", "# nothing\n\n", "maps nothing"},
  };
  for (const Case &c : cases) {
    std::string e = parseErr(c.dialect, c.text);
    EXPECT_NE(e.find(c.want), std::string::npos) << c.text << " -> " << e;
  }
}

TEST(ModbusMapFile, Hnc8BuiltInUnchanged) {
  // The built-in map answers as before (docs/modbus-map.md): B2 at 2004/2005, Y1.0 at coil 8.
  auto s = fresh();
  s->img.B[2] = -100000;
  s->img.Y[1] = 1;
  std::vector<uint16_t> regs;
  ASSERT_EQ(mbmap::readRegisters(MbTable::HoldingRegisters, 2004, 2, *s, regs), 0);
  EXPECT_EQ(static_cast<int32_t>(uint32_t{regs[0]} | uint32_t{regs[1]} << 16), -100000);
  std::vector<uint8_t> bits;
  ASSERT_EQ(mbmap::readBits(MbTable::Coils, 8, 1, *s, bits), 0);
  EXPECT_EQ(bits[0], 1);
  // An HNC-8 map file takes HNC-8 addresses.
  ModbusMap m = parseOk("hnc8", "holding 0 B0 50\ncoils 0 Y0.0 16\n");
  ASSERT_EQ(mbmap::readRegisters(m, MbTable::HoldingRegisters, 4, 2, *s, regs), 0); // B2
  EXPECT_EQ(static_cast<int32_t>(uint32_t{regs[0]} | uint32_t{regs[1]} << 16), -100000);
  std::vector<formats::Assignment> w;
  bool retained = false;
  ASSERT_EQ(mbmap::planRegisterWrite(m, 0, {1, 0}, false, w, retained), 0);
  EXPECT_TRUE(retained);
}

} // namespace

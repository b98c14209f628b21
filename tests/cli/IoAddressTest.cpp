// Unit tests of command-line addresses and values (CLI.md "Addresses on the command line";
// widths, signedness and ranges from DIALECT.md 1; number syntax from docs/dialect-notes.md).
#include "formats/Address.h"

#include <gtest/gtest.h>

#include <memory>

namespace lj::formats {
namespace {

CliAddress addr(const char *text) {
  std::string error;
  std::optional<CliAddress> a = parseAddress(text, error);
  EXPECT_TRUE(a.has_value()) << text << ": " << error;
  return a.value_or(CliAddress{});
}

std::string addrError(const char *text) {
  std::string error;
  EXPECT_FALSE(parseAddress(text, error).has_value()) << text;
  return error;
}

struct Fresh {
  std::unique_ptr<lj_state> s = std::make_unique<lj_state>();
  Fresh() { lj_state_reset(s.get()); }
};

TEST(CliAddress, ParsesBitsAndElements) {
  CliAddress a = addr("X1.0");
  EXPECT_EQ(a.area, Area::Input);
  EXPECT_EQ(a.index, 1);
  EXPECT_EQ(a.bit, 0);
  EXPECT_EQ(a.text, "X1.0");
  CliAddress g = addr("G2560.9"); // G is 16 bits: .9 exists (DIALECT.md 1)
  EXPECT_EQ(g.area, Area::NcControl);
  EXPECT_EQ(g.index, 2560);
  EXPECT_EQ(g.bit, 9);
  CliAddress d = addr("D5.31");
  EXPECT_EQ(d.bit, 31);
  CliAddress p = addr("P10");
  EXPECT_EQ(p.area, Area::Param);
  EXPECT_FALSE(p.isBit());
  EXPECT_EQ(addr("F2616").index, 2616);
}

TEST(CliAddress, CaseInsensitiveWithLeadingZeros) {
  // docs/dialect-notes.md "Text": area letters case-insensitive, X0010.3 = X10.3.
  CliAddress a = addr("x0010.3");
  EXPECT_EQ(a.area, Area::Input);
  EXPECT_EQ(a.index, 10);
  EXPECT_EQ(a.bit, 3);
  EXPECT_EQ(a.text, "x0010.3"); // kept as written for watch columns
  EXPECT_EQ(addr("d007").index, 7);
}

TEST(CliAddress, TimersAndCounters) {
  // T0..T127 and T300..T427; the only bit is .0 (dialect-notes "Function blocks").
  EXPECT_EQ(addr("T5").area, Area::Timer);
  EXPECT_EQ(addr("T5.0").bit, 0);
  EXPECT_EQ(addr("C427").index, 427);
  EXPECT_EQ(addr("t300").index, 300);
  EXPECT_NE(addrError("T128").find("out of range"), std::string::npos);
  EXPECT_NE(addrError("C299").find("out of range"), std::string::npos);
  EXPECT_NE(addrError("T5.1").find(".0"), std::string::npos);
}

TEST(CliAddress, RejectsBadAddressesWithTheirName) {
  EXPECT_NE(addrError("X513").find("X513"), std::string::npos); // X0..X512
  EXPECT_NE(addrError("X513").find("out of range"), std::string::npos);
  EXPECT_NE(addrError("X1.8").find("bit out of range"), std::string::npos); // 8-bit element
  EXPECT_NE(addrError("W3.16").find("bit out of range"), std::string::npos);
  EXPECT_NE(addrError("D100").find("out of range"), std::string::npos); // D0..D99
  EXPECT_NE(addrError("B50").find("out of range"), std::string::npos);
  EXPECT_NE(addrError("P200").find("out of range"), std::string::npos);
  EXPECT_NE(addrError("Q1").find("unknown area"), std::string::npos);
  EXPECT_NE(addrError("L3").find("unknown area"), std::string::npos); // labels are not data
  EXPECT_NE(addrError("S3").find("unknown area"), std::string::npos);
  EXPECT_NE(addrError("X").find("element number"), std::string::npos);
  EXPECT_NE(addrError("X1.").find("bit number"), std::string::npos);
  EXPECT_NE(addrError("X-1").find("element number"), std::string::npos);
  EXPECT_NE(addrError("X1.0.0").find("bit number"), std::string::npos);
  EXPECT_NE(addrError("X99999999999999999999").find("out of range"), std::string::npos);
  EXPECT_NE(addrError("").find("empty"), std::string::npos);
}

TEST(CliValue, DecimalSignAndHex) {
  std::string e;
  EXPECT_EQ(parseValue("0", e), 0);
  EXPECT_EQ(parseValue("-3", e), -3);
  EXPECT_EQ(parseValue("+12", e), 12);
  EXPECT_EQ(parseValue("007", e), 7); // never octal (dialect-notes "Text")
  EXPECT_EQ(parseValue("0x1F", e), 31);
  EXPECT_EQ(parseValue("0XfF", e), 255);
  EXPECT_EQ(parseValue("-2147483648", e), INT32_MIN);
  EXPECT_EQ(parseValue("0xFFFFFFFF", e), 0xFFFFFFFFll); // the 32-bit pattern of -1
  for (const char *bad : {"", "-", "abc", "1.5", "0x", "0xG1", "12a", "-2147483649", "4294967296",
                          "0x100000000", "99999999999999999999999"}) {
    EXPECT_FALSE(parseValue(bad, e).has_value()) << bad;
    EXPECT_NE(e.find("bad value"), std::string::npos) << bad;
  }
}

TEST(CliAccess, ElementsReadAtTheirWidthAndSign) {
  Fresh f;
  lj_state &s = *f.s;
  // DIALECT.md 1: X/Y/R zero-extended u8, F/G/W sign-extended i16, D/B/P i32.
  writeAddress(s, addr("X2"), -1);
  EXPECT_EQ(s.img.X[2], 0xFF);
  EXPECT_EQ(readAddress(s, addr("X2")), 255);
  writeAddress(s, addr("W7"), 0xFFFF);
  EXPECT_EQ(readAddress(s, addr("W7")), -1);
  writeAddress(s, addr("F2616"), -1); // "T code else -1" (hnc8-cnc-interface.md 1.3)
  EXPECT_EQ(readAddress(s, addr("F2616")), -1);
  writeAddress(s, addr("D5"), -3);
  EXPECT_EQ(readAddress(s, addr("D5")), -3);
  writeAddress(s, addr("B3"), 0xFFFFFFFFll);
  EXPECT_EQ(readAddress(s, addr("B3")), -1);
  writeAddress(s, addr("P10"), 345);
  EXPECT_EQ(s.img.P[10], 345);
  // "Writing an element sets the whole element (truncated)": 0x1234 into 8 bits keeps 0x34.
  writeAddress(s, addr("R4"), 0x1234);
  EXPECT_EQ(readAddress(s, addr("R4")), 0x34);
  writeAddress(s, addr("G3"), 0x18000); // low 16 bits 0x8000 = -32768 sign-extended
  EXPECT_EQ(readAddress(s, addr("G3")), -32768);
}

TEST(CliAccess, BitsTouchOnlyThemselves) {
  Fresh f;
  lj_state &s = *f.s;
  writeAddress(s, addr("Y3"), 0xA5);
  writeAddress(s, addr("Y3.1"), 1);
  writeAddress(s, addr("Y3.0"), 0);
  EXPECT_EQ(s.img.Y[3], 0xA6); // 1010 0101 -> bit1 set, bit0 cleared
  EXPECT_EQ(readAddress(s, addr("Y3.7")), 1);
  EXPECT_EQ(readAddress(s, addr("Y3.6")), 0);
  writeAddress(s, addr("D5.31"), 1); // bit k of element n = (value >> k) & 1
  EXPECT_EQ(s.img.D[5], INT32_MIN);
  EXPECT_EQ(readAddress(s, addr("D5.31")), 1);
  writeAddress(s, addr("W1.15"), 1);
  EXPECT_EQ(readAddress(s, addr("W1")), -32768);
  EXPECT_EQ(s.img.W[0], 0); // neighbours untouched
  EXPECT_EQ(s.img.W[2], 0);
}

TEST(CliAccess, TimerAndCounterState) {
  Fresh f;
  lj_state &s = *f.s;
  // T300 is slot 128 (abi.h lj_tc_slot).
  s.T[128].elapsed_ms = 1234;
  s.T[128].out = 1;
  EXPECT_EQ(readAddress(s, addr("T300")), 1234);
  EXPECT_EQ(readAddress(s, addr("T300.0")), 1);
  writeAddress(s, addr("C3"), 42);
  writeAddress(s, addr("C3.0"), 1);
  EXPECT_EQ(s.C[3].value, 42);
  EXPECT_EQ(s.C[3].out, 1);
  EXPECT_EQ(readAddress(s, addr("C3")), 42);
  std::string e;
  EXPECT_FALSE(checkWritable(addr("T5"), 1, e));
  EXPECT_NE(e.find("T5"), std::string::npos);
}

TEST(CliAssignment, ParsesAndChecks) {
  std::string e;
  std::optional<Assignment> a = parseAssignment("X1.0=1", e);
  ASSERT_TRUE(a);
  EXPECT_EQ(a->addr.index, 1);
  EXPECT_EQ(a->value, 1);
  EXPECT_EQ(parseAssignment("D5=-0x10", e)->value, -16);
  EXPECT_FALSE(parseAssignment("X1.0=2", e)); // a bit takes 0 or 1
  EXPECT_NE(e.find("expected 0 or 1"), std::string::npos);
  EXPECT_FALSE(parseAssignment("X1.0", e));
  EXPECT_NE(e.find("ADDR=VALUE"), std::string::npos);
  EXPECT_FALSE(parseAssignment("X600=1", e));
  EXPECT_NE(e.find("X600"), std::string::npos);
  EXPECT_FALSE(parseAssignment("D1=x", e));
  EXPECT_NE(e.find("bad value 'x'"), std::string::npos);
}

} // namespace
} // namespace lj::formats

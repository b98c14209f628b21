// Test-side address parsing and state access (DIALECT.md 1 widths, CLI.md address forms).
#include "tests/support/TestAddress.h"
#include "profiles/hnc8/Hnc8Profile.h"

#include <gtest/gtest.h>

#include <cstring>
#include <string>

namespace lj::test {

namespace {

bool parseNumber(std::string_view t, size_t &pos, int32_t &out) {
  size_t start = pos;
  int64_t v = 0;
  while (pos < t.size() && t[pos] >= '0' && t[pos] <= '9' && v < 100000)
    v = v * 10 + (t[pos++] - '0');
  out = static_cast<int32_t>(v);
  return pos > start;
}

/// Element base and width of the numeric areas inside lj_image.
unsigned char *elementPtr(lj_image &img, Area a, int32_t n, int &bytes) {
  switch (a) {
  case Area::Input:
    bytes = 1;
    return img.X + n;
  case Area::Output:
    bytes = 1;
    return img.Y + n;
  case Area::Relay:
    bytes = 1;
    return img.R + n;
  case Area::NcStatus:
    bytes = 2;
    return reinterpret_cast<unsigned char *>(img.F + n);
  case Area::NcControl:
    bytes = 2;
    return reinterpret_cast<unsigned char *>(img.G + n);
  case Area::Word:
    bytes = 2;
    return reinterpret_cast<unsigned char *>(img.W + n);
  case Area::DWord:
    bytes = 4;
    return reinterpret_cast<unsigned char *>(img.D + n);
  case Area::Retained:
    bytes = 4;
    return reinterpret_cast<unsigned char *>(img.B + n);
  case Area::Param:
    bytes = 4;
    return reinterpret_cast<unsigned char *>(img.P + n);
  default:
    bytes = 0;
    return nullptr;
  }
}

/// Raw element bits (zero-extended) and the signed value by the area's read rule.
int64_t readElement(const lj_state &s, Area a, int32_t n, bool asSigned) {
  int bytes = 0;
  const unsigned char *p = elementPtr(const_cast<lj_image &>(s.img), a, n, bytes);
  uint32_t raw = 0;
  std::memcpy(&raw, p, static_cast<size_t>(bytes)); // little-endian (abi.h)
  if (!asSigned) return raw;
  if (bytes == 1) return raw;                       // X/Y/R zero-extend
  if (bytes == 2) return static_cast<int16_t>(raw); // F/G/W sign-extend
  return static_cast<int32_t>(raw);
}

} // namespace

TestAddr parseTestAddr(std::string_view text) {
  TestAddr a;
  auto bad = [&] {
    ADD_FAILURE() << "bad test address '" << std::string(text) << "'";
    return TestAddr{};
  };
  if (text.empty()) return bad();
  std::optional<Area> area = hnc8::profile().areaFromLetter(text[0]);
  if (!area || *area == Area::Label || *area == Area::Subroutine) return bad();
  size_t pos = 1;
  int32_t n = 0, bitNo = -1;
  if (!parseNumber(text, pos, n) || !hnc8::profile().validIndex(*area, n)) return bad();
  if (pos < text.size()) {
    if (text[pos] != '.') return bad();
    ++pos;
    if (!parseNumber(text, pos, bitNo) || pos != text.size() ||
        bitNo >= hnc8::profile().bitWidth(*area))
      return bad();
  }
  a.area = *area;
  a.index = n;
  a.bit = static_cast<int8_t>(bitNo);
  return a;
}

int64_t readAddr(const lj_state &s, const TestAddr &a) {
  if (a.area == Area::None) return 0;
  if (a.area == Area::Timer || a.area == Area::Counter) {
    int slot = lj_tc_slot(a.index);
    if (a.area == Area::Timer) return a.bit >= 0 ? s.T[slot].out : s.T[slot].elapsed_ms;
    return a.bit >= 0 ? s.C[slot].out : s.C[slot].value;
  }
  if (a.bit >= 0) return (readElement(s, a.area, a.index, false) >> a.bit) & 1;
  return readElement(s, a.area, a.index, true);
}

void writeAddr(lj_state &s, const TestAddr &a, int64_t value) {
  if (a.area == Area::None) return;
  if (a.area == Area::Timer || a.area == Area::Counter) {
    int slot = lj_tc_slot(a.index);
    if (a.area == Area::Timer) {
      if (a.bit >= 0)
        s.T[slot].out = value != 0;
      else
        s.T[slot].elapsed_ms = value;
    } else {
      if (a.bit >= 0)
        s.C[slot].out = value != 0;
      else
        s.C[slot].value = static_cast<int32_t>(value);
    }
    return;
  }
  int bytes = 0;
  unsigned char *p = elementPtr(s.img, a.area, a.index, bytes);
  uint32_t raw = 0;
  std::memcpy(&raw, p, static_cast<size_t>(bytes));
  if (a.bit >= 0) {
    uint32_t m = 1u << a.bit;
    raw = value ? (raw | m) : (raw & ~m);
  } else {
    raw = static_cast<uint32_t>(value); // truncated to the width by the copy below
  }
  std::memcpy(p, &raw, static_cast<size_t>(bytes));
}

} // namespace lj::test

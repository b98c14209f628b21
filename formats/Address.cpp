// Command-line address and value parsing, and element/bit access to an lj_state by address.
#include "formats/Address.h"
#include "frontends/common/ProfileAddress.h"
#include "frontends/hnc8/Address.h"
#include "profiles/hnc8/Hnc8Profile.h"

#include <cctype>
#include <cstring>

namespace lj::formats {

namespace {

constexpr int64_t kValueMin = INT32_MIN;
constexpr int64_t kValueMax = UINT32_MAX; // 0xFFFFFFFF: the 32-bit pattern of -1

bool isDigits(std::string_view s) {
  if (s.empty()) return false;
  for (char c : s)
    if (!std::isdigit(static_cast<unsigned char>(c))) return false;
  return true;
}

// Decimal digits to a number, saturating far above any valid index so "X99999999999" is a
// range error rather than an overflow.
int64_t digitsValue(std::string_view s) {
  int64_t v = 0;
  for (char c : s) {
    v = v * 10 + (c - '0');
    if (v > (int64_t{1} << 40)) return int64_t{1} << 40;
  }
  return v;
}

// Raw little-endian element storage of (area, index) and its width in bytes.
struct Cell {
  const void *ptr;
  int bytes;
  bool isSigned;
};

const TargetProfile &profileOf(const CliAddress &a) {
  return a.profile ? *a.profile : hnc8::profile();
}

/// Where `a`'s element lives: byte offset in lj_state, width, signedness; bytes 0 for T, C, L, S
/// (no image element).
struct Place {
  uint32_t offset;
  int bytes;
  bool isSigned;
};

Place placeOf(const CliAddress &a) {
  if (a.area == Area::None && a.profile) // a system-parameter byte (CliAddress::area)
    return {static_cast<uint32_t>(a.index), 1, false};
  const TargetProfile &tp = profileOf(a);
  const AreaInfo &info = tp.area(a.area);
  if (info.bytes == 0) return {0, 0, false};
  return {tp.elementOffset(a.area, a.index), a.width ? a.width : info.bytes, info.isSigned};
}

Cell cellOf(const lj_state &s, const CliAddress &a) {
  const Place p = placeOf(a);
  if (p.bytes == 0) return {nullptr, 0, false};
  return {reinterpret_cast<const unsigned char *>(&s) + p.offset, p.bytes, p.isSigned};
}

// The element's bits as an unsigned pattern (zero-extended to 32 bits).
uint32_t rawBits(const Cell &c) {
  uint32_t v = 0;
  std::memcpy(&v, c.ptr, static_cast<size_t>(c.bytes)); // little-endian host, like the ABI
  return v;
}

int64_t readElement(const Cell &c) {
  uint32_t raw = rawBits(c);
  if (!c.isSigned) return raw;
  if (c.bytes == 1) return static_cast<int8_t>(raw);
  if (c.bytes == 2) return static_cast<int16_t>(raw);
  return static_cast<int32_t>(raw);
}

} // namespace

std::optional<CliAddress> parseAddress(std::string_view text, std::string &error) {
  auto fail = [&](const std::string &why) -> std::optional<CliAddress> {
    error = "bad address '" + std::string(text) + "': " + why;
    return std::nullopt;
  };
  if (text.empty()) return fail("empty");
  // The HNC-8 address syntax (frontends/hnc8/Address.h), as the STL parser reads it.
  const hnc8::AddressText lexed = hnc8::lexAddress(text);
  const Area area = lexed.area;
  if (lexed.lex == hnc8::AddressText::Lex::NoArea || area == Area::Label ||
      area == Area::Subroutine || area == Area::None)
    return fail("unknown area (expected one of X Y F G R W D B P T C)");
  if (lexed.lex == hnc8::AddressText::Lex::NoIndex)
    return fail("expected an element number after the area letter");
  if (lexed.lex == hnc8::AddressText::Lex::NoBit) return fail("expected a bit number after '.'");
  const int64_t index = lexed.index;
  if (!hnc8::profile().validIndex(area, index)) {
    if (area == Area::Timer || area == Area::Counter)
      return fail("number out of range (0..127 or 300..427)");
    return fail("element out of range (0.." + std::to_string(hnc8::profile().area(area).count - 1) +
                ")");
  }
  CliAddress a;
  a.area = area;
  a.index = static_cast<int32_t>(index);
  a.text = std::string(text);
  if (lexed.bit >= 0) {
    const int64_t b = lexed.bit;
    int width = hnc8::profile().bitWidth(area);
    if (b >= width) {
      if (area == Area::Timer || area == Area::Counter)
        return fail("the only bit of a timer/counter is .0");
      return fail("bit out of range (0.." + std::to_string(width - 1) + ")");
    }
    a.bit = static_cast<int8_t>(b);
  }
  return a;
}

std::optional<int64_t> parseValue(std::string_view text, std::string &error) {
  auto fail = [&](const char *why) -> std::optional<int64_t> {
    error = "bad value '" + std::string(text) + "': " + why;
    return std::nullopt;
  };
  std::string_view s = text;
  bool neg = false;
  if (!s.empty() && (s[0] == '+' || s[0] == '-')) {
    neg = s[0] == '-';
    s.remove_prefix(1);
  }
  if (s.empty()) return fail("expected a number");
  int64_t v = 0;
  if (s.size() > 2 && s[0] == '0' && (s[1] == 'x' || s[1] == 'X')) {
    s.remove_prefix(2);
    for (char c : s) {
      if (!std::isxdigit(static_cast<unsigned char>(c))) return fail("bad hex digit");
      int d = std::isdigit(static_cast<unsigned char>(c)) ? c - '0' : std::tolower(c) - 'a' + 10;
      v = v * 16 + d;
      if (v > kValueMax + 1) return fail("out of range (-2147483648..0xFFFFFFFF)");
    }
  } else {
    if (!isDigits(s)) return fail("expected a decimal number or 0x hex");
    v = digitsValue(s);
  }
  if (neg) v = -v;
  if (v < kValueMin || v > kValueMax) return fail("out of range (-2147483648..0xFFFFFFFF)");
  return v;
}

bool checkWritable(const CliAddress &addr, int64_t value, std::string &error) {
  if (addr.area == Area::Timer) {
    error = "cannot write timer '" + addr.text + "': its state follows from its input and now_ms";
    return false;
  }
  if (addr.isBit() && value != 0 && value != 1) {
    error = "bad value " + std::to_string(value) + " for bit '" + addr.text + "': expected 0 or 1";
    return false;
  }
  return true;
}

int64_t readAddress(const lj_state &s, const CliAddress &addr) {
  if (addr.area == Area::Timer || addr.area == Area::Counter) {
    int slot = profileOf(addr).tcSlot(addr.area, addr.index);
    if (addr.area == Area::Timer) return addr.isBit() ? s.T[slot].out : s.T[slot].elapsed_ms;
    return addr.isBit() ? s.C[slot].out : s.C[slot].value;
  }
  Cell c = cellOf(s, addr);
  if (addr.isBit()) return (rawBits(c) >> addr.bit) & 1u;
  return readElement(c);
}

int addressBits(const CliAddress &addr) {
  if (addr.isBit()) return 1;
  if (addr.area == Area::Timer || addr.area == Area::Counter) return 32;
  if (addr.area == Area::None && addr.profile) return 8; // a system-parameter byte
  const int bytes = addr.width ? addr.width : profileOf(addr).area(addr.area).bytes;
  return bytes * 8;
}

ResolvedAddress resolveAddress(const CliAddress &addr) {
  ResolvedAddress r;
  if (addr.area == Area::Timer || addr.area == Area::Counter) return r;
  const Place p = placeOf(addr);
  if (p.bytes != 1 && p.bytes != 2 && p.bytes != 4) return r;
  r.direct = true;
  r.bytes = static_cast<uint8_t>(p.bytes);
  r.isSigned = p.isSigned;
  r.bit = addr.bit;
  r.offset = p.offset;
  return r;
}

void writeAddress(lj_state &s, const CliAddress &addr, int64_t value) {
  if (addr.area == Area::Counter) {
    lj_counter &k = s.C[profileOf(addr).tcSlot(addr.area, addr.index)];
    if (addr.isBit())
      k.out = static_cast<uint8_t>(value & 1);
    else
      k.value = static_cast<int32_t>(static_cast<uint32_t>(value));
    return;
  }
  if (addr.area == Area::Timer) return; // rejected by checkWritable
  Cell c = cellOf(s, addr);
  void *ptr = const_cast<void *>(c.ptr);
  uint32_t raw = rawBits(c);
  if (addr.isBit()) {
    uint32_t mask = 1u << addr.bit;
    raw = (value & 1) ? (raw | mask) : (raw & ~mask);
  } else {
    raw = static_cast<uint32_t>(value); // low 32 bits; memcpy keeps the low 8/16 of those
  }
  std::memcpy(ptr, &raw, static_cast<size_t>(c.bytes));
}

namespace {

// `addr=value` with the address read by `parse` (the value as parseValue reads it, checked with
// checkWritable); a missing `=` quotes `shown`.
template <class ParseAddress>
std::optional<Assignment> assignmentOf(std::string_view item, std::string_view shown,
                                       std::string &error, ParseAddress parse) {
  size_t eq = item.find('=');
  if (eq == std::string_view::npos) {
    error = "bad assignment '" + std::string(shown) + "': expected ADDR=VALUE";
    return std::nullopt;
  }
  std::optional<CliAddress> addr = parse(item.substr(0, eq), error);
  if (!addr) return std::nullopt;
  std::optional<int64_t> value = parseValue(item.substr(eq + 1), error);
  if (!value) return std::nullopt;
  if (!checkWritable(*addr, *value, error)) return std::nullopt;
  return Assignment{std::move(*addr), *value};
}

} // namespace

std::optional<Assignment> parseAssignmentWith(AddressParser parse, std::string_view item,
                                              std::string &error, size_t shownBytes) {
  return assignmentOf(item, item.substr(0, shownBytes), error, parse);
}

std::optional<Assignment> parseAssignment(std::string_view item, std::string &error) {
  return parseAssignmentWith(parseAddress, item, error);
}

std::optional<CliAddress> parseProfileAddress(const TargetProfile &tp, std::string_view text,
                                              std::string &error) {
  auto fail = [&](const std::string &why) -> std::optional<CliAddress> {
    error = "bad address '" + std::string(text) + "': " + why;
    return std::nullopt;
  };
  if (text.empty()) return fail("empty");
  // The profile-laid address syntax (frontends/common/ProfileAddress.h), as the FANUC parser
  // reads it, plus `:width`.
  using Lex = frontend::ProfileAddressText::Lex;
  const frontend::ProfileAddressText lexed = frontend::lexProfileAddress(tp, text);
  std::string known;
  for (int i = 0; i < kAreaCount; ++i) {
    const AreaInfo &ai = tp.areas[static_cast<size_t>(i)];
    if (ai.count > 0 && ai.bytes > 0) known += (known.empty() ? "" : " ") + std::string(ai.name);
  }
  // An area name runs to the first digit here: `X.5` names no area.
  const bool dotInName =
      lexed.lex == Lex::NoIndex && lexed.nameEnd < text.size() && text[lexed.nameEnd] == '.';
  if (lexed.lex == Lex::NoArea || dotInName || tp.area(lexed.area).bytes == 0)
    return fail("unknown area (expected one of " + known + ")");
  if (lexed.lex == Lex::NoIndex) return fail("expected an element number after the area name");
  const Area area = lexed.area;
  const AreaInfo &ai = tp.area(area);
  const int64_t index = lexed.index;
  CliAddress a;
  a.area = area;
  a.profile = &tp;
  a.text = std::string(text);
  int64_t width = ai.bytes;
  if (lexed.sep == '.') {
    if (lexed.lex == Lex::NoBit) return fail("expected a bit number after '.'");
    const int64_t b = lexed.bit;
    if (b >= tp.bitWidth(area))
      return fail("bit out of range (0.." + std::to_string(tp.bitWidth(area) - 1) + ")");
    a.bit = static_cast<int8_t>(b);
  } else if (lexed.sep == ':') {
    if (ai.bytes != 1) return fail("a width ':N' is only for byte areas");
    if (lexed.lex == Lex::NoWidth) return fail("width must be 1, 2 or 4 bytes");
    width = lexed.width;
    a.width = static_cast<uint8_t>(width);
  }
  if (!tp.validSpan(area, index, ai.bytes == 1 ? width : 1)) {
    std::string ranges = std::string(ai.name) + "0.." + ai.name + std::to_string(ai.count - 1);
    if (ai.upperCount > 0)
      ranges += ", " + std::string(ai.name) + std::to_string(ai.upperLo) + ".." + ai.name +
                std::to_string(ai.upperLo + ai.upperCount - 1);
    return fail("element out of range (" + ranges + ")");
  }
  a.index = static_cast<int32_t>(index);
  return a;
}

std::string formatProfileAddress(const CliAddress &addr) {
  std::string s(profileOf(addr).area(addr.area).name);
  s += std::to_string(addr.index);
  if (addr.isBit())
    s += "." + std::to_string(addr.bit);
  else if (addr.width > 1)
    s += ":" + std::to_string(addr.width);
  return s;
}

std::optional<Assignment> parseProfileAssignment(const TargetProfile &tp, std::string_view item,
                                                 std::string &error) {
  return assignmentOf(item, item, error, [&](std::string_view text, std::string &why) {
    return parseProfileAddress(tp, text, why);
  });
}

const Symbol *findSymbol(std::span<const Symbol> symbols, std::string_view name) {
  auto same = [](std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (size_t i = 0; i < a.size(); ++i)
      if (std::toupper(static_cast<unsigned char>(a[i])) !=
          std::toupper(static_cast<unsigned char>(b[i])))
        return false;
    return true;
  };
  for (const Symbol &s : symbols)
    if (same(s.name, name)) return &s;
  return nullptr;
}

std::optional<CliAddress> parseAddressIn(AddressParser parse, std::span<const Symbol> symbols,
                                         std::string_view text, std::string &error) {
  const Symbol *sym = SymbolTable::isNameShaped(text) ? findSymbol(symbols, text) : nullptr;
  if (!sym) return parse(text, error);
  std::optional<CliAddress> a = parse(sym->address, error);
  if (!a) {
    error = "symbol " + SymbolTable::quote(sym->name) + " = " + sym->address + ": " + error;
    return std::nullopt;
  }
  a->text = std::string(text);
  return a;
}

std::optional<Assignment> parseAssignmentIn(AddressParser parse, AssignmentParser assign,
                                            std::span<const Symbol> symbols, std::string_view item,
                                            std::string &error) {
  const size_t eq = item.find('=');
  const std::string_view name = item.substr(0, eq);
  if (eq == std::string_view::npos || !SymbolTable::isNameShaped(name) ||
      !findSymbol(symbols, name))
    return assign(item, error);
  return assignmentOf(item, item, error, [&](std::string_view text, std::string &why) {
    return parseAddressIn(parse, symbols, text, why);
  });
}

std::string formatAddress(const CliAddress &addr) {
  std::string s(hnc8::profile().area(addr.area).name);
  s += std::to_string(addr.index);
  if (addr.isBit()) s += "." + std::to_string(addr.bit);
  return s;
}

} // namespace lj::formats

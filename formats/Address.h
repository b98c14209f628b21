// Addresses and values as a user writes them on the command line and in stimulus files
// (CLI.md "Addresses on the command line"), and reading/writing them in an lj_state.
#pragma once

#include "ir/Area.h"
#include "ir/Profile.h"
#include "ir/SymbolTable.h"
#include "ladderjit/abi.h"

#include <cstdint>
#include <cstring>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace lj::formats {

/// One command-line address: a bit (`X1.0`, `T5.0`) or a whole element (`D5`, `T5`, `C3`).
struct CliAddress {
  /// Area::None with a `profile`: the system-parameter byte at lj_state offset `index`
  /// (TargetProfile::SystemParams; only parameter files name it, formats::parseParams).
  Area area = Area::None;
  int32_t index = 0; ///< element number (T/C: the timer/counter number, not its slot)
  int8_t bit = -1;   ///< bit number, -1 for the whole element
  std::string text;  ///< as the user wrote it (used as the watch column name)
  /// The target whose memory the address names (nullptr: HNC-8, what parseAddress gives).
  const TargetProfile *profile = nullptr;
  uint8_t width = 0; ///< element: bytes read/written little-endian (0: the area's width)

  bool isBit() const { return bit >= 0; }
};

/// Parse `X1.0`, `d05`, `T5.0`, `C3`... Area letters are case-insensitive and numbers accept
/// leading zeros (docs/dialect-notes.md "Text"). Areas X Y F G R W D B P T C are accepted; the
/// index must be in range (DIALECT.md 1) and the bit below the element width (T/C: only .0).
/// On failure returns nothing and sets `error` to a message naming the address.
std::optional<CliAddress> parseAddress(std::string_view text, std::string &error);

/// An address of a profile-laid target (FANUC, IEC): the area's name as the profile spells it
/// (longest match, case-insensitive), the element number, then `.bit` or, where the area's
/// elements are bytes, `:2` / `:4` for a little-endian signed word starting at that byte
/// (`R100`, `R100.3`, `D100:4`). The whole element span must exist. Errors name the address.
std::optional<CliAddress> parseProfileAddress(const TargetProfile &tp, std::string_view text,
                                              std::string &error);
/// `addr` written back in its profile's syntax (parseProfileAddress's inverse).
std::string formatProfileAddress(const CliAddress &addr);
/// `addr` as the HNC-8 dialect writes it (`X1.0`, `D5`): area letter, index, `.bit` for a bit.
std::string formatAddress(const CliAddress &addr);

/// Parse a value: decimal with optional sign, or `0x` hex (docs/dialect-notes.md "Text"), in
/// the range INT32_MIN..UINT32_MAX so `0xFFFFFFFF` is the bit pattern -1 of a 32-bit element.
std::optional<int64_t> parseValue(std::string_view text, std::string &error);

/// Check that `value` can be written to `addr`: a bit takes only 0 or 1, an element anything
/// parseValue accepts (it is truncated on write). Timers are read-only (their state is derived
/// from timestamps); counters can be preset. Returns false and sets `error` otherwise.
bool checkWritable(const CliAddress &addr, int64_t value, std::string &error);

/// The value of `addr`: a bit as 0/1; an element at its width and signedness (DIALECT.md 1);
/// `Tn` = elapsed_ms, `Cn` = count, `Tn.0` / `Cn.0` = output bit.
int64_t readAddress(const lj_state &s, const CliAddress &addr);

/// What `addr` reads: 1 for a bit, 8/16/32 for an element (its width), 32 for a timer's elapsed
/// ms or a counter's count. The watch table formats a value (hex, BCD, unsigned) by it.
int addressBits(const CliAddress &addr);

/// Write `value` to `addr`: a bit sets only that bit, an element keeps the low 8/16/32 bits.
/// `Cn` sets the count, `Cn.0` the output bit. Call checkWritable first.
void writeAddress(lj_state &s, const CliAddress &addr, int64_t value);

/// An address resolved once to where it lives in lj_state, for a copy that runs every tick
/// (the HAL component's pins): readResolved / writeResolved then look nothing up. A timer or
/// counter (whose slot is not an image element) stays `direct == false`: readAddress /
/// writeAddress do those.
struct ResolvedAddress {
  bool direct = false;
  uint8_t bytes = 0;     ///< 1, 2 or 4
  bool isSigned = false; ///< read rule of the element
  int8_t bit = -1;       ///< bit number, -1 for the whole element
  uint32_t offset = 0;   ///< byte offset of the element in lj_state
};
ResolvedAddress resolveAddress(const CliAddress &addr);

/// readAddress(s, addr) for `r = resolveAddress(addr)`.
inline int64_t readResolved(const lj_state &s, const ResolvedAddress &r, const CliAddress &addr) {
  if (!r.direct) return readAddress(s, addr);
  const auto *p = reinterpret_cast<const unsigned char *>(&s) + r.offset;
  uint32_t raw = 0;
  switch (r.bytes) { // fixed sizes: the copies inline (little-endian host, like the ABI)
  case 1:
    raw = *p;
    break;
  case 2: {
    uint16_t v;
    std::memcpy(&v, p, 2);
    raw = v;
    break;
  }
  default:
    std::memcpy(&raw, p, 4);
    break;
  }
  if (r.bit >= 0) return (raw >> r.bit) & 1u;
  if (!r.isSigned) return raw;
  if (r.bytes == 1) return static_cast<int8_t>(raw);
  if (r.bytes == 2) return static_cast<int16_t>(raw);
  return static_cast<int32_t>(raw);
}

/// writeAddress(s, addr, value) for `r = resolveAddress(addr)`.
inline void writeResolved(lj_state &s, const ResolvedAddress &r, const CliAddress &addr,
                          int64_t value) {
  if (!r.direct) return writeAddress(s, addr, value);
  auto *p = reinterpret_cast<unsigned char *>(&s) + r.offset;
  if (r.bit >= 0) { // the bit's byte alone: the same result as the element's read-modify-write
    unsigned char &b = p[r.bit >> 3];
    const auto mask = static_cast<unsigned char>(1u << (r.bit & 7));
    b = static_cast<unsigned char>((value & 1) ? (b | mask) : (b & ~mask));
    return;
  }
  const auto raw = static_cast<uint32_t>(value);
  switch (r.bytes) {
  case 1:
    *p = static_cast<unsigned char>(raw);
    break;
  case 2: {
    const auto v = static_cast<uint16_t>(raw);
    std::memcpy(p, &v, 2);
    break;
  }
  default:
    std::memcpy(p, &raw, 4);
    break;
  }
}

/// `addr=value` parsed into its parts (no spaces inside); errors name the whole item.
struct Assignment {
  CliAddress addr;
  int64_t value = 0;
};
std::optional<Assignment> parseAssignment(std::string_view item, std::string &error);
/// `addr=value` for a profile-laid target (parseProfileAddress syntax).
std::optional<Assignment> parseProfileAssignment(const TargetProfile &tp, std::string_view item,
                                                 std::string &error);

/// A dialect's reader of addresses and of `addr=value` items (Dialect::parseAddress,
/// Dialect::parseAssignment).
using AddressParser = std::optional<CliAddress> (*)(std::string_view text, std::string &error);
using AssignmentParser = std::optional<Assignment> (*)(std::string_view item, std::string &error);

/// `addr=value` with the address read by `parse` (a dialect's address syntax), the value as
/// parseValue reads it, checked with checkWritable; a message about a missing `=` quotes the
/// first `shownBytes` of the item.
std::optional<Assignment> parseAssignmentWith(AddressParser parse, std::string_view item,
                                              std::string &error,
                                              size_t shownBytes = std::string_view::npos);

/// The symbol named `name` in `symbols` (case-insensitive for ASCII letters, as SymbolTable
/// finds names), or nullptr.
const Symbol *findSymbol(std::span<const Symbol> symbols, std::string_view name);

/// `text` as an address: when it is shaped like a name (SymbolTable::isNameShaped) and
/// `symbols` (the program's) defines it, the address the symbol stands for, read by `parse`
/// (CliAddress::text keeps the name as written: the watch column says `COOLANT`); otherwise
/// `parse(text)` as it is. Errors about a symbol's address name the symbol.
std::optional<CliAddress> parseAddressIn(AddressParser parse, std::span<const Symbol> symbols,
                                         std::string_view text, std::string &error);

/// `addr=value` likewise: a defined symbol before the `=` is read as its address (then the value
/// as parseValue reads it, checked with checkWritable); any other item goes to `assign` as it is.
std::optional<Assignment> parseAssignmentIn(AddressParser parse, AssignmentParser assign,
                                            std::span<const Symbol> symbols, std::string_view item,
                                            std::string &error);

} // namespace lj::formats

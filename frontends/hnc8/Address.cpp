// The HNC-8 address lexer and the symbol rules built on it (frontends/hnc8/Address.h).
#include "frontends/hnc8/Address.h"
#include "profiles/hnc8/Hnc8Profile.h"

#include <optional>

namespace lj::hnc8 {

namespace {

bool isDigit(char c) { return c >= '0' && c <= '9'; }

} // namespace

bool readDecimal(std::string_view t, size_t &pos, int64_t &value) {
  size_t start = pos;
  value = 0;
  while (pos < t.size() && isDigit(t[pos])) {
    value = value * 10 + (t[pos] - '0');
    if (value > kSaturated) value = kSaturated;
    ++pos;
  }
  return pos > start;
}

AddressText lexAddress(std::string_view t) {
  AddressText a;
  std::optional<Area> area = t.empty() ? std::nullopt : profile().areaFromLetter(t[0]);
  if (!area) {
    a.lex = AddressText::Lex::NoArea;
    return a;
  }
  a.area = *area;
  size_t pos = 1;
  if (!readDecimal(t, pos, a.index) || (pos < t.size() && t[pos] != '.')) {
    a.lex = AddressText::Lex::NoIndex;
    return a;
  }
  if (pos < t.size()) {
    ++pos; // the '.'
    if (!readDecimal(t, pos, a.bit) || pos != t.size()) a.lex = AddressText::Lex::NoBit;
  }
  return a;
}

std::string canonicalAddress(std::string_view t, std::string &error) {
  const AddressText a = lexAddress(t);
  if (a.lex == AddressText::Lex::NoArea) {
    error = "bad address " + SymbolTable::quote(t) +
            ": expected an area letter (X Y F G R W D B P T C L S), "
            "a number and an optional .bit";
    return {};
  }
  if (a.lex != AddressText::Lex::Ok) {
    error = "bad address " + SymbolTable::quote(t) +
            ": expected an area letter, a number and an optional .bit";
    return {};
  }
  const std::string letter = profile().area(a.area).name;
  if (!profile().validIndex(a.area, a.index)) {
    error = "address " + SymbolTable::quote(t) + " out of range for area " + letter;
    return {};
  }
  if (a.bit >= 0 && a.bit >= profile().bitWidth(a.area)) {
    error = "bit number out of range in address " + SymbolTable::quote(t);
    return {};
  }
  std::string out(letter);
  out += std::to_string(a.index);
  if (a.bit >= 0) {
    out += '.';
    out += std::to_string(a.bit);
  }
  return out;
}

const SymbolRules &symbolRules() {
  static constexpr SymbolRules kRules{kMaxSymbols, kMaxNameBytes, kMaxCommentBytes, "HNC-8 limit",
                                      &canonicalAddress};
  return kRules;
}

} // namespace lj::hnc8

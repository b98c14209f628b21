// The address lexer of profile-laid dialects (frontends/common/ProfileAddress.h).
#include "frontends/common/ProfileAddress.h"

#include <algorithm>
#include <optional>

namespace lj::frontend {

namespace {

constexpr int64_t kSaturated = int64_t{1} << 40;

bool isDigit(char c) { return c >= '0' && c <= '9'; }

bool readDecimal(std::string_view t, size_t &pos, int64_t &value) {
  const size_t start = pos;
  value = 0;
  while (pos < t.size() && isDigit(t[pos])) {
    value = std::min(value * 10 + (t[pos] - '0'), kSaturated);
    ++pos;
  }
  return pos > start;
}

} // namespace

ProfileAddressText lexProfileAddress(const TargetProfile &tp, std::string_view t) {
  using Lex = ProfileAddressText::Lex;
  ProfileAddressText a;
  size_t n = 0;
  while (n < t.size() && !isDigit(t[n]) && t[n] != '.') ++n;
  a.nameEnd = n;
  std::optional<Area> area = n == 0 ? std::nullopt : tp.areaFromName(t.substr(0, n));
  if (!area) {
    a.lex = Lex::NoArea;
    return a;
  }
  a.area = *area;
  size_t pos = n;
  if (!readDecimal(t, pos, a.index) || (pos < t.size() && t[pos] != '.' && t[pos] != ':')) {
    a.lex = Lex::NoIndex;
    return a;
  }
  if (pos == t.size()) return a;
  a.sep = t[pos++];
  if (a.sep == '.') {
    if (!readDecimal(t, pos, a.bit) || pos != t.size()) a.lex = Lex::NoBit;
    return a;
  }
  const std::string_view w = t.substr(pos);
  if (w == "1" || w == "2" || w == "4")
    a.width = w[0] - '0';
  else
    a.lex = Lex::NoWidth;
  return a;
}

} // namespace lj::frontend

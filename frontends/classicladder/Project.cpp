// Facts about ClassicLadder's element and variable codes (classicladder.h, vars_names_list.c).
#include "frontends/classicladder/Project.h"

#include <cstdlib>
#include <cstring>

namespace lj::classicladder {

int rungWidth(Flavor f) { return f == Flavor::LinuxCnc ? 10 : 12; }
int rungHeight(Flavor f) { return f == Flavor::LinuxCnc ? 6 : 8; }

bool knownElement(int code, Flavor f) {
  switch (code) {
  case 0:
  case 1:
  case 2:
  case 3:
  case 4:
  case 9:
  case 10:
  case 11:
  case 12:
  case 13:
  case 20:
  case 50:
  case 51:
  case 52:
  case 53:
  case 54:
  case 55:
  case 60:
  case 99:
    return true;
  case 14:
    return f == Flavor::Upstream09;
  default:
    return code >= 100 && code <= 105; // editor tool codes: stale in real files, act as FREE
  }
}

const char *elementName(int code) {
  switch (code) {
  case 0:
    return "empty cell";
  case 1:
    return "contact";
  case 2:
    return "negated contact";
  case 3:
    return "rising-edge contact";
  case 4:
    return "falling-edge contact";
  case 9:
    return "connection";
  case 10:
    return "timer %T";
  case 11:
    return "monostable %M";
  case 12:
    return "counter %C";
  case 13:
    return "IEC timer %TM";
  case 14:
    return "register";
  case 20:
    return "compare block";
  case 50:
    return "coil";
  case 51:
    return "negated coil";
  case 52:
    return "set coil";
  case 53:
    return "reset coil";
  case 54:
    return "jump coil";
  case 55:
    return "call coil";
  case 60:
    return "operate block";
  case 99:
    return "block cell";
  default:
    return code >= 100 && code <= 105 ? "editor code" : "unknown element";
  }
}

bool isOutputElement(int code) { return (code >= 50 && code <= 55) || code == 60; }

void elementSize(int code, int &width, int &height) {
  width = height = 1;
  switch (code) {
  case 10:
  case 11:
  case 13:
  case 14:
    width = height = 2;
    break;
  case 12:
    width = 2;
    height = 4;
    break;
  case 20:
  case 60:
    width = 3;
    break;
  default:
    break;
  }
}

bool knownVar(int code, Flavor f) {
  switch (code) {
  case 0:
  case 10:
  case 11:
  case 15:
  case 20:
  case 25:
  case 26:
  case 27:
  case 30:
  case 50:
  case 60:
  case 70:
  case 75:
  case 200:
  case 220:
  case 230:
  case 231:
  case 240:
  case 241:
  case 250:
  case 251:
  case 260:
  case 261:
  case 270:
  case 280:
  case 290:
  case 300:
  case 310:
    return true;
  case 65:
  case 80:
  case 81:
  case 301:
  case 302:
    return f == Flavor::Upstream09;
  default:
    return false;
  }
}

namespace {

struct VarNameRow {
  int code;
  const char *prefix;
  const char *suffix;
};

// Longest prefixes first, so parseVarName matches %TM before %T and %IW before %I.
const VarNameRow kNames[] = {
    {15, "%TM", ".Q"}, {260, "%TM", ".P"}, {261, "%TM", ".V"}, {10, "%T", ".D"},  {11, "%T", ".R"},
    {230, "%T", ".P"}, {231, "%T", ".V"},  {20, "%M", ".R"},   {240, "%M", ".P"}, {241, "%M", ".V"},
    {25, "%C", ".D"},  {26, "%C", ".E"},   {27, "%C", ".F"},   {250, "%C", ".P"}, {251, "%C", ".V"},
    {220, "%X", ".V"}, {270, "%IW", ""},   {280, "%QW", ""},   {290, "%SW", ""},  {300, "%IF", ""},
    {310, "%QF", ""},  {0, "%B", ""},      {30, "%X", ""},     {50, "%I", ""},    {60, "%Q", ""},
    {70, "%S", ""},    {75, "%E", ""},     {200, "%W", ""},
};

} // namespace

std::string varName(int type, int num) {
  for (const auto &r : kNames)
    if (r.code == type) return std::string(r.prefix) + std::to_string(num) + r.suffix;
  return "?" + std::to_string(type) + "/" + std::to_string(num);
}

std::optional<VarRef> parseVarName(const std::string &text) {
  for (const auto &r : kNames) {
    size_t pl = std::strlen(r.prefix), sl = std::strlen(r.suffix);
    if (text.size() <= pl + sl || text.compare(0, pl, r.prefix) != 0) continue;
    if (sl && text.compare(text.size() - sl, sl, r.suffix) != 0) continue;
    std::string digits = text.substr(pl, text.size() - pl - sl);
    if (digits.empty() || digits.size() > 6 ||
        digits.find_first_not_of("0123456789") != std::string::npos)
      continue;
    VarRef v;
    v.type = r.code;
    v.num = std::atoi(digits.c_str());
    return v;
  }
  return std::nullopt;
}

} // namespace lj::classicladder

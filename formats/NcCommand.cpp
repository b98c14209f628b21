// Parser of the stimulus file's NC commands (`@TICK nc.mcode ch=0 m=3`): one command per line,
// keys checked against the command, values range-checked (grammar: docs/simulated-nc.md).
#include "formats/NcCommand.h"

#include <charconv>
#include <cmath>
#include <map>

namespace lj::formats {

namespace {

struct KeySpec {
  const char *key;
  int64_t lo, hi;
  bool optional; ///< only `ch` (default 0)
};

struct CommandSpec {
  NcCommandKind kind;
  const char *name;
  std::vector<KeySpec> keys;
};

constexpr int64_t kI32Min = INT32_MIN, kI32Max = INT32_MAX;

const std::vector<CommandSpec> &specs() {
  static const KeySpec ch{"ch", 0, 3, true};
  static const std::vector<CommandSpec> list = {
      {NcCommandKind::MCode, "mcode", {ch, {"m", 0, 32767, false}}},
      {NcCommandKind::TCode, "tcode", {ch, {"t", 0, 32767, false}}},
      // s is checked by parseSpeed (rpm with up to 3 decimals).
      {NcCommandKind::SCode, "scode", {ch, {"sp", 0, 3, false}, {"s", 0, 0, false}}},
      {NcCommandKind::Reset, "reset", {ch}},
      {NcCommandKind::End, "end", {ch}},
      // value is checked by the variable's kind.
      {NcCommandKind::Var,
       "var",
       {{"type", 0, 9, false}, {"offset", 0, kI32Max, false}, {"value", 0, 0, false}}},
      {NcCommandKind::Temp, "temp", {{"sensor", 0, 19, false}, {"value", -32768, 32767, false}}},
      {NcCommandKind::Tool, "tool", {{"pocket", 1, 63, false}, {"tool", 0, kI32Max, false}}},
      {NcCommandKind::Mpg, "mpg", {{"n", 0, 7, false}, {"delta", kI32Min, kI32Max, false}}},
      {NcCommandKind::ZPulse, "zpulse", {{"axis", 0, 31, false}}},
  };
  return list;
}

bool parseInt(std::string_view text, int64_t &out) {
  if (!text.empty() && text[0] == '+') text.remove_prefix(1);
  auto [p, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
  return ec == std::errc() && p == text.data() + text.size() && !text.empty();
}

bool parseDouble(std::string_view text, double &out) {
  if (!text.empty() && text[0] == '+') text.remove_prefix(1);
  auto [p, ec] = std::from_chars(text.data(), text.data() + text.size(), out);
  return ec == std::errc() && p == text.data() + text.size() && !text.empty() && std::isfinite(out);
}

// rpm with at most 3 decimals, exactly, into 0.001 rpm (FC[10..17] unit).
bool parseSpeed(std::string_view text, int64_t &milli) {
  size_t dot = text.find('.');
  std::string_view whole = text.substr(0, dot);
  std::string frac = dot == std::string_view::npos ? "" : std::string(text.substr(dot + 1));
  if (frac.size() > 3 || whole.empty() || whole[0] == '-') return false;
  for (char c : frac)
    if (c < '0' || c > '9') return false;
  int64_t w = 0;
  if (!parseInt(whole, w) || w > kI32Max / 1000) return false;
  while (frac.size() < 3) frac += '0';
  milli = w * 1000 + std::stoi(frac);
  return milli <= kI32Max;
}

} // namespace

const char *ncCommandName(NcCommandKind kind) {
  for (const CommandSpec &s : specs())
    if (s.kind == kind) return s.name;
  return "?";
}

std::optional<NcCommand> parseNcCommand(const std::vector<std::string_view> &items,
                                        std::string &why) {
  std::string_view head = items.at(0);
  std::string_view name = head.substr(3); // after "nc."
  const CommandSpec *spec = nullptr;
  for (const CommandSpec &s : specs())
    if (name == s.name) spec = &s;
  if (!spec) {
    why = "unknown NC command '" + std::string(head) + "' (expected nc.";
    for (size_t i = 0; i < specs().size(); ++i)
      why += (i ? ", nc." : "") + std::string(specs()[i].name);
    why += ")";
    return std::nullopt;
  }
  const std::string cmd = "nc." + std::string(spec->name);
  std::map<std::string, std::string_view> given;
  for (size_t i = 1; i < items.size(); ++i) {
    std::string_view item = items[i];
    size_t eq = item.find('=');
    if (eq == std::string_view::npos || eq == 0) {
      why = cmd + ": expected key=value, found '" + std::string(item) + "'";
      return std::nullopt;
    }
    std::string key(item.substr(0, eq));
    bool known = false;
    for (const KeySpec &k : spec->keys) known = known || key == k.key;
    if (!known) {
      why = cmd + ": unknown key '" + key + "' (expected";
      for (const KeySpec &k : spec->keys) why += std::string(" ") + k.key + "=";
      why += ")";
      return std::nullopt;
    }
    if (!given.emplace(key, item.substr(eq + 1)).second) {
      why = cmd + ": key '" + key + "' given twice";
      return std::nullopt;
    }
  }
  NcCommand c;
  c.kind = spec->kind;
  for (const KeySpec &k : spec->keys) {
    auto it = given.find(k.key);
    if (it == given.end()) {
      if (k.optional) continue;
      why = cmd + ": missing " + k.key + "=";
      return std::nullopt;
    }
    std::string_view text = it->second;
    std::string keyText = std::string(k.key) + "=" + std::string(text);
    std::string key = k.key;
    if (key == "s") {
      if (!parseSpeed(text, c.ivalue)) {
        why = cmd + ": " + keyText + " is not a speed (rpm >= 0, at most 3 decimals, < 2147484)";
        return std::nullopt;
      }
      continue;
    }
    if (key == "value" && c.kind == NcCommandKind::Var) {
      if (parseInt(text, c.ivalue)) {
        c.isInteger = true;
        c.fvalue = static_cast<double>(c.ivalue);
      } else if (parseDouble(text, c.fvalue)) {
        c.isInteger = false;
      } else {
        why = cmd + ": " + keyText + " is not a number";
        return std::nullopt;
      }
      continue;
    }
    int64_t v = 0;
    if (!parseInt(text, v)) {
      why = cmd + ": " + keyText + " is not an integer";
      return std::nullopt;
    }
    if (v < k.lo || v > k.hi) {
      why = cmd + ": " + keyText + " is out of range " + std::to_string(k.lo) + ".." +
            std::to_string(k.hi);
      return std::nullopt;
    }
    if (key == "ch")
      c.ch = static_cast<int32_t>(v);
    else if (key == "m" || key == "t" || key == "sp")
      c.code = static_cast<int32_t>(v);
    else if (key == "offset")
      c.offset = static_cast<int32_t>(v);
    else if (key == "type" || key == "sensor" || key == "pocket" || key == "n" || key == "axis")
      c.index = static_cast<int32_t>(v);
    else
      c.ivalue = v; // temp value, tool, delta
  }
  // Integer variable types take integers in their range (hnc8-functions-2.md 3).
  if (c.kind == NcCommandKind::Var) {
    bool isFloat = c.index == 0 || c.index == 1 || c.index == 4 || c.index == 6 || c.index == 9;
    bool is64 = c.index == 3 || c.index == 8;
    if (!isFloat && !c.isInteger) {
      why = cmd + ": type " + std::to_string(c.index) +
            " holds integers, value=" + std::string(given["value"]) + " is not one";
      return std::nullopt;
    }
    if (!isFloat && !is64 && (c.ivalue < kI32Min || c.ivalue > kI32Max)) {
      why = cmd + ": value=" + std::string(given["value"]) + " does not fit type " +
            std::to_string(c.index) + " (32-bit integer)";
      return std::nullopt;
    }
  }
  return c;
}

} // namespace lj::formats

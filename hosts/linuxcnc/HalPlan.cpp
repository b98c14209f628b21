// Pin plan of the HAL component: default X/Y bit pins from the program, the map file.
#include "hosts/linuxcnc/HalPlan.h"

#include "ir/OpTable.h"

#include <algorithm>
#include <cctype>
#include <cstddef>
#include <cstdio>
#include <map>
#include <set>
#include <sstream>

namespace lj::hal {

namespace {

/// Elements of a bit area the default pins cover (X and Y are bytes: bits 0..7).
constexpr int kBitsPerByte = 8;

std::string lower(std::string_view s) {
  std::string out;
  // IEC objects are written `%I0.3`: the pin is `i0.3` (a `%` is awkward in HAL files).
  for (char c : s)
    if (c != '%') out += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return out;
}

/// A name HAL users can type: ASCII letters, digits, `_`, `-`, `.`, starting with a letter.
bool halFriendly(std::string_view name) {
  if (name.empty() || !std::isalpha(static_cast<unsigned char>(name[0]))) return false;
  return std::all_of(name.begin(), name.end(), [](char c) {
    unsigned char u = static_cast<unsigned char>(c);
    return u < 0x80 && (std::isalnum(u) || c == '_' || c == '-' || c == '.');
  });
}

formats::CliAddress bitAddress(const pipeline::Dialect &d, const TargetProfile *tp, Area area,
                               int32_t index, int bit) {
  formats::CliAddress a;
  a.area = area;
  a.index = index;
  a.bit = static_cast<int8_t>(bit);
  // Profile-laid targets (FANUC, IEC) address lj_state.mem through their profile.
  if (tp && tp->area(area).offset >= offsetof(lj_state, mem)) a.profile = tp;
  a.text = d.formatAddress(a);
  return a;
}

using BitKey = std::pair<int32_t, int>; // element, bit

void addOperandBits(const Operand &o, int span, std::set<BitKey> &into) {
  if (o.kind == Operand::Kind::Bit) {
    into.insert({o.index, o.bit});
  } else if (o.kind == Operand::Kind::Reg) {
    for (int e = 0; e < span; ++e)
      for (int b = 0; b < kBitsPerByte; ++b) into.insert({o.index + e, b});
  }
}

bool parseType(std::string_view t, PinType &type) {
  if (t == "bit")
    type = PinType::Bit;
  else if (t == "s32")
    type = PinType::S32;
  else if (t == "u32")
    type = PinType::U32;
  else if (t == "float")
    type = PinType::Float;
  else
    return false;
  return true;
}

} // namespace

std::vector<PinSpec> defaultPins(const VerifiedProgram &prog, const pipeline::Dialect &dialect) {
  std::set<BitKey> reads, writes;
  for (const Stmt &st : prog.stmts) {
    const InstrInfo &info = instrInfo(st.op);
    for (int i = 0; i < st.operandCount && i < kMaxOperands; ++i) {
      const Operand &o = st.ops[i];
      const OperandSpec &spec = info.operands[i];
      int span = spec.span ? spec.span : 1;
      if (o.area == Area::Input && !spec.writes) addOperandBits(o, span, reads);
      if (o.area == Area::Output && spec.writes) addOperandBits(o, span, writes);
    }
  }
  std::map<std::string, std::string> symbolOf; // canonical address -> HAL-friendly name
  for (const Symbol &sym : prog.symbols)
    if (halFriendly(sym.name)) symbolOf.emplace(sym.address, lower(sym.name));
  std::vector<PinSpec> pins;
  auto add = [&](const std::set<BitKey> &bits, Area area, bool out) {
    for (const auto &[index, bit] : bits) {
      PinSpec p;
      p.addr = bitAddress(dialect, prog.profile, area, index, bit);
      p.out = out;
      auto it = symbolOf.find(p.addr.text);
      p.name = it != symbolOf.end() ? it->second : lower(p.addr.text);
      pins.push_back(std::move(p));
    }
  };
  add(reads, Area::Input, false);
  add(writes, Area::Output, true);
  // Two symbols that lowercase to one name: both fall back to their addresses.
  std::map<std::string, int> uses;
  for (const PinSpec &p : pins) ++uses[p.name];
  for (PinSpec &p : pins)
    if (uses[p.name] > 1) p.name = lower(p.addr.text);
  return pins;
}

bool applyMap(std::string_view text, const std::string &file, std::vector<PinSpec> &pins,
              std::string &error, const pipeline::Dialect &dialect) {
  std::vector<PinSpec> mapped;
  bool noDefaults = false;
  std::istringstream in{std::string(text)};
  std::string line;
  int lineNo = 0;
  auto fail = [&](const std::string &why) {
    error = file + ":" + std::to_string(lineNo) + ": " + why;
    return false;
  };
  while (std::getline(in, line)) {
    ++lineNo;
    if (size_t hash = line.find('#'); hash != std::string::npos) line.erase(hash);
    std::istringstream words(line);
    std::vector<std::string> w;
    for (std::string t; words >> t;) w.push_back(t);
    if (w.empty()) continue;
    if (w.size() == 1 && w[0] == "nodefaults") {
      noDefaults = true;
      continue;
    }
    if (w.size() < 3 || w.size() > 5)
      return fail("expected `in|out bit|s32|u32|float ADDRESS [NAME] [scale=K]` or `nodefaults`");
    PinSpec p;
    if (w[0] == "in")
      p.out = false;
    else if (w[0] == "out")
      p.out = true;
    else
      return fail("direction '" + w[0] + "' is not `in` or `out`");
    if (!parseType(w[1], p.type)) return fail("type '" + w[1] + "' is not bit, s32, u32 or float");
    std::string why;
    std::optional<formats::CliAddress> addr = dialect.parseAddress(w[2], why);
    if (!addr) return fail(why);
    if (addr->area == Area::Timer || addr->area == Area::Counter)
      return fail("'" + w[2] +
                  "': timers and counters cannot be mapped (map the register or "
                  "bit the program copies them to)");
    if ((p.type == PinType::Bit) != addr->isBit())
      return fail("'" + w[2] + "': a bit pin needs a bit address (X1.0), a " + w[1] +
                  " pin a whole element (D5)");
    p.addr = *addr;
    p.addr.text = dialect.formatAddress(p.addr);
    p.name = lower(p.addr.text);
    for (size_t i = 3; i < w.size(); ++i) {
      if (w[i].rfind("scale=", 0) == 0) {
        if (p.type != PinType::Float) return fail("scale= is for float pins only");
        char *end = nullptr;
        p.scale = std::strtod(w[i].c_str() + 6, &end);
        if (*end != '\0' || !(p.scale != 0.0) || p.scale != p.scale)
          return fail("'" + w[i] + "': the scale must be a non-zero number");
      } else if (i == 3) {
        if (!halFriendly(w[i]))
          return fail("pin name '" + w[i] +
                      "' must start with a letter and use only ASCII letters, digits, _ - .");
        p.name = w[i];
      } else {
        return fail("unexpected '" + w[i] + "'");
      }
    }
    // One element may feed several output pins (a bit and a number, two scales), but two
    // input pins writing one element would fight.
    for (const PinSpec &m : mapped)
      if (!p.out && !m.out && m.addr.text == p.addr.text)
        return fail("'" + p.addr.text + "' is mapped as an input twice");
    mapped.push_back(std::move(p));
  }
  if (noDefaults) pins.clear();
  // A map line replaces the default pin of its address and direction (the first such line
  // does; further output lines for that element add pins).
  std::vector<bool> replaced(pins.size(), false);
  for (PinSpec &m : mapped) {
    size_t i = 0;
    while (i < replaced.size() &&
           (replaced[i] || pins[i].addr.text != m.addr.text || pins[i].out != m.out))
      ++i;
    if (i < replaced.size()) {
      pins[i] = std::move(m);
      replaced[i] = true;
    } else {
      pins.push_back(std::move(m));
    }
  }
  return true;
}

bool classicLadderPins(const ClassicSizes &sizes, const pipeline::Dialect &dialect,
                       std::vector<PinSpec> &pins, std::string &error) {
  struct Kind {
    const char *param, *pin, *var;
    int32_t size, byDefault;
    PinType type;
    bool out;
  };
  const Kind kinds[] = {
      {"numPhysInputs", "in", "%I", sizes.physInputs, 15, PinType::Bit, false},
      {"numPhysOutputs", "out", "%Q", sizes.physOutputs, 15, PinType::Bit, true},
      {"numS32in", "s32in", "%IW", sizes.s32in, 10, PinType::S32, false},
      {"numS32out", "s32out", "%QW", sizes.s32out, 10, PinType::S32, true},
      {"numFloatIn", "floatin", "%IF", sizes.floatIn, 10, PinType::Float, false},
      {"numFloatOut", "floatout", "%QF", sizes.floatOut, 10, PinType::Float, true}};
  pins.clear();
  for (const Kind &k : kinds) {
    const int32_t n = k.size > 0 ? k.size : k.byDefault;
    for (int32_t i = 0; i < n; ++i) {
      std::string why;
      std::optional<formats::CliAddress> a = dialect.parseAddress(k.var + std::to_string(i), why);
      if (!a) {
        error = std::string(k.param) + "=" + std::to_string(n) + ": " + why;
        return false;
      }
      char name[32];
      std::snprintf(name, sizeof name, "%s-%02d", k.pin, static_cast<int>(i));
      PinSpec p;
      p.name = name;
      p.type = k.type;
      p.out = k.out;
      p.addr = *a;
      p.truncate = k.type == PinType::Float && !k.out;
      pins.push_back(std::move(p));
    }
  }
  return true;
}

bool checkPins(const std::vector<PinSpec> &pins, const std::string &prefix, std::string &error) {
  std::set<std::string> names;
  for (const PinSpec &p : pins) {
    std::string full = prefix + "." + p.name;
    if (full.size() > kHalNameLen) {
      error = "pin name '" + full + "' is longer than HAL's " + std::to_string(kHalNameLen) +
              " characters; give a shorter name in the map file";
      return false;
    }
    if (!names.insert(p.name).second) {
      error = "two pins are named '" + full + "' (" + p.addr.text + "); rename one in the map file";
      return false;
    }
  }
  return true;
}

} // namespace lj::hal

// VCD and CSV writers of signal recordings (formats/Vcd.h, docs/trace.md "Files").
#include "formats/Vcd.h"

#include "profiles/Profiles.h"

#include <charconv>

namespace lj::formats {

namespace {

void appendNumber(std::string &out, uint64_t v) {
  char tmp[24];
  auto res = std::to_chars(tmp, tmp + sizeof tmp, v);
  out.append(tmp, res.ptr);
}

void appendSigned(std::string &out, int64_t v) {
  char tmp[24];
  auto res = std::to_chars(tmp, tmp + sizeof tmp, v);
  out.append(tmp, res.ptr);
}

// The short identifier code of variable `n`: printable ASCII '!'..'~' in base 94 (IEEE 1364
// 18.2.3.1 allows any printable ASCII but white space).
std::string idCode(size_t n) {
  std::string id;
  do {
    id += static_cast<char>('!' + n % 94);
    n /= 94;
  } while (n > 0);
  return id;
}

uint64_t maskOf(int bits) { return bits >= 64 ? ~uint64_t{0} : (uint64_t{1} << bits) - 1; }

} // namespace

int signalBits(const CliAddress &addr) {
  if (addr.isBit()) return 1;
  if (addr.area == Area::Timer || addr.area == Area::Counter) return 32;
  if (addr.area == Area::None) return 8; // a system-parameter byte
  if (addr.width) return addr.width * 8;
  const TargetProfile &tp = addr.profile ? *addr.profile : *profileNamed("hnc8");
  const int bytes = tp.area(addr.area).bytes;
  return bytes > 0 ? bytes * 8 : 32;
}

std::string vcdTimescale(uint64_t periodNs, uint64_t &unitsPerTick) {
  static const struct {
    uint64_t ns;
    const char *text;
  } kUnits[] = {{100000000000, "100s"}, {10000000000, "10s"}, {1000000000, "1s"},
                {100000000, "100ms"},   {10000000, "10ms"},   {1000000, "1ms"},
                {100000, "100us"},      {10000, "10us"},      {1000, "1us"},
                {100, "100ns"},         {10, "10ns"}};
  for (const auto &u : kUnits) {
    if (periodNs >= u.ns && periodNs % u.ns == 0) {
      unitsPerTick = periodNs / u.ns;
      return u.text;
    }
  }
  unitsPerTick = periodNs ? periodNs : 1;
  return "1ns";
}

std::string vcdName(std::string_view name) {
  std::string out;
  for (char c : name) {
    const auto u = static_cast<unsigned char>(c);
    out += (u <= 0x20 || u == 0x7f) ? '_' : c;
  }
  if (out.empty() || out[0] == '$') out.insert(out.begin(), '_');
  return out;
}

VcdWriter::VcdWriter(std::vector<SignalInfo> signals, uint64_t periodNs, bool splitBits,
                     std::string comment)
    : signals_(std::move(signals)), comment_(std::move(comment)) {
  timescale_ = vcdTimescale(periodNs, unitsPerTick_);
  for (size_t i = 0; i < signals_.size(); ++i) {
    const int bits = signals_[i].bits;
    if (bits == 1 || !splitBits) {
      vars_.push_back(Var{idCode(vars_.size()), static_cast<int>(i), -1, bits});
      continue;
    }
    for (int b = 0; b < bits; ++b)
      vars_.push_back(Var{idCode(vars_.size()), static_cast<int>(i), b, 1});
  }
}

std::string VcdWriter::header() const {
  std::string h = "$version ladderjit $end\n";
  if (!comment_.empty()) h += "$comment " + comment_ + " $end\n";
  h += "$timescale " + timescale_ + " $end\n$scope module ladderjit $end\n";
  for (const Var &v : vars_) {
    h += "$var wire ";
    appendNumber(h, static_cast<uint64_t>(v.bits));
    h += ' ';
    h += v.id;
    h += ' ';
    h += vcdName(signals_[static_cast<size_t>(v.signal)].name);
    if (v.bit >= 0) {
      h += '[';
      appendNumber(h, static_cast<uint64_t>(v.bit));
      h += ']';
    }
    h += " $end\n";
  }
  h += "$upscope $end\n$enddefinitions $end\n";
  return h;
}

void VcdWriter::row(uint64_t tick, const int64_t *values, std::string &out) {
  bool stamped = false;
  for (Var &v : vars_) {
    const int sigBits = signals_[static_cast<size_t>(v.signal)].bits;
    uint64_t raw = static_cast<uint64_t>(values[v.signal]) & maskOf(sigBits);
    if (v.bit >= 0) raw = (raw >> v.bit) & 1u;
    if (!first_ && raw == v.last) continue;
    v.last = raw;
    if (!stamped) {
      out += '#';
      appendNumber(out, tick * unitsPerTick_);
      out += '\n';
      stamped = true;
    }
    if (v.bits == 1) {
      out += raw ? '1' : '0';
    } else {
      out += 'b';
      int top = v.bits - 1;
      while (top > 0 && !((raw >> top) & 1u)) --top;
      for (int b = top; b >= 0; --b) out += ((raw >> b) & 1u) ? '1' : '0';
      out += ' ';
    }
    out += v.id;
    out += '\n';
  }
  first_ = false;
}

void VcdWriter::finish(uint64_t lastTick, std::string &out) const {
  out += '#';
  appendNumber(out, (lastTick + 1) * unitsPerTick_);
  out += '\n';
}

std::string csvHeader(const std::vector<SignalInfo> &signals, bool withTrigger) {
  std::string h = "tick,ms";
  for (const SignalInfo &s : signals) h += "," + s.name;
  if (withTrigger) h += ",trigger";
  h += '\n';
  return h;
}

void csvRow(uint64_t tick, uint64_t periodNs, const int64_t *values, size_t count,
            int64_t triggerTick, std::string &out) {
  appendNumber(out, tick);
  out += ',';
  const uint64_t ns = tick * periodNs;
  appendNumber(out, ns / 1000000);
  if (uint64_t frac = ns % 1000000; frac != 0) {
    std::string digits = std::to_string(frac);
    digits.insert(0, 6 - digits.size(), '0');
    while (digits.back() == '0') digits.pop_back();
    out += '.';
    out += digits;
  }
  for (size_t i = 0; i < count; ++i) {
    out += ',';
    appendSigned(out, values[i]);
  }
  if (triggerTick >= 0) out += static_cast<uint64_t>(triggerTick) == tick ? ",1" : ",0";
  out += '\n';
}

} // namespace lj::formats

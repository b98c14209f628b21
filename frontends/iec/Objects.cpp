// Neza objects <-> IR operands on the IEC profile's layout (profiles/iec/IecProfile.h).
#include "frontends/iec/Objects.h"
#include "frontends/common/OperandText.h"

#include "ir/IecBlocks.h"
#include "profiles/iec/IecProfile.h"

#include <cctype>

namespace lj::iec {

namespace {

bool startsWithCi(std::string_view s, std::string_view p) {
  if (s.size() < p.size()) return false;
  for (size_t i = 0; i < p.size(); ++i)
    if (std::toupper(static_cast<unsigned char>(s[i])) != p[i]) return false;
  return true;
}

/// Leading decimal digits of `s` (saturating), advancing `s`; nullopt when there are none.
std::optional<int64_t> digits(std::string_view &s) {
  size_t n = 0;
  int64_t v = 0;
  while (n < s.size() && std::isdigit(static_cast<unsigned char>(s[n]))) {
    v = std::min<int64_t>(v * 10 + (s[n] - '0'), int64_t{1} << 40);
    ++n;
  }
  if (n == 0) return std::nullopt;
  s.remove_prefix(n);
  return v;
}

Operand bitOp(Area a, int32_t index, int bit) {
  Operand o;
  o.kind = Operand::Kind::Bit;
  o.area = a;
  o.index = index;
  o.bit = static_cast<int8_t>(bit);
  return o;
}

Operand regOp(Area a, int32_t index) {
  Operand o;
  o.kind = Operand::Kind::Reg;
  o.area = a;
  o.index = index;
  return o;
}

std::string range(const char *what, int64_t hi) {
  const std::string w(what);
  return w + (w.empty() ? "" : " ") + "(0.." + std::to_string(hi) + ")";
}

/// %TMi, %TMi.Q/.V/.P, %Ci, %Ci.E/.D/.F/.V/.P (modicon-neza.md 1.2); `s` after the '%'.
template <class Fail> std::optional<Object> blockObject(std::string_view s, Fail &fail) {
  const bool timer = startsWithCi(s, "TM");
  s.remove_prefix(timer ? 2 : 1);
  std::optional<int64_t> n = digits(s);
  if (!n)
    return fail(timer ? "expected a timer number after %TM"
                      : "expected a counter number "
                        "after %C");
  const int32_t limit = timer ? kTimers : kCounters;
  if (*n >= limit)
    return fail(std::string(timer ? "timer" : "counter") + " number out of range " +
                range("", limit - 1));
  Object obj;
  obj.number = static_cast<int32_t>(*n);
  const Area area = timer ? Area::TimerData : Area::CounterData;
  const int32_t base = obj.number * (timer ? iec::kTimerWords : iec::kCounterWords);
  if (s.empty()) {
    obj.cls = timer ? ObjClass::Timer : ObjClass::Counter;
    obj.op = regOp(area, base);
    return obj;
  }
  if (s.size() != 2 || s[0] != '.')
    return fail(timer ? "expected %TMi, %TMi.Q, %TMi.V or %TMi.P"
                      : "expected %Ci, %Ci.E, %Ci.D, %Ci.F, %Ci.V or %Ci.P");
  const char f = static_cast<char>(std::toupper(static_cast<unsigned char>(s[1])));
  if (f == 'V' || f == 'P') {
    obj.cls = ObjClass::BlockWord;
    obj.writable = f == 'P';
    obj.op = regOp(area, base + (f == 'V' ? 0 : 1)); // kTimerV / kCounterV, then P
    return obj;
  }
  const int32_t status = base + (timer ? int32_t{iec::kTimerStatus} : int32_t{iec::kCounterStatus});
  obj.cls = ObjClass::BlockBit;
  if (timer && f == 'Q') {
    obj.op = bitOp(area, status, iec::kTimerQ);
    return obj;
  }
  if (!timer && (f == 'E' || f == 'D' || f == 'F')) {
    obj.op = bitOp(area, status,
                   f == 'E'   ? iec::kCounterE
                   : f == 'D' ? iec::kCounterD
                              : iec::kCounterF);
    return obj;
  }
  return fail(timer ? "a timer has the outputs Q, V and P" : "a counter has E, D, F, V and P");
}

} // namespace

std::optional<Object> parseObject(std::string_view text, std::string &error) {
  const std::string t(text);
  auto fail = [&](const std::string &why) -> std::optional<Object> {
    error = "'" + t.substr(0, 40) + "': " + why;
    return std::nullopt;
  };
  std::string_view s = text;
  Object obj;
  if (s.empty()) return fail("empty operand");
  if (std::isdigit(static_cast<unsigned char>(s[0])) || s[0] == '-' || s[0] == '+') {
    bool neg = s[0] == '-';
    if (s[0] == '-' || s[0] == '+') s.remove_prefix(1);
    std::optional<int64_t> v = digits(s);
    if (!v || !s.empty()) return fail("not a number");
    const int64_t value = neg ? -*v : *v;
    if (value < -32768 || value > 65535) return fail("constant out of range (-32768..65535)");
    obj.cls = ObjClass::Immediate;
    obj.number = static_cast<int32_t>(value);
    obj.op.kind = Operand::Kind::Const;
    obj.op.value = obj.number;
    return obj;
  }
  if (startsWithCi(s, "SR")) {
    s.remove_prefix(2);
    std::optional<int64_t> n = digits(s);
    if (!n || !s.empty()) return fail("expected SRi");
    if (*n >= kSubroutines)
      return fail("subroutine number out of range " + range("", kSubroutines - 1));
    obj.cls = ObjClass::Sub;
    obj.number = static_cast<int32_t>(*n);
    obj.op = regOp(Area::Subroutine, obj.number);
    return obj;
  }
  if (s[0] != '%')
    return fail("expected an object (%I, %Q, %M, %S, %MW, %KW, %SW, %L) or a number");
  s.remove_prefix(1);
  // Longest prefixes first: %MW before %M, %SW before %S.
  struct Kind {
    const char *prefix;
    ObjClass cls;
  };
  constexpr Kind kKinds[] = {{"MW", ObjClass::Word},     {"KW", ObjClass::ConstWord},
                             {"SW", ObjClass::Word},     {"I", ObjClass::InputBit},
                             {"Q", ObjClass::OutputBit}, {"M", ObjClass::MemoryBit},
                             {"S", ObjClass::SystemBit}, {"L", ObjClass::Label}};
  const Kind *kind = nullptr;
  if (startsWithCi(s, "SBR") || startsWithCi(s, "SC"))
    return fail("the function blocks %SBRi and %SCi are not supported (their pages are missing "
                "from the seed; docs/iec-il.md)");
  for (const Kind &k : kKinds)
    if (startsWithCi(s, k.prefix)) {
      kind = &k;
      break;
    }
  if (!kind) {
    if (startsWithCi(s, "TM") || startsWithCi(s, "C")) return blockObject(s, fail);
    if (startsWithCi(s, "R") || startsWithCi(s, "DR"))
      return fail("the function blocks %Ri and %DRi are not supported (their pages are missing "
                  "from the seed; docs/iec-il.md)");
    return fail("unknown object type (expected %I, %Q, %M, %S, %MW, %KW, %SW, %TM, %C or %L)");
  }
  const bool sysWord = std::string_view(kind->prefix) == "SW";
  s.remove_prefix(std::string_view(kind->prefix).size());
  std::optional<int64_t> n = digits(s);
  if (!n) return fail(std::string("expected a number after %") + kind->prefix);
  obj.cls = kind->cls;
  switch (kind->cls) {
  case ObjClass::InputBit:
  case ObjClass::OutputBit: {
    if (s.empty() || s[0] != '.') return fail("expected %Ii.j / %Qi.j (unit.point)");
    s.remove_prefix(1);
    std::optional<int64_t> j = digits(s);
    if (!j || !s.empty()) return fail("expected a point number after the '.'");
    if (*n >= kUnits)
      return fail("unit " + std::to_string(*n) + " is out of range " + range("", kUnits - 1));
    if (*j >= kPointsPerUnit)
      return fail("point " + std::to_string(*j) + " is out of range " +
                  range("", kPointsPerUnit - 1));
    const int32_t point = static_cast<int32_t>(*n * kPointsPerUnit + *j);
    obj.number = point;
    obj.op =
        bitOp(kind->cls == ObjClass::InputBit ? Area::Input : Area::Output, point / 8, point % 8);
    return obj;
  }
  case ObjClass::MemoryBit:
  case ObjClass::SystemBit: {
    if (!s.empty()) return fail("unexpected text after the bit number");
    const int32_t limit = kind->cls == ObjClass::MemoryBit ? kMemoryBits : kSystemBits;
    if (*n >= limit) return fail("bit number out of range " + range("", limit - 1));
    obj.number = static_cast<int32_t>(*n);
    if (kind->cls == ObjClass::SystemBit)
      obj.op = bitOp(Area::SystemBits, obj.number / 8, obj.number % 8);
    else if (obj.number < kRetainedBits)
      obj.op = bitOp(Area::KeepRelay, obj.number / 8, obj.number % 8);
    else
      obj.op =
          bitOp(Area::Relay, (obj.number - kRetainedBits) / 8, (obj.number - kRetainedBits) % 8);
    return obj;
  }
  case ObjClass::Label:
    if (!s.empty()) return fail("unexpected text after the label number");
    if (*n >= kLabels) return fail("label number out of range " + range("", kLabels - 1));
    obj.number = static_cast<int32_t>(*n);
    obj.op = regOp(Area::Label, obj.number);
    return obj;
  default:
    break;
  }
  // Words: %MWi, %KWi, %SWi, optionally :Xk.
  const Area area = kind->cls == ObjClass::ConstWord ? Area::ConstWords
                    : sysWord                        ? Area::SystemWords
                                                     : Area::Word;
  const int32_t limit = area == Area::ConstWords ? kConstWords : sysWord ? kSystemWords : kWords;
  if (*n >= limit) return fail("word number out of range " + range("", limit - 1));
  obj.number = static_cast<int32_t>(*n);
  if (s.empty()) {
    obj.op = regOp(area, obj.number);
    return obj;
  }
  if (!startsWithCi(s, ":X")) return fail("expected :Xk after the word");
  s.remove_prefix(2);
  std::optional<int64_t> k = digits(s);
  if (!k || !s.empty()) return fail("expected a bit number after :X");
  if (*k > 15) return fail("bit " + std::to_string(*k) + " of a word is out of range (0..15)");
  obj.cls = ObjClass::WordBit;
  obj.op = bitOp(area, obj.number, static_cast<int>(*k));
  return obj;
}

std::string formatOperand(const Operand &op) {
  switch (op.kind) {
  case Operand::Kind::None:
    return "";
  case Operand::Kind::Const:
    return frontend::constantText(op.value);
  case Operand::Kind::Reg:
    switch (op.area) {
    case Area::Label:
      return "%L" + std::to_string(op.index);
    case Area::Subroutine:
      return "SR" + std::to_string(op.index);
    case Area::ConstWords:
      return "%KW" + std::to_string(op.index);
    case Area::SystemWords:
      return "%SW" + std::to_string(op.index);
    case Area::TimerData:
    case Area::CounterData: {
      const bool t = op.area == Area::TimerData;
      const int32_t per = t ? iec::kTimerWords : iec::kCounterWords;
      const int32_t w = op.index % per;
      return std::string(t ? "%TM" : "%C") + std::to_string(op.index / per) +
             (w == 0   ? ".V"
              : w == 1 ? ".P"
                       : ".W" + std::to_string(w));
    }
    default:
      return "%MW" + std::to_string(op.index);
    }
  case Operand::Kind::Bit:
    break;
  }
  const std::string k = std::to_string(op.bit);
  switch (op.area) {
  case Area::Input:
  case Area::Output: {
    const int32_t point = op.index * 8 + op.bit;
    return std::string(op.area == Area::Input ? "%I" : "%Q") +
           std::to_string(point / kPointsPerUnit) + "." + std::to_string(point % kPointsPerUnit);
  }
  case Area::KeepRelay:
    return "%M" + std::to_string(op.index * 8 + op.bit);
  case Area::Relay:
    return "%M" + std::to_string(kRetainedBits + op.index * 8 + op.bit);
  case Area::ExtraRelay:
    return "%~" + std::to_string(op.index * 8 + op.bit);
  case Area::SystemBits:
    return "%S" + std::to_string(op.index * 8 + op.bit);
  case Area::ConstWords:
    return "%KW" + std::to_string(op.index) + ":X" + k;
  case Area::SystemWords:
    return "%SW" + std::to_string(op.index) + ":X" + k;
  case Area::Word:
    return "%MW" + std::to_string(op.index) + ":X" + k;
  case Area::TimerData:
    return "%TM" + std::to_string(op.index / iec::kTimerWords) + (op.bit == 0 ? ".Q" : ".X" + k);
  case Area::CounterData:
    return "%C" + std::to_string(op.index / iec::kCounterWords) +
           (op.bit == iec::kCounterE   ? ".E"
            : op.bit == iec::kCounterD ? ".D"
            : op.bit == iec::kCounterF ? ".F"
                                       : ".X" + k);
  default:
    return "%?" + std::to_string(op.index) + "." + k;
  }
}

} // namespace lj::iec

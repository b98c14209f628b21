// FunctionBlocks (Blocks.h): the Neza %TMi / %Ci blocks onto Op::IecTimer / Op::IecCounter.
#include "frontends/iec/Blocks.h"

#include "ir/IecBlocks.h"
#include "profiles/iec/IecProfile.h"

#include <cctype>

namespace lj::iec {

namespace {

std::string upper(std::string_view s) {
  std::string out(s);
  for (char &c : out) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return out;
}

bool blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == ','; }

Operand konst(int32_t v) {
  Operand o;
  o.kind = Operand::Kind::Const;
  o.value = v;
  return o;
}

constexpr const char *kCounterPins[] = {"R", "S", "CU", "CD"};

} // namespace

std::string FunctionBlocks::name(const Object &blk) {
  return (blk.cls == ObjClass::Timer ? "%TM" : "%C") + std::to_string(blk.number);
}

std::string FunctionBlocks::openBlock() const {
  if (!open_) return "";
  return "BLK " + name(open_->blk) + " (line " + std::to_string(open_->loc.line) + ")";
}

FunctionBlocks::Config &FunctionBlocks::configOf(const Object &blk) {
  return configs_[{blk.cls == ObjClass::Timer ? 0 : 1, blk.number}];
}

void FunctionBlocks::use(const Object &obj) {
  if (obj.op.area != Area::TimerData && obj.op.area != Area::CounterData) return;
  const bool timer = obj.op.area == Area::TimerData;
  const int32_t n = obj.op.index / (timer ? kTimerWords : kCounterWords);
  configs_.try_emplace({timer ? 0 : 1, n});
}

void FunctionBlocks::config(std::string_view args, SourceLoc loc) {
  // Split into blank- or comma-separated words.
  std::vector<std::string> words;
  std::string cur;
  for (char c : args) {
    if (blank(c)) {
      if (!cur.empty()) words.push_back(upper(cur));
      cur.clear();
    } else {
      cur += c;
    }
  }
  if (!cur.empty()) words.push_back(upper(cur));
  if (words.empty()) {
    diags_.error(loc, "LJ2001",
                 "CONFIG needs a block: CONFIG %TMi [TON|TOF|TP] [TB=...] [P=n] or "
                 "CONFIG %Ci [P=n]");
    return;
  }
  std::string err;
  std::optional<Object> blk = parseObject(words[0], err);
  if (!blk || !isBlock(*blk)) {
    diags_.error(loc, "LJ2002",
                 "CONFIG: " + (blk ? "'" + words[0] + "' is not a block (%TMi or %Ci)" : err));
    return;
  }
  const bool timer = blk->cls == ObjClass::Timer;
  Config &c = configOf(*blk);
  if (c.loc.line != 0) {
    diags_.error(loc, "LJ2003",
                 "CONFIG " + name(*blk) + " again (first on line " + std::to_string(c.loc.line) +
                     ")");
    return;
  }
  c.loc = loc;
  for (size_t k = 1; k < words.size(); ++k) {
    const std::string &w = words[k];
    if (timer && (w == "TON" || w == "TOF" || w == "TP")) {
      c.type = static_cast<int32_t>(w == "TON"   ? TimerType::Ton
                                    : w == "TOF" ? TimerType::Tof
                                                 : TimerType::Tp);
      continue;
    }
    if (timer && w.rfind("TB=", 0) == 0) {
      static const char *const kBases[] = {"1MIN", "1S", "100MS", "10MS", "1MS"};
      int code = -1;
      for (int b = 0; b < 5; ++b)
        if (w.substr(3) == kBases[b]) code = b;
      if (code < 0) {
        diags_.error(loc, "LJ2004",
                     "CONFIG " + name(*blk) + ": time base '" + w.substr(3) +
                         "' (1MIN, 1S, 100MS, 10MS or 1MS; modicon-neza.md 3.3, L1274)");
        continue;
      }
      if (code == 4 && blk->number > 1) {
        diags_.error(loc, "LJ2005",
                     "CONFIG " + name(*blk) +
                         ": the 1 ms time base is only for %TM0 and "
                         "%TM1 (modicon-neza.md 3.3, L1274-1275)");
        continue;
      }
      c.timeBase = code;
      continue;
    }
    if (w.rfind("P=", 0) == 0) {
      std::string digits = w.substr(2);
      bool ok = !digits.empty() && digits.size() <= 6;
      for (char d : digits) ok = ok && std::isdigit(static_cast<unsigned char>(d));
      const int32_t v = ok ? std::stoi(digits) : -1;
      if (!ok || v > kPresetMax) {
        diags_.error(loc, "LJ2006",
                     "CONFIG " + name(*blk) + ": preset '" + digits +
                         "' out of range (0 <= P <= 9999; modicon-neza.md 3.3, L1276-1278)");
        continue;
      }
      c.preset = v;
      continue;
    }
    diags_.error(loc, "LJ2007",
                 "CONFIG " + name(*blk) + ": unknown setting '" + w + "' (" +
                     (timer ? "TON, TOF, TP, TB=..., P=n" : "a counter takes only P=n") + ")");
  }
}

void FunctionBlocks::begin(std::string_view text, SourceLoc loc, SourceLoc opLoc) {
  if (open_) {
    diags_.error(loc, "LJ2008",
                 "BLK inside " + openBlock() + ": blocks do not nest (END_BLK ends the first one)");
    return;
  }
  if (text.empty()) {
    diags_.error(loc, "LJ2009", "BLK needs a block: BLK %TMi or BLK %Ci");
    return;
  }
  std::string err;
  std::optional<Object> blk = parseObject(text, err);
  if (!blk || !isBlock(*blk)) {
    diags_.error(opLoc, "LJ2010",
                 "BLK: " + (blk ? "'" + std::string(text) +
                                      "' is not a function block (%TMi timer, %Ci counter)"
                                : err));
    return;
  }
  use(*blk);
  open_ = Open{}; // not emplace(): clang rejects it for a nested aggregate with member initializers
  open_->blk = *blk;
  open_->loc = loc;
}

int FunctionBlocks::pinIndex(const Object &blk, const std::string &mnem, SourceLoc loc) {
  if (blk.cls == ObjClass::Timer) {
    if (mnem == "IN") return 0;
  } else {
    for (int k = 0; k < 4; ++k)
      if (mnem == kCounterPins[k]) return k;
  }
  diags_.error(loc, "LJ2011",
               mnem + " is not an input of " + name(blk) + " (" +
                   (blk.cls == ObjClass::Timer ? "a timer has the input IN"
                                               : "a counter has the inputs R, S, CU, CD") +
                   "; modicon-neza.md 3.2-3.3)");
  return -1;
}

void FunctionBlocks::pin(const std::string &mnem, SourceLoc loc) {
  const int k = pinIndex(open_->blk, mnem, loc);
  if (k < 0) return;
  if (open_->pins[static_cast<size_t>(k)]) {
    diags_.error(loc, "LJ2012",
                 mnem + " of " + name(open_->blk) + " is given twice in " + openBlock());
    return;
  }
  const Operand latch = em_.scratch(loc);
  em_.emit(Op::Coil, loc, {latch});
  open_->pins[static_cast<size_t>(k)] = latch;
}

Operand FunctionBlocks::zero(SourceLoc loc) {
  if (!zero_) zero_ = em_.scratch(loc); // never written: always 0
  return *zero_;
}

void FunctionBlocks::run(SourceLoc loc) {
  Open &b = *open_;
  b.ran = true;
  Config &c = configOf(b.blk);
  if (b.blk.cls == ObjClass::Timer) {
    if (!b.pins[0]) {
      diags_.error(b.loc, "LJ2013",
                   "BLK " + name(b.blk) + " has no IN input before " +
                       (b.outputs ? "OUT_BLK" : "END_BLK"));
      return;
    }
    em_.emit(Op::Load, loc, {*b.pins[0]});
    em_.emit(Op::IecTimer, loc, {b.blk.op, konst(c.type), konst(c.timeBase)});
    return;
  }
  int32_t mask = 0;
  for (int k = 0; k < 4; ++k)
    if (b.pins[static_cast<size_t>(k)]) mask |= 1 << k;
  if (mask == 0) {
    diags_.error(b.loc, "LJ2014",
                 "BLK " + name(b.blk) + " has no input (R, S, CU or CD) before " +
                     (b.outputs ? "OUT_BLK" : "END_BLK"));
    return;
  }
  for (int k = 0; k < 4; ++k)
    em_.emit(Op::Load, loc, {b.pins[static_cast<size_t>(k)].value_or(zero(loc))});
  em_.emit(Op::IecCounter, loc, {b.blk.op, konst(mask)});
}

void FunctionBlocks::outputs(SourceLoc loc) {
  if (!open_) {
    diags_.error(loc, "LJ2015", "OUT_BLK without BLK");
    return;
  }
  if (open_->outputs) {
    diags_.error(loc, "LJ2016", "OUT_BLK twice in " + openBlock());
    return;
  }
  open_->outputs = true;
  run(loc);
}

void FunctionBlocks::end(SourceLoc loc) {
  if (!open_) {
    diags_.error(loc, "LJ2017", "END_BLK without BLK");
    return;
  }
  if (!open_->ran) run(loc);
  open_.reset();
}

void FunctionBlocks::direct(const std::string &mnem, const Object &blk, SourceLoc loc,
                            SourceLoc opLoc) {
  use(blk);
  const int k = pinIndex(blk, mnem, opLoc);
  if (k < 0) return;
  Config &c = configOf(blk);
  if (blk.cls == ObjClass::Timer) {
    em_.emit(Op::IecTimer, loc, {blk.op, konst(c.type), konst(c.timeBase)});
    return;
  }
  // The counter runs with the accumulator on input k; LD of the latch gives the accumulator back.
  const Operand acc = em_.scratch(loc);
  em_.emit(Op::Coil, loc, {acc});
  for (int p = 0; p < 4; ++p) em_.emit(Op::Load, loc, {p == k ? acc : zero(loc)});
  em_.emit(Op::IecCounter, loc, {blk.op, konst(1 << k)});
  em_.emit(Op::Load, loc, {acc});
}

std::optional<Object> FunctionBlocks::bare(std::string_view name, SourceLoc loc, bool &isBare) {
  const std::string n = upper(name);
  isBare = n == "E" || n == "D" || n == "F" || n == "Q";
  if (!isBare) return std::nullopt;
  if (!open_ || !open_->outputs) {
    diags_.error(loc, "LJ2018",
                 "'" + n +
                     "' names a block output only between OUT_BLK and END_BLK; "
                     "elsewhere write it in full (%Ci." +
                     n + ", %TMi.Q; modicon-neza.md 1.2, L1082-1085)");
    return std::nullopt;
  }
  std::string err;
  std::optional<Object> o = parseObject(FunctionBlocks::name(open_->blk) + "." + n, err);
  if (!o)
    diags_.error(loc, "LJ2019", "'" + n + "' is not an output of " + openBlock() + ": " + err);
  return o;
}

void FunctionBlocks::mustBeClosed(SourceLoc loc, const std::string &where) {
  if (!open_) return;
  diags_.error(open_->loc, "LJ2020",
               openBlock() + " is not closed by END_BLK before " + where + " (line " +
                   std::to_string(loc.line) + ")");
  open_.reset();
}

std::vector<Stmt> FunctionBlocks::presets(SourceLoc loc) const {
  std::vector<Stmt> out;
  if (configs_.empty()) return out;
  Stmt one;
  one.op = Op::LoadTrue;
  one.loc = loc;
  out.push_back(one);
  for (const auto &[key, c] : configs_) {
    Stmt s;
    s.op = Op::Move;
    s.loc = c.loc.line ? c.loc : loc;
    s.ops[0] = konst(c.preset);
    s.ops[0].loc = s.loc;
    Operand &p = s.ops[1];
    p.kind = Operand::Kind::Reg;
    p.area = key.first == 0 ? Area::TimerData : Area::CounterData;
    p.index = key.second * (key.first == 0 ? kTimerWords : kCounterWords) + 1; // .P
    p.loc = s.loc;
    s.operandCount = 2;
    out.push_back(s);
  }
  return out;
}

} // namespace lj::iec

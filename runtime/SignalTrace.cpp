// The signal trace (runtime/SignalTrace.h, docs/trace.md).
#include "runtime/SignalTrace.h"

#include "profiles/Profiles.h"
#include "runtime/Executive.h"

#include <charconv>
#include <cstddef>
#include <cstring>

namespace lj::rt {

namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t' || s.front() == '\r'))
    s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r'))
    s.remove_suffix(1);
  return s;
}

bool parseCount(std::string_view s, uint32_t &out) {
  s = trim(s);
  auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), out);
  return !s.empty() && ec == std::errc() && end == s.data() + s.size();
}

const char *opText(CompareOp op) {
  switch (op) {
  case CompareOp::Eq:
    return "=";
  case CompareOp::Ne:
    return "<>";
  case CompareOp::Lt:
    return "<";
  case CompareOp::Gt:
    return ">";
  case CompareOp::Le:
    return "<=";
  case CompareOp::Ge:
    return ">=";
  }
  return "=";
}

bool compare(int64_t v, CompareOp op, int64_t k) {
  switch (op) {
  case CompareOp::Eq:
    return v == k;
  case CompareOp::Ne:
    return v != k;
  case CompareOp::Lt:
    return v < k;
  case CompareOp::Gt:
    return v > k;
  case CompareOp::Le:
    return v <= k;
  case CompareOp::Ge:
    return v >= k;
  }
  return false;
}

// `ADDR OP VALUE` (spaces optional): the first of <> <= >= = < > splits it.
bool parseComparison(std::string_view s, TraceDefinition &d, std::string &why) {
  size_t at = s.find_first_of("<>=");
  if (at == std::string_view::npos) {
    why = "expected manual, immediate, rising ADDR, falling ADDR or ADDR OP VALUE";
    return false;
  }
  std::string_view rest = s.substr(at);
  static const struct {
    const char *text;
    CompareOp op;
  } kOps[] = {{"<>", CompareOp::Ne}, {"<=", CompareOp::Le}, {">=", CompareOp::Ge},
              {"=", CompareOp::Eq},  {"<", CompareOp::Lt},  {">", CompareOp::Gt}};
  for (const auto &o : kOps) {
    const size_t n = std::strlen(o.text);
    if (rest.substr(0, n) != o.text) continue;
    d.triggerAddress = std::string(trim(s.substr(0, at)));
    std::optional<int64_t> v = formats::parseValue(trim(rest.substr(n)), why);
    if (d.triggerAddress.empty()) {
      why = "the comparison needs an address before " + std::string(o.text);
      return false;
    }
    if (!v) return false;
    d.trigger = TriggerKind::Compare;
    d.op = o.op;
    d.value = *v;
    return true;
  }
  why = "bad comparison";
  return false;
}

} // namespace

std::optional<TraceDefinition> parseTraceDefinition(std::string_view text, const std::string &file,
                                                    std::string &error) {
  TraceDefinition d;
  bool sawPre = false, sawPost = false;
  int line = 0;
  size_t pos = 0;
  while (pos <= text.size()) {
    size_t nl = text.find('\n', pos);
    std::string_view raw = text.substr(pos, nl == std::string_view::npos ? nl : nl - pos);
    pos = nl == std::string_view::npos ? text.size() + 1 : nl + 1;
    ++line;
    if (size_t hash = raw.find('#'); hash != std::string_view::npos) raw = raw.substr(0, hash);
    std::string_view l = trim(raw);
    if (l.empty()) continue;
    auto fail = [&](const std::string &why) {
      error = file + ":" + std::to_string(line) + ": " + why;
      return std::nullopt;
    };
    size_t sp = l.find_first_of(" \t");
    std::string_view key = l.substr(0, sp);
    std::string_view arg = sp == std::string_view::npos ? std::string_view{} : trim(l.substr(sp));
    if (key == "signal" || key == "signals") {
      if (arg.empty()) return fail("signal needs ADDR[, ADDR...]");
      size_t p = 0;
      while (p <= arg.size()) {
        size_t comma = arg.find(',', p);
        std::string_view item =
            trim(arg.substr(p, comma == std::string_view::npos ? comma : comma - p));
        if (item.empty()) return fail("empty address in '" + std::string(arg) + "'");
        d.signals.emplace_back(item);
        if (comma == std::string_view::npos) break;
        p = comma + 1;
      }
      if (d.signals.size() > kTraceMaxSignals)
        return fail("more than " + std::to_string(kTraceMaxSignals) + " signals");
    } else if (key == "trigger") {
      std::string why;
      if (arg == "manual") {
        d.trigger = TriggerKind::Manual;
      } else if (arg == "immediate") {
        d.trigger = TriggerKind::Immediate;
      } else if (arg.substr(0, 7) == "rising " || arg.substr(0, 8) == "falling ") {
        const bool rising = arg[0] == 'r';
        d.trigger = rising ? TriggerKind::Rising : TriggerKind::Falling;
        d.triggerAddress = std::string(trim(arg.substr(rising ? 7 : 8)));
      } else if (!parseComparison(arg, d, why)) {
        return fail("trigger: " + why);
      }
    } else if (key == "pre" || key == "post") {
      uint32_t n = 0;
      if (!parseCount(arg, n) || n >= kTraceMaxTicks)
        return fail(std::string(key) + ": expected ticks 0.." + std::to_string(kTraceMaxTicks - 1) +
                    ", got '" + std::string(arg) + "'");
      (key == "pre" ? d.pre : d.post) = n;
      (key == "pre" ? sawPre : sawPost) = true;
    } else if (key == "mode") {
      if (arg != "single" && arg != "repeat")
        return fail("mode: expected single or repeat, got '" + std::string(arg) + "'");
      d.repeat = arg == "repeat";
    } else {
      return fail("unknown item '" + std::string(key) +
                  "' (expected signal, trigger, pre, post or mode)");
    }
  }
  (void)sawPre;
  (void)sawPost;
  if (d.signals.empty()) {
    error = file + ": no signal: give 'signal ADDR[, ADDR...]'";
    return std::nullopt;
  }
  if (uint64_t{d.pre} + 1 + d.post > kTraceMaxTicks) {
    error = file + ": pre + 1 + post = " + std::to_string(uint64_t{d.pre} + 1 + d.post) +
            " ticks, more than the " + std::to_string(kTraceMaxTicks) + " a trace holds";
    return std::nullopt;
  }
  return d;
}

std::string formatTraceDefinition(const TraceDefinition &d) {
  std::string out = "signal ";
  for (size_t i = 0; i < d.signals.size(); ++i) out += (i ? ", " : "") + d.signals[i];
  out += "\ntrigger ";
  switch (d.trigger) {
  case TriggerKind::Manual:
    out += "manual";
    break;
  case TriggerKind::Immediate:
    out += "immediate";
    break;
  case TriggerKind::Rising:
    out += "rising " + d.triggerAddress;
    break;
  case TriggerKind::Falling:
    out += "falling " + d.triggerAddress;
    break;
  case TriggerKind::Compare:
    out += d.triggerAddress + " " + opText(d.op) + " " + std::to_string(d.value);
    break;
  }
  out += "\npre " + std::to_string(d.pre) + "\npost " + std::to_string(d.post) + "\nmode " +
         (d.repeat ? "repeat" : "single") + "\n";
  return out;
}

std::unique_ptr<SignalTrace> SignalTrace::make(const TraceDefinition &def,
                                               const AddressParser &parse, uint64_t periodNs,
                                               std::string &error) {
  if (def.signals.empty() || def.signals.size() > kTraceMaxSignals) {
    error = "a trace has 1.." + std::to_string(kTraceMaxSignals) + " signals, got " +
            std::to_string(def.signals.size());
    return nullptr;
  }
  if (uint64_t{def.pre} + 1 + def.post > kTraceMaxTicks) {
    error = "pre + 1 + post is more than the " + std::to_string(kTraceMaxTicks) +
            " ticks a trace holds";
    return nullptr;
  }
  std::unique_ptr<SignalTrace> t(new SignalTrace());
  t->def_ = def;
  t->periodNs_ = periodNs;
  // Where an address's value lives in lj_state (formats/Address.cpp reads the same places).
  auto locate = [&](const formats::CliAddress &a, Source &src) {
    const TargetProfile &tp = a.profile ? *a.profile : *profileNamed("hnc8");
    src.bit = a.bit;
    if (a.area == Area::Timer || a.area == Area::Counter) {
      const size_t slot = static_cast<size_t>(tp.tcSlot(a.area, a.index));
      const bool timer = a.area == Area::Timer;
      const size_t base = timer ? offsetof(lj_state, T) + slot * sizeof(lj_timer)
                                : offsetof(lj_state, C) + slot * sizeof(lj_counter);
      if (a.isBit()) {
        src.stateOffset = static_cast<uint32_t>(
            base + (timer ? offsetof(lj_timer, out) : offsetof(lj_counter, out)));
        src.bytes = 1;
        src.bit = 0;
      } else { // elapsed_ms (capped at the preset) and the count: their low 32 bits
        src.stateOffset = static_cast<uint32_t>(
            base + (timer ? offsetof(lj_timer, elapsed_ms) : offsetof(lj_counter, value)));
        src.bytes = 4;
        src.isSigned = true;
      }
      return true;
    }
    if (a.area == Area::None) { // a system-parameter byte
      src.stateOffset = static_cast<uint32_t>(a.index);
      src.bytes = 1;
      src.isSigned = false;
      return true;
    }
    const AreaInfo &info = tp.area(a.area);
    if (info.bytes == 0) return false;
    src.stateOffset = tp.elementOffset(a.area, a.index);
    src.bytes = static_cast<uint8_t>(a.width ? a.width : info.bytes);
    src.isSigned = info.isSigned;
    return true;
  };
  uint32_t row = 8;
  for (const std::string &text : def.signals) {
    std::optional<formats::CliAddress> a = parse(text, error);
    if (!a) return nullptr;
    Source src{};
    if (!locate(*a, src)) {
      error = "'" + text + "' cannot be traced (no memory of its own)";
      return nullptr;
    }
    src.rowOffset = static_cast<uint16_t>(row);
    row += src.bytes;
    t->sources_.push_back(src);
    t->info_.push_back({a->text.empty() ? text : a->text, formats::signalBits(*a)});
  }
  t->rowBytes_ = row;
  if (def.trigger == TriggerKind::Rising || def.trigger == TriggerKind::Falling ||
      def.trigger == TriggerKind::Compare) {
    std::optional<formats::CliAddress> a = parse(def.triggerAddress, error);
    if (!a) {
      error = "trigger: " + error;
      return nullptr;
    }
    if (!locate(*a, t->trig_)) {
      error = "trigger: '" + def.triggerAddress + "' cannot be traced";
      return nullptr;
    }
  }
  t->ringCap_ = def.pre + 1;
  t->post_ = def.post;
  for (Slot &s : t->slots_) s.rows.assign(size_t{t->ringCap_ + t->post_} * t->rowBytes_, 0);
  return t;
}

int64_t SignalTrace::decode(const unsigned char *p, const Source &src) const {
  uint32_t raw = 0;
  std::memcpy(&raw, p, src.bytes); // little-endian host, like the ABI
  if (src.bit >= 0) return (raw >> src.bit) & 1u;
  if (!src.isSigned) return raw;
  if (src.bytes == 1) return static_cast<int8_t>(raw);
  if (src.bytes == 2) return static_cast<int16_t>(raw);
  return static_cast<int32_t>(raw);
}

int64_t SignalTrace::readNow(const lj_state &s, const Source &src) const {
  return decode(reinterpret_cast<const unsigned char *>(&s) + src.stateOffset, src);
}

void SignalTrace::sample(const lj_state &s, uint64_t tick) {
  if (phase_ == Done) return;
  Slot &slot = slots_[back_];
  uint32_t index;
  if (phase_ == Waiting) {
    index = (slot.ringHead + slot.ringLen) % ringCap_;
    if (slot.ringLen < ringCap_)
      ++slot.ringLen;
    else
      slot.ringHead = (slot.ringHead + 1) % ringCap_;
  } else {
    index = ringCap_ + slot.post++;
  }
  unsigned char *row = slot.rows.data() + size_t{index} * rowBytes_;
  std::memcpy(row, &tick, 8);
  const auto *base = reinterpret_cast<const unsigned char *>(&s);
  for (const Source &src : sources_) {
    const unsigned char *from = base + src.stateOffset;
    switch (src.bytes) {
    case 1:
      row[src.rowOffset] = *from;
      break;
    case 2:
      std::memcpy(row + src.rowOffset, from, 2);
      break;
    default:
      std::memcpy(row + src.rowOffset, from, 4);
      break;
    }
  }
  samples_.store(++sampled_, std::memory_order_relaxed); // a plain store: one writer
  if (phase_ == Waiting) {
    bool fire = manual_.load(std::memory_order_relaxed) &&
                manual_.exchange(false, std::memory_order_acq_rel);
    if (def_.trigger != TriggerKind::Manual && def_.trigger != TriggerKind::Immediate) {
      const int64_t v = readNow(s, trig_);
      if (havePrev_) {
        switch (def_.trigger) {
        case TriggerKind::Rising:
          fire |= prev_ == 0 && v != 0;
          break;
        case TriggerKind::Falling:
          fire |= prev_ != 0 && v == 0;
          break;
        case TriggerKind::Compare:
          fire |= compare(v, def_.op, def_.value) && !compare(prev_, def_.op, def_.value);
          break;
        default:
          break;
        }
      } else if (def_.trigger == TriggerKind::Compare) {
        fire |= compare(v, def_.op, def_.value); // already true when armed: fires at once
      }
      prev_ = v;
      havePrev_ = true;
    }
    if (def_.trigger == TriggerKind::Immediate) fire = true;
    if (fire) {
      slot.triggerTick = tick;
      phase_ = Recording;
      state_.store(Recording, std::memory_order_relaxed);
    }
  } else if (def_.trigger != TriggerKind::Manual && def_.trigger != TriggerKind::Immediate) {
    prev_ = readNow(s, trig_); // edges after this capture compare with the last tick seen
  }
  if (phase_ == Recording && slot.post == post_) publish();
}

void SignalTrace::publish() {
  Slot &done = slots_[back_];
  done.sequence = ++sequence_;
  const uint32_t old = middle_.exchange(back_ | kFresh, std::memory_order_acq_rel);
  if (old & kFresh) dropped_.fetch_add(1, std::memory_order_relaxed);
  back_ = old & 3u;
  Slot &next = slots_[back_];
  next.ringLen = next.ringHead = next.post = 0;
  captures_.fetch_add(1, std::memory_order_release);
  if (def_.repeat) { // `immediate` and repeat: back-to-back captures, every tick recorded
    phase_ = Waiting;
    state_.store(Waiting, std::memory_order_relaxed);
  } else {
    phase_ = Done;
    state_.store(Done, std::memory_order_relaxed);
  }
}

bool SignalTrace::take(TraceCapture &out) {
  std::lock_guard<std::mutex> g(readMu_);
  if (!(middle_.load(std::memory_order_acquire) & kFresh)) return false;
  front_ = middle_.exchange(front_, std::memory_order_acq_rel) & 3u;
  const Slot &s = slots_[front_];
  out.signals = info_;
  out.periodNs = periodNs_;
  out.triggerTick = s.triggerTick;
  out.preTicks = s.ringLen - 1;
  out.postTicks = s.post;
  out.sequence = s.sequence;
  const size_t rows = size_t{s.ringLen} + s.post;
  out.ticks.resize(rows);
  out.values.resize(rows * sources_.size());
  for (size_t r = 0; r < rows; ++r) {
    const uint32_t index = r < s.ringLen ? (s.ringHead + static_cast<uint32_t>(r)) % ringCap_
                                         : ringCap_ + static_cast<uint32_t>(r - s.ringLen);
    const unsigned char *row = s.rows.data() + size_t{index} * rowBytes_;
    std::memcpy(&out.ticks[r], row, 8);
    for (size_t k = 0; k < sources_.size(); ++k)
      out.values[r * sources_.size() + k] = decode(row + sources_[k].rowOffset, sources_[k]);
  }
  return true;
}

TraceStatus SignalTrace::status() const {
  TraceStatus st;
  switch (state_.load(std::memory_order_relaxed)) {
  case Waiting:
    st.state = "waiting";
    break;
  case Recording:
    st.state = "recording";
    break;
  default:
    st.state = "done";
    break;
  }
  st.samples = samples_.load(std::memory_order_relaxed);
  st.captures = captures_.load(std::memory_order_acquire);
  st.dropped = dropped_.load(std::memory_order_relaxed);
  return st;
}

std::string TraceCapture::vcd(bool splitBits) const {
  std::string comment = "trigger at tick " + std::to_string(triggerTick) + ", " +
                        std::to_string(preTicks) + " ticks before, " + std::to_string(postTicks) +
                        " after; capture " + std::to_string(sequence);
  formats::VcdWriter w(signals, periodNs, splitBits, comment);
  std::string out = w.header();
  for (size_t r = 0; r < ticks.size(); ++r)
    w.row(ticks[r], values.data() + r * signals.size(), out);
  if (!ticks.empty()) w.finish(ticks.back(), out);
  return out;
}

std::string TraceCapture::csv() const {
  std::string out = formats::csvHeader(signals, true);
  for (size_t r = 0; r < ticks.size(); ++r)
    formats::csvRow(ticks[r], periodNs, values.data() + r * signals.size(), signals.size(),
                    static_cast<int64_t>(triggerTick), out);
  return out;
}

TraceControl::~TraceControl() {
  std::string error;
  if (armed_) exec_.setSignalTrace(nullptr, std::chrono::seconds(5), error);
}

bool TraceControl::define(const std::string &text, const std::string &file,
                          const AddressParser &parse, uint64_t periodNs, std::string &error) {
  std::optional<TraceDefinition> d = parseTraceDefinition(text, file, error);
  if (!d) return false;
  // Resolved now, so a bad address is refused before anything changes.
  if (!SignalTrace::make(*d, parse, periodNs, error)) return false;
  if (!disarm(error)) return false;
  collect();
  trace_.reset();
  def_ = std::move(d);
  parse_ = parse;
  periodNs_ = periodNs;
  return true;
}

bool TraceControl::arm(std::string &error) {
  if (!def_) {
    error = "no trace defined (monitor trace define FILE)";
    return false;
  }
  if (!disarm(error)) return false;
  collect();
  std::unique_ptr<SignalTrace> fresh = SignalTrace::make(*def_, parse_, periodNs_, error);
  if (!fresh) return false;
  if (!exec_.setSignalTrace(fresh.get(), std::chrono::seconds(5), error)) {
    std::string again;
    exec_.setSignalTrace(nullptr, std::chrono::seconds(5), again);
    return false;
  }
  trace_ = std::move(fresh);
  armed_ = true;
  return true;
}

bool TraceControl::disarm(std::string &error) {
  if (!armed_) return true;
  if (!exec_.setSignalTrace(nullptr, std::chrono::seconds(5), error)) return false;
  armed_ = false;
  return true;
}

void TraceControl::collect() {
  TraceCapture c;
  if (trace_ && trace_->take(c)) {
    last_ = std::move(c);
    ++lastId_;
  }
}

namespace {

/// One column (captureJson): run-length coded when that is shorter than the plain values.
nlohmann::json column(const std::vector<int64_t> &v) {
  size_t runs = 0;
  for (size_t i = 0; i < v.size(); ++i)
    if (i == 0 || v[i] != v[i - 1]) ++runs;
  if (2 * runs >= v.size()) return v;
  nlohmann::json rle = nlohmann::json::array();
  for (size_t i = 0; i < v.size();) {
    size_t j = i;
    while (j < v.size() && v[j] == v[i]) ++j;
    rle.push_back(v[i]);
    rle.push_back(j - i);
    i = j;
  }
  return {{"rle", std::move(rle)}};
}

} // namespace

nlohmann::json captureJson(const TraceCapture &c, uint64_t id) {
  using nlohmann::json;
  const size_t rows = c.ticks.size(), n = c.signals.size();
  json signals = json::array();
  for (const formats::SignalInfo &s : c.signals)
    signals.push_back({{"name", s.name}, {"bits", s.bits}});
  std::vector<int64_t> col(rows > 0 ? rows - 1 : 0);
  for (size_t r = 1; r < rows; ++r) col[r - 1] = static_cast<int64_t>(c.ticks[r] - c.ticks[r - 1]);
  json ticks = {{"from", rows ? c.ticks[0] : 0}, {"steps", column(col)}};
  json columns = json::array();
  col.resize(rows);
  for (size_t k = 0; k < n; ++k) {
    for (size_t r = 0; r < rows; ++r) col[r] = c.values[r * n + k];
    columns.push_back(column(col));
  }
  return {{"id", id},
          {"capture", c.sequence},
          {"period_ns", c.periodNs},
          {"trigger_tick", c.triggerTick},
          {"trigger_row", c.preTicks},
          {"rows", rows},
          {"signals", std::move(signals)},
          {"ticks", std::move(ticks)},
          {"columns", std::move(columns)}};
}

bool TraceControl::defineAndArm(const std::string &text, const std::string &file,
                                const AddressParser &parse, uint64_t periodNs, std::string &error) {
  std::lock_guard<std::mutex> g(mu_);
  return define(text, file, parse, periodNs, error) && arm(error);
}

nlohmann::json TraceControl::handle(const nlohmann::json &req, const AddressParser &parse,
                                    uint64_t periodNs) {
  using nlohmann::json;
  auto fail = [](const std::string &why) {
    return json{{"ok", false}, {"error", "trace: " + why}};
  };
  auto it = req.find("action");
  if (it == req.end() || !it->is_string())
    return fail("needs \"action\": define, arm, trigger, stop, status or save");
  const std::string action = it->get<std::string>();
  std::lock_guard<std::mutex> g(mu_);
  std::string error;
  if (action == "define") {
    if (!req.contains("text") || !req["text"].is_string())
      return fail("define needs \"text\", the definition");
    const std::string file = req.value("file", std::string("definition"));
    if (!define(req["text"].get<std::string>(), file, parse, periodNs, error)) return fail(error);
  } else if (action == "arm") {
    if (!arm(error)) return fail(error);
  } else if (action == "trigger") {
    if (!armed_) return fail("not armed");
    trace_->triggerNow();
  } else if (action == "stop") {
    if (!disarm(error)) return fail(error);
    collect();
  } else if (action == "save") {
    collect();
    if (!last_)
      return fail(std::string("no capture yet (") + (trace_ ? trace_->status().state : "idle") +
                  ")");
    const std::string format = req.value("format", std::string("vcd"));
    if (format != "vcd" && format != "csv")
      return fail("save: format must be vcd or csv, got '" + format + "'");
    const bool bits = req.value("bits", false);
    return {{"ok", true},
            {"data", format == "vcd" ? last_->vcd(bits) : last_->csv()},
            {"trigger_tick", last_->triggerTick},
            {"ticks", last_->ticks.size()},
            {"capture", last_->sequence}};
  } else if (action == "capture") {
    collect();
  } else if (action != "status") {
    return fail("unknown action '" + action +
                "' (define, arm, trigger, stop, status, save, capture)");
  }
  json st = {{"ok", true}, {"armed", armed_}};
  if (def_) st["definition"] = formatTraceDefinition(*def_);
  TraceStatus ts = trace_ ? trace_->status() : TraceStatus{};
  st["state"] = armed_ ? ts.state : (def_ ? "stopped" : "idle");
  st["samples"] = ts.samples;
  st["captures"] = ts.captures;
  st["dropped"] = ts.dropped;
  if (last_) {
    st["last_capture"] = {
        {"capture", last_->sequence}, {"trigger_tick", last_->triggerTick}, {"id", lastId_}};
    if (action == "capture") {
      const auto have = req.find("have");
      if (have == req.end() || !have->is_number_unsigned() || have->get<uint64_t>() != lastId_)
        st["capture"] = captureJson(*last_, lastId_);
    }
  }
  st["period_ns"] = periodNs;
  return st;
}

} // namespace lj::rt

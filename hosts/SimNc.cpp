// The simulated NC's channel model and tick protocol: M/T/S handshakes, reset handshake, mode
// switching, cycle start / feed hold, e-stop, overrides, part count, alarm/event/prompt diffs
// (hnc8-cnc-interface.md 1.3-1.6 and 3.2; docs/simulated-nc.md).
#include "hosts/SimNcModel.h"

#include <algorithm>

namespace lj::hosts {

SimNcConfig::SimNcConfig() {
  for (auto &row : channelAxes) row.fill(-1);
  for (auto &row : channelSpindles) row.fill(-1);
  channelAxes[0][0] = 0;
  channelAxes[0][1] = 1;
  channelAxes[0][2] = 2;
  channelSpindles[0][0] = 5;
}

int64_t readWords(const int16_t *area, int word, int count) {
  uint64_t v = 0;
  for (int i = count - 1; i >= 0; --i) v = (v << 16) | static_cast<uint16_t>(area[word + i]);
  if (count < 4) { // sign-extend from the top word
    int shift = 64 - 16 * count;
    return static_cast<int64_t>(v << shift) >> shift;
  }
  return static_cast<int64_t>(v);
}

void writeWords(int16_t *area, int word, int count, int64_t v) {
  uint64_t u = static_cast<uint64_t>(v);
  for (int i = 0; i < count; ++i, u >>= 16) area[word + i] = static_cast<int16_t>(u & 0xFFFFu);
}

namespace {

std::string chName(int c) { return "ch" + std::to_string(c); }

// Mode code of the one-hot panel word GC[60].0-6 (hnc8-cnc-interface.md 6.1 MDST: 1->1 auto,
// 2->7 single, 4->2 manual, 8->3 increment, 16->5 home, 32->4 MPG, 64->6 PMC); -1 = no request.
int oneHotMode(int bits) {
  static const int codes[7] = {1, 7, 2, 3, 5, 4, 6};
  if (bits == 0 || (bits & (bits - 1)) != 0) return -1;
  for (int b = 0; b < 7; ++b)
    if (bits == (1 << b)) return codes[b];
  return -1;
}

} // namespace

SimNc::SimNc(const SimNcConfig &cfg) : cfg_(cfg), m_(std::make_unique<Model>()) {
  cfg_.channels = std::clamp(cfg_.channels, 1, 4);
  cfg_.axes = std::clamp(cfg_.axes, 1, 32);
  cfg_.tools = std::clamp(cfg_.tools, 0, 10000);
  cfg_.pockets = std::clamp(cfg_.pockets, 0, 63);
  events_.setLimit(cfg_.logLimit);
  calls_.setLimit(cfg_.logLimit);
  bindHost();
}

SimNc::~SimNc() = default;

void SimNc::leaveWord(bool isF, int word) { (isF ? m_->leftF : m_->leftG).insert(word); }

void SimNc::powerUp(lj_state &s) {
  std::set<int> leftF = std::move(m_->leftF), leftG = std::move(m_->leftG);
  *m_ = Model{};
  m_->leftF = std::move(leftF);
  m_->leftG = std::move(leftG);
  for (NcChannel &c : m_->ch) c.mslot.fill(-1);
  events_.clear();
  calls_.clear();
  vars_.clear();
  tick_ = -1;
  state_ = &s;
  s.host = &host_;
  // G is the PLC's: at power-up it stays zero (DIALECT.md 1). The response words get -1 ("the
  // PLC handles no M/T code", hnc8-cnc-interface.md 1.4) when the NC posts a code, so a stale 0
  // never acknowledges an M0/T0, and again once a code is done.
  publish(s);
}

void SimNc::putF(lj_state &s, int word, int16_t v) const {
  if (!m_->leftF.count(word)) s.img.F[word] = v;
}

void SimNc::putG(lj_state &s, int word, int16_t v) const {
  if (!m_->leftG.count(word)) s.img.G[word] = v;
}

void SimNc::log(const std::string &what) {
  NcEvent &e = events_.next(); // a ring slot keeps its capacity (SimNcConfig::logLimit)
  e.tick = tick_ < 0 ? 0 : tick_;
  e.what = what;
}

void SimNc::beforeTick(lj_state &s, uint64_t tick) {
  tick_ = static_cast<int64_t>(tick);
  state_ = &s;
  s.host = &host_;
  publish(s);
}

void SimNc::publish(lj_state &s) {
  for (int c = 0; c < cfg_.channels; ++c) {
    NcChannel &ch = m_->ch[c];
    int16_t w0 = static_cast<int16_t>(ch.mode & 0xF);
    setBit(w0, 4, ch.held);
    setBit(w0, 5, ch.running);
    setBit(w0, 12, ch.resetFlag);
    setBit(w0, 15, channelZSearch(*m_, cfg_, c));
    putF(s, ncw::chan(c, 0), w0);
    int16_t w1 = 0;
    setBit(w1, 1, ch.running || ch.held);
    setBit(w1, 2, ch.finished);
    putF(s, ncw::chan(c, 1), w1);
    int16_t w2 = 0;
    for (int sp = 0; sp < 4; ++sp) {
      setBit(w2, 12 + sp, ch.sflag[sp]);
      int16_t words[2];
      writeWords(words, 0, 2, ch.sval[sp]);
      putF(s, ncw::chan(c, 10 + 2 * sp), words[0]);
      putF(s, ncw::chan(c, 11 + 2 * sp), words[1]);
    }
    putF(s, ncw::chan(c, 2), w2);
    for (int i = 0; i < 9; ++i) putF(s, ncw::chan(c, 21 + i), cfg_.channelAxes[c][i]);
    for (int i = 0; i < 4; ++i) putF(s, ncw::chan(c, 30 + i), cfg_.channelSpindles[c][i]);
    for (int k = 0; k < ncw::kMSlots; ++k) {
      putF(s, ncw::chan(c, 48 + k), ch.mslot[k]);
      if (ch.mgReset[k]) putG(s, ncw::chan(c, 48 + k), -1);
      ch.mgReset[k] = false;
    }
    putF(s, ncw::chan(c, 56), ch.tcode);
    if (ch.tgReset) putG(s, ncw::chan(c, 56), -1);
    ch.tgReset = false;
  }
  axesPublish(*m_, cfg_, s);
  for (int i = 0; i < ncw::kSensors; ++i)
    if (m_->tempSet[i]) putG(s, ncw::kTempBase + i, static_cast<int16_t>(m_->temp[i]));
}

void SimNc::resetChannel(int c, const char *why) {
  NcChannel &ch = m_->ch[c];
  ch.running = ch.held = ch.finished = false;
  for (int k = 0; k < ncw::kMSlots; ++k) {
    if (ch.mslot[k] != -1) ch.mgReset[k] = true;
    ch.mslot[k] = -1;
  }
  ch.mqueue.clear();
  if (ch.tcode != -1) ch.tgReset = true;
  ch.tcode = -1;
  ch.tqueue.clear();
  ch.sflag.fill(false);
  ch.resetFlag = true;
  log("reset " + chName(c) + " requested (" + why + ")");
}

void SimNc::channelAfterTick(const lj_state &s, int c) {
  NcChannel &ch = m_->ch[c];
  const int16_t g0 = s.img.G[ncw::chan(c, 0)];
  // Reset handshake: the ack (level) clears the flag before a new request is looked at.
  if (ch.resetFlag && bitOf(g0, 9)) {
    ch.resetFlag = false;
    log("reset " + chName(c) + " acknowledged");
  }
  bool resetReq = bitOf(g0, 13);
  if (resetReq && !ch.prevReset) resetChannel(c, "GC[0].13");
  ch.prevReset = resetReq;
  bool estop = bitOf(g0, 11);
  if (estop != ch.estop) log("estop " + chName(c) + (estop ? " on" : " off"));
  ch.estop = estop;
  if (estop) ch.running = ch.held = false;
  // Mode request: a one-hot GC[60].0-6 wins over the code GC[0].0-3 (levels, docs).
  int want = oneHotMode(s.img.G[ncw::chan(c, 60)] & 0x7F);
  if (want < 0 && (g0 & 0xF) <= 8) want = g0 & 0xF;
  if (want >= 0 && want != ch.mode && !channelZSearch(*m_, cfg_, c)) {
    ch.mode = want;
    log("mode " + chName(c) + " " + std::to_string(want));
    if (ch.running && want != 1 && want != 7) { // leaving auto/single holds the program
      ch.running = false;
      ch.held = true;
    }
  }
  // Cycle start on the rising edge of GC[0].5, only in auto (1) or single block (7).
  bool cycle = bitOf(g0, 5);
  if (cycle && !ch.prevCycle && (ch.mode == 1 || ch.mode == 7) && !estop && !ch.running) {
    ch.running = true;
    ch.held = ch.finished = false;
    log("cycle " + chName(c) + " start");
  }
  ch.prevCycle = cycle;
  if (bitOf(g0, 4) && ch.running) { // feed hold (no thread cutting in this model)
    ch.running = false;
    ch.held = true;
    log("feedhold " + chName(c));
  }
  // M codes: a slot is done when GC[48+k] equals it; it then shows -1 for at least one tick.
  ch.mcool.fill(false);
  for (int k = 0; k < ncw::kMSlots; ++k) {
    if (ch.mslot[k] != -1 && s.img.G[ncw::chan(c, 48 + k)] == ch.mslot[k]) {
      log("mcode " + chName(c) + " m" + std::to_string(ch.mslot[k]) + " done");
      ch.mslot[k] = -1;
      ch.mcool[k] = ch.mgReset[k] = true;
    }
  }
  for (int k = 0; k < ncw::kMSlots && !ch.mqueue.empty(); ++k) {
    if (ch.mslot[k] != -1 || ch.mcool[k]) continue;
    ch.mslot[k] = ch.mqueue.front();
    ch.mgReset[k] = true;
    ch.mqueue.pop_front();
  }
  ch.tcool = false;
  if (ch.tcode != -1 && s.img.G[ncw::chan(c, 56)] == ch.tcode) {
    log("tcode " + chName(c) + " t" + std::to_string(ch.tcode) + " done");
    ch.tcode = -1;
    ch.tcool = ch.tgReset = true;
  } else if (ch.tcode == -1 && !ch.tqueue.empty()) {
    ch.tcode = ch.tqueue.front();
    ch.tgReset = true;
    ch.tqueue.pop_front();
  }
  const int16_t g2 = s.img.G[ncw::chan(c, 2)];
  for (int sp = 0; sp < 4; ++sp) {
    if (ch.sflag[sp] && bitOf(g2, sp)) {
      ch.sflag[sp] = false;
      log("scode " + chName(c) + " sp" + std::to_string(sp) + " done");
    }
    ch.spindleCmd[sp] = static_cast<int32_t>(readWords(s.img.G, ncw::chan(c, 10 + 2 * sp), 2));
  }
  ch.feedOvr = s.img.G[ncw::chan(c, 4)];
  ch.rapidOvr = s.img.G[ncw::chan(c, 5)];
  for (int sp = 0; sp < 4; ++sp) ch.spindleOvr[sp] = s.img.G[ncw::chan(c, 6 + sp)];
  int32_t parts = s.img.G[ncw::chan(c, 19)];
  if (parts != ch.partCount) log("partcount " + chName(c) + " " + std::to_string(parts));
  ch.partCount = parts;
}

void SimNc::afterTick(lj_state &s, uint64_t tick) {
  tick_ = static_cast<int64_t>(tick);
  for (int c = 0; c < cfg_.channels; ++c) channelAfterTick(s, c);
  axesAfterTick(*m_, cfg_, s, tick_, events_);
  m_->activeChannel = s.img.G[2970];
  // Alarm, event and prompt bit areas: every change becomes one log line (hnc8-cnc-interface.md
  // 1.5, 6.3 ALARM/EVENT: alarm n = bit n-1, event n = bit n, prompt n = bit n-501).
  static const struct {
    int base;
    const char *name;
    int first;
  } areas[3] = {{ncw::kAlarmBase, "alarm", 1},
                {ncw::kEventBase, "event", 0},
                {ncw::kPromptBase, "prompt", 501}};
  for (int a = 0; a < 3; ++a) {
    for (int w = 0; w < ncw::kAreaWords; ++w) {
      const unsigned now = static_cast<uint16_t>(s.img.G[areas[a].base + w]);
      const unsigned changed = now ^ m_->areaPrev[a * ncw::kAreaWords + w];
      m_->areaPrev[a * ncw::kAreaWords + w] = static_cast<uint16_t>(now);
      for (int b = 0; b < 16; ++b) {
        if (!((changed >> b) & 1u)) continue;
        log(std::string(areas[a].name) + " " + std::to_string(areas[a].first + 16 * w + b) +
            (((now >> b) & 1u) ? " on" : " off"));
      }
    }
  }
}

void SimNc::apply(const formats::NcCommand &c) {
  int64_t saved = tick_;
  tick_ = tick_ + 1; // a command belongs to the tick about to run
  auto chanOk = [&] {
    if (c.ch >= 0 && c.ch < cfg_.channels) return true;
    log(std::string("ignored nc.") + formats::ncCommandName(c.kind) + ": no channel " +
        std::to_string(c.ch));
    return false;
  };
  switch (c.kind) {
  case formats::NcCommandKind::MCode:
    if (chanOk()) {
      NcChannel &ch = m_->ch[c.ch];
      auto code = static_cast<int16_t>(c.code);
      log("mcode " + chName(c.ch) + " m" + std::to_string(code) + " requested");
      int free = -1; // first slot that was free (and not just freed) during the last tick
      for (int k = 0; k < ncw::kMSlots && free < 0; ++k)
        if (ch.mslot[k] == -1 && !ch.mcool[k]) free = k;
      if (free >= 0 && ch.mqueue.empty()) {
        ch.mslot[free] = code;
        ch.mgReset[free] = true;
      } else
        ch.mqueue.push_back(code);
    }
    break;
  case formats::NcCommandKind::TCode:
    if (chanOk()) {
      NcChannel &ch = m_->ch[c.ch];
      log("tcode " + chName(c.ch) + " t" + std::to_string(c.code) + " requested");
      if (ch.tcode == -1 && !ch.tcool && ch.tqueue.empty()) {
        ch.tcode = static_cast<int16_t>(c.code);
        ch.tgReset = true;
      } else
        ch.tqueue.push_back(static_cast<int16_t>(c.code));
    }
    break;
  case formats::NcCommandKind::SCode:
    if (c.code < 0 || c.code > 3)
      log("ignored nc.scode: no spindle " + std::to_string(c.code));
    else if (chanOk()) {
      m_->ch[c.ch].sflag[c.code] = true;
      m_->ch[c.ch].sval[c.code] = static_cast<int32_t>(c.ivalue);
      log("scode " + chName(c.ch) + " sp" + std::to_string(c.code) + " s" +
          std::to_string(c.ivalue) + " requested");
    }
    break;
  case formats::NcCommandKind::Reset:
    if (chanOk()) resetChannel(c.ch, "panel");
    break;
  case formats::NcCommandKind::End:
    if (chanOk()) {
      NcChannel &ch = m_->ch[c.ch];
      ch.running = ch.held = false;
      ch.finished = true;
      log("program " + chName(c.ch) + " end");
    }
    break;
  case formats::NcCommandKind::Var: {
    NcVar v;
    v.isFloat = varIsFloat(c.index);
    v.i = c.ivalue;
    v.f = c.isInteger ? static_cast<double>(c.ivalue) : c.fvalue;
    if (!v.isFloat && !c.isInteger)
      log("ignored nc.var: type " + std::to_string(c.index) + " holds integers");
    else if (!setVar(c.index, c.offset, v))
      log("ignored nc.var: no variable type " + std::to_string(c.index) + " offset " +
          std::to_string(c.offset));
    break;
  }
  case formats::NcCommandKind::Temp:
    if (c.index < 0 || c.index >= ncw::kSensors) {
      log("ignored nc.temp: no sensor " + std::to_string(c.index));
      break;
    }
    m_->tempSet[c.index] = true;
    m_->temp[c.index] = static_cast<int32_t>(c.ivalue);
    break;
  case formats::NcCommandKind::Tool:
    if (c.index >= 1 && c.index <= cfg_.pockets)
      m_->pocket[c.index] = static_cast<int32_t>(c.ivalue);
    else
      log("ignored nc.tool: no pocket " + std::to_string(c.index));
    break;
  case formats::NcCommandKind::Mpg:
    if (c.index >= 0 && c.index < ncw::kMpgs)
      m_->mpgPending[c.index] += c.ivalue;
    else
      log("ignored nc.mpg: no handwheel " + std::to_string(c.index));
    break;
  case formats::NcCommandKind::ZPulse:
    if (c.index >= 0 && c.index < cfg_.axes)
      m_->ax[c.index].zpulse = true;
    else
      log("ignored nc.zpulse: no axis " + std::to_string(c.index));
    break;
  }
  tick_ = saved;
}

int32_t SimNc::pocketTool(int p) const { return p >= 1 && p <= cfg_.pockets ? m_->pocket[p] : 0; }
int32_t SimNc::toolInUse(int ch) const { return ch >= 0 && ch < 4 ? m_->ch[ch].toolInUse : 0; }
bool SimNc::toolVector(int ch) const { return ch >= 0 && ch < 4 && m_->ch[ch].toolVector; }
int32_t SimNc::partCount(int ch) const { return ch >= 0 && ch < 4 ? m_->ch[ch].partCount : 0; }
int64_t SimNc::axisPosition(int a) const { return a >= 0 && a < 32 ? m_->ax[a].pos : 0; }
int32_t SimNc::spindleSpeed(int a) const { return a >= 0 && a < 32 ? m_->ax[a].spindleSpeed : 0; }
int32_t SimNc::temperature(int sensor) const {
  return sensor >= 0 && sensor < ncw::kSensors ? m_->temp[sensor] : 0;
}

} // namespace lj::hosts

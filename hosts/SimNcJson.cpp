// The simulated NC as JSON (the "nc" object of `ladderjit run --dump`), its digest and equality
// (two NCs fed identically by equal engines end equal: the differential fuzzer's check).
#include "hosts/SimNcModel.h"

#include <nlohmann/json.hpp>

namespace lj::hosts {

namespace {

using Json = nlohmann::ordered_json;

Json channelJson(const NcChannel &c) {
  Json j;
  j["mode"] = c.mode;
  j["running"] = c.running;
  j["feed_hold"] = c.held;
  j["finished"] = c.finished;
  j["reset_flag"] = c.resetFlag;
  j["estop"] = c.estop;
  j["m_slots"] = c.mslot;
  j["m_queue"] = Json(std::vector<int16_t>(c.mqueue.begin(), c.mqueue.end()));
  j["t_code"] = c.tcode;
  j["t_queue"] = Json(std::vector<int16_t>(c.tqueue.begin(), c.tqueue.end()));
  j["s_flags"] = c.sflag;
  j["s_values"] = c.sval;
  j["feed_override"] = c.feedOvr;
  j["rapid_override"] = c.rapidOvr;
  j["spindle_override"] = c.spindleOvr;
  j["spindle_command"] = c.spindleCmd;
  j["part_count"] = c.partCount;
  j["tool_in_use"] = c.toolInUse;
  j["tool_vector"] = c.toolVector;
  return j;
}

Json axisJson(const NcAxis &x) {
  static const char *phases[] = {"idle", "dog", "z_search"};
  Json j;
  j["position"] = x.pos;
  j["moving"] = x.moving;
  j["ready"] = x.ready;
  j["servo_ok"] = x.servoOk;
  j["locked"] = x.locked;
  j["home_phase"] = phases[static_cast<int>(x.home)];
  j["homed"] = x.homed;
  j["home_failed"] = x.homeFailed;
  j["pmc_active"] = x.pmcActive;
  j["pmc_target"] = x.pmcTarget;
  j["control_mode"] = x.ctrlMode >> 9;
  j["spindle_speed"] = x.spindleSpeed;
  j["spindle_target"] = x.spindleTarget;
  j["oriented"] = x.oriented;
  j["slave_home"] = x.slaveHome;
  return j;
}

} // namespace

nlohmann::ordered_json SimNc::toJson() const {
  Json j;
  Json chans = Json::array();
  for (int c = 0; c < cfg_.channels; ++c) chans.push_back(channelJson(m_->ch[c]));
  j["channels"] = std::move(chans);
  // Only axes that left their power-up state, keyed by axis number.
  Json axes = Json::object();
  for (int a = 0; a < cfg_.axes; ++a)
    if (!(m_->ax[a] == NcAxis{})) axes[std::to_string(a)] = axisJson(m_->ax[a]);
  j["axes"] = std::move(axes);
  j["active_channel"] = m_->activeChannel;
  Json pockets = Json::object();
  for (int p = 1; p <= cfg_.pockets; ++p)
    if (m_->pocket[p] != 0) pockets[std::to_string(p)] = m_->pocket[p];
  j["pockets"] = std::move(pockets);
  Json temps = Json::object();
  for (int i = 0; i < ncw::kSensors; ++i)
    if (m_->tempSet[i]) temps[std::to_string(i)] = m_->temp[i];
  j["temperatures"] = std::move(temps);
  Json mpg = Json::object();
  for (int i = 0; i < ncw::kMpgs; ++i)
    if (m_->mpgPending[i] != 0) mpg[std::to_string(i)] = m_->mpgPending[i];
  j["mpg_pending"] = std::move(mpg);
  Json vars = Json::array();
  for (const auto &[key, v] : vars_) {
    Json e;
    e["type"] = key.first;
    e["offset"] = key.second;
    if (v.isFloat)
      e["value"] = v.f;
    else
      e["value"] = v.i;
    vars.push_back(std::move(e));
  }
  j["variables"] = std::move(vars);
  Json events = Json::array();
  events_.forEach([&](const NcEvent &e) {
    events.push_back({{"tick", e.tick}, {"what", e.what}});
  });
  j["events"] = std::move(events);
  Json calls = Json::array();
  calls_.forEach([&](const NcCall &c) {
    Json e;
    e["tick"] = c.tick;
    e["name"] = c.name;
    e["args"] = c.args;
    if (!c.out.empty()) e["out"] = c.out;
    e["result"] = c.result;
    calls.push_back(std::move(e));
  });
  j["calls"] = std::move(calls);
  // Only a limited log drops entries; the unlimited dump of `run` keeps its fields.
  if (events_.dropped() || calls_.dropped())
    j["log_dropped"] = {{"events", events_.dropped()}, {"calls", calls_.dropped()}};
  return j;
}

uint64_t SimNc::digest() const {
  // FNV-1a over the JSON form (everything observable) and the edge/timer memory it omits.
  std::string text = toJson().dump();
  for (int c = 0; c < cfg_.channels; ++c) {
    const NcChannel &ch = m_->ch[c];
    text += ch.prevCycle ? '1' : '0';
    text += ch.prevReset ? '1' : '0';
  }
  uint64_t h = 1469598103934665603ull;
  for (unsigned char ch : text) {
    h ^= ch;
    h *= 1099511628211ull;
  }
  return h;
}

bool SimNc::operator==(const SimNc &o) const {
  return *m_ == *o.m_ && vars_ == o.vars_ && events_ == o.events_ && calls_ == o.calls_;
}

} // namespace lj::hosts

// The simulated NC's axis and spindle model: enable/servo delays, lock, limits, jog and
// increment moves, homing state machine, PMC moves, control mode, spindle ramp and orientation
// (hnc8-cnc-interface.md 1.1/1.2 and 3.2; docs/simulated-nc.md "Axes").
#include "hosts/SimNcModel.h"

#include <algorithm>

namespace lj::hosts {

namespace {

// A response to a G bit first seen at tick `since` shows from tick since + delay (at least
// the next tick, since F is only written between ticks).
bool delayed(int64_t since, int64_t tick, uint32_t delay) {
  return since >= 0 && tick + 1 >= since + std::max<int64_t>(delay, 1);
}

// Channel c and spindle index of spindle axis a, or false.
bool spindleOf(const SimNcConfig &cfg, int a, int &c, int &sp) {
  for (c = 0; c < cfg.channels; ++c)
    for (sp = 0; sp < 4; ++sp)
      if (cfg.channelSpindles[c][sp] == a) return true;
  return false;
}

std::string axName(int a) { return "axis" + std::to_string(a); }

// Panel jog keys GC[62]/GC[63] of the channel axis a belongs to: +1, -1 or 0; `mode` is the
// channel mode and `mult` the increment code of GC[60].8-9.
int panelKeys(const SimNcConfig &cfg, const lj_state &s, int a, int &c, bool &plus, bool &minus) {
  c = -1;
  plus = minus = false;
  for (int ch = 0; ch < cfg.channels; ++ch) {
    for (int i = 0; i < 9; ++i) {
      if (cfg.channelAxes[ch][i] != a) continue;
      c = ch;
      plus = bitOf(s.img.G[ncw::chan(ch, 62)], i);
      minus = bitOf(s.img.G[ncw::chan(ch, 63)], i);
      return i;
    }
  }
  return -1;
}

} // namespace

int axisChannel(const SimNcConfig &cfg, int a) {
  for (int c = 0; c < cfg.channels; ++c) {
    for (int i = 0; i < 9; ++i)
      if (cfg.channelAxes[c][i] == a) return c;
    for (int sp = 0; sp < 4; ++sp)
      if (cfg.channelSpindles[c][sp] == a) return c;
  }
  return -1;
}

bool channelZSearch(const SimNc::Model &m, const SimNcConfig &cfg, int c) {
  for (int a = 0; a < cfg.axes; ++a)
    if (m.ax[a].home == HomePhase::ZSearch && axisChannel(cfg, a) == c) return true;
  return false;
}

void axesAfterTick(SimNc::Model &m, const SimNcConfig &cfg, const lj_state &s, int64_t t,
                   NcLog<NcEvent> &log) {
  auto note = [&](int a, const std::string &what) {
    NcEvent &e = log.next();
    e.tick = t;
    e.what = axName(a) + " " + what;
  };
  for (int a = 0; a < cfg.axes; ++a) {
    NcAxis &x = m.ax[a];
    const int16_t *g = &s.img.G[ncw::axis(a, 0)];
    // Enable / servo: FA[2].8 / FA[3].0 follow GA[0].7 / GA[3].0 after enableDelay ticks.
    x.enableSince = bitOf(g[0], 7) ? (x.enableSince < 0 ? t : x.enableSince) : -1;
    x.servoSince = bitOf(g[3], 0) ? (x.servoSince < 0 ? t : x.servoSince) : -1;
    x.ready = delayed(x.enableSince, t, cfg.enableDelay);
    x.servoOk = delayed(x.servoSince, t, cfg.enableDelay);
    x.posLimit = bitOf(g[0], 0);
    x.negLimit = bitOf(g[0], 1);
    x.locked = bitOf(g[0], 6);
    x.released = bitOf(g[0], 11);
    x.ctrlMode = static_cast<uint16_t>(g[2]) & 0x0E00u;
    int c = axisChannel(cfg, a);
    bool estop = c >= 0 && m.ch[c].estop;
    // Single-axis reset or e-stop aborts homing and PMC moves.
    if (bitOf(g[0], 15) || estop) {
      if (x.home != HomePhase::Idle) {
        x.home = HomePhase::Idle;
        x.homeFailed = true;
        note(a, "home failed");
      }
      x.pmcActive = false;
    }
    // Homing (rising edge of GA[0].4): phase 1 until the dog GA[0].5, phase 2 (Z search,
    // FA[0].2 and FC[0].15) for homeZDelay ticks or until `nc.zpulse`, then done at position 0.
    bool start = bitOf(g[0], 4);
    if (start && !x.prevHomeStart && x.home == HomePhase::Idle && !estop) {
      x.home = HomePhase::Dog;
      x.homeSince = t;
      x.homed = x.homeFailed = false;
      note(a, "home start");
    }
    x.prevHomeStart = start;
    int64_t step = 0;
    if (x.home == HomePhase::Dog) {
      if (bitOf(g[0], 5)) {
        x.home = HomePhase::ZSearch;
        x.homeSince = t;
        x.zpulse = false;
        note(a, "home dog");
      } else {
        step = -cfg.jogStep; // towards the dog
      }
    } else if (x.home == HomePhase::ZSearch) {
      if (x.zpulse || t - x.homeSince >= cfg.homeZDelay) {
        x.home = HomePhase::Idle;
        x.homed = true;
        x.pos = 0;
        note(a, "home done");
      }
    }
    if (x.home != HomePhase::ZSearch) x.zpulse = false;
    if (x.home == HomePhase::Idle) {
      // Jog flag GA[4] (+/-) at the speed GA[6/7]: 0/1 parameter speed, 2 rapid, >2 per tick.
      int64_t speed = readWords(s.img.G, ncw::axis(a, 6), 2);
      int64_t v = speed <= 1 ? cfg.jogStep : speed == 2 ? cfg.rapidStep : speed;
      if (g[4] > 0) step = v;
      if (g[4] < 0) step = -v;
      // Increment flag GA[5]: one step of GA[8] units (at least 1) per rising edge.
      bool inc = g[5] != 0;
      if (inc && !x.prevStep) step += (g[5] > 0 ? 1 : -1) * std::max<int64_t>(g[8], 1);
      x.prevStep = inc;
      // Panel keys of the channel: continuous in manual mode, one increment per press in
      // increment mode (GC[60].8-9: x1, x10, x100, x1000).
      int pc;
      bool plus, minus;
      if (panelKeys(cfg, s, a, pc, plus, minus) >= 0) {
        if (m.ch[pc].mode == 2) step += (plus ? cfg.jogStep : 0) - (minus ? cfg.jogStep : 0);
        if (m.ch[pc].mode == 3) {
          static const int kMul[4] = {1, 10, 100, 1000};
          int mul = kMul[(static_cast<uint16_t>(s.img.G[ncw::chan(pc, 60)]) >> 8) & 3u];
          step += ((plus && !x.prevIncPlus) ? mul : 0) - ((minus && !x.prevIncMinus) ? mul : 0);
        }
        x.prevIncPlus = plus;
        x.prevIncMinus = minus;
      }
      // PMC moves on the rising edge of GA[1].1 (relative, GA[52..55]) / GA[1].0 (absolute,
      // GA[48..51]); GA[62].0 stops them.
      bool abs = bitOf(g[1], 0), rel = bitOf(g[1], 1);
      if (rel && !x.prevPmcRel) {
        x.pmcTarget = x.pos + readWords(s.img.G, ncw::axis(a, 52), 4);
        x.pmcActive = true;
        note(a, "pmc move to " + std::to_string(x.pmcTarget));
      }
      if (abs && !x.prevPmcAbs) {
        x.pmcTarget = readWords(s.img.G, ncw::axis(a, 48), 4);
        x.pmcActive = true;
        note(a, "pmc move to " + std::to_string(x.pmcTarget));
      }
      x.prevPmcAbs = abs;
      x.prevPmcRel = rel;
      if (bitOf(g[62], 0)) x.pmcActive = false;
      if (x.pmcActive) {
        int64_t d = x.pmcTarget - x.pos;
        step += std::clamp<int64_t>(d, -cfg.pmcStep, cfg.pmcStep);
      }
    }
    // Lock, limit switches and direction inhibits stop motion.
    if (x.locked) step = 0;
    if (step > 0 && (x.posLimit || bitOf(g[0], 2))) step = 0;
    if (step < 0 && (x.negLimit || bitOf(g[0], 3))) step = 0;
    x.pos += step;
    x.lastStep = static_cast<int32_t>(step);
    x.moving = step != 0 || x.home != HomePhase::Idle;
    if (x.pmcActive && x.pos == x.pmcTarget) {
      x.pmcActive = false;
      note(a, "pmc move done");
    }
    // Spindle: commanded speed GC[10+2sp] (or the feed-spindle keys GA[1].6/7), ramped;
    // orientation GA[2].12 stops it and reports FA[3].8 after orientDelay ticks.
    x.orientSince = bitOf(g[2], 12) ? (x.orientSince < 0 ? t : x.orientSince) : -1;
    x.oriented = delayed(x.orientSince, t, cfg.orientDelay);
    int sc, sp;
    if (spindleOf(cfg, a, sc, sp)) {
      int32_t target = m.ch[sc].spindleCmd[sp];
      if (target == 0 && bitOf(g[1], 6)) target = cfg.spindleJog;
      if (target == 0 && bitOf(g[1], 7)) target = -cfg.spindleJog;
      if (x.orientSince >= 0) target = 0;
      x.spindleTarget = target;
      int64_t d = static_cast<int64_t>(target) - x.spindleSpeed;
      x.spindleSpeed +=
          static_cast<int32_t>(std::clamp<int64_t>(d, -cfg.spindleRamp, cfg.spindleRamp));
    }
  }
}

void axesPublish(SimNc::Model &m, const SimNcConfig &cfg, lj_state &s) {
  auto putF = [&](int w, int16_t v) {
    if (!m.leftF.count(w)) s.img.F[w] = v;
  };
  auto putG = [&](int w, int16_t v) {
    if (!m.leftG.count(w)) s.img.G[w] = v;
  };
  for (int a = 0; a < cfg.axes; ++a) {
    const NcAxis &x = m.ax[a];
    int16_t w0 = 0, w1 = 0, w2 = static_cast<int16_t>(x.ctrlMode), w3 = 0, w36 = 0;
    setBit(w0, 0, x.moving);
    setBit(w0, 1, x.home == HomePhase::Dog);
    setBit(w0, 2, x.home == HomePhase::ZSearch);
    setBit(w0, 3, x.homeFailed);
    setBit(w0, 4, x.homed);
    setBit(w0, 6, x.slaveHome);
    setBit(w0, 7, x.released);
    setBit(w0, 8, x.homed && x.pos == 0); // at reference point 1
    setBit(w0, 14, x.locked);
    setBit(w1, 0, x.pmcActive);
    setBit(w2, 8, x.ready);
    int sc, sp;
    bool spindle = spindleOf(cfg, a, sc, sp);
    if (spindle) {
      setBit(w2, 14, x.spindleTarget != 0 && x.spindleSpeed == x.spindleTarget);
      setBit(w2, 15, x.spindleSpeed == 0);
    }
    setBit(w3, 0, x.servoOk);
    setBit(w3, 8, x.oriented);
    setBit(w36, 2, x.posLimit);
    setBit(w36, 3, x.negLimit);
    putF(ncw::axis(a, 0), w0);
    putF(ncw::axis(a, 1), w1);
    putF(ncw::axis(a, 2), w2);
    putF(ncw::axis(a, 3), w3);
    int c = axisChannel(cfg, a);
    putF(ncw::axis(a, 4), static_cast<int16_t>(c));
    putF(ncw::axis(a, 36), w36);
    int16_t words[4];
    writeWords(words, 0, 4, x.pos);
    for (int i = 0; i < 4; ++i) {
      putF(ncw::axis(a, 28 + i), words[i]); // machine command position
      putF(ncw::axis(a, 32 + i), words[i]); // machine actual position
    }
    if (c < 0) continue; // drive feedback G words only for axes of the machine
    for (int i = 0; i < 4; ++i) putG(ncw::axis(a, 12 + i), words[i]);
    int16_t v[2];
    writeWords(v, 0, 2, spindle ? x.spindleSpeed : x.lastStep);
    putG(ncw::axis(a, 20), v[0]);
    putG(ncw::axis(a, 21), v[1]);
  }
}

} // namespace lj::hosts

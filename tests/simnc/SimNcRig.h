// A bare lj_state and a SimNc driven tick by tick without any engine: the test plays the PLC
// by writing G words between beforeTick and afterTick (the scan's place in the tick protocol).
#pragma once

#include "hosts/SimNc.h"

#include <memory>

namespace lj::hosts::testing {

/// F/G word numbers of the map (hnc8-cnc-interface.md 1.1-1.4).
constexpr int FA(int a, int k) { return a * 80 + k; }
constexpr int FC(int c, int k) { return 2560 + c * 80 + k; }

struct Rig {
  explicit Rig(const SimNcConfig &cfg = {}) : nc(cfg) {
    lj_state_reset(s.get());
    nc.powerUp(*s);
  }
  /// The NC publishes for the next tick; the test then "scans" by editing words.
  void before() { nc.beforeTick(*s, tick); }
  /// The scan is over: the NC consumes G.
  void after() { nc.afterTick(*s, tick++); }
  /// A whole tick with no PLC action.
  void idle(int n = 1) {
    for (int i = 0; i < n; ++i) {
      before();
      after();
    }
  }
  int16_t &F(int w) { return s->img.F[w]; }
  int16_t &G(int w) { return s->img.G[w]; }
  bool Fbit(int w, int b) { return (static_cast<uint16_t>(F(w)) >> b) & 1u; }
  void setG(int w, int b, bool on) {
    uint16_t u = static_cast<uint16_t>(G(w));
    G(w) = static_cast<int16_t>(on ? (u | (1u << b)) : (u & ~(1u << b)));
  }
  bool hasEvent(const std::string &what) const {
    for (const NcEvent &e : nc.events())
      if (e.what == what) return true;
    return false;
  }
  int64_t eventTick(const std::string &what) const {
    for (const NcEvent &e : nc.events())
      if (e.what == what) return e.tick;
    return -100;
  }

  std::unique_ptr<lj_state> s = std::make_unique<lj_state>();
  SimNc nc;
  uint64_t tick = 0;
};

inline formats::NcCommand mcode(int ch, int m) {
  formats::NcCommand c;
  c.kind = formats::NcCommandKind::MCode;
  c.ch = ch;
  c.code = m;
  return c;
}
inline formats::NcCommand tcode(int ch, int t) {
  formats::NcCommand c = mcode(ch, t);
  c.kind = formats::NcCommandKind::TCode;
  return c;
}
inline formats::NcCommand simple(formats::NcCommandKind k, int index = 0, int64_t value = 0) {
  formats::NcCommand c;
  c.kind = k;
  c.index = index;
  c.ch = index;
  c.ivalue = value;
  return c;
}

} // namespace lj::hosts::testing

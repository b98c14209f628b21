// The FANUC random generator (FanucProgram.h). Programs verify by construction: the ST depth
// is tracked (1..8), timer and edge numbers are used once, jumps go forward to a label of the
// same level, subroutines are called from level 2 and from the subroutines defined before them,
// and JMPC leaves a subroutine for a label of level 2.
#include "gen/FanucProgram.h"

#include "gen/FanucArith.h"
#include "gen/FanucData.h"
#include "gen/FanucTimerCounter.h"
#include "gen/Rng.h"
#include "profiles/fanuc/FanucProfile.h"

#include <algorithm>
#include <cstring>

namespace lj::gen {

namespace {

class Gen {
public:
  explicit Gen(uint64_t seed) : r_(seed) {}

  std::vector<std::string> program(int32_t statements) {
    // Subroutine numbers drawn over P1..P5000 (ref 4.2), each defined once.
    const int count = static_cast<int>(r_.range(0, 2));
    for (int k = 0; k < count; ++k) subs_.push_back(fresh(subUsed_, kSubs));
    rungs(statements / 4 + 1, 1, count);
    out("END1");
    if (count > 0) { // the JMPC guard starts every level-2 scan at 0 (jumpOut below)
      out("RD R9091.1");
      out("NUMEB 2 0 " + std::string(kJumpGuard));
    }
    rungs(statements / 2 + 1, 2, count);
    out("END2");
    // A subroutine calls only the ones defined after it (no recursion), so chains of calls
    // carry a JMPC up through more than one subroutine.
    for (size_t k = 0; k < subs_.size(); ++k) {
      out("SP P" + std::to_string(subs_[k]));
      callFrom_ = static_cast<int>(k) + 1;
      rungs(static_cast<int>(r_.range(1, 4)), 4, count);
      out("SPE");
    }
    out("END");
    return std::move(lines_);
  }

private:
  // The 0i-D resource counts (profiles/fanuc/Areas.cpp): TMRB/TMRBF 1..500, DIFU/DIFD 1..1000,
  // subroutines P1..P5000.
  static constexpr int kTimers = fanuc::kTmrbTimers, kEdges = fanuc::kDifEdges,
                       kSubs = fanuc::kSubroutines;

  void out(std::string s) { lines_.push_back(std::move(s)); }
  /// A number of 1..max not used yet (marked used now), drawn over the whole range so the
  /// highest numbers (the last slots of the state) are exercised too; 0 when all are used.
  int fresh(std::vector<bool> &used, int max) {
    if (used.empty()) used.assign(static_cast<size_t>(max) + 1, false);
    if (std::count(used.begin() + 1, used.end(), false) == 0) return 0;
    for (;;) {
      const auto n = static_cast<size_t>(pick(1, max));
      if (!used[n]) {
        used[n] = true;
        return static_cast<int>(n);
      }
    }
  }
  int64_t pick(int64_t lo, int64_t hi) { return r_.range(lo, hi); }

  std::string readBit() {
    switch (pick(0, 5)) {
    case 0:
    case 1: { // an input from the machine (X) or the CNC (F): live in level 1, latched in level 2
      const std::string area = r_.chance(70) ? "X" : "F";
      return area + std::to_string(pick(0, 3)) + "." + std::to_string(pick(0, 7));
    }
    case 2:
      return "Y" + std::to_string(pick(0, 1)) + "." + std::to_string(pick(0, 7));
    case 3:
      return "R9091." + std::to_string(pick(0, 2));
    default:
      return writeBit();
    }
  }
  std::string writeBit() {
    const char *areas[] = {"R", "R", "D", "K", "E", "Y"};
    return std::string(areas[pick(0, 5)]) + std::to_string(pick(0, 7)) + "." +
           std::to_string(pick(0, 7));
  }
  /// A byte address of the data pools R0..R11, D0..D11 leaving room for `width` bytes.
  std::string data(int width, bool writable = true) {
    if (!writable && r_.chance(25)) {
      const std::string area = r_.chance(70) ? "X" : "F";
      return area + std::to_string(pick(0, 4 - width));
    }
    return std::string(r_.chance(50) ? "R" : "D") + std::to_string(pick(0, 12 - width));
  }
  std::string konst(int width) {
    const int64_t lim = width == 1 ? 127 : width == 2 ? 32767 : 2147483647;
    if (r_.chance(20)) return std::to_string(pick(-3, 3));
    return std::to_string(pick(-lim - 1, lim));
  }
  int width() {
    static constexpr int kW[] = {1, 2, 4};
    return kW[pick(0, 2)];
  }

  void logic() {
    out(std::string(r_.chance(70) ? "RD " : "RD.NOT ") + readBit());
    int depth = 1;
    const int n = static_cast<int>(pick(0, 6));
    for (int k = 0; k < n; ++k) {
      const int64_t c = pick(0, 9);
      if (c <= 5) {
        static const char *ops[] = {"AND ", "AND.NOT ", "OR ", "OR.NOT "};
        out(ops[pick(0, 3)] + readBit());
      } else if (c <= 7 && depth < 8) {
        out(std::string(r_.chance(70) ? "RD.STK " : "RD.NOT.STK ") + readBit());
        ++depth;
      } else if (depth >= 2) {
        out(r_.chance(50) ? "AND.STK" : "OR.STK");
        --depth;
      }
    }
    while (depth > 1) {
      out(r_.chance(50) ? "AND.STK" : "OR.STK");
      --depth;
    }
  }

  void rungs(int n, int level, int subs) {
    for (int i = 0; i < n; ++i) {
      if (level == 2 && subs > 0 && r_.chance(10)) { // a label JMPC can go on at
        const int lbl = ++label_;
        exitLabels_.push_back(lbl);
        out("LBL L" + std::to_string(lbl));
      }
      if (level == 4 && !exitLabels_.empty() && r_.chance(25)) {
        jumpOut();
        continue;
      }
      if (level == 2 && !exitLabels_.empty() && r_.chance(10)) { // more calls that can JMPC
        logic();
        out(std::string(r_.chance(50) ? "CALL P" : "CALLU P") + subroutine(subs));
        continue;
      }
      if (r_.chance(8)) { // a forward jump over a few rungs of the same level
        const int lbl = ++label_;
        logic();
        out("JMPB L" + std::to_string(lbl));
        const int skip = static_cast<int>(pick(1, 3));
        for (int k = 0; k < skip; ++k) rung(level, subs);
        out("LBL L" + std::to_string(lbl));
        continue;
      }
      rung(level, subs);
    }
  }

  void rung(int level, int subs) {
    logic();
    if (r_.chance(12)) return fanucDataRung(r_, lines_); // gen/FanucData.cpp (fanuc-b)
    if (r_.chance(8)) return fanucArithRung(r_, lines_); // gen/FanucArith.cpp (fanuc-c)
    const int64_t c = pick(0, 19);
    if (c <= 6) {
      const int coils = static_cast<int>(pick(1, 3));
      static const char *ops[] = {"WRT ", "WRT.NOT ", "SET ", "RST "};
      for (int k = 0; k < coils; ++k) out(ops[pick(0, 3)] + writeBit());
      return;
    }
    switch (c) {
    case 7:
    case 8:
      if (const int n = fresh(timerUsed_, kTimers)) {
        out(std::string(r_.chance(50) ? "TMRB " : "TMRBF ") + std::to_string(n) + " " +
            std::to_string(pick(1, 30)));
        out("WRT " + writeBit());
      }
      return;
    case 9:
      if (const int n = fresh(edgeUsed_, kEdges)) {
        out(std::string(r_.chance(50) ? "DIFU " : "DIFD ") + std::to_string(n));
        out("WRT " + writeBit());
      }
      return;
    case 10: {
      static const char *mv[] = {"MOVB", "MOVW", "MOVD"};
      const int k = static_cast<int>(pick(0, 2));
      const int w = k == 0 ? 1 : k == 1 ? 2 : 4;
      out(std::string(mv[k]) + " " + data(w, false) + " " + data(w));
      return;
    }
    case 11: {
      const int n = static_cast<int>(pick(1, 6));
      out("SUB 45");
      out("(PRM) " + std::to_string(n));
      out("(PRM) " + data(n));
      out("(PRM) " + data(n));
      return;
    }
    case 12: {
      auto nib = [&] {
        std::string s;
        for (int b = 0; b < 4; ++b) s += r_.chance(50) ? '1' : '0';
        return s;
      };
      if (r_.chance(50))
        out("MOVE " + nib() + " " + nib() + " " + data(1, false) + " " + data(1));
      else
        out("MOVOR " + data(1, false) + " " + data(1, false) + " " + data(1));
      return;
    }
    case 13:
    case 14: {
      const int w = width();
      const bool addr = r_.chance(50);
      const int64_t sub = pick(59, 62);
      out("SUB " + std::to_string(sub));
      if (sub == 62) {
        out("(PRM) 000" + std::to_string(w));
        out("(PRM) " + data(w, false));
        out("(PRM) " + data(w));
        return;
      }
      out(std::string("(PRM) ") + (addr ? "1" : "0") + "00" + std::to_string(w));
      out("(PRM) " + data(w, false));
      out("(PRM) " + (addr ? data(w, false) : konst(w)));
      out("(PRM) " + data(w));
      return;
    }
    case 15:
    case 16:
    case 17: {
      static const char *cmp[] = {"EQ", "GT", "LT", "GE", "LE"};
      const int w = width();
      const char suffix = w == 1 ? 'B' : w == 2 ? 'W' : 'D';
      const std::string a = r_.chance(30) ? konst(w) : data(w, false);
      const std::string b = r_.chance(40) ? konst(w) : data(w, false);
      out(std::string(cmp[pick(0, 4)]) + suffix + " " + a + " " + b);
      out("WRT " + writeBit());
      return;
    }
    case 18:
      return fanucTimerCounterRung(r_, lines_); // gen/FanucTimerCounter.cpp
    default:
      if (level == 4 && callFrom_ >= subs) { // the last subroutine calls none
        out("WRT " + writeBit());
      } else if (level >= 2 && subs > 0 && r_.chance(30)) {
        selectCall(subs); // fanuc-e
      } else if (level >= 2 && subs > 0) {
        out(std::string(r_.chance(50) ? "CALL P" : "CALLU P") + subroutine(subs));
      } else {
        out("WRT " + writeBit());
      }
      return;
    }
  }

  /// The number of one of the `subs` defined subroutines (drawn over P1..P5000, fanuc-f); in a
  /// subroutine one defined after it.
  std::string subroutine(int subs) {
    return std::to_string(subs_[static_cast<size_t>(pick(callFrom_, subs - 1))]);
  }

  /// A JMPC to one of level 2's labels (before or after the CALL that reaches it), taken when
  /// the logic line is 1 and, usually, while the guard counts fewer than a bound: the guard is
  /// 0 at every level-2 start and counts each pass here, so a JMPC back to a label before the
  /// CALL loops a few times; an unguarded one runs into the watchdog while its input holds.
  void jumpOut() {
    out("RD R9091.0");     // RST 0
    out("RD.STK R9091.1"); // ACT 1
    out("ADDB 0002 " + std::string(kJumpGuard) + " 1 " + std::string(kJumpGuard));
    logic();
    if (r_.chance(90)) out("LTW " + std::string(kJumpGuard) + " " + std::to_string(pick(1, 4)));
    const std::string lbl =
        "L" +
        std::to_string(exitLabels_[static_cast<size_t>(pick(0, int64_t(exitLabels_.size()) - 1))]);
    if (r_.chance(50)) {
      out("JMPC " + lbl);
    } else {
      out("SUB 73");
      out("(PRM) " + lbl);
    }
  }

  /// fanuc-e: a CS..CE select-call of 1..4 CM lines (docs/fanuc-pmc.md [EXT] select-call). The
  /// index is usually first masked to 0..3 (SUB 60 AND with 3, under the same ACT) so that CM
  /// entries are selected, out-of-range entries included; else any 2-byte pool value.
  void selectCall(int subs) {
    const std::string idx = data(2);
    if (r_.chance(75)) {
      out("SUB 60");
      out("(PRM) 0002");
      out("(PRM) " + data(2, false));
      out("(PRM) 3");
      out("(PRM) " + idx);
    }
    out(r_.chance(50) ? "CS " + idx : "SUB 74 " + idx);
    const int n = static_cast<int>(pick(1, 4));
    for (int k = 0; k < n; ++k) out((r_.chance(50) ? "CM P" : "SUB 75 P") + subroutine(subs));
    out(r_.chance(50) ? "CE" : "SUB 76");
  }

  Rng r_;
  std::vector<std::string> lines_;
  int label_ = 0;
  std::vector<int> exitLabels_; ///< level-2 labels a JMPC may name
  int callFrom_ = 0;            ///< the first subroutine (index into subs_) rung() may call
  /// The JMPC guard: outside the data pools (R0..R11, D0..D11) and the table pools.
  static constexpr const char *kJumpGuard = "D200";
  std::vector<bool> timerUsed_, edgeUsed_, subUsed_;
  std::vector<int> subs_; ///< the subroutine numbers, in definition order
};

} // namespace

std::vector<std::string> generateFanuc(uint64_t seed, int32_t statements) {
  return Gen(seed).program(statements);
}

Stimulus generateFanucStimulus(uint64_t seed, uint32_t ticks) {
  Rng r(seed);
  Stimulus st;
  uint64_t now = 0;
  for (Area a : {Area::Input, Area::NcStatus})
    for (int k = 0; k < 4; ++k)
      st.beforeInit.push_back({a, k, -1, static_cast<int32_t>(r.range(0, 255))});
  // X0..X3 and F0..F3 change on any tick, so also in the middle of a level-2 scan, which must
  // go on with the inputs latched at its first slice (docs/fanuc-pmc.md "Level 2 and its
  // inputs").
  for (uint32_t t = 0; t < ticks; ++t) {
    std::vector<HostWrite> w;
    const int n = static_cast<int>(r.range(0, 3));
    for (int k = 0; k < n; ++k) {
      const Area a = r.chance(65) ? Area::Input : Area::NcStatus;
      if (r.chance(50))
        w.push_back(
            {a, static_cast<int32_t>(r.range(0, 3)), -1, static_cast<int32_t>(r.range(0, 255))});
      else
        w.push_back({a, static_cast<int32_t>(r.range(0, 3)), static_cast<int8_t>(r.range(0, 7)),
                     static_cast<int32_t>(r.range(0, 1))});
    }
    st.writes.push_back(std::move(w));
    now +=
        r.chance(90) ? static_cast<uint64_t>(r.range(1, 8)) : static_cast<uint64_t>(r.range(0, 50));
    st.nowMs.push_back(now);
  }
  // Drawn last so the writes above are the same as before JMPC: a backward JMPC without a guard
  // runs into the watchdog, at a limit that keeps such ticks short.
  static constexpr uint64_t kLimits[] = {50, 300, 2000, 20000};
  st.maxBackwardSteps = kLimits[r.range(0, 3)];
  // CTR counts in binary or in BCD (the counter data type system parameter, ref 6.4).
  st.counterFormat = r.chance(50) ? TargetProfile::kCounterBcd : TargetProfile::kCounterBinary;
  return st;
}

void applyFanucWrites(const TargetProfile &tp, lj_state &s, const std::vector<HostWrite> &ws) {
  auto *base = reinterpret_cast<unsigned char *>(&s);
  for (const HostWrite &w : ws) {
    if (!tp.validIndex(w.area, w.index) || tp.area(w.area).bytes != 1) continue;
    unsigned char &b = base[tp.elementOffset(w.area, w.index)];
    if (w.bit >= 0)
      b = static_cast<unsigned char>((w.value & 1) ? (b | (1u << w.bit)) : (b & ~(1u << w.bit)));
    else
      b = static_cast<unsigned char>(w.value);
  }
}

} // namespace lj::gen

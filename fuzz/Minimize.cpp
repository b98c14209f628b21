// Delta debugging of a failing differential case (Zeller's ddmin over statement lines, then the
// stimulus), so a mismatch is reported as the smallest program and input that still show it.
#include "fuzz/Differential.h"

#include <algorithm>

namespace lj::fuzz {

namespace {

class Minimizer {
public:
  Minimizer(Outcome::Kind kind, const EngineFactory &f, uint32_t budget)
      : kind_(kind), factory_(f), budget_(budget) {}

  /// Whether `c` still fails the same way; on success `c` is cut to the failing tick.
  bool fails(Case &c) {
    if (runs_ >= budget_) return false;
    ++runs_;
    Outcome o = runCase(c, factory_);
    if (o.kind != kind_) return false;
    if (o.kind == Outcome::Kind::Mismatch) truncate(c, o.tick);
    return true;
  }

  /// Keep only the ticks up to and including `tick` (none when the difference was after init).
  static void truncate(Case &c, uint32_t tick) {
    size_t keep = tick == Outcome::kInitTick ? 0 : static_cast<size_t>(tick) + 1;
    if (keep < c.stim.nowMs.size()) {
      c.stim.nowMs.resize(keep);
      c.stim.writes.resize(keep);
    }
  }

  void ddminLines(Case &best) {
    size_t n = 2;
    while (best.lines.size() >= 2 && runs_ < budget_) {
      const size_t len = best.lines.size();
      n = std::min(n, len);
      const size_t chunk = (len + n - 1) / n;
      bool reduced = false;
      for (size_t start = 0; start < len && !reduced; start += chunk) {
        Case c = best;
        c.lines.erase(c.lines.begin() + static_cast<std::ptrdiff_t>(start),
                      c.lines.begin() + static_cast<std::ptrdiff_t>(std::min(start + chunk, len)));
        if (fails(c)) {
          best = std::move(c);
          n = std::max<size_t>(n - 1, 2);
          reduced = true;
        }
      }
      if (!reduced) {
        if (n >= len) break;
        n = std::min(n * 2, len);
      }
    }
  }

  /// ddmin is only 1-minimal: an MPS/MPP pair or an SP..SPE block can be dropped only
  /// together. Try every contiguous run of 2..8 lines, then (for small programs) every pair.
  bool rangesAndPairs(Case &best) {
    bool any = false;
    for (size_t len = std::min<size_t>(8, best.lines.size()); len >= 2; --len) {
      for (size_t start = 0; start + len <= best.lines.size() && runs_ < budget_;) {
        Case c = best;
        auto first = c.lines.begin() + static_cast<std::ptrdiff_t>(start);
        c.lines.erase(first, first + static_cast<std::ptrdiff_t>(len));
        if (fails(c)) {
          best = std::move(c);
          any = true;
        } else {
          ++start;
        }
      }
    }
    if (best.lines.size() > 24) return any;
    for (size_t i = 0; i < best.lines.size(); ++i) {
      for (size_t j = best.lines.size(); j-- > i + 1 && runs_ < budget_;) {
        Case c = best;
        c.lines.erase(c.lines.begin() + static_cast<std::ptrdiff_t>(j));
        c.lines.erase(c.lines.begin() + static_cast<std::ptrdiff_t>(i));
        if (fails(c)) {
          best = std::move(c);
          any = true;
          j = best.lines.size();
        }
      }
    }
    return any;
  }

  void simplifyStimulus(Case &best) {
    for (size_t t = best.stim.writes.size(); t-- > 0;) {
      if (best.stim.writes[t].empty() || t >= best.stim.writes.size()) continue;
      Case c = best;
      c.stim.writes[t].clear();
      if (fails(c)) {
        best = std::move(c);
        continue;
      }
      for (size_t i = best.stim.writes[t].size(); i-- > 0;) {
        Case d = best;
        d.stim.writes[t].erase(d.stim.writes[t].begin() + static_cast<std::ptrdiff_t>(i));
        if (fails(d)) best = std::move(d);
        if (t >= best.stim.writes.size()) break;
      }
    }
    for (size_t i = best.stim.beforeInit.size(); i-- > 0;) {
      Case c = best;
      c.stim.beforeInit.erase(c.stim.beforeInit.begin() + static_cast<std::ptrdiff_t>(i));
      if (fails(c)) best = std::move(c);
    }
    // A linear clock and the default watchdog replay with plain `ladderjit run`.
    Case lin = best;
    lin.stim.initNowMs = 0;
    for (size_t t = 0; t < lin.stim.nowMs.size(); ++t) lin.stim.nowMs[t] = t;
    if (fails(lin)) best = std::move(lin);
    if (best.stim.maxBackwardSteps != 1000000) {
      Case wd = best;
      wd.stim.maxBackwardSteps = 1000000;
      if (fails(wd)) best = std::move(wd);
    }
    if (best.stim.counterFormat != 0) { // FANUC: binary counters replay without --params
      Case bin = best;
      bin.stim.counterFormat = 0;
      if (fails(bin)) best = std::move(bin);
    }
  }

  uint32_t runs() const { return runs_; }

private:
  Outcome::Kind kind_;
  const EngineFactory &factory_;
  uint32_t budget_;
  uint32_t runs_ = 0;
};

} // namespace

Case minimize(const Case &failing, Outcome::Kind kind, const EngineFactory &factory,
              uint32_t budget) {
  Minimizer m(kind, factory, budget);
  Case best = failing;
  if (!m.fails(best)) return failing; // not reproducible: report it as found
  m.ddminLines(best);
  m.simplifyStimulus(best);
  // A simpler stimulus can free more lines; coarse-to-fine rounds until nothing changes.
  for (int round = 0; round < 4; ++round) {
    m.ddminLines(best);
    if (!m.rangesAndPairs(best)) break;
  }
  return best;
}

} // namespace lj::fuzz

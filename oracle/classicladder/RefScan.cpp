// The reference ClassicLadder scan (LinuxCNC 2.9), literally: column-major rung evaluation with
// StateOnLeft's vertical groups, coils written at once, the blocks' state machines, sections in
// index order with NEXTRUNG chains, jumps and calls, the Grafcet pages, and the HAL copy-in /
// copy-out (reference sections 2.4 and 4).
#include "oracle/classicladder/RefScan.h"

#include <algorithm>

namespace lj::oracle {

using namespace lj::classicladder;

namespace {
constexpr int kSteps = 128;
template <typename T> bool inRange(const std::vector<T> &v, int32_t i) {
  return i >= 0 && static_cast<size_t>(i) < v.size();
}
} // namespace

ClReferenceScan::ClReferenceScan(const Project &p, const ClSizes &sz) : p_(p), sz_(sz) {
  in.assign(sz.inputs, 0);
  s32in.assign(sz.s32in, 0);
  floatIn.assign(sz.floatIn, 0.0);
  out.assign(sz.outputs, 0);
  s32out.assign(sz.s32out, 0);
  floatOut.assign(sz.floatOut, 0.0);
  bits_.assign(sz.bits, 0);
  sys_.assign(20, 0);
  err_.assign(10, 0);
  steps_.assign(kSteps, 0);
  words_.assign(sz.words, 0);
  sysWords_.assign(20, 0);
  stepSeconds_.assign(kSteps, 0);
  timers_.resize(sz.timers);
  for (size_t i = 0; i < timers_.size() && i < p.timers.size(); ++i) {
    timers_[i].baseMs = p.timers[i].baseMs;
    timers_[i].presetMs = p.timers[i].preset * p.timers[i].baseMs;
    timers_[i].value = timers_[i].presetMs; // PrepareTimers: Value = Preset
  }
  monos_.resize(sz.monostables);
  for (size_t i = 0; i < monos_.size() && i < p.monostables.size(); ++i) {
    monos_[i].baseMs = p.monostables[i].baseMs;
    monos_[i].presetMs = p.monostables[i].preset * p.monostables[i].baseMs;
  }
  counters_.resize(sz.counters);
  for (size_t i = 0; i < counters_.size() && i < p.counterPresets.size(); ++i)
    counters_[i].preset = p.counterPresets[i];
  iec_.resize(sz.timersIec);
  for (size_t i = 0; i < iec_.size() && i < p.timersIec.size(); ++i) {
    iec_[i].baseMs = p.timersIec[i].baseMs;
    iec_[i].preset = p.timersIec[i].preset;
    iec_[i].mode = p.timersIec[i].mode;
  }
  for (const auto &[n, r] : p.rungs)
    dyn_[n].assign(r.cells.size(), std::vector<Dyn>(r.cells.empty() ? 0 : r.cells[0].size()));
  stepActive_.assign(kSteps, 0);
  stepTime_.assign(kSteps, 0);
  for (const auto &s : p.sequential.steps)
    if (s.slot >= 0 && s.slot < kSteps && s.initial) stepActive_[s.slot] = 1;
}

int32_t ClReferenceScan::readVar(int32_t type, int32_t n) const {
  auto b = [&](const std::vector<uint8_t> &v) { return inRange(v, n) ? int32_t(v[n]) : 0; };
  auto w = [&](const std::vector<int32_t> &v) { return inRange(v, n) ? v[n] : 0; };
  switch (type) {
  case 0:
    return b(bits_);
  case 10:
    return inRange(timers_, n) ? timers_[n].done : 0;
  case 11:
    return inRange(timers_, n) ? timers_[n].running : 0;
  case 15:
    return inRange(iec_, n) ? iec_[n].q : 0;
  case 20:
    return inRange(monos_, n) ? monos_[n].running : 0;
  case 25:
    return inRange(counters_, n) ? counters_[n].done : 0;
  case 26:
    return inRange(counters_, n) ? counters_[n].empty : 0;
  case 27:
    return inRange(counters_, n) ? counters_[n].full : 0;
  case 30:
    return b(steps_);
  case 50:
    return b(in);
  case 60:
    return b(out);
  case 70:
    return b(sys_);
  case 75:
    return b(err_);
  case 200:
    return w(words_);
  case 220:
    return w(stepSeconds_);
  case 230:
    return inRange(timers_, n) ? timers_[n].presetMs / timers_[n].baseMs : 0;
  case 231:
    return inRange(timers_, n) ? timers_[n].value / timers_[n].baseMs : 0;
  case 240:
    return inRange(monos_, n) ? monos_[n].presetMs / monos_[n].baseMs : 0;
  case 241:
    return inRange(monos_, n) ? monos_[n].value / monos_[n].baseMs : 0;
  case 250:
    return inRange(counters_, n) ? counters_[n].preset : 0;
  case 251:
    return inRange(counters_, n) ? counters_[n].value : 0;
  case 260:
    return inRange(iec_, n) ? iec_[n].preset : 0;
  case 261:
    return inRange(iec_, n) ? iec_[n].value : 0;
  case 270:
    return w(s32in);
  case 280:
    return w(s32out);
  case 290:
    return w(sysWords_);
  case 300:
    return inRange(floatIn, n) ? static_cast<int32_t>(floatIn[n]) : 0; // read as int
  case 310:
    return inRange(floatOut, n) ? static_cast<int32_t>(floatOut[n]) : 0;
  default:
    return 0;
  }
}

void ClReferenceScan::writeVar(int32_t type, int32_t n, int32_t v) {
  auto b = [&](std::vector<uint8_t> &a) {
    if (inRange(a, n)) a[n] = v != 0;
  };
  auto w = [&](std::vector<int32_t> &a) {
    if (inRange(a, n)) a[n] = v;
  };
  switch (type) {
  case 0:
    b(bits_);
    break;
  case 15:
    if (inRange(iec_, n)) iec_[n].q = v != 0;
    break;
  case 30:
    b(steps_);
    break;
  case 50:
    b(in);
    break;
  case 60:
    b(out);
    break;
  case 70:
    b(sys_);
    break;
  case 75:
    b(err_);
    break;
  case 200:
    w(words_);
    break;
  case 230:
    if (inRange(timers_, n)) timers_[n].presetMs = v * timers_[n].baseMs;
    break;
  case 240:
    if (inRange(monos_, n)) monos_[n].presetMs = v * monos_[n].baseMs;
    break;
  case 250:
    if (inRange(counters_, n)) counters_[n].preset = v;
    break;
  case 251:
    if (inRange(counters_, n)) counters_[n].value = v;
    break;
  case 260:
    if (inRange(iec_, n)) iec_[n].preset = v;
    break;
  case 261:
    if (inRange(iec_, n)) iec_[n].value = v;
    break;
  case 270:
    w(s32in);
    break;
  case 280:
    w(s32out);
    break;
  case 290:
    w(sysWords_);
    break;
  case 300:
    if (inRange(floatIn, n)) floatIn[n] = v;
    break;
  case 310:
    if (inRange(floatOut, n)) floatOut[n] = v;
    break; // only whole numbers
  default:
    break;
  }
}

int32_t ClReferenceScan::readRef(const VarRef &v) const {
  int32_t n = v.num;
  if (v.indexType >= 0) n += readVar(v.indexType, v.indexNum); // master's index
  return readVar(v.type, n);
}

bool ClReferenceScan::stateOnLeft(const Rung &r, int x, int y) const {
  if (x <= 0) return true; // the rail
  const auto &d = dyn_.at(r.index);
  const int h = static_cast<int>(r.cells[x].size());
  int top = y, bottom = y;
  while (top > 0 && r.cells[x][top].connectedWithTop) --top;
  while (bottom + 1 < h && r.cells[x][bottom + 1].connectedWithTop) ++bottom;
  for (int k = top; k <= bottom; ++k)
    if (d[x - 1][k].out) return true;
  return false;
}

int32_t ClReferenceScan::refreshRung(int32_t index) {
  const Rung &r = p_.rungs.at(index);
  auto &d = dyn_.at(index);
  const int w = static_cast<int>(r.cells.size());
  const int h = w ? static_cast<int>(r.cells[0].size()) : 0;
  int32_t jump = -1;
  for (int x = 0; x < w && jump == -1; ++x) {
    for (int y = 0; y < h && jump == -1; ++y) {
      const Cell &c = r.cells[x][y];
      Dyn &cell = d[x][y];
      switch (c.type) {
      case 1:
        cell.out = readVar(c.varType, c.varNum) != 0 && stateOnLeft(r, x, y);
        break;
      case 2:
        cell.out = readVar(c.varType, c.varNum) == 0 && stateOnLeft(r, x, y);
        break;
      case 3:
      case 4: {
        uint8_t v = readVar(c.varType, c.varNum) != 0;
        bool edge = c.type == 3 ? (v && !cell.bak) : (!v && cell.bak);
        cell.bak = v;
        cell.out = edge && stateOnLeft(r, x, y);
        break;
      }
      case 9:
        cell.out = stateOnLeft(r, x, y);
        break;
      case 10: {
        if (!inRange(timers_, c.varNum) || y + 1 >= h) break;
        OldTimer &t = timers_[c.varNum];
        bool e = stateOnLeft(r, x - 1, y), ctl = stateOnLeft(r, x - 1, y + 1);
        if (!e) {
          t.running = t.done = 0;
          t.value = t.presetMs;
        } else if (t.value > 0) {
          if (ctl) {
            t.value -= ms_;
            t.running = 1;
            t.done = 0;
          }
        } else {
          t.running = 0;
          t.done = 1;
        }
        cell.out = t.done;
        d[x][y + 1].out = t.running;
        break;
      }
      case 11: {
        if (!inRange(monos_, c.varNum)) break;
        Mono &m = monos_[c.varNum];
        uint8_t i = stateOnLeft(r, x - 1, y);
        if (i && !m.inputBak && m.value == 0) {
          m.running = 1;
          m.value = m.presetMs;
        }
        if (m.value > 0)
          m.value -= ms_;
        else
          m.running = 0;
        m.inputBak = i;
        cell.out = m.running;
        break;
      }
      case 12: {
        if (!inRange(counters_, c.varNum) || y + 3 >= h) break;
        Counter &k = counters_[c.varNum];
        bool in4[4];
        for (int j = 0; j < 4; ++j) in4[j] = x == 0 || stateOnLeft(r, x - 1, y + j);
        bool reset = in4[0], preset = in4[1], up = in4[2], down = in4[3];
        if (up && !k.upBak) {
          k.valueBak = k.value;
          if (++k.value > 9999) k.value = 0;
        }
        if (down && !k.downBak) {
          k.valueBak = k.value;
          if (--k.value < 0) k.value = 9999;
        }
        k.upBak = up;
        k.downBak = down;
        if (preset) {
          k.valueBak = k.value;
          k.value = k.preset;
        }
        if (reset) {
          k.valueBak = k.value;
          k.value = 0;
        }
        k.done = k.value == k.preset;
        k.empty = k.value == 9999 && k.valueBak == 0;
        k.full = k.value == 0 && k.valueBak == 9999;
        cell.out = k.empty;
        d[x][y + 1].out = k.done;
        d[x][y + 2].out = k.full;
        break;
      }
      case 13: {
        if (!inRange(iec_, c.varNum)) break;
        IecTimer &t = iec_[c.varNum];
        uint8_t i = stateOnLeft(r, x - 1, y);
        bool inc = false;
        switch (t.mode) {
        case IecMode::Ton:
          if (!i)
            t.q = 0, t.value = 0;
          else if (t.value < t.preset)
            inc = true;
          else
            t.q = 1;
          break;
        case IecMode::Tof:
          if (i)
            t.q = 1, t.value = 0, t.started = 0;
          else if (t.inputBak)
            t.started = 1;
          if (t.started) {
            if (t.value < t.preset)
              inc = true;
            else
              t.q = 0, t.value = 0, t.started = 0;
          }
          break;
        case IecMode::Tp:
          if (i && !t.inputBak && !t.started) t.q = 1, t.value = 0, t.started = 1;
          if (t.started) {
            if (t.value < t.preset)
              inc = true;
            else
              t.q = 0, t.value = 0, t.started = 0;
          }
          break;
        }
        if (inc) {
          t.acc += ms_;
          if (t.acc >= t.baseMs) {
            ++t.value;
            t.acc -= t.baseMs;
          }
        }
        t.inputBak = i;
        cell.out = t.q;
        break;
      }
      case 20: {
        const ArithExpr *a = p_.expression(c.varNum);
        bool v = a && evaluateCompare(a->expr, [&](const VarRef &v) { return readRef(v); });
        cell.out = v && stateOnLeft(r, x - 2, y);
        break;
      }
      case 50:
        writeVar(c.varType, c.varNum, stateOnLeft(r, x, y));
        break;
      case 51:
        writeVar(c.varType, c.varNum, !stateOnLeft(r, x, y));
        break;
      case 52:
        if (stateOnLeft(r, x, y)) writeVar(c.varType, c.varNum, 1);
        break;
      case 53:
        if (stateOnLeft(r, x, y)) writeVar(c.varType, c.varNum, 0);
        break;
      case 54:
        if (stateOnLeft(r, x, y)) jump = c.varNum;
        break;
      case 55:
        if (stateOnLeft(r, x, y)) {
          for (const auto &s : p_.sections) {
            if (s.subRoutine != c.varNum) continue;
            if (s.language == Language::Ladder) refreshSection(s);
            break;
          }
        }
        break;
      case 60:
        if (stateOnLeft(r, x - 2, y)) {
          const ArithExpr *a = p_.expression(c.varNum);
          if (a && !a->expr.empty && a->expr.isOperate) {
            int32_t v = evaluate(*a->expr.value, [&](const VarRef &v) { return readRef(v); });
            int32_t n = a->expr.target.num;
            if (a->expr.target.indexType >= 0)
              n += readVar(a->expr.target.indexType, a->expr.target.indexNum);
            writeVar(a->expr.target.type, n, v);
          }
        }
        break;
      default:
        break; // FREE, 99, editor codes: DynamicOutput is never written
      }
    }
  }
  return jump;
}

void ClReferenceScan::refreshSection(const Section &s) {
  int32_t rung = s.firstRung;
  for (;;) {
    if (!running_ || !p_.rungs.count(rung)) return;
    int32_t g = refreshRung(rung);
    if (g >= 0) {
      if (++jumps_ > 99999) {
        running_ = false; // MadLoopBreak: the ladder stops
        return;
      }
      if (!p_.rungs.count(g)) return;
      rung = g;
    } else if (rung == s.lastRung) {
      return;
    } else {
      rung = p_.rungs.at(rung).nextRung;
    }
  }
}

void ClReferenceScan::refreshSequentialPage(int32_t page) {
  const auto &seq = p_.sequential;
  std::vector<const Transition *> order;
  for (const auto &t : seq.transitions)
    if (t.page == page) order.push_back(&t);
  std::sort(order.begin(), order.end(),
            [](const Transition *a, const Transition *b) { return a->slot < b->slot; });
  bool changed = true;
  for (int pass = 0; pass < 50 && changed; ++pass) {
    changed = false;
    for (const Transition *t : order) {
      if (t->condition.type < 0 || readRef(t->condition) == 0) continue;
      bool all = true;
      for (int32_t s : t->deactivate) all = all && s >= 0 && s < kSteps && stepActive_[s];
      if (!all) continue;
      for (int32_t s : t->deactivate) stepActive_[s] = 0;
      for (int32_t s : t->activate)
        if (s >= 0 && s < kSteps) stepActive_[s] = 1;
      changed = true;
    }
  }
  refreshStepsVars();
}

void ClReferenceScan::refreshStepsVars() {
  std::vector<int32_t> number(kSteps, 0);
  for (const auto &s : p_.sequential.steps)
    if (s.slot >= 0 && s.slot < kSteps) number[s.slot] = s.stepNumber;
  for (int i = 0; i < kSteps; ++i) { // 2.9: every slot, unused ones writing %X0
    stepTime_[i] = stepActive_[i] ? stepTime_[i] + ms_ : 0;
    int32_t n = number[i];
    if (n >= 0 && n < kSteps) {
      steps_[n] = stepActive_[i];
      stepSeconds_[n] = stepTime_[i] / 1000;
    }
  }
}

void ClReferenceScan::refresh(int32_t ms) {
  if (!running_ || ms < 1) return;
  ms_ = ms;
  for (auto &f : floatIn) f = static_cast<double>(static_cast<int32_t>(f)); // read as int
  std::vector<const Section *> order;
  for (const auto &s : p_.sections) order.push_back(&s);
  std::sort(order.begin(), order.end(),
            [](const Section *a, const Section *b) { return a->number < b->number; });
  for (const Section *s : order) {
    jumps_ = 0;
    if (s->language == Language::Ladder && s->subRoutine == -1)
      refreshSection(*s);
    else if (s->language == Language::Sequential)
      refreshSequentialPage(s->sequentialPage);
    if (!running_) return;
  }
}

} // namespace lj::oracle

// Random host stimulus (X/F writes, now_ms stream, retain store and parameters) and its
// rendering in the CLI stimulus-file format (CLI.md `--stimulus`).
#include "gen/GenPools.h"
#include "gen/ProgramGenerator.h"

#include "frontends/iec/Objects.h"
#include "profiles/hnc8/Hnc8Profile.h"

#include <cstring>
#include <iterator>
#include <sstream>

namespace lj::gen {

std::string GenProgram::text() const {
  std::string t;
  for (const std::string &l : lines) {
    t += l;
    t += '\n';
  }
  return t;
}

namespace {

/// A write to the F words the CNC blocks read (cnc-interface 1.1, 1.3, 1.6): FC[0] status bits
/// (reset request .12, hold .4, cycle .5, mode .0-3), the M-code slots FC[48..55] and the T code
/// FC[56] with matching codes or -1 (nothing pending), S/G31/spindle words, and FA[0..3] axis
/// status bits, mostly for channel 0 and the low axes the generator picks most.
HostWrite cncInput(Rng &rng) {
  HostWrite w;
  w.area = Area::NcStatus;
  const int32_t ch = static_cast<int32_t>(rng.chance(60) ? 0 : rng.below(4));
  const int32_t axis = static_cast<int32_t>(rng.chance(80) ? rng.below(4) : rng.below(32));
  switch (rng.below(6)) {
  case 0:
    w.index = fcWord(ch, 0);
    w.bit = static_cast<int8_t>(rng.chance(40) ? 12 : rng.below(16));
    w.value = static_cast<int32_t>(rng.below(2));
    break;
  case 1:
    w.index = fcWord(ch, 48 + static_cast<int32_t>(rng.below(8)));
    w.value = rng.chance(30) ? -1 : kMCodes[rng.below(std::size(kMCodes))];
    break;
  case 2:
    w.index = fcWord(ch, 56);
    w.value = rng.chance(30) ? -1 : kTCodes[rng.below(std::size(kTCodes))];
    break;
  case 3: {
    static constexpr int32_t kWords[] = {0, 2, 10, 11, 18, 19, 30, 31, 78};
    w.index = fcWord(ch, kWords[rng.below(std::size(kWords))]);
    w.value = static_cast<int16_t>(interestingConst(rng));
    break;
  }
  default:
    w.index = faWord(axis, static_cast<int32_t>(rng.below(4)));
    w.bit = static_cast<int8_t>(rng.below(16));
    w.value = static_cast<int32_t>(rng.below(2));
    break;
  }
  return w;
}

/// One random X or F write: a whole element or a single bit.
HostWrite randomInput(Rng &rng) {
  if (rng.chance(20)) return cncInput(rng);
  HostWrite w;
  w.area = rng.chance(60) ? Area::Input : Area::NcStatus;
  w.index = pickIndex(rng, w.area);
  if (rng.chance(50)) {
    w.bit = static_cast<int8_t>(rng.below(static_cast<uint64_t>(hnc8::profile().bitWidth(w.area))));
    w.value = static_cast<int32_t>(rng.below(2));
  } else if (w.area == Area::Input) {
    w.value = static_cast<int32_t>(rng.below(256));
  } else {
    w.value = static_cast<int16_t>(interestingConst(rng));
  }
  return w;
}

/// Element `index` of a writable-by-host area, as raw bytes of the image.
void *elementPtr(lj_state &s, Area a, int32_t index, int &bytes) {
  lj_image &m = s.img;
  switch (a) {
  case Area::Input:
    bytes = 1;
    return &m.X[index];
  case Area::Output:
    bytes = 1;
    return &m.Y[index];
  case Area::NcStatus:
    bytes = 2;
    return &m.F[index];
  case Area::NcControl:
    bytes = 2;
    return &m.G[index];
  case Area::Relay:
    bytes = 1;
    return &m.R[index];
  case Area::Word:
    bytes = 2;
    return &m.W[index];
  case Area::DWord:
    bytes = 4;
    return &m.D[index];
  case Area::Retained:
    bytes = 4;
    return &m.B[index];
  case Area::Param:
    bytes = 4;
    return &m.P[index];
  default:
    bytes = 0;
    return nullptr;
  }
}

} // namespace

Stimulus generateStimulus(uint64_t seed, uint32_t ticks) {
  Rng rng(seed);
  Stimulus st;
  static constexpr uint64_t kLimits[] = {50, 300, 2000, 20000};
  st.maxBackwardSteps = kLimits[rng.below(4)];
  for (Area a : {Area::Param, Area::Retained}) {
    for (int32_t i = 0; i < poolSize(a); ++i)
      if (rng.chance(70)) st.beforeInit.push_back({a, i, -1, interestingConst(rng)});
  }
  // Most programs start with no M / T code pending in any channel (FC[48..56] = -1).
  for (int32_t ch = 0; ch < 4; ++ch) {
    if (!rng.chance(80)) continue;
    for (int32_t k = 48; k <= 56; ++k)
      st.beforeInit.push_back({Area::NcStatus, fcWord(ch, k), -1, -1});
  }
  int initial = static_cast<int>(rng.range(0, 6));
  for (int i = 0; i < initial; ++i) st.beforeInit.push_back(randomInput(rng));
  st.initNowMs = rng.chance(80) ? 0 : rng.below(1000000);

  uint64_t now = st.initNowMs;
  int busy = static_cast<int>(rng.range(5, 60)); // percent of ticks with input changes
  st.writes.resize(ticks);
  st.nowMs.resize(ticks);
  for (uint32_t t = 0; t < ticks; ++t) {
    // Mostly one period per tick; jumps make long presets and minute/hour units fire, and a
    // jump past 2^32 ms checks 64-bit time arithmetic.
    static constexpr int kJumps[] = {80, 10, 6, 3, 1};
    switch (rng.weighted(kJumps)) {
    case 0:
      now += 1;
      break;
    case 1:
      now += rng.range(2, 300);
      break;
    case 2:
      now += rng.range(1000, 200000);
      break;
    case 3:
      now += rng.range(3600000, 4 * 3600000ll);
      break;
    default:
      now += 5000000000ull;
      break;
    }
    st.nowMs[t] = now;
    if (rng.chance(busy)) {
      int n = static_cast<int>(rng.range(1, 4));
      for (int i = 0; i < n; ++i) st.writes[t].push_back(randomInput(rng));
    }
  }
  return st;
}

void applyWrites(lj_state &s, const std::vector<HostWrite> &writes) {
  for (const HostWrite &w : writes) {
    int bytes = 0;
    void *p = nullptr;
    if (w.profile) { // a profile-laid target (IEC): the element's bytes in lj_state
      bytes = w.profile->area(w.area).bytes;
      if (bytes > 0 && w.profile->validIndex(w.area, w.index))
        p = reinterpret_cast<unsigned char *>(&s) + w.profile->elementOffset(w.area, w.index);
    } else {
      p = elementPtr(s, w.area, w.index, bytes);
    }
    if (!p) continue;
    uint32_t cur = 0;
    std::memcpy(&cur, p, static_cast<size_t>(bytes)); // little-endian host (DIALECT.md 1)
    uint32_t v = static_cast<uint32_t>(w.value);
    if (w.bit >= 0) {
      uint32_t m = 1u << w.bit;
      v = (w.value & 1) ? (cur | m) : (cur & ~m);
    }
    std::memcpy(p, &v, static_cast<size_t>(bytes));
  }
}

std::string formatAddress(const HostWrite &w) {
  if (w.profile && std::string_view(w.profile->name) == "iec") {
    Operand o;
    o.kind = w.bit >= 0 ? Operand::Kind::Bit : Operand::Kind::Reg;
    o.area = w.area;
    o.index = w.index;
    o.bit = w.bit;
    return iec::formatOperand(o); // %I0.3, %KW1
  }
  std::string s(hnc8::profile().area(w.area).name);
  s += std::to_string(w.index);
  if (w.bit >= 0) s += "." + std::to_string(w.bit);
  return s;
}

std::string formatStimulus(const Stimulus &st) {
  std::ostringstream o;
  o << "# watchdog max_backward_steps=" << st.maxBackwardSteps << "\n";
  if (!st.beforeInit.empty()) {
    o << "# before init (--set / --params):";
    for (const HostWrite &w : st.beforeInit) o << ' ' << formatAddress(w) << '=' << w.value;
    o << "\n";
  }
  o << "# now_ms: init=" << st.initNowMs;
  bool linear = true;
  for (uint32_t t = 0; t < st.ticks(); ++t) linear = linear && st.nowMs[t] == t;
  if (linear) {
    o << ", tick t at t ms (--period-ms 1)\n";
  } else {
    o << ", per tick:";
    for (uint32_t t = 0; t < st.ticks(); ++t) o << ' ' << st.nowMs[t];
    o << "\n";
  }
  for (uint32_t t = 0; t < st.ticks(); ++t) {
    if (st.writes[t].empty()) continue;
    o << '@' << t;
    for (const HostWrite &w : st.writes[t]) o << ' ' << formatAddress(w) << '=' << w.value;
    o << "\n";
  }
  return o.str();
}

} // namespace lj::gen

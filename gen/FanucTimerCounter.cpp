// FANUC PMC timer / counter / compare rungs for the differential fuzzer (FanucTimerCounter.h).
// Every line verifies by construction: depth stays within ST0..ST7, numbers are used once and
// within the 0i-D resource counts, multi-byte operands stay inside the pools R0..R11, D0..D11.
#include "gen/FanucTimerCounter.h"

#include <cstdlib>
#include <iterator>

namespace lj::gen {

namespace {

std::string num(int64_t v) { return std::to_string(v); }

/// A number of 1..max that no line `prefix N` of the program uses yet, drawn over the whole
/// range (so TMR 250, CTR 100 and CTRB 100, the last of the 0i-D counts, are generated too);
/// 0 when all are taken.
int freshNumber(Rng &r, const std::vector<std::string> &lines, const std::string &prefix, int max) {
  std::vector<bool> taken(static_cast<size_t>(max) + 1, false);
  int count = 0;
  for (const std::string &l : lines) {
    if (l.rfind(prefix, 0) != 0) continue;
    const int v = std::atoi(l.c_str() + prefix.size());
    if (v >= 1 && v <= max && !taken[static_cast<size_t>(v)]) {
      taken[static_cast<size_t>(v)] = true;
      ++count;
    }
  }
  if (count == max) return 0;
  for (;;) {
    const auto v = static_cast<int>(r.range(1, max));
    if (!taken[static_cast<size_t>(v)]) return v;
  }
}

std::string bit(Rng &r) {
  if (r.chance(40)) {
    const std::string area = r.chance(70) ? "X" : "F";
    return area + num(r.range(0, 3)) + "." + num(r.range(0, 7));
  }
  if (r.chance(15)) return "R9091." + num(r.range(0, 1));
  return std::string(r.chance(50) ? "R" : "D") + num(r.range(0, 7)) + "." + num(r.range(0, 7));
}
std::string writeBit(Rng &r) {
  return std::string(r.chance(50) ? "R" : "D") + num(r.range(0, 7)) + "." + num(r.range(0, 7));
}
std::string data(Rng &r, int width) {
  return std::string(r.chance(50) ? "R" : "D") + num(r.range(0, 12 - width));
}
std::string konst(Rng &r, int width) {
  const int64_t lim = width == 1 ? 127 : width == 2 ? 32767 : 2147483647;
  if (r.chance(40)) return num(r.range(-3, 12));
  return num(r.range(-lim - 1, lim));
}
int width(Rng &r) {
  static constexpr int kW[] = {1, 2, 4};
  return kW[r.range(0, 2)];
}
/// A preset source of small counts mostly: the pools hold anything, so mask through AND.
void presetInto(Rng &r, std::vector<std::string> &out, const std::string &target) {
  out.push_back("RD R9091.1");
  out.push_back("SUB 60");
  out.push_back("(PRM) 0002");
  out.push_back("(PRM) " + data(r, 2));
  out.push_back("(PRM) " + num(r.chance(80) ? r.range(0, 15) : r.range(0, 32767)));
  out.push_back("(PRM) " + target);
}
/// `RD act` / `NUMEB 2 v target` with v a value near BCD digit carries or invalid BCD (CTR in
/// either counter data type, docs/fanuc-pmc.md "System parameters").
void bcdInto(Rng &r, std::vector<std::string> &out, const std::string &act,
             const std::string &target) {
  static constexpr int32_t kValues[] = {
      9,     10, 16, 19, 20, 0x19, 0x20, 0x1A, 0x99, 0x100, 0x999, 0x1234, -26216 /* 0x9998 */,
      -26215 /* 0x9999 */};
  out.push_back("RD " + act);
  out.push_back("NUMEB 2 " +
                num(kValues[r.range(0, static_cast<int64_t>(std::size(kValues)) - 1)]) + " " +
                target);
}
/// Three more inputs on top of the logic line (CN0 / BYT), ACT last.
void pushInputs(Rng &r, std::vector<std::string> &out, int n) {
  for (int k = 0; k < n; ++k) out.push_back((r.chance(70) ? "RD.STK " : "RD.NOT.STK ") + bit(r));
}

} // namespace

void fanucTimerCounterRung(Rng &r, std::vector<std::string> &out) {
  switch (r.range(0, 8)) {
  case 0: { // TMR n: preset T(2(n-1)), precision T9000 + 2(n-1)
    const int n = freshNumber(r, out, "TMR ", 250);
    if (n == 0) break;
    out.push_back("TMR " + num(n));
    out.push_back("WRT " + writeBit(r));
    presetInto(r, out, "T" + num(2 * (n - 1)));
    if (r.chance(50)) presetInto(r, out, "T" + num(9000 + 2 * (n - 1)));
    return;
  }
  case 1:
    out.push_back("TMRC " + num(r.range(0, 7)) + " " + data(r, 2) + " " + data(r, 4));
    out.push_back("WRT " + writeBit(r));
    return;
  case 2: { // CTR n: preset C(4(n-1)), current C(4(n-1)+2)
    const int n = freshNumber(r, out, "CTR ", 100);
    if (n == 0) break;
    pushInputs(r, out, 3);
    out.push_back("CTR " + num(n));
    out.push_back("WRT " + writeBit(r));
    if (r.chance(60))
      presetInto(r, out, "C" + num(4 * (n - 1)));
    else if (r.chance(60)) // a preset whose BCD and binary readings differ (20 vs 0x20)
      bcdInto(r, out, "R9091.1", "C" + num(4 * (n - 1)));
    if (r.chance(40)) // now and then a count a digit below a BCD carry (0x09, 0x99, 0x9999)
      bcdInto(r, out, bit(r), "C" + num(4 * (n - 1) + 2));
    return;
  }
  case 3: {
    const int n = freshNumber(r, out, "CTRB ", 100);
    if (n == 0) break;
    pushInputs(r, out, 3);
    out.push_back("CTRB " + num(n) + " " + num(r.range(0, 20)));
    out.push_back("WRT " + writeBit(r));
    return;
  }
  case 4:
    pushInputs(r, out, 3);
    out.push_back("CTRC " + data(r, 2) + " " + data(r, 4));
    out.push_back("WRT " + writeBit(r));
    return;
  case 5: {
    const int w = width(r);
    const bool addr = r.chance(50);
    out.push_back(std::string("COMPB ") + (addr ? "1" : "0") + "00" + num(w) + " " +
                  (addr ? data(r, w) : konst(r, w)) + " " + data(r, w));
    return;
  }
  case 6: {
    pushInputs(r, out, 1);
    const bool addr = r.chance(50);
    out.push_back(std::string(r.chance(50) ? "COMP " : "COIN ") + (addr ? "1 " : "0 ") +
                  (addr ? data(r, 2) : num(r.range(0, 9999))) + " " + data(r, 2));
    out.push_back("WRT " + writeBit(r));
    return;
  }
  case 7: {
    const int w = width(r);
    const char *sfx = w == 1 ? "B " : w == 2 ? "W " : "D ";
    out.push_back(std::string("NE") + sfx + (r.chance(30) ? konst(r, w) : data(r, w)) + " " +
                  (r.chance(40) ? konst(r, w) : data(r, w)));
    out.push_back("WRT " + writeBit(r));
    return;
  }
  default: {
    const int w = width(r);
    const char *sfx = w == 1 ? "B " : w == 2 ? "W " : "D ";
    out.push_back(std::string("RNG") + sfx + (r.chance(40) ? konst(r, w) : data(r, w)) + " " +
                  (r.chance(40) ? konst(r, w) : data(r, w)) + " " + data(r, w));
    out.push_back("WRT " + writeBit(r));
    return;
  }
  }
  out.push_back("WRT " + writeBit(r)); // numbers used up: an ordinary coil
}

} // namespace lj::gen

// The IEC IL program generator (IlGenerator.h). It writes IL text as a Neza programmer would;
// the front end checks it, so a generator slip shows up as "programs not verified".
#include "gen/IlGenerator.h"

#include "gen/Rng.h"
#include "profiles/iec/IecProfile.h"

#include <string>
#include <vector>

namespace lj::gen {

namespace {

class IlGen {
public:
  IlGen(uint64_t seed, int32_t statements) : rng_(seed), budget_(statements) {}

  GenProgram run() {
    subs_ = static_cast<int>(rng_.below(4));
    configure();
    if (rng_.chance(20)) {
      line("LD %S1"); // the start-up idiom (L581-582)
      line("ENDC");
    }
    while (budget_ > 0) rung(-1);
    placeLabels(true);
    if (subs_ > 0 || rng_.chance(30)) line("END");
    for (int s = 0; s < subs_; ++s) {
      line("SR" + std::to_string(s) + " :");
      const int rungs = static_cast<int>(rng_.range(1, 4));
      for (int r = 0; r < rungs; ++r) rung(s);
      placeLabels(true);
      if (rng_.chance(70)) line("RET");
    }
    return std::move(prog_);
  }

private:
  void line(std::string s) {
    prog_.lines.push_back(std::move(s));
    --budget_;
  }

  std::string input() {
    const int u = rng_.chance(80) ? 0 : static_cast<int>(rng_.range(1, 3));
    return "%I" + std::to_string(u) + "." + std::to_string(rng_.below(16));
  }
  std::string memory(bool edge) {
    if (edge || rng_.chance(70)) return "%M" + std::to_string(rng_.below(32));
    return "%M" + std::to_string(rng_.range(32, 127));
  }
  std::string output() {
    return "%Q" + std::to_string(rng_.below(2)) + "." + std::to_string(rng_.below(16));
  }
  std::string wordBit() {
    return "%MW" + std::to_string(rng_.below(8)) + ":X" + std::to_string(rng_.below(16));
  }
  /// A system bit: any of %S0..%S40 to read (the runtime's %S0, %S1, %S4..%S7, %S13 too), one
  /// the program may write (%S20..%S40) otherwise.
  std::string systemBit(bool write = false) {
    return "%S" + std::to_string(write ? rng_.range(20, 40) : rng_.range(0, 40));
  }
  std::string timer() { return "%TM" + std::to_string(rng_.below(kTimersUsed)); }
  std::string counter() { return "%C" + std::to_string(rng_.below(kCountersUsed)); }
  /// A function-block output bit (%TMi.Q, %Ci.E / .D / .F).
  std::string blockBit() {
    static const char *const kOut[] = {".E", ".D", ".F"};
    return rng_.chance(50) ? timer() + ".Q" : counter() + kOut[rng_.below(3)];
  }
  /// A function-block word (.V, .P).
  std::string blockWord() {
    return (rng_.chance(50) ? timer() : counter()) + (rng_.chance(50) ? ".V" : ".P");
  }

  /// CONFIG lines for some of the timers and counters the program may use (the others keep
  /// TON, 1 min, 9999); presets small enough to run out within a fuzz run.
  void configure() {
    static const char *const kType[] = {"TON", "TOF", "TP"};
    for (int t = 0; t < kTimersUsed; ++t) {
      if (!rng_.chance(80)) continue;
      static const char *const kTb[] = {"10MS", "10MS", "100MS", "1S", "1MIN"};
      const std::string tb = t < 2 && rng_.chance(50) ? "1MS" : kTb[rng_.below(5)];
      line("CONFIG %TM" + std::to_string(t) + " " + kType[rng_.below(3)] + " TB=" + tb +
           " P=" + std::to_string(rng_.chance(90) ? rng_.below(12) : rng_.below(10000)));
    }
    for (int c = 0; c < kCountersUsed; ++c)
      if (rng_.chance(70))
        line("CONFIG %C" + std::to_string(c) +
             " P=" + std::to_string(rng_.chance(90) ? rng_.below(6) : rng_.below(10000)));
  }

  /// A bit to test: any readable bit; `edge`: %I or %M0..31 only.
  std::string testBit(bool edge) {
    if (edge) return rng_.chance(50) ? input() : memory(true);
    switch (rng_.below(6)) {
    case 0:
    case 1:
      return input();
    case 2:
    case 3:
      return memory(false);
    case 4:
      return rng_.chance(40) ? output() : rng_.chance(50) ? systemBit() : blockBit();
    default:
      return rng_.chance(50)
                 ? wordBit()
                 : "%KW" + std::to_string(rng_.below(4)) + ":X" + std::to_string(rng_.below(16));
    }
  }
  std::string coilBit() {
    switch (rng_.below(5)) {
    case 0:
    case 1:
      return output();
    case 2:
    case 3:
      return memory(false);
    default:
      return rng_.chance(50) ? wordBit() : systemBit(true);
    }
  }
  std::string word() {
    switch (rng_.below(5)) {
    case 0:
      return "%KW" + std::to_string(rng_.below(4));
    case 4:
      return blockWord();
    case 1:
      return std::to_string(rng_.range(-40, 40));
    default:
      return "%MW" + std::to_string(rng_.below(8));
    }
  }
  std::string comparison() {
    static const char *const kRel[] = {"<", "<=", ">", ">=", "=", "<>"};
    return "[" + word() + kRel[rng_.below(6)] + word() + "]";
  }

  /// A first operand with its modifier letter: "" / "N" / "R" / "F" and the operand text.
  std::pair<std::string, std::string> firstOperand(bool immediateOk) {
    const int k = static_cast<int>(rng_.below(10));
    if (k == 0 && immediateOk) return {"", rng_.chance(70) ? "1" : "0"};
    if (k == 1) return {rng_.chance(50) ? "" : "N", comparison()};
    if (k <= 3) return {rng_.chance(50) ? "R" : "F", testBit(true)};
    return {rng_.chance(70) ? "" : "N", testBit(false)};
  }

  void load() {
    auto [mod, op] = firstOperand(true);
    line("LD" + mod + " " + op);
  }

  /// Test instructions at parenthesis depth `depth`.
  void tests(int depth, int n) {
    for (int i = 0; i < n && budget_ > -50; ++i) {
      const int k = static_cast<int>(rng_.below(20));
      if (k < 4 && depth < 8) {
        auto [mod, op] = firstOperand(true);
        line(std::string(rng_.chance(50) ? "AND(" : "OR(") + mod + " " + op);
        tests(depth + 1, static_cast<int>(rng_.below(depth < 3 ? 4 : 2)));
        line(")");
      } else if (k < 6) {
        static const char *const kX[] = {"XOR", "XORN", "XORR", "XORF"};
        const int x = static_cast<int>(rng_.below(4));
        line(std::string(kX[x]) + " " + testBit(x >= 2));
      } else if (k == 6) {
        line("N");
      } else if (k == 7) {
        line(rng_.chance(50) ? "AND 0" : "OR 1");
      } else if (k == 8) {
        line(std::string(rng_.chance(50) ? "AND " : "ANDN ") + comparison());
      } else {
        static const char *const kF[] = {"AND", "OR"};
        static const char *const kM[] = {"", "N", "R", "F"};
        const int m = static_cast<int>(rng_.below(4));
        line(std::string(kF[rng_.below(2)]) + kM[m] + " " + testBit(m >= 2));
      }
    }
  }

  void actions(int sub) {
    const int n = static_cast<int>(rng_.range(1, 3));
    for (int i = 0; i < n; ++i) {
      const int k = static_cast<int>(rng_.below(14));
      if (k < 8) {
        static const char *const kC[] = {"ST", "STN", "S", "R"};
        line(std::string(kC[rng_.below(4)]) + " " + coilBit());
      } else if (k < 10) {
        operation();
      } else if (k == 10 && labels_ < 60) {
        const int l = labels_++;
        pending_.push_back(l);
        line(std::string(rng_.chance(70) ? "JMPC" : "JMPCN") + " %L" + std::to_string(l));
      } else if (k == 11 && sub < 0 && rng_.chance(20)) {
        line(rng_.chance(50) ? "ENDC" : "ENDCN");
      } else if (k == 12 && sub + 1 < subs_) {
        line("SR" + std::to_string(rng_.range(sub + 1, subs_ - 1)));
      } else if (k == 13 && sub >= 0 && rng_.chance(30)) {
        line(rng_.chance(50) ? "RETC" : "RETCN");
      } else if (rng_.chance(40)) {
        directBlock();
      } else {
        line("ST " + output());
      }
    }
  }

  /// An operation block; a preset destination takes a constant 0..9999 or a word.
  void operation() {
    static const char *const kOp[] = {"+", "-", "*", "/"};
    if (rng_.chance(15)) {
      const std::string dst = (rng_.chance(50) ? timer() : counter()) + ".P";
      line("[" + dst + " := " +
           (rng_.chance(50) ? std::to_string(rng_.below(12))
                            : "%MW" + std::to_string(rng_.below(8))) +
           "]");
      return;
    }
    const std::string dst = "%MW" + std::to_string(rng_.below(8));
    if (rng_.chance(40))
      line("[" + dst + " := " + word() + "]");
    else
      line("[" + dst + " := " + word() + kOp[rng_.below(4)] + word() + "]");
  }

  /// The instruction form of a block input: IN %TMi, R / S / CU / CD %Ci.
  void directBlock() {
    static const char *const kPin[] = {"R", "S", "CU", "CD"};
    if (rng_.chance(40))
      line("IN " + timer());
    else
      line(std::string(kPin[rng_.below(4)]) + " " + counter());
  }

  /// Actions allowed in a block's output section (no jumps, calls, END, blocks).
  void blockActions() {
    const int n = static_cast<int>(rng_.range(1, 3));
    for (int i = 0; i < n; ++i) {
      if (rng_.chance(75)) {
        static const char *const kC[] = {"ST", "STN", "S", "R"};
        line(std::string(kC[rng_.below(4)]) + " " + coilBit());
      } else {
        operation();
      }
    }
  }

  /// BLK %TMi / %Ci with its inputs, sometimes an output section with the bare outputs.
  void block() {
    const bool isTimer = rng_.chance(45);
    line("BLK " + (isTimer ? timer() : counter()));
    static const char *const kPin[] = {"R", "S", "CU", "CD"};
    int order[4] = {0, 1, 2, 3};
    const int pins = isTimer ? 1 : static_cast<int>(rng_.range(1, 4));
    for (int i = 3; i > 0; --i)
      std::swap(order[i], order[rng_.below(static_cast<uint64_t>(i) + 1)]);
    for (int p = 0; p < pins; ++p) {
      load();
      tests(0, static_cast<int>(rng_.below(3)));
      line(isTimer ? "IN" : kPin[order[p]]);
    }
    if (rng_.chance(60)) {
      line("OUT_BLK");
      static const char *const kOut[] = {"E", "D", "F"};
      const int outs = static_cast<int>(rng_.range(1, 2));
      for (int o = 0; o < outs; ++o) {
        const std::string bare = isTimer ? "Q" : kOut[rng_.below(3)];
        line((rng_.chance(70) ? "LD " : "LDN ") + (rng_.chance(80) ? bare : testBit(false)));
        tests(0, static_cast<int>(rng_.below(3)));
        blockActions();
      }
    }
    line("END_BLK");
  }

  void placeLabels(bool all) {
    while (!pending_.empty() && (all || rng_.chance(50))) {
      line("%L" + std::to_string(pending_.back()) + " :");
      pending_.pop_back();
    }
  }

  void rung(int sub) {
    if (!pending_.empty() && rng_.chance(30)) placeLabels(false);
    if (rng_.chance(4) && labels_ < 60) {
      const int l = labels_++;
      pending_.push_back(l);
      line("JMP %L" + std::to_string(l));
      placeLabels(false); // sometimes right away: the jumped-over part may be empty
      return;
    }
    if (rng_.chance(8)) {
      block();
      return;
    }
    load();
    tests(0, static_cast<int>(rng_.below(5)));
    if (rng_.chance(25)) {
      // MPS ... MRD ... MPP, nested up to the seed's 8 levels.
      mps(1 + static_cast<int>(rng_.below(rng_.chance(10) ? 8 : 3)), sub);
      return;
    }
    actions(sub);
  }

  void mps(int levels, int sub) {
    line("MPS");
    tests(0, static_cast<int>(rng_.below(3)));
    if (levels > 1)
      mps(levels - 1, sub);
    else
      actions(sub);
    const int reads = static_cast<int>(rng_.below(3));
    for (int r = 0; r < reads; ++r) {
      line("MRD");
      tests(0, static_cast<int>(rng_.below(3)));
      actions(sub);
    }
    line("MPP");
    tests(0, static_cast<int>(rng_.below(3)));
    actions(sub);
  }

  static constexpr int kTimersUsed = 6, kCountersUsed = 4;

  Rng rng_;
  int32_t budget_;
  int subs_ = 0;
  int labels_ = 0;
  std::vector<int> pending_;
  GenProgram prog_;
};

} // namespace

GenProgram generateIl(uint64_t seed, int32_t statements) { return IlGen(seed, statements).run(); }

Stimulus generateIlStimulus(uint64_t seed, uint32_t ticks) {
  Rng rng(seed);
  Stimulus st;
  const TargetProfile *tp = &iec::profile();
  for (int k = 0; k < 4; ++k)
    st.beforeInit.push_back(
        {Area::ConstWords, k, -1, static_cast<int32_t>(rng.range(-40, 40)), tp});
  for (int b = 0; b < 8; ++b)
    st.beforeInit.push_back({Area::Input, b, -1, static_cast<int32_t>(rng.below(256)), tp});
  uint64_t now = 0;
  for (uint32_t t = 0; t < ticks; ++t) {
    std::vector<HostWrite> w;
    const int n = static_cast<int>(rng.below(4));
    for (int i = 0; i < n; ++i) {
      if (rng.chance(10))
        w.push_back({Area::ConstWords, static_cast<int32_t>(rng.below(4)), -1,
                     static_cast<int32_t>(rng.range(-40, 40)), tp});
      else
        w.push_back({Area::Input, rng.chance(70) ? 0 : static_cast<int32_t>(rng.below(8)),
                     static_cast<int8_t>(rng.below(8)), static_cast<int32_t>(rng.below(2)), tp});
    }
    st.writes.push_back(std::move(w));
    now += rng.range(0, 12); // uneven scan times for the timers (never backwards)
    st.nowMs.push_back(now);
  }
  return st;
}

} // namespace lj::gen

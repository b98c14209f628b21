// The benchmark program generator: rungs as a machine builder writes them (interlocks, self
// holding coils, MPS output branches, timers, counters, compares, math, moves), laid out as
// init / PLC1 / PLC2 / subroutines, with an exact statement count.
#include "gen/ProgramGenerator.h"
#include "gen/Rng.h"

#include <array>
#include <string>

namespace lj::gen {

namespace {

using Lines = std::vector<std::string>;

class RealisticGen {
public:
  explicit RealisticGen(const RealisticOptions &o) : o_(o), rng_(o.seed) {}
  GenProgram run();

private:
  // Addresses.
  std::string input();
  std::string coil();
  std::string word(bool writable = true);
  std::string num(int64_t lo, int64_t hi) { return std::to_string(rng_.range(lo, hi)); }

  // Rung templates; each returns complete statements, the number of function-block lines in
  // `fb`.
  Lines bitRung();
  Lines blockRung(int &fb);
  Lines filler(int32_t left);

  /// Emit rungs until exactly `budget` statements are written.
  void part(int32_t budget, int sub);
  void emitAll(const Lines &l) { out_.insert(out_.end(), l.begin(), l.end()); }

  RealisticOptions o_;
  Rng rng_;
  Lines out_;
  std::vector<std::string> recentCoils_; ///< relays read back by later rungs
  int32_t rCursor_ = 0, yCursor_ = 0, gCursor_ = 0;
  int32_t tmrb_ = 0, stmr_ = 0, ctrc_ = 0, ctud_ = 0, blk_[3] = {0, 0, 0};
  int32_t label_ = 0;
  int64_t fbLines_ = 0, allLines_ = 0;
  int32_t subs_ = 0;
};

std::string RealisticGen::input() {
  switch (rng_.weighted(std::array<int, 5>{40, 30, 10, 10, 10})) {
  case 0:
    return "X" + num(0, 63) + "." + num(0, 7);
  case 1:
    if (!recentCoils_.empty()) return recentCoils_[rng_.below(recentCoils_.size())];
    return "R" + num(0, 399) + "." + num(0, 7);
  case 2:
    return "Y" + num(0, 127) + "." + num(0, 7);
  case 3:
    return "F" + num(0, 99) + "." + num(0, 15);
  default:
    return (rng_.chance(50) ? "T" : "C") + num(0, 127) + ".0";
  }
}

std::string RealisticGen::coil() {
  // Fresh bits in turn, so no coil is written twice (double coils are a warning).
  std::string c;
  int k = rng_.weighted(std::array<int, 3>{50, 30, 20});
  if (k == 0) {
    int32_t b = rCursor_++ % (400 * 8);
    c = "R" + std::to_string(b / 8) + "." + std::to_string(b % 8);
    recentCoils_.push_back(c);
    if (recentCoils_.size() > 64) recentCoils_.erase(recentCoils_.begin());
  } else if (k == 1) {
    int32_t b = yCursor_++ % (513 * 8);
    c = "Y" + std::to_string(b / 8) + "." + std::to_string(b % 8);
  } else {
    int32_t b = gCursor_++ % (3120 * 16);
    c = "G" + std::to_string(b / 16) + "." + std::to_string(b % 16);
  }
  return c;
}

std::string RealisticGen::word(bool writable) {
  switch (rng_.below(writable ? 2 : 3)) {
  case 0:
    return "D" + num(0, 79);
  case 1:
    return "W" + num(0, 199);
  default:
    return "F" + num(0, 99);
  }
}

Lines RealisticGen::bitRung() {
  Lines l;
  auto contacts = [&](int lo, int hi) {
    static const char *kOps[] = {"AND ", "ANI ", "AND ", "OR ", "ORI "};
    int n = static_cast<int>(rng_.range(lo, hi));
    for (int i = 0; i < n; ++i) l.push_back(kOps[rng_.below(5)] + input());
  };
  switch (rng_.weighted(std::array<int, 7>{25, 15, 15, 12, 13, 12, 8})) {
  case 0: // interlock chain
    l.push_back((rng_.chance(80) ? "LD " : "LDI ") + input());
    contacts(1, 4);
    l.push_back("OUT " + coil());
    break;
  case 1: { // self-holding coil: start, hold, stop
    std::string c = coil();
    l.push_back("LD " + input());
    l.push_back("OR " + c);
    l.push_back("ANI " + input());
    contacts(0, 2);
    l.push_back("OUT " + c);
    break;
  }
  case 2: // parallel branches
    l.push_back("LD " + input());
    l.push_back("AND " + input());
    l.push_back("LD " + input());
    l.push_back("ANI " + input());
    l.push_back("ORB");
    if (rng_.chance(40)) {
      l.push_back("LD " + input());
      l.push_back("AND " + input());
      l.push_back("ORB");
    }
    l.push_back("AND " + input());
    l.push_back("OUT " + coil());
    break;
  case 3: // series of parallel blocks
    l.push_back("LD " + input());
    l.push_back("OR " + input());
    l.push_back("LD " + input());
    l.push_back("ORI " + input());
    l.push_back("ANB");
    contacts(0, 1);
    l.push_back("OUT " + coil());
    break;
  case 4: // one condition, several outputs
    l.push_back("LD " + input());
    contacts(0, 2);
    l.push_back("MPS");
    l.push_back("AND " + input());
    l.push_back("OUT " + coil());
    if (rng_.chance(60)) {
      l.push_back("MRD");
      l.push_back("ANI " + input());
      l.push_back("OUT " + coil());
    }
    l.push_back("MPP");
    l.push_back("AND " + input());
    l.push_back((rng_.chance(70) ? "OUT " : "SET ") + coil());
    break;
  case 5: { // edge-triggered set / reset pair
    std::string c = coil();
    l.push_back((rng_.chance(50) ? "LDP " : "LD ") + input());
    l.push_back((rng_.chance(50) ? "ANDP " : "AND ") + input());
    l.push_back("SET " + c);
    l.push_back((rng_.chance(50) ? "LDF " : "LD ") + input());
    l.push_back((rng_.chance(30) ? "ORF " : "OR ") + input());
    l.push_back("RST " + c);
    break;
  }
  default: // inverted output
    l.push_back("LD " + input());
    l.push_back((rng_.chance(50) ? "ORP " : "ANI ") + input());
    l.push_back("OOUT " + coil());
    break;
  }
  return l;
}

Lines RealisticGen::blockRung(int &fb) {
  Lines l;
  fb = 1;
  auto len = [&]() { return rng_.chance(70) ? num(10, 5000) : word(); };
  // Timer numbers: TMRB gets T0..T127 and T300..T379, STMR T380..T427, so the two kinds never
  // share a number (an error) and a 10k program rarely reuses one (a warning).
  auto tmrbNo = [&]() {
    int32_t k = tmrb_++ % 208;
    return std::to_string(k < 128 ? k : k - 128 + 300);
  };
  const int kind =
      o_.coreSubset
          ? 4 + static_cast<int>(rng_.weighted(std::array<int, 3>{20, 30, 16}))
          : static_cast<int>(rng_.weighted(std::array<int, 8>{8, 3, 6, 4, 20, 30, 16, 10}));
  switch (kind) {
  case 0:
    l = {"LD " + input(), "AND " + input(), "TMRB " + tmrbNo() + " 0 " + len(), "OUT " + coil()};
    break;
  case 1:
    l = {"LD " + input(),
         "STMR " + std::to_string(380 + stmr_++ % 48) + " " + num(0, 1) + " " +
             (rng_.chance(70) ? num(1, 30) : word()),
         "OUT " + coil()};
    break;
  case 2:
    l = {"LD " + input(), "LD " + input(),
         "CTRC " + std::to_string(ctrc_++ % 128) + " " + num(1, 1000), "OUT " + coil()};
    break;
  case 3:
    l = {"LDP " + input(),
         "LD " + input(),
         "LD " + input(),
         "LD " + input(),
         rng_.chance(50) ? "CTUD " + std::to_string(300 + ctud_++ % 128) + " " + num(1, 500)
                         : "CTR D" + num(80, 99) + " " + num(1, 500),
         "OUT " + coil()};
    break;
  case 4: { // compare into a relay
    static const char *kCmp[] = {"CMP ", "LT ", "COIN "};
    if (rng_.chance(50)) {
      l = {"LD " + input(), kCmp[rng_.below(3)] + word(false) + " " + num(0, 1000),
           "OUT " + coil()};
    } else {
      l = {"LDT", "ACMP " + num(0, 100) + " " + num(200, 3000) + " " + word(false),
           "OUT " + coil()};
    }
    break;
  }
  case 5: { // arithmetic on process words
    static const char *kMath[] = {"ADD ", "SUB ", "MUL ", "WAND ", "WOR ", "WXOR "};
    l = {"LD " + input(), kMath[rng_.below(6)] + word(false) + " " +
                              (rng_.chance(50) ? num(1, 100) : word(false)) + " " + word()};
    if (rng_.chance(30)) l.push_back("DIV " + word(false) + " " + num(1, 60) + " " + word());
    if (rng_.chance(30)) {
      static const char *kUnary[] = {"INC ", "DEC ", "NEG "};
      l.push_back(kUnary[rng_.below(3)] + word());
    }
    fb = static_cast<int>(l.size()) - 1;
    break;
  }
  case 6: // moves
    l = {"LD " + input(), "MOV " + (rng_.chance(50) ? num(0, 30000) : word(false)) + " " + word()};
    break;
  default: { // one-shot and toggle blocks
    static const char *kBlk[] = {"PLS ", "PLF ", "ALT "};
    int k = static_cast<int>(rng_.below(3));
    l = {"LD " + input(), kBlk[k] + std::to_string(blk_[k]++ % 512), "OUT " + coil()};
    break;
  }
  }
  return l;
}

Lines RealisticGen::filler(int32_t left) {
  if (left == 1) return {"MOV " + num(0, 100) + " W" + num(150, 199)};
  if (left == 2) return {"LD " + input(), "OUT " + coil()};
  Lines l{"LD " + input()};
  while (static_cast<int32_t>(l.size()) < left - 1) l.push_back("AND " + input());
  l.push_back("OUT " + coil());
  return l;
}

void RealisticGen::part(int32_t budget, int sub) {
  const int32_t end = static_cast<int32_t>(out_.size()) + budget;
  // PLC2 (sub == -2) calls every subroutine once up front, then now and then; a subroutine
  // calls the next one now and then (nested calls, no recursion).
  if (sub == -2)
    for (int32_t s = 0; s < subs_ && static_cast<int32_t>(out_.size()) + 2 < end; ++s)
      emitAll({"LD " + input(), "CALL S" + std::to_string(10 + s)});
  int32_t jumpEnd = -1, jumpLabel = -1;
  while (static_cast<int32_t>(out_.size()) < end) {
    int32_t left = end - static_cast<int32_t>(out_.size());
    if (jumpEnd >= 0 && (static_cast<int32_t>(out_.size()) >= jumpEnd || left == 1)) {
      out_.push_back("LBL L" + std::to_string(jumpLabel));
      jumpEnd = -1;
      continue;
    }
    Lines l;
    int fb = 0;
    int callee = sub == -2 ? static_cast<int>(rng_.below(std::max(subs_, 1)))
                           : (sub >= 0 && sub + 1 < subs_ ? sub + 1 : -1);
    const bool flow = !o_.coreSubset;
    if (callee >= 0 && subs_ > 0 && rng_.chance(sub == -2 ? 1 : 3)) {
      l = {"LD " + input(), "CALL S" + std::to_string(10 + callee)};
      fb = 1;
    } else if (sub >= 0 && rng_.chance(2)) {
      l = {"LD " + input(), "RETN"};
      fb = 1;
    } else if (flow && jumpEnd < 0 && left > 30 && rng_.chance(2)) {
      jumpLabel = label_++;
      jumpEnd = static_cast<int32_t>(out_.size()) + static_cast<int32_t>(rng_.range(6, 25));
      l = {"LD " + input(), "JMP L" + std::to_string(jumpLabel)};
      fb = 1;
    } else if (fbLines_ * 10 < allLines_ * (o_.coreSubset ? 2 : 3)) {
      l = blockRung(fb);
    } else {
      l = bitRung();
    }
    // The label needs one statement; keep room for it.
    int32_t room = left - (jumpEnd >= 0 ? 1 : 0);
    if (static_cast<int32_t>(l.size()) > room) {
      if (room <= 0) continue;
      l = filler(room);
      fb = room == 1 ? 1 : 0;
    }
    fbLines_ += fb;
    allLines_ += static_cast<int64_t>(l.size());
    emitAll(l);
  }
}

GenProgram RealisticGen::run() {
  const int32_t n = std::max<int32_t>(o_.statements, 40);
  subs_ = o_.coreSubset ? 0 : std::max<int32_t>(0, std::min<int32_t>(o_.subroutines, n / 100));
  int32_t body = n - 3 - 2 * subs_;
  int32_t init = std::max<int32_t>(3, body / 50);
  int32_t subSize = subs_ ? std::max<int32_t>(4, body * 3 / 200) : 0;
  int32_t rest = body - init - subSize * subs_;
  int32_t plc1 = rest / 10;
  int32_t plc2 = rest - plc1;

  // Init: presets and modes a machine builder loads once.
  int32_t initEnd = init;
  while (static_cast<int32_t>(out_.size()) < initEnd) {
    int32_t left = initEnd - static_cast<int32_t>(out_.size());
    if (left >= 2 && rng_.chance(70))
      emitAll({"LDT", "MOV " + num(0, 30000) + " " + word()});
    else
      out_.push_back("MOV " + num(0, 100) + " W" + num(150, 199));
  }
  out_.push_back("IEND");
  part(plc1, -1);
  out_.push_back("1END");
  part(plc2, -2);
  out_.push_back("2END");
  for (int32_t s = 0; s < subs_; ++s) {
    out_.push_back("SP S" + std::to_string(10 + s));
    part(subSize, s);
    out_.push_back("SPE");
  }
  GenProgram p;
  p.lines = std::move(out_);
  p.plc2Nvalue = 200;
  return p;
}

} // namespace

GenProgram generateRealistic(const RealisticOptions &opts) { return RealisticGen(opts).run(); }

} // namespace lj::gen

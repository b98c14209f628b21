// Random rungs of the fanuc-b instructions for the FANUC generator (FanucData.h): XMOVB, DSCHB,
// PARI, SFT, COD, CODB, DCNV, DCNVB, DEC, DECB, COM..COME, JMP..JMPE, NOP, fanuc-d's XMOV and
// DSCH and the rotation control ROT and ROTB, over the same small byte pools as
// gen/FanucProgram.cpp (R0..R11, D0..D11) so they meet the other instructions' bytes, with table
// heads near the end of R as well (the range checks of XMOVB and DSCHB).
#include "gen/FanucData.h"
#include "gen/FanucRung.h"
#include "ir/Bcd.h"

namespace lj::gen {

namespace {

class DataRung : FanucRungBase {
public:
  DataRung(Rng &r, std::vector<std::string> &out) : FanucRungBase(r, out) {}

  void run() {
    switch (pick(0, 17)) {
    case 0:
      inputs(2); // RW, RST, ACT
      xmovb();
      return;
    case 1:
      inputs(1);
      dschb();
      return;
    case 2:
      inputs(2);
      line("PARI " + data(1, false));
      w1();
      return;
    case 3:
      inputs(3);
      line("SFT " + data(2, true));
      w1();
      return;
    case 4:
      inputs(2);
      cod();
      return;
    case 5:
      inputs(1);
      codb();
      return;
    case 6:
      inputs(3);
      line("DCNV " + data(2, false) + " " + data(2, true));
      w1();
      return;
    case 7: {
      inputs(3);
      const int w = width();
      line("DCNVB " + std::to_string(w) + " " + data(w, false) + " " + data(w, true));
      w1();
      return;
    }
    case 8: {
      static const char *dd[] = {"01", "10", "11"};
      const int64_t nn = r_.chance(50) ? pick(0, 9) : pick(0, 99);
      line("DEC " + data(1, false) + " " + (nn < 10 ? "0" : "") + std::to_string(nn) +
           dd[pick(0, 2)]);
      w1();
      return;
    }
    case 9: {
      const int w = width();
      const int nn = static_cast<int>(pick(0, 3));
      const int groups = nn == 0 ? 1 : nn;
      line("DECB 0" + std::string(nn < 10 ? "0" : "") + std::to_string(nn) + std::to_string(w) +
           " " + data(w, false) + " " + std::to_string(pick(-20, 20)) + " " + data(groups, true));
      return;
    }
    case 10:
    case 11:
      region(r_.chance(50));
      return;
    case 12:
      line("NOP");
      coil();
      return;
    case 13: // fanuc-d: XMOV (BYT, RW, RST, ACT)
      inputs(3);
      line("XMOV " + capacity() + " " + table(true) + " " + data(2, true) + " " + data(2, false));
      w1();
      return;
    case 14: // fanuc-d: DSCH (BYT, RST, ACT), a D table only
      inputs(2);
      line("DSCH " + capacity() + " " + table(false) + " " + data(2, false) + " " + data(2, true));
      w1();
      return;
    case 15: // ROT (RN0, BYT, DIR, POS, INC, ACT)
      rot();
      return;
    case 16: // ROTB (RN0, DIR, POS, INC, ACT)
      rotb();
      return;
    default:
      coil();
      return;
    }
  }

private:
  /// A byte address of the pools leaving room for `span` bytes (X too when read-only).
  std::string data(int span, bool writable) {
    if (!writable && r_.chance(20)) {
      const std::string area = r_.chance(70) ? "X" : "F";
      return area + std::to_string(pick(0, 4 - std::min(span, 4)));
    }
    if (span <= 12 && !r_.chance(10))
      return std::string(r_.chance(50) ? "R" : "D") + std::to_string(pick(0, 12 - span));
    return "R" + std::to_string(pick(7990 - span, 8000 - span));
  }
  /// The first input is the caller's logic line; `more` further inputs via RD.STK, ACT last.
  void inputs(int more) {
    for (int k = 0; k < more; ++k)
      line(std::string(r_.chance(70) ? "RD.STK " : "RD.NOT.STK ") + readBit());
  }
  void w1() {
    if (r_.chance(80)) line(std::string(r_.chance(80) ? "WRT " : "WRT.NOT ") + writeBit());
  }
  void coil() {
    static const char *ops[] = {"WRT ", "WRT.NOT ", "SET ", "RST "};
    line(ops[pick(0, 3)] + writeBit());
  }

  /// A BCD table's capacity: small, at the index boundary, or large (fanuc-d).
  std::string capacity() {
    return std::to_string(r_.chance(70) ? pick(1, 12) : r_.chance(50) ? pick(99, 101) : 9999);
  }
  /// A BCD table head: the pools, or near the end of R / D (the range checks); D only for DSCH.
  std::string table(bool anyArea) {
    const bool r = anyArea && r_.chance(50);
    if (r_.chance(80)) return std::string(r ? "R" : "D") + std::to_string(pick(0, 11));
    return r ? "R" + std::to_string(pick(7990, 7999)) : "D" + std::to_string(pick(9990, 9999));
  }
  /// A rotor index count n: small, 8, around the 2-digit boundary, 200 or the largest of ROT.
  int64_t rotorCount() {
    switch (pick(0, 5)) {
    case 0:
      return 8;
    case 1:
      return pick(98, 101);
    case 2:
      return r_.chance(50) ? 200 : 9999;
    default:
      return pick(2, 12);
    }
  }
  /// A position for n positions numbered from 0 or 1 (RN0 is drawn at run time): mostly in
  /// 0..n (often 0..99, the 2-digit ones), sometimes just outside.
  int64_t position(int64_t n) {
    if (r_.chance(80)) return pick(0, r_.chance(30) ? std::min<int64_t>(n, 99) : n);
    return r_.chance(50) ? n + pick(1, 3) : pick(-3, -1);
  }
  /// Current and goal positions; a quarter half a turn apart (a tie with DIR = 1, n even).
  std::pair<int64_t, int64_t> positions(int64_t n) {
    const int64_t c = position(n);
    return {c, r_.chance(25) ? c + n / 2 : position(n)};
  }
  /// ACT of the set-up lines: always on, or a bit that changes between scans.
  void setUp() { line("RD.STK " + (r_.chance(70) ? std::string("R9091.1") : readBit())); }
  /// Back to the caller's line after the set-up (ST depth 1).
  void setUpEnd() { line(r_.chance(50) ? "AND.STK" : "OR.STK"); }
  /// NUMEB writing the low `w` bytes of `v` (as the signed value NUMEB accepts).
  void numeb(int w, int64_t v, const std::string &at) {
    const int shift = 64 - 8 * w;
    v = static_cast<int64_t>(static_cast<uint64_t>(v) << shift) >> shift;
    line("NUMEB " + std::to_string(w) + " " + std::to_string(v) + " " + at);
  }
  /// `v` >= 0 as BCD digits (a digit above 9 for -1: 0x1A, the invalid BCD of the rules).
  static int64_t bcd(int64_t v) {
    return v < 0 ? 0x1A : static_cast<int64_t>(lj::bcd::encode(static_cast<uint64_t>(v), 16));
  }
  /// The `count` operand addresses of a rotation, `w` bytes each, the last one written: one
  /// after the other in R or D, or drawn from a few bytes so that they overlap (n in memory
  /// shared with the positions or the result).
  std::vector<std::string> rotAddresses(int count, int w) {
    std::vector<std::string> a;
    const std::string area = r_.chance(50) ? "R" : "D";
    const bool apart = r_.chance(70);
    const int64_t base = pick(0, 12);
    for (int k = 0; k < count; ++k) {
      if (apart)
        a.push_back(area + std::to_string(base + k * w));
      else
        a.push_back(r_.chance(20) ? data(w, k == count - 1) : area + std::to_string(pick(0, 4)));
    }
    return a;
  }
  void rot() {
    const int64_t n = rotorCount();
    const std::vector<std::string> at = rotAddresses(3, 2);
    const std::string &cur = at[0], &goal = at[1], &out = at[2];
    if (r_.chance(85)) { // BCD positions (or 0x1A) of 1 or 2 bytes
      setUp();
      const auto [c, g] = positions(n);
      for (const auto &[a, v] : {std::pair{&cur, c}, std::pair{&goal, g}}) {
        if (a->front() == 'X' || a->front() == 'F') continue; // inputs: read-only
        const int bytes = r_.chance(50) ? 1 : 2; // one draw per statement: a fixed order
        numeb(bytes, bcd(r_.chance(10) ? -1 : v % 10000), *a);
      }
      setUpEnd();
    }
    inputs(5);
    line(std::string(r_.chance(30) ? "SUB 6 " : "ROT ") + std::to_string(n) + " " + cur + " " +
         goal + " " + out);
    w1();
  }
  void rotb() {
    const int w = width();
    const std::vector<std::string> at = rotAddresses(4, w);
    const std::string &cnt = at[0], &cur = at[1], &goal = at[2], &out = at[3];
    const int64_t lim = w == 1 ? 127 : w == 2 ? 32767 : 2147483647;
    const int64_t n = r_.chance(10) ? pick(-2, 1) : r_.chance(10) ? lim : rotorCount() % (lim + 1);
    if (r_.chance(85)) { // n and the positions (n written on some scans only)
      setUp();
      if (cnt.front() != 'X' && cnt.front() != 'F') numeb(w, n, cnt);
      const auto [c, g] = positions(n < 2 ? 8 : n);
      for (const auto &[a, v] : {std::pair{&cur, c}, std::pair{&goal, g}})
        if (a->front() != 'X' && a->front() != 'F') numeb(w, r_.chance(10) ? lim : v, *a);
      setUpEnd();
    }
    inputs(4);
    line(std::string(r_.chance(30) ? "SUB 26 " : "ROTB ") + std::to_string(w) + " " + cnt + " " +
         cur + " " + goal + " " + out);
    w1();
  }
  void xmovb() {
    const int w = width();
    const int nn = static_cast<int>(r_.chance(50) ? pick(0, 1) : pick(2, 4));
    const int items = nn <= 1 ? 1 : nn;
    line("XMOVB 0" + std::string(nn < 10 ? "0" : "") + std::to_string(nn) + std::to_string(w) +
         " " + data(w, false) + " " + data(w, true) + " " + data(items * w, true) + " " +
         data(w, false));
    w1();
  }
  void dschb() {
    const int w = width();
    line("DSCHB " + std::to_string(w) + " " + data(w, false) + " " + data(w, false) + " " +
         data(w, false) + " " + data(w, true));
    w1();
  }
  void cod() {
    const int64_t n = pick(0, 12);
    std::string s = "COD " + std::to_string(n) + " " + data(1, false) + " " + data(2, true);
    for (int64_t k = 0; k < n; ++k) s += " " + std::to_string(pick(0, 9999));
    line(s);
    w1();
  }
  void codb() {
    const int w = width();
    const int64_t n = r_.chance(80) ? pick(0, 12) : pick(200, 256);
    const int64_t lim = w == 1 ? 127 : w == 2 ? 32767 : 2147483647;
    line("CODB " + std::to_string(w));
    line("(PRM) " + std::to_string(n));
    line("(PRM) " + data(1, false));
    line("(PRM) " + data(w, true));
    for (int64_t k = 0; k < n; ++k) line("(PRM) " + std::to_string(pick(-lim - 1, lim)));
    w1();
  }
  /// COM..COME or JMP..JMPE around 1..3 logic lines with coils (the ACT is the caller's line).
  void region(bool com) {
    line(com ? "COM" : "JMP");
    const int n = static_cast<int>(pick(1, 3));
    for (int k = 0; k < n; ++k) {
      line(std::string(r_.chance(70) ? "RD " : "RD.NOT ") + readBit());
      if (r_.chance(40)) line(std::string(r_.chance(50) ? "AND " : "OR.NOT ") + readBit());
      const int coils = static_cast<int>(pick(1, 2));
      for (int c = 0; c < coils; ++c) coil();
      if (r_.chance(25)) line("MOVB " + data(1, false) + " " + data(1, true));
    }
    line(com ? "COME" : "JMPE");
  }
};

} // namespace

void fanucDataRung(Rng &r, std::vector<std::string> &out) { DataRung(r, out).run(); }

} // namespace lj::gen

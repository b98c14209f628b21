// Random rungs of the fanuc-b instructions for the FANUC generator (FanucData.h): XMOVB, DSCHB,
// PARI, SFT, COD, CODB, DCNV, DCNVB, DEC, DECB, COM..COME, JMP..JMPE, NOP and fanuc-d's XMOV and
// DSCH, over the same small byte pools as gen/FanucProgram.cpp (R0..R11, D0..D11) so they meet the
// other instructions' bytes, with table heads near the end of R as well (the range checks of XMOVB
// and DSCHB).
#include "gen/FanucData.h"
#include "gen/FanucRung.h"

namespace lj::gen {

namespace {

class DataRung : FanucRungBase {
public:
  DataRung(Rng &r, std::vector<std::string> &out) : FanucRungBase(r, out) {}

  void run() {
    switch (pick(0, 15)) {
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
    default:
      coil();
      return;
    }
  }

private:
  /// A byte address of the pools leaving room for `span` bytes (X too when read-only).
  std::string data(int span, bool writable) {
    if (!writable && r_.chance(20)) return "X" + std::to_string(pick(0, 4 - std::min(span, 4)));
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

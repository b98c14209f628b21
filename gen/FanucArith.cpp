// Random rungs of the fanuc-c instructions for the FANUC generator (FanucArith.h): ADDB, SUBB,
// MULB, DIVB, ADD, SUB 20, MUL, DIV, NUMEB, NUME, over the same small byte pools as
// gen/FanucProgram.cpp (R0..R11, D0..D11) plus R9000..R9005 (the flags and the DIVB remainder
// the instructions write), with the operands that reach the error paths: divisors 0, the
// extremes of each width (overflow), BCD bytes with a nibble above 9 and constants too long for
// two digits. A NUME before a BCD instruction often gives it valid BCD operands.
#include "gen/FanucArith.h"
#include "gen/FanucRung.h"

namespace lj::gen {

namespace {

class ArithRung : FanucRungBase {
public:
  ArithRung(Rng &r, std::vector<std::string> &out) : FanucRungBase(r, out) {}

  void run() {
    switch (pick(0, 5)) {
    case 0:
    case 1:
      inputs(1); // RST, ACT
      binary();
      w1();
      return;
    case 2:
    case 3:
      if (r_.chance(50)) { // NUME first: ACT from the caller's line, BYT pushed
        inputs(1);
        line("NUME " + std::to_string(bcdConst()) + " " + data(2, true));
      }
      inputs(2); // BYT, RST, ACT
      bcd();
      w1();
      return;
    case 4: {
      const int w = width();
      line("NUMEB " + std::to_string(w) + " " + konst(w) + " " + data(w, true));
      return;
    }
    default:
      inputs(1);
      line("NUME " + std::to_string(bcdConst()) + " " + data(2, true));
      if (r_.chance(50)) line("WRT " + writeBit());
      return;
    }
  }

private:
  /// A byte address of the pools leaving room for `span` bytes (X too when read-only; the
  /// flags and remainder bytes R9000..R9005 sometimes).
  std::string data(int span, bool writable) {
    if (!writable && r_.chance(20)) {
      const std::string area = r_.chance(70) ? "X" : "F";
      return area + std::to_string(pick(0, 4 - std::min(span, 4)));
    }
    if (r_.chance(8)) return "R" + std::to_string(pick(9000, 9006 - span));
    return std::string(r_.chance(50) ? "R" : "D") + std::to_string(pick(0, 12 - span));
  }
  /// A signed constant of `w` bytes, often 0, +-1 or an extreme (division by zero, overflow).
  std::string konst(int w) {
    const int64_t lim = w == 1 ? 127 : w == 2 ? 32767 : 2147483647;
    switch (pick(0, 5)) {
    case 0:
      return std::to_string(pick(-2, 2));
    case 1:
      return std::to_string(r_.chance(50) ? lim : -lim - 1);
    default:
      return std::to_string(pick(-lim - 1, lim));
    }
  }
  int64_t bcdConst() {
    switch (pick(0, 3)) {
    case 0:
      return pick(0, 9);
    case 1:
      return pick(0, 99);
    default:
      return pick(0, 9999);
    }
  }
  /// The first input is the caller's logic line; `more` further inputs via RD.STK, ACT last.
  void inputs(int more) {
    for (int k = 0; k < more; ++k)
      line(std::string(r_.chance(70) ? "RD.STK " : "RD.NOT.STK ") + readBit());
  }
  void w1() {
    if (r_.chance(80)) line(std::string(r_.chance(80) ? "WRT " : "WRT.NOT ") + writeBit());
  }

  void binary() {
    static const char *names[] = {"ADDB", "SUBB", "MULB", "DIVB"};
    const int w = width();
    const bool addr = r_.chance(50);
    const std::string name = names[pick(0, 3)];
    const std::string head = name + " " + (addr ? "1" : "0") + "00" + std::to_string(w);
    const std::string b = addr ? data(w, false) : konst(w);
    if (r_.chance(30)) { // the SUB form with (PRM) lines
      static const char *subs[] = {"36", "37", "38", "39"};
      line(std::string("SUB ") + subs[name == "ADDB"   ? 0
                                      : name == "SUBB" ? 1
                                      : name == "MULB" ? 2
                                                       : 3]);
      line(std::string("(PRM) ") + (addr ? "1" : "0") + "00" + std::to_string(w));
      line("(PRM) " + data(w, false));
      line("(PRM) " + b);
      line("(PRM) " + data(w, true));
      return;
    }
    line(head + " " + data(w, false) + " " + b + " " + data(w, true));
  }
  void bcd() {
    static const char *subs[] = {"19", "20", "21", "22"};
    static const char *names[] = {"ADD", "SUB 20", "MUL", "DIV"};
    const int k = static_cast<int>(pick(0, 3));
    const bool addr = r_.chance(50);
    const std::string b = addr ? data(2, false) : std::to_string(bcdConst());
    if (k == 1 || r_.chance(30)) { // the SUB n form (the only one of the BCD subtract)
      line(std::string("SUB ") + subs[k]);
      line(std::string("(PRM) ") + (addr ? "1" : "0"));
      line("(PRM) " + data(2, false));
      line("(PRM) " + b);
      line("(PRM) " + data(2, true));
      return;
    }
    line(std::string(names[k]) + " " + (addr ? "1" : "0") + " " + data(2, false) + " " + b + " " +
         data(2, true));
  }
};

} // namespace

void fanucArithRung(Rng &r, std::vector<std::string> &out) { ArithRung(r, out).run(); }

} // namespace lj::gen

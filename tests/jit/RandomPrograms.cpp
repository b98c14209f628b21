// The random program generator: tracks the ST depth it produces so every program verifies.
#include "tests/jit/RandomPrograms.h"

#include <climits>
#include <string>
#include <vector>

namespace lj::test {
namespace {

class Gen {
public:
  Gen(uint64_t seed, int rungs) : r_(seed), rungs_(rungs) {}

  std::string program() {
    nSubs_ = 1 + static_cast<int>(r_.below(4));
    scopeBody(2, 0, -1, false);
    line("IEND");
    depth_ = 0;
    scopeBody(rungs_, 0, -1, false);
    line("1END");
    depth_ = 0;
    scopeBody(rungs_, 0, -1, false);
    line("2END");
    for (int i = 0; i < nSubs_; ++i) {
      line("SP S" + std::to_string(i));
      depth_ = 0;
      scopeBody(3 + static_cast<int>(r_.below(8)), 0, i, true);
      line("SPE");
    }
    return out_;
  }

private:
  void line(const std::string &s) { out_ += s + "\n"; }
  std::string pick(std::initializer_list<const char *> l) {
    return *(l.begin() + r_.below(static_cast<uint32_t>(l.size())));
  }
  std::string num(uint32_t n) { return std::to_string(r_.below(n)); }

  std::string contact() {
    switch (r_.below(12)) {
    case 0:
      return "X" + num(10) + "." + num(8);
    case 1:
      return "Y" + num(10) + "." + num(8);
    case 2:
      return "R" + num(50) + "." + num(8);
    case 3:
      return "F" + num(4) + "." + num(16);
    case 4:
      return "G" + num(4) + "." + num(16);
    case 5:
      return "W" + num(10) + "." + num(16);
    case 6:
      return "D" + num(20) + "." + num(32);
    case 7:
      return "B" + num(10) + "." + num(32);
    case 8:
      return "P" + num(4) + "." + num(32);
    case 9:
      return "T" + std::to_string(r_.chance(80) ? r_.below(16) : 300 + r_.below(4)) + ".0";
    case 10:
      return "C" + std::to_string(r_.chance(80) ? r_.below(16) : 300 + r_.below(4)) + ".0";
    default:
      return "X" + num(3) + "." + num(8);
    }
  }
  std::string coil() {
    switch (r_.below(6)) {
    case 0:
      return "Y" + num(10) + "." + num(8);
    case 1:
      return "W" + num(10) + "." + num(16);
    case 2:
      return "D" + num(20) + "." + num(32);
    case 3:
      return "B" + num(10) + "." + num(32);
    case 4:
      return "G" + num(4) + "." + num(16);
    default:
      return "R" + num(50) + "." + num(8);
    }
  }
  std::string dst() {
    switch (r_.below(6)) {
    case 0:
      return "Y" + num(10);
    case 1:
      return "G" + num(4);
    case 2:
      return "W" + num(10);
    case 3:
      return "D" + num(20);
    case 4:
      return "B" + num(10);
    default:
      return "R" + num(50);
    }
  }
  std::string src() {
    static const int64_t kConsts[] = {0,   1,     -1,     2,     3,         7,         100, 255,
                                      256, 32767, -32768, 65535, INT32_MIN, INT32_MAX, -5};
    switch (r_.below(10)) {
    case 0:
    case 1:
      return std::to_string(kConsts[r_.below(15)]);
    case 2:
      return "X" + num(10);
    case 3:
      return "F" + num(10);
    case 4:
      return "R" + num(60);
    case 5:
      return "W" + num(10);
    case 6:
      return "D" + num(20);
    case 7:
      return "B" + num(10);
    case 8:
      return "P" + num(4);
    default:
      return r_.chance(50) ? "Y" + num(10) : "G" + num(4);
    }
  }

  // Pushes exactly one ST entry.
  void expr(int nest) {
    if (depth_ == 0 && r_.chance(15)) { // a compare on the left rail pushes its output
      compare();
    } else {
      switch (r_.below(6)) {
      case 0:
        line("LDT");
        break;
      case 1:
        line("LDI " + contact());
        break;
      case 2:
        line(pick({"LDP ", "LDF "}) + contact());
        break;
      default:
        line("LD " + contact());
        break;
      }
      ++depth_;
    }
    int ops = static_cast<int>(r_.below(4));
    for (int i = 0; i < ops; ++i) {
      uint32_t k = r_.below(10);
      if (k < 5) {
        line(pick({"AND ", "ANI ", "OR ", "ORI ", "ANDP ", "ANDF ", "ORP ", "ORF "}) + contact());
      } else if (k < 7 && nest < 3) {
        expr(nest + 1);
        line(pick({"ANB", "ORB"}));
        --depth_;
      } else if (k < 9) {
        compare();
      } else {
        line(pick({"PLS ", "PLF "}) + num(16));
      }
    }
  }
  void compare() {
    switch (r_.below(4)) {
    case 0:
      line("CMP " + src() + " " + src());
      break;
    case 1:
      line("LT " + src() + " " + src());
      break;
    case 2:
      line("COIN " + src() + " " + src());
      break;
    default:
      line("ACMP " + src() + " " + src() + " " + src());
      break;
    }
    if (depth_ == 0) depth_ = 1;
  }

  void sink(int sub, bool inSub) {
    switch (r_.below(inSub ? 11 : 10)) {
    case 0:
    case 1:
    case 2: {
      int n = 1 + static_cast<int>(r_.below(3));
      for (int i = 0; i < n; ++i) line(pick({"OUT ", "OUT ", "OOUT ", "SET ", "RST "}) + coil());
      break;
    }
    case 3:
      line("MPS");
      line(pick({"AND ", "ANI "}) + contact());
      line("OUT " + coil());
      line("MRD");
      line(pick({"ORI ", "ANDP "}) + contact());
      line("OUT " + coil());
      line("MPP");
      line("OUT " + coil());
      break;
    case 4: {
      static const char *kBin[] = {"ADD", "SUB", "MUL", "DIV", "WAND", "WOR", "WXOR"};
      if (r_.chance(30))
        line(pick({"INC ", "DEC ", "NEG "}) + dst());
      else
        line(std::string(kBin[r_.below(7)]) + " " + src() + " " + src() + " " + dst());
      if (r_.chance(50)) line("OUT " + coil());
      break;
    }
    case 5:
      line("MOV " + src() + " " + dst());
      if (r_.chance(50)) line("OUT " + coil());
      break;
    case 6: {
      std::string op = pick({"CTR", "CTRC", "CTUD"});
      int k = op == "CTRC" ? 2 : 4;
      for (int i = 1; i < k; ++i) expr(1);
      std::string preset =
          r_.chance(70) ? std::to_string(r_.below(6)) : pick({"R", "W", "D", "B", "P"}) + num(4);
      if (op == "CTR") line("CTR " + pick({"R", "D", "W", "B"}) + num(10) + " " + preset);
      if (op == "CTRC") line("CTRC " + num(8) + " " + preset);
      if (op == "CTUD") line("CTUD " + std::to_string(8 + r_.below(8)) + " " + preset);
      depth_ -= k - 1;
      line("OUT " + coil());
      break;
    }
    case 7: {
      bool on = r_.chance(50);
      int n = static_cast<int>(r_.below(8)) + (on ? 0 : 8);
      std::string t = r_.chance(85) ? std::to_string(n) : std::to_string(300 + r_.below(4));
      if (!on && t.size() == 3) t = std::to_string(8 + r_.below(8)); // T300.. are TMRB only
      std::string len = r_.chance(60) ? std::to_string(r_.below(30)) : "D" + num(20);
      line(std::string(on ? "TMRB " : "STMR ") + t + " " + (r_.chance(90) ? "0" : "1") + " " + len);
      line("OUT " + coil());
      break;
    }
    case 8:
      line(pick({"PLS ", "PLF ", "ALT "}) + num(16));
      line("OUT " + coil());
      break;
    case 9:
      if (sub + 1 < nSubs_) {
        line("CALL S" + std::to_string(sub + 1 + static_cast<int>(r_.below(nSubs_ - sub - 1))));
        if (r_.chance(50)) line("OUT " + coil()); // the caller's ST0 survives the call
      } else {
        line("OUT " + coil());
      }
      break;
    default:
      line("RETN");
      break;
    }
  }

  void scopeBody(int items, int loopNest, int sub, bool inSub) {
    for (int i = 0; i < items; ++i) {
      uint32_t k = r_.below(100);
      if (k < 8 && loopNest < 2) {
        line("LOOP " + (r_.chance(50) ? std::to_string(static_cast<int>(r_.below(5)) - 1)
                                      : "R" + std::to_string(50 + r_.below(10))));
        depth_ = 0;
        scopeBody(1 + static_cast<int>(r_.below(4)), loopNest + 1, sub, inSub);
        line("NEXT");
        depth_ = 0;
      } else if (k < 14) {
        std::string l = "L" + std::to_string(label_++);
        expr(0);
        line("JMP " + l);
        scopeBody(1 + static_cast<int>(r_.below(3)), loopNest, sub, inSub);
        line("LBL " + l);
        depth_ = 0;
      } else if (k < 17 && bound_ < 10) {
        std::string l = "L" + std::to_string(label_++);
        std::string d = "D" + std::to_string(90 + bound_++);
        line("LDT");
        line("MOV 0 " + d);
        line("LBL " + l);
        depth_ = 0;
        scopeBody(1 + static_cast<int>(r_.below(3)), loopNest, sub, inSub);
        line("LDT");
        line("INC " + d);
        line("LT " + d + " " + std::to_string(1 + r_.below(4)));
        line("JMP " + l);
        depth_ += 1;
      } else {
        expr(0);
        sink(sub, inSub);
      }
    }
  }

  Rng r_;
  int rungs_;
  int nSubs_ = 1;
  int depth_ = 0;
  int label_ = 0;
  int bound_ = 0;
  std::string out_;
};

} // namespace

std::string randomProgram(uint64_t seed, int rungs) { return Gen(seed, rungs).program(); }

void randomInputs(uint64_t seed, uint32_t tick, lj_state &s) {
  Rng r(seed * 7919 + tick);
  for (int i = 0; i < 10; ++i) {
    s.img.X[i] = static_cast<uint8_t>(r.next());
    s.img.F[i] = static_cast<int16_t>(r.chance(50) ? r.below(200) - 100 : r.next());
  }
  for (int i = 50; i < 60; ++i) s.img.R[i] = static_cast<uint8_t>(r.below(5));
}

} // namespace lj::test

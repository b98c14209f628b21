// The shape corpus (gen/ShapeCorpus.h): one rung generator per dialect with the knobs each shape
// turns (edge share, nesting depth, MPS fan width, share of data / compare and of timer /
// counter rungs). Everything is in the PLC1 / level-1 / cyclic part, so one full scan runs the
// whole program, as the transpile-to-C toolchains the C baseline imitates run their scan().
#include "gen/ShapeCorpus.h"

#include "gen/Rng.h"

#include <algorithm>
#include <array>

namespace lj::gen {

namespace {

using Lines = std::vector<std::string>;

/// Knobs of the HNC-8 shapes.
struct HncKnobs {
  std::array<int, 4> contact{6, 3, 1, 1}; ///< normal : negated : rising : falling
  int maxNest = 2;                        ///< ANB/ORB block nesting levels
  int nestPct = 35;                       ///< chance a block opens a nested block
  int cmpPct = 20;                        ///< rungs whose condition ends with CMP Dn k
  int dataPct = 25;                       ///< MPS / MOV or ADD / MPP / coil rungs
  int twoBranchPct = 30;                  ///< of the rest: MPS / AND / coil / MPP / AND / coil
  int fanMin = 2, fanMax = 2;             ///< branches of a two-branch rung (MRD between)
  int wordPct = 0;                        ///< word rungs (math, moves, compares)
  int timerPct = 0;                       ///< timer / counter / pulse rungs
};

class HncShape {
public:
  HncShape(const HncKnobs &k, uint64_t seed) : k_(k), rng_(seed) {}

  GenProgram run(int32_t statements) {
    out_.push_back("IEND");
    const int32_t end = statements - 2;
    while (static_cast<int32_t>(out_.size()) < end) {
      Lines r = rung();
      const int32_t room = end - static_cast<int32_t>(out_.size());
      if (static_cast<int32_t>(r.size()) > room) r = filler(room);
      out_.insert(out_.end(), r.begin(), r.end());
    }
    out_.push_back("1END");
    out_.push_back("2END");
    GenProgram p;
    p.lines = std::move(out_);
    return p;
  }

private:
  std::string num(int64_t lo, int64_t hi) { return std::to_string(rng_.range(lo, hi)); }
  std::string bit(const char *area) { return area + num(0, 63) + "." + num(0, 7); }
  std::string contactBit() {
    static const char *kAreas[] = {"X", "X", "R", "Y"};
    return bit(kAreas[rng_.below(4)]);
  }
  std::string coilBit() { return bit(rng_.chance(50) ? "R" : "Y"); }
  std::string dreg() { return "D" + num(0, 99); }

  /// A contact: `form` 0 = LD, 1 = AND, 2 = OR, of a kind drawn with the shape's weights.
  std::string contact(int form) {
    static const char *kForms[3][4] = {{"LD ", "LDI ", "LDP ", "LDF "},
                                       {"AND ", "ANI ", "ANDP ", "ANDF "},
                                       {"OR ", "ORI ", "ORP ", "ORF "}};
    return kForms[form][rng_.weighted(k_.contact)] + contactBit();
  }

  /// A block of 1-4 contacts, which may open nested blocks joined by ANB / ORB.
  void block(Lines &l, int level) {
    l.push_back(contact(0));
    const int n = static_cast<int>(rng_.range(0, 3));
    for (int i = 0; i < n; ++i) l.push_back(contact(rng_.chance(70) ? 1 : 2));
    while (level < k_.maxNest && rng_.chance(k_.nestPct)) {
      block(l, level + 1);
      l.push_back(rng_.chance(50) ? "ANB" : "ORB");
    }
  }

  std::string coil() {
    static const char *kCoils[] = {"OUT ", "OOUT ", "SET ", "RST "};
    return kCoils[rng_.weighted(std::array<int, 4>{6, 1, 2, 2})] + coilBit();
  }

  std::string wordOp() {
    switch (rng_.below(6)) {
    case 0:
      return "MOV " + (rng_.chance(50) ? num(0, 30000) : dreg()) + " " + dreg();
    case 1:
      return "ADD " + dreg() + " " + (rng_.chance(50) ? num(1, 100) : dreg()) + " " + dreg();
    case 2:
      return "SUB " + dreg() + " " + (rng_.chance(50) ? num(1, 100) : dreg()) + " " + dreg();
    case 3:
      return "MUL " + dreg() + " " + num(1, 7) + " " + dreg();
    case 4:
      return (rng_.chance(50) ? "WAND " : "WOR ") + dreg() + " " + num(0, 65535) + " " + dreg();
    default:
      return "INC " + dreg();
    }
  }

  std::string compare() {
    static const char *kCmp[] = {"CMP ", "LT ", "COIN "};
    return kCmp[rng_.below(3)] + dreg() + " " + num(-100, 30000);
  }

  Lines wordRung() {
    Lines l;
    block(l, k_.maxNest); // a plain 1-4 contact condition
    switch (rng_.below(4)) {
    case 0: // compare into a coil
      l.push_back(compare());
      l.push_back(coil());
      break;
    case 1: // a chain of operations under one condition
      for (int i = static_cast<int>(rng_.range(1, 4)); i > 0; --i) l.push_back(wordOp());
      break;
    case 2: // window compare
      l = {"LDT", "ACMP " + num(0, 1000) + " " + num(2000, 30000) + " " + dreg(), coil()};
      break;
    default: // compares in series, then an operation
      l.push_back(compare());
      l.push_back(compare());
      l.push_back(wordOp());
      break;
    }
    return l;
  }

  Lines timerRung() {
    Lines l;
    block(l, k_.maxNest);
    switch (rng_.weighted(std::array<int, 5>{40, 15, 15, 15, 15})) {
    case 0: { // TMRB T0..T127, T300..T379 (208 timers)
      const int32_t t = tmrb_++ % 208;
      l.push_back("TMRB " + std::to_string(t < 128 ? t : t - 128 + 300) + " 0 " +
                  (rng_.chance(70) ? num(10, 3000) : dreg()));
      l.push_back(coil());
      break;
    }
    case 1: // CTRC C0..C127: count, reset
      l.push_back(contact(0));
      l.push_back("CTRC " + std::to_string(ctrc_++ % 128) + " " + num(1, 1000));
      l.push_back(coil());
      break;
    case 2: // CTUD C300..C427: count, s1, down, reset
      l.push_back(contact(0));
      l.push_back(contact(0));
      l.push_back(contact(0));
      l.push_back("CTUD " + std::to_string(300 + ctud_++ % 128) + " " + num(1, 500));
      l.push_back(coil());
      break;
    case 3: // CTR on a register
      l.push_back(contact(0));
      l.push_back(contact(0));
      l.push_back(contact(0));
      l.push_back("CTR D" + num(80, 99) + " " + num(1, 500));
      l.push_back(coil());
      break;
    default: { // PLS / PLF / ALT
      static const char *kBlk[] = {"PLS ", "PLF ", "ALT "};
      const int k = static_cast<int>(rng_.below(3));
      l.push_back(kBlk[k] + std::to_string(blk_[k]++ % 512));
      l.push_back(coil());
      break;
    }
    }
    return l;
  }

  Lines rung() {
    if (rng_.chance(k_.wordPct)) return wordRung();
    if (rng_.chance(k_.timerPct)) return timerRung();
    Lines l;
    block(l, 0);
    if (rng_.chance(k_.cmpPct)) l.push_back("CMP " + dreg() + " " + num(0, 1000));
    if (rng_.chance(k_.dataPct)) {
      l.push_back("MPS");
      l.push_back(rng_.chance(50) ? "MOV " + num(0, 30000) + " " + dreg()
                                  : "ADD " + dreg() + " " + num(1, 100) + " " + dreg());
      l.push_back("MPP");
      l.push_back(coil());
    } else if (rng_.chance(k_.twoBranchPct)) {
      const int n = static_cast<int>(rng_.range(k_.fanMin, k_.fanMax));
      l.push_back("MPS");
      for (int b = 0; b < n; ++b) {
        if (b > 0) l.push_back(b + 1 < n ? "MRD" : "MPP");
        l.push_back(contact(1));
        l.push_back(coil());
      }
    } else {
      l.push_back(coil());
    }
    return l;
  }

  Lines filler(int32_t left) {
    if (left == 1) return {"MOV " + num(0, 100) + " " + dreg()};
    Lines l{"LD " + contactBit()};
    while (static_cast<int32_t>(l.size()) < left - 1) l.push_back("AND " + contactBit());
    l.push_back("OUT " + coilBit());
    return l;
  }

  HncKnobs k_;
  Rng rng_;
  Lines out_;
  int32_t tmrb_ = 0, ctrc_ = 0, ctud_ = 0, blk_[3] = {0, 0, 0};
};

/// FANUC PMC (docs/fanuc-pmc.md): level 1 only; RD / AND / OR with RD.STK and AND.STK /
/// OR.STK, WRT / WRT.NOT / SET / RST, DIFU / DIFD, MOVB / MOVW and the compares on R / D.
GenProgram fanucShape(uint64_t seed, int32_t statements) {
  Rng r(seed);
  Lines out;
  auto num = [&](int64_t lo, int64_t hi) { return std::to_string(r.range(lo, hi)); };
  auto readBit = [&] {
    static const char *kAreas[] = {"X", "X", "R", "Y"};
    return std::string(kAreas[r.below(4)]) + num(0, 63) + "." + num(0, 7);
  };
  auto writeBit = [&] {
    return std::string(r.chance(50) ? "R" : "Y") + num(0, 63) + "." + num(0, 7);
  };
  int edge = 0;
  while (static_cast<int32_t>(out.size()) < statements - 3) {
    out.push_back(std::string(r.chance(75) ? "RD " : "RD.NOT ") + readBit());
    int depth = 1;
    for (int n = static_cast<int>(r.range(0, 5)); n > 0; --n) {
      const int64_t c = r.range(0, 9);
      if (c <= 6) {
        static const char *ops[] = {"AND ", "AND ", "AND.NOT ", "OR ", "OR.NOT "};
        out.push_back(ops[r.below(5)] + readBit());
      } else if (c <= 8 && depth < 3) {
        out.push_back(std::string(r.chance(75) ? "RD.STK " : "RD.NOT.STK ") + readBit());
        ++depth;
      } else if (depth >= 2) {
        out.push_back(r.chance(50) ? "AND.STK" : "OR.STK");
        --depth;
      }
    }
    for (; depth > 1; --depth) out.push_back(r.chance(50) ? "AND.STK" : "OR.STK");
    const int64_t k = r.range(0, 19);
    if (k <= 11) {
      static const char *ops[] = {"WRT ", "WRT ", "WRT ", "WRT.NOT ", "SET ", "RST "};
      for (int n = static_cast<int>(r.range(1, 2)); n > 0; --n)
        out.push_back(ops[r.below(6)] + writeBit());
    } else if (k <= 13 && edge < 1000) { // DIFU 1..1000 / DIFD 1..1000, each once
      ++edge;
      out.push_back(std::string(r.chance(50) ? "DIFU " : "DIFD ") + std::to_string(edge));
      out.push_back("WRT " + writeBit());
    } else if (k <= 16) {
      static const char *mv[] = {"MOVB", "MOVW"};
      const int w = static_cast<int>(r.below(2));
      out.push_back(std::string(mv[w]) + " D" + num(0, 98) + " D" + num(0, 98));
    } else {
      static const char *cmp[] = {"EQ", "GT", "LT", "GE", "LE"};
      const bool word = r.chance(50);
      out.push_back(std::string(cmp[r.below(5)]) + (word ? "W D" : "B D") + num(0, 98) + " " +
                    (word ? num(-1000, 1000) : num(0, 127)));
      out.push_back("WRT " + writeBit());
    }
  }
  out.push_back("END1");
  out.push_back("END2");
  out.push_back("END");
  GenProgram p;
  p.lines = std::move(out);
  return p;
}

/// IEC IL (Neza, docs/iec-il.md): LD / LDN / LDR / LDF, AND / OR with N / R / F and
/// parentheses, MPS / MRD / MPP, ST / STN / S / R, comparisons and operation blocks on %MW.
GenProgram iecShape(uint64_t seed, int32_t statements) {
  Rng r(seed);
  Lines out;
  auto num = [&](int64_t lo, int64_t hi) { return std::to_string(r.range(lo, hi)); };
  auto input = [&] { return "%I" + num(0, 3) + "." + num(0, 15); };
  auto testBit = [&](bool edge) {
    if (!edge && r.chance(25)) return "%Q" + num(0, 3) + "." + num(0, 15);
    if (edge) return r.chance(60) ? input() : "%M" + num(0, 31); // edges: %I, %M0..%M31
    return r.chance(60) ? input() : "%M" + num(0, 127);
  };
  auto coilBit = [&] {
    return r.chance(50) ? "%Q" + num(0, 3) + "." + num(0, 15) : "%M" + num(0, 127);
  };
  auto word = [&] { return "%MW" + num(0, 99); };
  auto mod = [&] { return r.weighted(std::array<int, 4>{6, 3, 1, 1}); };
  static const char *kMod[] = {"", "N", "R", "F"};
  auto test = [&](const char *op) {
    const int m = mod();
    return std::string(op) + kMod[m] + " " + testBit(m >= 2);
  };
  // At most 10,000 instructions in an IEC program (docs/iec-il.md), the closing label and
  // the parentheses counted; stay well below. A rung is at most 12 lines.
  const int32_t limit = std::min<int32_t>(statements, 9500) - 12;
  while (static_cast<int32_t>(out.size()) < limit) {
    if (r.chance(15)) {
      static const char *kRel[] = {"<", "<=", ">", ">=", "=", "<>"};
      out.push_back("LD [" + word() + " " + kRel[r.below(6)] + " " + num(0, 1000) + "]");
    } else {
      out.push_back(test("LD"));
    }
    for (int n = static_cast<int>(r.range(0, 3)); n > 0; --n) {
      if (r.chance(15)) {
        out.push_back(std::string(r.chance(50) ? "AND(" : "OR(") + " " + testBit(false));
        for (int m = static_cast<int>(r.range(1, 2)); m > 0; --m)
          out.push_back(test(r.chance(50) ? "AND" : "OR"));
        out.push_back(")");
      } else {
        out.push_back(test(r.chance(70) ? "AND" : "OR"));
      }
    }
    const int64_t k = r.range(0, 9);
    static const char *kC[] = {"ST ", "ST ", "ST ", "STN ", "S ", "R "};
    if (k <= 5) {
      out.push_back(kC[r.below(6)] + coilBit());
    } else if (k <= 7) {
      out.push_back("MPS");
      out.push_back(test("AND"));
      out.push_back(kC[r.below(6)] + coilBit());
      out.push_back("MPP");
      out.push_back(test("AND"));
      out.push_back(kC[r.below(6)] + coilBit());
    } else {
      static const char *kOp[] = {"+", "-", "+", "*"};
      out.push_back(r.chance(40) ? "[" + word() + " := " + num(0, 30000) + "]"
                                 : "[" + word() + " := " + word() + " " + kOp[r.below(4)] + " " +
                                       num(1, 9) + "]");
    }
  }
  GenProgram p;
  p.lines = std::move(out);
  return p;
}

} // namespace

const std::vector<CorpusShape> &corpusShapes() {
  static const std::vector<CorpusShape> kShapes = {
      {"plc1-mixed", ".stl",
       "PLC1 only: 1-4 contact blocks nested 2 deep, ~18% edges, 20% CMP, 25% MPS/MOV|ADD/MPP"},
      {"edge-heavy", ".stl", "as plc1-mixed with half of the contacts edge-triggered"},
      {"deep-nesting", ".stl", "ANB/ORB blocks nested 5 deep, few data rungs"},
      {"mps-fan", ".stl", "MPS / MRD x 2-10 / MPP output fans"},
      {"word-heavy", ".stl", "~60% data and compare instructions on D registers"},
      {"timer-counter", ".stl", "~45% TMRB / CTRC / CTUD / CTR / PLS / PLF / ALT rungs"},
      {"fanuc", ".pmc",
       "FANUC PMC level 1: RD.STK nesting, WRT/SET/RST, DIFU/DIFD, MOVx, compares"},
      {"iec", ".il", "IEC IL: parentheses, edges, MPS, ST/STN/S/R, comparisons, %MW operations"},
  };
  return kShapes;
}

GenProgram generateShape(const std::string &name, uint64_t seed, int32_t statements) {
  HncKnobs k;
  if (name == "plc1-mixed") {
  } else if (name == "edge-heavy") {
    k.contact = {3, 2, 3, 2};
  } else if (name == "deep-nesting") {
    k.maxNest = 5;
    k.nestPct = 55;
    k.dataPct = 5;
    k.cmpPct = 5;
  } else if (name == "mps-fan") {
    k.dataPct = 5;
    k.twoBranchPct = 85;
    k.fanMin = 2;
    k.fanMax = 10;
  } else if (name == "word-heavy") {
    k.wordPct = 55;
    k.dataPct = 40;
    k.cmpPct = 40;
  } else if (name == "timer-counter") {
    k.timerPct = 60;
    k.dataPct = 10;
  } else if (name == "fanuc") {
    return fanucShape(seed, statements);
  } else if (name == "iec") {
    return iecShape(seed, statements);
  } else {
    return {};
  }
  return HncShape(k, seed).run(statements);
}

} // namespace lj::gen

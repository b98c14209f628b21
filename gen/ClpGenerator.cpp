// Random ClassicLadder projects for the oracle harness: grids built the way ClassicLadder's
// editor places elements (blocks alive at their top-right cell, 99 in their other cells, coils
// and operate blocks in column 9), so `classicladder --nogui` loads every one.
#include "gen/ClpGenerator.h"

#include "gen/Rng.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <vector>

namespace lj::gen {

namespace {

constexpr int kW = 10, kH = 6; // LinuxCNC's rung grid

struct Cell {
  int type = 0, top = 0, vt = 0, vn = 0;
};
using Grid = std::array<std::array<Cell, kH>, kW>; // [x][y]

class ClpGen {
public:
  ClpGen(uint64_t seed, const ClpGenSizes &s, ClpElements e)
      : rng_(seed), sz_(s), logicOnly_(e != ClpElements::All),
        expressions_(e != ClpElements::Logic) {}

  std::string project(int32_t rungs) {
    rungs = std::max(rungs, 1);
    rungs_ = rungs;
    sz_.arithmExpr = std::max(sz_.arithmExpr, 3 * rungs + 1); // at most 3 blocks a rung
    int sections = static_cast<int>(std::min<int64_t>(rng_.range(1, 3), rungs));
    sections = std::min(sections, sz_.sections);
    // rung slots in a shuffled order: execution follows #NEXTRUNG, not the file numbers
    std::vector<int> slots(static_cast<size_t>(rungs));
    for (int i = 0; i < rungs; ++i) slots[static_cast<size_t>(i)] = i;
    for (int i = rungs - 1; i > 0; --i)
      std::swap(slots[static_cast<size_t>(i)], slots[rng_.below(static_cast<uint64_t>(i) + 1)]);
    std::string out = "_FILES_CLASSICLADDER\n";
    std::string sec = "#VER=1.0\n";
    std::string secLines;
    size_t at = 0;
    for (int s = 0; s < sections; ++s) {
      size_t n =
          s + 1 == sections
              ? slots.size() - at
              : static_cast<size_t>(std::max<int64_t>(
                    1, rng_.range(1, static_cast<int64_t>((slots.size() - at) -
                                                          static_cast<size_t>(sections - s - 1)))));
      std::vector<int> chain(slots.begin() + static_cast<long>(at),
                             slots.begin() + static_cast<long>(at + n));
      at += n;
      char name[32];
      std::snprintf(name, sizeof name, "#NAME%03d=Sec%d\n", s, s);
      sec += name;
      char line[64];
      std::snprintf(line, sizeof line, "%03d,0,-1,%d,%d,0\n", s, chain.front(), chain.back());
      secLines += line;
      for (size_t i = 0; i < chain.size(); ++i)
        out += rungFile(chain[i], i ? chain[i - 1] : -1, i + 1 < chain.size() ? chain[i + 1] : -1);
    }
    out += block("sections.csv", sec + secLines);
    out += block("arithmetic_expressions.csv", exprFile());
    out += block("timers.csv", paramFile(sz_.timers, 2));
    out += block("monostables.csv", paramFile(sz_.monostables, 2));
    out += block("counters.csv", counterFile());
    out += block("timers_iec.csv", iecFile());
    out += block("symbols.csv", "#VER=1.0\n%I0,start,start button\n%Q0,lamp,\n%B0,memo,\n");
    out += block("general.txt", general());
    return out + "_/FILES_CLASSICLADDER\n";
  }

private:
  static std::string block(const std::string &name, const std::string &body) {
    return "_FILE-" + name + "\n" + body + "_/FILE-" + name + "\n";
  }

  int idx(int size) { return static_cast<int>(rng_.below(static_cast<uint64_t>(size))); }

  /// A boolean operand for a contact: mostly I/Q/B, sometimes a block output.
  void boolVar(Cell &c) {
    switch (logicOnly_ ? rng_.weighted(std::array<int, 3>{14, 3, 3})
                       : rng_.weighted(std::array<int, 8>{14, 3, 3, 1, 1, 1, 1, 1})) {
    case 0:
      c.vt = 50, c.vn = idx(sz_.inputs);
      break;
    case 1:
      c.vt = 60, c.vn = idx(sz_.outputs);
      break;
    case 2:
      c.vt = 0, c.vn = idx(sz_.bits);
      break;
    case 3:
      c.vt = 10 + static_cast<int>(rng_.below(2)), c.vn = idx(sz_.timers);
      break;
    case 4:
      c.vt = 20, c.vn = idx(sz_.monostables);
      break;
    case 5:
      c.vt = 25 + static_cast<int>(rng_.below(3)), c.vn = idx(sz_.counters);
      break;
    case 6:
      c.vt = 15, c.vn = idx(sz_.timersIec);
      break;
    default:
      c.vt = 50, c.vn = idx(sz_.inputs);
      break;
    }
  }

  void contact(Cell &c) {
    c.type = std::array<int, 4>{1, 2, 3, 4}[rng_.weighted(std::array<int, 4>{7, 3, 1, 1})];
    boolVar(c);
  }

  /// Contacts in columns [0, n) of row y, then connections up to column `to` (exclusive).
  void series(Grid &g, int y, int n, int to) {
    for (int x = 0; x < n && x < to; ++x) contact(g[x][y]);
    for (int x = n; x < to; ++x) g[x][y].type = 9;
  }

  void coil(Cell &c) {
    c.type = 50 + rng_.weighted(std::array<int, 4>{6, 1, 2, 2});
    if (rng_.chance(60))
      c.vt = 60, c.vn = idx(sz_.outputs);
    else
      c.vt = 0, c.vn = idx(sz_.bits);
  }

  /// Contacts, branches closed by vertical links, coils.
  void logicRung(Grid &g) {
    int rows = static_cast<int>(rng_.range(1, 3));
    for (int y = 0; y < rows; ++y) {
      series(g, y, static_cast<int>(rng_.weighted(std::array<int, 4>{0, 5, 3, 1})), 9);
      if (y > 0 && rng_.chance(35)) g[rng_.range(1, 8)][y].top = 1; // an inner OR
      if (y == 0 || rng_.chance(50))
        coil(g[9][y]);
      else
        g[9][y].top = 1; // OR into the coil above
    }
  }

  /// A 2x2 block (old timer, monostable, IEC timer) with its alive cell at (x, 0).
  void smallBlockRung(Grid &g) {
    int kind = rng_.weighted(std::array<int, 3>{3, 2, 3});
    int x = static_cast<int>(rng_.range(2, 6));
    Cell &a = g[x][0];
    a.type = kind == 0 ? 10 : kind == 1 ? 11 : 13;
    a.vn = idx(kind == 0 ? sz_.timers : kind == 1 ? sz_.monostables : sz_.timersIec);
    g[x - 1][0].type = g[x - 1][1].type = g[x][1].type = 99;
    series(g, 0, static_cast<int>(rng_.range(1, x - 1)), x - 1);
    if (kind == 0) {
      // the old timer's C input: usually wired to E by a link on its lower-left cell
      if (rng_.chance(75))
        g[x - 1][1].top = 1;
      else
        series(g, 1, static_cast<int>(rng_.range(1, x - 1)), x - 1);
      for (int c = x + 1; c < 9; ++c) g[c][1].type = 9;
      coil(g[9][1]);
    }
    for (int c = x + 1; c < 9; ++c) g[c][0].type = 9;
    coil(g[9][0]);
  }

  /// A counter (2x4) at rows 0..3: inputs R, P, U, D; outputs E, D, F.
  void counterRung(Grid &g) {
    int x = static_cast<int>(rng_.range(2, 5));
    g[x][0].type = 12;
    g[x][0].vn = idx(sz_.counters);
    for (int y = 0; y < 4; ++y) {
      g[x - 1][y].type = 99;
      if (y) g[x][y].type = 99;
      // R and P rarely powered, U and D often (edges count)
      if (rng_.chance(y < 2 ? 40 : 85)) {
        g[0][y].type = rng_.chance(80) ? 1 : 2;
        g[0][y].vt = 50;
        g[0][y].vn = idx(sz_.inputs);
        for (int c = 1; c < x - 1; ++c) g[c][y].type = 9;
      }
    }
    for (int y = 0; y < 3; ++y) {
      if (!rng_.chance(70)) continue;
      for (int c = x + 1; c < 9; ++c) g[c][y].type = 9;
      coil(g[9][y]);
    }
  }

  void compareRung(Grid &g) {
    int rows = static_cast<int>(rng_.range(1, 2));
    for (int y = 0; y < rows; ++y) {
      int x = static_cast<int>(rng_.range(2, 6));
      g[x][y].type = 20;
      g[x][y].vn = newExpr(true);
      g[x - 1][y].type = g[x - 2][y].type = 99;
      if (x > 2) series(g, y, static_cast<int>(rng_.range(0, x - 2)), x - 2);
      for (int c = x + 1; c < 9; ++c) g[c][y].type = 9;
      coil(g[9][y]);
    }
  }

  void operateRung(Grid &g) {
    int rows = static_cast<int>(rng_.range(1, 3));
    for (int y = 0; y < rows; ++y) {
      series(g, y, static_cast<int>(rng_.range(1, 3)), 7);
      if (rng_.chance(40)) g[0][y].type = 3; // a rising edge: one-shot
      g[7][y].type = g[8][y].type = 99;
      g[9][y].type = 60;
      g[9][y].vn = newExpr(false);
    }
  }

  std::string rungFile(int n, int prev, int next) {
    Grid g{};
    switch (!logicOnly_     ? rng_.weighted(std::array<int, 5>{5, 3, 1, 2, 2})
            : !expressions_ ? 0
                            : rng_.weighted(std::array<int, 5>{5, 0, 0, 2, 2})) {
    case 0:
      logicRung(g);
      break;
    case 1:
      smallBlockRung(g);
      break;
    case 2:
      counterRung(g);
      break;
    case 3:
      compareRung(g);
      break;
    default:
      operateRung(g);
      break;
    }
    std::string body = "#VER=2.0\n#LABEL=R" + std::to_string(n) + "\n#COMMENT=generated\n" +
                       "#PREVRUNG=" + std::to_string(prev) + "\n#NEXTRUNG=" + std::to_string(next) +
                       "\n";
    for (int y = 0; y < kH; ++y) {
      for (int x = 0; x < kW; ++x) {
        const Cell &c = g[x][y];
        body += std::to_string(c.type) + "-" + std::to_string(c.top) + "-" + std::to_string(c.vt) +
                "/" + std::to_string(c.vn) + (x + 1 < kW ? " , " : "\n");
      }
    }
    return block("rung_" + std::to_string(n) + ".csv", body);
  }

  std::string var() {
    switch (logicOnly_ ? rng_.weighted(std::array<int, 9>{5, 5, 2, 2, 0, 0, 0, 1, 2})
                       : rng_.weighted(std::array<int, 9>{5, 5, 2, 2, 1, 1, 1, 1, 2})) {
    case 0:
      return "@200/" + std::to_string(idx(sz_.words)) + "@";
    case 1:
      return "@270/" + std::to_string(idx(sz_.s32in)) + "@";
    case 2:
      return "@280/" + std::to_string(idx(sz_.s32out)) + "@";
    case 3:
      return "@300/" + std::to_string(idx(sz_.floatIn)) + "@";
    case 4:
      return "@251/" + std::to_string(idx(sz_.counters)) + "@";
    case 5:
      return "@261/" + std::to_string(idx(sz_.timersIec)) + "@";
    case 6:
      return "@231/" + std::to_string(idx(sz_.timers)) + "@";
    case 7:
      return "@50/" + std::to_string(idx(sz_.inputs)) + "@";
    default:
      return "@0/" + std::to_string(idx(sz_.bits)) + "@";
    }
  }

  std::string term(int depth) {
    switch (rng_.weighted(std::array<int, 7>{4, 6, 1, 1, 1, 1, depth > 0 ? 2 : 0})) {
    case 0:
      return std::to_string(rng_.range(0, 100));
    case 1:
      return var();
    case 2:
      return "-" + std::to_string(rng_.range(1, 9));
    case 3:
      return "$" + std::string(1, "0123456789ABCDEF"[rng_.below(16)]) + "F";
    case 4:
      return "!" + var();
    case 5: {
      const char *f[] = {"ABS", "MINI", "MAXI", "MOY"};
      int k = static_cast<int>(rng_.below(4));
      return std::string(f[k]) + "(" + var() + (k ? "," + var() : "") + ")";
    }
    default:
      return "(" + expr(depth - 1) + ")";
    }
  }

  std::string expr(int depth) {
    std::string e = term(depth);
    int ops = static_cast<int>(rng_.range(0, 2));
    for (int i = 0; i < ops; ++i) {
      switch (rng_.below(8)) {
      case 0:
        e += "+" + term(depth);
        break;
      case 1:
        e += "-" + term(depth);
        break;
      case 2:
        e += "*" + term(depth);
        break;
      case 3:
        e += "&" + term(depth);
        break;
      case 4:
        e += "|" + term(depth);
        break;
      case 5:
        e += "/" + std::to_string(rng_.range(1, 9));
        break; // never INT_MIN / -1
      case 6:
        e += "%" + std::to_string(rng_.range(1, 9));
        break;
      default:
        e += "^" + std::to_string(rng_.range(0, 2));
        break; // a^(2^b)
      }
    }
    return e;
  }

  /// A new expression slot: a comparison or an assignment of at most 49 characters.
  int newExpr(bool compare) {
    static const char *ops[] = {">", "<", "=", ">=", "<=", "<>"};
    std::string t;
    for (int tries = 0; tries < 20; ++tries) {
      if (compare)
        t = expr(1) + ops[rng_.below(6)] + expr(1);
      else {
        int k = rng_.weighted(std::array<int, 3>{3, 4, 1});
        std::string target = k == 0   ? "@200/" + std::to_string(idx(sz_.words)) + "@"
                             : k == 1 ? "@280/" + std::to_string(idx(sz_.s32out)) + "@"
                                      : "@310/" + std::to_string(idx(sz_.floatOut)) + "@";
        t = target + ":=" + expr(1);
      }
      if (t.size() <= 49) break;
      t = compare ? var() + ops[rng_.below(6)] + std::to_string(rng_.range(0, 20))
                  : "@200/0@:=@200/0@+1";
    }
    int n = static_cast<int>(exprs_.size());
    exprs_.push_back(t);
    return n;
  }

  std::string exprFile() {
    std::string s = "#VER=2.0\n";
    for (size_t i = 0; i < exprs_.size(); ++i) {
      char head[32];
      std::snprintf(head, sizeof head, "%04zu,", i);
      s += head + exprs_[i] + "\n";
    }
    return s;
  }

  /// `base,preset` lines: 100 ms or 1 s bases, presets that run out in under ~3 s.
  std::string paramFile(int n, int) {
    std::string s;
    for (int i = 0; i < n; ++i) {
      if (rng_.chance(80))
        s += "2," + std::to_string(rng_.range(1, 25)) + "\n";
      else
        s += "1," + std::to_string(rng_.range(1, 3)) + "\n";
    }
    return s;
  }

  std::string counterFile() {
    std::string s;
    for (int i = 0; i < sz_.counters; ++i) s += std::to_string(rng_.range(0, 8)) + "\n";
    return s;
  }

  std::string iecFile() {
    std::string s;
    for (int i = 0; i < sz_.timersIec; ++i) {
      std::string base = rng_.chance(85) ? "2," + std::to_string(rng_.range(0, 12))
                                         : "1," + std::to_string(rng_.range(1, 2));
      s += base + "," + std::to_string(rng_.below(3)) + "\n";
    }
    return s;
  }

  std::string general() {
    auto kv = [](const char *k, int v) { return std::string(k) + "=" + std::to_string(v) + "\n"; };
    return kv("PERIODIC_REFRESH", 1) + kv("SIZE_NBR_RUNGS", rungs_) +
           kv("SIZE_NBR_BITS", sz_.bits) + kv("SIZE_NBR_WORDS", sz_.words) +
           kv("SIZE_NBR_TIMERS", sz_.timers) + kv("SIZE_NBR_MONOSTABLES", sz_.monostables) +
           kv("SIZE_NBR_COUNTERS", sz_.counters) + kv("SIZE_NBR_TIMERS_IEC", sz_.timersIec) +
           kv("SIZE_NBR_PHYS_INPUTS", sz_.inputs) + kv("SIZE_NBR_PHYS_OUTPUTS", sz_.outputs) +
           kv("SIZE_NBR_ARITHM_EXPR", sz_.arithmExpr) + kv("SIZE_NBR_SECTIONS", sz_.sections);
  }

  Rng rng_;
  ClpGenSizes sz_;
  std::vector<std::string> exprs_;
  int rungs_ = 1;
  bool logicOnly_ = false;  ///< contacts and coils on %I %Q %B only
  bool expressions_ = true; ///< compare and operate rungs
};

} // namespace

std::string generateClp(uint64_t seed, int32_t rungs, const ClpGenSizes &sizes,
                        ClpElements elements) {
  return ClpGen(seed, sizes, elements).project(rungs);
}

} // namespace lj::gen

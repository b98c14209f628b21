// The ClassicLadder project reader (files.c, files_project.c, files_sequential.c of LinuxCNC
// 2.9 as the reference describes them), strict where ClassicLadder would run garbage and
// located: every error names the project file, the line, the embedded file and, in a rung, the
// rung, row and column.
#include "frontends/classicladder/Reader.h"

#include <algorithm>
#include <cstdlib>
#include <dirent.h>
#include <fstream>
#include <set>
#include <sstream>
#include <sys/stat.h>

namespace lj::classicladder {

namespace {

constexpr size_t kMaxLine = 299;     // fgets(..., 300): a longer line is split by ClassicLadder
constexpr int32_t kMaxIndex = 99999; // bound on rung, block and expression numbers

bool endsWith(const std::string &s, const char *suffix) {
  size_t n = std::char_traits<char>::length(suffix);
  return s.size() >= n && s.compare(s.size() - n, n, suffix) == 0;
}

std::string trim(std::string_view s) {
  size_t b = 0, e = s.size();
  while (b < e && (s[b] == ' ' || s[b] == '\t')) ++b;
  while (e > b && (s[e - 1] == ' ' || s[e - 1] == '\t')) --e;
  return std::string(s.substr(b, e - b));
}

/// A whole decimal integer (optional sign, surrounding blanks), bounded to +-99,999,999.
bool toInt(std::string_view text, int32_t &out) {
  std::string t = trim(text);
  if (t.empty()) return false;
  size_t i = 0;
  bool neg = false;
  if (t[0] == '-' || t[0] == '+') {
    neg = t[0] == '-';
    i = 1;
  }
  if (i >= t.size() || t.size() - i > 8) return false;
  int32_t v = 0;
  for (; i < t.size(); ++i) {
    if (t[i] < '0' || t[i] > '9') return false;
    v = v * 10 + (t[i] - '0');
  }
  out = neg ? -v : v;
  return true;
}

std::vector<std::string> splitCommas(const std::string &line) {
  std::vector<std::string> out;
  size_t start = 0;
  for (;;) {
    size_t c = line.find(',', start);
    out.push_back(line.substr(start, c == std::string::npos ? std::string::npos : c - start));
    if (c == std::string::npos) break;
    start = c + 1;
  }
  return out;
}

/// Builds located errors for one project.
class Reader {
public:
  Reader(const std::string &path, Flavor flavor) { project_.path = path, project_.flavor = flavor; }

  Status error(const ProjectFile &f, size_t line, const std::string &where,
               const std::string &msg) const {
    ErrorLoc loc;
    loc.file = project_.path;
    loc.line = line < f.lineNumbers.size() ? f.lineNumbers[line] : 0;
    loc.col = 1;
    std::string text = project_.path;
    if (loc.line) text += ":" + std::to_string(loc.line);
    text += ": error: " + f.name + (where.empty() ? "" : " " + where) + ": " + msg;
    return Status::error(ErrorCode::BadFormat, text, loc);
  }

  Result<Project> run(const std::vector<ProjectFile> &files) {
    std::set<std::string> seen;
    for (const auto &f : files) {
      if (!seen.insert(f.name).second)
        return error(f, 0, "", "the file appears twice in the project");
      project_.files.push_back(f.name);
    }
    // general.txt first: the sizes bound the block numbers of the rungs.
    for (const auto &f : files)
      if (f.name == "general.txt") general(f);
    for (const auto &f : files) {
      Status s;
      if (f.name == "timers.csv")
        s = timerParams(f, project_.timers, false);
      else if (f.name == "monostables.csv")
        s = timerParams(f, project_.monostables, false);
      else if (f.name == "timers_iec.csv")
        s = timerIecParams(f);
      else if (f.name == "counters.csv")
        s = counterParams(f);
      else if (f.name == "arithmetic_expressions.csv")
        s = expressions(f);
      else if (f.name == "symbols.csv")
        symbols(f);
      else if (f.name == "sequential.csv")
        s = sequential(f);
      if (!s.ok()) return s;
    }
    for (const auto &f : files) {
      int32_t n = 0;
      if (f.name.rfind("rung_", 0) == 0 && endsWith(f.name, ".csv") &&
          toInt(std::string_view(f.name).substr(5, f.name.size() - 9), n)) {
        if (n < 0 || n > kMaxIndex) return error(f, 0, "", "rung number out of range");
        Status s = rung(f, n);
        if (!s.ok()) return s;
      }
    }
    const ProjectFile *sections = nullptr;
    for (const auto &f : files)
      if (f.name == "sections.csv") sections = &f;
    Status s = sections ? sectionsFile(*sections) : sectionsV1();
    if (!s.ok()) return s;
    for (const auto &[n, r] : project_.rungs) {
      (void)n;
      Status c = crossCheck(r);
      if (!c.ok()) return c;
    }
    return std::move(project_);
  }

private:
  void general(const ProjectFile &f) {
    struct Key {
      const char *name;
      int32_t Sizes::*field;
    };
    static const Key keys[] = {{"SIZE_NBR_RUNGS", &Sizes::rungs},
                               {"SIZE_NBR_BITS", &Sizes::bits},
                               {"SIZE_NBR_WORDS", &Sizes::words},
                               {"SIZE_NBR_TIMERS", &Sizes::timers},
                               {"SIZE_NBR_MONOSTABLES", &Sizes::monostables},
                               {"SIZE_NBR_COUNTERS", &Sizes::counters},
                               {"SIZE_NBR_TIMERS_IEC", &Sizes::timersIec},
                               {"SIZE_NBR_PHYS_INPUTS", &Sizes::physInputs},
                               {"SIZE_NBR_PHYS_OUTPUTS", &Sizes::physOutputs},
                               {"SIZE_NBR_ARITHM_EXPR", &Sizes::arithmExpr},
                               {"SIZE_NBR_SECTIONS", &Sizes::sections},
                               {"SIZE_NBR_SYMBOLS", &Sizes::symbols},
                               {"SIZE_NBR_PHYS_WORDS_INPUTS", &Sizes::s32in},
                               {"SIZE_NBR_PHYS_WORDS_OUTPUTS", &Sizes::s32out}};
    for (const auto &l : f.lines) {
      size_t eq = l.find('=');
      if (l.empty() || l[0] == '#' || l[0] == ';' || eq == std::string::npos) continue;
      std::string k = l.substr(0, eq), v = l.substr(eq + 1);
      project_.general[k] = v;
      int32_t n = 0;
      if (!toInt(v, n) || n <= 0 || n > kMaxIndex) continue;
      if (k == "PERIODIC_REFRESH") project_.periodMs = n;
      for (const auto &key : keys)
        if (k == key.name) project_.sizes.*key.field = n;
    }
  }

  /// Data lines of a parameter file: not `;`/`#`, not empty; 0.9 prefixes them with `T0,`.
  static bool dataLine(const std::string &l, std::string &data) {
    if (l.empty() || l[0] == ';' || l[0] == '#') return false;
    data = l;
    if ((data[0] >= 'A' && data[0] <= 'Z') || (data[0] >= 'a' && data[0] <= 'z')) {
      size_t c = data.find(',');
      data = c == std::string::npos ? "" : data.substr(c + 1);
    }
    return !trim(data).empty();
  }

  bool baseMs(int32_t id, int32_t &ms) {
    switch (id) {
    case 0:
      ms = 60000;
      return true;
    case 1:
      ms = 1000;
      return true;
    case 2:
      ms = 100;
      return true;
    default:
      return false;
    }
  }

  Status timerParams(const ProjectFile &f, std::vector<TimerParams> &out, bool) {
    for (size_t i = 0; i < f.lines.size(); ++i) {
      std::string d;
      if (!dataLine(f.lines[i], d)) continue;
      auto v = splitCommas(d);
      TimerParams t;
      int32_t base = 0;
      if (v.size() < 2 || !toInt(v[0], base) || !toInt(v[1], t.preset))
        return error(f, i, "line '" + f.lines[i] + "'", "expected 'base,preset'");
      if (!baseMs(base, t.baseMs))
        return error(f, i, "line '" + f.lines[i] + "'",
                     "time base " + std::to_string(base) + " (0 = minute, 1 = second, 2 = 100 ms)");
      if (t.preset < 0) return error(f, i, "line '" + f.lines[i] + "'", "negative preset");
      out.push_back(t);
    }
    return {};
  }

  Status timerIecParams(const ProjectFile &f) {
    for (size_t i = 0; i < f.lines.size(); ++i) {
      std::string d;
      if (!dataLine(f.lines[i], d)) continue;
      auto v = splitCommas(d);
      TimerIecParams t;
      int32_t base = 0, mode = 0;
      if (v.size() < 3 || !toInt(v[0], base) || !toInt(v[1], t.preset) || !toInt(v[2], mode))
        return error(f, i, "line '" + f.lines[i] + "'", "expected 'base,preset,mode'");
      if (!baseMs(base, t.baseMs))
        return error(f, i, "line '" + f.lines[i] + "'",
                     "time base " + std::to_string(base) + " (0 = minute, 1 = second, 2 = 100 ms)");
      if (mode < 0 || mode > 2)
        return error(f, i, "line '" + f.lines[i] + "'",
                     "timer mode " + std::to_string(mode) + " (0 = TON, 1 = TOF, 2 = TP)");
      if (t.preset < 0) return error(f, i, "line '" + f.lines[i] + "'", "negative preset");
      t.mode = static_cast<IecMode>(mode);
      project_.timersIec.push_back(t);
    }
    return {};
  }

  Status counterParams(const ProjectFile &f) {
    for (size_t i = 0; i < f.lines.size(); ++i) {
      std::string d;
      if (!dataLine(f.lines[i], d)) continue;
      int32_t p = 0;
      if (!toInt(splitCommas(d)[0], p))
        return error(f, i, "line '" + f.lines[i] + "'", "expected a counter preset");
      project_.counterPresets.push_back(p);
    }
    return {};
  }

  Status expressions(const ProjectFile &f) {
    int32_t next = 0;
    ExprDialect dialect =
        project_.flavor == Flavor::LinuxCnc ? ExprDialect::LinuxCnc29 : ExprDialect::Upstream09;
    for (size_t i = 0; i < f.lines.size(); ++i) {
      const std::string &l = f.lines[i];
      if (l.empty() || l[0] == ';' || l[0] == '#') continue;
      int32_t index = next;
      std::string text = l;
      if (l[0] >= '0' && l[0] <= '9') {
        // LoadArithmeticExpr: index = atoi(line), the text at offset 5 ("NNNN,")
        if (l.size() < 5 || l[4] != ',' || !toInt(l.substr(0, 4), index))
          return error(f, i, "line '" + l + "'", "expected 'NNNN,expression' (four digits)");
        text = l.substr(5);
      }
      next = index + 1;
      if (text.size() > 49) {
        project_.warnings.push_back(f.name + " expression " + std::to_string(index) +
                                    ": cut to 49 characters as ClassicLadder stores it");
        text.resize(49);
      }
      ArithExpr a;
      a.index = index;
      a.line = i < f.lineNumbers.size() ? f.lineNumbers[i] : 0;
      ExprError err;
      if (!parseExpression(text, dialect, a.expr, err)) {
        // Reported when a compare or operate block uses the slot (crossCheck).
        badExpr_[index] = {err.offset, err.message};
        badExprFile_[index] = {&f, i};
      } else if (!a.expr.ignored.empty()) {
        project_.warnings.push_back(f.name + " expression " + std::to_string(index) + " '" + text +
                                    "': ClassicLadder ignores '" + a.expr.ignored + "'");
      }
      project_.expressions[index] = std::move(a);
    }
    return {};
  }

  void symbols(const ProjectFile &f) {
    for (const auto &l : f.lines) {
      if (l.empty() || l[0] == ';' || l[0] == '#') continue;
      auto v = splitCommas(l);
      Symbol s;
      s.varName = trim(v[0]);
      s.var = parseVarName(s.varName);
      // ConvRawLineOfStringsOrNumbers leaves a field longer than its limit empty.
      if (v.size() > 1 && v[1].size() <= 9) s.symbol = v[1];
      std::string comment;
      for (size_t k = 2; k < v.size(); ++k) comment += (k > 2 ? "," : "") + v[k];
      if (comment.size() <= 49) s.comment = comment;
      project_.symbols.push_back(std::move(s));
    }
  }

  Status sequential(const ProjectFile &f) {
    auto &seq = project_.sequential;
    for (size_t i = 0; i < f.lines.size(); ++i) {
      const std::string &l = f.lines[i];
      if (l.empty() || l[0] == ';' || l[0] == '#') continue;
      auto bad = [&](const std::string &msg) { return error(f, i, "line '" + l + "'", msg); };
      char kind = l[0];
      auto v = splitCommas(l.substr(1));
      std::vector<int32_t> n;
      if (kind == 'S' || kind == 'T') {
        for (const auto &x : v) {
          int32_t k = 0;
          if (!toInt(x, k)) return bad("expected numbers");
          n.push_back(k);
        }
      }
      if (kind == 'S') {
        if (n.size() != 6 || n[0] < 0 || n[0] > 127)
          return bad("expected 'S<slot 0..127>,init,stepnumber,page,x,y'");
        Step s{n[0], n[1] != 0, n[2], n[3], n[4], n[5]};
        seq.steps.push_back(s);
      } else if (kind == 'T') {
        if (n.size() != 44 || n[0] < 0 || n[0] > 255)
          return bad("expected 'T<slot 0..255>,' then 40 step/transition numbers and page,x,y");
        Transition t;
        t.slot = n[0];
        auto list = [&](int from, std::vector<int32_t> &out) {
          for (int k = 0; k < 10; ++k)
            if (n[1 + from + k] >= 0) out.push_back(n[1 + from + k]);
        };
        list(0, t.activate);
        list(10, t.deactivate);
        list(20, t.linkedStart);
        list(30, t.linkedEnd);
        for (int32_t s : t.activate)
          if (s > 127) return bad("step slot " + std::to_string(s) + " (0..127)");
        for (int32_t s : t.deactivate)
          if (s > 127) return bad("step slot " + std::to_string(s) + " (0..127)");
        t.page = n[41];
        t.x = n[42];
        t.y = n[43];
        seq.transitions.push_back(std::move(t));
      } else if (kind == 'C') {
        // "C<idx>,0,<vartype>/<varnum>": the loader skips to the first comma, then 3 characters
        int32_t slot = 0;
        size_t c = l.find(',');
        size_t slash = l.find('/', c == std::string::npos ? 0 : c);
        VarRef var;
        if (c == std::string::npos || c + 3 > l.size() || slash == std::string::npos ||
            !toInt(l.substr(1, c - 1), slot) || !toInt(l.substr(c + 3, slash - c - 3), var.type) ||
            !toInt(l.substr(slash + 1), var.num))
          return bad("expected 'C<transition>,0,<vartype>/<varnum>'");
        auto it = std::find_if(seq.transitions.begin(), seq.transitions.end(),
                               [&](const Transition &t) { return t.slot == slot; });
        if (it == seq.transitions.end())
          return bad("condition of transition " + std::to_string(slot) + ", which is not defined");
        if (!knownVar(var.type, project_.flavor))
          return bad("unknown variable type " + std::to_string(var.type));
        it->condition = var;
      } else if (kind == 'P') {
        continue; // 0.9: a page title (display only)
      } else if (kind == 'N') {
        SeqComment cm;
        if (v.size() < 4 || !toInt(v[0], cm.slot) || !toInt(v[1], cm.page) || !toInt(v[2], cm.x) ||
            !toInt(v[3], cm.y))
          return bad("expected 'N<idx>,page,x,y,text'");
        for (size_t k = 4; k < v.size(); ++k) cm.text += (k > 4 ? "," : "") + v[k];
        seq.comments.push_back(std::move(cm));
      } else {
        return bad("unknown sequential line (S step, T transition, C condition, N comment)");
      }
    }
    return {};
  }

  /// `Type-ConnectedWithTop-VarType/VarNum` with an optional `[IdxType/IdxNum]`.
  static bool parseCell(const std::string &text, Cell &c, std::string &why) {
    std::string t = trim(text);
    size_t p = 0;
    auto num = [&](int32_t &out, bool sign) {
      size_t b = p;
      if (sign && p < t.size() && t[p] == '-') ++p;
      while (p < t.size() && t[p] >= '0' && t[p] <= '9') ++p;
      return p > b && toInt(std::string_view(t).substr(b, p - b), out);
    };
    auto lit = [&](char ch) {
      if (p < t.size() && t[p] == ch) {
        ++p;
        return true;
      }
      return false;
    };
    int32_t type = 0, top = 0;
    if (!num(type, false) || !lit('-') || !num(top, false) || !lit('-') || !num(c.varType, false) ||
        !lit('/') || !num(c.varNum, true)) {
      why = "expected 'type-top-vartype/varnum'";
      return false;
    }
    if (lit('[')) {
      if (!num(c.indexType, false) || !lit('/') || !num(c.indexNum, false) || !lit(']')) {
        why = "expected '[vartype/varnum]' after the operand";
        return false;
      }
    }
    if (p != t.size()) {
      why = "unexpected '" + t.substr(p) + "'";
      return false;
    }
    if (top != 0 && top != 1) {
      why = "the vertical-link field is " + std::to_string(top) + " (0 or 1)";
      return false;
    }
    c.type = static_cast<int16_t>(type > 32000 ? 32000 : type);
    c.connectedWithTop = top == 1;
    return true;
  }

  static std::string cellWhere(int32_t rung, int y, int x) {
    return "rung " + std::to_string(rung) + " row " + std::to_string(y) + " column " +
           std::to_string(x);
  }

  Status rung(const ProjectFile &f, int32_t index) {
    const int width = rungWidth(project_.flavor), height = rungHeight(project_.flavor);
    Rung r;
    r.index = index;
    r.cells.assign(width, std::vector<Cell>(height));
    r.linesUsed = height;
    int y = 0;
    for (size_t i = 0; i < f.lines.size(); ++i) {
      const std::string &l = f.lines[i];
      if (l.empty() || l[0] == ';') continue;
      std::string where = "rung " + std::to_string(index);
      if (l[0] == '#') {
        auto val = [&](const char *key) { return l.substr(std::char_traits<char>::length(key)); };
        int32_t n = 0;
        if (l.rfind("#VER=", 0) == 0) {
          double ver = std::atof(val("#VER=").c_str());
          r.version = static_cast<int32_t>(ver);
          if (ver > 2 && project_.flavor == Flavor::LinuxCnc)
            return error(f, i, where,
                         "#VER=" + val("#VER=") +
                             " is a ClassicLadder 0.9 rung (12x8 grid), which LinuxCNC does not "
                             "read; save the project as a .clprj or with LinuxCNC's editor");
        } else if (l.rfind("#LABEL=", 0) == 0) {
          r.label = val("#LABEL=").substr(0, 9);
        } else if (l.rfind("#COMMENT=", 0) == 0) {
          r.comment = val("#COMMENT=").substr(0, 29);
        } else if (l.rfind("#COMMENT_LONG=", 0) == 0) {
          r.comment = val("#COMMENT_LONG=");
        } else if (l.rfind("#PREVRUNG=", 0) == 0 || l.rfind("#NEXTRUNG=", 0) == 0) {
          bool next = l[1] == 'N';
          if (!toInt(val("#PREVRUNG="), n) || n < -1 || n > kMaxIndex)
            return error(f, i, where, "bad rung number in '" + l + "'");
          (next ? r.nextRung : r.prevRung) = n;
        } else if (l.rfind("#NBRLINES=", 0) == 0) {
          if (!toInt(val("#NBRLINES="), n) || n < 0 || n > height)
            return error(f, i, where, "bad line count in '" + l + "'");
          r.linesUsed = n;
        }
        continue;
      }
      if (y >= height)
        return error(f, i, where,
                     "more than " + std::to_string(height) + " rows (a rung is " +
                         std::to_string(width) + "x" + std::to_string(height) + ")");
      auto cells = splitCommas(l);
      r.rowLines.push_back(i < f.lineNumbers.size() ? f.lineNumbers[i] : 0);
      if (static_cast<int>(cells.size()) != width)
        return error(f, i, where + " row " + std::to_string(y),
                     std::to_string(cells.size()) + " cells (a row has " + std::to_string(width) +
                         ")");
      for (int x = 0; x < width; ++x) {
        Cell &c = r.cells[x][y];
        std::string why;
        if (!parseCell(cells[x], c, why))
          return error(f, i, cellWhere(index, y, x), "bad cell '" + trim(cells[x]) + "': " + why);
        if (!knownElement(c.type, project_.flavor))
          return error(f, i, cellWhere(index, y, x),
                       "unknown element type " + std::to_string(c.type) + " in '" + trim(cells[x]) +
                           "'");
        if (c.indexType >= 0 && project_.flavor == Flavor::LinuxCnc)
          project_.warnings.push_back(f.name + " " + cellWhere(index, y, x) +
                                      ": indexed operand in '" + trim(cells[x]) +
                                      "': LinuxCNC master adds the index, 2.9 (atoi) ignores it");
        cellLines_[{index, x, y}] = {&f, i};
      }
      ++y;
    }
    project_.rungs[index] = std::move(r);
    return {};
  }

  /// The checks that need every file: operands, block numbers and placement, expressions used
  /// by blocks, jump targets.
  Status crossCheck(const Rung &r) {
    const int width = static_cast<int>(r.cells.size());
    const int height = width ? static_cast<int>(r.cells[0].size()) : 0;
    const Sizes &sz = project_.sizes;
    for (int x = 0; x < width; ++x) {
      for (int y = 0; y < height; ++y) {
        const Cell &c = r.cells[x][y];
        auto at = cellLines_.find({r.index, x, y});
        if (at == cellLines_.end()) continue; // a row the file does not have: empty
        const ProjectFile &f = *at->second.first;
        size_t line = at->second.second;
        auto bad = [&](const std::string &msg) {
          return error(f, line, cellWhere(r.index, y, x),
                       std::string(elementName(c.type)) + ": " + msg);
        };
        int t = c.type;
        bool operand = (t >= 1 && t <= 4) || (t >= 50 && t <= 53);
        if (operand) {
          if (!knownVar(c.varType, project_.flavor))
            return bad("unknown variable type " + std::to_string(c.varType));
          if (c.varNum < 0 || c.varNum > kMaxIndex)
            return bad("variable number " + std::to_string(c.varNum));
          noteVar(c.varType, c.varNum);
          continue;
        }
        int w = 1, h = 1;
        elementSize(t, w, h);
        if (x - (w - 1) < 0 || y + h > height)
          return bad(std::to_string(w) + "x" + std::to_string(h) +
                     " block does not fit the grid at this cell (its top-right cell)");
        auto number = [&](int32_t limit, int32_t Sizes::*need, const char *what) -> Status {
          if (c.varNum < 0 || c.varNum > kMaxIndex)
            return bad(std::string(what) + " number " + std::to_string(c.varNum));
          project_.needed.*need = std::max(project_.needed.*need, c.varNum + 1);
          if (c.varNum >= limit)
            warn(r.index, x, y,
                 std::string(what) + " " + std::to_string(c.varNum) + " is beyond the " +
                     std::to_string(limit) + " of general.txt");
          return {};
        };
        Status s;
        switch (t) {
        case 10:
          s = number(sz.timers, &Sizes::timers, "timer");
          break;
        case 11:
          s = number(sz.monostables, &Sizes::monostables, "monostable");
          break;
        case 12:
          s = number(sz.counters, &Sizes::counters, "counter");
          break;
        case 13:
          s = number(sz.timersIec, &Sizes::timersIec, "IEC timer");
          break;
        case 20:
        case 60: {
          s = number(sz.arithmExpr, &Sizes::arithmExpr, "expression");
          if (!s.ok()) break;
          auto bx = badExpr_.find(c.varNum);
          if (bx != badExpr_.end()) {
            auto [ef, el] = badExprFile_[c.varNum];
            const ArithExpr &a = project_.expressions[c.varNum];
            return error(*ef, el,
                         "expression " + std::to_string(c.varNum) + " (used by the " +
                             elementName(t) + " at " + cellWhere(r.index, y, x) + ")",
                         "'" + a.expr.text + "' column " + std::to_string(bx->second.first + 1) +
                             ": " + bx->second.second);
          }
          const ArithExpr *a = project_.expression(c.varNum);
          if (a && a->expr.isCompare) {
            noteExpr(*a->expr.left);
            noteExpr(*a->expr.right);
          }
          if (a && a->expr.isOperate && t == 60) {
            noteVar(a->expr.target.type, a->expr.target.num);
            noteExpr(*a->expr.value);
          }
          if (t == 60 && a && !a->expr.empty && !a->expr.isOperate)
            return bad("expression " + std::to_string(c.varNum) + " '" + a->expr.text +
                       "' is not an assignment '@var@:=...'");
          if (t == 20 && a && !a->expr.empty && !a->expr.isCompare)
            return bad("expression " + std::to_string(c.varNum) + " '" + a->expr.text +
                       "' is not a comparison");
          break;
        }
        case 54:
          if (!project_.rungs.count(c.varNum))
            return bad("jump to rung " + std::to_string(c.varNum) +
                       ", which the project does not have");
          break;
        case 55:
          if (c.varNum < 0 || c.varNum > kMaxIndex)
            return bad("sub-routine number " + std::to_string(c.varNum));
          break;
        default:
          break;
        }
        if (!s.ok()) return s;
      }
    }
    return {};
  }

  void warn(int32_t rung, int x, int y, const std::string &msg) {
    project_.warnings.push_back(cellWhere(rung, y, x) + ": " + msg);
  }

  /// Records the sizes a variable needs (bits, I/O, words, floats).
  void noteVar(int32_t type, int32_t num) {
    Sizes &n = project_.needed;
    auto need = [&](int32_t Sizes::*f) { n.*f = std::max(n.*f, num + 1); };
    switch (type) {
    case 0:
      need(&Sizes::bits);
      break;
    case 50:
      need(&Sizes::physInputs);
      break;
    case 60:
      need(&Sizes::physOutputs);
      break;
    case 200:
      need(&Sizes::words);
      break;
    case 270:
      need(&Sizes::s32in);
      break;
    case 280:
      need(&Sizes::s32out);
      break;
    case 300:
      if (project_.flavor == Flavor::LinuxCnc) need(&Sizes::floatIn);
      break;
    case 310:
      need(&Sizes::floatOut);
      break;
    case 10:
    case 11:
    case 230:
    case 231:
      need(&Sizes::timers);
      break;
    case 20:
    case 240:
    case 241:
      need(&Sizes::monostables);
      break;
    case 25:
    case 26:
    case 27:
    case 250:
    case 251:
      need(&Sizes::counters);
      break;
    case 15:
    case 260:
    case 261:
      need(&Sizes::timersIec);
      break;
    default:
      break;
    }
  }

  /// The variables of an expression tree.
  void noteExpr(const ExprNode &e) {
    if (e.kind == ExprNode::Kind::Var) noteVar(e.var.type, e.var.num);
    for (const auto &k : e.kids) noteExpr(*k);
  }

  /// FirstRung .. NextRung .. LastRung over the rungs the project has, without a cycle.
  bool chain(Section &s, std::string &why) {
    std::set<int32_t> seen;
    int32_t r = s.firstRung;
    for (;;) {
      auto it = project_.rungs.find(r);
      if (it == project_.rungs.end()) {
        why = "its chain reaches rung " + std::to_string(r) + ", which the project does not have";
        return false;
      }
      if (!seen.insert(r).second) {
        why = "its chain loops back to rung " + std::to_string(r) + " before its last rung " +
              std::to_string(s.lastRung);
        return false;
      }
      s.order.push_back(r);
      if (r == s.lastRung) return true;
      r = it->second.nextRung;
      if (r == -1) {
        why = "its chain ends (#NEXTRUNG=-1) before its last rung " + std::to_string(s.lastRung);
        return false;
      }
    }
  }

  Status sectionsFile(const ProjectFile &f) {
    project_.hasSectionsFile = true;
    std::map<int32_t, std::string> names;
    for (size_t i = 0; i < f.lines.size(); ++i) {
      const std::string &l = f.lines[i];
      if (l.rfind("#NAME", 0) == 0) {
        int32_t n = 0;
        if (l.size() < 9 || l[8] != '=' || !toInt(l.substr(5, 3), n))
          return error(f, i, "line '" + l + "'", "expected '#NAMEnnn=name' (three digits)");
        names[n] = l.substr(9);
        continue;
      }
      if (l.empty() || l[0] == '#' || l[0] == ';') continue;
      auto v = splitCommas(l);
      int32_t n[6];
      bool ok = v.size() == 6;
      for (size_t k = 0; ok && k < 6; ++k) ok = toInt(v[k], n[k]);
      if (!ok)
        return error(f, i, "line '" + l + "'",
                     "expected 'number,language,subroutine,firstrung,lastrung,page'");
      Section s;
      s.number = n[0];
      if (n[1] != 0 && n[1] != 1)
        return error(f, i, "section " + std::to_string(n[0]),
                     "language " + std::to_string(n[1]) + " (0 = ladder, 1 = sequential)");
      s.language = static_cast<Language>(n[1]);
      s.subRoutine = n[2];
      s.firstRung = n[3];
      s.lastRung = n[4];
      s.sequentialPage = n[5];
      if (s.number < 0 || s.number > kMaxIndex || s.subRoutine < -1 || s.subRoutine > kMaxIndex)
        return error(f, i, "section " + std::to_string(n[0]), "number out of range");
      for (const auto &o : project_.sections)
        if (o.number == s.number)
          return error(f, i, "section " + std::to_string(n[0]), "defined twice");
      if (s.language == Language::Ladder) {
        std::string why;
        if (!chain(s, why)) return error(f, i, "section " + std::to_string(n[0]), why);
      } else if (s.sequentialPage < 0 || s.sequentialPage > 4) {
        return error(f, i, "section " + std::to_string(n[0]),
                     "sequential page " + std::to_string(s.sequentialPage) + " (0..4)");
      }
      project_.sections.push_back(std::move(s));
    }
    for (auto &s : project_.sections) {
      auto it = names.find(s.number);
      if (it != names.end()) s.name = it->second;
    }
    return {};
  }

  /// No sections.csv ("V1"): every rung in numeric order, one main section.
  Status sectionsV1() {
    if (project_.rungs.empty()) return {};
    Section s;
    s.name = "Prog1";
    s.firstRung = project_.rungs.begin()->first;
    s.lastRung = project_.rungs.rbegin()->first;
    for (const auto &[n, r] : project_.rungs) {
      (void)r;
      s.order.push_back(n);
    }
    project_.sections.push_back(std::move(s));
    return {};
  }

  Project project_;
  std::map<std::tuple<int32_t, int, int>, std::pair<const ProjectFile *, size_t>> cellLines_;
  std::map<int32_t, std::pair<int32_t, std::string>> badExpr_;
  std::map<int32_t, std::pair<const ProjectFile *, size_t>> badExprFile_;
};

Flavor flavorOf(const std::string &path) {
  return endsWith(path, ".clprj") ? Flavor::Upstream09 : Flavor::LinuxCnc;
}

/// Lines of `text` with CR/LF stripped; an error for a line ClassicLadder would split.
Status lines(std::string_view text, const std::string &path, std::vector<std::string> &out) {
  size_t start = 0;
  while (start < text.size()) {
    size_t nl = text.find('\n', start);
    size_t end = nl == std::string_view::npos ? text.size() : nl;
    std::string_view l = text.substr(start, end - start);
    while (!l.empty() && (l.back() == '\r')) l.remove_suffix(1);
    if (l.size() > kMaxLine) {
      ErrorLoc loc{path, static_cast<int32_t>(out.size() + 1), 1};
      return Status::error(ErrorCode::BadFormat,
                           path + ":" + std::to_string(loc.line) +
                               ": error: a line of more than 299 characters (ClassicLadder reads "
                               "lines of at most 299)",
                           loc);
    }
    if (l.find('\0') != std::string_view::npos) {
      ErrorLoc loc{path, static_cast<int32_t>(out.size() + 1), 1};
      return Status::error(ErrorCode::BadFormat,
                           path + ":" + std::to_string(loc.line) + ": error: a NUL byte in a line",
                           loc);
    }
    out.emplace_back(l);
    if (nl == std::string_view::npos) break;
    start = nl + 1;
  }
  return {};
}

Result<std::string> slurp(const std::string &path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return Status::error(ErrorCode::NotFound, path + ": error: cannot open the file");
  std::string data;
  char buf[65536];
  while (in.read(buf, sizeof buf) || in.gcount() > 0) {
    data.append(buf, static_cast<size_t>(in.gcount()));
    if (data.size() > kMaxProjectBytes)
      return Status::error(ErrorCode::BadFormat, path + ": error: larger than " +
                                                     std::to_string(kMaxProjectBytes >> 20) +
                                                     " MiB");
  }
  return data;
}

} // namespace

Result<std::vector<ProjectFile>> splitContainer(std::string_view text, const std::string &path) {
  std::vector<std::string> all;
  Status s = lines(text, path, all);
  if (!s.ok()) return s;
  auto fail = [&](size_t line, const std::string &msg) {
    ErrorLoc loc{path, static_cast<int32_t>(line + 1), 1};
    return Status::error(ErrorCode::BadFormat,
                         path + ":" + std::to_string(line + 1) + ": error: " + msg, loc);
  };
  if (all.empty() || all[0].rfind("_FILES_CLASSICLADDER", 0) != 0)
    return fail(0, "not a ClassicLadder project: the first line is not _FILES_CLASSICLADDER");
  std::vector<ProjectFile> files;
  ProjectFile *open = nullptr;
  size_t openLine = 0;
  for (size_t i = 1; i < all.size(); ++i) {
    const std::string &l = all[i];
    if (l.rfind("_/FILES_CLASSICLADDER", 0) == 0) {
      if (open) return fail(openLine, "the block _FILE-" + open->name + " is not closed");
      break;
    }
    if (l.rfind("_/FILE-", 0) == 0) {
      if (!open) return fail(i, "'" + l + "' closes no block");
      if (std::all_of(open->lines.begin(), open->lines.end(),
                      [](const std::string &x) { return x.empty(); }))
        return fail(openLine, "the block _FILE-" + open->name +
                                  " is empty (ClassicLadder would read the next block into it)");
      open = nullptr;
      continue;
    }
    if (l.rfind("_FILE-", 0) == 0) {
      if (open) return fail(openLine, "the block _FILE-" + open->name + " is not closed");
      std::string name = l.substr(6);
      if (name.empty() || name.find('/') != std::string::npos || name == "." || name == "..")
        return fail(i, "bad embedded file name '" + name + "'");
      files.push_back({name, {}, {}});
      open = &files.back();
      openLine = i;
      continue;
    }
    if (open) {
      open->lines.push_back(l);
      open->lineNumbers.push_back(static_cast<int32_t>(i + 1));
    } else if (!l.empty()) {
      return fail(i, "text outside a _FILE- block");
    }
  }
  if (open) return fail(openLine, "the block _FILE-" + open->name + " is not closed");
  return files;
}

Result<Project> readProjectFiles(const std::vector<ProjectFile> &files, const std::string &path,
                                 Flavor flavor) {
  return Reader(path, flavor).run(files);
}

Result<Project> readProjectText(std::string_view text, const std::string &path) {
  if (text.size() > kMaxProjectBytes)
    return Status::error(ErrorCode::BadFormat, path + ": error: larger than 16 MiB");
  auto files = splitContainer(text, path);
  if (!files.ok()) return files.status();
  return readProjectFiles(*files, path, flavorOf(path));
}

Result<Project> readProject(const std::string &path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0)
    return Status::error(ErrorCode::NotFound, path + ": error: no such file or folder");
  if (!S_ISDIR(st.st_mode)) {
    if (!endsWith(path, ".clp") && !endsWith(path, ".clprj"))
      return Status::error(ErrorCode::InvalidArgument,
                           path + ": error: a ClassicLadder project is a .clp or .clprj file or a "
                                  "folder of its files");
    auto text = slurp(path);
    if (!text.ok()) return text.status();
    return readProjectText(*text, path);
  }
  // A project folder: the same files, each read whole.
  std::vector<std::string> names;
  if (DIR *d = ::opendir(path.c_str())) {
    while (dirent *e = ::readdir(d)) {
      std::string n = e->d_name;
      if (endsWith(n, ".csv") || endsWith(n, ".txt")) names.push_back(n);
    }
    ::closedir(d);
  } else {
    return Status::error(ErrorCode::NotFound, path + ": error: cannot read the folder");
  }
  std::sort(names.begin(), names.end());
  std::vector<ProjectFile> files;
  size_t total = 0;
  for (const auto &n : names) {
    std::string full = path + "/" + n;
    auto text = slurp(full);
    if (!text.ok()) return text.status();
    total += text->size();
    if (total > kMaxProjectBytes)
      return Status::error(ErrorCode::BadFormat, path + ": error: larger than 16 MiB");
    ProjectFile f;
    f.name = n;
    Status s = lines(*text, full, f.lines);
    if (!s.ok()) return s;
    for (size_t i = 0; i < f.lines.size(); ++i)
      f.lineNumbers.push_back(static_cast<int32_t>(i + 1));
    files.push_back(std::move(f));
  }
  if (files.empty())
    return Status::error(ErrorCode::NotFound,
                         path + ": error: the folder holds no ClassicLadder project files");
  return readProjectFiles(files, path, Flavor::LinuxCnc);
}

} // namespace lj::classicladder

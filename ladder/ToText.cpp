// Networks -> program text in their dialect (docs/ladder-json.md "Other dialects"): the runs of
// rungs the networks leave unchanged are copied from the program text they were made from, byte
// for byte (comments, spelling, blank lines, order); the others are printed by the dialect's
// DialectText::printStmts. The front end then reads the result as any program file, with all
// its checks, and the verifier runs on it: networks edited in a JSON are a program.
#include "ladder/Json.h"

#include <algorithm>
#include <cstdlib>
#include <unordered_map>

namespace lj::ladder {

namespace {

bool sameElement(const Element &a, const Element &b) {
  return a.op == b.op && a.operands == b.operands && a.symbols == b.symbols && a.id == b.id &&
         a.before == b.before && a.hasComment == b.hasComment && a.comment == b.comment &&
         a.role == b.role && a.written == b.written && a.lead == b.lead;
}

/// A run of whole source lines holding whole rungs: statements [begin, end) of the program,
/// lines [from, to) (1-based) of its text.
struct Group {
  size_t begin = 0, end = 0;
  int32_t from = 0, to = 0;
};

/// The groups of `src`: a rung starts a new group where its first line (its comment block's, a
/// line that made no statement written before it, or its first statement's) comes after every
/// line of the rungs before it.
std::vector<Group> groupsOf(const VerifiedProgram &src, int32_t lineCount, int32_t &tailFrom) {
  const size_t n = src.stmts.size();
  // headLine[k]: the first line before statement k that goes with it (INT32_MAX: none).
  std::vector<int32_t> headLine(n + 1, INT32_MAX);
  auto goesWith = [&](int32_t stmt, int32_t line, size_t count) {
    if (stmt >= 0 && static_cast<size_t>(stmt) < count)
      headLine[static_cast<size_t>(stmt)] = std::min(headLine[static_cast<size_t>(stmt)], line);
  };
  for (const Comment &c : src.comments)
    if (!c.trailing) goesWith(c.stmt, c.line, n + 1); // n: the comment block after the last
  // A line that made no statement (FANUC COME) starts the rung whose first instruction it went
  // with: deleting or printing anew the rung before keeps it.
  for (const WrittenInstr &w : src.written)
    if (w.line > 0) goesWith(w.first, w.line, n);
  std::vector<Group> out;
  int32_t lastLine = 0; // the last line of any statement so far
  for (const RungRange &r : src.rungs) {
    if (r.range.empty()) continue;
    const auto b = static_cast<size_t>(r.range.begin);
    const int32_t first = std::min(headLine[b], src.stmts[b].loc.line);
    if (out.empty() || first > lastLine) {
      if (!out.empty()) out.back().to = first;
      out.push_back({b, b, first, first});
    }
    out.back().end = static_cast<size_t>(r.range.end);
    for (auto i = b; i < static_cast<size_t>(r.range.end); ++i)
      lastLine = std::max(lastLine, src.stmts[i].loc.line);
  }
  // The tail: the comment block after the last statement, and whatever follows.
  tailFrom = headLine[n] != INT32_MAX && headLine[n] > lastLine ? headLine[n] : lastLine + 1;
  tailFrom = std::min(tailFrom, lineCount + 1);
  if (!out.empty()) out.back().to = tailFrom;
  return out;
}

} // namespace

StmtText stmtTextOf(const Element &e) {
  StmtText t;
  t.op = e.op;
  t.instr = e.drawnWhole ? std::string() : e.drawn;
  for (size_t k = 0; k < e.operands.size(); ++k)
    t.operands.push_back(k < e.symbols.size() && !e.symbols[k].empty() ? e.symbols[k]
                                                                       : e.operands[k]);
  t.implied = e.implied;
  t.before = e.before;
  t.comment = e.comment;
  t.hasComment = e.hasComment;
  t.role = e.role;
  t.written = e.written;
  return t;
}

bool programText(const Networks &given, const VerifiedProgram &src, std::string_view srcText,
                 std::string &out, std::string &error, bool printAll,
                 std::vector<LineOrigin> *origins) {
  const DialectText *d = given.text ? given.text : src.dialect;
  const bool prints = d && d->printStmts;
  Networks made = fromProgram(src);
  std::vector<Element> a, b;
  std::vector<std::string> where;
  const bool stated = toStatements(given, a, error, &where) && toStatements(made, b, error);
  if (prints && !stated) return false;
  // The source's lines, each with its line break.
  std::vector<std::string_view> lines;
  for (size_t p = 0; p < srcText.size();) {
    size_t nl = srcText.find('\n', p);
    size_t e = nl == std::string_view::npos ? srcText.size() : nl + 1;
    lines.push_back(srcText.substr(p, e - p));
    p = e;
  }
  if (!prints) {
    // A dialect that prints no text (ClassicLadder: its source is its editor's grid): networks
    // that are the source's own, unchanged, read back as the source itself.
    if (stated && std::equal(a.begin(), a.end(), b.begin(), b.end(), sameElement)) {
      out.assign(srcText);
      if (origins) origins->assign(lines.size(), LineOrigin{});
      return true;
    }
    error = "the " + given.dialect +
            " dialect prints no program text: its network JSON reads back only unchanged (edit "
            "the program in its own editor)";
    return false;
  }
  auto count = static_cast<int32_t>(lines.size());
  int32_t tailFrom = count + 1;
  std::vector<Group> groups = groupsOf(src, count, tailFrom);
  // origins: the statement of each source line (its first), -1 for a line without one.
  std::vector<int32_t> stmtOfLine;
  if (origins) {
    stmtOfLine.assign(static_cast<size_t>(count) + 2, -1);
    for (size_t k = src.stmts.size(); k-- > 0;) {
      const int32_t l = src.stmts[k].loc.line;
      if (l >= 1 && l <= count) stmtOfLine[static_cast<size_t>(l)] = static_cast<int32_t>(k);
    }
  }
  auto origin = [&](size_t k) {
    LineOrigin o;
    if (k < a.size()) {
      o.where = where[k];
      o.id = a[k].id;
    }
    return o;
  };
  // Lines [from, to) of the source; `at`: where in `a` the statement b[bBegin] is (a copied
  // group), or npos (the head and tail: no statement).
  auto copy = [&](int32_t from, int32_t to, size_t at = std::string::npos, size_t bBegin = 0) {
    const int32_t first = std::max(from, 1);
    for (int32_t l = first; l < to && l <= count; ++l) out += lines[static_cast<size_t>(l - 1)];
    if (!origins) return;
    for (int32_t l = first; l < to && l <= count; ++l) {
      size_t k = std::string::npos;
      for (int32_t m = l; m < to && m <= count && at != std::string::npos; ++m)
        if (stmtOfLine[static_cast<size_t>(m)] >= 0) {
          k = at + (static_cast<size_t>(stmtOfLine[static_cast<size_t>(m)]) - bBegin);
          break;
        }
      origins->push_back(origin(k));
    }
  };
  auto matches = [&](size_t i, const Group &g) {
    if (i + (g.end - g.begin) > a.size()) return false;
    for (size_t k = 0; k < g.end - g.begin; ++k)
      if (!sameElement(a[i + k], b[g.begin + k])) return false;
    return true;
  };
  auto printRung = [&](size_t from, size_t to) {
    std::vector<StmtText> t;
    for (size_t k = from; k < to; ++k) t.push_back(stmtTextOf(a[k]));
    std::string err;
    if (!out.empty() && out.back() != '\n') out += '\n';
    const size_t before = out.size();
    // The lines written before the rung that made no statement (Rung::lead: FANUC COME), where
    // its first instruction is printed from its statements (its written text would hold them).
    const std::vector<std::string> &lead = a[from].lead;
    const bool leads = a[from].role != WrittenRole::First;
    if (leads)
      for (const std::string &l : lead) out += l + "\n";
    if (d->printStmts(t, out, err)) {
      if (origins) {
        // A line per comment line before a statement (given to that statement) and one per
        // statement; a dialect's extra lines (an IL closing parenthesis) go to the last.
        std::vector<size_t> plan(leads ? lead.size() : 0, from);
        for (size_t k = from; k < to; ++k) {
          plan.insert(plan.end(), a[k].before.size(), k);
          plan.push_back(k);
        }
        size_t n = static_cast<size_t>(
            std::count(out.begin() + static_cast<std::ptrdiff_t>(before), out.end(), '\n'));
        if (!out.empty() && out.back() != '\n') ++n;
        for (size_t k = 0; k < n; ++k)
          origins->push_back(origin(plan[std::min(k, plan.size() - 1)]));
      }
      return true;
    }
    size_t k = 0; // "statement K: ..." -> the place of statement K in the networks
    if (err.rfind("statement ", 0) == 0) {
      k = static_cast<size_t>(std::max(0L, std::strtol(err.c_str() + 10, nullptr, 10) - 1));
      if (size_t c = err.find(": "); c != std::string::npos) err = err.substr(c + 2);
    }
    const size_t at = std::min(from + k, a.size() - 1);
    error = where[at] + " (id " + std::to_string(a[at].id) + "): " + err +
            "; edit this rung in the program text";
    return false;
  };
  // Printed one rung at a time: each starts on an empty stack (the value an output left on it
  // is dead), which is where a dialect writes RD / LD anew.
  auto isRungStart = [&](size_t k) {
    const std::string_view w = where[k], tail = " element 1";
    return w.size() >= tail.size() && w.substr(w.size() - tail.size()) == tail;
  };
  auto print = [&](size_t from, size_t to) {
    for (size_t r = from; r < to;) {
      size_t e = r + 1;
      while (e < to && !isRungStart(e)) ++e;
      if (!printRung(r, e)) return false;
      r = e;
    }
    return true;
  };
  std::unordered_map<StmtId, size_t> posA, posB;
  for (size_t i = 0; i < a.size(); ++i) posA.emplace(a[i].id, i);
  for (size_t i = 0; i < b.size(); ++i) posB.emplace(b[i].id, i);
  // A rung's lead (COME before it) and its first instruction's written text say the same: a
  // lead edited in the JSON while the instruction keeps the text it was written with would
  // print that text, not the lead.
  for (size_t k = 0; k < a.size(); ++k)
    if (!a[k].lead.empty() && a[k].role == WrittenRole::First && !a[k].written.empty() &&
        leadLines(d, a[k].written) != a[k].lead) {
      error = where[k] + " (id " + std::to_string(a[k].id) +
              "): the rung's \"lead\" is not the lines its first instruction was written after "
              "(its \"written\"): add or remove COME / NOP in the program text";
      return false;
    }
  // An instruction printed as written (WrittenRole) whose statements the networks changed is
  // printed from its statements: its text is the one they were made from.
  for (size_t i = 0; i < a.size();) {
    size_t e = i + 1;
    while (e < a.size() && a[e].role == WrittenRole::Part) ++e;
    bool same = true;
    for (size_t k = i; k < e && same; ++k) {
      auto it = posB.find(a[k].id);
      const Element *m = it == posB.end() ? nullptr : &b[it->second];
      same = m && m->op == a[k].op && m->operands == a[k].operands && m->symbols == a[k].symbols &&
             m->role == a[k].role && m->written == a[k].written;
    }
    if (!same)
      for (size_t k = i; k < e; ++k)
        if (a[k].role != WrittenRole::None) {
          // Its lines that made no statement (FANUC COME) still stand before it, from a JSON
          // without the rung's "lead" too.
          if (a[k].role == WrittenRole::First && a[k].lead.empty())
            a[k].lead = leadLines(d, a[k].written);
          a[k].role = WrittenRole::None;
          a[k].written.clear();
        }
    i = e;
  }
  copy(1, groups.empty() ? tailFrom : groups[0].from);
  size_t i = 0, g = printAll ? groups.size() : 0;
  while (i < a.size() || g < groups.size()) {
    if (g < groups.size() && matches(i, groups[g])) {
      copy(groups[g].from, groups[g].to, i, groups[g].begin);
      i += groups[g].end - groups[g].begin;
      ++g;
      continue;
    }
    // The next group the networks hold unchanged at or after i; the statements before it are
    // printed, the groups skipped were deleted or edited.
    size_t next = groups.size(), j = a.size();
    for (size_t h = g; h < groups.size(); ++h) {
      if (groups[h].end == groups[h].begin) continue;
      auto it = posA.find(b[groups[h].begin].id);
      if (it != posA.end() && it->second >= i && matches(it->second, groups[h])) {
        next = h;
        j = it->second;
        break;
      }
    }
    if (j > i && !print(i, j)) return false;
    i = j;
    g = next;
  }
  copy(tailFrom, count + 1);
  return true;
}

} // namespace lj::ladder

// Writing and reading the ladder network JSON (docs/ladder-json.md), and the JSON PROGRAM
// paths: HNC-8 JSON -> networks -> statements -> STL text for the HNC-8 parser; another
// dialect's JSON -> program text of that dialect (ToText.cpp). Instructions are named in the
// dialect's words (DialectText::spellStmt / lookup), never through a front end directly.
#include "ladder/Json.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <set>

namespace lj::ladder {

namespace {

using json = nlohmann::ordered_json; // members in the order written: "type" first

const char *const kContact[] = {"no", "nc", "rise", "fall", "true"};
const char *const kEntry[] = {"auto", "direct", "mps", "mrd", "mpp"};

/// The word the JSON names an element's instruction by: the dialect's (the user's) when that
/// word names the same operation back, else the operation's neutral name.
std::string instrWord(const Element &e, const DialectText *d) {
  std::string w = e.drawnWhole || e.drawn.empty() ? spelling(d, e.op) : e.drawn;
  Op back = Op::LoadTrue;
  if (d && d->lookup && d->lookup(w, back) && back == e.op) return w;
  return instrInfo(e.op).name;
}

json elemJson(const Element &e, bool withInstr, const DialectText *d) {
  json j;
  if (withInstr) j["instr"] = instrWord(e, d);
  j["id"] = e.id;
  j["line"] = e.loc.line;
  j["col"] = e.loc.col;
  json ops = json::array();
  for (size_t i = 0; i < e.operands.size(); ++i) {
    json o{{"text", e.operands[i]}};
    if (i < e.symbols.size() && !e.symbols[i].empty()) o["symbol"] = e.symbols[i];
    ops.push_back(o);
  }
  j["operands"] = ops;
  if (e.hasComment) j["comment"] = e.comment;
  if (!e.before.empty()) j["before"] = e.before;
  if (e.role == WrittenRole::First) { // its lines (none: text the front end makes itself)
    json lines = json::array();
    for (size_t p = 0; p < e.written.size();) {
      size_t nl = std::min(e.written.find('\n', p), e.written.size());
      lines.push_back(e.written.substr(p, nl - p));
      p = nl + 1;
    }
    j["written"] = lines;
  }
  if (e.role == WrittenRole::Part) j["in_written"] = true;
  return j;
}

json nodeJson(const Node &n, const DialectText *d) {
  json j;
  auto withElem = [&](const char *type, const Element &e, bool instr) {
    j["type"] = type;
    json fields = elemJson(e, instr, d); // named: items() of a temporary would dangle
    for (auto &[k, v] : fields.items()) j[k] = v;
  };
  switch (n.kind) {
  case NodeKind::Series:
  case NodeKind::Parallel: {
    j["type"] = n.kind == NodeKind::Series ? "series" : "parallel";
    json c = json::array();
    for (const Node &k : n.children) c.push_back(nodeJson(k, d));
    j["children"] = c;
    break;
  }
  case NodeKind::FanOut: {
    j["type"] = "fanout";
    json c = json::array();
    for (const Node &k : n.children) {
      json b = nodeJson(k, d);
      c.push_back(b);
    }
    j["branches"] = c;
    break;
  }
  case NodeKind::Contact:
    j["type"] = "contact";
    j["contact"] = kContact[static_cast<int>(n.contact)];
    {
      json fields = elemJson(n.elem, false, d);
      for (auto &[k, v] : fields.items()) j[k] = v;
    }
    break;
  case NodeKind::Coil:
    withElem("coil", n.elem, true);
    break;
  case NodeKind::Box: {
    withElem("box", n.elem, true);
    if (n.rail) j["rail"] = true;
    if (!n.children.empty()) {
      json c = json::array();
      for (const Node &k : n.children) c.push_back(nodeJson(k, d));
      j["inputs"] = c;
    }
    break;
  }
  }
  if (n.link.id >= 0 || n.link.loc.line > 0 || n.link.hasComment || !n.link.before.empty()) {
    json l = elemJson(n.link, false, d);
    l.erase("operands");
    j["link"] = l;
  }
  if (n.join != Join::Auto) j["join"] = n.join == Join::Inline ? "inline" : "block";
  if (n.entry != Entry::Auto) j["entry"] = kEntry[static_cast<int>(n.entry)];
  return j;
}

const char *kindName(Rung::Kind k) {
  return k == Rung::Kind::Ladder ? "ladder" : k == Rung::Kind::Stl ? "stl" : "marker";
}

/// The op whose neutral name (InstrInfo::name) is `m`: how the JSON writes an operation HNC-8
/// does not spell (a FANUC ROT is `BcdRotation`).
bool neutralName(std::string_view m, Op &out) {
  for (int k = 0; k < kOpCount; ++k)
    if (m == instrInfo(static_cast<Op>(k)).name) {
      out = static_cast<Op>(k);
      return true;
    }
  return false;
}

/// Reader with the JSON path of the value being read, for messages.
class Reader {
public:
  Reader(std::string &error, const DialectText *d) : error_(error), d_(d) {}

  bool fail(const std::string &path, const std::string &msg) {
    if (error_.empty()) error_ = (path.empty() ? std::string("top level") : path) + ": " + msg;
    return false;
  }

  bool str(const json &j, const char *key, const std::string &path, std::string &out,
           bool required = true) {
    auto it = j.find(key);
    if (it == j.end()) return !required || fail(path, std::string("missing \"") + key + "\"");
    if (!it->is_string()) return fail(path + "." + key, "expected a string");
    out = it->get<std::string>();
    if (out.find_first_of("\n\r") != std::string::npos)
      return fail(path + "." + key, "a line break is not allowed here");
    return true;
  }

  bool integer(const json &j, const char *key, const std::string &path, int32_t &out) {
    auto it = j.find(key);
    if (it == j.end()) return true;
    if (!it->is_number_integer()) return fail(path + "." + key, "expected an integer");
    auto v = it->get<int64_t>();
    if (v < -1 || v > INT32_MAX) return fail(path + "." + key, "out of range");
    out = static_cast<int32_t>(v);
    return true;
  }

  bool strings(const json &j, const char *key, const std::string &path,
               std::vector<std::string> &out) {
    auto it = j.find(key);
    if (it == j.end()) return true;
    if (!it->is_array()) return fail(path + "." + key, "expected an array of strings");
    for (size_t i = 0; i < it->size(); ++i) {
      const json &v = (*it)[i];
      std::string at = path + "." + key + "[" + std::to_string(i) + "]";
      if (!v.is_string()) return fail(at, "expected a string");
      out.push_back(v.get<std::string>());
      if (out.back().find_first_of("\n\r") != std::string::npos)
        return fail(at, "a line break is not allowed here");
    }
    return true;
  }

  /// A token that must stay one STL token: printable, no blank, no comment marker.
  bool token(const std::string &t, const std::string &path) {
    if (t.empty()) return fail(path, "empty operand");
    for (unsigned char c : t)
      if (c <= ' ' || c == ';' || c == '/' || c == 0x7f)
        return fail(path, "operand " + quoteToken(t, 40) + " is not one token");
    return true;
  }

  bool element(const json &j, const std::string &path, Element &e, bool needInstr) {
    if (!j.is_object()) return fail(path, "expected an object");
    if (needInstr) {
      std::string m;
      if (!str(j, "instr", path, m)) return false;
      if (d_ && d_->lookup && d_->lookup(m, e.op))
        e.drawn = m; // as the user's dialect names it (FANUC EQB: the width is in the word)
      else if (!neutralName(m, e.op))
        return fail(path + ".instr", "unknown instruction " + quoteToken(m, 40));
    }
    if (!integer(j, "id", path, e.id) || !integer(j, "line", path, e.loc.line) ||
        !integer(j, "col", path, e.loc.col))
      return false;
    if (e.id >= 0 && !ids_.insert(e.id).second)
      return fail(path + ".id", "duplicate statement id " + std::to_string(e.id));
    auto ops = j.find("operands");
    if (ops != j.end()) {
      if (!ops->is_array()) return fail(path + ".operands", "expected an array");
      for (size_t i = 0; i < ops->size(); ++i) {
        std::string at = path + ".operands[" + std::to_string(i) + "]";
        std::string text, sym;
        if (!(*ops)[i].is_object()) return fail(at, "expected an object");
        if (!str((*ops)[i], "text", at, text) || !str((*ops)[i], "symbol", at, sym, false))
          return false;
        if (!token(text, at + ".text") || (!sym.empty() && !token(sym, at + ".symbol")))
          return false;
        e.operands.push_back(text);
        e.symbols.push_back(sym);
        // An operand the front end implies (a FANUC timer's time unit): as fromProgram marks it.
        if (needInstr && d_ && d_->implied && i < 32 && d_->implied(e.op, static_cast<int>(i)))
          e.implied |= 1u << i;
      }
    }
    if (e.drawn.size() > 1 && e.drawn.back() == ':' && e.operands.size() == 1) {
      e.drawn = e.operands[0] + ":"; // a label written whole (IL `%L64:`)
      e.drawnWhole = true;
    }
    if (j.contains("comment")) {
      e.hasComment = true;
      if (!str(j, "comment", path, e.comment)) return false;
    }
    if (j.contains("written")) {
      std::vector<std::string> lines;
      if (!strings(j, "written", path, lines)) return false;
      e.role = WrittenRole::First;
      for (size_t k = 0; k < lines.size(); ++k) e.written += (k ? "\n" : "") + lines[k];
    }
    if (auto w = j.find("in_written"); w != j.end()) {
      if (!w->is_boolean()) return fail(path + ".in_written", "expected true or false");
      if (w->get<bool>()) {
        if (e.role == WrittenRole::First)
          return fail(path, "\"written\" and \"in_written\" on one statement");
        e.role = WrittenRole::Part;
      }
    }
    return strings(j, "before", path, e.before);
  }

  bool node(const json &j, const std::string &path, Node &n, int depth = 0) {
    if (depth > 2000) return fail(path, "network nested too deeply");
    if (!j.is_object()) return fail(path, "expected an object");
    std::string type, join, entry;
    if (!str(j, "type", path, type) || !str(j, "join", path, join, false) ||
        !str(j, "entry", path, entry, false))
      return false;
    if (join == "inline")
      n.join = Join::Inline;
    else if (join == "block")
      n.join = Join::Block;
    else if (!join.empty())
      return fail(path + ".join", "expected inline or block");
    if (!entry.empty()) {
      size_t k = 0;
      while (k < 5 && entry != kEntry[k]) ++k;
      if (k == 5) return fail(path + ".entry", "expected auto, direct, mps, mrd or mpp");
      n.entry = static_cast<Entry>(k);
    }
    if (j.contains("link") && !element(j["link"], path + ".link", n.link, false)) return false;
    auto kids = [&](const char *key, bool required) {
      auto it = j.find(key);
      if (it == j.end()) return !required || fail(path, std::string("missing \"") + key + "\"");
      if (!it->is_array()) return fail(path + "." + key, "expected an array");
      for (size_t i = 0; i < it->size(); ++i) {
        n.children.emplace_back();
        if (!node((*it)[i], path + "." + key + "[" + std::to_string(i) + "]", n.children.back(),
                  depth + 1))
          return false;
      }
      return true;
    };
    if (type == "series" || type == "parallel") {
      n.kind = type == "series" ? NodeKind::Series : NodeKind::Parallel;
      return kids("children", true);
    }
    if (type == "fanout") {
      n.kind = NodeKind::FanOut;
      return kids("branches", true);
    }
    if (type == "contact") {
      n.kind = NodeKind::Contact;
      std::string c;
      if (!str(j, "contact", path, c)) return false;
      size_t k = 0;
      while (k < 5 && c != kContact[k]) ++k;
      if (k == 5) return fail(path + ".contact", "expected no, nc, rise, fall or true");
      n.contact = static_cast<ContactKind>(k);
      static constexpr Op kOps[] = {Op::Load, Op::LoadNot, Op::LoadRise, Op::LoadFall,
                                    Op::LoadTrue};
      n.elem.op = kOps[k];
      return element(j, path, n.elem, false);
    }
    if (type == "coil" || type == "box") {
      n.kind = type == "coil" ? NodeKind::Coil : NodeKind::Box;
      if (!element(j, path, n.elem, true)) return false;
      n.rail = j.contains("rail") && j["rail"].is_boolean() && j["rail"].get<bool>();
      StackRule want = n.kind == NodeKind::Coil ? StackRule::Coil : StackRule::Block;
      StackRule has = instrInfo(n.elem.op).stack;
      bool statusBox = n.kind == NodeKind::Box && n.rail && has == StackRule::Push &&
                       n.elem.op != Op::Load && n.elem.op != Op::LoadNot &&
                       n.elem.op != Op::LoadRise && n.elem.op != Op::LoadFall &&
                       n.elem.op != Op::LoadTrue;
      if (has != want && !statusBox)
        return fail(path + ".instr", std::string(spelling(d_, n.elem.op)) + " is not a " + type);
      return kids("inputs", false);
    }
    return fail(path + ".type", "unknown node type " + quoteToken(type, 40));
  }

  bool rung(const json &j, const std::string &path, Rung &r) {
    if (!j.is_object()) return fail(path, "expected an object");
    std::string kind;
    if (!str(j, "kind", path, kind) || !strings(j, "comment", path, r.comment) ||
        !strings(j, "lead", path, r.lead))
      return false;
    // Only the lines the dialect writes between rungs (FANUC COME, NOP): networks -> program
    // text prints them as they are.
    for (size_t i = 0; i < r.lead.size(); ++i)
      if (!d_ || !d_->markerLine || !d_->markerLine(r.lead[i]))
        return fail(path + ".lead[" + std::to_string(i) + "]",
                    quoteToken(r.lead[i], 40) + " is no line the " +
                        std::string(d_ ? d_->name : "") +
                        " dialect writes between rungs (FANUC COME, NOP)");
    if (kind == "ladder") {
      r.kind = Rung::Kind::Ladder;
      if (!j.contains("network")) return fail(path, "missing \"network\"");
      return node(j["network"], path + ".network", r.network);
    }
    if (kind != "stl" && kind != "marker")
      return fail(path + ".kind", "expected ladder, stl or marker");
    r.kind = kind == "stl" ? Rung::Kind::Stl : Rung::Kind::Marker;
    auto it = j.find("stmts");
    if (it == j.end() || !it->is_array()) return fail(path, "missing \"stmts\" (an array)");
    for (size_t i = 0; i < it->size(); ++i) {
      r.stmts.emplace_back();
      if (!element((*it)[i], path + ".stmts[" + std::to_string(i) + "]", r.stmts.back(), true))
        return false;
    }
    return true;
  }

  /// Statements without an id get fresh ones after the highest given.
  void fillIds(Networks &n) {
    StmtId next = ids_.empty() ? 0 : *ids_.rbegin() + 1;
    auto fix = [&](Element &e) {
      if (e.id < 0) e.id = next++;
    };
    std::vector<Node *> todo;
    for (Part &p : n.parts)
      for (Rung &r : p.rungs) {
        for (Element &e : r.stmts) fix(e);
        todo.push_back(&r.network);
      }
    while (!todo.empty()) {
      Node *x = todo.back();
      todo.pop_back();
      if (x->kind == NodeKind::Contact || x->kind == NodeKind::Coil || x->kind == NodeKind::Box)
        fix(x->elem);
      if (x->join == Join::Block || x->entry == Entry::Mps || x->entry == Entry::Mrd ||
          x->entry == Entry::Mpp)
        fix(x->link);
      for (auto it = x->children.rbegin(); it != x->children.rend(); ++it) todo.push_back(&*it);
    }
  }

private:
  std::string &error_;
  const DialectText *d_;
  std::set<StmtId> ids_;
};

} // namespace

std::string writeJson(const Networks &nets, std::string_view source) {
  json j;
  j["format"] = "ladderjit-ladder";
  j["version"] = kJsonVersion;
  j["dialect"] = nets.dialect;
  j["file"] = nets.file;
  if (!source.empty()) j["source"] = std::string(source);
  json syms = json::array();
  for (const Symbol &s : nets.symbols)
    syms.push_back({{"name", s.name}, {"address", s.address}, {"comment", s.comment}});
  j["symbols"] = syms;
  json parts = json::array();
  for (const Part &p : nets.parts) {
    json rungs = json::array();
    for (size_t i = 0; i < p.rungs.size(); ++i) {
      const Rung &r = p.rungs[i];
      json jr{{"number", i + 1}, {"kind", kindName(r.kind)}, {"comment", r.comment}};
      if (!r.lead.empty()) jr["lead"] = r.lead;
      if (r.kind == Rung::Kind::Ladder) {
        jr["network"] = nodeJson(r.network, nets.text);
      } else {
        json st = json::array();
        for (const Element &e : r.stmts) st.push_back(elemJson(e, true, nets.text));
        jr["stmts"] = st;
      }
      rungs.push_back(jr);
    }
    parts.push_back({{"name", p.name}, {"rungs", rungs}});
  }
  j["parts"] = parts;
  j["trailing_comments"] = nets.trailingComments;
  return j.dump(1, ' ', false, json::error_handler_t::replace) + "\n";
}

bool readJson(std::string_view text, Networks &out, std::string &error, const DialectText &d) {
  error.clear();
  json j = json::parse(text.begin(), text.end(), nullptr, false);
  if (j.is_discarded()) {
    error = "not valid JSON";
    return false;
  }
  Reader rd(error, &d);
  if (!j.is_object()) return rd.fail("", "expected an object");
  std::string format, dialect;
  if (!rd.str(j, "format", "", format) || !rd.str(j, "dialect", "", dialect)) return false;
  if (format != "ladderjit-ladder")
    return rd.fail("format", "expected \"ladderjit-ladder\", got " + quoteToken(format, 40));
  if (!j.contains("version") || !j["version"].is_number_integer() ||
      j["version"].get<int64_t>() != kJsonVersion)
    return rd.fail("version", "this ladderjit reads version " + std::to_string(kJsonVersion));
  if (dialect.empty()) return rd.fail("dialect", "empty");
  if (dialect != d.name)
    return rd.fail("dialect", quoteToken(dialect, 40) + " networks read as '" + d.name + "'");
  out = Networks{};
  out.dialect = dialect;
  out.text = &d;
  if (!rd.str(j, "file", "", out.file, false)) return false;
  if (j.contains("source") && !j["source"].is_string())
    return rd.fail("source", "expected a string (the program text)");
  if (j.contains("source")) out.source = j["source"].get<std::string>();
  if (j.contains("symbols")) {
    const json &s = j["symbols"];
    if (!s.is_array()) return rd.fail("symbols", "expected an array");
    for (size_t i = 0; i < s.size(); ++i) {
      std::string at = "symbols[" + std::to_string(i) + "]";
      Symbol sym;
      if (!s[i].is_object()) return rd.fail(at, "expected an object");
      if (!rd.str(s[i], "name", at, sym.name) || !rd.str(s[i], "address", at, sym.address) ||
          !rd.str(s[i], "comment", at, sym.comment, false))
        return false;
      out.symbols.push_back(sym);
    }
  }
  auto parts = j.find("parts");
  if (parts == j.end() || !parts->is_array()) return rd.fail("", "missing \"parts\" (an array)");
  for (size_t p = 0; p < parts->size(); ++p) {
    const json &jp = (*parts)[p];
    std::string at = "parts[" + std::to_string(p) + "]";
    out.parts.emplace_back();
    Part &part = out.parts.back();
    if (!jp.is_object()) return rd.fail(at, "expected an object");
    if (!rd.str(jp, "name", at, part.name)) return false;
    auto rungs = jp.find("rungs");
    if (rungs == jp.end() || !rungs->is_array()) return rd.fail(at, "missing \"rungs\" (an array)");
    for (size_t r = 0; r < rungs->size(); ++r) {
      part.rungs.emplace_back();
      if (!rd.rung((*rungs)[r], at + ".rungs[" + std::to_string(r) + "]", part.rungs.back()))
        return false;
    }
  }
  if (!rd.strings(j, "trailing_comments", "", out.trailingComments)) return false;
  rd.fillIds(out);
  return true;
}

std::string stlText(const std::vector<Element> &stmts, const std::vector<std::string> *where,
                    std::vector<LineOrigin> *origins, const DialectText *d) {
  std::string out;
  auto line = [&](const std::string &text, const LineOrigin &o) {
    out += text;
    out += '\n';
    if (origins) origins->push_back(o);
  };
  for (size_t i = 0; i < stmts.size(); ++i) {
    const Element &e = stmts[i];
    for (const std::string &c : e.before) line("; " + c, {});
    std::string t = spelling(d, e.op);
    for (size_t k = 0; k < e.operands.size(); ++k)
      t += " " + (k < e.symbols.size() && !e.symbols[k].empty() ? e.symbols[k] : e.operands[k]);
    if (e.hasComment) t += " ; " + e.comment;
    line(t, {where && i < where->size() ? (*where)[i] : std::string(), e.loc, e.id});
  }
  return out;
}

bool stlFromJson(std::string_view text, StlFromJson &out, std::string &error,
                 const DialectText &d) {
  Networks nets;
  if (!readJson(text, nets, error, d)) return false;
  if (!nets.symbols.empty() && !d.symbolRules) {
    error = "symbols: " + std::string(d.name) + " programs have no symbol table";
    return false;
  }
  if (d.symbolRules) out.symbols = SymbolTable(d.symbolRules());
  for (size_t i = 0; i < nets.symbols.size(); ++i) {
    const Symbol &s = nets.symbols[i];
    std::string err;
    if (!out.symbols.add(s.name, s.address, s.comment, err)) {
      error = "symbols[" + std::to_string(i) + "]: " + err;
      return false;
    }
  }
  std::vector<Element> stmts;
  std::vector<std::string> where;
  if (!toStatements(nets, stmts, error, &where)) return false;
  out.text = stlText(stmts, &where, &out.lines, &d);
  for (const std::string &c : nets.trailingComments) {
    out.text += "; " + c + "\n";
    out.lines.push_back({});
  }
  return true;
}

std::string renderDiagnostics(const Diagnostics &diags, const StlFromJson &src) {
  Diagnostics out(diags.file());
  for (const Diagnostic &d : diags.all()) {
    SourceLoc loc = d.loc;
    std::string msg = d.message;
    if (d.loc.line >= 1 && static_cast<size_t>(d.loc.line) <= src.lines.size()) {
      const LineOrigin &o = src.lines[static_cast<size_t>(d.loc.line - 1)];
      if (!o.where.empty()) msg = o.where + " (id " + std::to_string(o.id) + "): " + msg;
      loc = o.loc;
    }
    switch (d.severity) {
    case Diagnostic::Severity::Error:
      out.error(loc, msg);
      break;
    case Diagnostic::Severity::Warning:
      out.warning(loc, msg);
      break;
    case Diagnostic::Severity::Note:
      out.note(loc, msg);
      break;
    }
  }
  return out.render();
}

bool sameStatementsAs(const Networks &given, const Networks &made, std::string &error,
                      bool compareIds) {
  std::vector<Element> a, b;
  std::vector<std::string> where;
  if (!toStatements(given, a, error, &where) || !toStatements(made, b, error)) return false;
  auto operandsOf = [](const Element &e) {
    std::string t;
    for (size_t k = 0; k < e.operands.size(); ++k)
      t += " " + (k < e.symbols.size() && !e.symbols[k].empty()
                      ? e.symbols[k] + "(" + e.operands[k] + ")"
                      : e.operands[k]);
    return t;
  };
  auto show = [&](const Element &e) { return spelling(given.text, e.op) + operandsOf(e); };
  const size_t n = std::min(a.size(), b.size());
  for (size_t i = 0; i < n; ++i) {
    if (a[i].op == b[i].op && a[i].operands == b[i].operands && a[i].symbols == b[i].symbols &&
        (a[i].id == b[i].id || !compareIds))
      continue;
    error = where[i] + " (id " + std::to_string(a[i].id) + "): the networks say '" + show(a[i]) +
            "', the program text they carry says '" + show(b[i]) + "' (id " +
            std::to_string(b[i].id) + ")";
    return false;
  }
  if (a.size() != b.size()) {
    error = "the networks hold " + std::to_string(a.size()) +
            " statements, the program text they carry " + std::to_string(b.size());
    return false;
  }
  return true;
}

void applyOrigins(VerifiedProgram &prog, const StlFromJson &src) {
  StmtId next = 0;
  for (const LineOrigin &o : src.lines) next = std::max(next, o.id + 1);
  for (Stmt &s : prog.stmts) {
    if (s.loc.line < 1 || static_cast<size_t>(s.loc.line) > src.lines.size()) continue;
    const LineOrigin &o = src.lines[static_cast<size_t>(s.loc.line - 1)];
    s.id = o.id >= 0 ? o.id : next++; // a join the JSON left implicit gets a fresh id
    if (o.loc.line <= 0) continue;
    s.loc = o.loc; // where the statement was written, as the JSON recorded it
    for (Operand &op : s.ops) op.loc.line = o.loc.line;
  }
}

} // namespace lj::ladder

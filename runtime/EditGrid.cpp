// The page editor's grid route (runtime/EditGrid.h).
#include "runtime/EditGrid.h"

#include "formats/Address.h"
#include "ir/OpTable.h"
#include "ladder/Grid.h"
#include "ladder/Json.h"
#include "ladder/Network.h"
#include "pipeline/Dialects.h"
#include "services/HttpServer.h"

#include <cctype>
#include <charconv>
#include <string>
#include <vector>

namespace lj::rt {

using nlohmann::json;

namespace {

constexpr int kMaxRows = 64, kMaxCols = 64; // a rung the page can show; bigger is refused

EditAnswer bad(const std::string &why) { return {400, {{"error", why}}}; }

/// A one-input box at the right rail: what the grid draws as 功能模块 (ladder/Grid.cpp's rule).
bool editorBox(const InstrInfo &ii) { return ii.stack == StackRule::Block && ii.inputs <= 1; }

/// What the page's operand texts are checked against: the dialect's address syntax, the
/// program's symbols and, for a box, the operation's operand specs.
struct Checker {
  const pipeline::Dialect &d;
  const DialectText &text;
  const VerifiedProgram &prog;

  /// The symbol `name` stands for (case-insensitive), or null.
  const Symbol *symbol(std::string_view name) const {
    return formats::findSymbol(prog.symbols, name);
  }

  /// A contact's or an output's operand: a bit address or a symbol of one.
  bool bit(const std::string &operand, std::string &error) const {
    const Symbol *s = symbol(operand);
    std::optional<formats::CliAddress> a = d.parseAddress(s ? s->address : operand, error);
    if (!a) return false;
    if (!a->isBit()) {
      error = "not a bit address: a contact or an output takes one bit";
      return false;
    }
    return true;
  }

  /// Operand `k` of box `op`: by its spec (a constant in range, or an address).
  bool boxOperand(Op op, int k, const std::string &operand, std::string &error) const {
    const InstrInfo &ii = instrInfo(op);
    int written = -1, spec = -1;
    for (int i = 0; i < ii.operandCount; ++i) {
      if (text.implied && text.implied(op, i)) continue;
      if (++written == k) {
        spec = i;
        break;
      }
    }
    if (spec < 0) {
      error =
          "box " + std::string(spelling(&text, op)) + " has no operand " + std::to_string(k + 1);
      return false;
    }
    const OperandSpec &os = ii.operands[spec];
    if (operand.empty()) {
      error = std::string("the ") + os.role + " is missing";
      return false;
    }
    int64_t v = 0;
    const char *b = operand.data(), *e = b + operand.size();
    if (*b == '+') ++b;
    auto [p, ec] = std::from_chars(b, e, v);
    if (ec == std::errc() && p == e) {
      if (!os.constOk) {
        error = std::string("the ") + os.role + " takes an address, not a constant";
        return false;
      }
      if (v < os.cmin || v > os.cmax || !inValueSet(os, v)) {
        error = std::string("the ") + os.role + " " + operand + " is out of range (" +
                std::to_string(os.cmin) + ".." + std::to_string(os.cmax) + ")";
        return false;
      }
      return true;
    }
    // A jump label or subroutine number (`L3`, `S1`; IL `%L3`, `%SR1`) is the verifier's to
    // check (the part must exist): the update's check names it on its cell.
    if (hasArea(os.areas, Area::Label) || hasArea(os.areas, Area::Subroutine)) return true;
    const Symbol *s = symbol(operand);
    std::optional<formats::CliAddress> a = d.parseAddress(s ? s->address : operand, error);
    if (!a) return false;
    if (os.isBit && !a->isBit() && !os.wordOk) {
      error = std::string("the ") + os.role + " is a bit address";
      return false;
    }
    if (!os.isBit && a->isBit()) {
      error = std::string("the ") + os.role + " is a register, not a bit";
      return false;
    }
    return true;
  }
};

/// The words a user types for `op`: a table word may name several (FANUC `MOVB/MOVW/MOVD`,
/// `LEx/GEx` for B, W and D, `AND(SUB60)/MOVE`); each kept when the dialect reads it back as `op`.
std::vector<std::string> wordsOf(const DialectText &t, Op op) {
  std::vector<std::string> out;
  const char *spelled = t.spell(op);
  if (!spelled) return out;
  const std::string all = spelled;
  Op whole = Op::LoadTrue;
  if (t.lookup && t.lookup(all, whole) && whole == op) return {all}; // one word (IL `/`)
  size_t from = 0;
  while (from <= all.size()) {
    size_t to = all.find('/', from);
    if (to == std::string::npos) to = all.size();
    std::string w = all.substr(from, to - from);
    if (size_t paren = w.find('('); paren != std::string::npos) w.erase(paren);
    std::vector<std::string> cands{w};
    if (!w.empty() && w.back() == 'x') {
      w.pop_back();
      cands = {w + "B", w + "W", w + "D"};
    }
    for (const std::string &c : cands) {
      Op back = Op::LoadTrue;
      if (!c.empty() && t.lookup && t.lookup(c, back) && back == op) out.push_back(c);
    }
    from = to + 1;
  }
  return out;
}

json catalogue(const DialectText &t) {
  json boxes = json::array();
  for (const InstrInfo &ii : instrTable()) {
    if (!editorBox(ii)) continue;
    const std::vector<std::string> words = wordsOf(t, ii.op);
    if (words.empty()) continue;
    json ops = json::array();
    for (int i = 0; i < ii.operandCount; ++i) {
      if (t.implied && t.implied(ii.op, i)) continue;
      const OperandSpec &os = ii.operands[i];
      ops.push_back(
          {{"role", os.role}, {"bit", os.isBit}, {"constant", os.constOk}, {"writes", os.writes}});
    }
    for (const std::string &w : words)
      boxes.push_back({{"instr", w}, {"operands", ops}, {"summary", ii.summary}});
  }
  return boxes;
}

json gridJson(const ladder::GridRung &g) {
  json cells = json::array();
  for (const ladder::GridCell &c : g.cells) {
    json j{{"k", ladder::cellKindName(c.kind)}};
    if (!c.operand.empty()) j["op"] = c.operand;
    if (c.kind == ladder::CellKind::Box) {
      j["instr"] = c.instr;
      j["ops"] = c.operands;
    }
    cells.push_back(std::move(j));
  }
  json links = json::array();
  for (int r = 0; r + 1 < g.rows; ++r)
    for (int b = 1; b < g.cols; ++b)
      if (g.link(r, b)) links.push_back({r, b});
  return {{"rows", g.rows}, {"cols", g.cols}, {"cells", cells}, {"links", links}};
}

/// The page's grid; false with `error` naming the member.
bool readGrid(const json &j, ladder::GridRung &g, std::string &error) {
  if (!j.is_object() || !j.contains("rows") || !j.contains("cols") ||
      !j["rows"].is_number_integer() || !j["cols"].is_number_integer()) {
    error = "grid: needs integer rows and cols";
    return false;
  }
  const int rows = j["rows"].get<int>(), cols = j["cols"].get<int>();
  if (rows < 1 || cols < 1 || rows > kMaxRows || cols > kMaxCols) {
    error = "grid: rows and cols must be 1.." + std::to_string(kMaxRows);
    return false;
  }
  g = ladder::GridRung::blank(rows, cols);
  const json &cells = j.value("cells", json::array());
  if (!cells.is_array() || cells.size() != static_cast<size_t>(rows * cols)) {
    error = "grid: cells must hold rows x cols cells, row by row";
    return false;
  }
  for (size_t i = 0; i < cells.size(); ++i) {
    const json &c = cells[i];
    const std::string k = c.is_object() ? c.value("k", "") : "";
    ladder::CellKind kind = ladder::CellKind::Empty;
    bool known = false;
    for (int n = 0; n <= static_cast<int>(ladder::CellKind::BoxPart); ++n)
      if (k == ladder::cellKindName(static_cast<ladder::CellKind>(n))) {
        kind = static_cast<ladder::CellKind>(n);
        known = true;
      }
    if (!known) {
      error = "grid: cells[" + std::to_string(i) + "]: unknown kind '" + k + "'";
      return false;
    }
    ladder::GridCell &cell = g.cells[i];
    cell.kind = kind;
    if (c.contains("op") && c["op"].is_string()) cell.operand = c["op"].get<std::string>();
    if (kind == ladder::CellKind::Box) {
      if (c.contains("instr") && c["instr"].is_string()) cell.instr = c["instr"].get<std::string>();
      if (c.contains("ops") && c["ops"].is_array())
        for (const json &o : c["ops"])
          cell.operands.push_back(o.is_string() ? o.get<std::string>() : std::string());
    }
  }
  const json &links = j.value("links", json::array());
  if (!links.is_array()) {
    error = "grid: links must be [[row, boundary], ...]";
    return false;
  }
  for (const json &l : links) {
    if (!l.is_array() || l.size() != 2 || !l[0].is_number_integer() || !l[1].is_number_integer()) {
      error = "grid: links must be [[row, boundary], ...]";
      return false;
    }
    g.setLink(l[0].get<int>(), l[1].get<int>(), true);
  }
  if (j.contains("comment") && j["comment"].is_array())
    for (const json &c : j["comment"])
      if (c.is_string()) g.comment.push_back(c.get<std::string>());
  return true;
}

/// Operands written as symbols keep their symbol: the element gets the address, the symbol
/// name beside it (what the program text prints back), as in the running program's networks.
void symbolsIn(ladder::Node &n, const Checker &ck) {
  for (ladder::Node &c : n.children) symbolsIn(c, ck);
  for (size_t k = 0; k < n.elem.operands.size(); ++k)
    if (const Symbol *s = ck.symbol(n.elem.operands[k])) {
      n.elem.operands[k] = s->address;
      if (k < n.elem.symbols.size()) n.elem.symbols[k] = s->name;
    }
}

/// `n` (network JSON) without statement ids, lines and columns: the server numbers new
/// statements after the program's highest id when the draft is read.
void withoutPlaces(json &n) {
  if (n.is_object()) {
    n.erase("id");
    n.erase("line");
    n.erase("col");
    for (auto &[k, v] : n.items()) withoutPlaces(v);
  } else if (n.is_array()) {
    for (json &v : n) withoutPlaces(v);
  }
}

json convert(const Checker &ck, const json &req) {
  json out = json::object();
  const std::string part = req.value("partName", std::string("rung"));
  const int rung =
      req.contains("rung") && req["rung"].is_number_integer() ? req["rung"].get<int>() + 1 : 0;
  ladder::GridRung g;
  std::string error;
  if (!req.contains("grid") || !readGrid(req["grid"], g, error)) {
    out["ok"] = false;
    out["errors"] =
        json::array({{{"row", -1}, {"col", -1}, {"message", error.empty() ? "no grid" : error}}});
    return out;
  }
  json errors = json::array();
  // Boxes first: their operands by the operation's specs (gridToNetwork checks the word).
  for (int r = 0; r < g.rows; ++r)
    for (int c = 0; c < g.cols; ++c) {
      const ladder::GridCell &cell = g.at(r, c);
      if (cell.kind != ladder::CellKind::Box) continue;
      Op op = Op::LoadTrue;
      if (!ck.text.lookup || !ck.text.lookup(cell.instr, op)) continue;
      int want = 0;
      for (int i = 0; i < instrInfo(op).operandCount; ++i)
        if (!(ck.text.implied && ck.text.implied(op, i))) ++want;
      if (static_cast<int>(cell.operands.size()) != want) {
        errors.push_back(
            {{"row", r},
             {"col", c},
             {"message", "box " + cell.instr + " takes " + std::to_string(want) +
                             " operand(s), not " + std::to_string(cell.operands.size())}});
        continue;
      }
      for (size_t k = 0; k < cell.operands.size(); ++k)
        if (!ck.boxOperand(op, static_cast<int>(k), cell.operands[k], error))
          errors.push_back(
              {{"row", r}, {"col", c}, {"message", "'" + cell.operands[k] + "': " + error}});
    }
  ladder::OperandCheck check = [&ck](ladder::CellKind k, const std::string &operand,
                                     std::string &err) {
    return k == ladder::CellKind::Box || ck.bit(operand, err);
  };
  ladder::Node net;
  std::vector<ladder::GridError> gerrs;
  const bool ok = ladder::gridToNetwork(g, ck.text, check, part, rung, net, gerrs);
  for (const ladder::GridError &e : gerrs)
    errors.push_back({{"row", e.row}, {"col", e.col}, {"message", e.message}});
  if (!ok || !errors.empty()) {
    out["ok"] = false;
    out["errors"] = errors;
    return out;
  }
  // The statements in program order, each with its cell (gridToNetwork gives an element the id
  // row * cols + col): what the check's diagnostics (rung, element) are drawn on.
  std::vector<ladder::Element> stmts;
  json cells = json::array();
  if (ladder::rungStatements(net, stmts, error, &ck.text))
    for (const ladder::Element &e : stmts)
      cells.push_back(e.id >= 0 ? json{e.id / g.cols, e.id % g.cols} : json(nullptr));
  symbolsIn(net, ck);
  // The network as the JSON writes it, without the grid's ids: the server numbers new
  // statements after the program's highest id.
  ladder::Networks one;
  one.dialect = ck.d.name;
  one.text = &ck.text;
  ladder::Rung lr;
  lr.kind = ladder::Rung::Kind::Ladder;
  lr.comment = g.comment;
  lr.network = std::move(net);
  one.parts.push_back({part, {std::move(lr)}});
  json w = json::parse(ladder::writeJson(one), nullptr, false);
  if (w.is_discarded()) {
    out["ok"] = false;
    out["errors"] = json::array({{{"row", -1}, {"col", -1}, {"message", "no JSON form"}}});
    return out;
  }
  json network = w["parts"][0]["rungs"][0]["network"];
  withoutPlaces(network);
  out["ok"] = true;
  out["network"] = network;
  out["cells"] = cells;
  return out;
}

/// 列表编辑: a new subroutine part named `name` as the dialect writes it (HNC-8 `S7`, FANUC `P7`,
/// IL `SR7`): its begin and end markers (SP / SPE; IL `SR7:` and the implicit end the IL printer
/// leaves out) as the network JSON writes them, made from the neutral operations and spelled by
/// the dialect, so the page copies no dialect's words. The draft's verify checks the rest.
json subroutinePart(const Checker &ck, const std::string &name) {
  const TargetProfile *pf = ck.prog.profile;
  if (!pf) return {{"ok", false}, {"error", "this program has no target profile"}};
  const AreaInfo &area = pf->area(Area::Subroutine);
  const std::string prefix = area.name ? area.name : "";
  auto fail = [&](const std::string &why) {
    return json{{"ok", false},
                {"error", "'" + services::clientText(name) + "': " + why +
                              " (a subroutine is written " + prefix + "<number>, e.g. " + prefix +
                              "7)"}};
  };
  if (prefix.empty() || area.count <= 0)
    return {{"ok", false},
            {"error", "the " + std::string(ck.d.name) + " dialect has no subroutines"}};
  if (name.size() <= prefix.size() || name.size() > prefix.size() + 6) return fail("not a name");
  for (size_t i = 0; i < prefix.size(); ++i)
    if (std::toupper(static_cast<unsigned char>(name[i])) != prefix[i]) return fail("not a name");
  int32_t n = 0;
  const char *b = name.data() + prefix.size(), *e = name.data() + name.size();
  auto [ptr, ec] = std::from_chars(b, e, n);
  if (ec != std::errc() || ptr != e || *b == '+' || *b == '-') return fail("not a number");
  if (!pf->validIndex(Area::Subroutine, n))
    return fail("out of range (" + prefix + std::to_string(area.first) + ".." + prefix +
                std::to_string(area.count - 1) + ")");
  ladder::Networks one;
  one.dialect = ck.d.name;
  one.text = &ck.text;
  ladder::Part part;
  part.name = prefix + std::to_string(n);
  for (Op op : {Op::SubBegin, Op::SubEnd}) {
    Stmt s;
    s.op = op;
    if (op == Op::SubBegin) {
      s.operandCount = 1;
      s.ops[0].kind = Operand::Kind::Reg;
      s.ops[0].area = Area::Subroutine;
      s.ops[0].index = n;
    }
    ladder::Rung r;
    r.kind = ladder::Rung::Kind::Marker;
    r.stmts.push_back(ladder::stmtElement(s, &ck.text, pf, ck.prog.symbols));
    part.rungs.push_back(std::move(r));
  }
  one.parts.push_back(std::move(part));
  json w = json::parse(ladder::writeJson(one), nullptr, false);
  if (w.is_discarded()) return {{"ok", false}, {"error", "no JSON form of the markers"}};
  json rungs = w["parts"][0]["rungs"];
  withoutPlaces(rungs);
  return {{"ok", true}, {"name", one.parts[0].name}, {"number", n}, {"rungs", rungs}};
}

} // namespace

namespace {

EditAnswer gridRoute(const ProgramVersion *v, const json &body);

} // namespace

EditAnswer editGrid(const ProgramVersion *v, const json &body) {
  try {
    return gridRoute(v, body);
  } catch (const json::exception &e) { // a member of the wrong type ({"open":"yes"})
    return bad(std::string("a member of the wrong type: ") + e.what());
  }
}

namespace {

EditAnswer gridRoute(const ProgramVersion *v, const json &body) {
  if (!v || !v->prog) return {409, {{"error", "no program is running"}}};
  const VerifiedProgram &prog = *v->prog;
  const pipeline::Dialect *d =
      prog.profile ? pipeline::dialectNamed(prog.profile->name) : &pipeline::defaultDialect();
  if (!d) d = &pipeline::defaultDialect();
  const DialectText &text = prog.dialect ? *prog.dialect : d->text();
  Checker ck{*d, text, prog};
  for (const auto &[k, val] : body.items())
    if (k != "open" && k != "rungs" && k != "operand" && k != "kind" && k != "box" &&
        k != "index" && k != "subroutine")
      return bad("unknown field '" + services::clientText(k) +
                 "' in /api/edit/grid (open, rungs, operand, subroutine)");

  if (body.value("open", false)) {
    ladder::Networks nets = ladder::fromProgram(prog);
    json parts = json::array();
    for (const ladder::Part &p : nets.parts) {
      json rungs = json::array();
      for (const ladder::Rung &r : p.rungs) {
        json jr{{"comment", r.comment}};
        ladder::GridRung g;
        std::string why;
        if (r.kind != ladder::Rung::Kind::Ladder)
          jr["why"] = r.kind == ladder::Rung::Kind::Marker ? "a marker" : "statement text only";
        else if (!ladder::gridOfRung(r, g, why))
          jr["why"] = why;
        else
          jr["grid"] = gridJson(g);
        rungs.push_back(std::move(jr));
      }
      // A subroutine (its first rung SP / IL `SRn:`) is what 列表编辑 renames and deletes.
      const bool sub = !p.rungs.empty() && p.rungs[0].kind == ladder::Rung::Kind::Marker &&
                       !p.rungs[0].stmts.empty() && p.rungs[0].stmts[0].op == Op::SubBegin;
      parts.push_back({{"name", p.name}, {"rungs", rungs}, {"subroutine", sub}});
    }
    json syms = json::object();
    for (const Symbol &s : prog.symbols) syms[s.name] = s.address;
    // 列表编辑: how the dialect names a subroutine (HNC-8 S0..S511, FANUC P1..P5000, IL
    // SR0..SR63), for the page's suggestion; /api/edit/grid {"subroutine"} checks a name.
    json subs = nullptr;
    if (prog.profile && prog.profile->area(Area::Subroutine).count > 0) {
      const AreaInfo &a = prog.profile->area(Area::Subroutine);
      subs = {{"prefix", a.name}, {"first", a.first}, {"last", a.count - 1}};
    }
    return {200,
            {{"ok", true},
             {"dialect", d->name},
             {"hash", v->hash},
             {"version", v->id},
             {"parts", parts},
             {"boxes", catalogue(text)},
             // The edge contacts of the dialect (HNC-8 LDP/LDF, IL LDR/LDF; FANUC PMC has none).
             {"edges", text.spell(Op::LoadRise) != nullptr && text.spell(Op::LoadFall) != nullptr},
             {"symbols", syms},
             {"subroutines", subs}}};
  }
  if (body.contains("rungs")) {
    if (!body["rungs"].is_array() || body["rungs"].size() > 256)
      return bad("rungs: an array of at most 256 {part, rung, grid}");
    json out = json::array();
    for (const json &r : body["rungs"]) {
      if (!r.is_object()) return bad("rungs: each is an object {part, rung, grid}");
      out.push_back(convert(ck, r));
    }
    return {200, {{"ok", true}, {"rungs", out}}};
  }
  if (body.contains("subroutine")) {
    if (!body["subroutine"].is_string() || body["subroutine"].get<std::string>().size() > 64)
      return bad("subroutine: the new part's name as the dialect writes it (\"S7\")");
    return {200, subroutinePart(ck, body["subroutine"].get<std::string>())};
  }
  if (body.contains("operand")) {
    if (!body["operand"].is_string()) return bad("operand: a string");
    const std::string op = body["operand"].get<std::string>();
    std::string error;
    bool ok = false;
    if (body.contains("box") && body["box"].is_string()) {
      Op o = Op::LoadTrue;
      const std::string word = body["box"].get<std::string>();
      if (!text.lookup || !text.lookup(word, o))
        error = "'" + word + "' is no instruction of the " + d->name + " dialect";
      else
        ok = ck.boxOperand(o, body.value("index", 0), op, error);
    } else {
      ok = op.empty() ? (error = "no address", false) : ck.bit(op, error);
    }
    json a{{"ok", ok}};
    if (!ok) a["error"] = error;
    if (const Symbol *s = ck.symbol(op)) a["address"] = s->address;
    return {200, a};
  }
  return bad("POST /api/edit/grid takes {\"open\":true}, {\"rungs\":[...]}, {\"operand\":...} or "
             "{\"subroutine\":...}");
}

} // namespace

} // namespace lj::rt

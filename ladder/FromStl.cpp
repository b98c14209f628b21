// STL -> networks (ladder-view-research.md 1.7): a symbolic ST/MS walk over each rung of a
// verified program, with network nodes instead of bits. A rung becomes a Ladder rung only when
// its network turns back into exactly its statements; otherwise it stays an Stl rung.
#include "ladder/Network.h"

#include "ir/Profile.h"

#include <algorithm>

namespace lj::ladder {

namespace {

constexpr int kMaxNetworkDepth = 1000; ///< the JSON reader accepts 2000

ContactKind contactKind(Op op) {
  switch (op) {
  case Op::LoadNot:
  case Op::AndNot:
  case Op::OrNot:
    return ContactKind::NC;
  case Op::LoadRise:
  case Op::AndRise:
  case Op::OrRise:
    return ContactKind::Rise;
  case Op::LoadFall:
  case Op::AndFall:
  case Op::OrFall:
    return ContactKind::Fall;
  case Op::LoadTrue:
    return ContactKind::True;
  default:
    return ContactKind::NO;
  }
}

bool isLoadContact(Op op) {
  return op == Op::Load || op == Op::LoadNot || op == Op::LoadRise || op == Op::LoadFall ||
         op == Op::LoadTrue;
}

bool isOrForm(Op op) {
  return op == Op::Or || op == Op::OrNot || op == Op::OrRise || op == Op::OrFall;
}

Node series(std::vector<Node> children = {}, Entry entry = Entry::Auto) {
  Node n;
  n.kind = NodeKind::Series;
  n.entry = entry;
  n.children = std::move(children);
  return n;
}

Node leaf(NodeKind kind, const Element &e) {
  Node n;
  n.kind = kind;
  n.elem = e;
  n.contact = contactKind(e.op);
  return n;
}

/// The one node of a one-child Series, else the Series itself.
Node unwrap(Node s) {
  if (s.kind == NodeKind::Series && s.children.size() == 1 && s.entry == Entry::Auto) {
    Node c = std::move(s.children[0]);
    c.join = Join::Auto;
    return c;
  }
  return s;
}

/// The symbolic stacks of one rung.
class Builder {
public:
  explicit Builder(const VerifiedProgram &p) : p_(p) {}

  /// The network of statements [r.begin, r.end) with their elements, or false.
  bool build(StmtRange r, const std::vector<Element> &elems, Node &out) {
    std::vector<char> in;
    for (int32_t i = r.begin; i < r.end; ++i)
      in.push_back(p_.info[static_cast<size_t>(i)].hasInput);
    return build(elems, in, out);
  }

  /// The network of elements in order (each with the operation it stands for; `hasInput`:
  /// whether a block of them reads ST0), or false.
  bool build(const std::vector<Element> &elems, const std::vector<char> &hasInput, Node &out) {
    for (size_t i = 0; i < elems.size(); ++i)
      if (!step(elems[i], hasInput[i] != 0)) return false;
    if (!ms_.empty()) return false;
    if (st_.empty()) {
      if (!zeroDepth_) return false;
      out = series({zeroNode_});
      return true;
    }
    if (st_.size() != 1 || depth(st_[0].net) > kMaxNetworkDepth) return false;
    out = std::move(st_[0].net);
    simplify(out);
    return true;
  }

private:
  struct Ent {
    Node net; ///< a Series
    bool pure = true;
  };
  struct MsMark {
    size_t entry; ///< index in st_ of the entry the MPS was on
    int hop;      ///< the fan-out's place on that entry's open path
  };

  /// The open (last) series of `s`: follow each trailing FanOut into its last branch.
  static Node &open(Node &s, int &hops) {
    hops = 0;
    Node *cur = &s;
    while (!cur->children.empty() && cur->children.back().kind == NodeKind::FanOut) {
      cur = &cur->children.back().children.back();
      ++hops;
    }
    return *cur;
  }

  static Node *fanAt(Node &s, int hop) {
    Node *cur = &s;
    for (int h = 0;; ++h) {
      if (cur->children.empty() || cur->children.back().kind != NodeKind::FanOut) return nullptr;
      Node &f = cur->children.back();
      if (h == hop) return &f;
      cur = &f.children.back();
    }
  }

  void output(Ent &e, Node l) {
    int hops = 0;
    Node &s = open(e.net, hops);
    if (s.children.empty() && hops > 0 && s.entry == Entry::None) {
      Node *f = fanAt(e.net, hops - 1);
      f->children.insert(f->children.end() - 1, series({std::move(l)}, Entry::None));
    } else {
      Node f;
      f.kind = NodeKind::FanOut;
      f.children = {series({std::move(l)}, Entry::None), series({}, Entry::None)};
      s.children.push_back(std::move(f));
    }
    e.pure = false;
  }

  bool branch(Entry how, const Element &el) {
    if (ms_.empty() || st_.empty() || ms_.back().entry != st_.size() - 1) return false;
    Node *f = fanAt(st_.back().net, ms_.back().hop);
    if (!f) return false;
    f->children.push_back(series({}, how));
    f->children.back().link = el;
    if (how == Entry::Mpp) ms_.pop_back();
    return true;
  }

  bool step(const Element &el, bool hasInput) {
    const InstrInfo &ii = instrInfo(el.op);
    switch (ii.stack) {
    case StackRule::Push: {
      if (isLoadContact(el.op)) {
        st_.push_back({series({leaf(NodeKind::Contact, el)})});
        return true;
      }
      Node b = leaf(NodeKind::Box, el); // a status block (AXRDY...): its result from the rail
      b.rail = true;
      st_.push_back({series({std::move(b)})});
      return true;
    }
    case StackRule::Combine: {
      if (st_.empty()) return false;
      Ent &e = st_.back();
      Node c = leaf(NodeKind::Contact, el);
      c.join = Join::Inline;
      if (!isOrForm(el.op)) {
        int hops = 0;
        open(e.net, hops).children.push_back(std::move(c));
        return true;
      }
      return parallel(e, std::move(c));
    }
    case StackRule::BlockPop: {
      if (st_.size() < 2 || !st_.back().pure) return false;
      Node b = unwrap(std::move(st_.back().net));
      st_.pop_back();
      b.join = Join::Block;
      b.link = el;
      Ent &a = st_.back();
      if (el.op == Op::AndBlock) {
        int hops = 0;
        open(a.net, hops).children.push_back(std::move(b));
        return true;
      }
      return parallel(a, std::move(b));
    }
    case StackRule::MpsPush: {
      if (st_.empty()) return false;
      Ent &e = st_.back();
      int hops = 0;
      Node &o = open(e.net, hops);
      if (o.children.empty() && hops > 0 && o.entry == Entry::None) {
        o.entry = Entry::Mps;
        o.link = el;
        ms_.push_back({st_.size() - 1, hops - 1});
      } else {
        Node f;
        f.kind = NodeKind::FanOut;
        f.children = {series({}, Entry::Mps)};
        f.children[0].link = el;
        o.children.push_back(std::move(f));
        ms_.push_back({st_.size() - 1, hops});
      }
      e.pure = false;
      return true;
    }
    case StackRule::MsRead:
      return branch(Entry::Mrd, el);
    case StackRule::MsPop:
      return branch(Entry::Mpp, el);
    case StackRule::Coil:
      if (st_.empty()) return false;
      output(st_.back(), leaf(NodeKind::Coil, el));
      return true;
    case StackRule::Structural:
      return false;
    case StackRule::Block:
      return block(hasInput, ii, el);
    }
    return false;
  }

  bool parallel(Ent &e, Node c) {
    if (!e.pure) return false;
    Node a = unwrap(std::move(e.net));
    if (a.kind == NodeKind::Parallel) {
      a.children.push_back(std::move(c));
    } else {
      Node par;
      par.kind = NodeKind::Parallel;
      par.children.push_back(std::move(a));
      par.children.push_back(std::move(c));
      a = std::move(par);
    }
    e.net = series({std::move(a)});
    return true;
  }

  bool block(bool hasInput, const InstrInfo &ii, const Element &el) {
    Node b = leaf(NodeKind::Box, el);
    if (ii.inputs > 1) {
      if (st_.size() < ii.inputs) return false;
      for (size_t k = st_.size() - ii.inputs; k < st_.size(); ++k) {
        if (!st_[k].pure) return false;
        b.children.push_back(unwrap(std::move(st_[k].net)));
      }
      st_.resize(st_.size() - ii.inputs);
      st_.push_back({series({std::move(b)})});
      return true;
    }
    if (st_.empty()) {
      if (hasInput) return false; // reads an entry from before the rung
      b.rail = true;
      if (ii.output == OutputRule::None) {
        if (zeroDepth_) return false;
        zeroDepth_ = true;
        zeroNode_ = std::move(b);
        return true;
      }
      st_.push_back({series({std::move(b)})});
      return true;
    }
    if (zeroDepth_) return false;
    if (ii.output == OutputRule::None) {
      output(st_.back(), std::move(b));
      return true;
    }
    int hops = 0;
    b.join = Join::Inline;
    open(st_.back().net, hops).children.push_back(std::move(b));
    return true;
  }

  /// Nesting depth of a network (deeper ones stay STL rungs; the JSON reader has a limit).
  static int depth(const Node &n) {
    int d = 0;
    std::vector<std::pair<const Node *, int>> todo{{&n, 1}};
    while (!todo.empty()) {
      auto [x, k] = todo.back();
      todo.pop_back();
      d = std::max(d, k);
      for (const Node &c : x->children) todo.push_back({&c, k + 1});
    }
    return d;
  }

  /// Drops the empty continuation a last output leaves, and a fan-out left with one direct
  /// branch becomes part of its series.
  static void simplify(Node &n) {
    for (Node &c : n.children) simplify(c);
    if (n.kind != NodeKind::Series || n.children.empty()) return;
    Node &last = n.children.back();
    if (last.kind != NodeKind::FanOut) return;
    if (last.children.size() > 1 && last.children.back().children.empty() &&
        last.children.back().entry == Entry::None)
      last.children.pop_back();
    if (last.children.size() == 1 && last.children[0].entry == Entry::None) {
      std::vector<Node> tail = std::move(last.children[0].children);
      n.children.pop_back();
      for (Node &t : tail) n.children.push_back(std::move(t));
    }
  }

  const VerifiedProgram &p_;
  std::vector<Ent> st_;
  std::vector<MsMark> ms_;
  bool zeroDepth_ = false;
  Node zeroNode_;
};

/// An operand without a dialect to write it (a program no front end made): the profile's area
/// name and index.
std::string neutralOperand(const TargetProfile *profile, const Operand &o) {
  if (o.kind == Operand::Kind::Const) return std::to_string(o.value);
  if (o.kind == Operand::Kind::None || !profile) return "";
  std::string t = std::string(profile->area(o.area).name) + std::to_string(o.index);
  return o.kind == Operand::Kind::Bit ? t + "." + std::to_string(o.bit) : t;
}

Element elementOf(const VerifiedProgram &p, int32_t i) {
  return stmtElement(p.stmts[static_cast<size_t>(i)], p.dialect, p.profile, p.symbols);
}

bool sameStatements(const std::vector<Element> &a, const std::vector<Element> &b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (a[i].op != b[i].op || a[i].operands != b[i].operands || a[i].id != b[i].id) return false;
  return true;
}

/// The part a statement belongs to: its name ("init", "PLC1", "PLC2", "S<n>").
std::string partOf(const VerifiedProgram &p, int32_t i) {
  auto in = [&](StmtRange r, Op marker) {
    return (i >= r.begin && i < r.end) || (i == r.end && i < static_cast<int32_t>(p.stmts.size()) &&
                                           p.stmts[static_cast<size_t>(i)].op == marker);
  };
  if (in(p.init, Op::EndInit)) return "init";
  if (in(p.plc1, Op::EndCyclic)) return "PLC1";
  if (in(p.plc2, Op::EndSliced)) return "PLC2";
  for (const Subroutine &s : p.subs)
    if (i >= s.spIndex && i <= s.body.end)
      return std::string(p.profile->area(Area::Subroutine).name) + std::to_string(s.number);
  return "PLC1";
}

/// The rung of `rr` as its user wrote it (Rung::drawing), where the dialect draws an instruction
/// of it otherwise than as the statements the front end made of it (DialectText::drawStmts):
/// those statements become one element with the written form and the operation it stands for,
/// the ones the front end added on its own are left out. Nothing is set when every statement
/// is drawn as itself. For drawings only: no statement is read back from it.
void drawWritten(const VerifiedProgram &p, const RungRange &rr, const std::vector<Element> &mine,
                 Rung &rung) {
  if (!p.dialect || (!p.dialect->drawStmts && p.written.empty())) return;
  const StmtRange r = rr.range;
  const std::span<const Stmt> part(p.stmts.data() + r.begin, static_cast<size_t>(r.end - r.begin));
  Rung::Drawing dr;
  std::vector<Element> drawn;
  std::vector<char> in;
  bool changed = false;
  for (size_t i = 0; i < part.size();) {
    DrawnInstr w;
    if (!p.dialect->drawStmts || !p.dialect->drawStmts(part, i, w) || w.as == DrawAs::Plain) {
      // A box the front end recorded as written, one statement with other operands than the
      // user wrote (FANUC DEC's `nndd` as a value and a mask, GTB as LTB with its operands
      // swapped, MOVE's two mask nibbles as one byte; ir/Program.h WrittenInstr): drawn with
      // the word and parameters as written, where the IR's form would show what the user
      // never wrote (`[LTB 5 D100]` for `GTB D100 5`).
      const Element &e0 = mine[i];
      const StackRule rule = instrInfo(e0.op).stack;
      if (e0.role == WrittenRole::First && !e0.written.empty() &&
          (i + 1 == part.size() || mine[i + 1].role != WrittenRole::Part) &&
          (rule == StackRule::Block || rule == StackRule::Push || rule == StackRule::Combine)) {
        const std::string written =
            p.dialect->drawWritten ? p.dialect->drawWritten(e0.written) : e0.written;
        std::vector<std::string> words;
        for (size_t a = 0; a < written.size();) {
          const size_t b = written.find_first_of(" \t", a);
          const size_t end = b == std::string::npos ? written.size() : b;
          if (end > a) words.push_back(written.substr(a, end - a));
          a = end + 1;
        }
        if (!words.empty()) {
          Element e = e0;
          e.drawn = words[0];
          e.drawnWhole = false;
          e.implied = 0;
          e.operands.assign(words.begin() + 1, words.end());
          e.symbols.assign(e.operands.size(), std::string());
          for (size_t k = 0; k < e.operands.size(); ++k) // a symbol written as such stays one
            for (size_t q = 0; q < e0.operands.size() && q < e0.symbols.size(); ++q)
              if (!e0.symbols[q].empty() && e0.symbols[q] == e.operands[k]) {
                e.operands[k] = e0.operands[q];
                e.symbols[k] = e0.symbols[q];
              }
          changed = true;
          drawn.push_back(std::move(e));
          in.push_back(p.info[static_cast<size_t>(r.begin) + i].hasInput);
          ++i;
          continue;
        }
      }
      drawn.push_back(mine[i]);
      in.push_back(p.info[static_cast<size_t>(r.begin) + i].hasInput);
      ++i;
      continue;
    }
    changed = true;
    const size_t n =
        std::clamp<size_t>(static_cast<size_t>(std::max(w.count, 1)), 1, part.size() - i);
    if (w.as == DrawAs::Hidden) {
      for (size_t k = 0; k < n; ++k) dr.hidden.push_back(mine[i + k].id);
      i += n;
      continue;
    }
    const size_t m = std::min(static_cast<size_t>(std::max(w.main, 0)), n - 1);
    Element e = mine[i + m];
    e.op = w.op;
    e.form = w.as;
    e.drawn = w.text;
    e.drawnWhole = true;
    e.implied = 0;
    e.operands.clear();
    e.symbols.clear();
    e.before = mine[i].before;
    e.comment.clear();
    e.hasComment = false;
    if (!w.operand.empty()) {
      e.operands.push_back(w.operand);
      e.symbols.emplace_back();
    }
    for (size_t k = i; k < i + n; ++k) {
      const Element &g = mine[k];
      if (k != i + m) e.covers.push_back(g.id);
      if (k != i) e.before.insert(e.before.end(), g.before.begin(), g.before.end());
      if (g.hasComment) {
        e.comment += (e.hasComment ? " " : "") + g.comment;
        e.hasComment = true;
      }
      if (!e.operands.empty() && !g.operands.empty() && g.operands[0] == e.operands[0] &&
          !g.symbols.empty() && !g.symbols[0].empty())
        e.symbols[0] = g.symbols[0];
    }
    drawn.push_back(std::move(e));
    in.push_back(w.fromRail ? 0 : 1);
    i += n;
  }
  if (!changed) return;
  Node net;
  if (rr.kind == RungRange::Kind::Marker || drawn.empty()) {
    dr.kind = Rung::Kind::Marker;
    dr.stmts = std::move(drawn);
  } else if (Builder(p).build(drawn, in, net)) {
    dr.kind = Rung::Kind::Ladder;
    dr.network = std::move(net);
  } else {
    dr.kind = Rung::Kind::Stl;
    dr.stmts = std::move(drawn);
  }
  rung.drawing.push_back(std::move(dr));
}

} // namespace

std::vector<std::string> leadLines(const DialectText *d, std::string_view written) {
  std::vector<std::string> lead;
  if (!d || !d->markerLine) return lead;
  for (size_t nl; (nl = written.find('\n')) != std::string_view::npos;
       written.remove_prefix(nl + 1)) {
    std::string_view line = written.substr(0, nl);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (!d->markerLine(line)) break;
    lead.emplace_back(line);
  }
  return lead;
}

Element stmtElement(const Stmt &s, const DialectText *d, const TargetProfile *profile,
                    const std::vector<Symbol> &symbols) {
  Element e;
  e.id = s.id;
  e.loc = s.loc;
  e.op = s.op;
  e.drawn = drawnMnemonic(d, s);
  // A label written whole, with its operand (IL `%L64:`, `SR0:`; DialectText::spellStmt).
  e.drawnWhole = s.operandCount == 1 && e.drawn.size() > 1 && e.drawn.back() == ':';
  for (int k = 0; k < s.operandCount; ++k) {
    const Operand &o = s.ops[static_cast<size_t>(k)];
    if (d && d->implied && d->implied(s.op, k)) e.implied |= 1u << k;
    // In the program's own dialect (an IEC program draws `%I0.1`, not the image address).
    e.operands.push_back(d ? d->formatOperand(o) : neutralOperand(profile, o));
    e.symbols.push_back(o.symbol >= 0 && static_cast<size_t>(o.symbol) < symbols.size()
                            ? symbols[static_cast<size_t>(o.symbol)].name
                            : std::string());
  }
  return e;
}

Networks fromProgram(const VerifiedProgram &prog) {
  Networks nets;
  nets.file = prog.file;
  if (prog.dialect) nets.dialect = prog.dialect->name;
  nets.text = prog.dialect;
  nets.symbols = prog.symbols;
  nets.grids = prog.grids;
  auto n = static_cast<int32_t>(prog.stmts.size());
  std::vector<Element> elems;
  elems.reserve(prog.stmts.size());
  for (int32_t i = 0; i < n; ++i) elems.push_back(elementOf(prog, i));
  for (const WrittenInstr &w : prog.written) {
    if (w.count <= 0 || w.first < 0 || w.first + w.count > n) continue;
    for (int32_t i = w.first; i < w.first + w.count; ++i)
      elems[static_cast<size_t>(i)].role = i == w.first ? WrittenRole::First : WrittenRole::Part;
    elems[static_cast<size_t>(w.first)].written = w.text;
  }
  // Comments: the block before a rung's first statement is the rung comment; others stay with
  // their statement.
  // A comment line holds no line break (the JSON and text forms are line based): a lone CR in a
  // comment, or an IL comment over several lines, becomes several comment lines, or blanks in a
  // trailing comment.
  std::vector<std::vector<std::string>> before(prog.stmts.size() + 1);
  for (const Comment &c : prog.comments) {
    if (c.stmt < 0 || c.stmt > n) continue;
    if (c.trailing && c.stmt < n) {
      std::string t = c.text;
      std::replace_if(
          t.begin(), t.end(), [](char ch) { return ch == '\r' || ch == '\n'; }, ' ');
      elems[static_cast<size_t>(c.stmt)].comment = std::move(t);
      elems[static_cast<size_t>(c.stmt)].hasComment = true;
      continue;
    }
    std::string_view t = c.text;
    for (size_t b; (b = t.find_first_of("\r\n")) != std::string_view::npos; t.remove_prefix(b + 1))
      before[static_cast<size_t>(c.stmt)].emplace_back(t.substr(0, b));
    before[static_cast<size_t>(c.stmt)].emplace_back(t);
  }
  nets.trailingComments = before[static_cast<size_t>(n)];
  for (const RungRange &rr : prog.rungs) {
    Rung rung;
    StmtRange r = rr.range;
    rung.comment = std::move(before[static_cast<size_t>(r.begin)]);
    for (int32_t i = r.begin + 1; i < r.end; ++i)
      elems[static_cast<size_t>(i)].before = std::move(before[static_cast<size_t>(i)]);
    std::vector<Element> mine(elems.begin() + r.begin, elems.begin() + r.end);
    drawWritten(prog, rr, mine, rung);
    if (!mine.empty() && mine[0].role == WrittenRole::First)
      rung.lead = leadLines(prog.dialect, mine[0].written);
    if (rr.kind == RungRange::Kind::Marker) {
      rung.kind = Rung::Kind::Marker;
      rung.stmts = std::move(mine);
    } else {
      Node net;
      std::vector<Element> back;
      std::string err;
      if (Builder(prog).build(r, mine, net) && rungStatements(net, back, err, prog.dialect) &&
          sameStatements(back, mine)) {
        rung.kind = Rung::Kind::Ladder;
        rung.network = std::move(net);
      } else {
        rung.kind = Rung::Kind::Stl;
        rung.stmts = std::move(mine);
      }
    }
    std::string part = partOf(prog, r.begin);
    if (nets.parts.empty() || nets.parts.back().name != part) nets.parts.push_back({part, {}});
    nets.parts.back().rungs.push_back(std::move(rung));
  }
  return nets;
}

RungCounts countRungs(const Networks &nets) {
  RungCounts c;
  for (const Part &p : nets.parts)
    for (const Rung &r : p.rungs)
      (r.kind == Rung::Kind::Ladder ? c.ladder : r.kind == Rung::Kind::Stl ? c.stl : c.marker)++;
  return c;
}

} // namespace lj::ladder

// Networks -> statements (ladder-view-research.md 1.8): a post-order walk. A contact takes the
// LD/AND/OR form of its place; a sub-network joined in series or parallel is its own LD chain
// then ANB/ORB; a fan-out is entered directly (outputs, then the continuation) or through
// MPS/MRD/MPP. Join and entry hints, when present, choose between equivalent forms.
#include "ladder/Network.h"

namespace lj::ladder {

namespace {

enum class Pos : uint8_t { Start, Series, Parallel };

Op contactOp(ContactKind k, Pos pos) {
  static constexpr Op kTable[5][3] = {{Op::Load, Op::And, Op::Or},
                                      {Op::LoadNot, Op::AndNot, Op::OrNot},
                                      {Op::LoadRise, Op::AndRise, Op::OrRise},
                                      {Op::LoadFall, Op::AndFall, Op::OrFall},
                                      {Op::LoadTrue, Op::LoadTrue, Op::LoadTrue}};
  return kTable[static_cast<int>(k)][static_cast<int>(pos)];
}

bool isOutput(const Node &n) {
  return n.kind == NodeKind::Coil ||
         (n.kind == NodeKind::Box && instrInfo(n.elem.op).stack == StackRule::Block &&
          instrInfo(n.elem.op).output == OutputRule::None && instrInfo(n.elem.op).inputs <= 1);
}

/// A Box whose result is a new ST entry (its own inputs or the rail), not an extension.
bool isBlockBox(const Node &n) {
  return n.kind == NodeKind::Box && (n.rail || !n.children.empty());
}

class Emitter {
public:
  Emitter(std::vector<Element> &out, std::string &error, const DialectText *d)
      : out_(out), error_(error), d_(d) {}

  bool series(const Node &s, bool start, const std::string &path) {
    if (s.kind != NodeKind::Series) return fail(path, "expected a series");
    if (start && s.children.empty()) return fail(path, "empty series");
    for (size_t i = 0; i < s.children.size(); ++i) {
      Pos pos = (start && i == 0) ? Pos::Start : Pos::Series;
      if (!child(s.children[i], pos, path + "/" + std::to_string(i))) return false;
      if (isOutput(s.children[i]) && i + 1 < s.children.size())
        return fail(path + "/" + std::to_string(i + 1),
                    "nothing may follow an output in series (use a fan-out)");
    }
    return true;
  }

private:
  bool fail(const std::string &path, const std::string &msg) {
    error_ = "network element " + (path.empty() ? std::string("/") : path) + ": " + msg;
    return false;
  }

  void emit(const Element &e, Op op) {
    out_.push_back(e);
    if (op != e.op) out_.back().drawn.clear(); // the word of another form (RD for an AND place)
    out_.back().op = op;
  }

  /// The ANB/ORB/MPS/MRD/MPP a place implies, with the id and comments the node recorded.
  void join(Op op, const Node &n) {
    out_.push_back(n.link);
    out_.back().op = op;
    out_.back().operands.clear();
    out_.back().symbols.clear();
  }

  bool child(const Node &n, Pos pos, const std::string &path) {
    switch (n.kind) {
    case NodeKind::Contact: {
      bool block = pos != Pos::Start && (n.join == Join::Block || n.contact == ContactKind::True);
      emit(n.elem, contactOp(n.contact, block ? Pos::Start : pos));
      if (block) join(pos == Pos::Series ? Op::AndBlock : Op::OrBlock, n);
      return true;
    }
    case NodeKind::Series:
    case NodeKind::Parallel:
      if (!(n.kind == NodeKind::Series ? series(n, true, path) : parallel(n, path))) return false;
      if (pos != Pos::Start) join(pos == Pos::Series ? Op::AndBlock : Op::OrBlock, n);
      return true;
    case NodeKind::Coil:
      if (pos == Pos::Start) return fail(path, "an output needs a network before it");
      if (pos == Pos::Parallel) return fail(path, "an output cannot be a parallel branch");
      emit(n.elem, n.elem.op);
      return true;
    case NodeKind::Box:
      return box(n, pos, path);
    case NodeKind::FanOut:
      if (pos != Pos::Series) return fail(path, "a fan-out must follow a network in series");
      return fanOut(n, path);
    }
    return false;
  }

  bool parallel(const Node &p, const std::string &path) {
    if (p.children.size() < 2) return fail(path, "a parallel needs two branches or more");
    for (size_t i = 0; i < p.children.size(); ++i) {
      const Node &c = p.children[i];
      std::string at = path + "/" + std::to_string(i);
      if (isOutput(c)) return fail(at, "an output cannot be a parallel branch");
      if (!child(c, i == 0 ? Pos::Start : Pos::Parallel, at)) return false;
    }
    return true;
  }

  bool box(const Node &n, Pos pos, const std::string &path) {
    const InstrInfo &ii = instrInfo(n.elem.op);
    if (ii.stack != StackRule::Block && !(ii.stack == StackRule::Push && n.rail))
      return fail(path, std::string(spelling(d_, ii.op)) + " is no box");
    if (!n.children.empty()) {
      if (n.children.size() != ii.inputs)
        return fail(path, std::string(spelling(d_, ii.op)) + " takes " + std::to_string(ii.inputs) +
                              " inputs, the box has " + std::to_string(n.children.size()));
      for (size_t i = 0; i < n.children.size(); ++i)
        if (!child(n.children[i], Pos::Start, path + "/in" + std::to_string(i))) return false;
    } else if (n.rail) {
      if (ii.inputs > 1)
        return fail(path, std::string(spelling(d_, ii.op)) + " needs its " +
                              std::to_string(ii.inputs) + " inputs");
    } else if (pos == Pos::Start || ii.inputs > 1) {
      return fail(path, std::string(spelling(d_, ii.op)) + " needs its input network");
    }
    if (pos == Pos::Parallel && !isBlockBox(n))
      return fail(path, "a box in parallel needs its own inputs");
    emit(n.elem, n.elem.op);
    if (pos != Pos::Start && isBlockBox(n)) {
      if (ii.output == OutputRule::None && ii.inputs <= 1)
        return fail(path, "an output box with the rail as input must start its rung");
      join(pos == Pos::Series ? Op::AndBlock : Op::OrBlock, n);
    }
    return true;
  }

  static bool outputsOnly(const Node &b) {
    for (const Node &c : b.children)
      if (!isOutput(c)) return false;
    return true;
  }

  bool fanOut(const Node &f, const std::string &path) {
    if (f.children.empty()) return fail(path, "empty fan-out");
    size_t m = f.children.size();
    bool direct = true; // canonical: direct when every branch but the last is outputs only
    for (size_t i = 0; i + 1 < m; ++i) direct = direct && outputsOnly(f.children[i]);
    for (size_t i = 0; i < m; ++i) {
      const Node &b = f.children[i];
      std::string at = path + "/" + std::to_string(i);
      Entry e = b.entry;
      if (e == Entry::Auto)
        e = direct ? Entry::None : i == 0 ? Entry::Mps : i + 1 == m ? Entry::Mpp : Entry::Mrd;
      if (e == Entry::None && i + 1 < m && !outputsOnly(b))
        return fail(at, "a branch entered directly must hold outputs only, unless it is last");
      if (e == Entry::Mps) ms_.push_back(0);
      if (e == Entry::Mrd || e == Entry::Mpp) {
        if (ms_.empty()) return fail(at, "a branch read/pop without a branch push before it");
        if (e == Entry::Mpp) ms_.pop_back();
      }
      if (e == Entry::Mps || e == Entry::Mrd || e == Entry::Mpp)
        join(e == Entry::Mps   ? Op::BranchPush
             : e == Entry::Mrd ? Op::BranchRead
                               : Op::BranchPop,
             b);
      if (!series(b, false, at)) return false;
    }
    return true;
  }

  std::vector<Element> &out_;
  std::string &error_;
  const DialectText *d_;
  std::vector<int> ms_;

public:
  bool balanced() const { return ms_.empty(); }
};

} // namespace

bool rungStatements(const Node &network, std::vector<Element> &out, std::string &error,
                    const DialectText *d) {
  Emitter em(out, error, d);
  if (!em.series(network, true, "")) return false;
  if (!em.balanced()) {
    error = "network: a branch push has no branch pop after it";
    return false;
  }
  return true;
}

bool toStatements(const Networks &nets, std::vector<Element> &out, std::string &error,
                  std::vector<std::string> *where) {
  for (size_t p = 0; p < nets.parts.size(); ++p) {
    const Part &part = nets.parts[p];
    for (size_t r = 0; r < part.rungs.size(); ++r) {
      const Rung &rung = part.rungs[r];
      size_t first = out.size();
      if (rung.kind == Rung::Kind::Ladder) {
        std::string err;
        if (!rungStatements(rung.network, out, err, nets.text)) {
          error = part.name + " rung " + std::to_string(r + 1) + ": " + err;
          return false;
        }
      } else {
        out.insert(out.end(), rung.stmts.begin(), rung.stmts.end());
      }
      if (where) {
        std::string at = part.name + " rung " + std::to_string(r + 1) + " element ";
        for (size_t k = first; k < out.size(); ++k)
          where->push_back(at + std::to_string(k - first + 1));
      }
      if (out.size() > first) {
        auto &b = out[first].before;
        b.insert(b.begin(), rung.comment.begin(), rung.comment.end());
        out[first].lead = rung.lead;
      }
    }
  }
  return true;
}

} // namespace lj::ladder

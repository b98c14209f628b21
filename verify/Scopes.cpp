// Per-unit checks (a main part or a subroutine): loop bodies and scopes, labels and jumps, the
// static ST/MS depth before every statement, MPS pairing, double coils, unreachable code and
// CALL sites (DIALECT.md 2, 3, 6; dialect-notes "Stacks and blocks", "Flow", "Double coils").
#include "verify/VerifierInternal.h"

#include "ir/StackEffect.h"

#include <algorithm>
#include <string_view>
#include <unordered_map>

namespace lj::verifier {

namespace {

std::string lineText(const Stmt &s) { return "line " + std::to_string(s.loc.line); }
/// A label as the dialect writes it ("L3").
std::string label(const Context &cx, int32_t n) {
  return std::string(cx.tp.area(Area::Label).name) + std::to_string(n);
}

class UnitChecker {
public:
  UnitChecker(Context &cx, size_t unitIndex)
      : cx_(cx), unit_(cx.units[unitIndex]), calls_(cx.calls[unitIndex]) {}

  void run() {
    scopes();
    stacks();
  }

private:
  // Pass 1: LOOP/NEXT pairing gives every statement a scope id (part or subroutine body = the
  // unit's scope, each loop body a new one); labels are collected per unit.
  void scopes() {
    auto len = static_cast<size_t>(unit_.body.end - unit_.body.begin);
    scope_.assign(len, 0);
    std::vector<int32_t> open; // LOOP indices
    int32_t cur = 0, next = 1;
    std::vector<int32_t> scopeOfLoop;
    for (int32_t i = unit_.body.begin; i < unit_.body.end; ++i) {
      const Stmt &s = cx_.stmt(i);
      scope_[rel(i)] = cur;
      if (s.op == Op::LoopBegin) {
        open.push_back(i);
        cur = next++;
      } else if (s.op == Op::LoopEnd) {
        if (open.empty()) {
          cx_.error(s.loc, "LJ1007",
                    std::string(cx_.spell(Op::LoopEnd)) + " without " + cx_.spell(Op::LoopBegin));
          continue;
        }
        int32_t loop = open.back();
        open.pop_back();
        cx_.info(loop).target = i;
        cx_.info(i).target = loop;
        cur = scope_[rel(loop)];
        scope_[rel(i)] = cur;
      } else if (s.op == Op::Label) {
        int32_t n = s.ops[0].index;
        auto [it, fresh] = labels_.try_emplace(n, i);
        if (!fresh)
          cx_.error(s.ops[0].loc, "LJ1008",
                    "duplicate label " + label(cx_, n) + " (first on " +
                        lineText(cx_.stmt(it->second)) + ")");
      }
    }
    for (int32_t loop : open)
      cx_.error(cx_.stmt(loop).loc, "LJ1009",
                std::string(cx_.spell(Op::LoopBegin)) + " without " + cx_.spell(Op::LoopEnd));
  }

  size_t rel(int32_t i) const { return static_cast<size_t>(i - unit_.body.begin); }

  void jump(int32_t i) {
    const Stmt &s = cx_.stmt(i);
    int32_t n = s.ops[0].index;
    auto it = labels_.find(n);
    if (it == labels_.end()) {
      cx_.error(s.ops[0].loc, "LJ1010", "missing label " + label(cx_, n));
      return;
    }
    int32_t lbl = it->second;
    if (scope_[rel(lbl)] != scope_[rel(i)]) {
      cx_.error(s.ops[0].loc, "LJ1011",
                std::string(cx_.spell(Op::Jump)) + " " + label(cx_, n) +
                    " crosses a scope boundary (" + cx_.spell(Op::Label) + " " + label(cx_, n) +
                    " on " + lineText(cx_.stmt(lbl)) + " is not in the same loop body)");
      return;
    }
    cx_.info(i).target = lbl;
    cx_.info(i).backward = lbl < i;
    cx_.jumpSpans.emplace_back(std::min(lbl, i), std::max(lbl, i));
  }

  void call(int32_t i) {
    const Stmt &s = cx_.stmt(i);
    int32_t n = s.ops[0].index;
    int16_t sub = cx_.prog.subByNumber[static_cast<size_t>(n)];
    if (sub < 0) {
      cx_.error(s.ops[0].loc, "LJ1012",
                "undefined subroutine " + std::string(cx_.tp.area(Area::Subroutine).name) +
                    std::to_string(n));
      return;
    }
    cx_.info(i).target = sub;
    calls_.push_back({i, sub});
  }

  void underflow(const Stmt &s, const std::string &what) {
    cx_.error(s.loc, "LJ1013", "stack underflow: " + what);
  }

  /// Every MPS still open at a stack reset is an error, reported at the MPS.
  void closeMps(const std::string &where) {
    for (int32_t mps : mps_)
      if (mps >= 0)
        cx_.error(cx_.stmt(mps).loc, "LJ1014",
                  "unclosed " + std::string(cx_.spell(Op::BranchPush)) + ": MS is not empty at " +
                      where);
    mps_.clear();
  }

  void doubleCoil(int32_t i) {
    const Operand &o = cx_.stmt(i).ops[0];
    // A front end's own scratch (an area named with `~`: ClassicLadder's cell states, IL's
    // temporaries) is written wherever the front end needs it; the user never wrote it.
    const char *areaName = cx_.tp.area(o.area).name;
    if (areaName && std::string_view(areaName).find('~') != std::string_view::npos) return;
    // Area, element and bit each in a field of their own: an element number of 4096 and more
    // (FANUC E4096, D) must not reach the next area's elements.
    const uint64_t key = static_cast<uint64_t>(o.area) << 40 |
                         static_cast<uint64_t>(static_cast<uint32_t>(o.index)) << 8 |
                         static_cast<uint8_t>(o.bit);
    auto [it, fresh] = coils_.try_emplace(key, i);
    if (fresh) return;
    const Stmt &first = cx_.stmt(it->second);
    std::string a = cx_.operandText(o);
    cx_.warning(o.loc, "LJ1015", "double coil: " + a + " is also written on " + lineText(first));
    cx_.note(first.ops[0].loc, "first write of " + a + " is here");
  }

  /// Block checks at ST depth `d` (the depth change is ir/StackEffect.h's, applied by stacks()).
  void block(int32_t i, const InstrInfo &ii, int32_t d) {
    const Stmt &s = cx_.stmt(i);
    StmtInfo &inf = cx_.info(i);
    inf.hasInput = d > 0;
    if (ii.inputs > 1) {
      // Multi-input blocks pop k (first loaded = input 1) and push their output.
      if (d < ii.inputs)
        underflow(s, std::string(cx_.spell(ii.op)) + " needs " + std::to_string(ii.inputs) +
                         " inputs on ST, found " + std::to_string(d));
    } else {
      if (ii.input == InputRule::Required && d == 0)
        cx_.warning(s.loc, "LJ1016",
                    std::string(cx_.spell(ii.op)) +
                        ": block needs an input; ST is empty, input is 1");
    }
    if (s.op == Op::Jump) jump(i);
    if (s.op == Op::Call) call(i);
    if (s.op == Op::Return && unit_.kind != Unit::Kind::Sub)
      cx_.error(s.loc, "LJ1017", std::string(cx_.spell(Op::Return)) + " outside a subroutine");
  }

  /// Stack effect of the dropped lines just before statement `i` (or the unit's end), without
  /// any diagnostic: their own error is reported already, follow-on errors would be noise.
  void applyDropped(int32_t i, int32_t &d, int32_t &ms) {
    while (dropIt_ != cx_.dropped.end() && dropIt_->before == i) {
      const InstrInfo &ii = instrInfo((dropIt_++)->op);
      // Structure is not guessed from a broken line: a dropped LBL/LOOP/NEXT/marker keeps the
      // stacks as they are; every other rule moves them as ir/StackEffect.h says.
      if (ii.stack == StackRule::Structural) continue;
      const StackEffect e = stackEffect(ii, d);
      d = e.after(d);
      if (e.msDelta > 0) {
        ++ms;
        mps_.push_back(-1);
      } else if (e.msDelta < 0 && ms > 0) {
        --ms;
        mps_.pop_back();
      }
    }
  }

  // Pass 2: one linear walk. LBL/LOOP/NEXT empty both stacks, so the depth at every statement
  // is the same on every path that reaches it.
  void stacks() {
    int32_t d = 0, ms = 0;
    bool dead = false; // after an unconditional RETN or JMP, until the next LBL/NEXT
    dropIt_ = std::lower_bound(cx_.dropped.begin(), cx_.dropped.end(), unit_.body.begin,
                               [](const DroppedStmt &x, int32_t i) { return x.before < i; });
    for (int32_t i = unit_.body.begin; i < unit_.body.end; ++i) {
      applyDropped(i, d, ms);
      const Stmt &s = cx_.stmt(i);
      const InstrInfo &ii = instrInfo(s.op);
      StmtInfo &inf = cx_.info(i);
      inf.depth = d;
      inf.msDepth = ms;
      if (s.op == Op::Label || s.op == Op::LoopEnd) dead = false;
      if (dead) {
        cx_.warning(s.loc, "LJ1018", "unreachable code");
        dead = false;
      }
      // The depth after it is ir/StackEffect.h's; the cases check and report.
      const StackEffect effect = stackEffect(ii, d);
      switch (ii.stack) {
      case StackRule::Push:
        break;
      case StackRule::Combine:
        if (d < 1) underflow(s, std::string(cx_.spell(ii.op)) + " with an empty ST");
        break;
      case StackRule::BlockPop:
        if (d < 2)
          underflow(s, std::string(cx_.spell(ii.op)) + " needs 2 entries on ST, found " +
                           std::to_string(d));
        break;
      case StackRule::MpsPush:
        if (d < 1) underflow(s, std::string(cx_.spell(Op::BranchPush)) + " with an empty ST");
        ++ms;
        mps_.push_back(i);
        break;
      case StackRule::MsRead:
      case StackRule::MsPop:
        if (ms < 1) {
          underflow(s, std::string(cx_.spell(ii.op)) + " with an empty MS");
        } else if (ii.stack == StackRule::MsPop) {
          --ms;
          mps_.pop_back();
        }
        break;
      case StackRule::Coil:
        if (d < 1) underflow(s, std::string(cx_.spell(ii.op)) + " with an empty ST");
        if (s.op == Op::Coil || s.op == Op::CoilNot) doubleCoil(i);
        break;
      case StackRule::Structural:
        if (s.op == Op::Label || s.op == Op::LoopBegin || s.op == Op::LoopEnd)
          closeMps(std::string(cx_.spell(s.op)) + " (" + lineText(s) + ")");
        ms = 0;
        break;
      case StackRule::Block: {
        bool uncond = d == 0 || (i > unit_.body.begin && cx_.stmt(i - 1).op == Op::LoadTrue);
        block(i, ii, d);
        if ((s.op == Op::Jump || s.op == Op::JumpOut || s.op == Op::Return) && uncond) dead = true;
        break;
      }
      }
      d = effect.after(d);
      cx_.prog.maxDepth = std::max({cx_.prog.maxDepth, inf.depth, d});
      cx_.prog.maxMsDepth = std::max({cx_.prog.maxMsDepth, inf.msDepth, ms});
    }
    applyDropped(unit_.body.end, d, ms);
    closeMps(endName());
  }

  std::string endName() const {
    switch (unit_.kind) {
    case Unit::Kind::Init:
      return "the end of the init part";
    case Unit::Kind::Plc1:
      return "the end of PLC1";
    case Unit::Kind::Plc2:
      return "the end of PLC2";
    case Unit::Kind::Sub:
      break;
    }
    int32_t end = unit_.body.end;
    if (end < static_cast<int32_t>(cx_.prog.stmts.size()) && cx_.stmt(end).op == Op::SubEnd)
      return std::string(cx_.spell(Op::SubEnd)) + " (" + lineText(cx_.stmt(end)) + ")";
    return "the end of the subroutine";
  }

  Context &cx_;
  const Unit &unit_;
  std::vector<CallSite> &calls_;
  std::vector<int32_t> scope_; // per statement of the unit
  std::unordered_map<int32_t, int32_t> labels_;
  std::unordered_map<uint64_t, int32_t> coils_;
  std::vector<int32_t> mps_; // open MPS statements (-1: a dropped line's MPS)
  std::vector<DroppedStmt>::const_iterator dropIt_;
};

} // namespace

void checkUnit(Context &cx, size_t unitIndex) { UnitChecker(cx, unitIndex).run(); }

} // namespace lj::verifier

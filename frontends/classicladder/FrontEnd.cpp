// The ClassicLadder front end: a project's rungs as IR statements (FrontEnd.h). The cell states
// live in the profile's ExtraRelay bytes: for rung slot k (in the order the rungs are first met)
// the power of cell (x, y) is bit k * 2 * W * H + x * H + y and an edge contact's previous value
// the bit W * H further (oracle/classicladder/RefScan.cpp keeps the same two bytes per cell).
#include "frontends/classicladder/FrontEnd.h"

#include "frontends/classicladder/Reader.h"
#include "profiles/classicladder/ClassicLadderProfile.h"

#include <algorithm>
#include <map>

namespace lj::classicladder {

namespace {

const char *spell(Op op) {
  switch (op) {
  case Op::Load:
    return "LD";
  case Op::LoadNot:
    return "LDN";
  case Op::LoadTrue:
    return "LD 1";
  case Op::And:
    return "AND";
  case Op::AndNot:
    return "ANDN";
  case Op::Or:
    return "OR";
  case Op::Coil:
    return "COIL";
  case Op::CoilNot:
    return "COILN";
  case Op::Set:
    return "SET";
  case Op::Reset:
    return "RESET";
  case Op::Move:
    return "MOVE";
  case Op::Add:
    return "ADD";
  case Op::Subtract:
    return "SUB";
  case Op::Multiply:
    return "MUL";
  case Op::Divide:
    return "DIV";
  case Op::BitAnd:
    return "AND_W";
  case Op::BitOr:
    return "OR_W";
  case Op::BitXor:
    return "XOR_W";
  case Op::CompareLt:
    return "LT";
  case Op::CompareLe:
    return "LE";
  case Op::CompareEq:
    return "EQ";
  case Op::Jump:
    return "JUMP";
  case Op::Label:
    return "RUNG";
  case Op::Call:
    return "CALL";
  case Op::SubBegin:
    return "SR";
  case Op::SubEnd:
    return "END_SR";
  case Op::EndInit:
    return "END_INIT";
  case Op::EndCyclic:
    return "END_SCAN";
  case Op::EndSliced:
    return "END";
  case Op::ClClock:
    return "CLOCK";
  case Op::ClTimer:
    return "TIMER";
  case Op::ClMonostable:
    return "MONOSTABLE";
  case Op::ClCounter:
    return "COUNTER";
  case Op::ClIecTimer:
    return "TIMER_IEC";
  default:
    return nullptr;
  }
}

std::string formatOperand(const Operand &o) {
  if (o.kind == Operand::Kind::Const) return std::to_string(o.value);
  const int32_t n =
      o.kind == Operand::Kind::Bit ? o.index * 8 + std::max<int8_t>(o.bit, 0) : o.index;
  switch (o.area) {
  case Area::Input:
    return "%I" + std::to_string(n);
  case Area::Output:
    return "%Q" + std::to_string(n);
  case Area::Relay:
    return "%B" + std::to_string(n);
  case Area::KeepRelay:
    return "%S" + std::to_string(n);
  case Area::DWord:
    return (n < kWords ? "%W" : "tmp") + std::to_string(n);
  case Area::Word:
    return "%IW" + std::to_string(n);
  case Area::Retained:
    return "%QW" + std::to_string(n);
  case Area::Param:
    return "%IF" + std::to_string(n);
  case Area::NcControl:
    return "%QF" + std::to_string(n);
  case Area::Label:
    return "L" + std::to_string(o.index);
  case Area::Subroutine:
    return "SR" + std::to_string(o.index);
  case Area::ExtraRelay:
    return "cell" + std::to_string(n); // a rung cell's state, never written by a user
  case Area::TimerData:
    return "blk" + std::to_string(o.index); // a block's word (ir/ClBlocks.h)
  default:
    return "?";
  }
}

const DialectText kText{"classicladder", spell, formatOperand};

Operand bitOperand(Area a, int32_t n) {
  Operand o;
  o.kind = Operand::Kind::Bit;
  o.area = a;
  o.index = n / 8;
  o.bit = static_cast<int8_t>(n % 8);
  return o;
}

Operand blockWord(int32_t index) {
  Operand o;
  o.kind = Operand::Kind::Reg;
  o.area = Area::TimerData;
  o.index = index;
  return o;
}
/// A block's flag word read as a bit (it holds 0 or 1).
Operand blockFlag(int32_t index) {
  Operand o = blockWord(index);
  o.kind = Operand::Kind::Bit;
  o.bit = 0;
  return o;
}
/// The first word of block `n` of element `type` (10 %T, 11 %M, 12 %C, 13 %TM).
int32_t blockAt(int32_t type, int32_t n) {
  using namespace clblocks;
  switch (type) {
  case 10:
    return kTimerAt + n * kTimerWords;
  case 11:
    return kMonoAt + n * kMonoWords;
  case 12:
    return kCounterAt + n * kCounterWords;
  default:
    return kIecAt + n * kIecWords;
  }
}
/// How many blocks of element `type` the profile holds.
int32_t blockCount(int32_t type) {
  return type == 10 ? kOldTimers : type == 11 ? kMonostables : type == 12 ? kCounters : kIecTimers;
}
/// The time base in ms of old timer (10) or monostable (11) `n`: timers.csv / monostables.csv,
/// else 1 s as classicladder_rt leaves a block without parameters.
int32_t baseMsOf(const Project &p, int32_t type, int32_t n) {
  const std::vector<TimerParams> &v = type == 10 ? p.timers : p.monostables;
  return n >= 0 && static_cast<size_t>(n) < v.size() ? v[static_cast<size_t>(n)].baseMs : 1000;
}
/// Whether variable `type` is a block's output or value that only the block writes: a coil or
/// an operate block on it does nothing (calc.c WriteVar has no case for it).
bool readOnlyBlockVar(int32_t type) {
  return type == 10 || type == 11 || type == 20 || type == 25 || type == 26 || type == 27 ||
         type == 231 || type == 241;
}

/// ExtraRelay bits at the end of the cell bytes kept for the expression code (flag()).
constexpr int32_t kScratchBits = 8;
/// Labels (one per rung placed in a section) and sub-routines the profile holds
/// (profiles/classicladder/Areas.cpp).
constexpr int32_t kLabels = 4096, kSubroutines = 64;
/// The label at the end of the cyclic part, where a stopped ladder goes (the last one).
constexpr int32_t kEndLabel = kLabels - 1;

class RungMapper {
public:
  RungMapper(const Project &p, ParsedProgram &out, Diagnostics &diags)
      : p_(p), out_(out), diags_(diags) {}

  void run() {
    powerUp();
    emit(Op::EndInit, {});
    emit(Op::ClClock, {blockWord(kClockAt), konst(clblocks::kClockScan)});
    emit(Op::Load, {blockFlag(kStoppedAt)}); // a stopped ladder does nothing
    emit(Op::Jump, {label(kEndLabel)});
    std::vector<const Section *> order;
    for (const Section &s : p_.sections) order.push_back(&s);
    std::stable_sort(order.begin(), order.end(),
                     [](const Section *a, const Section *b) { return a->number < b->number; });
    for (const Section *s : order) {
      if (s->language == Language::Sequential) {
        refuse("section " + std::to_string(s->number) + " '" + s->name +
               "': sequential (Grafcet) sections are not supported yet by the classicladder "
               "front end");
        continue;
      }
      if (s->subRoutine >= 0) continue; // runs only when a CALL coil calls it (below)
      emit(Op::LoadTrue, {});           // a section pass counts its jumps from 0
      emit(Op::Move, {konst(0), blockWord(kJumpsAt)});
      section(*s);
    }
    emit(Op::Label, {label(kEndLabel)});
    emit(Op::EndCyclic, {});
    emit(Op::EndSliced, {});
    // sub-routine sections: a CALL coil runs the first section with its number (calc.c)
    std::map<int32_t, const Section *> subs;
    for (const Section &s : p_.sections)
      if (s.subRoutine >= 0 && !subs.count(s.subRoutine)) subs[s.subRoutine] = &s;
    for (const auto &[n, s] : subs) {
      if (s->language != Language::Ladder || n >= kSubroutines) continue; // calls do nothing
      Operand sr;
      sr.kind = Operand::Kind::Reg;
      sr.area = Area::Subroutine;
      sr.index = n;
      emit(Op::SubBegin, {sr});
      section(*s);
      emit(Op::SubEnd, {});
    }
  }

private:
  /// The init part: the scan clock's first period and the blocks' presets as classicladder_rt
  /// loads them (an old timer's remaining time starts at its preset: PrepareTimers).
  void powerUp() {
    using namespace clblocks;
    emit(Op::ClClock, {blockWord(kClockAt), konst(kClockPowerUp)});
    auto set = [&](int32_t word, int64_t v) {
      if (v == 0) return;
      emit(Op::LoadTrue, {});
      emit(Op::Move, {konst(static_cast<int32_t>(static_cast<uint32_t>(v))), blockWord(word)});
    };
    for (size_t i = 0; i < p_.timers.size() && i < size_t{kOldTimers}; ++i) {
      const int64_t ms = int64_t{p_.timers[i].preset} * p_.timers[i].baseMs;
      set(blockAt(10, int32_t(i)) + kTimerPresetMs, ms);
      set(blockAt(10, int32_t(i)) + kTimerValueMs, ms);
    }
    for (size_t i = 0; i < p_.monostables.size() && i < size_t{kMonostables}; ++i)
      set(blockAt(11, int32_t(i)) + kMonoPresetMs,
          int64_t{p_.monostables[i].preset} * p_.monostables[i].baseMs);
    for (size_t i = 0; i < p_.counterPresets.size() && i < size_t{kCounters}; ++i)
      set(blockAt(12, int32_t(i)) + kCounterPreset, p_.counterPresets[i]);
    for (size_t i = 0; i < p_.timersIec.size() && i < size_t{kIecTimers}; ++i)
      set(blockAt(13, int32_t(i)) + kIecPreset, p_.timersIec[i].preset);
  }

  void refuse(const std::string &msg) {
    if (diags_.errorCount() < 50) diags_.error({}, msg);
  }
  /// A refused cell, located at its row's line of the project file where the reader knows it.
  void refuseCell(int32_t rung, int x, int y, const std::string &what) {
    SourceLoc loc{};
    auto it = p_.rungs.find(rung);
    if (it != p_.rungs.end() && y >= 0 && static_cast<size_t>(y) < it->second.rowLines.size() &&
        it->second.rowLines[static_cast<size_t>(y)] > 0)
      loc = {it->second.rowLines[static_cast<size_t>(y)], 1};
    if (diags_.errorCount() < 50)
      diags_.error(loc, "rung " + std::to_string(rung) + " row " + std::to_string(y) + " column " +
                            std::to_string(x) + ": " + what);
  }

  void emit(Op op, std::initializer_list<Operand> ops) {
    Stmt s;
    s.op = op;
    s.loc = {static_cast<int32_t>(rung_ + 1), static_cast<int32_t>(1)};
    s.operandCount = static_cast<uint8_t>(ops.size());
    size_t k = 0;
    for (const Operand &o : ops) s.ops[k++] = o;
    s.id = static_cast<StmtId>(out_.stmts.size());
    out_.stmts.push_back(s);
  }

  /// Whether a cell writes DynamicOutput (FREE, coils and the editor codes never do).
  static bool writesPower(const Cell &c) {
    return (c.type >= 1 && c.type <= 4) || (c.type >= 9 && c.type <= 13) || c.type == 20 ||
           c.type == 99; // 99: the cells a timer or counter writes below its first row
  }

  Operand power(int x, int y) const { return bitOperand(Area::ExtraRelay, base_ + x * h_ + y); }
  Operand previous(int x, int y) const {
    return bitOperand(Area::ExtraRelay, base_ + w_ * h_ + x * h_ + y);
  }

  /// Pushes StateOnLeft(x, y): the rail in column 0, else the OR of the powers of the vertical
  /// group (column x's links) in column x - 1; 0 when no cell there writes its power.
  void loadLeft(const Rung &r, int x, int y) {
    if (x <= 0) {
      emit(Op::LoadTrue, {});
      return;
    }
    int top = y, bottom = y;
    while (top > 0 && r.cells[x][top].connectedWithTop) --top;
    while (bottom + 1 < h_ && r.cells[x][bottom + 1].connectedWithTop) ++bottom;
    bool first = true;
    for (int k = top; k <= bottom; ++k) {
      if (!writesPower(r.cells[x - 1][k])) continue;
      emit(first ? Op::Load : Op::Or, {power(x - 1, k)});
      first = false;
    }
    if (first) { // nothing conducts into this cell: a constant 0
      emit(Op::Load, {power(x, y)});
      emit(Op::AndNot, {power(x, y)});
    }
  }

  std::optional<Operand> boolVar(int32_t rung, int x, int y, const Cell &c, bool write) {
    const Ele e = static_cast<Ele>(c.type);
    const bool blockOut = c.varType == 10 || c.varType == 11 || c.varType == 15 ||
                          c.varType == 20 || (c.varType >= 25 && c.varType <= 27);
    const bool ok = c.varType == 0 || c.varType == 60 || c.varType == 70 ||
                    (!write && (c.varType == 50 || blockOut)) || (write && c.varType == 15);
    if (!ok) {
      refuseCell(rung, x, y,
                 std::string(elementName(c.type)) + " on " + varName(c.varType, c.varNum) +
                     " is not supported yet by the classicladder front end" +
                     (write && c.varType == 50 ? " (a coil on an input)" : ""));
      return std::nullopt;
    }
    (void)e;
    std::string why;
    std::optional<Operand> o = varOperand(c.varType, c.varNum, why);
    if (!o) refuseCell(rung, x, y, why);
    return o;
  }

  /// A ladder section's rungs in #NEXTRUNG order, each with a label a jump can reach.
  void section(const Section &s) {
    section_ = &s;
    // The drawing: one part per section, named as the editor names it.
    GridPartDrawing part;
    part.name = s.subRoutine >= 0 ? "SR" + std::to_string(s.subRoutine) + " " + s.name : s.name;
    out_.grids.push_back(std::move(part));
    labels_.clear();
    for (int32_t r : s.order) labels_[r] = nextLabel_++;
    for (size_t i = 0; i < s.order.size(); ++i) {
      position_ = static_cast<int32_t>(i);
      if (labels_.at(s.order[i]) < kEndLabel) emit(Op::Label, {label(labels_.at(s.order[i]))});
      rung(s.order[i]);
    }
    section_ = nullptr;
  }
  static Operand label(int32_t n) {
    Operand o;
    o.kind = Operand::Kind::Reg;
    o.area = Area::Label;
    o.index = n;
    return o;
  }

  /// Leaves the scan when the ladder has stopped: from a main section to the end of the cyclic
  /// part, from a sub-routine back to its caller (which checks again after its CALL).
  void leaveIfStopped(const Operand &cond) {
    emit(Op::Load, {cond});
    if (section_ && section_->subRoutine >= 0)
      emit(Op::Return, {});
    else
      emit(Op::Jump, {label(kEndLabel)});
  }

  /// Jump coil: when powered, the rest of the rung is skipped and the section goes on at the
  /// target rung along its chain (calc.c), forward or back (a loop within the scan). Every jump
  /// counts towards calc.c's MadLoopBreak: the jump that makes more than 99,999 in one section
  /// pass stops the ladder for good instead. A target outside the section's chain is refused.
  void jump(const Rung &r, int x, int y, const Cell &c) {
    const auto at = std::find(section_->order.begin(), section_->order.end(), c.varNum);
    if (at == section_->order.end()) {
      refuseCell(r.index, x, y,
                 "jump coil to rung " + std::to_string(c.varNum) +
                     ", which is not on this section's chain, is not supported yet by the "
                     "classicladder front end");
      return;
    }
    const int32_t l = labels_.at(c.varNum);
    if (l >= kEndLabel) {
      refuseCell(r.index, x, y, "the project has more rungs than the profile's labels");
      return;
    }
    const Operand taken = previous(x, y); // a coil cell keeps no edge memory: the jump's bit
    loadLeft(r, x, y);
    emit(Op::Coil, {taken});
    emit(Op::Load, {taken});
    emit(Op::Increment, {blockWord(kJumpsAt)});
    test(Op::CompareLt, konst(kMaxJumps), blockWord(kJumpsAt));
    emit(Op::Load, {taken});
    emit(Op::And, {flag()});
    emit(Op::Set, {blockFlag(kStoppedAt)});
    leaveIfStopped(blockFlag(kStoppedAt));
    emit(Op::Load, {taken});
    emit(Op::Jump, {label(l)});
  }

  /// Call coil: when powered, the sub-routine section runs now, mid-rung (calc.c).
  void call(const Rung &r, int x, int y, const Cell &c) {
    const Section *target = nullptr;
    for (const Section &s : p_.sections)
      if (s.subRoutine == c.varNum) {
        target = &s;
        break;
      }
    if (!target || target->language != Language::Ladder) return; // calc.c: nothing happens
    if (c.varNum < 0 || c.varNum >= kSubroutines) {
      refuseCell(r.index, x, y,
                 "call coil SR" + std::to_string(c.varNum) + " is beyond the profile's SR0..SR" +
                     std::to_string(kSubroutines - 1));
      return;
    }
    Operand sr;
    sr.kind = Operand::Kind::Reg;
    sr.area = Area::Subroutine;
    sr.index = c.varNum;
    loadLeft(r, x, y);
    emit(Op::Call, {sr});
    leaveIfStopped(blockFlag(kStoppedAt)); // the sub-routine stopped the ladder
  }

  /// Old timer (2x2), monostable (2x1), counter (2x4) or IEC timer (2x2) at its top-right cell
  /// (calc.c): inputs StateOnLeft(x - 1, row) of its rows, outputs the power of its right cells.
  /// A block whose rows do not fit the rung does nothing, as in calc.c.
  void block(const Rung &r, int x, int y, const Cell &c) {
    using namespace clblocks;
    const int rows = c.type == 10 ? 2 : c.type == 12 ? 4 : 1;
    if (y + rows > h_) return;
    if (c.varNum < 0 || c.varNum >= blockCount(c.type)) {
      refuseCell(r.index, x, y,
                 blockText(c) + " is beyond the " + std::to_string(blockCount(c.type)) +
                     " of the classicladder profile");
      return;
    }
    const int32_t at = blockAt(c.type, c.varNum);
    const Operand clock = blockWord(kClockAt);
    for (int k = 0; k < rows; ++k) loadLeft(r, x - 1, y + k);
    switch (c.type) {
    case 10:
      emit(Op::ClTimer, {blockWord(at), clock});
      emit(Op::Coil, {power(x, y)});
      emit(Op::Load, {blockFlag(at + kTimerRunning)});
      emit(Op::Coil, {power(x, y + 1)});
      return;
    case 11:
      emit(Op::ClMonostable, {blockWord(at), clock});
      emit(Op::Coil, {power(x, y)});
      return;
    case 12:
      emit(Op::ClCounter, {blockWord(at)});
      emit(Op::Coil, {power(x, y)});
      emit(Op::Load, {blockFlag(at + kCounterDone)});
      emit(Op::Coil, {power(x, y + 1)});
      emit(Op::Load, {blockFlag(at + kCounterFull)});
      emit(Op::Coil, {power(x, y + 2)});
      return;
    default: {
      const bool known = static_cast<size_t>(c.varNum) < p_.timersIec.size();
      const TimerIecParams t =
          known ? p_.timersIec[static_cast<size_t>(c.varNum)] : TimerIecParams{};
      emit(Op::ClIecTimer, {blockWord(at), clock, konst(static_cast<int32_t>(t.mode)),
                            konst(known ? t.baseMs : 1000)});
      emit(Op::Coil, {power(x, y)});
      return;
    }
    }
  }

  /// %Tn.P %Tn.V %Mn.P %Mn.V (230, 231, 240, 241): the block's ms word, read as whole base units.
  static bool scaledVar(int32_t type) {
    return type == 230 || type == 231 || type == 240 || type == 241;
  }
  std::optional<Operand> scaledWord(int32_t type, int32_t num, std::string &why) const {
    using namespace clblocks;
    const int32_t kind = type < 240 ? 10 : 11;
    if (num < 0 || num >= blockCount(kind)) {
      why = "variable " + varName(type, num) + " is beyond the " +
            std::to_string(blockCount(kind)) + " " + (kind == 10 ? "timers" : "monostables") +
            " of the classicladder profile";
      return std::nullopt;
    }
    const bool preset = type == 230 || type == 240;
    const int32_t word = kind == 10 ? int32_t{preset ? kTimerPresetMs : kTimerValueMs}
                                    : int32_t{preset ? kMonoPresetMs : kMonoValueMs};
    return blockWord(blockAt(kind, num) + word);
  }

  void rung(int32_t index) {
    auto it = p_.rungs.find(index);
    if (it == p_.rungs.end()) return; // the reader checked the chains
    const Rung &r = it->second;
    rung_ = index;
    w_ = static_cast<int>(r.cells.size());
    h_ = w_ ? static_cast<int>(r.cells[0].size()) : 0;
    auto slot = slots_.find(index);
    if (slot == slots_.end()) {
      slot = slots_.emplace(index, next_).first;
      next_ += 2 * w_ * h_;
    }
    base_ = slot->second;
    if (base_ + 2 * w_ * h_ > kCellBytes * 8 - kScratchBits) {
      if (!tooBig_)
        refuse("rung " + std::to_string(index) +
               ": the project has more rung cells than the "
               "classicladder profile holds (" +
               std::to_string(kCellBytes * 8 / 120) + " rungs of 10x6)");
      tooBig_ = true;
      return;
    }
    GridRungDrawing dr;
    if (!r.label.empty() || !r.comment.empty())
      dr.comment.push_back(r.label +
                           (r.comment.empty() ? "" : (r.label.empty() ? "" : ": ") + r.comment));
    dr.rows = h_;
    dr.cols = w_;
    drawing_ = out_.grids.empty() ? nullptr : &dr;
    for (int x = 0; x < w_; ++x) {
      for (int y = 0; y < h_; ++y) {
        const size_t before = out_.stmts.size();
        cell(r, x, y);
        if (drawing_) draw(r, x, y, before);
      }
    }
    drawing_ = nullptr;
    if (!out_.grids.empty()) out_.grids.back().rungs.push_back(std::move(dr));
  }

  /// The drawing of cell (x, y) (ir/Program.h GridCellDrawing): where ClassicLadder's editor
  /// draws it, its text, and the statement whose traced value the live view shows (a contact's
  /// AND, an edge contact's or a compare's power, a coil, a block, a jump's condition, a call).
  void draw(const Rung &r, int x, int y, size_t before) {
    const Cell &c = r.cells[static_cast<size_t>(x)][static_cast<size_t>(y)];
    if (y > 0 && c.connectedWithTop) {
      GridCellDrawing v;
      v.kind = "vlink";
      v.row = y - 1;
      v.col = x;
      drawing_->cells.push_back(v);
    }
    const size_t end = out_.stmts.size();
    auto first = [&](auto pred) -> StmtId {
      for (size_t k = before; k < end; ++k)
        if (pred(out_.stmts[k])) return out_.stmts[k].id;
      return -1;
    };
    const Operand pw = power(x, y);
    auto writesPowerBit = [&](const Stmt &st) {
      return st.op == Op::Coil && st.operandCount == 1 && st.ops[0].area == pw.area &&
             st.ops[0].index == pw.index && st.ops[0].bit == pw.bit;
    };
    GridCellDrawing d;
    d.row = y;
    d.col = x;
    switch (c.type) {
    case 1:
    case 2:
    case 3:
    case 4: {
      static const char *kinds[] = {"contact-no", "contact-nc", "contact-rise", "contact-fall"};
      d.kind = kinds[c.type - 1];
      d.text = varName(c.varType, c.varNum);
      const StmtId at = first(writesPowerBit);
      // NO / NC: the AND before the power's store (the contact's conduction); an edge: the power.
      d.stmt = at < 0 ? -1 : c.type <= 2 ? at - 1 : at;
      break;
    }
    case 9:
      d.kind = "wire";
      break;
    case 50:
    case 51:
    case 52:
    case 53: {
      static const char *kinds[] = {"coil", "coil-not", "set", "rst"};
      d.kind = kinds[c.type - 50];
      d.text = varName(c.varType, c.varNum);
      d.stmt = end > before ? out_.stmts[end - 1].id : -1;
      break;
    }
    case 10:
    case 11:
    case 12:
    case 13: {
      int w = 1, h = 1;
      elementSize(c.type, w, h);
      static const char *names[] = {"%T", "%M", "%C", "%TM"};
      d.kind = "box";
      d.text = names[c.type - 10] + std::to_string(c.varNum);
      d.col = x - (w - 1);
      d.width = w;
      d.height = h;
      const int rows = c.type == 10 ? 2 : c.type == 12 ? 4 : 1;
      for (int k = 0; k < rows; ++k) d.pins.push_back(k);
      d.stmt = first([](const Stmt &st) {
        return st.op == Op::ClTimer || st.op == Op::ClMonostable || st.op == Op::ClCounter ||
               st.op == Op::ClIecTimer;
      });
      break;
    }
    case 20:
    case 60: {
      const ArithExpr *a = p_.expression(c.varNum);
      d.kind = c.type == 20 ? "compare" : "operate";
      d.text = a ? shownExpression(a->expr.text) : "";
      d.col = x - 2;
      d.width = 3;
      d.stmt = c.type == 20 ? first(writesPowerBit) : -1;
      break;
    }
    case 54: {
      auto t = p_.rungs.find(c.varNum);
      d.kind = "jump";
      d.text = "JUMP " + (t != p_.rungs.end() && !t->second.label.empty()
                              ? t->second.label
                              : "rung " + std::to_string(c.varNum));
      d.stmt = first([](const Stmt &st) { return st.op == Op::Coil; });
      break;
    }
    case 55:
      d.kind = "call";
      d.text = "CALL SR" + std::to_string(c.varNum);
      d.stmt = first([](const Stmt &st) { return st.op == Op::Call; });
      break;
    default:
      return; // FREE, the dead cells of a block, editor codes
    }
    if (d.col < 0) d.col = 0;
    if (!d.text.empty()) // symbols.csv names the variable (display only)
      for (const Symbol &sym : p_.symbols)
        if (!sym.symbol.empty() && sym.varName == d.text) d.symbol = sym.symbol;
    drawing_->cells.push_back(std::move(d));
  }

  /// An expression as ClassicLadder's editor shows it: `@200/0@:=@200/0@+1` as `%W0:=%W0+1`.
  static std::string shownExpression(const std::string &text) {
    std::string out;
    for (size_t i = 0; i < text.size();) {
      if (text[i] == '@') {
        const size_t slash = text.find('/', i + 1), close = text.find('@', i + 1);
        if (slash != std::string::npos && close != std::string::npos && slash < close) {
          const std::string t = text.substr(i + 1, slash - i - 1),
                            n = text.substr(slash + 1, close - slash - 1);
          if (!t.empty() && !n.empty() && t.find_first_not_of("0123456789") == std::string::npos &&
              n.find_first_not_of("0123456789") == std::string::npos && t.size() < 6 &&
              n.size() < 6) {
            out += varName(std::stoi(t), std::stoi(n));
            i = close + 1;
            continue;
          }
        }
      }
      out += text[i++];
    }
    return out;
  }

  void cell(const Rung &r, int x, int y) {
    const Cell &c = r.cells[x][y];
    switch (c.type) {
    case 1:
    case 2:
    case 3:
    case 4: {
      std::optional<Operand> v = boolVar(r.index, x, y, c, false);
      if (!v) return;
      loadLeft(r, x, y);
      if (c.type == 1) emit(Op::And, {*v});
      if (c.type == 2) emit(Op::AndNot, {*v});
      if (c.type == 3) emit(Op::AndNot, {previous(x, y)}), emit(Op::And, {*v});
      if (c.type == 4) emit(Op::And, {previous(x, y)}), emit(Op::AndNot, {*v});
      emit(Op::Coil, {power(x, y)});
      if (c.type >= 3) { // DynamicVarBak := the variable, whatever the power on the left
        emit(Op::Load, {*v});
        emit(Op::Coil, {previous(x, y)});
      }
      return;
    }
    case 9:
      loadLeft(r, x, y);
      emit(Op::Coil, {power(x, y)});
      return;
    case 50:
    case 51:
    case 52:
    case 53: {
      if (readOnlyBlockVar(c.varType)) return; // calc.c WriteVar: nothing happens
      std::optional<Operand> v = boolVar(r.index, x, y, c, true);
      if (!v) return;
      loadLeft(r, x, y);
      const Op op = c.type == 50   ? Op::Coil
                    : c.type == 51 ? Op::CoilNot
                    : c.type == 52 ? Op::Set
                                   : Op::Reset;
      emit(op, {*v});
      return;
    }
    case 10:
    case 11:
    case 12:
    case 13:
      block(r, x, y, c);
      return;
    case 20:
      compare(r, x, y, c);
      return;
    case 54:
      jump(r, x, y, c);
      return;
    case 55:
      call(r, x, y, c);
      return;
    case 60:
      operate(r, x, y, c);
      return;
    case 0:
    case 99:
      return;
    default:
      if (c.type >= 100 && c.type <= 105) return; // editor codes act like FREE
      refuseCell(r.index, x, y,
                 blockText(c) + " is not supported yet by the classicladder front end");
    }
  }

  // ---- compare and operate blocks: the expression trees of Expression.h evaluated into the
  // scratch words after %W (one per tree level) with 2.9's rules: 32-bit wrapping + - *,
  // division and modulo by zero keep the left operand, a^b squares a b times ----

  static Operand word(int32_t k) {
    Operand o;
    o.kind = Operand::Kind::Reg;
    o.area = Area::DWord;
    o.index = kWords + k;
    return o;
  }
  static Operand konst(int32_t v) {
    Operand o;
    o.kind = Operand::Kind::Const;
    o.value = v;
    return o;
  }
  /// A scratch bit of the expression code (a condition computed and used at once).
  static Operand flag() { return bitOperand(Area::ExtraRelay, kCellBytes * 8 - 1); }

  /// dst := value, unconditionally.
  void move(const Operand &from, const Operand &to) {
    emit(Op::LoadTrue, {});
    emit(Op::Move, {from, to});
  }
  /// flag := a OP b (OP a compare operation: a < b, a <= b, a == b).
  void test(Op op, const Operand &a, const Operand &b) {
    emit(Op::LoadTrue, {});
    emit(op, {a, b});
    emit(Op::Coil, {flag()});
  }

  /// The value of `n` into scratch word k (words above k are free). False (reported) when the
  /// tree uses what the front end does not map.
  bool value(const ExprNode &n, int32_t k, const std::string &where) {
    using K = ExprNode::Kind;
    if (k + 3 >= kTempWords) {
      refuse(where + ": the expression nests deeper than the classicladder profile's " +
             std::to_string(kTempWords) + " scratch words");
      return false;
    }
    const Operand t = word(k), u = word(k + 1), v = word(k + 2);
    switch (n.kind) {
    case K::Const:
      move(konst(n.value), t);
      return true;
    case K::Var: {
      if (n.var.indexType >= 0) {
        refuse(where + ": indexed variable " + varName(n.var.type, n.var.num) +
               "[...] is not supported yet by the classicladder front end");
        return false;
      }
      std::string why;
      if (scaledVar(n.var.type)) { // ms / base, truncated as C divides
        std::optional<Operand> w = scaledWord(n.var.type, n.var.num, why);
        if (!w) {
          refuse(where + ": " + why);
          return false;
        }
        move(*w, t);
        emit(Op::LoadTrue, {});
        emit(Op::Divide, {t, konst(baseMsOf(p_, n.var.type < 240 ? 10 : 11, n.var.num)), t});
        return true;
      }
      std::optional<Operand> o = varOperand(n.var.type, n.var.num, why);
      if (!o) {
        refuse(where + ": " + why);
        return false;
      }
      if (o->kind == Operand::Kind::Bit) { // a bit read as a value: 0 or 1
        move(konst(0), t);
        emit(Op::Load, {*o});
        emit(Op::Move, {konst(1), t});
      } else {
        move(*o, t);
      }
      return true;
    }
    case K::Not:
      if (!value(*n.kids[0], k, where)) return false;
      test(Op::CompareEq, t, konst(0));
      move(konst(0), t);
      emit(Op::Load, {flag()});
      emit(Op::Move, {konst(1), t});
      return true;
    case K::Or:
    case K::Xor:
    case K::And:
    case K::Add:
    case K::Sub:
    case K::Mul: {
      if (!value(*n.kids[0], k, where) || !value(*n.kids[1], k + 1, where)) return false;
      const Op op = n.kind == K::Or    ? Op::BitOr
                    : n.kind == K::Xor ? Op::BitXor
                    : n.kind == K::And ? Op::BitAnd
                    : n.kind == K::Add ? Op::Add
                    : n.kind == K::Sub ? Op::Subtract
                                       : Op::Multiply;
      emit(Op::LoadTrue, {});
      emit(op, {t, u, t});
      return true;
    }
    case K::Div:
    case K::Mod:
      // by zero: nothing done, the left operand stays (2.9); INT_MIN / -1 is INT_MIN (the IR's
      // Divide) and INT_MIN % -1 = INT_MIN - INT_MIN * -1 = 0, as Expression.cpp evaluates
      if (!value(*n.kids[0], k, where) || !value(*n.kids[1], k + 1, where)) return false;
      test(Op::CompareEq, u, konst(0));
      emit(Op::LoadNot, {flag()});
      emit(Op::Divide, {t, u, n.kind == K::Div ? t : v});
      if (n.kind == K::Mod) {
        emit(Op::LoadNot, {flag()});
        emit(Op::Multiply, {v, u, v});
        emit(Op::LoadNot, {flag()});
        emit(Op::Subtract, {t, v, t});
      }
      return true;
    case K::Pow:
      // pow_int squares a b times; modulo 2^32 the squares are fixed after 32 (Expression.cpp)
      if (!value(*n.kids[0], k, where) || !value(*n.kids[1], k + 1, where)) return false;
      for (int32_t i = 0; i < 40; ++i) {
        test(Op::CompareLt, konst(i), u);
        emit(Op::Load, {flag()});
        emit(Op::Multiply, {t, t, t});
      }
      return true;
    case K::Abs:
      if (!value(*n.kids[0], k, where)) return false;
      test(Op::CompareLt, t, konst(0));
      emit(Op::Load, {flag()});
      emit(Op::Subtract, {konst(0), t, t});
      return true;
    case K::Mini:
    case K::Maxi:
    case K::Avg: {
      if (n.kids.empty()) {
        move(konst(n.kind == K::Mini ? INT32_MAX : n.kind == K::Maxi ? INT32_MIN : 0), t);
        return true;
      }
      if (!value(*n.kids[0], k, where)) return false;
      for (size_t i = 1; i < n.kids.size(); ++i) {
        if (!value(*n.kids[i], k + 1, where)) return false;
        if (n.kind == K::Avg) {
          emit(Op::LoadTrue, {});
          emit(Op::Add, {t, u, t});
          continue;
        }
        n.kind == K::Mini ? test(Op::CompareLt, u, t) : test(Op::CompareLt, t, u);
        emit(Op::Load, {flag()});
        emit(Op::Move, {u, t});
      }
      if (n.kind == K::Avg && n.kids.size() > 1) {
        emit(Op::LoadTrue, {});
        emit(Op::Divide, {t, konst(static_cast<int32_t>(n.kids.size())), t});
      }
      return true;
    }
    default:
      refuse(where + ": the 0.9 function of '" + toString(n) +
             "' is not supported by the classicladder front end (LinuxCNC has none)");
      return false;
    }
  }

  std::string cellWhere(const Rung &r, int x, int y) const {
    return "rung " + std::to_string(r.index) + " row " + std::to_string(y) + " column " +
           std::to_string(x);
  }

  /// Compare block (3x1, alive at its right cell): power = comparison && StateOnLeft(x - 2).
  void compare(const Rung &r, int x, int y, const Cell &c) {
    const ArithExpr *a = p_.expression(c.varNum);
    const std::string where =
        cellWhere(r, x, y) + ": compare block (expression " + std::to_string(c.varNum) + ")";
    const Operand res = previous(x, y); // the block's comparison result
    if (!a || a->expr.empty || !a->expr.isCompare) {
      emit(Op::Load, {res}); // an empty slot or a text that is no comparison: false
      emit(Op::AndNot, {res});
      emit(Op::Coil, {power(x, y)});
      return;
    }
    const Expression &e = a->expr;
    if (!value(*e.left, 0, where) || !value(*e.right, 1, where)) return;
    using C = Expression::CmpOp;
    const Operand l = word(0), rr = word(1);
    switch (e.cmp) {
    case C::Gt:
      test(Op::CompareLt, rr, l);
      break;
    case C::Lt:
      test(Op::CompareLt, l, rr);
      break;
    case C::Ge:
      test(Op::CompareLe, rr, l);
      break;
    case C::Le:
      test(Op::CompareLe, l, rr);
      break;
    case C::Eq:
    case C::Ne:
      test(Op::CompareEq, l, rr);
      break;
    }
    emit(e.cmp == C::Ne ? Op::LoadNot : Op::Load, {flag()});
    emit(Op::Coil, {res});
    loadLeft(r, x - 2, y);
    emit(Op::And, {res});
    emit(Op::Coil, {power(x, y)});
  }

  /// Operate block (3x1 in the output column): when StateOnLeft(x - 2), target := value.
  void operate(const Rung &r, int x, int y, const Cell &c) {
    const ArithExpr *a = p_.expression(c.varNum);
    if (!a || a->expr.empty || !a->expr.isOperate) return; // does nothing (2.9)
    const Expression &e = a->expr;
    const std::string where =
        cellWhere(r, x, y) + ": operate block (expression " + std::to_string(c.varNum) + ")";
    if (e.target.indexType >= 0) {
      refuse(where + ": indexed target " + varName(e.target.type, e.target.num) +
             "[...] is not supported yet by the classicladder front end");
      return;
    }
    std::string why;
    if (readOnlyBlockVar(e.target.type)) return;        // calc.c WriteVar: nothing happens
    if (e.target.type == 230 || e.target.type == 240) { // P := value x base (in ms)
      std::optional<Operand> w = scaledWord(e.target.type, e.target.num, why);
      if (!w) {
        refuse(where + ": " + why);
        return;
      }
      const Operand en = previous(x, y);
      loadLeft(r, x - 2, y);
      emit(Op::Coil, {en});
      if (!value(*e.value, 0, where)) return;
      emit(Op::Load, {en});
      emit(Op::Multiply,
           {word(0), konst(baseMsOf(p_, e.target.type == 230 ? 10 : 11, e.target.num)), *w});
      return;
    }
    std::optional<Operand> to = varOperand(e.target.type, e.target.num, why);
    if (!to || to->area == Area::Input || to->area == Area::Word ||
        to->area == Area::Param) { // %I, %IW: HAL copies them in
      refuse(where + ": " +
             (to ? "writing the input " + varName(e.target.type, e.target.num) +
                       " is not supported yet by the classicladder front end"
                 : why));
      return;
    }
    const Operand en = previous(x, y); // StateOnLeft, kept while the value is computed
    loadLeft(r, x - 2, y);
    emit(Op::Coil, {en});
    if (!value(*e.value, 0, where)) return;
    if (to->kind == Operand::Kind::Bit) { // a bit := value != 0
      test(Op::CompareEq, word(0), konst(0));
      emit(Op::Load, {en});
      emit(Op::AndNot, {flag()});
      emit(Op::Set, {*to});
      emit(Op::Load, {en});
      emit(Op::And, {flag()});
      emit(Op::Reset, {*to});
      return;
    }
    emit(Op::Load, {en});
    emit(Op::Move, {word(0), *to});
  }

  /// The element of a refused cell as ClassicLadder's editor names it: `timer %T2`.
  static std::string blockText(const Cell &c) {
    const std::string n = std::to_string(c.varNum);
    switch (c.type) {
    case 10:
      return "timer %T" + n;
    case 11:
      return "monostable %M" + n;
    case 12:
      return "counter %C" + n;
    case 13:
      return "IEC timer %TM" + n;
    case 20:
      return "compare block (expression " + n + ")";
    case 60:
      return "operate block (expression " + n + ")";
    case 54:
      return "jump coil (to rung " + n + ")";
    case 55:
      return "call coil (SR" + n + ")";
    default:
      return std::string(elementName(c.type)) + " (element " + std::to_string(c.type) + ")";
    }
  }

  const Project &p_;
  ParsedProgram &out_;
  Diagnostics &diags_;
  std::map<int32_t, int32_t> slots_;   ///< rung index -> first state bit
  const Section *section_ = nullptr;   ///< the section being mapped
  GridRungDrawing *drawing_ = nullptr; ///< the drawing of the rung being mapped
  std::map<int32_t, int32_t> labels_;  ///< its rungs -> their labels
  int32_t position_ = 0;               ///< the rung being mapped, in the section's order
  int32_t nextLabel_ = 0;
  int32_t next_ = 0, base_ = 0, rung_ = 0;
  int w_ = 0, h_ = 0;
  bool tooBig_ = false;
};

} // namespace

std::optional<Operand> varOperand(int32_t type, int32_t num, std::string &why) {
  using namespace clblocks;
  // the blocks' outputs (bits) and the values kept in whole units (words)
  struct BlockVar {
    int32_t type, kind, word;
    bool bit;
  };
  static constexpr BlockVar kBlockVars[] = {{10, 10, kTimerDone, true},
                                            {11, 10, kTimerRunning, true},
                                            {20, 11, kMonoRunning, true},
                                            {25, 12, kCounterDone, true},
                                            {26, 12, kCounterEmpty, true},
                                            {27, 12, kCounterFull, true},
                                            {250, 12, kCounterPreset, false},
                                            {251, 12, kCounterValue, false},
                                            {15, 13, kIecQ, true},
                                            {260, 13, kIecPreset, false},
                                            {261, 13, kIecValue, false}};
  for (const BlockVar &b : kBlockVars) {
    if (b.type != type) continue;
    if (num < 0 || num >= blockCount(b.kind)) {
      why = "variable " + varName(type, num) + " is beyond the " +
            std::to_string(blockCount(b.kind)) + " blocks of its kind in the classicladder profile";
      return std::nullopt;
    }
    const int32_t w = blockAt(b.kind, num) + b.word;
    return b.bit ? blockFlag(w) : blockWord(w);
  }
  Area a;
  int32_t count;
  switch (type) {
  case 50:
    a = Area::Input, count = kInputs;
    break;
  case 60:
    a = Area::Output, count = kOutputs;
    break;
  case 0:
    a = Area::Relay, count = kBits;
    break;
  case 70:
    a = Area::KeepRelay, count = kSystemBits;
    break;
  case 200:
    a = Area::DWord, count = kWords;
    break;
  case 270:
    a = Area::Word, count = kWordInputs;
    break;
  case 280:
    a = Area::Retained, count = kWordOutputs;
    break;
  case 300:
    a = Area::Param, count = kFloatInputs;
    break;
  case 310:
    a = Area::NcControl, count = kFloatOutputs;
    break;
  default:
    why = "variable " + varName(type, num) + " is not supported yet by the classicladder front end";
    return std::nullopt;
  }
  if (num < 0 || num >= count) {
    why = "variable " + varName(type, num) + " is beyond the " + std::to_string(count) + " " +
          varName(type, 0).substr(0, varName(type, 0).size() - 1) +
          " variables of the classicladder profile";
    return std::nullopt;
  }
  if (a == Area::DWord || a == Area::Word || a == Area::Retained || a == Area::Param ||
      a == Area::NcControl) {
    Operand o;
    o.kind = Operand::Kind::Reg;
    o.area = a;
    o.index = num;
    return o;
  }
  return bitOperand(a, num);
}

ParsedProgram toProgram(const Project &project, std::string file, Diagnostics &diags) {
  ParsedProgram out;
  out.file = std::move(file);
  out.dialect = &kText;
  out.profile = &profile();
  if (project.flavor == Flavor::Upstream09) {
    diags.error({}, "an upstream ClassicLadder 0.9 project (.clprj, #VER=3.0 rungs of 12x8, "
                    "variable code 300 a register) does not run: LinuxCNC's classicladder_rt "
                    "cannot load it either; save it from LinuxCNC's ClassicLadder as a .clp");
    return out;
  }
  RungMapper(project, out, diags).run();
  return out;
}

ParsedProgram parseClp(std::string_view text, std::string file, Diagnostics &diags) {
  Result<Project> p = readProjectText(text, file);
  if (!p) {
    // The reader's message is `PATH:LINE: error: TEXT` (or TEXT alone): keep the line as the
    // location so the rendered diagnostic names the file once.
    std::string msg = p.status().message();
    SourceLoc loc{};
    if (msg.rfind(file + ":", 0) == 0) {
      size_t at = file.size() + 1;
      int32_t line = 0;
      while (at < msg.size() && msg[at] >= '0' && msg[at] <= '9' && line < 100000000)
        line = line * 10 + (msg[at++] - '0');
      const std::string tag = ": error: ";
      if (line > 0 && msg.compare(at, tag.size(), tag) == 0) {
        loc = {line, 1};
        msg = msg.substr(at + tag.size());
      }
    }
    diags.error(loc, msg);
    ParsedProgram out;
    out.file = std::move(file);
    out.dialect = &kText;
    out.profile = &profile();
    return out;
  }
  for (const std::string &w : p->warnings) diags.warning({}, w);
  return toProgram(*p, std::move(file), diags);
}

const DialectText &dialectText() { return kText; }

} // namespace lj::classicladder

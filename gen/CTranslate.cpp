// Straight C for the subset of gen/CTranslate.h, statement by statement, with the semantics of
// the reference interpreter (interp/InterpFlow.cpp, interp/InterpBlocks.cpp): operands by byte
// offset inside lj_state (ir/Area.h stateOffset), ST and MS entries as local arrays indexed by the
// verifier's static depths (compilers keep them in registers), int32 arithmetic wrapping.
#include "gen/CTranslate.h"

#include "ir/Profile.h"

#include "ladderjit/abi.h"

#include <cstddef>
#include <sstream>

namespace lj::gen {
namespace {

bool supported(Op op) {
  switch (op) {
  case Op::Load:
  case Op::LoadNot:
  case Op::LoadTrue:
  case Op::LoadRise:
  case Op::LoadFall:
  case Op::And:
  case Op::AndNot:
  case Op::Or:
  case Op::OrNot:
  case Op::AndRise:
  case Op::AndFall:
  case Op::OrRise:
  case Op::OrFall:
  case Op::AndBlock:
  case Op::OrBlock:
  case Op::BranchPush:
  case Op::BranchRead:
  case Op::BranchPop:
  case Op::Coil:
  case Op::CoilNot:
  case Op::Set:
  case Op::Reset:
  case Op::EndInit:
  case Op::EndCyclic:
  case Op::EndSliced:
  case Op::Add:
  case Op::Subtract:
  case Op::Multiply:
  case Op::Divide:
  case Op::BitAnd:
  case Op::BitOr:
  case Op::BitXor:
  case Op::Increment:
  case Op::Decrement:
  case Op::Negate:
  case Op::Move:
  case Op::CompareLe:
  case Op::CompareLt:
  case Op::CompareEq:
  case Op::CompareRange:
  case Op::Label: // no jumps in the subset: a label (IEC IL's closing one) does nothing
  case Op::OnDelayTimer:
  case Op::RegisterCounter:
  case Op::RingCounter:
  case Op::UpDownCounter:
  case Op::RisePulse:
  case Op::FallPulse:
  case Op::Toggle:
    return true;
  default:
    return false;
  }
}

/// Byte offset and mask of a bit operand (as interp decode()).
void bitRef(const TargetProfile &tp, const Operand &o, uint32_t &off, unsigned &mask) {
  if (o.area == Area::Timer || o.area == Area::Counter) {
    int slot = tp.tcSlot(o.area, o.index);
    off = o.area == Area::Timer
              ? static_cast<uint32_t>(offsetof(lj_state, T) + slot * sizeof(lj_timer) +
                                      offsetof(lj_timer, out))
              : static_cast<uint32_t>(offsetof(lj_state, C) + slot * sizeof(lj_counter) +
                                      offsetof(lj_counter, out));
    mask = 1;
    return;
  }
  off = tp.elementOffset(o.area, o.index) + static_cast<uint32_t>(o.bit / 8);
  mask = 1u << (o.bit % 8);
}

std::string bitRead(const TargetProfile &tp, const Operand &o) {
  uint32_t off;
  unsigned mask;
  bitRef(tp, o, off, mask);
  return "((B(" + std::to_string(off) + ") & " + std::to_string(mask) + "u) != 0)";
}

std::string bitWrite(const TargetProfile &tp, const Operand &o, const std::string &v) {
  uint32_t off;
  unsigned mask;
  bitRef(tp, o, off, mask);
  std::string b = "B(" + std::to_string(off) + ")", m = std::to_string(mask) + "u";
  return b + " = (unsigned char)((" + v + ") ? (" + b + " | " + m + ") : (" + b + " & ~" + m +
         "));";
}

/// Width and signedness of a register operand as the interpreter's decode() has them.
void regKind(const TargetProfile &tp, const Operand &o, uint32_t &bytes, bool &isSigned) {
  const AreaInfo &ai = tp.area(o.area);
  bytes = o.width ? o.width : ai.bytes;
  isSigned = ai.isSigned;
}

std::string valueRead(const TargetProfile &tp, const Operand &o) {
  if (o.kind == Operand::Kind::Const)
    return o.value == INT32_MIN ? "(-2147483647 - 1)" : "(" + std::to_string(o.value) + ")";
  if (o.kind == Operand::Kind::Bit) return "(int32_t)" + bitRead(tp, o);
  uint32_t bytes;
  bool sgn;
  regKind(tp, o, bytes, sgn);
  std::string off = std::to_string(tp.elementOffset(o.area, o.index));
  if (bytes == 1) return sgn ? "(int32_t)(int8_t)B(" + off + ")" : "(int32_t)B(" + off + ")";
  if (bytes == 2) return sgn ? "(int32_t)I16(" + off + ")" : "(int32_t)(uint16_t)I16(" + off + ")";
  return "I32(" + off + ")";
}

std::string valueWrite(const TargetProfile &tp, const Operand &o, const std::string &v) {
  uint32_t bytes;
  bool sgn;
  regKind(tp, o, bytes, sgn);
  std::string off = std::to_string(tp.elementOffset(o.area, o.index));
  if (bytes == 1) return "B(" + off + ") = (unsigned char)(uint32_t)(" + v + ");";
  if (bytes == 2) return "I16(" + off + ") = (int16_t)(uint16_t)(uint32_t)(" + v + ");";
  return "I32(" + off + ") = (" + v + ");";
}

std::string edgeSample(const TargetProfile &tp, int32_t slot, const Operand &o, bool rising) {
  std::string e = "B(" + std::to_string(offsetof(lj_state, edge) + static_cast<size_t>(slot)) + ")";
  // EdgePolicy::PerObject: the edge memory is the object's previous-scan image, sampled at the
  // end of the cyclic part (emitPart), never written by the contact.
  const bool perInstance = tp.edgePolicy == EdgePolicy::PerInstance;
  return "{ unsigned char c = " + bitRead(tp, o) + ", m = " + e + " != 0; " +
         (perInstance ? e + " = c; " : std::string()) + "ev = " + (rising ? "c && !m" : "!c && m") +
         "; }";
}

/// `countStep` of interp/InterpBlocks.cpp (hnc8-functions-1.md 3.3) on C lvalues.
std::string countStep(const std::string &cnt, const std::string &s1, const std::string &dn,
                      const std::string &rst, const std::string &pv, const std::string &cv,
                      const std::string &prev, const std::string &out) {
  return "{ int32_t init = " + s1 + " ? 1 : 0, pv = " + pv + "; if (" + rst + ") { " + cv + " = " +
         dn + " ? pv : init; " + out + " = 0; } else { if (" + cnt + " && !" + prev + ") { if (!" +
         dn + ") " + cv + " = (" + cv + " >= pv) ? init : " + cv + " + 1; else " + cv + " = (" +
         cv + " <= init) ? pv : " + cv + " - 1; } " + out + " = " + dn + " ? (" + cv +
         " <= init) : (" + cv + " >= pv); } " + prev + " = " + cnt + "; }";
}

void emitStmt(std::ostringstream &c, const VerifiedProgram &p, int32_t pc) {
  const Stmt &st = p.stmts[static_cast<size_t>(pc)];
  const StmtInfo &in = p.info[static_cast<size_t>(pc)];
  const TargetProfile &tp = *p.profile;
  const int d = in.depth, m = in.msDepth;
  auto S = [](int i) { return "st[" + std::to_string(i) + "]"; };
  auto M = [](int i) { return "ms[" + std::to_string(i) + "]"; };
  const Operand &a = st.ops[0], &b = st.ops[1], &x = st.ops[2];
  const std::string en = d > 0 ? S(d - 1) : "1";
  auto out = [&](const std::string &v) { return (d > 0 ? S(d - 1) : S(d)) + " = (" + v + ");"; };
  c << "  ";
  switch (st.op) {
  case Op::Load:
    c << S(d) << " = " << bitRead(tp, a) << ";";
    break;
  case Op::LoadNot:
    c << S(d) << " = !" << bitRead(tp, a) << ";";
    break;
  case Op::LoadTrue:
    c << S(d) << " = 1;";
    break;
  case Op::LoadRise:
  case Op::LoadFall:
    c << edgeSample(tp, in.slot, a, st.op == Op::LoadRise) << " " << S(d) << " = ev;";
    break;
  case Op::And:
    c << S(d - 1) << " &= " << bitRead(tp, a) << ";";
    break;
  case Op::AndNot:
    c << S(d - 1) << " &= !" << bitRead(tp, a) << ";";
    break;
  case Op::Or:
    c << S(d - 1) << " |= " << bitRead(tp, a) << ";";
    break;
  case Op::OrNot:
    c << S(d - 1) << " |= !" << bitRead(tp, a) << ";";
    break;
  case Op::AndRise:
  case Op::AndFall:
    c << edgeSample(tp, in.slot, a, st.op == Op::AndRise) << " " << S(d - 1) << " &= ev;";
    break;
  case Op::OrRise:
  case Op::OrFall:
    c << edgeSample(tp, in.slot, a, st.op == Op::OrRise) << " " << S(d - 1) << " |= ev;";
    break;
  case Op::AndBlock:
    c << S(d - 2) << " &= " << S(d - 1) << ";";
    break;
  case Op::OrBlock:
    c << S(d - 2) << " |= " << S(d - 1) << ";";
    break;
  case Op::BranchPush:
    c << M(m) << " = " << S(d - 1) << ";";
    break;
  case Op::BranchRead:
  case Op::BranchPop:
    c << S(d - 1) << " = " << M(m - 1) << ";";
    break;
  case Op::Coil:
    c << bitWrite(tp, a, S(d - 1));
    break;
  case Op::CoilNot:
    c << bitWrite(tp, a, "!" + S(d - 1));
    break;
  case Op::Set:
    c << "if (" << S(d - 1) << ") " << bitWrite(tp, a, "1");
    break;
  case Op::Reset:
    c << "if (" << S(d - 1) << ") " << bitWrite(tp, a, "0");
    break;
  case Op::Label:
  case Op::EndInit:
  case Op::EndCyclic:
  case Op::EndSliced:
    c << "/* end of part */";
    break;
  case Op::Add:
  case Op::Subtract:
  case Op::Multiply:
  case Op::BitAnd:
  case Op::BitOr:
  case Op::BitXor: {
    const char *o = st.op == Op::Add        ? "+"
                    : st.op == Op::Subtract ? "-"
                    : st.op == Op::Multiply ? "*"
                    : st.op == Op::BitAnd   ? "&"
                    : st.op == Op::BitOr    ? "|"
                                            : "^";
    c << "if (" << en << ") { uint32_t va = (uint32_t)" << valueRead(tp, a) << ", vb = (uint32_t)"
      << valueRead(tp, b) << "; " << valueWrite(tp, x, std::string("(int32_t)(va ") + o + " vb)")
      << " } " << out(en);
    break;
  }
  case Op::Divide:
    c << "{ unsigned char o = " << en << "; if (o) { int32_t va = " << valueRead(tp, a)
      << ", vb = " << valueRead(tp, b) << "; if (vb == 0) { ++U32("
      << offsetof(lj_state, fault_divzero) << "); o = 0; } else { "
      << valueWrite(tp, x, "(va == (-2147483647 - 1) && vb == -1) ? va : va / vb") << " } } "
      << out("o") << " }";
    break;
  case Op::Increment:
  case Op::Decrement:
  case Op::Negate: {
    std::string r = st.op == Op::Increment   ? "(int32_t)((uint32_t)" + valueRead(tp, a) + " + 1u)"
                    : st.op == Op::Decrement ? "(int32_t)((uint32_t)" + valueRead(tp, a) + " - 1u)"
                                             : "(int32_t)(0u - (uint32_t)" + valueRead(tp, a) + ")";
    c << "if (" << en << ") { " << valueWrite(tp, a, r) << " } " << out(en);
    break;
  }
  case Op::Move:
    c << "if (" << en << ") { " << valueWrite(tp, b, valueRead(tp, a)) << " } " << out(en);
    break;
  case Op::CompareLe:
    c << out(en + " && " + valueRead(tp, a) + " <= " + valueRead(tp, b));
    break;
  case Op::CompareLt:
    c << out(en + " && " + valueRead(tp, a) + " < " + valueRead(tp, b));
    break;
  case Op::CompareEq:
    c << out(en + " && " + valueRead(tp, a) + " == " + valueRead(tp, b));
    break;
  case Op::CompareRange:
    c << "{ int32_t lo = " << valueRead(tp, a) << ", hi = " << valueRead(tp, b)
      << ", v = " << valueRead(tp, x) << "; " << out(en + " && lo < v && v < hi") << " }";
    break;
  case Op::OnDelayTimer: { // dialect-notes "Timers": state in the profile's timer slot
    const std::string t = std::to_string(tp.timerOffset(in.slot));
    auto F = [&](const char *ty, size_t off) {
      return std::string("(*(") + ty + " *)((unsigned char *)s + " + t + " + " +
             std::to_string(off) + "))";
    };
    const std::string run = F("uint8_t", offsetof(lj_timer, running)),
                      tout = F("uint8_t", offsetof(lj_timer, out)),
                      start = F("int64_t", offsetof(lj_timer, start_ms)),
                      el = F("int64_t", offsetof(lj_timer, elapsed_ms));
    c << "{ int32_t unit = " << valueRead(tp, b) << " & 3; int64_t preset = (int64_t)"
      << valueRead(tp, x) << " * (unit == 0 ? " << tp.timerUnitMs[0] << " : unit == 1 ? "
      << tp.timerUnitMs[1] << " : unit == 2 ? " << tp.timerUnitMs[2] << " : " << tp.timerUnitMs[3]
      << "); (void)unit; if (preset < 0) preset = 0; if (" << en
      << ") { int64_t now = (int64_t)NOW; if (!" << run << ") { " << run << " = 1; " << start
      << " = now; } int64_t e = now > " << start << " ? now - " << start << " : 0; " << tout
      << " = e >= preset; " << el << " = e < preset ? e : preset; } else { " << run << " = 0; "
      << tout << " = 0; " << el << " = 0; } " << out(tout + " != 0") << " }";
    break;
  }
  case Op::RegisterCounter: {
    const std::string cv = "cv",
                      prev = "B(" + std::to_string(offsetof(lj_state, edge) + in.slot) + ")";
    c << "{ int32_t cv = " << valueRead(tp, a) << "; unsigned char o, pr = " << prev << " != 0; "
      << countStep(S(d - 4), S(d - 3), S(d - 2), S(d - 1), valueRead(tp, b), cv, "pr", "o") << " "
      << valueWrite(tp, a, "cv") << " " << prev << " = pr; " << S(d - 4) << " = o; }";
    break;
  }
  case Op::RingCounter:
  case Op::UpDownCounter: {
    const size_t base = offsetof(lj_state, C) + static_cast<size_t>(in.slot) * sizeof(lj_counter);
    const std::string cv = "I32(" + std::to_string(base + offsetof(lj_counter, value)) + ")",
                      out = "B(" + std::to_string(base + offsetof(lj_counter, out)) + ")";
    const std::string prev = "B(" + std::to_string(base + offsetof(lj_counter, prev)) + ")";
    const bool ud = st.op == Op::UpDownCounter;
    const int k = ud ? 4 : 2;
    c << "{ int32_t cv = " << cv << "; unsigned char o, pr = " << prev << " != 0; "
      << countStep(S(d - k), ud ? S(d - 3) : "0", ud ? S(d - 2) : "0", S(d - 1), valueRead(tp, b),
                   "cv", "pr", "o")
      << " " << cv << " = cv; " << prev << " = pr; " << out << " = o; " << S(d - k) << " = o; }";
    break;
  }
  case Op::RisePulse:
  case Op::FallPulse: {
    const std::string pr =
        "B(" + std::to_string(tp.pulseOffset(st.op == Op::RisePulse, in.slot)) + ")";
    c << "{ unsigned char e = " << en
      << ", o = " << (st.op == Op::RisePulse ? "e && !" + pr : "!e && " + pr) << "; " << pr
      << " = e; " << out("o") << " }";
    break;
  }
  case Op::Toggle: {
    const std::string pr = "B(" + std::to_string(offsetof(lj_state, alt_prev) + in.slot) + ")",
                      sv = "B(" + std::to_string(offsetof(lj_state, alt_state) + in.slot) + ")";
    c << "{ unsigned char e = " << en << "; if (e && !" << pr << ") " << sv << " = !" << sv << "; "
      << pr << " = e; " << out(sv + " != 0") << " }";
    break;
  }
  default:
    c << "#error unsupported statement";
    break;
  }
  c << "\n";
}

void emitPart(std::ostringstream &c, const VerifiedProgram &p, const std::string &name, StmtRange r,
              bool edgeImage = false) {
  c << "static uint32_t " << name << "(lj_state *s) {\n  unsigned char st[" << p.maxDepth + 2
    << "] = {0}, ms[" << p.maxMsDepth + 2 << "] = {0}, ev = 0;\n  (void)ms; (void)ev;\n";
  for (int32_t pc = r.begin; pc < r.end; ++pc) emitStmt(c, p, pc);
  // EdgePolicy::PerObject: the previous-scan image of every edge object (interp runPlc1).
  if (edgeImage)
    for (size_t k = 0; k < p.edgeObjects.size(); ++k)
      if (p.edgeObjects[k].kind == Operand::Kind::Bit)
        c << "  B(" << offsetof(lj_state, edge) + k
          << ") = " << bitRead(*p.profile, p.edgeObjects[k]) << ";\n";
  c << "  return 0;\n}\n\n";
}

} // namespace

bool cTranslatable(const VerifiedProgram &prog, std::string &error) {
  if (!prog.subs.empty()) {
    error = "subroutines (SP " + std::to_string(prog.subs.front().number) +
            ") are outside the C baseline's subset";
    return false;
  }
  for (size_t i = 0; i < prog.stmts.size(); ++i) {
    const Stmt &s = prog.stmts[i];
    if (supported(s.op)) continue;
    error = prog.file + ":" + std::to_string(s.loc.line) + ": '" + spelling(prog.dialect, s.op) +
            "' is outside the C baseline's subset (bit logic, MOV, math, compares, TMRB, counters, "
            "PLS/PLF/ALT)";
    return false;
  }
  return true;
}

std::string translateToC(const VerifiedProgram &p) {
  std::ostringstream c;
  c << "/* C baseline of " << p.file << " (ladderjit bench --c-baseline) */\n"
    << "#include <stdint.h>\n"
    << "typedef struct lj_state lj_state;\n"
    << "#define B(o) (((unsigned char *)s)[o])\n"
    << "#define I16(o) (*(int16_t *)((unsigned char *)s + (o)))\n"
    << "#define I32(o) (*(int32_t *)((unsigned char *)s + (o)))\n"
    << "#define U32(o) (*(uint32_t *)((unsigned char *)s + (o)))\n"
    << "#define NOW (*(uint64_t *)((unsigned char *)s + " << offsetof(lj_state, now_ms) << "))\n\n";
  emitPart(c, p, "part_init", p.init);
  emitPart(c, p, "part_plc1", p.plc1, p.profile->edgePolicy == EdgePolicy::PerObject);
  std::vector<StmtRange> slices = p.slices;
  if (slices.empty()) slices.push_back(p.plc2);
  for (size_t k = 0; k < slices.size(); ++k)
    emitPart(c, p, "slice_" + std::to_string(k), slices[k]);
  c << "uint32_t ljc_init(void *ctx, lj_state *s) { (void)ctx; return part_init(s); }\n"
    << "uint32_t ljc_plc1(void *ctx, lj_state *s) { (void)ctx; return part_plc1(s); }\n"
    << "uint32_t ljc_plc2_slice(void *ctx, lj_state *s, uint32_t k) {\n  (void)ctx;\n"
    << "  switch (k) {\n";
  for (size_t k = 0; k < slices.size(); ++k)
    c << "  case " << k << ": return slice_" << k << "(s);\n";
  c << "  default: return 0;\n  }\n}\n";
  return c.str();
}

} // namespace lj::gen

// The reference interpreter (the oracle): operand decoding, stack sizing, the entry points and
// the Engine. Written straight from DIALECT.md, docs/dialect-notes.md and the reference tables; it
// shares no code with the lowering or the JIT (STYLE.md 8). Statement dispatch, contacts, coils
// and flow: InterpFlow.cpp; function blocks: InterpBlocks.cpp (twins of lowering/Emit*.cpp).
//
// Shape: operands are decoded once into byte offsets of lj_state; each scope (part, subroutine,
// loop body) runs as a statement range with explicit ST/MS stacks. Recursion is a compile error,
// so every subroutine can own one preallocated pair of stacks; loops run on their scope's stacks
// (they are emptied at LOOP and NEXT anyway).
#include "interp/Interpreter.h"
#include "interp/InterpreterInternal.h"
#include "ir/SyncInputs.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cassert>
#include <cstddef>
#include <cstring>
#include <vector>

namespace lj {

using namespace interp;

// Bit operands are reduced to "one byte and a mask", which matches DIALECT.md 1 (bit k of a
// little-endian element) only on a little-endian host; the ABI is little-endian by definition.
static_assert(std::endian::native == std::endian::little, "lj_state is little-endian");

namespace {
/// Whether a verifier-assigned slot indexes its lj_state array (checked once, in asserts).
[[maybe_unused]] bool slotInRange(const TargetProfile &tp, StateKind k, int32_t slot) {
  switch (k) {
  case StateKind::None:
    return true;
  case StateKind::Edge:
    return slot >= 0 && slot < LJ_EDGE_SLOTS;
  case StateKind::Timer:
    return slot >= 0 && slot < tp.timerSlots();
  case StateKind::Counter:
    return slot >= 0 && slot < LJ_TC_SLOTS;
  case StateKind::Pls:
  case StateKind::Plf:
    return slot >= 0 && slot < tp.pulseSlots();
  case StateKind::Words:
    return slot >= 0 && slot + 1 < LJ_INST_WORDS;
  default:
    return slot >= 0 && slot < LJ_BLOCK_SLOTS;
  }
}

} // namespace

Interpreter::Impl::Impl(const VerifiedProgram &p, const ContactForces &forces, int32_t *traceBuf)
    : prog(p), trace(traceBuf) {
  if (trace) traceAt = traceLayout(p);
  code.resize(p.stmts.size());
  const std::vector<int8_t> forced = forceTable(p, forces);
  for (size_t i = 0; i < p.stmts.size(); ++i) {
    const Stmt &st = p.stmts[i];
    Code &c = code[i];
    c.op = st.op;
    // FANUC level 2 reads X and F through the synchronized input memory (ir/SyncInputs.h).
    const bool sync = readsSyncInputs(p, static_cast<int32_t>(i));
    c.a = decode(*prog.profile, st.ops[0], sync);
    c.b = decode(*prog.profile, st.ops[1], sync);
    c.c = decode(*prog.profile, st.ops[2], sync);
    c.target = p.info[i].target;
    c.slot = p.info[i].slot;
    if (!forced.empty()) c.force = forced[i];
    if (opFamily(st.op) != Family::Core) {
      c.wide = static_cast<int32_t>(wide.size());
      std::array<Ref, kMaxOperands> &w = wide.emplace_back();
      for (int k = 0; k < st.operandCount; ++k) w[k] = decode(*prog.profile, st.ops[k], sync);
    }
    assert(slotInRange(*p.profile, instrInfo(c.op).state, c.slot) && "state slot out of range");
    assert((c.op != Op::Jump && c.op != Op::LoopBegin) ||
           (c.target >= 0 && static_cast<size_t>(c.target) < p.stmts.size()));
    assert(c.op != Op::JumpOut ||
           (c.target >= 0 && static_cast<size_t>(c.target) < p.stmts.size()));
    assert(c.op != Op::Call || (c.target >= 0 && static_cast<size_t>(c.target) < p.subs.size()));
  }
  edgeUpdates = p.profile->edgePolicy == EdgePolicy::PerInstance;
  for (size_t k = 0; k < p.edgeObjects.size(); ++k)
    if (p.edgeObjects[k].kind == Operand::Kind::Bit)
      edgeImage.emplace_back(static_cast<int32_t>(k), decode(*prog.profile, p.edgeObjects[k]));
  // Stack capacity per scope: the deepest "depth before" in the scope, plus one because a
  // statement raises the depth by at most one.
  auto need = [&](StmtRange r, int32_t &st, int32_t &ms) {
    for (int32_t i = r.begin; i < r.end; ++i) {
      st = std::max(st, p.info[i].depth + 1);
      ms = std::max(ms, p.info[i].msDepth + 1);
    }
  };
  int32_t st = std::max(p.maxDepth, 0) + 1, ms = std::max(p.maxMsDepth, 0) + 1;
  need(p.init, st, ms);
  need(p.plc1, st, ms);
  need(p.plc2, st, ms);
  for (int32_t d : p.sliceDepth) st = std::max(st, d + 1);
  stStore.emplace_back(st);
  msStore.emplace_back(ms);
  for (const Subroutine &sub : p.subs) {
    int32_t sst = 1, sms = 1;
    need(sub.body, sst, sms);
    stStore.emplace_back(sst);
    msStore.emplace_back(sms);
  }
}

Frame Interpreter::Impl::frame(size_t scope) {
  return Frame{stStore[scope].data(), msStore[scope].data(),
               static_cast<int32_t>(stStore[scope].size()),
               static_cast<int32_t>(msStore[scope].size())};
}

namespace {
uint32_t initEntry(void *ctx, lj_state *s) { return static_cast<Interpreter *>(ctx)->runInit(s); }
uint32_t plc1Entry(void *ctx, lj_state *s) { return static_cast<Interpreter *>(ctx)->runPlc1(s); }
uint32_t sliceEntry(void *ctx, lj_state *s, uint32_t k) {
  return static_cast<Interpreter *>(ctx)->runPlc2Slice(s, k);
}
} // namespace

Interpreter::Interpreter(const VerifiedProgram &prog, const ContactForces &forces, int32_t *trace)
    : impl_(std::make_unique<Impl>(prog, forces, trace)) {
  entries_.ctx = this;
  entries_.init = initEntry;
  entries_.plc1 = plc1Entry;
  entries_.plc2_slice = sliceEntry;
  entries_.plc2_slice_count = sliceCount();
}

Interpreter::~Interpreter() = default;

uint32_t Interpreter::runInit(lj_state *s) { return impl_->runPart(s, impl_->prog.init, 0); }

uint32_t Interpreter::runPlc1(lj_state *s) {
  uint32_t r = impl_->runPart(s, impl_->prog.plc1, 0);
  // EdgePolicy::PerObject: the previous-scan image, sampled once per scan (ir/Profile.h).
  for (const auto &[slot, bit] : impl_->edgeImage) s->edge[slot] = readBit(s, bit);
  return r;
}

uint32_t Interpreter::runPlc2Slice(lj_state *s, uint32_t slice) {
  const VerifiedProgram &p = impl_->prog;
  if (slice == 0 && latchesSyncInputs(p)) {
    // A scan of the divided sliced part starts: latch the inputs it reads (FANUC level 2's
    // synchronized input memory, ir/Profile.h SyncInputs).
    const TargetProfile::SyncInputs &m = p.profile->syncInputs;
    std::memcpy(bytes(s) + m.copy, bytes(s) + m.from, m.bytes);
  }
  if (p.slices.empty()) return slice == 0 ? impl_->runPart(s, p.plc2, 0) : LJ_FAULT_NONE;
  if (slice >= p.slices.size()) return LJ_FAULT_NONE;
  int32_t depth = slice < p.sliceDepth.size() ? p.sliceDepth[slice] : 0;
  return impl_->runPart(s, p.slices[slice], depth);
}

Op Interpreter::unimplemented() const { return impl_->unimplemented; }

uint32_t Interpreter::sliceCount() const {
  return std::max<uint32_t>(1u, static_cast<uint32_t>(impl_->prog.slices.size()));
}

namespace {
/// The interpreter behind the common Engine interface (ir/Engine.h).
class InterpreterEngine final : public Engine {
public:
  InterpreterEngine(const VerifiedProgram &prog, const ContactForces &forces, int32_t *trace)
      : interp_(prog, forces, trace) {}
  const lj_entries &entries() const override { return interp_.entries(); }
  const char *name() const override { return "interp"; }

private:
  Interpreter interp_;
};
} // namespace

std::unique_ptr<Engine> makeInterpreterEngine(const VerifiedProgram &prog,
                                              const ContactForces &forces, int32_t *trace) {
  return std::make_unique<InterpreterEngine>(prog, forces, trace);
}

} // namespace lj

// The content of a leaf's cache key (lowering/Incremental.h): everything the lowering of one
// leaf reads, with statement positions made relative to the leaf so that an edit elsewhere
// that only moves the leaf keeps its key, and every fact that changes its code changing it.
#include "lowering/Incremental.h"

#include "ir/SyncInputs.h"

#include <type_traits>

namespace lj::lower {

namespace {

// A new field in these types must be added below if the lowering reads it (else two leaves
// differing only in it would share cached code). The sizes are the reminder; jit/ObjectCache.cpp
// has the same one for the whole-program digest.
static_assert(sizeof(Operand) == 24 && sizeof(Stmt) == 232 && sizeof(StmtInfo) == 20 &&
                  sizeof(Subroutine) == 16 && sizeof(StmtRange) == 8 && sizeof(ChunkPlan) == 28,
              "program model changed: update leafDigestInput()");

// Little-endian, appended in one go (the key of every group is built on every compile).
template <typename T> void put(std::string &out, T v) {
  auto u = static_cast<uint64_t>(static_cast<std::make_unsigned_t<T>>(v));
  char b[sizeof(T)];
  for (size_t i = 0; i < sizeof(T); ++i) b[i] = static_cast<char>((u >> (8 * i)) & 0xff);
  out.append(b, sizeof(T));
}

} // namespace

std::string leafDigestInput(const VerifiedProgram &p, const Leaf &leaf,
                            const std::vector<int8_t> &forced) {
  std::string s;
  const StmtRange r = leaf.r;
  s.reserve(static_cast<size_t>(r.end - r.begin) * 64 + 64);
  s += "leaf 1";
  put(s, r.end - r.begin);
  put(s, leaf.deadDepth);
  put(s, leaf.retnStatus);
  put(s, static_cast<uint8_t>(leaf.chunk));
  put(s, static_cast<uint8_t>(leaf.carried));
  put(s, leaf.msBase);
  // X and F read live or from the synchronized input memory (the same statements in level 1
  // and in a divided level 2 of a FANUC program address different bytes).
  put(s, static_cast<uint8_t>(readsSyncInputs(p, r.begin)));
  if (leaf.chunk) {
    const ChunkPlan &c = leaf.plan;
    put(s, static_cast<uint8_t>(c.carriedIn));
    put(s, static_cast<uint8_t>(c.carriedOut));
    put(s, static_cast<uint8_t>(c.jumps));
    put(s, c.stLoad);
    put(s, c.msLoad);
    put(s, c.stStore);
    put(s, c.msStore);
  }
  for (int32_t i = r.begin; i < r.end; ++i) {
    const Stmt &st = p.stmts[i];
    const StmtInfo &in = p.info[i];
    put(s, static_cast<uint8_t>(st.op));
    put(s, st.operandCount);
    for (int32_t k = 0; k < st.operandCount && k < static_cast<int32_t>(std::size(st.ops)); ++k) {
      const Operand &o = st.ops[k];
      put(s, static_cast<uint8_t>(o.kind));
      put(s, static_cast<uint8_t>(o.area));
      put(s, o.index);
      put(s, o.bit);
      put(s, o.value);
      put(s, o.width); // MOVB and MOVW of the same bytes differ only here
      put(s, static_cast<uint8_t>(o.bcd));
    }
    put(s, in.depth);
    put(s, in.msDepth);
    put(s, in.slot); // an absolute edge / timer / counter / pulse slot: a state offset
    put(s, static_cast<uint8_t>(in.hasInput));
    put(s, static_cast<uint8_t>(in.backward));
    // Where the target is, as the code sees it.
    if (in.target < 0) {
      put(s, 'n');
    } else if (st.op == Op::JumpOut) {
      put(s, 'o'); // returns its label's number (an operand above), wherever the label is
    } else if (in.target >= r.begin && in.target < r.end && st.op != Op::Call) {
      put(s, 'r');
      put(s, in.target - r.begin);
    } else if (st.op == Op::Call && in.target < static_cast<int32_t>(p.subs.size())) {
      put(s, 'c'); // the callee by the number its symbol carries (lj_sub<number>)
      put(s, p.subs[in.target].number);
    } else if (st.op == Op::Jump && leaf.labelChunk && leaf.labelChunk->count(in.target)) {
      put(s, 'j'); // a jump out of this chunk returns the index of the chunk it goes on at
      put(s, leaf.labelChunk->at(in.target));
    } else {
      put(s, 'a'); // anything else: its absolute position (never reused after a shift)
      put(s, in.target);
    }
    // A CALL that goes on at a JumpOut's label: each label's number and where it is.
    if (st.op == Op::Call)
      for (const auto &[call, lbl] : exitsOfCall(p, i)) {
        put(s, p.stmts[lbl].ops[0].index);
        if (lbl >= r.begin && lbl < r.end) {
          put(s, 'r');
          put(s, lbl - r.begin);
        } else if (leaf.labelChunk && leaf.labelChunk->count(lbl)) {
          put(s, 'j');
          put(s, leaf.labelChunk->at(lbl));
        } else {
          put(s, 'a');
          put(s, lbl);
        }
      }
    put(s, forced.empty() ? int8_t{-1} : forced[i]);
  }
  return s;
}

} // namespace lj::lower

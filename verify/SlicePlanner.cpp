// PLC2 slice planning (DIALECT.md 4, dialect-notes "PLC2 slicing"): a slice ends at the first
// rung boundary after at least plc2_nvalue statements that is not inside a loop body nor between
// a JMP and its label. Rung boundaries (MS empty, no ST entry present read later before the next
// stack reset) come from VerifiedProgram::rungs (Rungs.cpp).
#include "verify/VerifierInternal.h"

namespace lj::verifier {

void planSlices(Context &cx) {
  VerifiedProgram &p = cx.prog;
  const StmtRange r = p.plc2;
  p.slices.clear();
  p.sliceDepth.clear();
  if (r.empty() || *cx.opts.plc2Nvalue <= 0) {
    p.slices.push_back(r);
    p.sliceDepth.push_back(0);
    return;
  }
  auto len = static_cast<size_t>(r.end - r.begin);
  auto rel = [&](int32_t i) { return static_cast<size_t>(i - r.begin); };

  // Rung starts (Rungs.cpp, planned before this): MS empty and every ST entry present dead.
  std::vector<char> rungStart(len + 1, 0);
  for (const RungRange &rr : p.rungs)
    if (rr.range.begin >= r.begin && rr.range.begin < r.end) rungStart[rel(rr.range.begin)] = 1;

  // Positions covered by a loop body or a JMP..LBL span: cover[i] > 0 forbids a boundary
  // before i. A body covers (LOOP, NEXT]; a jump span covers (min, max].
  std::vector<int32_t> cover(len + 1, 0);
  auto span = [&](int32_t a, int32_t b) {
    if (b < r.begin || a >= r.end) return;
    a = std::max(a, r.begin - 1);
    b = std::min(b, r.end - 1);
    ++cover[rel(a + 1)];
    --cover[rel(b + 1)];
  };
  for (const auto &[a, b] : cx.jumpSpans) span(a, b);
  for (int32_t i = r.begin; i < r.end; ++i)
    if (cx.stmt(i).op == Op::LoopBegin && p.info[static_cast<size_t>(i)].target > i)
      span(i, p.info[static_cast<size_t>(i)].target);
  for (size_t i = 1; i <= len; ++i) cover[i] += cover[i - 1];

  auto boundary = [&](int32_t i) { return rungStart[rel(i)] && cover[rel(i)] == 0; };

  const int64_t n = *cx.opts.plc2Nvalue;
  int32_t start = r.begin;
  int32_t i = r.begin;
  while (true) {
    i = static_cast<int32_t>(std::min<int64_t>(std::max<int64_t>(i, start + n), r.end));
    while (i < r.end && !boundary(i)) ++i;
    if (i >= r.end) break;
    p.slices.push_back({start, i});
    p.sliceDepth.push_back(p.info[static_cast<size_t>(start)].depth);
    start = i;
  }
  p.slices.push_back({start, r.end});
  p.sliceDepth.push_back(p.info[static_cast<size_t>(start)].depth);
}

} // namespace lj::verifier

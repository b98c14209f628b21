// The C baseline of `ladderjit bench --c-baseline` (docs/bench.md): a verified program as
// straight C over the lj_state layout of runtime_abi (byte offsets, ST/MS entries as locals),
// the way transpile-to-C PLC toolchains do it. Only a subset of statements is expressible; the
// rest is refused with the statement named.
#pragma once

#include "ir/Program.h"

#include <string>

namespace lj::gen {

/// Whether every statement of `prog` is in the subset: contacts (edges included, per instance
/// or per object), ANB/ORB, MPS/MRD/MPP, OUT/OOUT/SET/RST, the part markers, ADD/SUB/MUL/DIV/AND/
/// OR/XOR, INC/DEC/NEG, MOV, the compares (LE/LT/EQ/range), the on-delay timer (TMRB), the
/// counters (CTR, CTRC, CTUD), PLS/PLF (FANUC DIFU/DIFD), ALT and labels. Operands of any dialect
/// (HNC-8, FANUC, IEC) at their profile offsets and widths. No jumps, calls, loops or forces. On
/// false, `error` names the first statement that is not.
bool cTranslatable(const VerifiedProgram &prog, std::string &error);

/// The C translation: exports `ljc_init`, `ljc_plc1` (lj_part_fn) and `ljc_plc2_slice`
/// (lj_slice_fn). `prog` must be cTranslatable.
std::string translateToC(const VerifiedProgram &prog);

} // namespace lj::gen

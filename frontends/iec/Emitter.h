// How IEC IL maps onto the IR (docs/iec-il.md "Instructions"): the accumulator is ST0 of the
// IR's logic stack; LD pushes (the entries below are dead), AND( / OR( push their first operand
// and `)` combines with AndBlock / OrBlock, MPS/MRD/MPP are the IR's branch stack. N, XOR and
// OPEN/SHORT have no IR operation: they are expanded into existing ones through one scratch bit
// (of the profile's scratch bytes) per use, so the IR needed no change.
#pragma once

#include "ir/Diagnostics.h"
#include "ir/Program.h"

#include <initializer_list>

namespace lj::iec {

class Emitter {
public:
  Emitter(ParsedProgram &prog, Diagnostics &diags) : prog_(prog), diags_(diags) {}

  /// One statement `op` with `operands` at `loc`.
  void emit(Op op, SourceLoc loc, std::initializer_list<Operand> operands = {});
  /// A fresh scratch bit; an error at `loc` when they run out.
  Operand scratch(SourceLoc loc);
  /// acc := NOT acc.
  void negate(SourceLoc loc);
  /// acc := acc XOR c(x), c being the contact form `push` (Load, LoadNot, LoadRise, LoadFall).
  void exclusiveOr(Op push, const Operand &x, SourceLoc loc);
  /// acc := 0 (OPEN, AND 0) or acc := 1 (SHORT, OR 1).
  void constant(bool value, SourceLoc loc);

private:
  ParsedProgram &prog_;
  Diagnostics &diags_;
  int32_t scratchUsed_ = 0;
};

} // namespace lj::iec

// The reference interpreter (the oracle): executes a VerifiedProgram on an lj_state statement by
// statement with explicit ST/MS stacks, written straight from DIALECT.md (STYLE.md 8).
#pragma once

#include "ir/Engine.h"
#include "ir/Forces.h"
#include "ir/Program.h"
#include "ladderjit/abi.h"

#include <memory>

namespace lj {

/// Runs one verified program. Holds no program state of its own: everything persistent is in
/// the lj_state passed to each call, exactly as for compiled code. The interpreter only keeps
/// scratch stacks (preallocated) and the operands decoded once at construction.
class Interpreter {
public:
  /// Binds to `prog`, which must outlive the interpreter; the contacts in `forces` conduct
  /// their forced value (ir/Forces.h, kept in the decoded table, not in `prog`). `trace`, when
  /// not null, is a buffer of traceLayout(prog).words int32 words the statements record into
  /// (ir/Trace.h); it must outlive the interpreter.
  explicit Interpreter(const VerifiedProgram &prog, const ContactForces &forces = {},
                       int32_t *trace = nullptr);
  ~Interpreter();
  Interpreter(const Interpreter &) = delete;
  Interpreter &operator=(const Interpreter &) = delete;

  /// Run the init part. Returns LJ_FAULT_NONE or the fault that stopped it.
  uint32_t runInit(lj_state *s);
  /// Run PLC1 completely (or until a fault).
  uint32_t runPlc1(lj_state *s);
  /// Run PLC2 slice `slice` (an index >= sliceCount() runs nothing).
  uint32_t runPlc2Slice(lj_state *s, uint32_t slice);
  /// Number of PLC2 slices (>= 1).
  uint32_t sliceCount() const;
  /// The last executed instruction the interpreter has no semantics for (it did nothing), or
  /// Op::Count_ when there was none. Checked by the catalogue completeness test.
  Op unimplemented() const;

  /// Entry table bound to this interpreter, for lj_tick / lj_run_init. Valid while `this` lives.
  const lj_entries &entries() const { return entries_; }

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  lj_entries entries_{};
};

} // namespace lj

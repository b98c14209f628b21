// The reference interpreter (the oracle): executes a VerifiedProgram on an lj_state statement by
// statement with explicit ST/MS stacks, written straight from DIALECT.md (STYLE.md 8).
#pragma once

#include "instructions/Program.h"
#include "ladderjit/abi.h"

#include <memory>

namespace lj {

/// Runs one verified program. Holds no program state of its own: everything persistent is in
/// the lj_state passed to each call, exactly as for compiled code.
class Interpreter {
public:
  explicit Interpreter(const VerifiedProgram &prog);
  ~Interpreter();
  Interpreter(const Interpreter &) = delete;
  Interpreter &operator=(const Interpreter &) = delete;

  uint32_t runInit(lj_state *s);
  uint32_t runPlc1(lj_state *s);
  uint32_t runPlc2Slice(lj_state *s, uint32_t slice);
  uint32_t sliceCount() const;

  /// Entry table bound to this interpreter, for lj_tick / lj_run_init. Valid while `this` lives.
  const lj_entries &entries() const { return entries_; }

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  lj_entries entries_{};
};

} // namespace lj

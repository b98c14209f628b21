// A program ready to run: its entry table plus whatever keeps the code alive. The interpreter,
// the JIT and AOT loaders all hand out this one type, so tests, the fuzzer and the CLI drive
// every engine the same way (through lj_tick / lj_run_init).
#pragma once

#include "ir/Forces.h"
#include "ir/Program.h"
#include "ladderjit/abi.h"

#include <memory>

namespace lj {

class Engine {
public:
  virtual ~Engine() = default;
  /// Entry points; valid while the engine lives.
  virtual const lj_entries &entries() const = 0;
  /// Short name for messages ("interp", "jit").
  virtual const char *name() const = 0;
};

/// The reference interpreter bound to `prog` (which must outlive the engine), with the
/// contacts in `forces` forced (ir/Forces.h); `trace` not null: a traced build recording into
/// that buffer of traceLayout(prog).words words (ir/Trace.h), which must outlive the engine.
std::unique_ptr<Engine> makeInterpreterEngine(const VerifiedProgram &prog,
                                              const ContactForces &forces = {},
                                              int32_t *trace = nullptr);

} // namespace lj

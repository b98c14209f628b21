// Test harness of the JIT: compile STL, run it on the reference interpreter and on the JIT in
// lock-step with identical host writes, and compare the complete lj_state after every step.
#pragma once

#include "instructions/Engine.h"
#include "instructions/FrontEnd.h"
#include "jit/Jit.h"
#include "ladderjit/abi.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

namespace lj::test {

/// Front end or a recorded test failure.
std::optional<VerifiedProgram> verifyOrFail(std::string_view text, int32_t plc2Nvalue = 200);

/// Host writes of one run: `before` after reset and before init, `inputs` before each tick.
struct Drive {
  uint32_t ticks = 1;
  uint64_t periodMs = 1;
  uint64_t maxSteps = 1000000;
  std::function<void(lj_state &)> before;
  std::function<void(uint32_t tick, lj_state &)> inputs;
};

/// One program on one engine with its own state (reset to power-up).
struct Run {
  std::unique_ptr<Engine> engine;
  std::unique_ptr<lj_state> state;
};

/// The JIT engine of `prog` or a recorded failure (null).
std::unique_ptr<Engine> jitOrFail(const VerifiedProgram &prog, jit::Tier tier,
                                  int32_t chunkStatements = 150);

/// Name of the lj_state field holding byte `offset` ("img.R[10]", "T[3].out", "edge[7]").
std::string fieldAt(size_t offset);

/// First differing byte of two states, or success.
::testing::AssertionResult sameState(const lj_state &ref, const lj_state &got);

/// Run `prog` on the interpreter and on the JIT of `tier` (with `chunkStatements`), comparing
/// fault codes and full state after init and after every tick. `check`, if given, sees the
/// interpreter's state after each tick (tick index, state, fault) for expected-value checks.
::testing::AssertionResult
jitMatchesInterpreter(const VerifiedProgram &prog, jit::Tier tier, const Drive &drive,
                      const std::function<void(uint32_t, const lj_state &, uint32_t)> &check = {},
                      int32_t chunkStatements = 150);

/// Run `prog` on one engine alone and return the final state (for expected-value tests).
std::unique_ptr<lj_state>
runAlone(const Engine &engine, const Drive &drive,
         const std::function<void(uint32_t, const lj_state &, uint32_t)> &check = {});

/// Bit `bit` of byte array element (X/Y/R), for readable expectations.
inline int bitOf(uint8_t v, int bit) { return (v >> bit) & 1; }

/// Tier names for parameterized tests.
inline std::string tierName(const ::testing::TestParamInfo<jit::Tier> &info) {
  return info.param == jit::Tier::Fast ? "Fast" : "Optimizing";
}

} // namespace lj::test

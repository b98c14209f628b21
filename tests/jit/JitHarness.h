// JIT-specific test helpers: JIT engines built with explicit options (tier, chunking, partitioned
// compile), run against the reference interpreter by the shared lock-step harness of
// tests/support (CrossEngine.h), which compares fault codes and the complete lj_state.
#pragma once

#include "jit/Jit.h"
#include "tests/support/CrossEngine.h"
#include "tests/support/Machine.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <functional>
#include <optional>
#include <string>

namespace lj::test {

/// An engine factory for the JIT with exactly `opts` (the registry's JIT uses the defaults).
EngineFactory jitEngine(const jit::JitOptions &opts);

/// Expected-value check on the interpreter's state after each tick (tick, state, fault code).
using StateCheck = std::function<void(uint32_t tick, const lj_state &ref, uint32_t fault)>;

/// sameStateOnEngines on {reference interpreter, JIT built with `opts`}: fault codes and every
/// byte of lj_state equal after init and after every tick. `check` sees the interpreter's state
/// after every tick.
::testing::AssertionResult jitMatchesInterpreter(const VerifiedProgram &prog,
                                                 const jit::JitOptions &opts, const Scenario &sc,
                                                 const StateCheck &check = {});

/// The same for the JIT of `tier` cutting bodies every `chunkStatements` statements.
::testing::AssertionResult jitMatchesInterpreter(const VerifiedProgram &prog, jit::Tier tier,
                                                 const Scenario &sc, const StateCheck &check = {},
                                                 int32_t chunkStatements = 150);

/// The differential fuzzer's random program for `seed` of about `statements` statements
/// (gen/ProgramGenerator.h: every table row, deep ANB/ORB and MPS nesting, loops, jumps,
/// nested calls, RETN, faults), verified with `plc2Nvalue` or, when negative, with the slicing
/// parameter it was generated for. `text`, when given, receives the program.
std::optional<VerifiedProgram> randomProgramOrFail(uint64_t seed, int32_t statements,
                                                   std::string *text = nullptr,
                                                   int32_t plc2Nvalue = -1);

/// `ticks` ticks of the fuzzer's random stimulus for `seed` (P/B/X/F before init, X/F writes
/// before every tick) at now_ms = tick * `periodMs`, with the watchdog at `maxBackwardSteps`.
Scenario randomScenario(uint64_t seed, uint32_t ticks, uint32_t periodMs,
                        uint64_t maxBackwardSteps);

/// Bit `bit` of byte array element (X/Y/R), for readable expectations.
inline int bitOf(uint8_t v, int bit) { return (v >> bit) & 1; }

/// Tier names for parameterized tests.
inline std::string tierName(const ::testing::TestParamInfo<jit::Tier> &info) {
  return info.param == jit::Tier::Fast ? "Fast" : "Optimizing";
}

} // namespace lj::test

// Differential execution: one program and one scenario on every registered engine in lock-step,
// the complete lj_state compared after init and after every tick (STYLE.md 12).
#pragma once

#include "tests/support/Machine.h"
#include "verify/Verify.h"

#include <gtest/gtest.h>

#include <functional>

namespace lj::test {

/// Called on the reference engine (registeredEngines()[0]) after init (`tick` = -1) and after
/// every tick, with that step's fault code, so a test can also check expected values.
using TickCheck = std::function<void(int64_t tick, const Machine &ref, uint32_t fault)>;

/// Run `sc` on every registered engine: reset, `sc.before` and `sc.hostBefore` writes, init,
/// then `sc.ticks` ticks with `sc.inputs` and `sc.hostInputs` applied before their tick and
/// now_ms = tick * sc.periodMs. Fails at the first
/// step where a fault code or any byte of the state differs from the reference engine, naming
/// the step, the engine and the first differing field.
::testing::AssertionResult sameStateOnAllEngines(const VerifiedProgram &prog, const Scenario &sc,
                                                 const TickCheck &check = {});

/// The same on an explicit list of engines (entry 0 is the reference), e.g. engines built with
/// non-default options that the registry does not hold.
::testing::AssertionResult sameStateOnEngines(const std::vector<EngineFactory> &engines,
                                              const VerifiedProgram &prog, const Scenario &sc,
                                              const TickCheck &check = {});

/// compileOrFail + sameStateOnAllEngines.
::testing::AssertionResult sameStateOnAllEngines(std::string_view text, const Scenario &sc,
                                                 const VerifyOptions &opts = VerifyOptions{},
                                                 const TickCheck &check = {});

} // namespace lj::test

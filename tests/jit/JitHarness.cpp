// JIT engines with explicit options, checked against the interpreter by tests/support.
#include "tests/jit/JitHarness.h"

#include "gen/ProgramGenerator.h"

#include <memory>
#include <vector>

namespace lj::test {

EngineFactory jitEngine(const jit::JitOptions &opts) {
  std::string name = opts.tier == jit::Tier::Fast ? "jit_fast" : "jit_opt";
  return {name, [opts](const VerifiedProgram &p, std::string &error) {
            return jit::compile(p, opts, error);
          }};
}

::testing::AssertionResult jitMatchesInterpreter(const VerifiedProgram &prog,
                                                 const jit::JitOptions &opts, const Scenario &sc,
                                                 const StateCheck &check) {
  // registeredEngines() lists the reference interpreter first (EngineRegistry.h).
  const std::vector<EngineFactory> engines = {registeredEngines().front(), jitEngine(opts)};
  TickCheck afterTicks;
  if (check)
    afterTicks = [&check](int64_t tick, const Machine &ref, uint32_t fault) {
      if (tick >= 0) check(static_cast<uint32_t>(tick), ref.state(), fault);
    };
  return sameStateOnEngines(engines, prog, sc, afterTicks);
}

::testing::AssertionResult jitMatchesInterpreter(const VerifiedProgram &prog, jit::Tier tier,
                                                 const Scenario &sc, const StateCheck &check,
                                                 int32_t chunkStatements) {
  jit::JitOptions opts;
  opts.tier = tier;
  opts.chunkStatements = chunkStatements;
  return jitMatchesInterpreter(prog, opts, sc, check);
}

std::optional<VerifiedProgram> randomProgramOrFail(uint64_t seed, int32_t statements,
                                                   std::string *text, int32_t plc2Nvalue) {
  gen::RandomOptions o;
  o.seed = seed;
  o.statements = statements;
  o.avoidWatchdog = true; // most ticks run the whole program (the watchdog has its own tests)
  gen::GenProgram p = gen::generateRandom(o);
  if (text) *text = p.text();
  return compileOrFail(p.text(), optionsWithNvalue(plc2Nvalue < 0 ? p.plc2Nvalue : plc2Nvalue));
}

Scenario randomScenario(uint64_t seed, uint32_t ticks, uint32_t periodMs,
                        uint64_t maxBackwardSteps) {
  // Shared by the copies of the scenario the lambdas live in.
  auto st = std::make_shared<const gen::Stimulus>(gen::generateStimulus(seed, ticks));
  Scenario sc;
  sc.ticks = ticks;
  sc.periodMs = periodMs;
  // Not the stimulus' own limit: its small values (50, 300) would end a third of the ticks in
  // the watchdog and leave the rest of the program unchecked.
  sc.maxBackwardSteps = maxBackwardSteps;
  sc.hostBefore = [st](lj_state &s) { gen::applyWrites(s, st->beforeInit); };
  sc.hostInputs = [st](uint32_t tick, lj_state &s) { gen::applyWrites(s, st->writes[tick]); };
  return sc;
}

} // namespace lj::test

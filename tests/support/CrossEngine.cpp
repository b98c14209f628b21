// Lock-step runs of every registered engine with whole-state comparison.
#include "tests/support/CrossEngine.h"
#include "verify/Verify.h"

#include "tests/support/StateDiff.h"

#include <memory>
#include <vector>

namespace lj::test {

namespace {

::testing::AssertionResult compareAll(const std::vector<std::unique_ptr<Machine>> &ms,
                                      const std::vector<uint32_t> &faults, const char *step) {
  for (size_t i = 1; i < ms.size(); ++i) {
    const char *ref = ms[0]->engine().name(), *other = ms[i]->engine().name();
    if (faults[i] != faults[0])
      return ::testing::AssertionFailure() << step << ": fault code " << ref << "=" << faults[0]
                                           << " " << other << "=" << faults[i];
    std::string diff = describeDifference(ms[0]->state(), ms[i]->state(), ref, other);
    if (!diff.empty()) return ::testing::AssertionFailure() << step << ": " << diff;
  }
  return ::testing::AssertionSuccess();
}

} // namespace

::testing::AssertionResult sameStateOnAllEngines(const VerifiedProgram &prog, const Scenario &sc,
                                                 const TickCheck &check) {
  return sameStateOnEngines(registeredEngines(), prog, sc, check);
}

::testing::AssertionResult sameStateOnEngines(const std::vector<EngineFactory> &engines,
                                              const VerifiedProgram &prog, const Scenario &sc,
                                              const TickCheck &check) {
  std::vector<std::unique_ptr<Machine>> ms;
  for (const EngineFactory &f : engines) {
    std::unique_ptr<Machine> m = Machine::create(prog, f);
    if (!m) return ::testing::AssertionFailure() << "engine " << f.name << " could not be built";
    m->setPeriodMs(sc.periodMs);
    m->state().max_backward_steps = sc.maxBackwardSteps;
    for (const Stimulus &st : sc.before) m->set(st.addr, st.value);
    if (sc.hostBefore) sc.hostBefore(m->state());
    ms.push_back(std::move(m));
  }
  std::vector<uint32_t> faults(ms.size());
  for (size_t i = 0; i < ms.size(); ++i) faults[i] = ms[i]->init();
  if (check) check(-1, *ms[0], faults[0]);
  if (auto r = compareAll(ms, faults, "after init"); !r) return r;
  for (uint32_t t = 0; t < sc.ticks; ++t) {
    for (size_t i = 0; i < ms.size(); ++i) faults[i] = ms[i]->tick(sc);
    if (check) check(t, *ms[0], faults[0]);
    std::string step = "after tick " + std::to_string(t);
    if (auto r = compareAll(ms, faults, step.c_str()); !r) return r;
  }
  return ::testing::AssertionSuccess();
}

::testing::AssertionResult sameStateOnAllEngines(std::string_view text, const Scenario &sc,
                                                 const VerifyOptions &opts,
                                                 const TickCheck &check) {
  std::optional<VerifiedProgram> prog = compileOrFail(text, opts);
  if (!prog) return ::testing::AssertionFailure() << "program does not verify";
  return sameStateOnAllEngines(*prog, sc, check);
}

} // namespace lj::test

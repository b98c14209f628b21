// Fixture for execution tests: every TEST_P runs once per registered engine.
#pragma once

#include "tests/support/CrossEngine.h"
#include "tests/support/EngineRegistry.h"
#include "tests/support/Machine.h"
#include "verify/Verify.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <initializer_list>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace lj::test {

/// The inputs of one combination, looked up by address text.
class Inputs {
public:
  Inputs(std::vector<std::string> names, uint32_t combo)
      : names_(std::move(names)), combo_(combo) {}
  /// Value of input `name` in this combination (a missing name fails the test).
  bool operator()(std::string_view name) const {
    for (size_t i = 0; i < names_.size(); ++i)
      if (names_[i] == name) return (combo_ >> i) & 1u;
    ADD_FAILURE() << "input " << name << " is not part of the combination";
    return false;
  }
  std::string describe() const {
    std::string s;
    for (size_t i = 0; i < names_.size(); ++i)
      s += names_[i] + "=" + std::to_string((combo_ >> i) & 1u) + " ";
    return s;
  }

private:
  std::vector<std::string> names_;
  uint32_t combo_;
};

class ExecTest : public ::testing::TestWithParam<EngineFactory> {
protected:
  /// Compile, build the engine of this test instance and run init (which must not fault).
  std::unique_ptr<Machine> load(std::string_view text,
                                const VerifyOptions &opts = VerifyOptions{}) {
    std::unique_ptr<Machine> m = loadNoInit(text, opts);
    if (m) {
      EXPECT_EQ(m->init(), uint32_t{LJ_FAULT_NONE});
    }
    return m;
  }
  /// Compile and build without running init (to preset state first).
  std::unique_ptr<Machine> loadNoInit(std::string_view text,
                                      const VerifyOptions &opts = VerifyOptions{}) {
    return Machine::load(text, GetParam(), opts);
  }

  /// Load without init, attach the NC host (null: no host, the lj_host defaults), then init.
  std::unique_ptr<Machine> loadWithHost(std::string_view text, const lj_host *host) {
    std::unique_ptr<Machine> m = loadNoInit(text);
    if (!m) return m;
    m->state().host = host;
    EXPECT_EQ(m->init(), uint32_t{LJ_FAULT_NONE});
    return m;
  }

  /// For every combination of `names` (2^n): write them, run one tick, call check(in).
  template <typename Check>
  void forAllInputs(Machine &m, std::vector<std::string> names, Check check) {
    for (uint32_t combo = 0; combo < (1u << names.size()); ++combo) {
      Inputs in(names, combo);
      for (size_t i = 0; i < names.size(); ++i) m.set(names[i], (combo >> i) & 1u);
      EXPECT_EQ(m.tick(), uint32_t{LJ_FAULT_NONE});
      SCOPED_TRACE(in.describe());
      check(in);
    }
  }

  /// `n` full pulses of a bit (one tick at 1, one tick at 0 each).
  static void pulse(Machine &m, std::string_view addr, int n) {
    for (int i = 0; i < n; ++i) {
      m.set(addr, 1);
      m.tick();
      m.set(addr, 0);
      m.tick();
    }
  }
};

} // namespace lj::test

/// Instantiate a fixture derived from ExecTest once per registered engine.
#define LJ_EXEC_SUITE(Suite)                                                                       \
  INSTANTIATE_TEST_SUITE_P(Engines, Suite, ::testing::ValuesIn(::lj::test::registeredEngines()),   \
                           [](const ::testing::TestParamInfo<::lj::test::EngineFactory> &info) {   \
                             return info.param.name;                                               \
                           })

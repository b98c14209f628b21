// Fixture of the IEC IL tests: compile IL (frontends/iec), run it on every registered engine,
// read and write Neza objects (`%I0.1`, `%MW5`) through the dialect's address parser.
#pragma once

#include "frontends/iec/FrontEnd.h"
#include "pipeline/Compile.h"
#include "pipeline/Dialects.h"
#include "tests/support/EngineRegistry.h"
#include "tests/support/Machine.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace lj::test {

/// Compile IL; on an error, a test failure with the diagnostics.
inline std::optional<VerifiedProgram> compileIlOrFail(std::string_view text) {
  Diagnostics diags("test.il");
  std::optional<VerifiedProgram> p = pipeline::compileIl(text, "test.il", VerifyOptions{}, diags);
  if (!p) ADD_FAILURE() << diags.render();
  return p;
}

/// The diagnostics of compiling `text` (expected to fail).
inline std::string ilErrors(std::string_view text) {
  Diagnostics diags("test.il");
  std::optional<VerifiedProgram> p = pipeline::compileIl(text, "test.il", VerifyOptions{}, diags);
  EXPECT_FALSE(p.has_value()) << "compiled although it should not:\n" << text;
  return diags.render();
}

inline formats::CliAddress ilAddress(std::string_view text) {
  std::string err;
  std::optional<formats::CliAddress> a = pipeline::dialectNamed("iec")->parseAddress(text, err);
  EXPECT_TRUE(a.has_value()) << err;
  return a.value_or(formats::CliAddress{});
}

class IecExec : public ::testing::TestWithParam<EngineFactory> {
protected:
  std::unique_ptr<Machine> load(std::string_view text) {
    std::optional<VerifiedProgram> p = compileIlOrFail(text);
    if (!p) return nullptr;
    std::unique_ptr<Machine> m = Machine::create(*p, GetParam());
    if (m) {
      EXPECT_EQ(m->init(), uint32_t{LJ_FAULT_NONE});
    }
    return m;
  }
  static void set(Machine &m, std::string_view addr, int64_t v) {
    formats::writeAddress(m.state(), ilAddress(addr), v);
  }
  static int64_t get(const Machine &m, std::string_view addr) {
    return formats::readAddress(m.state(), ilAddress(addr));
  }
  /// Every combination of `names`: write them, one tick, check(bit of name).
  template <typename Check>
  void forAll(Machine &m, const std::vector<std::string> &names, Check check) {
    for (uint32_t combo = 0; combo < (1u << names.size()); ++combo) {
      std::string trace;
      for (size_t i = 0; i < names.size(); ++i) {
        set(m, names[i], (combo >> i) & 1u);
        trace += names[i] + "=" + std::to_string((combo >> i) & 1u) + " ";
      }
      EXPECT_EQ(m.tick(), uint32_t{LJ_FAULT_NONE});
      SCOPED_TRACE(trace);
      auto in = [&](std::string_view n) -> bool {
        for (size_t i = 0; i < names.size(); ++i)
          if (names[i] == n) return (combo >> i) & 1u;
        ADD_FAILURE() << n << " is not an input of the combination";
        return false;
      };
      check(in);
    }
  }
};

} // namespace lj::test

#define LJ_IEC_SUITE(Suite)                                                                        \
  INSTANTIATE_TEST_SUITE_P(Engines, Suite, ::testing::ValuesIn(::lj::test::registeredEngines()),   \
                           [](const ::testing::TestParamInfo<::lj::test::EngineFactory> &info) {   \
                             return info.param.name;                                               \
                           })

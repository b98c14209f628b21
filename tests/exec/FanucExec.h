// The FANUC execution tests' fixture: a .pmc text compiled and initialised on the engine under
// test, and FANUC addresses (X0.0, R100, D100:2) read and written through the dialect's profile.
#pragma once

#include "pipeline/Compile.h"
#include "tests/exec/ExecTest.h"

#include "formats/Address.h"
#include "frontends/fanuc/FrontEnd.h"
#include "profiles/fanuc/FanucProfile.h"

namespace lj::test {

class FanucExecTest : public ExecTest {
protected:
  std::unique_ptr<Machine> pmc(std::string_view text, const VerifyOptions &opts = {}) {
    Diagnostics d("t.pmc");
    std::optional<VerifiedProgram> p = pipeline::compilePmc(text, "t.pmc", opts, d, nullptr);
    if (!p) {
      ADD_FAILURE() << d.render() << text;
      return nullptr;
    }
    std::unique_ptr<Machine> m = Machine::create(*p, GetParam());
    if (m) {
      EXPECT_EQ(m->init(), uint32_t{LJ_FAULT_NONE});
    }
    return m;
  }
  static formats::CliAddress addr(std::string_view a) {
    std::string err;
    std::optional<formats::CliAddress> x = formats::parseProfileAddress(fanuc::profile(), a, err);
    EXPECT_TRUE(x) << err;
    return x ? *x : formats::CliAddress{};
  }
  static int64_t get(Machine &m, std::string_view a) {
    return formats::readAddress(m.state(), addr(a));
  }
  static void set(Machine &m, std::string_view a, int64_t v) {
    formats::writeAddress(m.state(), addr(a), v);
  }
};

} // namespace lj::test

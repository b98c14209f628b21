// hosts/HostChain: a layer over a bound lj_host forwards every callback to the base with the
// base's ctx, keeps the base's missing services missing, and adds its own save_data after the
// base's (how serve's retentive store hears SAVEDATA over the simulated NC).
#include "hosts/HostChain.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace lj::hosts {
namespace {

// A base host that records which callbacks reached it and with which ctx.
struct Recorder {
  std::vector<std::string> calls;
  lj_host table{};
  Recorder() {
    table.ctx = this;
    table.var_get = [](void *c, int32_t type, int32_t offset, int32_t exp, int32_t *v) {
      static_cast<Recorder *>(c)->calls.push_back("var_get " + std::to_string(type) + " " +
                                                  std::to_string(offset) + " " +
                                                  std::to_string(exp));
      *v = 77;
      return int32_t{1};
    };
    table.save_data = [](void *c) { static_cast<Recorder *>(c)->calls.push_back("save_data"); };
    table.nixie_encode = [](void *c, int32_t value, int32_t width) {
      static_cast<Recorder *>(c)->calls.push_back("nixie " + std::to_string(value) + " " +
                                                  std::to_string(width));
      return value + 1000;
    };
  }
};

TEST(HostChain, ForwardsToTheBaseWithItsCtx) {
  Recorder rec;
  lj_state s{};
  s.host = &rec.table;
  int saves = 0;
  HostChain chain([&] { ++saves; });
  chain.bindOver(s);
  ASSERT_NE(s.host, &rec.table);
  EXPECT_EQ(chain.base(), &rec.table);
  int32_t v = 0;
  EXPECT_EQ(s.host->var_get(s.host->ctx, 3, 12, 2, &v), 1);
  EXPECT_EQ(v, 77);
  EXPECT_EQ(s.host->nixie_encode(s.host->ctx, 5, 1), 1005);
  EXPECT_EQ(rec.calls, (std::vector<std::string>{"var_get 3 12 2", "nixie 5 1"}));
  EXPECT_EQ(saves, 0);
}

TEST(HostChain, MissingServicesStayMissing) {
  Recorder rec;
  lj_state s{};
  s.host = &rec.table;
  HostChain chain([] {});
  chain.bindOver(s);
  // The recorder serves neither VARSET nor TOOL: the engines must see "no NC service".
  EXPECT_EQ(s.host->var_set, nullptr);
  EXPECT_EQ(s.host->tool_select, nullptr);
  EXPECT_EQ(s.host->mpg_delta, nullptr);
}

TEST(HostChain, SaveDataRunsTheBaseThenTheLayer) {
  Recorder rec;
  lj_state s{};
  s.host = &rec.table;
  HostChain chain([&] { rec.calls.push_back("layer"); });
  chain.bindOver(s);
  s.host->save_data(s.host->ctx);
  EXPECT_EQ(rec.calls, (std::vector<std::string>{"save_data", "layer"}));
}

TEST(HostChain, WithoutABaseOnlyTheLayerServes) {
  lj_state s{};
  int saves = 0;
  HostChain chain([&] { ++saves; });
  chain.bindOver(s);
  ASSERT_NE(s.host, nullptr);
  EXPECT_EQ(chain.base(), nullptr);
  EXPECT_EQ(s.host->var_get, nullptr);
  s.host->save_data(s.host->ctx);
  EXPECT_EQ(saves, 1);
}

TEST(HostChain, RebindsOnlyWhenAnotherTableWasInstalled) {
  Recorder first, second;
  lj_state s{};
  s.host = &first.table;
  HostChain chain([] {});
  chain.bindOver(s);
  const lj_host *bound = s.host;
  chain.bindOver(s); // already bound: not wrapped twice
  EXPECT_EQ(s.host, bound);
  EXPECT_EQ(chain.base(), &first.table);
  s.host = &second.table; // e.g. the simulated NC installing its table at power-up
  chain.bindOver(s);
  EXPECT_EQ(chain.base(), &second.table);
  s.host->save_data(s.host->ctx);
  EXPECT_TRUE(first.calls.empty());
  EXPECT_EQ(second.calls, (std::vector<std::string>{"save_data"}));
}

} // namespace
} // namespace lj::hosts

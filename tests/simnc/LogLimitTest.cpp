// The simulated NC's bounded log (SimNcConfig::logLimit, docs/serve.md "The simulated NC in
// serve"): the last N host calls and events kept in order, the rest counted as dropped, and no
// allocation on the tick path once the ring is warm. Global operator new is replaced in this
// binary to count allocations, which is why these tests are a program of their own.
#include "SimNcRig.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <atomic>
#include <cstdlib>
#include <new>

// GCC flags free() in the replaced operator delete as mismatched once it inlines both halves;
// they are a matching malloc/free pair.
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
#endif

namespace {
std::atomic<uint64_t> gAllocs{0};
} // namespace

void *operator new(std::size_t n) {
  gAllocs.fetch_add(1, std::memory_order_relaxed);
  if (void *p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void operator delete(void *p) noexcept { std::free(p); }
void operator delete(void *p, std::size_t) noexcept { std::free(p); }

namespace lj::hosts::testing {
namespace {

SimNcConfig limited(size_t n) {
  SimNcConfig c;
  c.logLimit = n;
  return c;
}

TEST(LogLimit, DefaultKeepsEveryCall) {
  Rig r; // `run`'s NC: logLimit 0 = unlimited
  const lj_host *h = r.nc.host();
  r.before();
  for (int e = 0; e < 10; ++e) h->event(h->ctx, e);
  r.after();
  ASSERT_EQ(r.nc.calls().size(), 10u);
  EXPECT_EQ(r.nc.calls()[0], (NcCall{0, "event", {0}, {}, 0}));
  EXPECT_EQ(r.nc.callsDropped(), 0u);
  EXPECT_FALSE(r.nc.toJson().contains("log_dropped")); // `run --dump` unchanged
}

TEST(LogLimit, RingKeepsTheLastCallsOldestFirst) {
  Rig r(limited(3));
  const lj_host *h = r.nc.host();
  for (int t = 0; t < 4; ++t) { // ticks 0..3, events 10t and 10t+1 (7 calls after init's one)
    r.before();
    h->event(h->ctx, 10 * t);
    h->event(h->ctx, 10 * t + 1);
    r.after();
  }
  std::vector<NcCall> calls = r.nc.calls();
  ASSERT_EQ(calls.size(), 3u);
  EXPECT_EQ(calls[0], (NcCall{2, "event", {21}, {}, 0}));
  EXPECT_EQ(calls[1], (NcCall{3, "event", {30}, {}, 0}));
  EXPECT_EQ(calls[2], (NcCall{3, "event", {31}, {}, 0}));
  EXPECT_EQ(r.nc.callsDropped(), 5u);
  nlohmann::ordered_json j = r.nc.toJson();
  ASSERT_EQ(j["calls"].size(), 3u);
  EXPECT_EQ(j["calls"][0]["args"][0], 21); // the dump lists them oldest first too
  EXPECT_EQ(j["log_dropped"]["calls"], 5);
}

TEST(LogLimit, RingKeepsTheLastEvents) {
  // hnc8-cnc-interface.md 6.3 ALARM: alarm n is bit n-1 of G3010..; every change is an event.
  Rig r(limited(2));
  for (int n = 1; n <= 4; ++n) {
    r.before();
    r.setG(3010, n - 1, true);
    r.after();
  }
  std::vector<NcEvent> ev = r.nc.events();
  ASSERT_EQ(ev.size(), 2u);
  EXPECT_EQ(ev[0], (NcEvent{2, "alarm 3 on"}));
  EXPECT_EQ(ev[1], (NcEvent{3, "alarm 4 on"}));
  EXPECT_EQ(r.nc.eventsDropped(), 2u);
  r.nc.powerUp(*r.s); // a new power-up clears the log, the limit stays
  EXPECT_TRUE(r.nc.events().empty());
  EXPECT_EQ(r.nc.eventsDropped(), 0u);
}

// One tick as a serve scan would run it: host calls of several kinds and an alarm bit that
// changes every tick (one event per tick).
void busyTick(Rig &r) {
  const lj_host *h = r.nc.host();
  r.before();
  int32_t v = 0, pocket = 0, err = 0;
  h->var_set(h->ctx, 5, 3, 0, static_cast<int32_t>(r.tick));
  h->var_get(h->ctx, 5, 3, 0, &v);
  h->tool_select(h->ctx, 0, 7, &pocket, &err);
  h->temp_input(h->ctx, 1, 100, 1, 0, 1000, 0, 0);
  h->nixie_encode(h->ctx, 42, 1);
  h->event(h->ctx, 5);
  r.setG(3010, 0, r.tick % 2 == 0);
  r.after();
}

TEST(LogLimit, WarmRingRecordsWithoutAllocating) {
  Rig r(limited(16));
  r.before();
  int32_t v = 0;
  r.nc.host()->var_set(r.nc.host()->ctx, 5, 3, 0, 1); // the variable exists from here on
  r.nc.host()->var_get(r.nc.host()->ctx, 5, 3, 0, &v);
  r.after();
  for (int i = 0; i < 50; ++i) busyTick(r); // fills the ring: every slot has its capacity
  uint64_t before = gAllocs.load();
  for (int i = 0; i < 1000; ++i) busyTick(r);
  EXPECT_EQ(gAllocs.load() - before, 0u);
  EXPECT_EQ(r.nc.calls().size(), 16u);
  EXPECT_EQ(r.nc.events().size(), 16u);
  EXPECT_GT(r.nc.eventsDropped(), 1000u);
}

TEST(LogLimit, UnlimitedLogAllocatesAsItGrows) {
  // The counter can see allocations: the unlimited log of `run` grows on the same ticks.
  Rig r;
  for (int i = 0; i < 50; ++i) busyTick(r);
  uint64_t before = gAllocs.load();
  for (int i = 0; i < 1000; ++i) busyTick(r);
  EXPECT_GT(gAllocs.load() - before, 0u);
  EXPECT_EQ(r.nc.calls().size(), 6u * 1050); // six host calls per busy tick, all kept
}

} // namespace
} // namespace lj::hosts::testing

// The simulated NC's lj_host callbacks: the variable store with the VARGET/VARSET scaling rules
// (hnc8-functions-2.md 2.22, 2.23, 3 and resolution 14), tool select, temperatures, handwheels,
// the call log, JSON and equality (docs/simulated-nc.md "Host callbacks").
#include "SimNcRig.h"

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

namespace lj::hosts::testing {
namespace {

NcVar flt(double f) {
  NcVar v;
  v.isFloat = true;
  v.f = f;
  return v;
}

NcVar integer(int64_t i) {
  NcVar v;
  v.i = i;
  return v;
}

TEST(Vars, VarGetScalesFloatsAndTruncates) {
  Rig r;
  const lj_host *h = r.nc.host();
  int32_t out = 0;
  // 2.22 tests: #501 is type 1 offset 1.
  ASSERT_TRUE(r.nc.setVar(1, 1, flt(42.0)));
  EXPECT_EQ(h->var_get(h->ctx, 1, 1, 0, &out), 1);
  EXPECT_EQ(out, 42);
  r.nc.setVar(1, 1, flt(3.7));
  h->var_get(h->ctx, 1, 1, 0, &out);
  EXPECT_EQ(out, 3); // truncated
  r.nc.setVar(1, 1, flt(3.75));
  h->var_get(h->ctx, 1, 1, 2, &out);
  EXPECT_EQ(out, 375); // e = 2
  r.nc.setVar(1, 1, flt(-3.75));
  h->var_get(h->ctx, 1, 1, 1, &out);
  EXPECT_EQ(out, -37); // toward zero
  r.nc.setVar(0, 4999, flt(12.5));
  h->var_get(h->ctx, 0, 4999, 1, &out);
  EXPECT_EQ(out, 125); // 2.22 "12.5 with e=1 -> 125"
}

TEST(Vars, IntegerTypesIgnoreTheExponentAndKeepLowBits) {
  Rig r;
  const lj_host *h = r.nc.host();
  int32_t out = 0;
  r.nc.setVar(2, 9999, integer(-5));
  EXPECT_EQ(h->var_get(h->ctx, 2, 9999, 3, &out), 1);
  EXPECT_EQ(out, -5); // section 3: type 2 is int32, no scaling
  r.nc.setVar(3, 0, integer(0x100000007LL));
  h->var_get(h->ctx, 3, 0, 0, &out);
  EXPECT_EQ(out, 7); // 64-bit variable read into 32 bits keeps the low bits
}

TEST(Vars, MissingVariablesAreNotAvailable) {
  Rig r;
  const lj_host *h = r.nc.host();
  int32_t out = 99;
  EXPECT_EQ(h->var_get(h->ctx, 1, 500, 0, &out), 0);  // type 1 is offsets 0..499
  EXPECT_EQ(h->var_get(h->ctx, 10, 0, 0, &out), 0);   // types 0..9
  EXPECT_EQ(h->var_get(h->ctx, 5, 8000, 0, &out), 0); // 4 channels x 2000
  EXPECT_EQ(h->var_get(h->ctx, 7, -1, 0, &out), 0);
  EXPECT_EQ(out, 99); // nothing written
  EXPECT_EQ(h->var_set(h->ctx, 2, 10000, 0, 1), 0);
  EXPECT_EQ(r.nc.var(2, 10000), nullptr);
  // Never-written variables exist and read 0 (section 3: zero-initialised).
  EXPECT_EQ(h->var_get(h->ctx, 4, 17, 2, &out), 1);
  EXPECT_EQ(out, 0);
}

TEST(Vars, VarSetStoresIntegersAndDividesFloats) {
  Rig r;
  const lj_host *h = r.nc.host();
  EXPECT_EQ(h->var_set(h->ctx, 1, 1, 0, 42), 1); // 2.23 test: R100 = 42 -> #501 = 42.0
  ASSERT_NE(r.nc.var(1, 1), nullptr);
  EXPECT_TRUE(r.nc.var(1, 1)->isFloat);
  EXPECT_EQ(r.nc.var(1, 1)->f, 42.0);
  h->var_set(h->ctx, 6, 999, 2, 375); // resolution 14: value / 10^e
  EXPECT_EQ(r.nc.var(6, 999)->f, 3.75);
  int32_t out = 0;
  h->var_get(h->ctx, 6, 999, 2, &out); // and back with the same e
  EXPECT_EQ(out, 375);
  h->var_set(h->ctx, 8, 0, 4, -9); // integer type: stored as is
  EXPECT_FALSE(r.nc.var(8, 0)->isFloat);
  EXPECT_EQ(r.nc.var(8, 0)->i, -9);
}

TEST(Host, ToolSelectFromTheMagazine) {
  Rig r;
  formats::NcCommand c = simple(formats::NcCommandKind::Tool, 3, 12); // pocket 3 holds T12
  r.nc.apply(c);
  const lj_host *h = r.nc.host();
  int32_t pocket = -7, error = -7;
  EXPECT_EQ(h->tool_select(h->ctx, 0, 12, &pocket, &error), 1);
  EXPECT_EQ(pocket, 3);
  EXPECT_EQ(error, -7);
  EXPECT_EQ(h->tool_select(h->ctx, 0, 13, &pocket, &error), 0);
  EXPECT_EQ(error, 2); // not in the magazine
  EXPECT_EQ(pocket, 3);
  EXPECT_EQ(h->tool_select(h->ctx, 12, 12, &pocket, &error), 1);
  EXPECT_EQ(pocket, 0); // already in the spindle
}

TEST(Host, TemperaturesArePublishedInG3080) {
  Rig r;
  r.nc.apply(simple(formats::NcCommandKind::Temp, 2, 25));
  const lj_host *h = r.nc.host();
  h->temp_input(h->ctx, 4, 32767, 1, 10, 50, 0, 0); // type 1: p0 at 0, p1 at full scale
  r.before();
  EXPECT_EQ(r.G(3082), 25);
  EXPECT_EQ(r.G(3084), 50);
  EXPECT_EQ(r.G(3083), 0); // never set: not written
  r.after();
}

TEST(Host, HandwheelDeltas) {
  Rig r;
  r.nc.apply(simple(formats::NcCommandKind::Mpg, 1, 5));
  const lj_host *h = r.nc.host();
  h->mpg_input(h->ctx, 1, 100); // first raw value: the baseline
  h->mpg_input(h->ctx, 1, 103);
  EXPECT_EQ(h->mpg_delta(h->ctx, 1), 8); // 5 scripted + 3 turned
  EXPECT_EQ(h->mpg_delta(h->ctx, 1), 0); // consumed
  EXPECT_EQ(h->mpg_delta(h->ctx, 9), 0); // no such handwheel
}

TEST(Host, NotificationsAreStored) {
  Rig r;
  const lj_host *h = r.nc.host();
  h->tool_in_use(h->ctx, 1, 17);
  h->tool_vector(h->ctx, 1, 1);
  EXPECT_EQ(r.nc.toolInUse(1), 17);
  EXPECT_TRUE(r.nc.toolVector(1));
  h->tool_vector(h->ctx, 1, 0);
  EXPECT_FALSE(r.nc.toolVector(1));
  EXPECT_EQ(h->nixie_encode(h->ctx, 1234, 1), 0x1234); // BCD
  EXPECT_EQ(h->nixie_encode(h->ctx, 1234, 0), 0x34);
}

TEST(Host, SpindleDaFromThePBlock) {
  Rig r;
  // Gear 2 block at P10 + 5: motor max 3000, min 0, max 3000, ratio 2/1.
  int32_t *p = r.s->img.P;
  p[15] = 3000, p[16] = 0, p[17] = 3000, p[18] = 2, p[19] = 1;
  r.before();
  const lj_host *h = r.nc.host();
  EXPECT_EQ(h->spindle_da(h->ctx, 0, 0, 750, 2, 10), 5000); // 1500 of 3000 -> 5 V
  EXPECT_EQ(h->spindle_da(h->ctx, 0, 0, 750, 2, 198), 0);   // block past P199
  r.after();
}

TEST(Host, CallLogRecordsEveryCallWithItsTick) {
  Rig r;
  const lj_host *h = r.nc.host();
  h->event(h->ctx, 116); // during init: tick -1
  r.before();
  h->save_data(h->ctx);
  int32_t out;
  h->var_get(h->ctx, 1, 1, 0, &out);
  r.after();
  ASSERT_EQ(r.nc.calls().size(), 3u);
  EXPECT_EQ(r.nc.calls()[0], (NcCall{-1, "event", {116}, {}, 0}));
  EXPECT_EQ(r.nc.calls()[1], (NcCall{0, "save_data", {}, {}, 0}));
  EXPECT_EQ(r.nc.calls()[2], (NcCall{0, "var_get", {1, 1, 0}, {0}, 1}));
  nlohmann::ordered_json j = r.nc.toJson();
  EXPECT_EQ(j["calls"][0]["name"], "event");
  EXPECT_EQ(j["calls"].size(), 3u);
}

TEST(Host, TwoNcsFedIdenticallyAreEqual) {
  Rig a, b;
  for (Rig *r : {&a, &b}) {
    r->nc.apply(mcode(0, 3));
    r->before();
    r->G(2608) = 3;
    r->nc.host()->event(r->nc.host()->ctx, 5);
    r->after();
  }
  EXPECT_TRUE(a.nc == b.nc);
  EXPECT_EQ(a.nc.digest(), b.nc.digest());
  b.nc.host()->save_data(b.nc.host()->ctx);
  EXPECT_FALSE(a.nc == b.nc);
  EXPECT_NE(a.nc.digest(), b.nc.digest());
}

} // namespace
} // namespace lj::hosts::testing

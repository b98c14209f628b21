// RetainStore for the profile-laid targets (docs/retain.md "Format 2"): FANUC keeps K, D and the
// T / C data tables (fanuc-pmc.md 1.3 "Retentive memory": "Nonvolatile memory: T, C, K, D";
// "With an R register the accumulated count is 0 at power-on"), IEC keeps %M0..%M63
// (modicon-neza.md 1.1 footnote 3, L542). Everything else starts at zero after a restart.
#include "services/RetainStore.h"

#include "pipeline/Dialects.h"
#include "profiles/Profiles.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <memory>
#include <string>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace lj;
using lj::services::RestoreStatus;
using lj::services::RetainConfig;
using lj::services::RetainStore;

namespace {

class RetainProfileTest : public ::testing::Test {
protected:
  void SetUp() override {
    dir = fs::temp_directory_path() /
          ("lj-retainp-" + std::to_string(::getpid()) + "-" +
           ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir);
    fs::create_directories(dir);
    path = (dir / "plc.retain").string();
  }
  void TearDown() override { fs::remove_all(dir); }

  RetainConfig config(const char *profile) {
    RetainConfig c;
    c.path = path;
    c.profile = profileNamed(profile);
    c.log = [this](const std::string &l) { log += l + "\n"; };
    return c;
  }
  static std::unique_ptr<lj_state> fresh() {
    auto s = std::make_unique<lj_state>();
    lj_state_reset(s.get());
    return s;
  }
  static void set(lj_state &s, const char *profile, const char *item) {
    std::string err;
    auto a = pipeline::dialectNamed(profile)->parseAssignment(item, err);
    ASSERT_TRUE(a) << err;
    formats::writeAddress(s, a->addr, a->value);
  }
  static int64_t get(const lj_state &s, const char *profile, const char *addr) {
    std::string err;
    auto a = pipeline::dialectNamed(profile)->parseAddress(addr, err);
    EXPECT_TRUE(a) << err;
    return a ? formats::readAddress(s, *a) : -999;
  }
  /// Save `s` with `profile`'s store, then restore into a fresh state with a new store.
  std::unique_ptr<lj_state> roundTrip(const char *profile, const lj_state &s,
                                      RestoreStatus want = RestoreStatus::Restored) {
    {
      RetainStore st(config(profile));
      auto scratch = fresh();
      st.restore(*scratch, 0);
      st.start();
      st.stop(s, 7);
      EXPECT_EQ(st.stats().failures, 0u);
    }
    auto r = fresh();
    RetainStore st(config(profile));
    auto rep = st.restore(*r, 0);
    EXPECT_EQ(rep.status, want) << rep.message;
    return r;
  }

  fs::path dir;
  std::string path;
  std::string log;
};

TEST_F(RetainProfileTest, FanucKeepsKDTCAndClearsTheRest) {
  auto s = fresh();
  for (const char *item :
       {"K0=1", "K99=0x55", "K900=7", "K999=0xFF", "D0=-5", "D9998:2=-12345", "D100:4=123456789",
        "T0:2=5000", "T9499=3", "C0:2=10", "C2:2=4", "C5000:2=321", "C5199=9", "R10=1", "R9091=2",
        "E3=4", "A0=1", "Y0=8", "G4=1"})
    set(*s, "fanuc", item);
  auto r = roundTrip("fanuc", *s);
  EXPECT_EQ(get(*r, "fanuc", "K0"), 1);
  EXPECT_EQ(get(*r, "fanuc", "K99"), 0x55);
  EXPECT_EQ(get(*r, "fanuc", "K900"), 7);
  EXPECT_EQ(get(*r, "fanuc", "K999"), -1); // FANUC bytes read signed (docs/fanuc-pmc.md)
  EXPECT_EQ(get(*r, "fanuc", "D0"), -5);
  EXPECT_EQ(get(*r, "fanuc", "D9998:2"), -12345);
  EXPECT_EQ(get(*r, "fanuc", "D100:4"), 123456789);
  EXPECT_EQ(get(*r, "fanuc", "T0:2"), 5000);
  EXPECT_EQ(get(*r, "fanuc", "T9499"), 3);
  EXPECT_EQ(get(*r, "fanuc", "C0:2"), 10);
  EXPECT_EQ(get(*r, "fanuc", "C2:2"), 4);
  EXPECT_EQ(get(*r, "fanuc", "C5000:2"), 321);
  EXPECT_EQ(get(*r, "fanuc", "C5199"), 9);
  // Volatile: "an R register ... is 0 at power-on"; E, A, Y, G are not listed as nonvolatile.
  for (const char *a : {"R10", "R9091", "E3", "A0", "Y0", "G4"})
    EXPECT_EQ(get(*r, "fanuc", a), 0) << a;
  EXPECT_NE(log.find("restored " + path), std::string::npos) << log;
}

TEST_F(RetainProfileTest, IecKeepsTheFirst64InternalBits) {
  auto s = fresh();
  for (const char *item : {"%M0=1", "%M31=1", "%M63=1", "%M64=1", "%M127=1", "%MW10=77", "%Q0.1=1"})
    set(*s, "iec", item);
  auto r = roundTrip("iec", *s);
  EXPECT_EQ(get(*r, "iec", "%M0"), 1);
  EXPECT_EQ(get(*r, "iec", "%M31"), 1);
  EXPECT_EQ(get(*r, "iec", "%M63"), 1);
  EXPECT_EQ(get(*r, "iec", "%M1"), 0);
  for (const char *a : {"%M64", "%M127", "%MW10", "%Q0.1"}) EXPECT_EQ(get(*r, "iec", a), 0) << a;
}

TEST_F(RetainProfileTest, LayoutsOfTheTargets) {
  // FANUC: C, K, T, D are adjacent in lj_state.mem (profiles/fanuc/Areas.cpp): one span of
  // 600 + 200 + 1000 + 10000 bytes. IEC: the 8 bytes of %M0..%M63. HNC-8: format 1.
  auto f = services::retainLayoutOf(*profileNamed("fanuc"));
  EXPECT_FALSE(f.format1);
  EXPECT_EQ(f.payloadBytes(), 600u + 200u + 1000u + 10000u);
  EXPECT_EQ(f.timerSpan, -1);
  auto i = services::retainLayoutOf(*profileNamed("iec"));
  EXPECT_EQ(i.payloadBytes(), 8u);
  auto h = services::retainLayoutOf(*profileNamed("hnc8"));
  EXPECT_TRUE(h.format1);
  EXPECT_EQ(h.payloadBytes(), 4296u);
}

TEST_F(RetainProfileTest, AFileOfAnotherTargetIsRefused) {
  auto s = fresh();
  set(*s, "fanuc", "D5=9");
  roundTrip("fanuc", *s);
  for (const char *other : {"hnc8", "iec"}) {
    RetainStore st(config(other));
    auto r = fresh();
    auto rep = st.restore(*r, 0);
    EXPECT_EQ(rep.status, RestoreStatus::LayoutMismatch) << other << ": " << rep.message;
    EXPECT_NE(rep.message.find("another layout"), std::string::npos) << rep.message;
    EXPECT_NE(rep.message.find("profile fanuc"), std::string::npos) << rep.message;
  }
}

TEST_F(RetainProfileTest, DamagedFanucFileFallsBackToPrev) {
  auto s = fresh();
  set(*s, "fanuc", "D7=1");
  roundTrip("fanuc", *s);
  set(*s, "fanuc", "D7=2");
  roundTrip("fanuc", *s);
  // Flip a payload byte of the main file: the checksum catches it, FILE.prev (D7 = 1) is used.
  std::string text;
  {
    FILE *f = std::fopen(path.c_str(), "r+b");
    ASSERT_TRUE(f);
    std::fseek(f, 400, SEEK_SET);
    int c = std::fgetc(f);
    std::fseek(f, 400, SEEK_SET);
    std::fputc(c ^ 0x10, f);
    std::fclose(f);
  }
  auto r = fresh();
  RetainStore st(config("fanuc"));
  auto rep = st.restore(*r, 0);
  EXPECT_EQ(rep.status, RestoreStatus::RestoredPrev) << rep.message;
  EXPECT_EQ(get(*r, "fanuc", "D7"), 1);
}

TEST_F(RetainProfileTest, ChangeDetectionCapturesOnlyRetainedChanges) {
  RetainStore st(config("fanuc"));
  auto s = fresh();
  st.restore(*s, 0);
  st.afterTick(*s, 1);
  EXPECT_EQ(st.stats().captures, 1u);
  set(*s, "fanuc", "R5=1"); // not retained: no new capture
  st.afterTick(*s, 2);
  EXPECT_EQ(st.stats().captures, 1u);
  set(*s, "fanuc", "D9999=1"); // the last retained byte
  st.afterTick(*s, 3);
  EXPECT_EQ(st.stats().captures, 2u);
}

} // namespace

// RetainStore: what is retained (DIALECT.md 1: B, T300..T427, C300..C427), the file's crash
// safety and fallbacks, group commit and rate limiting (docs/retain.md).
#include "services/RetainStore.h"

#include "profiles/Profiles.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <openssl/evp.h>
#include <string>
#include <thread>
#include <unistd.h>
#include <vector>

namespace fs = std::filesystem;
using lj::services::RestoreStatus;
using lj::services::RetainConfig;
using lj::services::RetainImage;
using lj::services::RetainStore;

namespace {

const lj::services::RetainLayout &hnc8Layout() {
  static const lj::services::RetainLayout l =
      lj::services::retainLayoutOf(*lj::profileNamed("hnc8"));
  return l;
}

/// Bn in a format-1 payload (B0..B49 come first, docs/retain.md "File format").
int32_t bInFile(const RetainImage &img, int n) {
  int32_t v = 0;
  std::memcpy(&v, img.bytes.data() + 4 * n, 4);
  return v;
}

class RetainTest : public ::testing::Test {
protected:
  void SetUp() override {
    dir = fs::temp_directory_path() /
          ("lj-retain-" + std::to_string(::getpid()) + "-" +
           ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir);
    fs::create_directories(dir);
    path = (dir / "plc.retain").string();
  }
  void TearDown() override { fs::remove_all(dir); }

  RetainConfig config(std::chrono::milliseconds period = std::chrono::milliseconds(100)) {
    RetainConfig c;
    c.path = path;
    c.period = period;
    c.programHash = "sha256:" + std::string(64, 'a');
    c.log = [this](const std::string &l) {
      std::lock_guard lk(logMu);
      log += l + "\n";
    };
    return c;
  }
  static std::unique_ptr<lj_state> freshState() {
    auto s = std::make_unique<lj_state>();
    lj_state_reset(s.get());
    return s;
  }
  /// Save `s` (as of tick `tick`) with a store that is started and stopped cleanly.
  void saveOnce(const lj_state &s, uint64_t tick) {
    RetainStore st(config());
    auto scratch = freshState();
    st.restore(*scratch, 0); // continues the save numbering
    st.start();
    st.stop(s, tick);
    EXPECT_EQ(st.stats().failures, 0u);
  }
  std::vector<char> bytes(const std::string &p) {
    std::ifstream f(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(f), {}};
  }
  void writeBytes(const std::string &p, const std::vector<char> &b) {
    std::ofstream f(p, std::ios::binary | std::ios::trunc);
    f.write(b.data(), static_cast<std::streamsize>(b.size()));
  }

  fs::path dir;
  std::string path;
  std::mutex logMu;
  std::string log;
};

TEST_F(RetainTest, RoundTripKeepsRetainedAreasOnly) {
  auto s = freshState();
  s->img.B[0] = 7;
  s->img.B[49] = -123456789;
  s->img.D[0] = 55; // D is not retentive (DIALECT.md 1)
  s->now_ms = 5000;
  // T300 (slot 128) running for 1200 ms: started at 3800.
  s->T[128] = lj_timer{3800, 1200, 0, 1, {}};
  s->T[0] = lj_timer{100, 5, 1, 1, {}}; // T0 is not retentive
  s->C[255] = lj_counter{42, 1, 1, {}}; // C427
  s->C[3] = lj_counter{9, 0, 0, {}};    // C3 is not retentive
  saveOnce(*s, 5);
  ASSERT_TRUE(fs::exists(path));

  auto r = freshState();
  RetainStore st(config());
  auto rep = st.restore(*r, 0);
  EXPECT_EQ(rep.status, RestoreStatus::Restored) << rep.message;
  EXPECT_EQ(r->img.B[0], 7);
  EXPECT_EQ(r->img.B[49], -123456789);
  EXPECT_EQ(r->img.D[0], 0);
  // docs/retain.md "Timers": the timer keeps its age (1200 ms) relative to the new now_ms.
  EXPECT_EQ(0 - r->T[128].start_ms, 1200);
  EXPECT_EQ(r->T[128].elapsed_ms, 1200);
  EXPECT_EQ(r->T[128].running, 1);
  EXPECT_EQ(r->T[0].start_ms, 0);
  EXPECT_EQ(r->C[255].value, 42);
  EXPECT_EQ(r->C[255].out, 1);
  EXPECT_EQ(r->C[3].value, 0);
  EXPECT_NE(log.find("restored " + path + " (save #1"), std::string::npos) << log;
}

TEST_F(RetainTest, MissingFileStartsWithZeros) {
  auto r = freshState();
  RetainStore st(config());
  auto rep = st.restore(*r, 0);
  EXPECT_EQ(rep.status, RestoreStatus::NoFile);
  EXPECT_NE(rep.message.find("does not exist yet"), std::string::npos);
}

TEST_F(RetainTest, SecondSaveRotatesFirstIntoPrev) {
  auto s = freshState();
  s->img.B[1] = 1;
  saveOnce(*s, 1);
  s->img.B[1] = 2;
  saveOnce(*s, 2);
  RetainImage img;
  uint64_t seq = 0;
  std::string hash, err;
  ASSERT_EQ(RetainStore::readFile(hnc8Layout(), path, img, seq, hash, err),
            RetainStore::ReadResult::Ok)
      << err;
  EXPECT_EQ(bInFile(img, 1), 2);
  EXPECT_EQ(seq, 2u);
  ASSERT_EQ(RetainStore::readFile(hnc8Layout(), path + ".prev", img, seq, hash, err),
            RetainStore::ReadResult::Ok)
      << err;
  EXPECT_EQ(bInFile(img, 1), 1);
  EXPECT_EQ(seq, 1u);
  EXPECT_EQ(hash, "sha256:" + std::string(64, 'a'));
  EXPECT_FALSE(fs::exists(path + ".tmp"));
}

TEST_F(RetainTest, CorruptedFileFallsBackToPrev) {
  auto s = freshState();
  s->img.B[2] = 11;
  saveOnce(*s, 1);
  s->img.B[2] = 22;
  saveOnce(*s, 2);
  auto b = bytes(path);
  b[200] ^= 0x40; // a payload byte
  writeBytes(path, b);
  auto r = freshState();
  {
    RetainStore st(config());
    auto rep = st.restore(*r, 0);
    EXPECT_EQ(rep.status, RestoreStatus::RestoredPrev);
    EXPECT_EQ(r->img.B[2], 11);
    EXPECT_NE(rep.message.find("checksum mismatch"), std::string::npos) << rep.message;
    EXPECT_NE(rep.message.find("falling back to " + path + ".prev"), std::string::npos);
    // The next save must not rotate the damaged file over the good previous copy.
    st.start();
    r->img.B[2] = 33;
    st.stop(*r, 3);
  }
  RetainImage img;
  uint64_t seq = 0;
  std::string hash, err;
  ASSERT_EQ(RetainStore::readFile(hnc8Layout(), path + ".prev", img, seq, hash, err),
            RetainStore::ReadResult::Ok);
  EXPECT_EQ(bInFile(img, 2), 11);
  ASSERT_EQ(RetainStore::readFile(hnc8Layout(), path, img, seq, hash, err),
            RetainStore::ReadResult::Ok);
  EXPECT_EQ(bInFile(img, 2), 33);
}

TEST_F(RetainTest, TruncatedFileFallsBackToPrev) {
  auto s = freshState();
  s->img.B[3] = 5;
  saveOnce(*s, 1);
  saveOnce(*s, 2);
  for (size_t keep : {size_t{0}, size_t{10}, size_t{150}, size_t{4000}}) {
    auto b = bytes(path + ".prev");
    b.resize(keep);
    writeBytes(path, b);
    auto r = freshState();
    RetainStore st(config());
    auto rep = st.restore(*r, 0);
    EXPECT_EQ(rep.status, RestoreStatus::RestoredPrev) << keep;
    EXPECT_NE(rep.message.find("truncated"), std::string::npos) << rep.message;
    EXPECT_EQ(r->img.B[3], 5);
  }
}

TEST_F(RetainTest, BothBadStartsWithZerosAndSaysSo) {
  writeBytes(path, std::vector<char>(300, 'x'));
  writeBytes(path + ".prev", std::vector<char>(4500, 0));
  auto r = freshState();
  RetainStore st(config());
  auto rep = st.restore(*r, 0);
  EXPECT_EQ(rep.status, RestoreStatus::BothBad);
  EXPECT_NE(rep.message.find("no usable retain file"), std::string::npos) << rep.message;
  EXPECT_NE(rep.message.find("bad magic"), std::string::npos) << rep.message;
  EXPECT_NE(rep.message.find("starting with zeros"), std::string::npos);
  // Both damaged files are moved aside before any save (issue 28 finding 7), and the log says
  // where.
  EXPECT_FALSE(fs::exists(path));
  EXPECT_FALSE(fs::exists(path + ".prev"));
  EXPECT_NE(rep.message.find("damaged file kept as " + path + ".damaged-"), std::string::npos)
      << rep.message;
  EXPECT_NE(rep.message.find(", " + path + ".prev.damaged-"), std::string::npos) << rep.message;
  int kept = 0;
  for (const auto &e : fs::directory_iterator(fs::path(path).parent_path()))
    if (e.path().filename().string().find(".damaged-") != std::string::npos) {
      ++kept;
      EXPECT_EQ(fs::file_size(e.path()),
                e.path().string().find(".prev.damaged-") != std::string::npos ? 4500u : 300u);
    }
  EXPECT_EQ(kept, 2);
}

/// A valid file of another layout: the digest matches, the ABI version does not.
TEST_F(RetainTest, OtherLayoutIsRefusedUnlessForced) {
  auto s = freshState();
  s->img.B[4] = 9;
  saveOnce(*s, 1);
  auto b = bytes(path);
  b[16] = static_cast<char>(LJ_ABI_VERSION + 7); // abiVersion (docs/retain.md header table)
  // The SHA-256 trailer covers everything but the last 32 bytes (docs/retain.md).
  std::vector<unsigned char> body(b.begin(), b.end() - 32);
  unsigned char md[32];
  unsigned int mdLen = 0;
  EVP_Digest(body.data(), body.size(), md, &mdLen, EVP_sha256(), nullptr);
  std::copy(md, md + 32, b.end() - 32);
  writeBytes(path, b);
  {
    auto r = freshState();
    RetainStore st(config());
    auto rep = st.restore(*r, 0);
    EXPECT_EQ(rep.status, RestoreStatus::LayoutMismatch);
    EXPECT_NE(rep.message.find("another layout"), std::string::npos) << rep.message;
    EXPECT_EQ(r->img.B[4], 0);
    st.start();
    EXPECT_FALSE(st.commit(std::chrono::milliseconds(50)));
    st.stop(*r, 1);
    EXPECT_EQ(bytes(path), b); // never overwritten
  }
  auto forced = config();
  forced.force = true;
  RetainStore st(forced);
  auto r = freshState();
  auto rep = st.restore(*r, 0);
  EXPECT_EQ(rep.status, RestoreStatus::LayoutForced);
  EXPECT_EQ(r->img.B[4], 0);
  EXPECT_TRUE(fs::exists(path + ".rejected"));
  EXPECT_FALSE(fs::exists(path));
}

TEST_F(RetainTest, ProgramHashMismatchStillRestores) {
  auto s = freshState();
  s->img.B[5] = 77;
  saveOnce(*s, 1);
  auto c = config();
  c.programHash = "sha256:" + std::string(64, 'b');
  RetainStore st(c);
  auto r = freshState();
  auto rep = st.restore(*r, 0);
  EXPECT_EQ(rep.status, RestoreStatus::Restored);
  EXPECT_EQ(r->img.B[5], 77);
  EXPECT_NE(rep.message.find("note: saved by program"), std::string::npos) << rep.message;
}

/// The serve pattern: a scan thread applies client writes at tick boundaries and calls
/// afterTick; a client's commit() returns only once its write is in a durable file.
TEST_F(RetainTest, CommitMakesAppliedWritesDurable) {
  RetainStore st(config(std::chrono::hours(1))); // no periodic save gets in the way
  auto s = freshState();
  st.restore(*s, 0);
  st.start();
  std::atomic<int32_t> pending{-1};
  std::atomic<uint64_t> appliedTick{0};
  std::atomic<bool> stop{false};
  std::thread scan([&] {
    for (uint64_t tick = 1; !stop; ++tick) {
      int32_t v = pending.exchange(-1);
      if (v >= 0) s->img.B[0] = v;
      if (v >= 0) appliedTick = tick;
      s->now_ms = tick;
      ++s->img.B[1]; // the program changes a retained value every tick
      st.afterTick(*s, tick);
      std::this_thread::sleep_for(std::chrono::microseconds(300));
    }
  });
  for (int32_t k = 1; k <= 20; ++k) {
    uint64_t before = appliedTick;
    pending = k;
    while (appliedTick == before) std::this_thread::yield();
    ASSERT_TRUE(st.commit(std::chrono::seconds(5))) << k;
    RetainImage img;
    uint64_t seq = 0;
    std::string hash, err;
    ASSERT_EQ(RetainStore::readFile(hnc8Layout(), path, img, seq, hash, err),
              RetainStore::ReadResult::Ok);
    EXPECT_EQ(bInFile(img, 0), k);
  }
  stop = true;
  scan.join();
  st.stop(*s, 0);
  // One save for the first change (the rate limit starts open), then one per commit at most,
  // plus the final one: far fewer than the ticks.
  EXPECT_LE(st.stats().saves, 22u);
  EXPECT_GE(st.stats().saves, 20u);
}

TEST_F(RetainTest, RequestSaveWritesOutsideTheRateLimit) {
  RetainStore st(config(std::chrono::hours(1)));
  auto s = freshState();
  st.restore(*s, 0);
  st.start();
  s->img.B[6] = 1;
  st.afterTick(*s, 1); // first change: saved (the limit starts open)
  for (int i = 0; i < 200 && st.stats().saves < 1; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  ASSERT_EQ(st.stats().saves, 1u);
  for (int t = 2; t < 50; ++t) {
    s->img.B[6] = t;
    st.afterTick(*s, t);
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(20));
  EXPECT_EQ(st.stats().saves, 1u); // rate limited: a one-hour period
  st.requestSave();                // SAVEDATA, on the scan thread inside tick 50
  st.afterTick(*s, 50);
  for (int i = 0; i < 400 && st.stats().saves < 2; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  EXPECT_EQ(st.stats().saves, 2u);
  RetainImage img;
  uint64_t seq = 0;
  std::string hash, err;
  ASSERT_EQ(RetainStore::readFile(hnc8Layout(), path, img, seq, hash, err),
            RetainStore::ReadResult::Ok);
  EXPECT_EQ(bInFile(img, 6), 49);
  EXPECT_EQ(img.tick, 50u);
}

} // namespace

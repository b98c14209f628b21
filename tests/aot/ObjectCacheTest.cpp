// The JIT's object cache (docs/aot.md "Object cache"): hits are counted (not timed), return the
// same objects and the same behaviour, survive a new process (disk), and a damaged or foreign
// cache file is ignored and rewritten, never trusted.
#include "tests/aot/AotTestUtil.h"

#include "jit/Jit.h"
#include "jit/ObjectCache.h"
#include "tests/support/Machine.h"
#include "tests/support/StateDiff.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace lj::test::aot {
namespace {

const std::string kProgram = readBytes(LADDERJIT_SOURCE_DIR "/examples/part_counter.stl");

/// The complete state after init and 120 ticks of a finishing-parts pattern on `e`.
std::unique_ptr<lj_state> runPattern(const Engine &e) {
  auto s = std::make_unique<lj_state>();
  lj_state_reset(s.get());
  s->img.P[20] = 3;
  lj_run_init(s.get(), &e.entries());
  for (uint32_t t = 0; t < 120; ++t) {
    s->img.F[2560] = static_cast<int16_t>((t % 11) < 8 ? 0x20 : 0);
    s->img.F[2561] = static_cast<int16_t>((t % 11) == 8 ? 0x4 : 0);
    s->now_ms = t;
    lj_tick(s.get(), &e.entries());
  }
  return s;
}

class ObjectCacheTest : public ::testing::Test {
protected:
  void SetUp() override {
    std::optional<VerifiedProgram> p = compileOrFail(kProgram);
    ASSERT_TRUE(p);
    prog_ = *p;
    std::optional<VerifiedProgram> q = compileOrFail(kProgram, optionsWithNvalue(7));
    ASSERT_TRUE(q);
    other_ = *q;
  }
  std::unique_ptr<Engine> compile(const VerifiedProgram &p, std::shared_ptr<jit::ObjectCache> c,
                                  int32_t threads = 1) {
    jit::JitOptions o;
    o.cache = std::move(c);
    o.compileThreads = threads;
    o.minStatementsPerThread = 1; // threads > 1 then really partitions the program
    std::string error;
    std::unique_ptr<Engine> e = jit::compile(p, o, error);
    EXPECT_NE(e, nullptr) << error;
    return e;
  }
  /// The one cache file in the directory.
  std::string onlyFile() const {
    std::vector<std::string> files;
    for (const auto &f : std::filesystem::directory_iterator(dir_.dir()))
      files.push_back(f.path().string());
    EXPECT_EQ(files.size(), 1u);
    return files.empty() ? std::string() : files[0];
  }

  TempDir dir_;
  VerifiedProgram prog_, other_;
};

TEST_F(ObjectCacheTest, SecondCompileHitsAndBehavesTheSame) {
  auto cache = std::make_shared<jit::ObjectCache>(dir_.dir());
  std::unique_ptr<Engine> reference = compile(prog_, nullptr);
  std::unique_ptr<Engine> first = compile(prog_, cache);
  EXPECT_EQ(cache->stats().misses, 1u);
  EXPECT_EQ(cache->stats().stores, 1u);
  std::unique_ptr<Engine> second = compile(prog_, cache);
  EXPECT_EQ(cache->stats().hits, 1u);
  EXPECT_EQ(cache->stats().memoryHits, 1u);
  ASSERT_TRUE(reference && first && second);
  auto a = runPattern(*reference), b = runPattern(*second);
  EXPECT_FALSE(firstDifference(*a, *b)) << describeDifference(*a, *b, "uncached", "cached");
  EXPECT_GE(a->img.B[0], 3) << "the pattern finished parts"; // B0 = total good parts

  // Another process: a fresh cache on the same directory reads the disk file.
  auto fresh = std::make_shared<jit::ObjectCache>(dir_.dir());
  std::unique_ptr<Engine> third = compile(prog_, fresh);
  EXPECT_EQ(fresh->stats().diskHits, 1u);
  EXPECT_EQ(fresh->stats().misses, 0u);
  ASSERT_TRUE(third);
  auto c = runPattern(*third);
  EXPECT_FALSE(firstDifference(*a, *c)) << describeDifference(*a, *c, "uncached", "disk");
}

TEST_F(ObjectCacheTest, HitReturnsTheStoredObjects) {
  auto cache = std::make_shared<jit::ObjectCache>(dir_.dir());
  compile(prog_, cache, 2);
  std::string file = onlyFile();
  std::string key = std::filesystem::path(file).stem().string();
  std::vector<std::string> objs;
  auto fresh = std::make_shared<jit::ObjectCache>(dir_.dir());
  ASSERT_TRUE(fresh->lookup(key, objs));
  EXPECT_EQ(objs.size(), 2u) << "a partitioned compile caches every partition's object";
  for (const std::string &o : objs)
    EXPECT_EQ(o.substr(0, 4), "\x7f"
                              "ELF");
}

TEST_F(ObjectCacheTest, OtherProgramOrOptionsMiss) {
  auto cache = std::make_shared<jit::ObjectCache>(dir_.dir());
  compile(prog_, cache);
  compile(other_, cache); // same text, other plc2 nvalue: other slices, other code
  compile(prog_, cache, 2);
  jit::JitOptions fast;
  fast.tier = jit::Tier::Fast;
  fast.cache = cache;
  std::string error;
  EXPECT_NE(jit::compile(prog_, fast, error), nullptr) << error;
  EXPECT_EQ(cache->stats().hits, 0u);
  EXPECT_EQ(cache->stats().misses, 4u);
  EXPECT_NE(jit::programDigest(prog_), jit::programDigest(other_));
}

TEST_F(ObjectCacheTest, DamagedEntryIsIgnoredAndRewritten) {
  compile(prog_, std::make_shared<jit::ObjectCache>(dir_.dir()));
  std::string file = onlyFile();
  std::string good = readBytes(file);
  for (size_t pos : {size_t{0}, size_t{20}, good.size() / 2, good.size() - 1}) {
    std::string bad = good;
    bad[pos] = static_cast<char>(bad[pos] ^ 0x01);
    writeBytes(file, bad);
    auto cache = std::make_shared<jit::ObjectCache>(dir_.dir());
    std::unique_ptr<Engine> e = compile(prog_, cache);
    EXPECT_EQ(cache->stats().rejected, 1u) << "flip at " << pos;
    EXPECT_EQ(cache->stats().hits, 0u);
    EXPECT_EQ(readBytes(file), good) << "rewritten with the recompiled objects";
    ASSERT_TRUE(e);
    auto s = runPattern(*e);
    EXPECT_GE(s->img.B[0], 3);
  }
  writeBytes(file, good.substr(0, good.size() / 2)); // truncated
  auto cache = std::make_shared<jit::ObjectCache>(dir_.dir());
  compile(prog_, cache);
  EXPECT_EQ(cache->stats().rejected, 1u);
  // A valid entry of another key copied under this key's name is foreign: not trusted.
  compile(other_, cache);
  std::string otherFile;
  for (const auto &f : std::filesystem::directory_iterator(dir_.dir()))
    if (f.path().string() != file) otherFile = f.path().string();
  ASSERT_FALSE(otherFile.empty());
  std::filesystem::copy_file(otherFile, file, std::filesystem::copy_options::overwrite_existing);
  auto again = std::make_shared<jit::ObjectCache>(dir_.dir());
  compile(prog_, again);
  EXPECT_EQ(again->stats().rejected, 1u);
  EXPECT_EQ(again->stats().hits, 0u);
}

TEST_F(ObjectCacheTest, EntriesOthersCouldHavePlantedAreNotRun) {
  // Issue 11 (planted code): cached objects are code. An intact entry is refused when another
  // user could have written it: the entry writable by others, the directory writable by others,
  // or the entry a symlink. Refused entries are counted and nothing is written there.
  compile(prog_, std::make_shared<jit::ObjectCache>(dir_.dir()));
  const std::string file = onlyFile();
  namespace fs = std::filesystem;
  auto hitsWith = [&](const std::string &dir) {
    auto c = std::make_shared<jit::ObjectCache>(dir);
    EXPECT_TRUE(compile(prog_, c));
    return c->stats();
  };
  EXPECT_EQ(hitsWith(dir_.dir()).diskHits, 1u) << "the genuine private entry is used";
  fs::permissions(file, fs::perms::others_write, fs::perm_options::add);
  jit::ObjectCache::Stats st = hitsWith(dir_.dir());
  EXPECT_EQ(st.hits, 0u);
  EXPECT_EQ(st.rejected, 1u);
  fs::permissions(file, fs::perms::owner_read | fs::perms::owner_write, fs::perm_options::replace);
  fs::permissions(dir_.dir(), fs::perms::all, fs::perm_options::replace); // 0777
  st = hitsWith(dir_.dir());
  EXPECT_EQ(st.hits, 0u);
  EXPECT_EQ(st.rejected, 1u);
  EXPECT_EQ(st.writeErrors, 1u) << "no entry is written into a directory others can write";
  fs::permissions(dir_.dir(), fs::perms::owner_all, fs::perm_options::replace);
  TempDir other;
  fs::create_symlink(file, other.path(fs::path(file).filename().string()));
  st = hitsWith(other.dir());
  EXPECT_EQ(st.hits, 0u);
  EXPECT_EQ(st.rejected, 1u);
}

TEST(ObjectCacheEnv, OffDisablesAndDirOverrides) {
  ::setenv("LADDERJIT_CACHE", "off", 1);
  EXPECT_EQ(jit::ObjectCache::fromEnvironment(), nullptr);
  ::unsetenv("LADDERJIT_CACHE");
  ::setenv("LADDERJIT_CACHE_DIR", "/some/where", 1);
  auto c = jit::ObjectCache::fromEnvironment();
  ASSERT_NE(c, nullptr);
  EXPECT_EQ(c->dir(), "/some/where");
  ::unsetenv("LADDERJIT_CACHE_DIR");
  ::setenv("XDG_CACHE_HOME", "/xdg", 1);
  EXPECT_EQ(jit::ObjectCache::fromEnvironment()->dir(), "/xdg/ladderjit");
  ::unsetenv("XDG_CACHE_HOME");
}

} // namespace
} // namespace lj::test::aot

// Issue 11 finding 1: only a .so signed by a trusted key is loaded, and nothing of any other file
// is mapped (docs/aot.md "Trust"). In-process mutation campaign, untrusted signers, key files and
// file kinds; the CLI attacks (constructor marker) are tests/aot/aot_attacks.py.
#include "tests/aot/AotTestUtil.h"

#include "engines/AotLoader.h"
#include "ladderjit/program.h"
#include "signing/AotSigned.h"
#include "signing/AotTrust.h"
#include "tests/support/EngineRegistry.h"
#include "tests/support/Machine.h"

#include <gtest/gtest.h>

#include <cstring>
#include <random>
#include <sys/stat.h>
#include <unistd.h>

namespace lj::test::aot {
namespace {

class AotTrust : public ::testing::Test {
protected:
  void SetUp() override {
    std::optional<VerifiedProgram> p =
        compileOrFail(readBytes(LADDERJIT_SOURCE_DIR "/examples/part_counter.stl"));
    ASSERT_TRUE(p);
    prog_ = *p;
    so_ = dir_.path("prog.so");
    ASSERT_TRUE(buildSo(prog_, so_));
    bytes_ = readBytes(so_);
    ASSERT_EQ(signing::verifySigned(bytes_, testTrust(), meta_), "");
    image_ = bytes_.substr(0, meta_.imageSize);
    std::string error;
    ASSERT_TRUE(attacker_.generate(error)) << error;
  }
  std::unique_ptr<Engine> load(const std::string &bytes, std::string &error,
                               const signing::TrustedKeys &trust = testTrust()) {
    std::string path = dir_.path("x.so");
    writeBytes(path, bytes);
    return engines::loadAot(path, {testHash(prog_)}, trust, error);
  }
  /// `image` with a trailer stating the genuine facts, signed by `key`.
  std::string signWith(std::string image, const signing::SigningKey &key) {
    std::string error;
    EXPECT_TRUE(signing::signImage(image, meta_, key, error)) << error;
    return image;
  }
  /// The genuine META and footer text with `image`, naming the trusted key, and `sig`.
  std::string withStolenTrailer(const std::string &image, const std::string &sig) {
    std::string t = bytes_.substr(meta_.imageSize, bytes_.size() - meta_.imageSize - 64);
    return image + t + sig;
  }

  TempDir dir_;
  VerifiedProgram prog_;
  std::string so_, bytes_, image_;
  signing::AotMeta meta_;
  signing::SigningKey attacker_;
};

TEST_F(AotTrust, GenuineSignedSoLoadsAndTicksLikeTheInterpreter) {
  std::string error;
  std::unique_ptr<Engine> e = load(bytes_, error);
  ASSERT_NE(e, nullptr) << error;
  std::unique_ptr<Engine> ref = makeInterpreterEngine(prog_);
  auto a = std::make_unique<lj_state>(), b = std::make_unique<lj_state>();
  lj_state_reset(a.get());
  lj_state_reset(b.get());
  EXPECT_EQ(lj_run_init(a.get(), &e->entries()), lj_run_init(b.get(), &ref->entries()));
  for (uint32_t t = 0; t < 50; ++t) {
    a->img.F[2560] = b->img.F[2560] = (t % 7) < 4 ? 0x20 : 0;
    a->now_ms = b->now_ms = t;
    EXPECT_EQ(lj_tick(a.get(), &e->entries()), lj_tick(b.get(), &ref->entries()));
    ASSERT_EQ(std::memcmp(&a->img, &b->img, sizeof a->img), 0) << "tick " << t;
  }
}

TEST_F(AotTrust, ValidSoSignedByAnUntrustedKeyIsRefused) {
  std::string error;
  EXPECT_EQ(load(signWith(image_, attacker_), error), nullptr);
  EXPECT_NE(error.find("signed by " + signing::keyId(attacker_.publicRaw()) +
                       ", which is not a trusted key"),
            std::string::npos)
      << error;
  // Trusting the other key too makes it load: trust is the only thing that was missing.
  signing::TrustedKeys both = testTrust();
  both.addRaw(attacker_.publicRaw());
  EXPECT_NE(load(signWith(image_, attacker_), error, both), nullptr) << error;
  // Nothing trusted: nothing loads, not even the genuine file.
  EXPECT_EQ(load(bytes_, error, signing::TrustedKeys{}), nullptr);
}

TEST_F(AotTrust, HandMadeSoWithTheRightHashIsRefused) {
  // Exports every symbol and reports the program's hash, as in the issue; unsigned, or with the
  // genuine trailer (naming the trusted key) around it.
  writeBytes(dir_.path("h.c"), "const char *ljprog_hash(void) { return \"" + testHash(prog_) +
                                   "\"; }\nunsigned ljprog_abi_version(void) { return 5; }\n");
  int rc = 0;
  runCommand("cc -shared -fPIC -o " + dir_.path("h.so") + " " + dir_.path("h.c"), rc);
  ASSERT_EQ(rc, 0);
  std::string hand = readBytes(dir_.path("h.so")), error;
  EXPECT_EQ(load(hand, error), nullptr);
  EXPECT_NE(error.find("no ladderjit signature"), std::string::npos) << error;
  EXPECT_EQ(load(withStolenTrailer(hand, bytes_.substr(bytes_.size() - 64)), error), nullptr);
  EXPECT_NE(error.find("bad signature"), std::string::npos) << error;
}

TEST_F(AotTrust, MutationCampaignNothingRunsNothingCrashes) {
  // 2,000 copies with 1-4 random bytes changed (seeded), trailers redone every way an attacker
  // can: the genuine signed trailer kept, META rewritten with a forged signature, re-signed by
  // the attacker's own key, or mutations inside the trailer itself. None may load.
  std::mt19937_64 rnd(20261201);
  int refused = 0;
  const int kCopies = 2000;
  for (int i = 0; i < kCopies; ++i) {
    std::string img = image_;
    int flips = 1 + static_cast<int>(rnd() % 4);
    for (int f = 0; f < flips; ++f) {
      size_t pos = rnd() % img.size();
      char c = static_cast<char>(rnd() & 0xff);
      img[pos] = c == img[pos] ? static_cast<char>(c ^ 1) : c; // always a change
    }
    std::string file;
    switch (i % 4) {
    case 0:
      file = img + bytes_.substr(meta_.imageSize);
      break;
    case 1:
      file = withStolenTrailer(img, std::string(64, static_cast<char>(rnd())));
      break;
    case 2:
      file = signWith(img, attacker_);
      break;
    default: { // mutate the genuine file anywhere, trailer included
      file = bytes_;
      for (int f = 0; f < flips; ++f)
        file[rnd() % file.size()] ^= static_cast<char>(1 + rnd() % 255);
    }
    }
    std::string error;
    std::unique_ptr<Engine> e = load(file, error);
    EXPECT_EQ(e, nullptr) << "copy " << i << " was loaded";
    if (!e && !error.empty()) ++refused;
  }
  EXPECT_EQ(refused, kCopies);
}

TEST_F(AotTrust, FileKindsAndSizesAreRefusedWithAReason) {
  std::string error;
  std::string fifo = dir_.path("fifo.so");
  ASSERT_EQ(mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_EQ(engines::loadAot(fifo, {testHash(prog_)}, testTrust(), error), nullptr);
  EXPECT_NE(error.find("not a regular file"), std::string::npos) << error; // and no hang
  EXPECT_EQ(engines::loadAot(dir_.dir(), {testHash(prog_)}, testTrust(), error), nullptr);
  EXPECT_NE(error.find("not a regular file"), std::string::npos) << error;
  std::string big = dir_.path("big.so");
  writeBytes(big, "");
  ASSERT_EQ(truncate(big.c_str(), (off_t{256} << 20) + 1), 0); // sparse: nothing is written
  EXPECT_EQ(engines::loadAot(big, {testHash(prog_)}, testTrust(), error), nullptr);
  EXPECT_NE(error.find("too large"), std::string::npos) << error;
  EXPECT_EQ(load(bytes_.substr(0, bytes_.size() - 30), error), nullptr);
  EXPECT_NE(error.find("no ladderjit signature"), std::string::npos) << error;
}

TEST_F(AotTrust, KeyFilesAreCheckedAndNeverOverwritten) {
  std::string error;
  const std::string base = dir_.path("k");
  ASSERT_TRUE(signing::writeKeyPair(attacker_, base, error)) << error;
  struct stat st {};
  ASSERT_EQ(stat((base + ".key").c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0600u);
  EXPECT_FALSE(signing::writeKeyPair(attacker_, base, error));
  EXPECT_NE(error.find("already exists"), std::string::npos) << error;
  signing::SigningKey k;
  EXPECT_TRUE(k.loadFile(base + ".key", error)) << error;
  EXPECT_EQ(k.publicRaw(), attacker_.publicRaw());
  signing::TrustedKeys t;
  EXPECT_TRUE(t.addFile(base + ".pub", error)) << error;
  EXPECT_TRUE(t.trusts(attacker_.publicRaw()));
  // A private key others can read, a public key others can write: refused.
  ASSERT_EQ(chmod((base + ".key").c_str(), 0640), 0);
  EXPECT_FALSE(k.loadFile(base + ".key", error));
  EXPECT_NE(error.find("accessible by group or others"), std::string::npos) << error;
  ASSERT_EQ(chmod((base + ".pub").c_str(), 0666), 0);
  EXPECT_FALSE(t.addFile(base + ".pub", error));
  EXPECT_NE(error.find("writable by group or others"), std::string::npos) << error;
  // The default key directory must not be writable by others either.
  std::string keys = dir_.path("keys");
  ASSERT_EQ(mkdir(keys.c_str(), 0777), 0);
  ASSERT_EQ(chmod(keys.c_str(), 0777), 0);
  setenv("LADDERJIT_KEY_DIR", keys.c_str(), 1);
  std::string path;
  bool created = false;
  EXPECT_FALSE(signing::defaultSigningKey(k, path, created, error));
  EXPECT_NE(error.find("writable by group or others"), std::string::npos) << error;
  ASSERT_EQ(chmod(keys.c_str(), 0700), 0);
  EXPECT_TRUE(signing::defaultSigningKey(k, path, created, error)) << error;
  EXPECT_TRUE(created);
  signing::TrustedKeys d;
  EXPECT_TRUE(signing::loadTrustedKeys({}, d, error)) << error;
  EXPECT_TRUE(d.trusts(k.publicRaw()));
  unsetenv("LADDERJIT_KEY_DIR");
}

} // namespace
} // namespace lj::test::aot

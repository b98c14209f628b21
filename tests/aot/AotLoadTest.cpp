// The .so of `ladderjit compile`: its exported symbols, its ABI, and the loader's refusal of
// damaged, truncated, foreign and mismatched files (issue 5: "a clear error, never a crash").
// Signer trust and attacks on it: tests/security/AotTrustTest.cpp.
#include "tests/aot/AotTestUtil.h"

#include "engines/AotLoader.h"
#include "formats/PlcDit.h"
#include "ir/Engine.h"
#include "ladderjit/program.h"
#include "signing/AotSigned.h"
#include "tests/support/EngineRegistry.h"
#include "tests/support/Machine.h"
#include "tests/support/StateDiff.h"

#include <gtest/gtest.h>

#include <dlfcn.h>
#include <set>
#include <sstream>

namespace lj::test::aot {
namespace {

const std::string kProgram = readBytes(LADDERJIT_SOURCE_DIR "/examples/part_counter.stl");

/// part_counter with PLC2 nvalue 2: its 5-statement PLC2 runs in 2 slices (DIALECT.md 4).
VerifiedProgram program() {
  std::optional<VerifiedProgram> p = compileOrFail(kProgram, optionsWithNvalue(2));
  EXPECT_TRUE(p.has_value());
  return p ? *p : VerifiedProgram{};
}

/// `image` with a trailer signed by the trusted test key claiming to be `prog` (so only the
/// ELF or the exports can be wrong); `abi` = the ABI version it states.
std::string signedAs(std::string image, const VerifiedProgram &prog,
                     uint32_t abi = LJPROG_ABI_VERSION) {
  signing::AotMeta m;
  m.abi = abi;
  m.program = m.source = testHash(prog);
  m.plc2Nvalue = prog.plc2Nvalue;
  m.slices = static_cast<uint32_t>(prog.slices.size());
  m.stateSize = sizeof(lj_state);
  std::string error;
  EXPECT_TRUE(signing::signImage(image, m, testSigningKey(), error)) << error;
  return image;
}

/// The ELF image of a built .so (the bytes before its trailer).
std::string imageOf(const std::string &so) {
  signing::AotMeta m;
  EXPECT_EQ(signing::verifySigned(so, testTrust(), m), "");
  return so.substr(0, m.imageSize);
}

class AotLoad : public ::testing::Test {
protected:
  void SetUp() override {
    prog_ = program();
    so_ = dir_.path("prog.so");
    ASSERT_TRUE(buildSo(prog_, so_));
    bytes_ = readBytes(so_);
    ASSERT_GT(bytes_.size(), size_t{LJPROG_TRAILER_MIN});
    image_ = imageOf(bytes_);
  }
  /// Load `bytes` as a .so; expect a refusal whose message contains `want`.
  void expectRefused(const std::string &bytes, const std::string &want, const std::string &what) {
    std::string path = dir_.path("bad.so");
    writeBytes(path, bytes);
    std::string error;
    std::unique_ptr<Engine> e = engines::loadAot(path, {testHash(prog_)}, testTrust(), error);
    EXPECT_EQ(e, nullptr) << what;
    EXPECT_NE(error.find(want), std::string::npos) << what << ": " << error;
    EXPECT_NE(error.find(path), std::string::npos) << "the message names the file: " << error;
  }
  /// A shared object built by the system compiler from C `source`, signed by the trusted key.
  std::string foreignSo(const std::string &source, uint32_t abi = LJPROG_ABI_VERSION) {
    writeBytes(dir_.path("f.c"), source);
    int rc = 0;
    runCommand("cc -shared -fPIC -o " + dir_.path("f.so") + " " + dir_.path("f.c"), rc);
    EXPECT_EQ(rc, 0);
    return signedAs(readBytes(dir_.path("f.so")), prog_, abi);
  }

  TempDir dir_;
  VerifiedProgram prog_;
  std::string so_, bytes_, image_;
};

TEST_F(AotLoad, ExportsExactlyTheDocumentedSymbols) {
  // docs/aot.md "Symbols": the eight functions at version LJPROG_1, plus the version node.
  int rc = 0;
  std::string out = runCommand("nm -D --defined-only " + so_, rc);
  ASSERT_EQ(rc, 0);
  std::set<std::string> names;
  std::istringstream in(out);
  for (std::string line; std::getline(in, line);) names.insert(line.substr(line.rfind(' ') + 1));
  std::set<std::string> want = {"LJPROG_1"};
  for (const char *f : {"abi_version", "hash", "slice_count", "state_size", "state_reset", "init",
                        "tick", "entries"})
    want.insert(std::string("ljprog_") + f + "@@LJPROG_1");
  EXPECT_EQ(names, want) << out;
}

TEST_F(AotLoad, AbiFunctionsDescribeTheProgram) {
  void *h = dlopen(so_.c_str(), RTLD_NOW | RTLD_LOCAL);
  ASSERT_NE(h, nullptr) << dlerror();
  auto version = reinterpret_cast<ljprog_u32_fn>(dlsym(h, "ljprog_abi_version"));
  auto hash = reinterpret_cast<ljprog_hash_fn>(dlsym(h, "ljprog_hash"));
  auto slices = reinterpret_cast<ljprog_u32_fn>(dlsym(h, "ljprog_slice_count"));
  auto size = reinterpret_cast<ljprog_size_fn>(dlsym(h, "ljprog_state_size"));
  ASSERT_TRUE(version && hash && slices && size);
  EXPECT_EQ(version(), LJPROG_ABI_VERSION);
  EXPECT_EQ(std::string(hash()), testHash(prog_));
  EXPECT_GT(prog_.slices.size(), 1u);
  EXPECT_EQ(slices(), prog_.slices.size());
  EXPECT_EQ(size(), sizeof(lj_state));
  dlclose(h);
}

TEST_F(AotLoad, HostFunctionsTickLikeTheInterpreter) {
  // ljprog_state_reset / ljprog_init / ljprog_tick against the interpreter through lj_tick:
  // the same complete state after every tick, with inputs toggled by a host pattern.
  void *h = dlopen(so_.c_str(), RTLD_NOW | RTLD_LOCAL);
  ASSERT_NE(h, nullptr) << dlerror();
  auto reset = reinterpret_cast<ljprog_reset_fn>(dlsym(h, "ljprog_state_reset"));
  auto init = reinterpret_cast<ljprog_run_fn>(dlsym(h, "ljprog_init"));
  auto tick = reinterpret_cast<ljprog_run_fn>(dlsym(h, "ljprog_tick"));
  ASSERT_TRUE(reset && init && tick);
  std::unique_ptr<Engine> ref = makeInterpreterEngine(prog_);
  auto a = std::make_unique<lj_state>(), b = std::make_unique<lj_state>();
  reset(a.get());
  lj_state_reset(b.get());
  a->img.P[20] = b->img.P[20] = 3;
  EXPECT_EQ(init(a.get()), lj_run_init(b.get(), &ref->entries()));
  for (uint32_t t = 0; t < 200; ++t) {
    int16_t f2560 = (t % 13) < 9 ? 0x20 : 0, f2561 = (t % 13) == 9 ? 0x4 : 0; // run, finish
    a->img.F[2560] = b->img.F[2560] = f2560;
    a->img.F[2561] = b->img.F[2561] = f2561;
    a->img.X[12] = b->img.X[12] = static_cast<uint8_t>((t % 37) == 5 ? 0x04 : 0); // scrap key
    a->now_ms = b->now_ms = t;
    EXPECT_EQ(tick(a.get()), lj_tick(b.get(), &ref->entries()));
    ASSERT_FALSE(firstDifference(*a, *b))
        << "tick " << t << ": " << describeDifference(*a, *b, "aot", "interp");
  }
  EXPECT_GE(a->img.B[0], 3) << "the scenario finished parts"; // B0 = total good parts
  dlclose(h);
}

TEST_F(AotLoad, LoadsWithItsOwnHashOnly) {
  std::string error;
  EXPECT_NE(engines::loadAot(so_, {testHash(prog_)}, testTrust(), error), nullptr) << error;
  std::string other = "sha256:" + std::string(64, '0');
  EXPECT_EQ(engines::loadAot(so_, {other}, testTrust(), error), nullptr);
  EXPECT_NE(error.find("built from another program"), std::string::npos) << error;
}

TEST_F(AotLoad, AnotherNvalueOfTheSameProgramIsNamed) {
  // Issue 11 finding 9: the same source with another plc2 nvalue is not "another program"; the
  // message states the .so's nvalue (2, program()) and the one asked for.
  std::string error;
  engines::AotExpect want{"sha256:" + std::string(64, '1'), testHash(prog_), 200};
  EXPECT_EQ(engines::loadAot(so_, want, testTrust(), error), nullptr);
  EXPECT_NE(error.find("built from this program with plc2 nvalue 2, but plc2 nvalue 200 was "
                       "asked for"),
            std::string::npos)
      << error;
  EXPECT_EQ(error.find("another program"), std::string::npos) << error;
}

TEST_F(AotLoad, RebuiltAtTheSamePathWhileTheOldOneIsLoaded) {
  // Hot reload: v2 written over v1's path while v1 still runs. Each load gets its own program
  // (2 PLC2 slices at nvalue 2, 1 at the default 200), not the object already loaded.
  std::string error;
  std::unique_ptr<Engine> first = engines::loadAot(so_, {testHash(prog_)}, testTrust(), error);
  ASSERT_NE(first, nullptr) << error;
  std::optional<VerifiedProgram> v2 = compileOrFail(kProgram);
  ASSERT_TRUE(v2);
  ASSERT_TRUE(buildSo(*v2, so_));
  std::unique_ptr<Engine> second = engines::loadAot(so_, {testHash(*v2)}, testTrust(), error);
  ASSERT_NE(second, nullptr) << error;
  EXPECT_EQ(first->entries().plc2_slice_count, 2u);
  EXPECT_EQ(second->entries().plc2_slice_count, 1u);
}

TEST_F(AotLoad, TruncatedFilesAreRefused) {
  for (size_t n : {size_t{0}, size_t{10}, size_t{64}, size_t{200}, size_t{4096}, bytes_.size() / 2,
                   image_.size() - 1, image_.size(), image_.size() + 1,
                   bytes_.size() - LJPROG_TRAILER_MIN, bytes_.size() - 1})
    expectRefused(bytes_.substr(0, n), "'", "truncated to " + std::to_string(n));
}

TEST_F(AotLoad, FlippedBytesAreRefused) {
  // Every flip, in the ELF headers, code, tables or the trailer, is caught before dlopen; one in
  // the image breaks the signature.
  const size_t step = bytes_.size() / 97 + 1;
  for (size_t pos = 0; pos < bytes_.size(); pos += step) {
    std::string bad = bytes_;
    bad[pos] = static_cast<char>(bad[pos] ^ 0x5a);
    bool inImage = pos < image_.size();
    expectRefused(bad, inImage ? "bad signature" : "'", "byte " + std::to_string(pos) + " flipped");
  }
}

TEST_F(AotLoad, DamagedElfWithValidTrailerIsRefusedBeforeDlopen) {
  // Signed by the trusted key (a signer's bug, not an attack): still no bad ELF reaches dlopen.
  const std::string &image = image_;
  auto withTrailer = [&](const std::string &img) { return signedAs(img, prog_); };
  expectRefused(withTrailer(image.substr(0, image.size() / 2)), "truncated?", "half an image");
  std::string arm = image;
  arm[18] = static_cast<char>(0xb7); // e_machine = EM_AARCH64 (183)
  arm[19] = 0;
  expectRefused(withTrailer(arm), "another machine", "e_machine changed");
  expectRefused(withTrailer("LD X0.0\nOUT Y0.0\n"), "not an ELF file", "text file");
  std::string exec = image;
  exec[16] = 2; // e_type = ET_EXEC
  expectRefused(withTrailer(exec), "not an ELF shared object", "e_type changed");
}

TEST_F(AotLoad, ForeignSharedObjectsAreRefused) {
  expectRefused(foreignSo("unsigned ljprog_abi_version(void) { return 1; }\n"),
                "symbol 'ljprog_entries' missing", "only one symbol");
  std::string all = "#include <stddef.h>\n"
                    "unsigned ljprog_abi_version(void) { return 99; }\n"
                    "const char *ljprog_hash(void) { return \"x\"; }\n"
                    "unsigned ljprog_slice_count(void) { return 1; }\n"
                    "size_t ljprog_state_size(void) { return 1; }\n"
                    "void ljprog_state_reset(void *s) { (void)s; }\n"
                    "unsigned ljprog_init(void *s) { (void)s; return 0; }\n"
                    "unsigned ljprog_tick(void *s) { (void)s; return 0; }\n"
                    "void ljprog_entries(void *e) { (void)e; }\n";
  // The ABI version comes from the signed trailer; the .so's function (99) is never called.
  expectRefused(foreignSo(all, 2),
                "program ABI version 2, this ladderjit loads " + std::to_string(LJPROG_ABI_VERSION),
                "trailer states ABI version 2");
  expectRefused(image_, "no ladderjit signature", "trailer stripped");
}

} // namespace
} // namespace lj::test::aot

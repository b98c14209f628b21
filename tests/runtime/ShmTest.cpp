// The shared-memory image (docs/serve.md "Shared-memory image"): a host thread with its own
// mapping writes X through the input seqlock, the executive scans and publishes, the host reads
// Y back through the output seqlock.
#include "pipeline/Dialects.h"
#include "runtime/Executive.h"
#include "runtime/ProgramLoader.h"
#include "runtime/ShmImage.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <chrono>
#include <cstddef>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <thread>
#include <vector>

namespace lj::rt {
namespace {

TEST(ShmImage, RoundTripThroughASecondMapping) {
  std::string path =
      (std::filesystem::temp_directory_path() / ("ljshm-" + std::to_string(::getpid()) + ".stl"))
          .string();
  std::ofstream(path) << "LD X1.0\nOUT Y1.0\nLDT\nMOV X2 D7\n1END\n2END\n";
  ProgramLoader loader("interp", -1);
  std::string err;
  auto v = loader.load(path, {}, err);
  std::remove(path.c_str());
  ASSERT_TRUE(v) << err;

  const std::string name = "ljtest-" + std::to_string(::getpid());
  ShmMapping server;
  ASSERT_TRUE(server.create(name, /*hostOwnsF=*/true, 1000000, err)) << err;
  Exchange ex;
  Executive exec(ex, ExecutiveOptions{});
  ShmImage shm(server, true);
  exec.addIo(&shm);
  exec.addAfterTickHook([&shm](const lj_state &s, uint64_t t) { shm.publish(s, t); });
  ASSERT_TRUE(exec.start(v, err)) << err;

  bool sawY = false, sawD = false;
  std::thread host([&] {
    ShmMapping client;
    std::string e;
    ASSERT_TRUE(client.open(name, e)) << e;
    EXPECT_EQ(client.header()->abiVersion, LJ_ABI_VERSION);
    EXPECT_EQ(client.header()->flags, kShmHostOwnsF);
    uint8_t x[LJ_X_COUNT] = {};
    int16_t f[LJ_F_COUNT] = {};
    x[1] = 1;  // X1.0
    x[2] = 77; // X2 as a byte (DIALECT.md 1: X read zero-extended)
    f[5] = -3;
    shmWriteInputs(client, x, f);
    auto img = std::make_unique<lj_image>();
    auto until = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    while (std::chrono::steady_clock::now() < until && !(sawY && sawD)) {
      shmReadOutputs(client, *img);
      sawY = (img->Y[1] & 1) != 0;
      sawD = img->D[7] == 77;
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
  });
  host.join();
  exec.requestStop();
  exec.join();
  server.unlinkName();
  EXPECT_TRUE(sawY) << "Y1.0 never followed X1.0 from the host";
  EXPECT_TRUE(sawD) << "D7 never showed X2 from the host";
  EXPECT_EQ(exec.finalState().img.F[5], -3); // --io shm: F comes from the host
}

/// FANUC and IEC programs: the host writes the profile's input area in the region after the
/// image (lj_state.mem), serve publishes the rest of it (docs/serve.md "Shared-memory image").
void profileRoundTrip(const char *ext, const char *text, const char *dialect, const char *in,
                      int64_t inValue, const char *out) {
  std::string path = (std::filesystem::temp_directory_path() /
                      ("ljshm-" + std::to_string(::getpid()) + "-" + dialect + ext))
                         .string();
  std::ofstream(path) << text;
  ProgramLoader loader("interp", -1);
  std::string err;
  auto v = loader.load(path, {}, err);
  std::remove(path.c_str());
  ASSERT_TRUE(v) << err;
  const pipeline::Dialect *d = pipeline::dialectNamed(dialect);
  auto inAddr = d->parseAddress(in, err);
  auto outAddr = d->parseAddress(out, err);
  ASSERT_TRUE(inAddr && outAddr) << err;
  const TargetProfile &tp = *v->prog->profile;
  const uint32_t mem = static_cast<uint32_t>(offsetof(lj_state, mem));
  const uint32_t inOff = tp.elementOffset(inAddr->area, inAddr->index) - mem;
  const uint32_t outOff = tp.elementOffset(outAddr->area, outAddr->index) - mem;

  const std::string name = std::string("ljtest-") + dialect + std::to_string(::getpid());
  ShmMapping server;
  ASSERT_TRUE(server.create(name, false, 1000000, err)) << err;
  Exchange ex;
  Executive exec(ex, ExecutiveOptions{});
  ShmImage shm(server, false, &tp);
  exec.addIo(&shm);
  exec.addAfterTickHook([&shm](const lj_state &s, uint64_t t) { shm.publish(s, t); });
  ASSERT_TRUE(exec.start(v, err)) << err;
  bool saw = false;
  std::thread host([&] {
    ShmMapping client;
    std::string e;
    ASSERT_TRUE(client.open(name, e)) << e;
    EXPECT_EQ(client.header()->memSize, uint32_t{LJ_MEM_BYTES});
    uint8_t byte = static_cast<uint8_t>(inValue);
    shmWriteMem(client, inOff, &byte, 1);
    std::vector<uint8_t> region(LJ_MEM_BYTES);
    auto until = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    while (std::chrono::steady_clock::now() < until && !saw) {
      shmReadMem(client, region.data());
      saw = ((region[outOff] >> outAddr->bit) & 1) != 0;
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    // The host's input byte is never overwritten by the server's publication.
    EXPECT_EQ(region[inOff], byte);
  });
  host.join();
  exec.requestStop();
  exec.join();
  server.unlinkName();
  EXPECT_TRUE(saw) << out << " never followed " << in << " from the host";
}

TEST(ShmImage, FanucAreasInTheRegion) {
  // X200.3 is in the second X range (profiles/fanuc: X0..X127, X200..X327).
  profileRoundTrip(".pmc", "RD X200.3\nWRT Y0.1\nRD X0.0\nWRT K0.2\nEND1\nEND2\nEND\n", "fanuc",
                   "X200.3", 8, "Y0.1");
}

TEST(ShmImage, IecObjectsInTheRegion) {
  profileRoundTrip(".il", "000 LD %I0.2\n001 ST %Q0.1\n", "iec", "%I0.2", 4, "%Q0.1");
}

TEST(ShmImage, OpenRefusesSomethingElse) {
  ShmMapping m;
  std::string err;
  EXPECT_FALSE(m.open("ljtest-missing-" + std::to_string(::getpid()), err));
  EXPECT_FALSE(err.empty());
}

} // namespace
} // namespace lj::rt

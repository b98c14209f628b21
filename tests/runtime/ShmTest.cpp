// The shared-memory image (docs/serve.md "Shared-memory image"): a host thread with its own
// mapping writes X through the input seqlock, the executive scans and publishes, the host reads
// Y back through the output seqlock.
#include "runtime/Executive.h"
#include "runtime/ProgramLoader.h"
#include "runtime/ShmImage.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <thread>

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

TEST(ShmImage, OpenRefusesSomethingElse) {
  ShmMapping m;
  std::string err;
  EXPECT_FALSE(m.open("ljtest-missing-" + std::to_string(::getpid()), err));
  EXPECT_FALSE(err.empty());
}

} // namespace
} // namespace lj::rt

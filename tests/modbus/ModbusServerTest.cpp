// ModbusServer: the documented map (docs/modbus-map.md), Modbus exceptions (Modbus Application
// Protocol V1.1b3, 7) and many clients, against an in-memory backend through libmodbus clients.
#include "services/ModbusServer.h"

#include <gtest/gtest.h>

#include <cstring>

#include <arpa/inet.h>
#include <atomic>
#include <modbus/modbus.h>
#include <mutex>
#include <netinet/in.h>
#include <sys/socket.h>
#include <thread>
#include <unistd.h>

using namespace lj::services;
namespace formats = lj::formats;

namespace {

TEST(ModbusMap, BitsOfYRAndX) {
  lj_state s{};
  s.img.Y[1] = 0x04; // Y1.2 -> coil 8*1 + 2 = 10
  s.img.R[2] = 0x80; // R2.7 -> coil 5000 + 23
  s.img.X[512] = 0x01;
  std::vector<uint8_t> out;
  ASSERT_EQ(mbmap::readBits(MbTable::Coils, 9, 3, s, out), 0);
  EXPECT_EQ(out, (std::vector<uint8_t>{0, 1, 0}));
  ASSERT_EQ(mbmap::readBits(MbTable::Coils, 5023, 1, s, out), 0);
  EXPECT_EQ(out[0], 1);
  ASSERT_EQ(mbmap::readBits(MbTable::DiscreteInputs, 4096, 1, s, out), 0);
  EXPECT_EQ(out[0], 1);
  // 4104 is one past X512.7; a read crossing into the gap is refused as a whole.
  EXPECT_EQ(mbmap::readBits(MbTable::DiscreteInputs, 4100, 5, s, out), kMbIllegalDataAddress);
}

TEST(ModbusMap, RegistersWidthsAndWordOrder) {
  lj_state s{};
  s.img.W[3] = -2;         // int16 -> 0xFFFE
  s.img.B[3] = 0x12345678; // two registers, low word first
  s.img.D[99] = -1;
  s.img.G[3119] = 0x1234;
  s.img.F[7] = -32768;
  s.img.P[0] = 70000;
  s.img.X[4] = 200;
  std::vector<uint16_t> r;
  ASSERT_EQ(mbmap::readRegisters(MbTable::HoldingRegisters, 3, 1, s, r), 0);
  EXPECT_EQ(r[0], 0xFFFE);
  ASSERT_EQ(mbmap::readRegisters(MbTable::HoldingRegisters, 2006, 2, s, r), 0);
  EXPECT_EQ(r, (std::vector<uint16_t>{0x5678, 0x1234}));
  ASSERT_EQ(mbmap::readRegisters(MbTable::HoldingRegisters, 1198, 2, s, r), 0);
  EXPECT_EQ(r, (std::vector<uint16_t>{0xFFFF, 0xFFFF}));
  ASSERT_EQ(mbmap::readRegisters(MbTable::HoldingRegisters, 6119, 1, s, r), 0);
  EXPECT_EQ(r[0], 0x1234);
  ASSERT_EQ(mbmap::readRegisters(MbTable::InputRegisters, 7, 1, s, r), 0);
  EXPECT_EQ(r[0], 0x8000);
  ASSERT_EQ(mbmap::readRegisters(MbTable::InputRegisters, 5000, 2, s, r), 0);
  EXPECT_EQ(r, (std::vector<uint16_t>{70000 & 0xFFFF, 1}));
  ASSERT_EQ(mbmap::readRegisters(MbTable::InputRegisters, 4004, 1, s, r), 0);
  EXPECT_EQ(r[0], 200);
  s.T[128].elapsed_ms = 1500; // T300: slot 128 -> 6000 + 2 * 128
  s.C[0].value = -3;          // C0 -> 7000
  ASSERT_EQ(mbmap::readRegisters(MbTable::InputRegisters, 6256, 2, s, r), 0);
  EXPECT_EQ(r, (std::vector<uint16_t>{1500, 0}));
  ASSERT_EQ(mbmap::readRegisters(MbTable::InputRegisters, 7000, 2, s, r), 0);
  EXPECT_EQ(r, (std::vector<uint16_t>{0xFFFD, 0xFFFF}));
  EXPECT_EQ(mbmap::readRegisters(MbTable::HoldingRegisters, 200, 1, s, r), kMbIllegalDataAddress);
  EXPECT_EQ(mbmap::readRegisters(MbTable::InputRegisters, 65535, 1, s, r), kMbIllegalDataAddress);
}

TEST(ModbusMap, WritesOnlyWherePermitted) {
  std::vector<formats::Assignment> w;
  bool retained = false;
  ASSERT_EQ(mbmap::planRegisterWrite(2006, {0x5678, 0x1234}, false, w, retained), 0);
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(w[0].addr.area, lj::Area::Retained);
  EXPECT_EQ(w[0].addr.index, 3);
  EXPECT_EQ(w[0].value, 0x12345678);
  EXPECT_TRUE(retained);
  ASSERT_EQ(mbmap::planRegisterWrite(0, {0xFFFF}, false, w, retained), 0);
  EXPECT_FALSE(retained);
  EXPECT_EQ(w[0].addr.area, lj::Area::Word);
  // Half of a 32-bit element, or starting at its high word: refused.
  EXPECT_EQ(mbmap::planRegisterWrite(2006, {1}, false, w, retained), kMbIllegalDataAddress);
  EXPECT_EQ(mbmap::planRegisterWrite(2007, {1, 2}, false, w, retained), kMbIllegalDataAddress);
  // X and F only with writeInputs; P and the input-register table never.
  EXPECT_EQ(mbmap::planRegisterWrite(9000, {1}, false, w, retained), kMbIllegalDataAddress);
  EXPECT_EQ(mbmap::planRegisterWrite(9000, {1}, true, w, retained), 0);
  EXPECT_EQ(mbmap::planRegisterWrite(10000, {1}, false, w, retained), kMbIllegalDataAddress);
  EXPECT_EQ(mbmap::planCoilWrite(10000, {1}, false, w), kMbIllegalDataAddress);
  EXPECT_EQ(mbmap::planCoilWrite(10000, {1}, true, w), 0);
  EXPECT_EQ(w[0].addr.area, lj::Area::Input);
  // Byte registers take 0..255.
  EXPECT_EQ(mbmap::planRegisterWrite(7000, {256}, false, w, retained), kMbIllegalDataValue);
  ASSERT_EQ(mbmap::planCoilWrite(4103, {1}, false, w), 0); // Y512.7
  EXPECT_EQ(w[0].addr.index, 512);
  EXPECT_EQ(w[0].addr.bit, 7);
}

/// An in-memory stand-in for runtime::Exchange: writes apply at once.
struct FakeBackend {
  std::mutex mu;
  lj_state s{};
  uint64_t seq = 0;
  std::atomic<int> commits{0};
  ModbusBackend make() {
    ModbusBackend b;
    b.snapshot = [this](lj_state &out) {
      std::lock_guard lk(mu);
      out = s;
      return true;
    };
    b.post = [this](std::vector<formats::Assignment> w) {
      std::lock_guard lk(mu);
      for (auto &a : w) formats::writeAddress(s, a.addr, a.value);
      return ++seq;
    };
    b.waitVisible = [](uint64_t, std::chrono::milliseconds) { return true; };
    b.commitRetained = [this](std::chrono::milliseconds) {
      ++commits;
      return true;
    };
    return b;
  }
};

class ModbusServerTest : public ::testing::Test {
protected:
  void SetUp() override {
    ModbusConfig c;
    c.port = 0;
    c.maxClients = 8;
    c.log = [](const std::string &) {};
    server = std::make_unique<ModbusServer>(c, be.make());
    std::string err;
    ASSERT_TRUE(server->start(err)) << err;
  }
  modbus_t *client() {
    modbus_t *ctx = modbus_new_tcp("127.0.0.1", server->port());
    EXPECT_EQ(modbus_connect(ctx), 0);
    return ctx;
  }
  FakeBackend be;
  std::unique_ptr<ModbusServer> server;
};

TEST_F(ModbusServerTest, ReadWriteThroughLibmodbusClient) {
  modbus_t *ctx = client();
  uint16_t two[2] = {0x0007, 0x0001}; // B1 = 0x00010007, low word first
  ASSERT_EQ(modbus_write_registers(ctx, 2002, 2, two), 2);
  EXPECT_EQ(be.s.img.B[1], 0x00010007);
  EXPECT_EQ(be.commits, 1);                   // a B write waits for the retain commit
  ASSERT_EQ(modbus_write_bit(ctx, 17, 1), 1); // Y2.1
  EXPECT_EQ(be.s.img.Y[2], 0x02);
  EXPECT_EQ(be.commits, 1);
  uint16_t r[2];
  ASSERT_EQ(modbus_read_registers(ctx, 2002, 2, r), 2);
  EXPECT_EQ(r[0], 7);
  EXPECT_EQ(r[1], 1);
  uint8_t bits[8];
  ASSERT_EQ(modbus_read_bits(ctx, 16, 8, bits), 8);
  EXPECT_EQ(bits[1], 1);
  // Exceptions: unmapped addresses, F and X without the simulation flag, a bad coil value.
  EXPECT_EQ(modbus_read_registers(ctx, 500, 1, r), -1);
  EXPECT_EQ(errno, EMBXILADD);
  EXPECT_EQ(modbus_write_register(ctx, 6500, 1), -1);
  EXPECT_EQ(errno, EMBXILADD);
  EXPECT_EQ(modbus_write_register(ctx, 10000, 1), -1);
  EXPECT_EQ(errno, EMBXILADD);
  uint16_t in[2];
  ASSERT_EQ(modbus_read_input_registers(ctx, 5000, 2, in), 2); // P0, read-only
  EXPECT_EQ(modbus_write_bit(ctx, 10000, 1), -1);
  EXPECT_EQ(errno, EMBXILADD);
  modbus_close(ctx);
  modbus_free(ctx);
}

/// Raw frames: an unknown function code gets ILLEGAL FUNCTION, a frame with a bad protocol id
/// closes only that connection, and other clients keep being served.
TEST_F(ModbusServerTest, MalformedFramesAndManyClients) {
  int fd = ::socket(AF_INET, SOCK_STREAM, 0);
  sockaddr_in sa{};
  sa.sin_family = AF_INET;
  sa.sin_port = htons(static_cast<uint16_t>(server->port()));
  sa.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  ASSERT_EQ(::connect(fd, reinterpret_cast<sockaddr *>(&sa), sizeof sa), 0);
  const uint8_t unknownFc[] = {0, 1, 0, 0, 0, 4, 1, 0x41, 0xAA, 0xBB};
  ASSERT_EQ(::send(fd, unknownFc, sizeof unknownFc, 0), (ssize_t)sizeof unknownFc);
  uint8_t rsp[64];
  ASSERT_EQ(::recv(fd, rsp, sizeof rsp, 0), 9);
  EXPECT_EQ(rsp[7], 0xC1);
  EXPECT_EQ(rsp[8], kMbIllegalFunction);
  // Issue 28 finding 10: a function code >= 0x80 gets exception 01 with fc | 0x80 (itself), not
  // libmodbus's 8-bit fc + 0x80 (0x83 -> "03 01", which reads as an FC3 reply).
  for (uint8_t fc : {uint8_t{0x83}, uint8_t{0x80}, uint8_t{0xFF}}) {
    const uint8_t highFc[] = {0x12, 0x34, 0, 0, 0, 6, 7, fc, 0, 0, 0, 1};
    ASSERT_EQ(::send(fd, highFc, sizeof highFc, 0), (ssize_t)sizeof highFc);
    ASSERT_EQ(::recv(fd, rsp, sizeof rsp, 0), 9) << int(fc);
    const uint8_t want[] = {0x12, 0x34, 0, 0, 0, 3, 7, fc, kMbIllegalFunction};
    EXPECT_EQ(std::memcmp(rsp, want, sizeof want), 0) << int(fc) << ": fc " << int(rsp[7]);
  }
  const uint8_t tooMany[] = {0, 3, 0, 0, 0, 6, 1, 3, 0, 0, 0, 126}; // > 125 registers
  ASSERT_EQ(::send(fd, tooMany, sizeof tooMany, 0), (ssize_t)sizeof tooMany);
  ASSERT_EQ(::recv(fd, rsp, sizeof rsp, 0), 9);
  EXPECT_EQ(rsp[7], 0x83);
  EXPECT_EQ(rsp[8], kMbIllegalDataValue);
  const uint8_t badProto[] = {0, 2, 0x12, 0x34, 0, 6, 1, 3, 0, 0, 0, 1};
  ASSERT_EQ(::send(fd, badProto, sizeof badProto, 0), (ssize_t)sizeof badProto);
  EXPECT_EQ(::recv(fd, rsp, sizeof rsp, 0), 0); // closed
  ::close(fd);

  std::vector<modbus_t *> ctxs;
  for (int i = 0; i < 4; ++i) ctxs.push_back(client());
  for (int i = 0; i < 4; ++i) {
    uint16_t v = static_cast<uint16_t>(100 + i);
    ASSERT_EQ(modbus_write_register(ctxs[i], i, v), 1);
  }
  for (int i = 0; i < 4; ++i) {
    uint16_t r;
    ASSERT_EQ(modbus_read_registers(ctxs[(i + 1) % 4], i, 1, &r), 1);
    EXPECT_EQ(r, 100 + i);
  }
  for (modbus_t *c : ctxs) {
    modbus_close(c);
    modbus_free(c);
  }
  EXPECT_GE(server->stats().dropped, 1u);
}

} // namespace

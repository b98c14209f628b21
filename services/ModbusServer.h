// The Modbus TCP server of `ladderjit serve` (libmodbus): the register map of docs/modbus-map.md
// over the process image, one thread per client, writes applied at tick boundaries.
#pragma once

#include "formats/Address.h"
#include "ladderjit/abi.h"
#include "services/ClientSlots.h"
#include "services/ModbusMap.h"

#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <list>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace lj::services {

/// Modbus exception codes (Modbus Application Protocol V1.1b3, 7).
enum : uint8_t {
  kMbIllegalFunction = 0x01,
  kMbIllegalDataAddress = 0x02,
  kMbIllegalDataValue = 0x03,
  kMbServerDeviceFailure = 0x04,
};

/// Pure map logic (docs/modbus-map.md), separate from the sockets so it is unit-tested alone.
/// Every function returns 0 or a Modbus exception code. The overloads without a map use the
/// built-in HNC-8 map (ModbusMap::hnc8()).
namespace mbmap {
uint8_t readBits(const ModbusMap &map, MbTable table, uint16_t addr, uint16_t count,
                 const lj_state &s, std::vector<uint8_t> &out);
uint8_t readRegisters(const ModbusMap &map, MbTable table, uint16_t addr, uint16_t count,
                      const lj_state &s, std::vector<uint16_t> &out);
/// `retained` is set when an element of a retentive area is written (the write then waits
/// for a durable retain save).
uint8_t planCoilWrite(const ModbusMap &map, uint16_t addr, const std::vector<uint8_t> &bits,
                      bool writeInputs, std::vector<formats::Assignment> &out, bool &retained);
uint8_t planRegisterWrite(const ModbusMap &map, uint16_t addr, const std::vector<uint16_t> &regs,
                          bool writeInputs, std::vector<formats::Assignment> &out, bool &retained);
/// Read `count` bits of `table` (Coils or DiscreteInputs) starting at `addr` into `out` (0/1).
uint8_t readBits(MbTable table, uint16_t addr, uint16_t count, const lj_state &s,
                 std::vector<uint8_t> &out);
/// Read `count` registers of `table` (Holding or Input) starting at `addr` into `out`.
uint8_t readRegisters(MbTable table, uint16_t addr, uint16_t count, const lj_state &s,
                      std::vector<uint16_t> &out);
/// Turn a coil write into state assignments; `writeInputs` also allows the X coils.
uint8_t planCoilWrite(uint16_t addr, const std::vector<uint8_t> &bits, bool writeInputs,
                      std::vector<formats::Assignment> &out);
/// Turn a holding-register write into state assignments. 32-bit elements (D, B) must be
/// written whole (both registers in one request). `retained` is set when a B element is
/// written (the write then waits for a durable retain save).
uint8_t planRegisterWrite(uint16_t addr, const std::vector<uint16_t> &regs, bool writeInputs,
                          std::vector<formats::Assignment> &out, bool &retained);
} // namespace mbmap

/// What the server reads and writes: in serve, runtime::Exchange and the retain store.
struct ModbusBackend {
  /// A consistent copy of the last published state; false while none is published.
  std::function<bool(lj_state &)> snapshot;
  /// Queue writes for the next tick boundary; returns their sequence number.
  std::function<uint64_t(std::vector<formats::Assignment>)> post;
  /// Wait until a posted sequence is applied and its tick published.
  std::function<bool(uint64_t, std::chrono::milliseconds)> waitVisible;
  /// Optional: wait until a retain save containing everything applied so far is durable.
  std::function<bool(std::chrono::milliseconds)> commitRetained;
};

/// Server settings (`serve --modbus HOST:PORT`).
struct ModbusConfig {
  std::string host = "127.0.0.1"; ///< bind address (loopback by default)
  int port = 502;                 ///< 0 = any free port (see ModbusServer::port())
  bool writeInputs = false;       ///< X and F writable (simulation only)
  int maxClients = 16;            ///< at the cap, the longest-idle client is closed for a new one
  std::chrono::milliseconds writeTimeout{2000};   ///< apply + durable save, then exception 04
  std::chrono::milliseconds idleTimeout{30000};   ///< no request for this long: closed
  std::chrono::milliseconds requestTimeout{2000}; ///< a frame must be whole this long after
                                                  ///< its first byte, else the connection closes
  std::function<void(const std::string &)> log;   ///< default: stderr
  std::shared_ptr<const ModbusMap> map;           ///< null: the built-in HNC-8 map
};

/// Counters for the log and the tests.
struct ModbusStats {
  uint64_t requests = 0;
  uint64_t exceptions = 0;
  uint64_t connections = 0;
  uint64_t dropped = 0;    ///< connections closed for a malformed frame or over the cap
  uint64_t idleClosed = 0; ///< connections closed after idleTimeout without a request
  uint64_t timedOut = 0;   ///< connections closed for a frame not whole within requestTimeout
  uint64_t evicted = 0;    ///< idle (or stuck) connections closed to admit a new client
};

/// The server: an accept thread and one thread per client (each with its own libmodbus
/// context), so a client waiting for a durable write does not hold up the others. Frames are
/// read here (MBAP header, then its length) against a whole-request deadline, so a client
/// dripping bytes cannot keep a slot; libmodbus only builds the replies.
class ModbusServer {
public:
  ModbusServer(ModbusConfig cfg, ModbusBackend backend);
  ~ModbusServer(); ///< stop()
  ModbusServer(const ModbusServer &) = delete;
  ModbusServer &operator=(const ModbusServer &) = delete;

  /// Bind, listen and start accepting. False with `error` naming the problem.
  bool start(std::string &error);
  /// Close the listener and every client, join the threads.
  void stop();
  /// The bound port (after start).
  int port() const { return port_; }
  ModbusStats stats() const;

private:
  void acceptLoop();
  void clientLoop(ClientSlot *c);
  /// Read one ADU into `buf` by `deadlineMs` (steady ms): its length, -1 when the peer closed,
  /// -2 for a malformed MBAP header, -3 past the deadline.
  int readFrame(int fd, uint8_t *buf, int64_t deadlineMs);
  /// Handle one request ADU; false when the connection must be closed.
  bool handle(void *ctx, const uint8_t *req, int len);
  void logLine(const std::string &line) const;
  const ModbusMap &map() const { return cfg_.map ? *cfg_.map : ModbusMap::hnc8(); }

  ModbusConfig cfg_;
  ModbusBackend be_;
  int listenFd_ = -1;
  int port_ = 0;
  std::atomic<bool> stop_{false};
  std::thread acceptThread_;
  mutable std::mutex mu_;
  std::list<ClientSlot> clients_; // guarded by mu_
  ModbusStats stats_;             // guarded by mu_
};

} // namespace lj::services

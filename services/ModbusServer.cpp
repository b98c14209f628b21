// Modbus TCP server: the register map (docs/modbus-map.md), request validation with Modbus
// exceptions, framing under idle and whole-request deadlines, libmodbus replies, one thread per
// client.
#include "services/ModbusServer.h"

#include <algorithm>
#include <arpa/inet.h>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <modbus/modbus.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

namespace lj::services {
namespace {

using Kind = MbBlock::Kind;
using Access = MbBlock::Access;

bool writable(const MbBlock &b, bool writeInputs) {
  return b.access == Access::ReadWrite || (b.access == Access::InputWrite && writeInputs);
}

uint16_t be16(const uint8_t *p) { return static_cast<uint16_t>(p[0] << 8 | p[1]); }

} // namespace

namespace mbmap {

uint8_t readBits(const ModbusMap &map, MbTable table, uint16_t addr, uint16_t count,
                 const lj_state &s, std::vector<uint8_t> &out) {
  out.clear();
  for (uint32_t i = 0; i < count; ++i) {
    uint32_t el = 0;
    int part = 0;
    const MbBlock *b = map.resolve(table, uint32_t{addr} + i, el, part);
    if (!b) return kMbIllegalDataAddress;
    out.push_back(static_cast<uint8_t>(formats::readAddress(s, b->element(el)) ? 1 : 0));
  }
  return 0;
}

uint8_t readRegisters(const ModbusMap &map, MbTable table, uint16_t addr, uint16_t count,
                      const lj_state &s, std::vector<uint16_t> &out) {
  out.clear();
  for (uint32_t i = 0; i < count; ++i) {
    uint32_t el = 0;
    int part = 0;
    const MbBlock *b = map.resolve(table, uint32_t{addr} + i, el, part);
    if (!b) return kMbIllegalDataAddress;
    uint32_t v = static_cast<uint32_t>(formats::readAddress(s, b->element(el)));
    if (b->kind == Kind::Byte) v &= 0xFF; // bytes read 0..255, whatever their signedness
    // 32-bit elements: low word at the lower address (docs/modbus-map.md "Word order").
    out.push_back(static_cast<uint16_t>(part == 1 ? v >> 16 : v & 0xFFFF));
  }
  return 0;
}

uint8_t planCoilWrite(const ModbusMap &map, uint16_t addr, const std::vector<uint8_t> &bits,
                      bool writeInputs, std::vector<formats::Assignment> &out, bool &retained) {
  out.clear();
  retained = false;
  for (size_t i = 0; i < bits.size(); ++i) {
    uint32_t el = 0;
    int part = 0;
    const MbBlock *b =
        map.resolve(MbTable::Coils, uint32_t{addr} + static_cast<uint32_t>(i), el, part);
    if (!b || !writable(*b, writeInputs)) return kMbIllegalDataAddress;
    if (b->retained) retained = true;
    out.push_back({b->element(el), bits[i] ? 1 : 0});
  }
  return 0;
}

uint8_t planRegisterWrite(const ModbusMap &map, uint16_t addr, const std::vector<uint16_t> &regs,
                          bool writeInputs, std::vector<formats::Assignment> &out, bool &retained) {
  out.clear();
  retained = false;
  for (size_t i = 0; i < regs.size(); ++i) {
    uint32_t el = 0;
    int part = 0;
    const MbBlock *b =
        map.resolve(MbTable::HoldingRegisters, uint32_t{addr} + static_cast<uint32_t>(i), el, part);
    if (!b || !writable(*b, writeInputs)) return kMbIllegalDataAddress;
    int64_t value = regs[i];
    if (b->kind == Kind::Word32) {
      // Both halves in one request, low word first: a half write would race the program.
      if (part != 0 || i + 1 >= regs.size()) return kMbIllegalDataAddress;
      value = static_cast<int64_t>(uint32_t{regs[i]} | uint32_t{regs[i + 1]} << 16);
      ++i;
    } else if (b->kind == Kind::Byte && value > 0xFF) {
      return kMbIllegalDataValue;
    }
    if (b->retained) retained = true;
    out.push_back({b->element(el), value});
  }
  return 0;
}

uint8_t readBits(MbTable table, uint16_t addr, uint16_t count, const lj_state &s,
                 std::vector<uint8_t> &out) {
  return readBits(ModbusMap::hnc8(), table, addr, count, s, out);
}
uint8_t readRegisters(MbTable table, uint16_t addr, uint16_t count, const lj_state &s,
                      std::vector<uint16_t> &out) {
  return readRegisters(ModbusMap::hnc8(), table, addr, count, s, out);
}
uint8_t planCoilWrite(uint16_t addr, const std::vector<uint8_t> &bits, bool writeInputs,
                      std::vector<formats::Assignment> &out) {
  bool retained = false;
  return planCoilWrite(ModbusMap::hnc8(), addr, bits, writeInputs, out, retained);
}
uint8_t planRegisterWrite(uint16_t addr, const std::vector<uint16_t> &regs, bool writeInputs,
                          std::vector<formats::Assignment> &out, bool &retained) {
  return planRegisterWrite(ModbusMap::hnc8(), addr, regs, writeInputs, out, retained);
}

} // namespace mbmap

ModbusServer::ModbusServer(ModbusConfig cfg, ModbusBackend backend)
    : cfg_(std::move(cfg)), be_(std::move(backend)) {}

ModbusServer::~ModbusServer() { stop(); }

void ModbusServer::logLine(const std::string &line) const {
  if (cfg_.log)
    cfg_.log(line);
  else
    std::fprintf(stderr, "%s\n", line.c_str());
}

ModbusStats ModbusServer::stats() const {
  std::lock_guard lk(mu_);
  return stats_;
}

bool ModbusServer::start(std::string &error) {
  sockaddr_in sa{};
  sa.sin_family = AF_INET;
  sa.sin_port = htons(static_cast<uint16_t>(cfg_.port));
  if (cfg_.port < 0 || cfg_.port > 65535) {
    error = "modbus: port " + std::to_string(cfg_.port) + " out of range 0..65535";
    return false;
  }
  if (inet_pton(AF_INET, cfg_.host.c_str(), &sa.sin_addr) != 1) {
    error = "modbus: '" + cfg_.host + "' is not an IPv4 address";
    return false;
  }
  listenFd_ = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  int one = 1;
  if (listenFd_ < 0 || ::setsockopt(listenFd_, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one) != 0 ||
      ::bind(listenFd_, reinterpret_cast<sockaddr *>(&sa), sizeof sa) != 0 ||
      ::listen(listenFd_, 16) != 0) {
    error = "modbus: cannot listen on " + cfg_.host + ":" + std::to_string(cfg_.port) + ": " +
            std::strerror(errno);
    if (listenFd_ >= 0) ::close(listenFd_);
    listenFd_ = -1;
    return false;
  }
  socklen_t len = sizeof sa;
  ::getsockname(listenFd_, reinterpret_cast<sockaddr *>(&sa), &len);
  port_ = ntohs(sa.sin_port);
  stop_ = false;
  acceptThread_ = std::thread([this] { acceptLoop(); });
  return true;
}

void ModbusServer::stop() {
  stop_ = true;
  if (acceptThread_.joinable()) acceptThread_.join();
  if (listenFd_ >= 0) ::close(listenFd_);
  listenFd_ = -1;
  closeAll(clients_, mu_); // the shutdown wakes a client blocked in a read
}

void ModbusServer::acceptLoop() {
  while (!stop_) {
    pollfd p{listenFd_, POLLIN, 0};
    int r = ::poll(&p, 1, 100);
    std::lock_guard lk(mu_);
    reapFinished(clients_);
    if (r <= 0) continue;
    int fd = ::accept4(listenFd_, nullptr, nullptr, SOCK_CLOEXEC);
    if (fd < 0) continue;
    ++stats_.connections;
    // At the cap, make room (ClientSlots.h; docs/modbus-map.md "Connections").
    bool evicted = false;
    const int active = makeRoom(clients_, cfg_.maxClients, evicted);
    if (evicted) {
      ++stats_.evicted;
      logLine("modbus: " + std::to_string(cfg_.maxClients) +
              " clients connected; closed the one idle longest to admit a new one");
    }
    if (active >= cfg_.maxClients) {
      ++stats_.dropped;
      ::close(fd);
      logLine("modbus: connection refused: " + std::to_string(cfg_.maxClients) +
              " clients busy with requests");
      continue;
    }
    setSendTimeout(fd, cfg_.requestTimeout);
    ClientSlot &c = clients_.emplace_back();
    c.fd = fd;
    c.sinceMs = steadyMs();
    c.thread = std::thread([this, &c] { clientLoop(&c); });
  }
}

int ModbusServer::readFrame(int fd, uint8_t *buf, int64_t deadlineMs) {
  int have = 0, want = 7; // the MBAP header first (Modbus Messaging on TCP/IP V1.0b, 3.1.3)
  while (have < want) {
    int64_t left = deadlineMs - steadyMs();
    if (left <= 0) return -3;
    if (stop_) return -1;
    pollfd p{fd, POLLIN, 0};
    int r = ::poll(&p, 1, static_cast<int>(std::min<int64_t>(left, 100)));
    if (r < 0 && errno == EINTR) continue;
    if (r < 0) return -1;
    if (r == 0) continue;
    ssize_t n = ::recv(fd, buf + have, static_cast<size_t>(want - have), 0);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return -1;
    have += static_cast<int>(n);
    if (have == 7 && want == 7) {
      // Protocol 0; length = unit id + PDU, 2..254 (the largest ADU is 260 bytes).
      int declared = be16(buf + 4);
      if (be16(buf + 2) != 0 || declared < 2 || declared > MODBUS_TCP_MAX_ADU_LENGTH - 6) return -2;
      want = 6 + declared;
    }
  }
  return have;
}

void ModbusServer::clientLoop(ClientSlot *c) {
  // The context only replies on our socket; its own address is never used. Frames are read
  // by readFrame, under the whole-request deadline.
  modbus_t *ctx = modbus_new_tcp("127.0.0.1", 502);
  modbus_set_socket(ctx, c->fd);
  std::vector<uint8_t> req(MODBUS_TCP_MAX_ADU_LENGTH);
  int64_t idleSince = steadyMs();
  while (!stop_) {
    int64_t left = idleSince + cfg_.idleTimeout.count() - steadyMs();
    if (left <= 0) {
      std::lock_guard lk(mu_);
      ++stats_.idleClosed;
      break;
    }
    pollfd p{c->fd, POLLIN, 0};
    int r = ::poll(&p, 1, static_cast<int>(std::min<int64_t>(left, 100)));
    if (r == 0) continue;
    if (r < 0 && errno == EINTR) continue;
    if (r < 0 || (p.revents & (POLLERR | POLLNVAL))) break;
    int64_t first = steadyMs();
    c->sinceMs = first;
    c->state = ClientSlot::Receiving;
    int len = readFrame(c->fd, req.data(), first + cfg_.requestTimeout.count());
    if (len < 0) {
      if (len == -2) { // read what the peer already sent, so closing sends FIN, not RST
        uint8_t junk[MODBUS_TCP_MAX_ADU_LENGTH];
        for (int k = 0; k < 4 && ::recv(c->fd, junk, sizeof junk, MSG_DONTWAIT) > 0; ++k) {
        }
      }
      if (len != -1) {
        std::lock_guard lk(mu_);
        ++stats_.dropped;
        if (len == -3) ++stats_.timedOut;
      }
      break; // peer closed, a malformed header, or a frame not whole in time
    }
    c->state = ClientSlot::Handling;
    if (!handle(ctx, req.data(), len)) {
      std::lock_guard lk(mu_);
      ++stats_.dropped;
      break;
    }
    idleSince = steadyMs();
    c->sinceMs = idleSince;
    c->state = ClientSlot::Idle;
  }
  modbus_free(ctx); // does not close the socket (set with modbus_set_socket)
  std::lock_guard lk(mu_);
  ::close(c->fd);
  c->fd = -1;
  c->done = true;
}

bool ModbusServer::handle(void *vctx, const uint8_t *req, int len) {
  auto *ctx = static_cast<modbus_t *>(vctx);
  const int hl = modbus_get_header_length(ctx); // 7: the MBAP header
  // readFrame checked the MBAP header (protocol 0, a length that fits) and read the whole
  // frame; at least the unit id and a function code are here.
  if (len < hl + 1) return false;
  const uint8_t fc = req[hl];
  const uint8_t *d = req + hl + 1;
  const int dlen = len - hl - 1;
  uint8_t exc = 0;
  auto fail = [&](uint8_t code) {
    {
      std::lock_guard lk(mu_);
      ++stats_.exceptions; // the request itself was counted below
    }
    if (fc < 0x80) return modbus_reply_exception(ctx, req, code) >= 0;
    // libmodbus adds 0x80 to the function code in 8 bits: 0x83 would be answered as 03 01,
    // which reads as an FC3 reply. The exception reply keeps fc | 0x80 (= fc): MBAP header
    // (transaction, protocol 0, length 3, unit), function, exception code.
    uint8_t rsp[9] = {req[0], req[1], 0, 0, 0, 3, req[hl - 1], fc, code};
    const int fd = modbus_get_socket(ctx);
    for (size_t at = 0; at < sizeof rsp;) {
      ssize_t w = ::send(fd, rsp + at, sizeof rsp - at, MSG_NOSIGNAL);
      if (w < 0 && errno == EINTR) continue;
      if (w <= 0) return false;
      at += static_cast<size_t>(w);
    }
    return true;
  };
  {
    std::lock_guard lk(mu_);
    ++stats_.requests;
  }
  switch (fc) {
  case 1:
  case 2:
  case 3:
  case 4: {
    if (dlen != 4) return fail(kMbIllegalDataValue); // address, count
    uint16_t addr = be16(d), count = be16(d + 2);
    bool bits = fc <= 2;
    if (count < 1 || count > (bits ? MODBUS_MAX_READ_BITS : MODBUS_MAX_READ_REGISTERS))
      return fail(kMbIllegalDataValue);
    MbTable table = fc == 1   ? MbTable::Coils
                    : fc == 2 ? MbTable::DiscreteInputs
                    : fc == 3 ? MbTable::HoldingRegisters
                              : MbTable::InputRegisters;
    static thread_local lj_state snap;
    if (!be_.snapshot || !be_.snapshot(snap)) return fail(kMbServerDeviceFailure);
    std::vector<uint8_t> bv;
    std::vector<uint16_t> rv;
    exc = bits ? mbmap::readBits(map(), table, addr, count, snap, bv)
               : mbmap::readRegisters(map(), table, addr, count, snap, rv);
    if (exc) return fail(exc);
    modbus_mapping_t *m = modbus_mapping_new_start_address(
        fc == 1 ? addr : 0, fc == 1 ? count : 0, fc == 2 ? addr : 0, fc == 2 ? count : 0,
        fc == 3 ? addr : 0, fc == 3 ? count : 0, fc == 4 ? addr : 0, fc == 4 ? count : 0);
    if (!m) return fail(kMbServerDeviceFailure);
    for (int i = 0; i < count; ++i) {
      if (fc == 1) m->tab_bits[i] = bv[i];
      if (fc == 2) m->tab_input_bits[i] = bv[i];
      if (fc == 3) m->tab_registers[i] = rv[i];
      if (fc == 4) m->tab_input_registers[i] = rv[i];
    }
    bool ok = modbus_reply(ctx, req, len, m) >= 0;
    modbus_mapping_free(m);
    return ok;
  }
  case 5:
  case 6:
  case 15:
  case 16: {
    if (dlen < 4 || (fc <= 6 && dlen != 4)) return fail(kMbIllegalDataValue);
    uint16_t addr = be16(d);
    std::vector<formats::Assignment> writes;
    bool retained = false;
    uint16_t count = 1;
    if (fc == 5) {
      uint16_t v = be16(d + 2);
      if (v != 0xFF00 && v != 0x0000) return fail(kMbIllegalDataValue);
      exc = mbmap::planCoilWrite(map(), addr, {static_cast<uint8_t>(v ? 1 : 0)}, cfg_.writeInputs,
                                 writes, retained);
    } else if (fc == 6) {
      exc =
          mbmap::planRegisterWrite(map(), addr, {be16(d + 2)}, cfg_.writeInputs, writes, retained);
    } else {
      count = be16(d + 2);
      int bytes = dlen >= 5 ? d[4] : -1;
      bool coils = fc == 15;
      int maxCount = coils ? MODBUS_MAX_WRITE_BITS : MODBUS_MAX_WRITE_REGISTERS;
      int needBytes = coils ? (count + 7) / 8 : 2 * count;
      if (count < 1 || count > maxCount || bytes != needBytes || dlen != 5 + bytes)
        return fail(kMbIllegalDataValue);
      if (coils) {
        std::vector<uint8_t> bv(count);
        for (int i = 0; i < count; ++i) bv[i] = (d[5 + i / 8] >> (i % 8)) & 1;
        exc = mbmap::planCoilWrite(map(), addr, bv, cfg_.writeInputs, writes, retained);
      } else {
        std::vector<uint16_t> rv(count);
        for (int i = 0; i < count; ++i) rv[i] = be16(d + 5 + 2 * i);
        exc = mbmap::planRegisterWrite(map(), addr, rv, cfg_.writeInputs, writes, retained);
      }
    }
    if (exc) return fail(exc);
    if (!be_.post || !be_.waitVisible) return fail(kMbServerDeviceFailure);
    // Acknowledge only what is applied (and, for retained areas, durably saved): docs/retain.md.
    uint64_t seq = be_.post(std::move(writes));
    if (!be_.waitVisible(seq, cfg_.writeTimeout)) return fail(kMbServerDeviceFailure);
    if (retained && be_.commitRetained && !be_.commitRetained(cfg_.writeTimeout))
      return fail(kMbServerDeviceFailure);
    bool coils = fc == 5 || fc == 15;
    modbus_mapping_t *m = modbus_mapping_new_start_address(
        coils ? addr : 0, coils ? count : 0, 0, 0, coils ? 0 : addr, coils ? 0 : count, 0, 0);
    if (!m) return fail(kMbServerDeviceFailure);
    bool ok = modbus_reply(ctx, req, len, m) >= 0; // echoes the request (and fills `m`)
    modbus_mapping_free(m);
    return ok;
  }
  default:
    return fail(kMbIllegalFunction);
  }
}

} // namespace lj::services

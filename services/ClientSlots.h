// The connection slots of a server that caps its clients, and the cap's policy, shared by serve's
// control socket (runtime/ControlSocket.cpp) and the Modbus TCP server (ModbusServer.cpp): each
// connection has a thread and a state; at the cap the one idle longest (else the one longest
// stuck in an incomplete request) is closed to admit a new one, and one being served never is,
// so idle or dripping connections cannot lock a new client out (docs/modbus-map.md
// "Connections", docs/serve.md). Header-only: the two servers' libraries share no other code.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <list>
#include <mutex>
#include <sys/socket.h>
#include <sys/time.h>
#include <thread>

namespace lj::services {

/// Steady-clock milliseconds, the clock of ClientSlot::sinceMs.
inline int64_t steadyMs() {
  return std::chrono::duration_cast<std::chrono::milliseconds>(
             std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

/// One accepted connection. `fd` is closed (and set to -1) under the server's mutex, so a
/// shutdown() of an evicted slot never hits a reused number.
struct ClientSlot {
  enum State : int { Idle, Receiving, Handling };
  int fd = -1;
  std::thread thread;
  std::atomic<bool> done{false};
  std::atomic<int> state{Idle};
  std::atomic<int64_t> sinceMs{0}; ///< steady ms of the last state change
  bool evicted = false;            ///< guarded by the server's mutex
};

/// Join and drop the slots whose thread has finished. Under the server's mutex.
inline void reapFinished(std::list<ClientSlot> &slots) {
  for (auto it = slots.begin(); it != slots.end();) {
    if (it->done.load()) {
      it->thread.join();
      it = slots.erase(it);
    } else {
      ++it;
    }
  }
}

/// Before admitting a new connection, under the server's mutex: when `cap` slots are active
/// (not evicted), close the one idle longest, else the one longest in an incomplete request
/// (never one being served; shutdown() wakes its thread, which closes it). Returns how many
/// stay active; `evicted` says whether one was closed.
inline int makeRoom(std::list<ClientSlot> &slots, int cap, bool &evicted) {
  evicted = false;
  int active = 0;
  ClientSlot *victim = nullptr;
  for (ClientSlot &c : slots) {
    if (c.evicted) continue;
    ++active;
    int s = c.state.load();
    if (s == ClientSlot::Handling) continue;
    int vs = victim ? victim->state.load() : -1;
    if (!victim || (s == ClientSlot::Idle && vs != ClientSlot::Idle) ||
        (s == vs && c.sinceMs.load() < victim->sinceMs.load()))
      victim = &c;
  }
  if (active >= cap && victim) {
    victim->evicted = true;
    ::shutdown(victim->fd, SHUT_RDWR);
    --active;
    evicted = true;
  }
  return active;
}

/// At the server's stop: shut every open slot down (which wakes its thread) under `mu`, then
/// join the threads outside it.
inline void closeAll(std::list<ClientSlot> &slots, std::mutex &mu) {
  std::list<ClientSlot> all;
  {
    std::lock_guard<std::mutex> g(mu);
    for (ClientSlot &c : slots)
      if (c.fd >= 0) ::shutdown(c.fd, SHUT_RDWR);
    all.splice(all.end(), slots);
  }
  for (ClientSlot &c : all)
    if (c.thread.joinable()) c.thread.join();
}

/// Bound every send on `fd` by `timeout`: a client that never reads cannot hold a thread.
inline void setSendTimeout(int fd, std::chrono::milliseconds timeout) {
  timeval tv{static_cast<time_t>(timeout.count() / 1000),
             static_cast<suseconds_t>(timeout.count() % 1000 * 1000)};
  ::setsockopt(fd, SOL_SOCKET, SO_SNDTIMEO, &tv, sizeof tv);
}

} // namespace lj::services

// writeSystemBits (SystemBits.h).
#include "hosts/SystemBits.h"

namespace lj::hosts {

void writeSystemBits(const TargetProfile &tp, lj_state &s, uint64_t tick) {
  auto *bytes = reinterpret_cast<unsigned char *>(&s);
  for (const SystemBit &b : tp.systemBits) {
    bool v = false;
    switch (b.kind) {
    case SystemBit::Kind::Zero:
      v = false;
      break;
    case SystemBit::Kind::One:
      v = true;
      break;
    case SystemBit::Kind::FirstScan:
      v = tick == 0;
      break;
    case SystemBit::Kind::Clock:
      v = b.halfPeriodMs > 0 && (s.now_ms / b.halfPeriodMs) % 2 == 0;
      break;
    }
    const auto mask = static_cast<unsigned char>(1u << b.bit);
    bytes[b.offset] =
        static_cast<unsigned char>(v ? (bytes[b.offset] | mask) : (bytes[b.offset] & ~mask));
  }
}

} // namespace lj::hosts

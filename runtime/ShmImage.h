// The shared-memory process image of `ladderjit serve --shm NAME`: a POSIX shm object holding a
// small header (magic, ABI version, two sequence counters) and one lj_image (layout = abi.h).
// An external host writes X (and F with --io shm); serve publishes everything else after each
// tick. The protocol is two seqlocks (docs/serve.md "Shared-memory image").
#pragma once

#include "ladderjit/abi.h"
#include "runtime/Executive.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace lj::rt {

/// The header at offset 0 of the shm object; the lj_image follows at offset 64.
struct ShmHeader {
  char magic[8];       ///< "LJSHMIMG"
  uint32_t abiVersion; ///< LJ_ABI_VERSION
  uint32_t headerSize; ///< 64
  uint32_t imageSize;  ///< sizeof(lj_image)
  uint32_t flags;      ///< kShmHostOwnsF when the host writes F (--io shm)
  uint64_t periodNs;   ///< PLC1 period of the server
  uint64_t inSeq;      ///< host: odd while it writes X/F, even when they are consistent
  uint64_t outSeq;     ///< serve: odd while it writes the outputs, even when consistent
  uint64_t outTick;    ///< tick whose end state the outputs are
  uint64_t reserved;
};
static_assert(sizeof(ShmHeader) == 64, "shm header size");
inline constexpr char kShmMagic[8] = {'L', 'J', 'S', 'H', 'M', 'I', 'M', 'G'};
inline constexpr uint32_t kShmHostOwnsF = 1;
inline constexpr size_t kShmImageOffset = 64;
inline constexpr size_t kShmSize = kShmImageOffset + sizeof(lj_image);

/// A mapping of a shm image (server or client side).
class ShmMapping {
public:
  ShmMapping() = default;
  ~ShmMapping();
  ShmMapping(const ShmMapping &) = delete;
  ShmMapping &operator=(const ShmMapping &) = delete;
  /// Server: create `name` ("/name" or "name") as a new object (O_EXCL, mode 0600). An existing
  /// one of another user is refused; one of ours (left by a crash) is unlinked and replaced.
  bool create(const std::string &name, bool hostOwnsF, uint64_t periodNs, std::string &error);
  /// Client: map an existing image and check magic, ABI version and sizes.
  bool open(const std::string &name, std::string &error);
  ShmHeader *header() const { return static_cast<ShmHeader *>(base_); }
  lj_image *image() const {
    return reinterpret_cast<lj_image *>(static_cast<char *>(base_) + kShmImageOffset);
  }
  /// Remove the name (server, at exit).
  void unlinkName();

private:
  void *base_ = nullptr;
  std::string name_;
};

/// Client protocol: write X (and F when the host owns it) consistently.
void shmWriteInputs(ShmMapping &m, const uint8_t *x, const int16_t *f /* null = leave F */);
/// Client protocol: a consistent copy of the outputs; returns their tick.
uint64_t shmReadOutputs(const ShmMapping &m, lj_image &out);

/// Server side: reads the inputs before each scan (IoBinding) and publishes the outputs after
/// it (publish(), registered as an after-tick hook so locks are included).
class ShmImage : public IoBinding {
public:
  ShmImage(ShmMapping &m, bool hostOwnsF) : m_(m), hostOwnsF_(hostOwnsF) {}
  /// Copies X (and F) from the image when the host's sequence is even and unchanged over the
  /// copy; otherwise the previous consistent inputs stay (the scan never waits for the host).
  void beforeTick(lj_state &s, uint64_t tick) override;
  void afterTick(lj_state &, uint64_t) override {}
  /// Publish every area the host does not own.
  void publish(const lj_state &s, uint64_t tick);

private:
  ShmMapping &m_;
  bool hostOwnsF_;
  uint8_t x_[LJ_X_COUNT] = {};
  int16_t f_[LJ_F_COUNT] = {};
};

} // namespace lj::rt

// The shared-memory process image of `ladderjit serve --shm NAME`: a POSIX shm object holding a
// small header (magic, ABI version, two sequence counters), one lj_image (layout = abi.h) and the
// profile-laid region lj_state.mem (FANUC, IEC areas; ABI v3). An external host writes the
// inputs (HNC-8 X, FANUC X, IEC %I; and F with --io shm); serve publishes everything else after
// each tick. The protocol is two seqlocks (docs/serve.md "Shared-memory image").
#pragma once

#include "ir/Profile.h"
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
  uint32_t memSize;    ///< LJ_MEM_BYTES: the region at kShmMemOffset (lj_state.mem)
  uint32_t reserved;
};
static_assert(sizeof(ShmHeader) == 64, "shm header size");
inline constexpr char kShmMagic[8] = {'L', 'J', 'S', 'H', 'M', 'I', 'M', 'G'};
inline constexpr uint32_t kShmHostOwnsF = 1;
inline constexpr size_t kShmImageOffset = 64;
/// lj_state.mem follows the image: byte k of the region is lj_state.mem[k].
inline constexpr size_t kShmMemOffset = kShmImageOffset + sizeof(lj_image);
inline constexpr size_t kShmSize = kShmMemOffset + LJ_MEM_BYTES;
static_assert(kShmMemOffset % 16 == 0, "the region is 16-byte aligned");

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
  uint8_t *mem() const { return static_cast<uint8_t *>(base_) + kShmMemOffset; }
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
/// Client protocol, profile-laid targets: write `n` bytes at byte `offset` of the region (an
/// input area of the profile, e.g. FANUC X0.. at TargetProfile::elementOffset - mem) consistently.
void shmWriteMem(ShmMapping &m, uint32_t offset, const void *data, size_t n);
/// Client protocol: a consistent copy of the whole region (LJ_MEM_BYTES); returns its tick.
uint64_t shmReadMem(const ShmMapping &m, uint8_t *out);

/// A byte range of lj_state.mem (offsets relative to mem).
struct MemSpan {
  uint32_t offset = 0, bytes = 0;
};
/// The input areas of a profile-laid target inside lj_state.mem (its Input area; NcStatus too
/// when the host owns F): what the host writes. Empty for HNC-8 (its X is in lj_image).
std::vector<MemSpan> shmInputSpans(const TargetProfile &tp, bool hostOwnsF);

/// Server side: reads the inputs before each scan (IoBinding) and publishes the outputs after
/// it (publish(), registered as an after-tick hook so locks are included).
class ShmImage : public IoBinding {
public:
  /// `profile`: the program's target (nullptr: HNC-8); its input areas in lj_state.mem come
  /// from the host, the rest of the region is published.
  ShmImage(ShmMapping &m, bool hostOwnsF, const TargetProfile *profile = nullptr);
  /// Copies X (and F) from the image when the host's sequence is even and unchanged over the
  /// copy; otherwise the previous consistent inputs stay (the scan never waits for the host).
  void beforeTick(lj_state &s, uint64_t tick) override;
  void afterTick(lj_state &, uint64_t) override {}
  /// Publish every area the host does not own.
  void publish(const lj_state &s, uint64_t tick);

private:
  void beforeTickImage(lj_state &s); ///< the lj_image part (X, F)
  ShmMapping &m_;
  bool hostOwnsF_;
  uint8_t x_[LJ_X_COUNT] = {};
  int16_t f_[LJ_F_COUNT] = {};
  std::vector<MemSpan> inMem_;  ///< the host's spans of the region
  std::vector<MemSpan> outMem_; ///< the gaps between them: published
  std::vector<uint8_t> memIn_;  ///< last consistent copy of the host's spans (sized once)
};

} // namespace lj::rt

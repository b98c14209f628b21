// POSIX shm mapping of the process image and the two seqlock protocols around it.
#include "runtime/ShmImage.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstddef>
#include <cstring>
#include <thread>

namespace lj::rt {

namespace {

std::string shmName(const std::string &name) {
  return name.empty() || name[0] == '/' ? name : "/" + name;
}

std::atomic_ref<uint64_t> seq(uint64_t &v) { return std::atomic_ref<uint64_t>(v); }

} // namespace

ShmMapping::~ShmMapping() {
  if (base_) ::munmap(base_, kShmSize);
}

bool ShmMapping::create(const std::string &name, bool hostOwnsF, uint64_t periodNs,
                        std::string &error) {
  name_ = shmName(name);
  if (name_.size() < 2 || name_.find('/', 1) != std::string::npos) {
    error = "--shm: '" + name + "' is not a valid shared-memory name (one word, no '/')";
    return false;
  }
  // Always a new object (O_EXCL): an existing one may have been planted by someone who keeps
  // it mapped to inject inputs. Another user's is refused; our own (a server that crashed)
  // is unlinked, so whoever still maps it no longer reaches this server.
  int fd = ::shm_open(name_.c_str(), O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
  if (fd < 0 && errno == EEXIST) {
    int old = ::shm_open(name_.c_str(), O_RDONLY | O_CLOEXEC, 0);
    struct stat st;
    if (old >= 0 && ::fstat(old, &st) == 0 && st.st_uid != ::geteuid()) {
      ::close(old);
      error = "--shm: '" + name_ + "' already exists and belongs to uid " +
              std::to_string(st.st_uid) + ", not to this server (uid " +
              std::to_string(::geteuid()) + "); refusing to use an object someone else " +
              "controls: remove /dev/shm" + name_ + " or choose another name";
      return false;
    }
    if (old >= 0) ::close(old);
    ::shm_unlink(name_.c_str());
    fd = ::shm_open(name_.c_str(), O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
  }
  if (fd >= 0) ::fchmod(fd, 0600); // whatever the umask
  if (fd < 0 || ::ftruncate(fd, kShmSize) != 0) {
    error = "--shm: cannot create '" + name_ + "': " + std::strerror(errno);
    if (fd >= 0) ::close(fd);
    return false;
  }
  base_ = ::mmap(nullptr, kShmSize, PROT_READ | PROT_WRITE, MAP_SHARED, fd, 0);
  ::close(fd);
  if (base_ == MAP_FAILED) {
    base_ = nullptr;
    error = "--shm: cannot map '" + name_ + "': " + std::strerror(errno);
    return false;
  }
  ShmHeader *h = header();
  std::memcpy(h->magic, kShmMagic, sizeof h->magic);
  h->abiVersion = LJ_ABI_VERSION;
  h->headerSize = sizeof(ShmHeader);
  h->imageSize = sizeof(lj_image);
  h->flags = hostOwnsF ? kShmHostOwnsF : 0;
  h->periodNs = periodNs;
  h->memSize = LJ_MEM_BYTES;
  return true;
}

bool ShmMapping::open(const std::string &name, std::string &error) {
  name_ = shmName(name);
  int fd = ::shm_open(name_.c_str(), O_RDWR | O_CLOEXEC, 0);
  struct stat st;
  if (fd < 0 || ::fstat(fd, &st) != 0) {
    error = "shm '" + name_ + "': " + std::strerror(errno);
    if (fd >= 0) ::close(fd);
    return false;
  }
  if (static_cast<size_t>(st.st_size) < kShmSize) {
    ::close(fd);
    error = "shm '" + name_ + "' is too small for a ladderjit image";
    return false;
  }
  base_ = ::mmap(nullptr, kShmSize, PROT_READ | PROT_WRITE, MAP_SHARED, fd, 0);
  ::close(fd);
  if (base_ == MAP_FAILED) {
    base_ = nullptr;
    error = "shm '" + name_ + "': cannot map: " + std::strerror(errno);
    return false;
  }
  const ShmHeader *h = header();
  if (std::memcmp(h->magic, kShmMagic, sizeof h->magic) != 0 || h->abiVersion != LJ_ABI_VERSION ||
      h->headerSize != sizeof(ShmHeader) || h->imageSize != sizeof(lj_image) ||
      h->memSize != LJ_MEM_BYTES) {
    error = "shm '" + name_ + "' is not a ladderjit image of ABI version " +
            std::to_string(LJ_ABI_VERSION);
    return false;
  }
  return true;
}

void ShmMapping::unlinkName() {
  if (!name_.empty()) ::shm_unlink(name_.c_str());
}

void shmWriteInputs(ShmMapping &m, const uint8_t *x, const int16_t *f) {
  auto s = seq(m.header()->inSeq);
  s.fetch_add(1, std::memory_order_acq_rel); // odd: inputs in flux
  std::atomic_thread_fence(std::memory_order_release);
  std::memcpy(m.image()->X, x, sizeof m.image()->X);
  if (f) std::memcpy(m.image()->F, f, sizeof m.image()->F);
  s.fetch_add(1, std::memory_order_release); // even: consistent
}

uint64_t shmReadOutputs(const ShmMapping &m, lj_image &out) {
  auto s = seq(m.header()->outSeq);
  for (;;) {
    uint64_t a = s.load(std::memory_order_acquire);
    if ((a & 1) == 0) {
      std::memcpy(&out, m.image(), sizeof out);
      uint64_t tick = m.header()->outTick;
      std::atomic_thread_fence(std::memory_order_acquire);
      if (s.load(std::memory_order_relaxed) == a) return tick;
    }
    std::this_thread::yield();
  }
}

void shmWriteMem(ShmMapping &m, uint32_t offset, const void *data, size_t n) {
  if (offset > LJ_MEM_BYTES || n > LJ_MEM_BYTES - offset) return;
  auto s = seq(m.header()->inSeq);
  s.fetch_add(1, std::memory_order_acq_rel); // odd: inputs in flux
  std::atomic_thread_fence(std::memory_order_release);
  std::memcpy(m.mem() + offset, data, n);
  s.fetch_add(1, std::memory_order_release); // even: consistent
}

uint64_t shmReadMem(const ShmMapping &m, uint8_t *out) {
  auto s = seq(m.header()->outSeq);
  for (;;) {
    uint64_t a = s.load(std::memory_order_acquire);
    if ((a & 1) == 0) {
      std::memcpy(out, m.mem(), LJ_MEM_BYTES);
      uint64_t tick = m.header()->outTick;
      std::atomic_thread_fence(std::memory_order_acquire);
      if (s.load(std::memory_order_relaxed) == a) return tick;
    }
    std::this_thread::yield();
  }
}

std::vector<MemSpan> shmInputSpans(const TargetProfile &tp, bool hostOwnsF) {
  std::vector<MemSpan> out;
  const uint32_t mem = static_cast<uint32_t>(offsetof(lj_state, mem));
  for (Area a : {Area::Input, Area::NcStatus}) {
    if (a == Area::NcStatus && !hostOwnsF) continue;
    const AreaInfo &i = tp.area(a);
    if (i.bytes == 0 || i.count <= 0 || i.offset < mem) continue; // HNC-8: in lj_image
    out.push_back({i.offset - mem, static_cast<uint32_t>(i.count + i.upperCount) * i.bytes});
  }
  std::sort(out.begin(), out.end(),
            [](const MemSpan &x, const MemSpan &y) { return x.offset < y.offset; });
  return out;
}

ShmImage::ShmImage(ShmMapping &m, bool hostOwnsF, const TargetProfile *profile)
    : m_(m), hostOwnsF_(hostOwnsF) {
  if (!profile) return;
  inMem_ = shmInputSpans(*profile, hostOwnsF);
  // A profile with areas in the region publishes it, except the host's spans.
  bool usesMem = false;
  for (const AreaInfo &i : profile->areas)
    usesMem = usesMem || (i.bytes && i.offset >= offsetof(lj_state, mem));
  if (!usesMem) return;
  uint32_t at = 0, total = 0;
  for (const MemSpan &sp : inMem_) {
    if (sp.offset > at) outMem_.push_back({at, sp.offset - at});
    at = std::max(at, sp.offset + sp.bytes);
    total += sp.bytes;
  }
  if (at < LJ_MEM_BYTES) outMem_.push_back({at, LJ_MEM_BYTES - at});
  memIn_.assign(total, 0);
}

void ShmImage::beforeTick(lj_state &s, uint64_t) {
  if (!inMem_.empty()) {
    // The same seqlock as X: a torn copy is replaced by the last consistent one.
    auto q = seq(m_.header()->inSeq);
    uint64_t a = q.load(std::memory_order_acquire);
    bool ok = false;
    if ((a & 1) == 0) {
      for (const MemSpan &sp : inMem_)
        std::memcpy(s.mem + sp.offset, m_.mem() + sp.offset, sp.bytes);
      std::atomic_thread_fence(std::memory_order_acquire);
      ok = q.load(std::memory_order_relaxed) == a;
    }
    uint8_t *p = memIn_.data();
    for (const MemSpan &sp : inMem_) {
      if (ok)
        std::memcpy(p, s.mem + sp.offset, sp.bytes);
      else
        std::memcpy(s.mem + sp.offset, p, sp.bytes);
      p += sp.bytes;
    }
  }
  beforeTickImage(s);
}

void ShmImage::beforeTickImage(lj_state &s) {
  auto q = seq(m_.header()->inSeq);
  uint64_t a = q.load(std::memory_order_acquire);
  if ((a & 1) == 0) {
    // Copy into the state, then check: a torn copy is replaced by the last consistent one.
    std::memcpy(s.img.X, m_.image()->X, sizeof s.img.X);
    if (hostOwnsF_) std::memcpy(s.img.F, m_.image()->F, sizeof s.img.F);
    std::atomic_thread_fence(std::memory_order_acquire);
    if (q.load(std::memory_order_relaxed) == a) {
      std::memcpy(x_, s.img.X, sizeof x_);
      if (hostOwnsF_) std::memcpy(f_, s.img.F, sizeof f_);
      return;
    }
  }
  std::memcpy(s.img.X, x_, sizeof x_);
  if (hostOwnsF_) std::memcpy(s.img.F, f_, sizeof f_);
}

void ShmImage::publish(const lj_state &s, uint64_t tick) {
  ShmHeader *h = m_.header();
  lj_image *img = m_.image();
  auto q = seq(h->outSeq);
  q.fetch_add(1, std::memory_order_acq_rel);
  std::atomic_thread_fence(std::memory_order_release);
  std::memcpy(img->D, s.img.D, sizeof img->D);
  std::memcpy(img->B, s.img.B, sizeof img->B);
  std::memcpy(img->P, s.img.P, sizeof img->P);
  if (!hostOwnsF_) std::memcpy(img->F, s.img.F, sizeof img->F);
  std::memcpy(img->G, s.img.G, sizeof img->G);
  std::memcpy(img->W, s.img.W, sizeof img->W);
  std::memcpy(img->Y, s.img.Y, sizeof img->Y);
  std::memcpy(img->R, s.img.R, sizeof img->R);
  for (const MemSpan &sp : outMem_) std::memcpy(m_.mem() + sp.offset, s.mem + sp.offset, sp.bytes);
  h->outTick = tick;
  q.fetch_add(1, std::memory_order_release);
}

} // namespace lj::rt

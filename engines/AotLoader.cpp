// The AOT loader: read the file once, verify its signed trailer (a trusted signer, identity, ABI)
// and the ELF headers on those bytes, then dlopen exactly those bytes from a sealed memfd. No
// byte of an unsigned or modified file is ever mapped executable (docs/aot.md "Trust").
#include "engines/AotLoader.h"

#include "ladderjit/program.h"
#include "signing/AotSigned.h"

#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <dlfcn.h>
#include <elf.h>
#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

#ifndef MFD_EXEC
#define MFD_EXEC 0x0010U /* Linux 6.3: executable memfd even under vm.memfd_noexec=1 */
#endif

namespace lj::engines {

namespace {

/// Refuse files above this size before reading them (a 10,000-statement program is ~1 MiB).
constexpr uint64_t kMaxSize = uint64_t{256} << 20;

/// The loaded object and the memfd it was mapped from. The descriptor stays open while the
/// object is loaded so its /proc/self/fd name cannot be reused for another load meanwhile.
class AotEngine final : public Engine {
public:
  AotEngine(void *handle, int fd, const lj_entries &e) : handle_(handle), fd_(fd), entries_(e) {}
  ~AotEngine() override {
    dlclose(handle_);
    if (fd_ >= 0) close(fd_);
  }
  const lj_entries &entries() const override { return entries_; }
  const char *name() const override { return "aot"; }

private:
  void *handle_;
  int fd_;
  lj_entries entries_;
};

/// Closes a descriptor on every return path.
struct Fd {
  int fd = -1;
  ~Fd() {
    if (fd >= 0) close(fd);
  }
};

bool readAll(int fd, uint64_t size, std::string &out) {
  out.resize(size);
  uint64_t got = 0;
  while (got < size) {
    ssize_t n = pread(fd, out.data() + got, size - got, static_cast<off_t>(got));
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    got += static_cast<uint64_t>(n);
  }
  return true;
}

#if defined(__x86_64__)
constexpr uint16_t kMachine = EM_X86_64;
#elif defined(__aarch64__)
constexpr uint16_t kMachine = EM_AARCH64;
#else
constexpr uint16_t kMachine = 0; // unknown host: the header machine is not checked
#endif

/// The checks dlopen would otherwise do on untrusted bytes: every table inside the image.
std::string checkElf(std::string_view img) {
  if (img.size() < sizeof(Elf64_Ehdr) || std::memcmp(img.data(), ELFMAG, SELFMAG) != 0)
    return "not an ELF file";
  Elf64_Ehdr eh;
  std::memcpy(&eh, img.data(), sizeof eh);
  if (eh.e_ident[EI_CLASS] != ELFCLASS64 || eh.e_ident[EI_DATA] != ELFDATA2LSB)
    return "not a 64-bit little-endian ELF file";
  if (eh.e_type != ET_DYN) return "not an ELF shared object";
  if (kMachine != 0 && eh.e_machine != kMachine)
    return "built for another machine (ELF machine " + std::to_string(eh.e_machine) + ")";
  auto inside = [&](uint64_t off, uint64_t count, uint64_t entsize) {
    return off <= img.size() && count <= (img.size() - off) / (entsize ? entsize : 1);
  };
  if (eh.e_phentsize != sizeof(Elf64_Phdr) || eh.e_phnum == 0 ||
      !inside(eh.e_phoff, eh.e_phnum, sizeof(Elf64_Phdr)))
    return "bad ELF program header table";
  for (uint16_t i = 0; i < eh.e_phnum; ++i) {
    Elf64_Phdr ph;
    std::memcpy(&ph, img.data() + eh.e_phoff + i * sizeof ph, sizeof ph);
    if (ph.p_type == PT_LOAD &&
        (ph.p_offset > img.size() || ph.p_filesz > img.size() - ph.p_offset))
      return "ELF segment outside the file (truncated?)";
  }
  if (eh.e_shnum != 0 &&
      (eh.e_shentsize != sizeof(Elf64_Shdr) || !inside(eh.e_shoff, eh.e_shnum, sizeof(Elf64_Shdr))))
    return "bad ELF section header table (truncated?)";
  return {};
}

bool writeAll(int fd, std::string_view bytes) {
  size_t done = 0;
  while (done < bytes.size()) {
    ssize_t n = write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<size_t>(n);
  }
  return true;
}

/// dlopen the verified bytes from a sealed memfd (nobody can change them after the check, and
/// the file at `path` is never opened by the dynamic loader). glibc hands back an already loaded
/// object whose name matches, so a /proc/self/fd/N name still in use by a loaded object is
/// skipped by moving the descriptor. `fd` receives the descriptor to keep open while loaded.
void *openSealed(std::string_view bytes, int &fd, std::string &why) {
  fd = memfd_create("ladderjit-aot", MFD_CLOEXEC | MFD_ALLOW_SEALING | MFD_EXEC);
  if (fd < 0 && errno == EINVAL)
    fd = memfd_create("ladderjit-aot", MFD_CLOEXEC | MFD_ALLOW_SEALING);
  if (fd < 0) {
    why = std::string("memfd_create failed: ") + std::strerror(errno);
    return nullptr;
  }
  if (!writeAll(fd, bytes) ||
      fcntl(fd, F_ADD_SEALS, F_SEAL_SHRINK | F_SEAL_GROW | F_SEAL_WRITE | F_SEAL_SEAL) != 0) {
    why = std::string("cannot prepare the verified copy: ") + std::strerror(errno);
    close(fd);
    fd = -1;
    return nullptr;
  }
  std::string name;
  for (int tries = 0;; ++tries) {
    name = "/proc/self/fd/" + std::to_string(fd);
    void *old = dlopen(name.c_str(), RTLD_LAZY | RTLD_NOLOAD | RTLD_LOCAL);
    if (!old) break;
    dlclose(old);
    int moved = tries < 64 ? fcntl(fd, F_DUPFD_CLOEXEC, fd + 1) : -1;
    close(fd);
    fd = moved;
    if (fd < 0) {
      why = "no free descriptor name for the verified copy";
      return nullptr;
    }
  }
  void *handle = dlopen(name.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    const char *e = dlerror();
    why = std::string("dlopen failed: ") + (e ? e : "unknown error");
    close(fd);
    fd = -1;
  }
  return handle;
}

template <typename Fn> Fn symbol(void *handle, const char *name, std::string &missing) {
  void *p = dlsym(handle, name);
  if (!p && missing.empty()) missing = name;
  return reinterpret_cast<Fn>(p);
}

} // namespace

std::string sourceHash(std::string_view stl, const formats::DitFile *dit) {
  if (dit) return dit->hash;
  std::string canon = "ladderjit-source 1\n[program]\n";
  for (size_t i = 0; i < stl.size(); ++i) {
    if (stl[i] == '\r' && i + 1 < stl.size() && stl[i + 1] == '\n') continue;
    canon += stl[i];
  }
  if (!stl.empty() && canon.back() != '\n') canon += '\n';
  return formats::sha256Hash(canon);
}

AotExpect aotExpectOf(const pipeline::ProgramSource &src, int32_t plc2Nvalue) {
  const formats::DitFile *dit = src.dit ? &*src.dit : nullptr;
  return {pipeline::programHash(src.text, dit, plc2Nvalue), sourceHash(src.text, dit), plc2Nvalue};
}

std::unique_ptr<Engine> loadAot(const std::string &path, const AotExpect &expect,
                                const signing::TrustedKeys &trust, std::string &error) {
  auto fail = [&](const std::string &why) -> std::unique_ptr<Engine> {
    error = "'" + path + "': " + why;
    return nullptr;
  };
  // O_NONBLOCK: opening a FIFO must not wait for a writer (it is refused as not regular).
  Fd f;
  f.fd = open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY);
  if (f.fd < 0) return fail(std::string("cannot open: ") + std::strerror(errno));
  struct stat st {};
  if (fstat(f.fd, &st) != 0 || !S_ISREG(st.st_mode)) return fail("not a regular file");
  if (static_cast<uint64_t>(st.st_size) > kMaxSize)
    return fail("too large for a program (" + std::to_string(st.st_size) + " bytes, at most " +
                std::to_string(kMaxSize) + ")");
  std::string bytes;
  if (!readAll(f.fd, static_cast<uint64_t>(st.st_size), bytes)) return fail("cannot read");
  signing::AotMeta meta;
  if (std::string why = signing::verifySigned(bytes, trust, meta); !why.empty()) return fail(why);
  // From here on the trailer is the signer's word: identity and ABI come from it.
  if (meta.abi != LJPROG_ABI_VERSION)
    return fail("program ABI version " + std::to_string(meta.abi) + ", this ladderjit loads " +
                std::to_string(LJPROG_ABI_VERSION) + " (rebuild it with `ladderjit compile`)");
  if (meta.stateSize != sizeof(lj_state))
    return fail("built for a state of " + std::to_string(meta.stateSize) +
                " bytes, this ladderjit has " + std::to_string(sizeof(lj_state)));
  if (meta.program != expect.program) {
    if (!expect.source.empty() && meta.source == expect.source && expect.plc2Nvalue >= 0 &&
        meta.plc2Nvalue != expect.plc2Nvalue)
      return fail("built from this program with plc2 nvalue " + std::to_string(meta.plc2Nvalue) +
                  ", but plc2 nvalue " + std::to_string(expect.plc2Nvalue) +
                  " was asked for; rebuild it with `ladderjit compile --plc2-nvalue " +
                  std::to_string(expect.plc2Nvalue) + "` or give --plc2-nvalue " +
                  std::to_string(meta.plc2Nvalue));
    return fail("built from another program (its hash " + meta.program + ", the program's " +
                expect.program + "); rebuild it with `ladderjit compile`");
  }
  if (meta.slices == 0) return fail("inconsistent entry table");
  std::string_view image(bytes.data(), meta.imageSize);
  if (std::string why = checkElf(image); !why.empty()) return fail(why);

  int fd = -1;
  std::string why;
  void *handle = openSealed(bytes, fd, why);
  if (!handle) return fail(why);
  std::string missing;
  auto entriesFn = symbol<ljprog_entries_fn>(handle, "ljprog_entries", missing);
  for (const char *name : {"ljprog_abi_version", "ljprog_hash", "ljprog_slice_count",
                           "ljprog_state_size", "ljprog_state_reset", "ljprog_init", "ljprog_tick"})
    symbol<void *>(handle, name, missing);
  auto closeAndFail = [&](const std::string &reason) {
    dlclose(handle);
    close(fd);
    return fail(reason);
  };
  if (!missing.empty())
    return closeAndFail("not a ladderjit program: symbol '" + missing + "' missing");
  lj_entries e{};
  entriesFn(&e);
  if (!e.init || !e.plc1 || !e.plc2_slice || e.plc2_slice_count != meta.slices)
    return closeAndFail("inconsistent entry table");
  return std::make_unique<AotEngine>(handle, fd, e);
}

} // namespace lj::engines

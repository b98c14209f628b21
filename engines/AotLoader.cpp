// The AOT loader: read the file once, verify the integrity trailer and the ELF headers, then
// dlopen a private copy of exactly those bytes. A damaged file never reaches the dynamic
// loader, which may crash on bad ELF.
#include "engines/AotLoader.h"

#include "formats/PlcDit.h" // sha256Hash

#include "ladderjit/program.h"

#include <atomic>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <dlfcn.h>
#include <elf.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace lj::io {

namespace {

/// Refuse files above this size before reading them (a 10,000-statement program is ~1 MiB).
constexpr uint64_t kMaxSize = uint64_t{1} << 30;

class AotEngine final : public Engine {
public:
  AotEngine(void *handle, const lj_entries &e) : handle_(handle), entries_(e) {}
  ~AotEngine() override { dlclose(handle_); }
  const lj_entries &entries() const override { return entries_; }
  const char *name() const override { return "aot"; }

private:
  void *handle_;
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

/// The trailer `ladderjit compile` appends (program.h): SHA-256 over everything before it.
std::string checkTrailer(std::string_view file) {
  constexpr size_t kMagicLen = sizeof(LJPROG_TRAILER_MAGIC) - 1;
  if (file.size() < LJPROG_TRAILER_SIZE) return "too short to be a ladderjit program (truncated?)";
  std::string_view tr = file.substr(file.size() - LJPROG_TRAILER_SIZE);
  if (tr.substr(0, kMagicLen) != LJPROG_TRAILER_MAGIC || tr.back() != '\n')
    return "no ladderjit integrity trailer at the end (truncated, or not built by "
           "`ladderjit compile`)";
  std::string want = "sha256:" + std::string(tr.substr(kMagicLen, 64));
  std::string got = sha256Hash(file.substr(0, file.size() - LJPROG_TRAILER_SIZE));
  if (got != want) return "damaged: its content does not match its integrity checksum";
  return {};
}

/// dlopen the checked bytes from a private copy under a name never used before in this
/// process, then unlink it. Loading `path` itself could load other bytes than were checked (the
/// file may be replaced meanwhile), and glibc returns an already loaded object whose name
/// matches, so a reused name (a rebuilt .so at the same path, a reused /proc/self/fd/N) would
/// hand back the previous program. Null when the copy cannot be made or loaded.
void *openVerifiedCopy(const std::string &bytes) {
  static std::atomic<uint64_t> serial{0};
  const char *base = std::getenv("TMPDIR");
  std::string name = std::string(base && *base ? base : "/tmp") + "/ladderjit-aot-" +
                     std::to_string(getpid()) + "-" + std::to_string(serial++) + "-XXXXXX";
  std::vector<char> buf(name.begin(), name.end());
  buf.push_back('\0');
  Fd copy;
  copy.fd = mkostemp(buf.data(), O_CLOEXEC);
  if (copy.fd < 0) return nullptr;
  size_t done = 0;
  while (done < bytes.size()) {
    ssize_t n = write(copy.fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    done += static_cast<size_t>(n);
  }
  void *handle = done == bytes.size() ? dlopen(buf.data(), RTLD_NOW | RTLD_LOCAL) : nullptr;
  unlink(buf.data());
  return handle;
}

template <typename Fn> Fn symbol(void *handle, const char *name, std::string &missing) {
  void *p = dlsym(handle, name);
  if (!p && missing.empty()) missing = name;
  return reinterpret_cast<Fn>(p);
}

} // namespace

std::unique_ptr<Engine> loadAot(const std::string &path, const std::string &expectedHash,
                                std::string &error) {
  auto fail = [&](const std::string &why) -> std::unique_ptr<Engine> {
    error = "'" + path + "': " + why;
    return nullptr;
  };
  Fd f;
  f.fd = open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (f.fd < 0) return fail(std::string("cannot open: ") + std::strerror(errno));
  struct stat st {};
  if (fstat(f.fd, &st) != 0 || !S_ISREG(st.st_mode)) return fail("not a regular file");
  if (static_cast<uint64_t>(st.st_size) > kMaxSize) return fail("too large for a program");
  std::string bytes;
  if (!readAll(f.fd, static_cast<uint64_t>(st.st_size), bytes)) return fail("cannot read");
  if (std::string why = checkTrailer(bytes); !why.empty()) return fail(why);
  std::string_view image(bytes.data(), bytes.size() - LJPROG_TRAILER_SIZE);
  if (std::string why = checkElf(image); !why.empty()) return fail(why);

  void *handle = openVerifiedCopy(bytes);
  if (!handle) handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL); // e.g. a noexec TMPDIR
  if (!handle) {
    const char *why = dlerror();
    return fail(std::string("dlopen failed: ") + (why ? why : "unknown error"));
  }
  std::string missing;
  auto abiVersion = symbol<ljprog_u32_fn>(handle, "ljprog_abi_version", missing);
  auto hash = symbol<ljprog_hash_fn>(handle, "ljprog_hash", missing);
  auto slices = symbol<ljprog_u32_fn>(handle, "ljprog_slice_count", missing);
  auto stateSize = symbol<ljprog_size_fn>(handle, "ljprog_state_size", missing);
  auto entriesFn = symbol<ljprog_entries_fn>(handle, "ljprog_entries", missing);
  for (const char *name : {"ljprog_state_reset", "ljprog_init", "ljprog_tick"})
    symbol<void *>(handle, name, missing);
  auto closeAndFail = [&](const std::string &why) {
    dlclose(handle);
    return fail(why);
  };
  if (!missing.empty())
    return closeAndFail("not a ladderjit program: symbol '" + missing + "' missing");
  if (uint32_t v = abiVersion(); v != LJPROG_ABI_VERSION)
    return closeAndFail("program ABI version " + std::to_string(v) + ", this ladderjit loads " +
                        std::to_string(LJPROG_ABI_VERSION) +
                        " (rebuild it with `ladderjit compile`)");
  if (size_t n = stateSize(); n != sizeof(lj_state))
    return closeAndFail("built for a state of " + std::to_string(n) +
                        " bytes, this ladderjit has " + std::to_string(sizeof(lj_state)));
  const char *h = hash();
  std::string have = h ? std::string(h, strnlen(h, LJPROG_HASH_LEN + 1)) : std::string();
  if (have != expectedHash)
    return closeAndFail("built from another program (its hash " + have + ", the program's " +
                        expectedHash + "); rebuild it with `ladderjit compile`");
  lj_entries e{};
  entriesFn(&e);
  if (!e.init || !e.plc1 || !e.plc2_slice || e.plc2_slice_count == 0 ||
      e.plc2_slice_count != slices())
    return closeAndFail("inconsistent entry table");
  return std::make_unique<AotEngine>(handle, e);
}

} // namespace lj::io

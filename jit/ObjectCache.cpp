// Object cache: key derivation, the in-memory map and the disk format. A disk entry is
//   "LJOBJC1\n", key (64 hex) "\n", u32 count, per object u64 size + bytes, SHA-256 of all that
// and is read back only if every length fits, the key matches and the checksum is right.
#include "jit/ObjectCache.h"

#include "ir/Profile.h"

#include <llvm/ADT/ArrayRef.h>
#include <llvm/Config/llvm-config.h>
#include <llvm/Support/SHA256.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <dlfcn.h>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <sys/stat.h>
#include <unistd.h>

#ifndef LADDERJIT_VERSION
#define LADDERJIT_VERSION "unknown"
#endif

namespace lj::jit {

namespace {

namespace fs = std::filesystem;

constexpr std::string_view kMagic = "LJOBJC1\n";
constexpr size_t kMemoryLimit = size_t{64} << 20; ///< in-memory bytes before evicting the oldest

// A new field in these types must be added to programDigest (else two programs differing only
// in it would share cached code). The sizes are the reminder. (Operand::symbol and Stmt::id
// name what was written; they do not change the code.)
static_assert(sizeof(Operand) == 24 && sizeof(Stmt) == 232 && sizeof(StmtInfo) == 20 &&
                  sizeof(Subroutine) == 16 && sizeof(StmtRange) == 8,
              "program model changed: update programDigest()");

std::string hex(llvm::ArrayRef<uint8_t> bytes) {
  static const char *kHex = "0123456789abcdef";
  std::string out;
  for (uint8_t b : bytes) {
    out += kHex[b >> 4];
    out += kHex[b & 15];
  }
  return out;
}

llvm::ArrayRef<uint8_t> asBytes(std::string_view s) {
  return {reinterpret_cast<const uint8_t *>(s.data()), s.size()};
}

std::string sha256Hex(std::string_view s) { return hex(llvm::SHA256::hash(asBytes(s))); }

/// Little-endian fixed-width integers, so the serialization is unambiguous.
template <typename T> void put(std::string &out, T v) {
  auto u = static_cast<uint64_t>(static_cast<std::make_unsigned_t<T>>(v));
  for (size_t i = 0; i < sizeof(T); ++i) out += static_cast<char>((u >> (8 * i)) & 0xff);
}
void putStr(std::string &out, std::string_view s) {
  put<uint64_t>(out, s.size());
  out.append(s);
}
void putRange(std::string &out, const StmtRange &r) {
  put(out, r.begin);
  put(out, r.end);
}

std::string fileIdentity(const char *path) {
  struct stat st {};
  if (stat(path, &st) != 0) return "unknown";
  return std::to_string(st.st_dev) + ":" + std::to_string(st.st_ino) + ":" +
         std::to_string(st.st_size) + ":" + std::to_string(st.st_mtim.tv_sec) + "." +
         std::to_string(st.st_mtim.tv_nsec);
}

/// Identity of this build of ladderjit: inode, size and mtime of the running executable and of
/// the file this code is in, when that is another one (the LLVM module libladderjit_llvm.so,
/// engines/LlvmBackend.h, is rebuilt without the driver when only jit/ or lowering/ change).
const std::string &buildIdentity() {
  static const std::string id = [] {
    std::string s = "exe:" + fileIdentity("/proc/self/exe");
    Dl_info info{};
    if (dladdr(reinterpret_cast<void *>(&fileIdentity), &info) != 0 && info.dli_fname &&
        *info.dli_fname)
      s += " code:" + fileIdentity(info.dli_fname);
    return s;
  }();
  return id;
}

/// Cached objects are code this process will run: only a directory and entries of this user
/// that nobody else can write are used (else another user could plant an entry).
bool privateToUser(const struct stat &st) {
  return st.st_uid == geteuid() && (st.st_mode & 022) == 0;
}

bool privateDir(const std::string &dir) {
  struct stat st {};
  return stat(dir.c_str(), &st) == 0 && S_ISDIR(st.st_mode) && privateToUser(st);
}

enum class Entry { Missing, Refused, Read };

/// Read an entry: a regular file (no symlink) of this user, not writable by others, in a
/// private directory.
Entry readEntry(const std::string &dir, const std::string &path, std::string &out) {
  int fd = open(path.c_str(), O_RDONLY | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK);
  if (fd < 0) return errno == ENOENT ? Entry::Missing : Entry::Refused;
  struct stat st {};
  bool ok = fstat(fd, &st) == 0 && S_ISREG(st.st_mode) && privateToUser(st) &&
            st.st_size <= (off_t{1} << 30) && privateDir(dir);
  if (ok) {
    out.resize(static_cast<size_t>(st.st_size));
    size_t got = 0;
    while (got < out.size()) {
      ssize_t n = read(fd, out.data() + got, out.size() - got);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) break;
      got += static_cast<size_t>(n);
    }
    ok = got == out.size();
  }
  close(fd);
  return ok ? Entry::Read : Entry::Refused;
}

/// Parse a disk entry; false unless it is complete, intact and for `key`.
bool decode(std::string_view f, const std::string &key, std::vector<std::string> &objects) {
  constexpr size_t kSum = 32;
  if (f.size() < kMagic.size() + 65 + 4 + kSum) return false;
  std::string_view body = f.substr(0, f.size() - kSum);
  if (hex(asBytes(f.substr(body.size()))) != sha256Hex(body)) return false;
  if (body.substr(0, kMagic.size()) != kMagic) return false;
  if (body.substr(kMagic.size(), 64) != key || body[kMagic.size() + 64] != '\n') return false;
  size_t pos = kMagic.size() + 65;
  auto get = [&](size_t n, uint64_t &v) {
    if (body.size() - pos < n) return false;
    v = 0;
    for (size_t i = 0; i < n; ++i) v |= uint64_t{static_cast<uint8_t>(body[pos + i])} << (8 * i);
    pos += n;
    return true;
  };
  uint64_t count = 0;
  if (!get(4, count) || count == 0 || count > 64) return false;
  objects.clear();
  for (uint64_t i = 0; i < count; ++i) {
    uint64_t size = 0;
    if (!get(8, size) || size > body.size() - pos) return false;
    objects.emplace_back(body.substr(pos, size));
    pos += size;
  }
  return pos == body.size();
}

} // namespace

std::string programDigest(const VerifiedProgram &p) {
  std::string s;
  s.reserve(p.stmts.size() * 160);
  putStr(s, p.profile ? p.profile->name : ""); // the same statements lay out differently per target
  put<uint64_t>(s, p.stmts.size());
  for (const Stmt &st : p.stmts) {
    put(s, static_cast<uint8_t>(st.op));
    put(s, st.operandCount);
    put(s, st.loc.line);
    put(s, st.loc.col);
    for (const Operand &o : st.ops) {
      put(s, static_cast<uint8_t>(o.kind));
      put(s, static_cast<uint8_t>(o.area));
      put(s, o.width);
      put(s, static_cast<uint8_t>(o.bcd));
      put(s, o.index);
      put(s, o.bit);
      put(s, o.value);
      put(s, o.loc.line);
      put(s, o.loc.col);
    }
  }
  put<uint64_t>(s, p.info.size());
  for (const StmtInfo &i : p.info) {
    put(s, i.depth);
    put(s, i.msDepth);
    put(s, i.target);
    put(s, i.slot);
    put(s, static_cast<uint8_t>(i.hasInput));
    put(s, static_cast<uint8_t>(i.backward));
  }
  putRange(s, p.init);
  putRange(s, p.plc1);
  putRange(s, p.plc2);
  put<uint64_t>(s, p.subs.size());
  for (const Subroutine &sub : p.subs) {
    put(s, sub.number);
    put(s, sub.spIndex);
    putRange(s, sub.body);
  }
  for (int16_t v : p.subByNumber) put(s, v);
  put<uint64_t>(s, p.slices.size());
  for (const StmtRange &r : p.slices) putRange(s, r);
  put<uint64_t>(s, p.sliceDepth.size());
  for (int32_t d : p.sliceDepth) put(s, d);
  put(s, p.edgeSlots);
  put(s, p.wordSlots);
  put(s, p.plc2Nvalue);
  put(s, p.maxDepth);
  put(s, p.maxMsDepth);
  return sha256Hex(s);
}

/// What every cache key starts with: its kind, the build and the target the code is for.
static void putTargetIdentity(std::string &s, std::string_view kind, const CacheKeyInputs &in) {
  putStr(s, kind);
  putStr(s, LADDERJIT_VERSION);
  putStr(s, buildIdentity());
  putStr(s, LLVM_VERSION_STRING);
  putStr(s, in.triple);
  putStr(s, in.cpu);
  putStr(s, in.features);
  put(s, in.tier);
  put(s, in.chunkStatements);
}

std::string objectCacheKey(const VerifiedProgram &prog, const CacheKeyInputs &in) {
  std::string s;
  putTargetIdentity(s, "ladderjit-object-cache 1", in);
  put(s, in.partitions);
  // Forces by statement position (ids are not in the digest): the code a force makes.
  const std::vector<int8_t> forced = forceTable(prog, in.forces);
  put<uint64_t>(s, forced.size());
  for (int8_t v : forced) put(s, v);
  putStr(s, programDigest(prog));
  return sha256Hex(s);
}

std::string leafCacheKey(const CacheKeyInputs &in, std::string_view profile,
                         std::string_view leafBytes) {
  std::string s;
  putTargetIdentity(s, "ladderjit-leaf-cache 1", in);
  putStr(s, profile);
  putStr(s, leafBytes);
  return sha256Hex(s);
}

std::string spineCacheKey(const CacheKeyInputs &in, std::string_view bitcode) {
  std::string s;
  putTargetIdentity(s, "ladderjit-spine-cache 1", in);
  putStr(s, bitcode);
  return sha256Hex(s);
}

ObjectCache::ObjectCache(std::string dir) : dir_(std::move(dir)) {}

std::shared_ptr<ObjectCache> ObjectCache::fromEnvironment() {
  auto env = [](const char *name) -> std::string {
    const char *v = std::getenv(name);
    return v ? v : "";
  };
  std::string mode = env("LADDERJIT_CACHE");
  if (mode == "off" || mode == "0") return nullptr;
  std::string dir = env("LADDERJIT_CACHE_DIR");
  if (dir.empty() && !env("XDG_CACHE_HOME").empty()) dir = env("XDG_CACHE_HOME") + "/ladderjit";
  if (dir.empty() && !env("HOME").empty()) dir = env("HOME") + "/.cache/ladderjit";
  return std::make_shared<ObjectCache>(dir);
}

std::string ObjectCache::pathFor(const std::string &key) const {
  return dir_.empty() ? std::string() : dir_ + "/" + key + ".ljo";
}

bool ObjectCache::lookup(const std::string &key, std::vector<std::string> &objects) {
  {
    std::lock_guard<std::mutex> lock(mu_);
    if (auto it = memory_.find(key); it != memory_.end()) {
      objects = it->second;
      ++stats_.hits;
      ++stats_.memoryHits;
      return true;
    }
  }
  std::string file;
  Entry entry = dir_.empty() ? Entry::Missing : readEntry(dir_, pathFor(key), file);
  bool found = entry != Entry::Missing;
  bool ok = entry == Entry::Read && decode(file, key, objects);
  std::lock_guard<std::mutex> lock(mu_);
  if (found && !ok) ++stats_.rejected;
  if (!ok) {
    ++stats_.misses;
    return false;
  }
  ++stats_.hits;
  ++stats_.diskHits;
  return true;
}

void ObjectCache::store(const std::string &key, const std::vector<std::string_view> &objects) {
  std::vector<std::string> copy(objects.begin(), objects.end());
  size_t bytes = 0;
  for (const std::string &o : copy) bytes += o.size();
  std::string file;
  if (!dir_.empty()) {
    file.append(kMagic);
    file += key + "\n";
    put<uint32_t>(file, static_cast<uint32_t>(copy.size()));
    for (const std::string &o : copy) {
      put<uint64_t>(file, o.size());
      file += o;
    }
    auto sum = llvm::SHA256::hash(asBytes(file));
    file.append(reinterpret_cast<const char *>(sum.data()), sum.size());
  }
  bool written = true;
  if (!dir_.empty()) {
    // Best effort: a read-only or full disk only costs the next compile. Temp + rename so a
    // concurrent reader sees the old file or the new one, never a partial one.
    std::error_code ec;
    // Objects are code this process will run: a directory we create is private to the user.
    if (fs::create_directories(dir_, ec))
      fs::permissions(dir_, fs::perms::owner_all, fs::perm_options::replace, ec);
    written = privateDir(dir_); // never feed a directory others can write
    std::string tmp = dir_ + "/." + key + "." + std::to_string(getpid()) + "." +
                      std::to_string(std::random_device{}()) + ".tmp";
    if (written) {
      std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
      written =
          out && out.write(file.data(), static_cast<std::streamsize>(file.size())) && out.flush();
      fs::permissions(tmp, fs::perms::owner_read | fs::perms::owner_write,
                      fs::perm_options::replace, ec); // whatever the umask
    }
    if (!written || std::rename(tmp.c_str(), pathFor(key).c_str()) != 0) {
      written = false;
      fs::remove(tmp, ec);
    }
  }
  std::lock_guard<std::mutex> lock(mu_);
  ++stats_.stores;
  if (!written) ++stats_.writeErrors;
  if (bytes > kMemoryLimit || memory_.count(key)) return;
  while (memoryBytes_ + bytes > kMemoryLimit && !order_.empty()) {
    auto it = memory_.find(order_.front());
    for (const std::string &o : it->second) memoryBytes_ -= o.size();
    memory_.erase(it);
    order_.erase(order_.begin());
  }
  memory_.emplace(key, std::move(copy));
  order_.push_back(key);
  memoryBytes_ += bytes;
}

ObjectCache::Stats ObjectCache::stats() const {
  std::lock_guard<std::mutex> lock(mu_);
  return stats_;
}

void ObjectCache::dropMemory() {
  std::lock_guard<std::mutex> lock(mu_);
  memory_.clear();
  order_.clear();
  memoryBytes_ = 0;
}

} // namespace lj::jit

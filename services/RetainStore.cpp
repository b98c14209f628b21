// The retentive store: end-of-tick capture (triple buffer), the background writer (temp file,
// fsync, rename, directory fsync, FILE.prev rotation), group commit and restore with fallback.
// The bytes of the two file formats are RetainFormat.h's.
#include "services/RetainStore.h"
#include "services/RetainFormat.h"

#include "formats/PlcDit.h"
#include "profiles/Profiles.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <fcntl.h>
#include <filesystem>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

namespace lj::services {
namespace {

constexpr int kFresh = 4; // middle_ flag: the middle slot holds a capture the writer has not seen
// Writer poll interval: flags set on the scan thread (which never notifies) are seen this late.
constexpr auto kPoll = std::chrono::milliseconds(2);

std::string errnoText(const char *what, const std::string &path) {
  return std::string(what) + " " + path + ": " + std::strerror(errno);
}

bool writeAll(int fd, const unsigned char *p, size_t n) {
  while (n > 0) {
    ssize_t w = ::write(fd, p, n);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) return false;
    p += w;
    n -= static_cast<size_t>(w);
  }
  return true;
}

/// Move the damaged store file `path` aside to `path.damaged-YYYYMMDDTHHMMSSZ` (a numeric suffix
/// when that name is taken) so no save ever overwrites it. link + unlink, not rename: an existing
/// file of that name is never replaced. False (with `error`) when it cannot be moved.
bool moveAside(const std::string &path, std::string &moved, std::string &error) {
  char stamp[32];
  std::time_t t = std::time(nullptr);
  std::tm tm{};
  gmtime_r(&t, &tm);
  std::strftime(stamp, sizeof stamp, "%Y%m%dT%H%M%SZ", &tm);
  const std::string base = path + ".damaged-" + stamp;
  for (int n = 1; n < 1000; ++n) {
    moved = n == 1 ? base : base + "-" + std::to_string(n);
    if (::link(path.c_str(), moved.c_str()) == 0) {
      if (::unlink(path.c_str()) != 0) {
        error = std::string("cannot remove ") + path + " after keeping it as " + moved + ": " +
                std::strerror(errno);
        return false;
      }
      return true;
    }
    if (errno != EEXIST) {
      error = std::string("cannot keep ") + path + " as " + moved + ": " + std::strerror(errno);
      return false;
    }
  }
  error = "cannot keep " + path + ": too many " + base + "* files";
  return false;
}

std::string dirOf(const std::string &path) {
  size_t slash = path.rfind('/');
  if (slash == std::string::npos) return ".";
  return slash == 0 ? "/" : path.substr(0, slash);
}

const TargetProfile &profileForHnc8() { return *profileNamed("hnc8"); }

} // namespace

uint32_t RetainLayout::payloadBytes() const {
  uint32_t n = 0;
  for (const RetainSpan &sp : spans) n += sp.bytes;
  return n;
}

RetainLayout retainLayoutOf(const TargetProfile &tp) {
  RetainLayout l;
  l.profile = tp.name;
  std::vector<RetainSpan> spans;
  uint32_t timerOffset = 0, timerBytes = 0;
  for (int i = 0; i < kAreaCount; ++i) {
    const Area a = static_cast<Area>(i);
    const AreaInfo &info = tp.area(a);
    if (!(tp.retentiveAreas & bit(a)) || info.bytes == 0 || info.count <= 0) continue;
    // Both ranges of the area: the upper one is laid right after the first (elementOffset).
    const uint32_t n = static_cast<uint32_t>(info.count + info.upperCount);
    spans.push_back({info.offset, n * info.bytes});
  }
  auto tcSpan = [&](Area a, NumberRange r, uint32_t base, uint32_t size) -> RetainSpan {
    if (r.hi < r.lo) return {};
    int first = tp.tcSlot(a, r.lo), last = tp.tcSlot(a, r.hi);
    if (first < 0 || last < first) return {};
    return {base + static_cast<uint32_t>(first) * size,
            static_cast<uint32_t>(last - first + 1) * size};
  };
  RetainSpan t = tcSpan(Area::Timer, tp.retentiveTimers,
                        static_cast<uint32_t>(offsetof(lj_state, T)), sizeof(lj_timer));
  if (t.bytes) {
    spans.push_back(t);
    timerOffset = t.offset;
    timerBytes = t.bytes;
  }
  RetainSpan c = tcSpan(Area::Counter, tp.retentiveCounters,
                        static_cast<uint32_t>(offsetof(lj_state, C)), sizeof(lj_counter));
  if (c.bytes) spans.push_back(c);
  std::sort(spans.begin(), spans.end(),
            [](const RetainSpan &x, const RetainSpan &y) { return x.offset < y.offset; });
  for (const RetainSpan &sp : spans) {
    // Merge adjacent ranges, but never into the timer span (its slots are rebased on restore).
    bool isTimer = timerBytes && sp.offset == timerOffset;
    bool prevTimer = !l.spans.empty() && l.timerSpan == static_cast<int>(l.spans.size()) - 1;
    if (!l.spans.empty() && !isTimer && !prevTimer &&
        l.spans.back().offset + l.spans.back().bytes == sp.offset) {
      l.spans.back().bytes += sp.bytes;
      continue;
    }
    if (isTimer) l.timerSpan = static_cast<int>(l.spans.size());
    l.spans.push_back(sp);
  }
  // HNC-8 keeps the file format it always had: B, T300..T427, C300..C427.
  const RetainSpan b{static_cast<uint32_t>(offsetof(lj_state, img.B)),
                     sizeof(int32_t) * LJ_B_COUNT};
  const RetainSpan ht{
      static_cast<uint32_t>(offsetof(lj_state, T) + sizeof(lj_timer) * kRetainedTcFirstSlot),
      sizeof(lj_timer) * kRetainedTcCount};
  const RetainSpan hc{
      static_cast<uint32_t>(offsetof(lj_state, C) + sizeof(lj_counter) * kRetainedTcFirstSlot),
      sizeof(lj_counter) * kRetainedTcCount};
  l.format1 = l.profile == "hnc8" && l.spans == std::vector<RetainSpan>{b, ht, hc};
  return l;
}

void copyRetained(const RetainLayout &layout, const lj_state &from, lj_state &to) {
  const auto *src = reinterpret_cast<const unsigned char *>(&from);
  auto *dst = reinterpret_cast<unsigned char *>(&to);
  for (const RetainSpan &sp : layout.spans) std::memcpy(dst + sp.offset, src + sp.offset, sp.bytes);
}

RetainStore::RetainStore(RetainConfig config)
    : cfg_(std::move(config)),
      layout_(retainLayoutOf(cfg_.profile ? *cfg_.profile : profileForHnc8())) {
  // Every buffer the scan thread fills is sized here, so afterTick never allocates.
  for (RetainImage &img : slots_) img.bytes.assign(layout_.payloadBytes(), 0);
  last_.bytes.assign(layout_.payloadBytes(), 0);
}

bool RetainStore::sameAs(const RetainImage &img, const lj_state &s) const {
  const auto *src = reinterpret_cast<const unsigned char *>(&s);
  const unsigned char *p = img.bytes.data();
  for (const RetainSpan &sp : layout_.spans) {
    if (std::memcmp(p, src + sp.offset, sp.bytes) != 0) return false;
    p += sp.bytes;
  }
  return true;
}

void RetainStore::capture(RetainImage &img, const lj_state &s) const {
  const auto *src = reinterpret_cast<const unsigned char *>(&s);
  unsigned char *p = img.bytes.data();
  for (const RetainSpan &sp : layout_.spans) {
    std::memcpy(p, src + sp.offset, sp.bytes);
    p += sp.bytes;
  }
}

RetainStore::~RetainStore() {
  {
    std::lock_guard lk(mu_);
    stopping_ = true;
  }
  writerCv_.notify_all();
  if (writer_.joinable()) writer_.join();
  if (lockFd_ >= 0) ::close(lockFd_);
}

bool RetainStore::prepare(std::string &error) {
  const std::string dir = dirOf(cfg_.path);
  struct stat st;
  if (::stat(dir.c_str(), &st) != 0 || !S_ISDIR(st.st_mode)) {
    error = "the directory '" + dir + "' of " + cfg_.path + " does not exist";
    return false;
  }
  for (const std::string &p : {cfg_.path, cfg_.path + ".prev"}) {
    if (::lstat(p.c_str(), &st) == 0 && !S_ISREG(st.st_mode)) {
      error = p + " is not a regular file (" +
              (S_ISLNK(st.st_mode)    ? "a symbolic link"
               : S_ISFIFO(st.st_mode) ? "a FIFO"
               : S_ISDIR(st.st_mode)  ? "a directory"
                                      : "a device or socket") +
              "); the retain file must be one";
      return false;
    }
  }
  const std::string lock = cfg_.path + ".lock";
  int fd = ::open(lock.c_str(), O_RDWR | O_CREAT | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC, 0600);
  if (fd < 0 || ::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    error =
        fd < 0 ? errnoText("cannot create the lock file", lock) : lock + " is not a regular file";
    if (fd >= 0) ::close(fd);
    return false;
  }
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
    error = cfg_.path + " is in use by another process (" + lock +
            " is locked): two servers must not share a retain file";
    ::close(fd);
    return false;
  }
  lockFd_ = fd;
  // Temp files of a save that a crash interrupted (FILE.tmp.XXXXXX, ours: we hold the lock).
  const std::string base = cfg_.path.substr(cfg_.path.rfind('/') + 1) + ".tmp.";
  std::error_code ec;
  for (const auto &e : std::filesystem::directory_iterator(dir, ec)) {
    std::string name = e.path().filename().string();
    if (name.size() == base.size() + 6 && name.compare(0, base.size(), base) == 0 &&
        e.is_regular_file(ec) && !e.is_symlink(ec))
      ::unlink(e.path().c_str());
  }
  return true;
}

void RetainStore::logLine(const std::string &line) const {
  if (cfg_.log)
    cfg_.log(line);
  else
    std::fprintf(stderr, "%s\n", line.c_str());
}

RetainStore::ReadResult RetainStore::readFile(const RetainLayout &layout, const std::string &path,
                                              RetainImage &out, uint64_t &saveSeq,
                                              std::string &savedHash, std::string &error) {
  // O_NONBLOCK: a FIFO in the file's place never blocks the start (it is refused below).
  int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) {
    bool missing = errno == ENOENT;
    error = errnoText("cannot open", path);
    return missing ? ReadResult::Missing : ReadResult::Corrupt;
  }
  struct stat st;
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    error = path + ": not a regular file";
    ::close(fd);
    return ReadResult::Corrupt;
  }
  // Read at most one byte more than the largest file any layout writes, so trailing garbage is
  // detected; the size of this layout's file is checked below.
  const size_t cap = std::max(retain::fileBytes(layout), retain::maxFileBytes());
  std::vector<unsigned char> buf(cap + 1);
  size_t got = 0;
  while (got < buf.size()) {
    ssize_t r = ::read(fd, buf.data() + got, buf.size() - got);
    if (r < 0 && errno == EINTR) continue;
    if (r < 0) {
      error = errnoText("cannot read", path);
      ::close(fd);
      return ReadResult::Corrupt;
    }
    if (r == 0) break;
    got += static_cast<size_t>(r);
  }
  ::close(fd);
  return retain::decode(layout, path, buf.data(), got, out, saveSeq, savedHash, error);
}

RestoreReport RetainStore::restore(lj_state &s, uint64_t nowMs) {
  RestoreReport rep;
  const std::string prev = cfg_.path + ".prev";
  RetainImage img;
  uint64_t seq = 0;
  std::string savedHash, errMain, errPrev;
  ReadResult rMain = readFile(layout_, cfg_.path, img, seq, savedHash, errMain);
  ReadResult rPrev = ReadResult::Missing;
  std::string loadedFrom;
  if (rMain == ReadResult::Ok) {
    loadedFrom = cfg_.path;
    rep.status = RestoreStatus::Restored;
  } else if (rMain != ReadResult::Layout) {
    rPrev = readFile(layout_, prev, img, seq, savedHash, errPrev);
    if (rPrev == ReadResult::Ok) {
      loadedFrom = prev;
      rep.status = RestoreStatus::RestoredPrev;
      // Never rotate the damaged (or missing) main file over the good previous copy.
      mainIsGood_ = false;
    }
  }
  if (rMain == ReadResult::Layout || rPrev == ReadResult::Layout) {
    const std::string &why = rMain == ReadResult::Layout ? errMain : errPrev;
    if (!cfg_.force) {
      refused_ = true;
      rep.status = RestoreStatus::LayoutMismatch;
      rep.message = "retain: " + why +
                    ": refusing to load it or overwrite it; start with "
                    "--retain-force to begin with zeros (the old files are "
                    "kept as FILE.rejected)";
      logLine(rep.message);
      return rep;
    }
    // Keep the foreign files for inspection; the store starts empty.
    std::rename(cfg_.path.c_str(), (cfg_.path + ".rejected").c_str());
    std::rename(prev.c_str(), (prev + ".rejected").c_str());
    rep.status = RestoreStatus::LayoutForced;
    rep.message = "retain: " + why + "; --retain-force: starting with zeros, old files renamed " +
                  "to *.rejected";
    logLine(rep.message);
    return rep;
  }
  // A damaged file may still hold almost all of the machine's data: move it aside before the
  // first save could overwrite it, and say where (docs/retain.md "Restore").
  std::string kept;
  for (auto [r, file] : {std::pair{rMain, cfg_.path}, std::pair{rPrev, prev}}) {
    if (r != ReadResult::Corrupt || ::access(file.c_str(), F_OK) != 0) continue;
    std::string moved, err;
    if (!moveAside(file, moved, err)) {
      refused_ = true;
      rep.status = RestoreStatus::DamagedNotKept;
      rep.message = "retain: ERROR: " + (file == cfg_.path ? errMain : errPrev) + "; " + err +
                    ": refusing to overwrite it";
      logLine(rep.message);
      return rep;
    }
    kept += (kept.empty() ? "; damaged file kept as " : ", ") + moved;
  }
  if (loadedFrom.empty()) {
    if (rMain == ReadResult::Missing && rPrev == ReadResult::Missing) {
      rep.status = RestoreStatus::NoFile;
      rep.message = "retain: " + cfg_.path + " does not exist yet: starting with zeros";
    } else {
      rep.status = RestoreStatus::BothBad;
      mainIsGood_ = false;
      rep.message = "retain: ERROR: no usable retain file (" + errMain + "; " + errPrev +
                    "): starting with zeros" + kept;
    }
    logLine(rep.message);
    return rep;
  }
  auto *dst = reinterpret_cast<unsigned char *>(&s);
  const unsigned char *p = img.bytes.data();
  for (size_t k = 0; k < layout_.spans.size(); ++k) {
    const RetainSpan &sp = layout_.spans[k];
    std::memcpy(dst + sp.offset, p, sp.bytes);
    p += sp.bytes;
    if (static_cast<int>(k) != layout_.timerSpan) continue;
    // A retained timer keeps the age it had when saved: time while the controller was off
    // does not count (docs/retain.md "Timers").
    for (uint32_t off = 0; off + sizeof(lj_timer) <= sp.bytes; off += sizeof(lj_timer)) {
      lj_timer t;
      std::memcpy(&t, dst + sp.offset + off, sizeof t);
      int64_t age = static_cast<int64_t>(img.nowMs) - t.start_ms;
      t.start_ms = static_cast<int64_t>(nowMs) - age;
      std::memcpy(dst + sp.offset + off, &t, sizeof t);
    }
  }
  saveSeq_ = seq;
  rep.saveSeq = seq;
  std::string line = rep.status == RestoreStatus::RestoredPrev
                         ? "retain: WARNING: " + errMain + "; falling back to " + prev + ": "
                         : "retain: ";
  line += "restored " + loadedFrom + " (save #" + std::to_string(seq) + ", tick " +
          std::to_string(img.tick) + ")" + kept;
  if (!cfg_.programHash.empty() && !savedHash.empty() && savedHash != cfg_.programHash)
    line += "; note: saved by program " + savedHash + ", now running " + cfg_.programHash;
  rep.message = line;
  logLine(line);
  return rep;
}

void RetainStore::start() {
  std::lock_guard lk(mu_);
  if (started_ || refused_) return;
  started_ = true;
  writer_ = std::thread([this] { writerLoop(); });
}

void RetainStore::afterTick(const lj_state &s, uint64_t tick) {
  bool force = forceCapture_.exchange(false, std::memory_order_acq_rel);
  if (!force && haveLast_ && sameAs(last_, s)) return;
  RetainImage &dst = slots_[back_];
  capture(dst, s);
  dst.tick = tick;
  dst.nowMs = s.now_ms;
  dst.index = captures_.load(std::memory_order_relaxed) + 1;
  // Same sizes (set in the constructor): the copy assignment reuses last_'s buffer.
  std::memcpy(last_.bytes.data(), dst.bytes.data(), dst.bytes.size());
  last_.tick = dst.tick;
  last_.nowMs = dst.nowMs;
  last_.index = dst.index;
  haveLast_ = true;
  back_ = middle_.exchange(back_ | kFresh, std::memory_order_acq_rel) & ~kFresh;
  // Published after the slot: a commit() that reads this count knows the capture is taken.
  captures_.store(dst.index, std::memory_order_release);
}

void RetainStore::requestSave() {
  uint64_t want = captures_.load(std::memory_order_acquire) + 1;
  forceCapture_.store(true, std::memory_order_release);
  uint64_t cur = wantIndex_.load(std::memory_order_relaxed);
  while (cur < want && !wantIndex_.compare_exchange_weak(cur, want)) {
  }
}

bool RetainStore::commit(std::chrono::milliseconds timeout) {
  if (refused_) return false;
  // Every write applied before this call is in the state at the end of the current tick at the
  // latest; the capture of that tick (forced) has index > the count read here.
  uint64_t want = captures_.load(std::memory_order_acquire) + 1;
  requestSave();
  std::unique_lock lk(mu_);
  writerCv_.notify_all();
  return doneCv_.wait_for(lk, timeout, [&] { return durableIndex_ >= want; });
}

bool RetainStore::takeLatest() {
  if (!(middle_.load(std::memory_order_acquire) & kFresh)) return false;
  front_ = middle_.exchange(front_, std::memory_order_acq_rel) & ~kFresh;
  return true;
}

void RetainStore::writerLoop() {
  auto lastWrite = std::chrono::steady_clock::now() - cfg_.period;
  uint64_t written = 0; // capture index of the newest file this thread wrote (or tried)
  for (;;) {
    bool stopNow;
    {
      std::unique_lock lk(mu_);
      writerCv_.wait_for(lk, kPoll, [&] {
        return stopping_ || wantIndex_.load(std::memory_order_acquire) > durableIndex_;
      });
      stopNow = stopping_;
    }
    takeLatest();
    const RetainImage &img = slots_[front_];
    uint64_t want = wantIndex_.load(std::memory_order_acquire);
    auto now = std::chrono::steady_clock::now();
    // A commit waits for a capture taken after its request: writing an older one would only
    // cost a second save.
    bool urgent = stopNow || (want > written && img.index >= want);
    bool due = img.index > written && (urgent || now - lastWrite >= cfg_.period);
    if (due) {
      std::string err;
      bool ok = writeFile(img, err);
      lastWrite = now;
      {
        std::lock_guard lk(mu_);
        if (ok) {
          written = img.index;
          durableIndex_ = img.index;
          ++stats_.saves;
          stats_.lastSaveSeq = saveSeq_;
        } else {
          ++stats_.failures;
        }
      }
      doneCv_.notify_all();
      if (!ok) {
        logLine("retain: ERROR: save failed: " + err);
        // Do not spin on a full disk; commit() callers time out and report the failure.
        if (!stopNow) std::this_thread::sleep_for(cfg_.period);
      }
    }
    if (stopNow) return;
    // Waiting for the scan thread's next capture: do not spin on the predicate meanwhile.
    if (!due && want > written) std::this_thread::sleep_for(std::chrono::microseconds(100));
  }
}

bool RetainStore::writeFile(const RetainImage &img, std::string &error) {
  const std::vector<unsigned char> buf =
      retain::encode(layout_, img, {saveSeq_ + 1, img.tick, img.nowMs, cfg_.programHash});
  const uint64_t nextSeq = saveSeq_ + 1;

  // A new file with a random name (O_CREAT | O_EXCL, mode 0600): a symlink or file planted
  // under any predictable name is never followed or written.
  std::string tmpl = cfg_.path + ".tmp.XXXXXX";
  const std::string prev = cfg_.path + ".prev";
  int fd = ::mkostemp(tmpl.data(), O_CLOEXEC);
  const std::string tmp = tmpl;
  if (fd < 0) {
    error = errnoText("cannot create", tmp);
    return false;
  }
  if (!writeAll(fd, buf.data(), buf.size()) || ::fsync(fd) != 0) {
    error = errnoText("cannot write", tmp);
    ::close(fd);
    ::unlink(tmp.c_str());
    return false;
  }
  ::close(fd);
  // FILE.prev becomes the current FILE through a hard link renamed into place, so FILE and
  // FILE.prev both exist at every instant (after the first two saves).
  if (mainIsGood_ && ::access(cfg_.path.c_str(), F_OK) == 0) {
    const std::string link = prev + ".tmp";
    ::unlink(link.c_str());
    if (::link(cfg_.path.c_str(), link.c_str()) != 0 || ::rename(link.c_str(), prev.c_str()) != 0) {
      error = errnoText("cannot keep the previous copy as", prev);
      ::unlink(tmp.c_str());
      return false;
    }
  }
  if (::rename(tmp.c_str(), cfg_.path.c_str()) != 0) {
    error = errnoText("cannot rename into", cfg_.path);
    ::unlink(tmp.c_str());
    return false;
  }
  // The renames are durable only once the directory is synced; acknowledge after that.
  std::string dir = dirOf(cfg_.path);
  int dfd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dfd < 0 || ::fsync(dfd) != 0) {
    error = errnoText("cannot sync directory", dir);
    if (dfd >= 0) ::close(dfd);
    return false;
  }
  ::close(dfd);
  mainIsGood_ = true;
  saveSeq_ = nextSeq;
  return true;
}

void RetainStore::stop(const lj_state &finalState, uint64_t tick) {
  if (refused_) return;
  forceCapture_.store(true);
  afterTick(finalState, tick);
  uint64_t want = captures_.load();
  uint64_t cur = wantIndex_.load();
  while (cur < want && !wantIndex_.compare_exchange_weak(cur, want)) {
  }
  bool threaded;
  {
    std::lock_guard lk(mu_);
    threaded = started_;
    stopping_ = true;
  }
  writerCv_.notify_all();
  if (threaded) {
    if (writer_.joinable()) writer_.join();
    return;
  }
  takeLatest();
  std::string err;
  std::lock_guard lk(mu_);
  if (writeFile(slots_[front_], err)) {
    durableIndex_ = slots_[front_].index;
    ++stats_.saves;
    stats_.lastSaveSeq = saveSeq_;
  } else {
    ++stats_.failures;
    logLine("retain: ERROR: save failed: " + err);
  }
}

RetainStats RetainStore::stats() const {
  std::lock_guard lk(mu_);
  RetainStats s = stats_;
  s.captures = captures_.load();
  return s;
}

} // namespace lj::services

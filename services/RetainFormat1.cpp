// Retain file format 1, HNC-8's (docs/retain.md "File format"): a fixed 144-byte header that
// names B0..B49, T300..T427 and C300..C427 by their counts and sizes.
#include "services/RetainFormat.h"

#include <cstdio>
#include <cstring>

namespace lj::services::retain::format1 {
namespace {

/// The file header of format 1.
struct FileHeader {
  char magic[8];
  uint32_t formatVersion;
  uint32_t headerBytes;
  uint32_t abiVersion;
  uint32_t bCount;
  uint32_t tcFirst; // first retained timer/counter number (300)
  uint32_t tcCount;
  uint32_t timerBytes;
  uint32_t counterBytes;
  uint32_t payloadBytes;
  uint32_t reserved;
  uint64_t saveSeq;
  uint64_t tick;
  uint64_t nowMs;
  char programHash[kHashField];
};
static_assert(sizeof(FileHeader) == kHeaderBytes, "retain file header layout");
static_assert(offsetof(FileHeader, saveSeq) == kStampAt &&
                  offsetof(FileHeader, tick) == kStampAt + 8 &&
                  offsetof(FileHeader, nowMs) == kStampAt + 16 &&
                  offsetof(FileHeader, programHash) == kStampAt + 24,
              "the stamp at the header's tail (RetainFormat.cpp decode)");

constexpr uint32_t kPayloadBytes = sizeof(int32_t) * LJ_B_COUNT +
                                   sizeof(lj_timer) * kRetainedTcCount +
                                   sizeof(lj_counter) * kRetainedTcCount;

FileHeader expectedHeader() {
  FileHeader h{};
  std::memcpy(h.magic, kMagic, sizeof kMagic);
  h.formatVersion = kFormat1;
  h.headerBytes = sizeof(FileHeader);
  h.abiVersion = LJ_ABI_VERSION;
  h.bCount = LJ_B_COUNT;
  h.tcFirst = 300;
  h.tcCount = kRetainedTcCount;
  h.timerBytes = sizeof(lj_timer);
  h.counterBytes = sizeof(lj_counter);
  h.payloadBytes = kPayloadBytes;
  return h;
}

} // namespace

unsigned char *writeHeader(unsigned char *p, const Stamp &s) {
  FileHeader h = expectedHeader();
  h.saveSeq = s.saveSeq;
  h.tick = s.tick;
  h.nowMs = s.nowMs;
  std::snprintf(h.programHash, sizeof h.programHash, "%s", s.programHash.c_str());
  std::memcpy(p, &h, sizeof h);
  return p + sizeof h;
}

bool sameLayout(const unsigned char *buf, std::string &why) {
  FileHeader h;
  std::memcpy(&h, buf, sizeof h);
  FileHeader e = expectedHeader();
  auto item = [](const char *name, uint32_t v) {
    return std::string(name) + " " + std::to_string(v);
  };
  std::string saved = item("ABI", h.abiVersion) + ", " + item("B", h.bCount) + ", " +
                      item("T/C from", h.tcFirst) + " x" + std::to_string(h.tcCount) + ", " +
                      item("timer bytes", h.timerBytes) + ", " +
                      item("counter bytes", h.counterBytes);
  std::string ours = item("ABI", e.abiVersion) + ", " + item("B", e.bCount) + ", " +
                     item("T/C from", e.tcFirst) + " x" + std::to_string(e.tcCount) + ", " +
                     item("timer bytes", e.timerBytes) + ", " +
                     item("counter bytes", e.counterBytes);
  if (saved == ours && h.payloadBytes == e.payloadBytes) return true;
  why = "saved with another layout (" + saved + "; this build: " + ours + ")";
  return false;
}

std::string describe() { return "format 1 (HNC-8 B, T300..T427, C300..C427)"; }

} // namespace lj::services::retain::format1

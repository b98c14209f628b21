// Retain file format 2, the profile-laid targets' (docs/retain.md "Format 2"): a 144-byte header
// naming the profile, then spanCount (offset, bytes) pairs of lj_state, the payload and the
// digest.
#include "services/RetainFormat.h"

#include <algorithm>
#include <cstdio>
#include <cstring>

namespace lj::services::retain::format2 {
namespace {

/// The file header of format 2, followed by spanCount (offset, bytes) pairs.
struct FileHeader2 {
  char magic[8];
  uint32_t formatVersion; // 2
  uint32_t headerBytes;   // 144
  uint32_t abiVersion;
  uint32_t spanCount;
  uint32_t payloadBytes;
  uint32_t timerSpan; // index of the lj_timer span, 0xFFFFFFFF: none
  char profile[16];   // NUL padded
  uint64_t saveSeq;
  uint64_t tick;
  uint64_t nowMs;
  char programHash[kHashField];
};
static_assert(sizeof(FileHeader2) == kHeaderBytes, "retain file header 2 layout");
static_assert(offsetof(FileHeader2, saveSeq) == kStampAt &&
                  offsetof(FileHeader2, tick) == kStampAt + 8 &&
                  offsetof(FileHeader2, nowMs) == kStampAt + 16 &&
                  offsetof(FileHeader2, programHash) == kStampAt + 24,
              "the stamp at the header's tail (RetainFormat.cpp decode)");

FileHeader2 expectedHeader2(const RetainLayout &l) {
  FileHeader2 h{};
  std::memcpy(h.magic, kMagic, sizeof kMagic);
  h.formatVersion = kFormat2;
  h.headerBytes = sizeof(FileHeader2);
  h.abiVersion = LJ_ABI_VERSION;
  h.spanCount = static_cast<uint32_t>(l.spans.size());
  h.payloadBytes = l.payloadBytes();
  h.timerSpan = l.timerSpan < 0 ? 0xFFFFFFFFu : static_cast<uint32_t>(l.timerSpan);
  std::snprintf(h.profile, sizeof h.profile, "%s", l.profile.c_str());
  return h;
}

std::string describe2(const FileHeader2 &h, const unsigned char *spans) {
  std::string out = "profile " + std::string(h.profile, strnlen(h.profile, sizeof h.profile)) +
                    ", ABI " + std::to_string(h.abiVersion) + ", spans";
  for (uint32_t i = 0; i < h.spanCount && i < kMaxSpans; ++i) {
    uint32_t o, b;
    std::memcpy(&o, spans + 8 * i, 4);
    std::memcpy(&b, spans + 8 * i + 4, 4);
    out += " " + std::to_string(o) + "+" + std::to_string(b);
  }
  return out;
}

/// The span list of `l` as the file stores it.
std::vector<unsigned char> spanBytes(const RetainLayout &l) {
  std::vector<unsigned char> out(8 * l.spans.size());
  for (size_t i = 0; i < l.spans.size(); ++i) {
    std::memcpy(out.data() + 8 * i, &l.spans[i].offset, 4);
    std::memcpy(out.data() + 8 * i + 4, &l.spans[i].bytes, 4);
  }
  return out;
}

} // namespace

size_t headerBytes(const RetainLayout &l) { return sizeof(FileHeader2) + 8 * l.spans.size(); }

unsigned char *writeHeader(unsigned char *p, const RetainLayout &l, const Stamp &s) {
  FileHeader2 h = expectedHeader2(l);
  h.saveSeq = s.saveSeq;
  h.tick = s.tick;
  h.nowMs = s.nowMs;
  std::snprintf(h.programHash, sizeof h.programHash, "%s", s.programHash.c_str());
  std::memcpy(p, &h, sizeof h);
  p += sizeof h;
  for (const RetainSpan &sp : l.spans) {
    std::memcpy(p, &sp.offset, 4);
    std::memcpy(p + 4, &sp.bytes, 4);
    p += 8;
  }
  return p;
}

bool sameLayout(const RetainLayout &l, const unsigned char *buf, size_t got, size_t want) {
  const FileHeader2 e2 = expectedHeader2(l);
  const std::vector<unsigned char> ourSpans = spanBytes(l);
  FileHeader2 h;
  std::memcpy(&h, buf, sizeof h);
  return h.abiVersion == e2.abiVersion && h.spanCount == e2.spanCount &&
         h.payloadBytes == e2.payloadBytes && h.timerSpan == e2.timerSpan &&
         std::memcmp(h.profile, e2.profile, sizeof h.profile) == 0 && got == want &&
         std::memcmp(buf + sizeof h, ourSpans.data(), ourSpans.size()) == 0;
}

std::string describe(const RetainLayout &l) {
  return "format 2, " + describe2(expectedHeader2(l), spanBytes(l).data());
}

std::string describeSaved(const unsigned char *buf, size_t got) {
  FileHeader2 h;
  std::memcpy(&h, buf, sizeof h);
  std::string saved = "format 2";
  if (sizeof h + 8ull * std::min(h.spanCount, kMaxSpans) <= got)
    saved += ", " + describe2(h, buf + sizeof h);
  return saved;
}

} // namespace lj::services::retain::format2

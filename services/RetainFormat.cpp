// What the two retain file formats share (docs/retain.md): the magic, the SHA-256 digest over
// everything before it, the stamp at the header's tail, and the choice of format by layout.
#include "services/RetainFormat.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cstring>
#include <openssl/evp.h>

namespace lj::services::retain {
namespace {

// The file stores integers in host order; the format is defined little-endian (docs/retain.md).
static_assert(std::endian::native == std::endian::little, "retain file format is little-endian");

std::array<unsigned char, kDigestBytes> sha256(const unsigned char *data, size_t n) {
  std::array<unsigned char, kDigestBytes> out{};
  unsigned int len = 0;
  EVP_Digest(data, n, out.data(), &len, EVP_sha256(), nullptr);
  return out;
}

} // namespace

size_t fileBytes(const RetainLayout &l) {
  return (l.format1 ? kHeaderBytes : format2::headerBytes(l)) + l.payloadBytes() + kDigestBytes;
}

size_t maxFileBytes() { return kHeaderBytes + 8 * kMaxSpans + sizeof(lj_state) + kDigestBytes; }

std::vector<unsigned char> encode(const RetainLayout &l, const RetainImage &img, const Stamp &s) {
  std::vector<unsigned char> buf(fileBytes(l));
  unsigned char *p =
      l.format1 ? format1::writeHeader(buf.data(), s) : format2::writeHeader(buf.data(), l, s);
  std::memcpy(p, img.bytes.data(), img.bytes.size());
  p += img.bytes.size();
  auto digest = sha256(buf.data(), static_cast<size_t>(p - buf.data()));
  std::memcpy(p, digest.data(), kDigestBytes);
  return buf;
}

RetainStore::ReadResult decode(const RetainLayout &layout, const std::string &path,
                               const unsigned char *buf, size_t got, RetainImage &out,
                               uint64_t &saveSeq, std::string &savedHash, std::string &error) {
  using ReadResult = RetainStore::ReadResult;
  const size_t want = fileBytes(layout);
  if (got < kHeaderBytes + kDigestBytes) {
    error = path + ": truncated (" + std::to_string(got) + " bytes, a retain file has " +
            std::to_string(want) + ")";
    return ReadResult::Corrupt;
  }
  if (std::memcmp(buf, kMagic, sizeof kMagic) != 0) {
    error = path + ": not a ladderjit retain file (bad magic)";
    return ReadResult::Corrupt;
  }
  // The digest covers everything before it, whatever the layout, so damage is told apart from
  // a file of another version or layout.
  auto digest = sha256(buf, got - kDigestBytes);
  if (std::memcmp(digest.data(), buf + got - kDigestBytes, kDigestBytes) != 0) {
    error = path + (got == want ? ": checksum mismatch (corrupted)"
                                : ": truncated or corrupted (" + std::to_string(got) +
                                      " bytes, checksum mismatch)");
    return ReadResult::Corrupt;
  }
  uint32_t format = 0, headerBytes = 0;
  std::memcpy(&format, buf + 8, 4);
  std::memcpy(&headerBytes, buf + 12, 4);
  const uint32_t ours = layout.format1 ? kFormat1 : kFormat2;
  if ((format != kFormat1 && format != kFormat2) || headerBytes != kHeaderBytes) {
    error = path + ": retain file format " + std::to_string(format) +
            ", this build reads formats 1 and 2";
    return ReadResult::Layout;
  }
  const std::string ourText = layout.format1 ? format1::describe() : format2::describe(layout);
  if (format != ours) {
    const std::string saved =
        format == kFormat1 ? format1::describe() : format2::describeSaved(buf, got);
    error = path + ": saved with another layout (" + saved + "; this program: " + ourText + ")";
    return ReadResult::Layout;
  }
  if (layout.format1) {
    std::string why;
    if (!format1::sameLayout(buf, why) || got != want) {
      error = path + ": " + (why.empty() ? "unexpected size " + std::to_string(got) : why);
      return ReadResult::Layout;
    }
  } else if (!format2::sameLayout(layout, buf, got, want)) {
    error = path + ": saved with another layout (" + format2::describeSaved(buf, got) +
            "; this program: " + ourText + ")";
    return ReadResult::Layout;
  }
  // Both headers keep the save number, tick, now_ms and program hash at kStampAt.
  uint64_t seq = 0, tick = 0, nowMs = 0;
  std::memcpy(&seq, buf + kStampAt, 8);
  std::memcpy(&tick, buf + kStampAt + 8, 8);
  std::memcpy(&nowMs, buf + kStampAt + 16, 8);
  char hash[kHashField];
  std::memcpy(hash, buf + kStampAt + 24, kHashField);
  hash[kHashField - 1] = '\0';
  const size_t payloadAt = want - kDigestBytes - layout.payloadBytes();
  out.bytes.assign(buf + payloadAt, buf + payloadAt + layout.payloadBytes());
  out.tick = tick;
  out.nowMs = nowMs;
  out.index = 0;
  saveSeq = seq;
  savedHash = hash;
  return ReadResult::Ok;
}

} // namespace lj::services::retain

// The retain file's bytes, one file per format (docs/retain.md): RetainFormat1.cpp is format 1
// (HNC-8: B, T300..T427, C300..C427 in a fixed header), RetainFormat2.cpp format 2 (the spans
// of a profile-laid target listed after the header); RetainFormat.cpp what both share (magic,
// digest, the stamp at the header's tail) and the choice between them. RetainStore.cpp does the
// files themselves (open, read, write, fsync, rename). Internal to services/.
#pragma once

#include "services/RetainStore.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace lj::services::retain {

inline constexpr char kMagic[8] = {'L', 'J', 'R', 'E', 'T', 'A', 'I', 'N'};
inline constexpr uint32_t kFormat1 = 1;
inline constexpr uint32_t kFormat2 = 2;
inline constexpr int kHashField = 72; // "sha256:" + 64 hex digits + NUL
inline constexpr size_t kDigestBytes = 32;
inline constexpr size_t kHeaderBytes = 144; // both formats
inline constexpr uint32_t kMaxSpans = 64;
/// Where both headers keep the stamp: saveSeq, tick, nowMs (uint64) and the program hash.
inline constexpr size_t kStampAt = 48;

/// What every save writes into its header; both formats keep it at the same offsets.
struct Stamp {
  uint64_t saveSeq = 0;
  uint64_t tick = 0;
  uint64_t nowMs = 0;
  std::string programHash;
};

namespace format1 {
/// Write the header at `p`; returns the end of what was written.
unsigned char *writeHeader(unsigned char *p, const Stamp &s);
/// False with `why` when the saved header at `buf` has another layout than this build's.
bool sameLayout(const unsigned char *buf, std::string &why);
/// "format 1 (HNC-8 B, T300..T427, C300..C427)".
std::string describe();
} // namespace format1

namespace format2 {
/// Bytes of the header and the span list of layout `l`.
size_t headerBytes(const RetainLayout &l);
/// Write the header and the span list of `l` at `p`; returns the end of what was written.
unsigned char *writeHeader(unsigned char *p, const RetainLayout &l, const Stamp &s);
/// True when the saved file at `buf` (`got` bytes, `want` for `l`) has layout `l`.
bool sameLayout(const RetainLayout &l, const unsigned char *buf, size_t got, size_t want);
/// "format 2, profile ..., ABI ..., spans ..." of layout `l`.
std::string describe(const RetainLayout &l);
/// "format 2, profile ..., spans ..." of a saved format-2 file of `got` bytes in `buf`.
std::string describeSaved(const unsigned char *buf, size_t got);
} // namespace format2

/// Bytes of a whole file of layout `l`.
size_t fileBytes(const RetainLayout &l);
/// Bytes of the largest file any layout writes.
size_t maxFileBytes();
/// The whole file of `img` in layout `l`: header, payload, digest.
std::vector<unsigned char> encode(const RetainLayout &l, const RetainImage &img, const Stamp &s);
/// Check and decode the `got` bytes of the file `path` read into `buf` for layout `l`: the image,
/// its save number and program hash, or `error` (naming `path`) when it is damaged or of another
/// layout.
RetainStore::ReadResult decode(const RetainLayout &l, const std::string &path,
                               const unsigned char *buf, size_t got, RetainImage &out,
                               uint64_t &saveSeq, std::string &savedHash, std::string &error);

} // namespace lj::services::retain

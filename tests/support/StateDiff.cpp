// Field table of lj_state (abi.h) for readable cross-engine mismatch reports.
#include "tests/support/StateDiff.h"

#include <cstring>
#include <sstream>

namespace lj::test {

namespace {

/// One array (or scalar, count 1) of the state: where it is and how big an element is.
struct Field {
  const char *name;
  size_t offset, elemSize, count;
};

#define LJ_ARRAY(path, elem, n)                                                                    \
  Field { #path, offsetof(lj_state, path), sizeof(elem), n }
#define LJ_SCALAR(path)                                                                            \
  Field { #path, offsetof(lj_state, path), sizeof(lj_state::path), 1 }

const Field kFields[] = {
    LJ_ARRAY(img.D, int32_t, LJ_D_COUNT),
    LJ_ARRAY(img.B, int32_t, LJ_B_COUNT),
    LJ_ARRAY(img.P, int32_t, LJ_P_COUNT),
    LJ_ARRAY(img.F, int16_t, LJ_F_COUNT),
    LJ_ARRAY(img.G, int16_t, LJ_G_COUNT),
    LJ_ARRAY(img.W, int16_t, LJ_W_COUNT),
    LJ_ARRAY(img.X, uint8_t, LJ_X_COUNT),
    LJ_ARRAY(img.Y, uint8_t, LJ_Y_COUNT),
    LJ_ARRAY(img.R, uint8_t, LJ_R_COUNT),
    LJ_ARRAY(img.pad_, uint8_t, 6),
    LJ_ARRAY(T, lj_timer, LJ_TC_SLOTS),
    LJ_ARRAY(C, lj_counter, LJ_TC_SLOTS),
    LJ_ARRAY(pls_prev, uint8_t, LJ_BLOCK_SLOTS),
    LJ_ARRAY(plf_prev, uint8_t, LJ_BLOCK_SLOTS),
    LJ_ARRAY(alt_prev, uint8_t, LJ_BLOCK_SLOTS),
    LJ_ARRAY(alt_state, uint8_t, LJ_BLOCK_SLOTS),
    LJ_ARRAY(edge, uint8_t, LJ_EDGE_SLOTS),
    LJ_SCALAR(now_ms),
    LJ_SCALAR(max_backward_steps),
    LJ_SCALAR(steps),
    LJ_SCALAR(plc2_next_slice),
    LJ_SCALAR(last_fault),
    LJ_SCALAR(fault_watchdog),
    LJ_SCALAR(fault_index),
    LJ_SCALAR(fault_divzero),
    LJ_SCALAR(pad_),
};

#undef LJ_ARRAY
#undef LJ_SCALAR

std::string timerMember(size_t off) {
  if (off < offsetof(lj_timer, elapsed_ms)) return "start_ms";
  if (off < offsetof(lj_timer, out)) return "elapsed_ms";
  if (off < offsetof(lj_timer, running)) return "out";
  if (off < offsetof(lj_timer, pad_)) return "running";
  return "pad_";
}

std::string counterMember(size_t off) {
  if (off < offsetof(lj_counter, out)) return "value";
  if (off < offsetof(lj_counter, prev)) return "out";
  if (off < offsetof(lj_counter, pad_)) return "prev";
  return "pad_";
}

const Field *fieldOf(size_t offset) {
  for (const Field &f : kFields)
    if (offset >= f.offset && offset < f.offset + f.elemSize * f.count) return &f;
  return nullptr;
}

/// The element holding `offset`, as an integer (little-endian, up to 8 bytes, zero-extended).
uint64_t elementBits(const lj_state &s, const Field &f, size_t offset) {
  size_t elem = (offset - f.offset) / f.elemSize;
  size_t start = f.offset + elem * f.elemSize;
  size_t n = f.elemSize > 8 ? 1 : f.elemSize; // structs: show the differing byte
  if (f.elemSize > 8) start = offset;
  uint64_t v = 0;
  std::memcpy(&v, reinterpret_cast<const unsigned char *>(&s) + start, n);
  return v;
}

} // namespace

std::optional<size_t> firstDifference(const lj_state &a, const lj_state &b) {
  if (std::memcmp(&a, &b, LJ_STATE_COMPARED_BYTES) == 0) return std::nullopt;
  const auto *pa = reinterpret_cast<const unsigned char *>(&a);
  const auto *pb = reinterpret_cast<const unsigned char *>(&b);
  for (size_t i = 0; i < LJ_STATE_COMPARED_BYTES; ++i)
    if (pa[i] != pb[i]) return i;
  return std::nullopt;
}

std::string fieldAt(size_t offset) {
  const Field *f = fieldOf(offset);
  if (!f) return "?";
  std::ostringstream os;
  os << f->name;
  size_t rel = offset - f->offset;
  if (f->count > 1) os << '[' << rel / f->elemSize << ']';
  size_t inElem = rel % f->elemSize;
  if (f->offset == offsetof(lj_state, T)) {
    os << '.' << timerMember(inElem);
  } else if (f->offset == offsetof(lj_state, C)) {
    os << '.' << counterMember(inElem);
  } else if (f->elemSize > 1 && (f->count > 1 || inElem > 0)) {
    os << " (byte " << inElem << ')';
  }
  return os.str();
}

std::string describeDifference(const lj_state &a, const lj_state &b, const char *nameA,
                               const char *nameB) {
  std::optional<size_t> off = firstDifference(a, b);
  if (!off) return {};
  std::ostringstream os;
  os << "first difference at " << fieldAt(*off) << " (offset " << *off << ")";
  if (const Field *f = fieldOf(*off)) {
    os << ": " << nameA << "=0x" << std::hex << elementBits(a, *f, *off) << ' ' << nameB << "=0x"
       << elementBits(b, *f, *off) << std::dec;
  }
  size_t count = 0;
  const auto *pa = reinterpret_cast<const unsigned char *>(&a);
  const auto *pb = reinterpret_cast<const unsigned char *>(&b);
  for (size_t i = 0; i < LJ_STATE_COMPARED_BYTES; ++i) count += pa[i] != pb[i];
  os << " (" << count << " differing bytes in all)";
  return os.str();
}

} // namespace lj::test

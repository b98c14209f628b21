// Interpreter semantics of the FANUC transfer, search, conversion and flow operations (fanuc-b
// rows of ir/OpTable.h; FANUC PMC manual ref 4.2, 6.5, 6.7-6.9; the [EXT]/[INF]
// readings are rows of docs/fanuc-pmc.md). Twin of lowering/EmitFanucData.cpp.
//
// Control inputs are ST entries: ACT = ST0, the next input ST1, ... (reference 5). An instruction
// with k inputs pops k - 1 of them and leaves W1 in ST0. The RST family (PARI, SFT, DCNV, DCNVB,
// COD, CODB, XMOVB, DSCHB) keeps W1 in its edge slot: ACT = 1 sets it to this execution's error,
// ACT = 0 keeps it, RST = 1 clears it (after the execution). ROT / ROTB (no RST) hold their W1,
// the direction, in the edge slot too: only an execution that decides a direction sets it.
#include "interp/InterpFanucCommon.h"
#include "interp/InterpreterInternal.h"

#include <algorithm>

namespace lj::interp {

namespace {

using fanuc::at;
using fanuc::fromBcd;
using fanuc::Inputs;
using fanuc::take;
using fanuc::w1;

/// `width` bytes at `off`, little-endian, sign-extended (reference 3.1).
int32_t readLe(const BlockCall &b, uint32_t off, int width) {
  uint32_t v = 0;
  for (int k = 0; k < width; ++k) v |= static_cast<uint32_t>(at(b, off)[k]) << (8 * k);
  if (width < 4) {
    const uint32_t sign = 1u << (8 * width - 1);
    v = (v ^ sign) - sign;
  }
  return static_cast<int32_t>(v);
}
void writeLe(const BlockCall &b, uint32_t off, int width, uint32_t v) {
  for (int k = 0; k < width; ++k) at(b, off)[k] = static_cast<unsigned char>(v >> (8 * k));
}

/// Bytes from operand `o` to the end of the range of its area it lies in.
int64_t roomAfter(const BlockCall &b, const Operand &o) {
  const AreaInfo &ai = b.tp.area(o.area);
  const int64_t end = o.index < ai.count ? ai.count : int64_t{ai.upperLo} + ai.upperCount;
  return end - o.index;
}

/// `v` (0 <= v < 10^digits) as BCD digits.
uint32_t toBcd(int64_t v, int digits) {
  return static_cast<uint32_t>(bcd::encode(static_cast<uint64_t>(v), digits));
}

void parity(const BlockCall &b) {
  const Inputs in = take(b, 3); // ACT, RST, O.E
  bool err = false;
  if (in.v[0]) {
    const int ones = __builtin_popcount(at(b, b.ops[0].off)[0]);
    // O.E = 1: odd parity is checked (an even count is the error); O.E = 0: even (6.8).
    err = in.v[2] ? ones % 2 == 0 : ones % 2 == 1;
  }
  w1(b, in.v[0], in.v[1], err);
}

void shift(const BlockCall &b) {
  const Inputs in = take(b, 4); // ACT, RST, CONT, DIR
  bool out = false;
  if (in.v[0]) {
    const uint32_t off = b.ops[0].off;
    const uint32_t v = static_cast<uint32_t>(readLe(b, off, 2)) & 0xFFFFu;
    const bool right = in.v[3];
    uint32_t r = right ? v >> 1 : (v << 1) & 0xFFFFu;
    out = right ? (v & 1u) : (v >> 15) & 1u;
    if (in.v[2]) r |= v; // CONT = 1: bits that were 1 stay 1 ([INF] 6.8)
    writeLe(b, off, 2, r);
  }
  w1(b, in.v[0], in.v[1], out);
}

void decode(const BlockCall &b) {
  const bool act = b.f.top();
  const uint8_t v = at(b, b.ops[0].off)[0];
  b.f.setTop(act && (v & b.ops[2].value) == b.ops[1].value);
}

void groupDecode(const BlockCall &b) {
  const bool act = b.f.top();
  const int64_t delta = int64_t{readValue(b.s, b.ops[0])} - b.ops[1].value;
  const int groups = b.ops[2].value;
  const uint32_t out = b.ops[3].off;
  for (int j = 0; j < groups; ++j) {
    uint8_t byte = 0;
    if (act && delta >= 8 * j && delta < 8 * j + 8)
      byte = static_cast<uint8_t>(1u << (delta - 8 * j));
    at(b, out)[j] = byte;
  }
}

void convert(const BlockCall &b) {
  const Inputs in = take(b, 4); // ACT, RST, CNV, BYT
  bool err = false;
  if (in.v[0]) {
    const int width = in.v[3] ? 2 : 1;
    const uint32_t raw =
        static_cast<uint32_t>(readLe(b, b.ops[0].off, width)) & (width == 2 ? 0xFFFFu : 0xFFu);
    int64_t v = 0;
    uint32_t result = 0;
    if (in.v[2]) { // BCD -> binary
      err = !fromBcd(raw, 2 * width, v);
      result = static_cast<uint32_t>(v);
    } else { // binary -> BCD: the unsigned value must fit 2 / 4 digits
      err = raw > (width == 2 ? 9999u : 99u);
      result = toBcd(raw, 2 * width);
    }
    if (!err) writeLe(b, b.ops[1].off, width, result);
  }
  w1(b, in.v[0], in.v[1], err);
}

void convertExt(const BlockCall &b) {
  const Inputs in = take(b, 4); // ACT, RST, CNV, SIN
  bool err = false;
  if (in.v[0]) {
    const int width = b.stmt.ops[0].width;
    const int digits = 2 * width;
    const int32_t x = readLe(b, b.ops[0].off, width);
    bool overflow = false;
    int64_t result = 0;
    if (in.v[2]) { // BCD -> binary, sign from SIN (at most 8 digits: always fits)
      const uint32_t raw = static_cast<uint32_t>(x) & (width == 4 ? ~0u : (1u << (8 * width)) - 1);
      int64_t v;
      err = !fromBcd(raw, digits, v);
      result = in.v[3] ? -v : v;
    } else { // binary -> BCD of |x|; the sign goes to N
      const int64_t mag = x < 0 ? -int64_t{x} : x;
      overflow = err = mag >= bcd::limit(digits);
      result = toBcd(mag, digits);
    }
    // N: the converted value is negative (only when the conversion succeeded).
    const bool negative = !err && (in.v[2] ? result < 0 : x < 0);
    if (!err) writeLe(b, b.ops[1].off, width, static_cast<uint32_t>(result));
    // R9000: N (#1) = sign of the result, V (#5) = overflow ([EXT] 6.9); other bits kept.
    unsigned char &flags = at(b, b.ops[2].off)[0];
    flags = static_cast<unsigned char>((flags & ~0x22u) | (negative ? 0x02u : 0u) |
                                       (overflow ? 0x20u : 0u));
  }
  w1(b, in.v[0], in.v[1], err);
}

/// Entry `k` of the constant table in the TableRows statements after the head statement.
int32_t tableEntry(const BlockCall &b, int32_t k) {
  const Stmt *rows = &b.stmt + 1; // parsed right after the head (frontends/fanuc)
  return rows[k / kMaxOperands].ops[k % kMaxOperands].value;
}

void codeTable(const BlockCall &b) {
  const bool binary = b.c.op == Op::CodeTableBinary;
  const Inputs in = take(b, binary ? 2 : 3); // ACT, RST[, BYT]
  bool err = false;
  if (in.v[0]) {
    const int32_t size = b.stmt.ops[0].value;
    const uint32_t raw = at(b, b.ops[1].off)[0];
    int64_t index = raw; // CODB: one unsigned byte
    if (!binary) err = !fromBcd(raw, 2, index);
    err = err || index >= size;
    if (!err) {
      const int32_t v = tableEntry(b, static_cast<int32_t>(index));
      const int width = binary ? b.stmt.ops[2].width : in.v[2] ? 2 : 1;
      writeLe(b, b.ops[2].off, width, static_cast<uint32_t>(v));
    }
  }
  w1(b, in.v[0], in.v[1], err);
}

void indexedTable(const BlockCall &b) {
  const Inputs in = take(b, 3); // ACT, RST, RW
  bool err = false;
  if (in.v[0]) {
    const auto &o = b.stmt.ops;
    const int width = o[2].width;
    const int64_t items = o[0].value;
    const int64_t cap = readValue(b.s, b.ops[1]);
    const int64_t index = readValue(b.s, b.ops[4]);
    // Items index .. index + items - 1 must be below the capacity and inside the table's range.
    err = index < 0 || index + items > cap || (index + items) * width > roomAfter(b, o[2]);
    if (!err) {
      for (int64_t k = 0; k < items; ++k) {
        const uint32_t t = b.ops[2].off + static_cast<uint32_t>((index + k) * width);
        const uint32_t d = b.ops[3].off + static_cast<uint32_t>(k * width);
        if (in.v[2])
          writeLe(b, t, width, static_cast<uint32_t>(readLe(b, d, width)));
        else
          writeLe(b, d, width, static_cast<uint32_t>(readLe(b, t, width)));
      }
    }
  }
  w1(b, in.v[0], in.v[1], err);
}

void searchTable(const BlockCall &b) {
  const Inputs in = take(b, 2); // ACT, RST
  bool err = false;
  if (in.v[0]) {
    const auto &o = b.stmt.ops;
    const int width = o[1].width;
    const int64_t cap = readValue(b.s, b.ops[0]);
    const int32_t key = readValue(b.s, b.ops[2]);
    // A capacity past the table's range is an error; otherwise W1 = not found (6.7).
    err = cap < 0 || cap * width > roomAfter(b, o[1]);
    int64_t found = -1;
    for (int64_t k = 0; !err && found < 0 && k < cap; ++k)
      if (readLe(b, b.ops[1].off + static_cast<uint32_t>(k * width), width) == key) found = k;
    err = err || found < 0;
    if (!err) writeValue(b.s, b.ops[3], static_cast<int32_t>(found));
  }
  w1(b, in.v[0], in.v[1], err);
}

/// Unsigned `width` bytes at `off` (BCD items are digit patterns, not signed values).
uint32_t readRaw(const BlockCall &b, uint32_t off, int width) {
  return static_cast<uint32_t>(readLe(b, off, width)) & (width == 1 ? 0xFFu : 0xFFFFu);
}

/// XMOV (ref 6.5): one item of 1 or 2 bytes (BYT) at the BCD index; W1 = invalid BCD index,
/// index >= capacity (capacity = n + 1 for a table 0..n) or past the table's range.
void bcdIndexedTable(const BlockCall &b) {
  const Inputs in = take(b, 4); // ACT, RST, RW, BYT
  bool err = false;
  if (in.v[0]) {
    const auto &o = b.stmt.ops;
    const int width = in.v[3] ? 2 : 1;
    int64_t index = 0;
    err = !fromBcd(readRaw(b, b.ops[3].off, width), 2 * width, index) || index >= o[0].value ||
          (index + 1) * width > roomAfter(b, o[1]);
    if (!err) {
      const uint32_t t = b.ops[1].off + static_cast<uint32_t>(index * width);
      if (in.v[2])
        writeLe(b, t, width, readRaw(b, b.ops[2].off, width));
      else
        writeLe(b, b.ops[2].off, width, readRaw(b, t, width));
    }
  }
  w1(b, in.v[0], in.v[1], err);
}

/// DSCH (ref 6.7): the first of the capacity items (1 or 2 bytes by BYT, within the table's
/// range) equal to the search data; its index goes to the result as BCD. W1 = not found.
void bcdSearchTable(const BlockCall &b) {
  const Inputs in = take(b, 3); // ACT, RST, BYT
  bool err = false;
  if (in.v[0]) {
    const auto &o = b.stmt.ops;
    const int width = in.v[2] ? 2 : 1;
    const int64_t n = std::min<int64_t>(o[0].value, roomAfter(b, o[1]) / width);
    const uint32_t key = readRaw(b, b.ops[2].off, width);
    int64_t found = -1;
    for (int64_t k = 0; found < 0 && k < n; ++k)
      if (readRaw(b, b.ops[1].off + static_cast<uint32_t>(k * width), width) == key) found = k;
    // A found index the result's BCD digits cannot hold (100 and up with BYT = 0) is an error.
    err = found < 0 || found >= (width == 1 ? 100 : 10000);
    if (!err) writeLe(b, b.ops[3].off, width, toBcd(found, 2 * width));
  }
  w1(b, in.v[0], in.v[1], err);
}

/// What ROT / ROTB output: the result and the direction (W1).
struct Rotation {
  int64_t result = 0;
  bool reverse = false; ///< W1: 1 reverse (position numbers decreasing), 0 forward
};

/// Rotation control (docs/fanuc-pmc.md "Rotation control"): n positions numbered from s (RN0),
/// current c, goal g. False, nothing decided, when n < 2 or c or g is outside s..s + n - 1.
bool rotate(int64_t n, int64_t s, int64_t c, int64_t g, bool dir, bool pos, bool inc, Rotation &r) {
  if (n < 2 || c < s || c > s + n - 1 || g < s || g > s + n - 1) return false;
  const auto mod = [n](int64_t x) { return (x % n + n) % n; };
  const int64_t cc = c - s, gg = g - s;
  const int64_t fwd = mod(gg - cc), rev = mod(cc - gg);
  r.reverse = dir && rev < fwd; // DIR = 1: the shorter way, a tie forward; DIR = 0: forward
  const int64_t steps = r.reverse ? rev : fwd;
  if (inc)
    r.result = pos ? std::max<int64_t>(steps - 1, 0) : steps;
  else
    r.result = pos ? mod(gg + (r.reverse ? 1 : -1)) + s : g; // the position before the goal
  return true;
}

/// W1 of ROT / ROTB, held in the edge slot: the direction of an execution that decided one,
/// else (ACT = 0 or an error) the previous W1.
void rotationW1(const BlockCall &b, bool decided, bool reverse) {
  uint8_t &held = b.s->edge[b.info.slot];
  if (decided) held = reverse;
  b.f.setTop(held != 0);
}

/// ROT: BCD positions and result of 2 digits (BYT = 0, 1 byte) or 4 (BYT = 1, 2 bytes); a digit
/// above 9 or a result with more digits is an error (nothing written).
void bcdRotation(const BlockCall &b) {
  const Inputs in = take(b, 6); // ACT, INC, POS, DIR, BYT, RN0
  Rotation r;
  bool ok = false;
  if (in.v[0]) {
    const int width = in.v[4] ? 2 : 1;
    int64_t c, g;
    ok = fromBcd(readRaw(b, b.ops[1].off, width), 2 * width, c) &&
         fromBcd(readRaw(b, b.ops[2].off, width), 2 * width, g) &&
         rotate(b.stmt.ops[0].value, in.v[5], c, g, in.v[3], in.v[2], in.v[1], r) &&
         r.result < (width == 1 ? 100 : 10000);
    if (ok) writeLe(b, b.ops[3].off, width, toBcd(r.result, 2 * width));
  }
  rotationW1(b, ok, r.reverse);
}

/// ROTB: the position count, positions and result signed binary of the format's bytes.
void binaryRotation(const BlockCall &b) {
  const Inputs in = take(b, 5); // ACT, INC, POS, DIR, RN0
  Rotation r;
  const bool ok = in.v[0] && rotate(readValue(b.s, b.ops[1]), in.v[4], readValue(b.s, b.ops[2]),
                                    readValue(b.s, b.ops[3]), in.v[3], in.v[2], in.v[1], r);
  if (ok) writeValue(b.s, b.ops[4], static_cast<int32_t>(r.result));
  rotationW1(b, ok, r.reverse);
}

void commonCoil(const BlockCall &b) {
  // The COM this coil belongs to is ops[1] statements back (frontends/fanuc); its edge slot holds
  // its ACT of this scan.
  const StmtInfo &com = *(&b.info - b.stmt.ops[1].value);
  const bool on = b.s->edge[com.slot] != 0;
  const bool st0 = b.f.top();
  const Ref &bit = b.ops[0];
  switch (b.stmt.ops[2].value) {
  case 0: // WRT
    writeBit(b.s, bit, on && st0);
    break;
  case 1: // WRT.NOT: 0 while the COM is off
    writeBit(b.s, bit, on && !st0);
    break;
  case 2: // SET
    writeBit(b.s, bit, readBit(b.s, bit) || (on && st0));
    break;
  default: // RST
    writeBit(b.s, bit, readBit(b.s, bit) && !(on && st0));
    break;
  }
}

} // namespace

bool runFanucData(const BlockCall &b) {
  switch (b.c.op) {
  case Op::ParityCheck:
    parity(b);
    return true;
  case Op::ShiftWord:
    shift(b);
    return true;
  case Op::BcdDecode:
    decode(b);
    return true;
  case Op::GroupDecode:
    groupDecode(b);
    return true;
  case Op::BcdConvert:
    convert(b);
    return true;
  case Op::BcdConvertExt:
    convertExt(b);
    return true;
  case Op::CodeTable:
  case Op::CodeTableBinary:
    codeTable(b);
    return true;
  case Op::TableRows: // read by their COD/CODB; ST0 stays
    return true;
  case Op::IndexedTable:
    indexedTable(b);
    return true;
  case Op::SearchTable:
    searchTable(b);
    return true;
  case Op::BcdIndexedTable:
    bcdIndexedTable(b);
    return true;
  case Op::BcdSearchTable:
    bcdSearchTable(b);
    return true;
  case Op::BcdRotation:
    bcdRotation(b);
    return true;
  case Op::BinaryRotation:
    binaryRotation(b);
    return true;
  case Op::CommonBegin:
    b.s->edge[b.info.slot] = b.f.top();
    return true;
  case Op::CommonCoil:
    commonCoil(b);
    return true;
  default:
    return false;
  }
}

} // namespace lj::interp

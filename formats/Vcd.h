// Signal recordings as files (docs/trace.md "Files"): IEEE 1364 value change dump (VCD, for
// GTKWave and PulseView) and CSV. The writers take one row of values per tick, as `run --watch`
// and the serve trace (runtime/SignalTrace.h) produce them; they keep no rows, so a run of
// millions of ticks streams through them.
#pragma once

#include "formats/Address.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace lj::formats {

/// One recorded signal: its name (the address or symbol as the user wrote it) and width in
/// bits: 1 for a bit (a VCD wire), 8, 16 or 32 for a byte, word or double word (a VCD vector).
struct SignalInfo {
  std::string name;
  int bits = 1;
};

/// The width of `addr` in a recording: 1 for a bit, the element's bytes * 8 for an element of
/// the image or of a profile's byte region (`D100:4` = 32), 32 for a timer's elapsed ms and a
/// counter's count (both kept as 32-bit values, ladderjit/abi.h).
int signalBits(const CliAddress &addr);

/// The VCD `$timescale` of a tick of `periodNs`: the largest of 1, 10, 100 s / ms / us / ns that
/// divides the period (1 ms -> "1ms", 8 ms -> "1ms", 100 ms -> "100ms", 250 us -> "10us"), and
/// `unitsPerTick`, the tick's length in that unit (1, 8, 1, 25).
std::string vcdTimescale(uint64_t periodNs, uint64_t &unitsPerTick);

/// `name` as a VCD reference: no white space or control bytes (each becomes `_`), not empty, not
/// starting with `$` (a `_` is put in front), so GTKWave and sigrok read it back as one token.
std::string vcdName(std::string_view name);

/// The VCD writer. One variable per signal: `$var wire 1` for a bit, `$var wire N` (a vector,
/// `bVALUE` lines) for an element. With `splitBits`, an element is written as its N bit wires
/// `NAME[0]`..`NAME[N-1]` instead (PulseView 0.4 / libsigrok 0.5, Debian 12's, read only 1-bit
/// wires and stop at the first vector value). Values are written as two's complement bits of the
/// signal's width; only changes are written, every value at the first row.
class VcdWriter {
public:
  /// `comment` goes into a `$comment` section (the program, the trigger); may be empty.
  VcdWriter(std::vector<SignalInfo> signals, uint64_t periodNs, bool splitBits,
            std::string comment = {});
  /// The declarations, up to and including `$enddefinitions $end`.
  std::string header() const;
  /// Append tick `tick`'s values (one per signal, as readAddress gives them) to `out`: a
  /// `#TIME` line and the changed values. Ticks must increase.
  void row(uint64_t tick, const int64_t *values, std::string &out);
  /// Append the closing `#TIME` of the tick after `lastTick` (so the last row has its length).
  void finish(uint64_t lastTick, std::string &out) const;

private:
  struct Var {
    std::string id;
    int signal; ///< index into signals_
    int bit;    ///< -1: the whole signal; else this bit of it (splitBits)
    int bits;   ///< width of the variable
    uint64_t last = 0;
  };
  std::vector<SignalInfo> signals_;
  std::vector<Var> vars_;
  std::string timescale_, comment_;
  uint64_t unitsPerTick_ = 1;
  bool first_ = true;
};

/// The CSV of a recording: `tick,ms,NAME...` then one line per tick with signed decimal values
/// (as `run --watch` prints them); `triggerTick` >= 0 adds a last column `trigger`, 1 on that
/// tick's row.
std::string csvHeader(const std::vector<SignalInfo> &signals, bool withTrigger);
void csvRow(uint64_t tick, uint64_t periodNs, const int64_t *values, size_t count,
            int64_t triggerTick, std::string &out);

} // namespace lj::formats

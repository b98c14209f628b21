// Parsers of the run inputs a user writes by hand: stimulus files (`@TICK ADDR=VALUE ...`) and
// parameter files (`P12=345`). Errors are `file:line: problem`, never exceptions.
#pragma once

#include "formats/Address.h"
#include "formats/NcCommand.h"

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lj::formats {

/// The assignments of one stimulus line, applied before the scan of `tick`, or (a line
/// `@TICK nc.COMMAND key=value ...`) one command of the simulated NC (docs/simulated-nc.md).
struct StimulusEvent {
  uint64_t tick = 0;
  int32_t line = 0; ///< source line, for messages
  std::vector<Assignment> sets;
  std::vector<NcCommand> nc; ///< at most one; applied after all assignments of the tick
};

/// A whole stimulus file: events in file order, ticks non-decreasing.
struct Stimulus {
  std::vector<StimulusEvent> events;
};

/// Parse stimulus text. Rules (CLI.md `--stimulus`, decisions in README "Stimulus files"):
/// one event per line `@TICK ADDR=VALUE [ADDR=VALUE ...]`, items separated by spaces/tabs;
/// `#` starts a comment; blank lines are ignored; TICK is a decimal >= 0 and must not be
/// smaller than the previous line's (equal ticks are applied in file order); a line needs at
/// least one assignment, or exactly one NC command `nc.NAME key=value ...` instead
/// (docs/simulated-nc.md). `file` names the source in errors (`file:line: ...`).
/// `assign` parses one `ADDR=VALUE` item in the program's dialect (Dialect::parseAssignment).
/// A reader of `ADDR=VALUE` items (a dialect's, perhaps with the program's symbols).
using ItemParser = std::function<std::optional<Assignment>(std::string_view, std::string &)>;
std::optional<Stimulus> parseStimulus(std::string_view text, const std::string &file,
                                      std::string &error, ItemParser assign = nullptr);

/// Parse a parameter file: one `Pn=VALUE` per line (spaces around `=` allowed), `#` comments,
/// blank lines ignored; only whole P elements. Later lines win for the same Pn.
std::optional<std::vector<Assignment>> parseParams(std::string_view text, const std::string &file,
                                                   std::string &error);

/// The parameter file of the program's target `tp` (nullptr or HNC-8: the P values above). A
/// target with system parameters (TargetProfile::SystemParams, FANUC) reads one setting per
/// line, `NAME = VALUE`, `#` comments (docs/fanuc-pmc.md "System parameters"):
/// `COUNTER = BCD` or `BINARY` (the counter data type; an Assignment of Area::None at the
/// parameter byte's offset) and PMC parameter values `ADDR = VALUE` of the areas T, C, K and D
/// in the target's address syntax; with BCD, a value of CTR's counter data (the first range of
/// C) is written as BCD digits and must have as many digits as its bytes hold (a located error
/// `file:line:col: ...` otherwise). Assignments come in file order, the counter data type first.
std::optional<std::vector<Assignment>> parseParams(std::string_view text, const std::string &file,
                                                   std::string &error, const TargetProfile *tp);

/// Size limit of every file a user hands to ladderjit (PROGRAM, plc.dit, stimulus, params,
/// symbols): a 10,000-statement program is about 1 MiB.
inline constexpr size_t kMaxInputFileBytes = size_t{16} << 20;

/// Read a whole file into `out`; false (with `error` naming the file and the reason) if it
/// cannot be read. The one bounded reader of every input: regular files only (a FIFO or device
/// is refused without blocking), at most `maxBytes` (never more is read, whatever the file
/// claims), read errors reported (/proc/self/mem is an error, not an empty file).
bool readFile(const std::string &path, std::string &out, std::string &error,
              size_t maxBytes = kMaxInputFileBytes);

} // namespace lj::formats

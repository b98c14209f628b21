// Parsers of the run inputs a user writes by hand: stimulus files (`@TICK ADDR=VALUE ...`) and
// parameter files (`P12=345`). Errors are `file:line: problem`, never exceptions.
#pragma once

#include "formats/Address.h"
#include "formats/NcCommand.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lj::io {

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
std::optional<Stimulus> parseStimulus(std::string_view text, const std::string &file,
                                      std::string &error);

/// Parse a parameter file: one `Pn=VALUE` per line (spaces around `=` allowed), `#` comments,
/// blank lines ignored; only whole P elements. Later lines win for the same Pn.
std::optional<std::vector<Assignment>> parseParams(std::string_view text, const std::string &file,
                                                   std::string &error);

/// Read a whole file into `out`; false (with `error` naming the file and the reason) if it
/// cannot be read.
bool readFile(const std::string &path, std::string &out, std::string &error);

} // namespace lj::io

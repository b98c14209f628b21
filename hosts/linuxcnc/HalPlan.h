// The pins of the LinuxCNC HAL component (docs/linuxcnc.md): which process-image elements become
// which HAL pins, from the verified program (default: every X bit it reads, every Y bit it
// writes) and an optional map file. Plain C++ without the HAL headers, so the set-up is testable
// and the real-time part (HalComponent.cpp) only copies through precomputed pointers.
#pragma once

#include "formats/Address.h"
#include "ir/Program.h"
#include "pipeline/Dialects.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace lj::hal {

/// HAL pin types the component creates (hal_type_t without HAL_PORT).
enum class PinType : uint8_t { Bit, S32, U32, Float };

/// One pin: HAL `prefix.name`, the element it mirrors and how.
struct PinSpec {
  std::string name; ///< without the component prefix ("x484.5", "cw_key", "speed")
  PinType type = PinType::Bit;
  bool out = false; ///< HAL_OUT: program -> HAL; else HAL_IN: HAL -> program, before each tick
  formats::CliAddress addr;
  /// `addr` resolved to its place in lj_state (Instance::create): the refresh copies through it.
  formats::ResolvedAddress at;
  double scale = 1.0;    ///< float pins: pin = element * scale (in: element = lround(pin / scale))
  bool truncate = false; ///< float input: element = the pin truncated toward zero (ClassicLadder)
};

/// The sizes of classicladder_rt's HAL pins, its loadrt parameters (docs/linuxcnc.md
/// "ClassicLadder drop-in"): as classicladder_rt reads them, a value > 0 overrides the default
/// (15 bit inputs and outputs, 10 s32 and 10 float inputs and outputs).
struct ClassicSizes {
  int32_t physInputs = 0, physOutputs = 0, s32in = 0, s32out = 0, floatIn = 0, floatOut = 0;
};

/// The prefix of the drop-in's pins and function: classicladder_rt's names.
inline constexpr const char *kClassicPrefix = "classicladder.0";

/// The pins classicladder_rt exports for its sizes, in its order: in-NN (%In, bit in), out-NN
/// (%Qn, bit out), s32in-NN (%IWn), s32out-NN (%QWn), floatin-NN (%IFn, truncated toward zero
/// as ClassicLadder reads a float input), floatout-NN (%QFn); NN is printf's %02d. `dialect`
/// (ClassicLadder's) reads the variables. False with `error` naming the parameter when a size
/// is beyond the classicladder profile (%I0..%I511, %IW0..%IW255, %IF0..%IF63...).
bool classicLadderPins(const ClassicSizes &sizes, const pipeline::Dialect &dialect,
                       std::vector<PinSpec> &pins, std::string &error);

/// The longest pin name HAL accepts (HAL_NAME_LEN in hal.h), prefix and dot included.
inline constexpr size_t kHalNameLen = 47;

/// Default pins: every X bit the program reads (contacts, and every bit of an X byte read as
/// a register) becomes an input bit pin, every Y bit it writes an output bit pin, in address
/// order. Named after the symbol of that address when the program has one whose name is a
/// HAL-friendly ASCII name (letters, digits, `_`, `-`; lowercased), else after the address
/// (`x484.5`, `y0.1`; FANUC `x0.0`, `y200.1`; IEC `i0.3`, `q0.1`: the dialect's spelling,
/// lowercased, without `%`). `dialect` spells the addresses (default: HNC-8).
std::vector<PinSpec> defaultPins(const VerifiedProgram &prog,
                                 const pipeline::Dialect &dialect = pipeline::defaultDialect());

/// Parse a map file (format: docs/linuxcnc.md "Map file") and merge it with `defaults`: a line
/// for an address and direction already in the list replaces that pin, other lines add pins
/// (one element may feed several output pins, never two input pins); a `nodefaults` line drops
/// every default pin. `file` names the source in errors (`file:line: ...`). False
/// (with `error`) on any bad line, a duplicate name or address, or a name HAL would refuse.
/// Addresses are `dialect`'s (FANUC `D100:2`, IEC `%MW10`).
bool applyMap(std::string_view text, const std::string &file, std::vector<PinSpec> &pins,
              std::string &error, const pipeline::Dialect &dialect = pipeline::defaultDialect());

/// Check the final list against HAL's rules with `prefix` ("ladderjit"): names unique and at
/// most kHalNameLen long. False (with `error`) otherwise.
bool checkPins(const std::vector<PinSpec> &pins, const std::string &prefix, std::string &error);

} // namespace lj::hal

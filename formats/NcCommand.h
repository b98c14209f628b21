// A scripted action of the simulated NC (`@TICK nc.<command> key=value ...` in a stimulus file),
// kept free of the model so the stimulus parser can produce it without the NC itself.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lj::formats {

/// What a scripted NC command does (grammar and effects: docs/simulated-nc.md).
enum class NcCommandKind {
  MCode,  ///< `nc.mcode ch=C m=M`: the part program reaches M code M (queued if 8 are pending)
  TCode,  ///< `nc.tcode ch=C t=T`: the part program reaches T code T (queued while one pends)
  SCode,  ///< `nc.scode ch=C sp=N s=RPM`: S command for spindle N (0..3), RPM in 0.001 rpm units
  Reset,  ///< `nc.reset ch=C`: panel Reset key (reset handshake, FC[0].12)
  End,    ///< `nc.end ch=C`: the running part program ends (FC[0].5 off, FC[1].2 on)
  Var,    ///< `nc.var type=T offset=O value=V`: preset a CNC variable
  Temp,   ///< `nc.temp sensor=S value=V`: temperature sensor S (0..19) reads V (G3080+S)
  Tool,   ///< `nc.tool pocket=P tool=T`: magazine pocket P holds tool T (0 = empty)
  Mpg,    ///< `nc.mpg n=N delta=D`: handwheel N turned by D pulses (read by mpg_delta)
  ZPulse, ///< `nc.zpulse axis=A`: the Z pulse of a homing axis arrives now (ends phase 2)
};

/// One parsed NC command. Only the fields of its kind are meaningful (see NcCommandKind).
struct NcCommand {
  NcCommandKind kind = NcCommandKind::MCode;
  int32_t line = 0;      ///< stimulus line, for messages
  int32_t ch = 0;        ///< channel (mcode, tcode, scode, reset, end)
  int32_t code = 0;      ///< M or T code; spindle index for scode
  int32_t index = 0;     ///< var type, sensor, pocket, handwheel or axis number
  int32_t offset = 0;    ///< var offset
  int64_t ivalue = 0;    ///< integer value (scode speed, tool, delta, temp, integer var value)
  double fvalue = 0;     ///< value as a double (float variables)
  bool isInteger = true; ///< whether `value=` was written as an integer literal
};

/// The command's keyword as written after `nc.` ("mcode").
const char *ncCommandName(NcCommandKind kind);

/// Parse one command from the items of a stimulus line after `@TICK`: items[0] is `nc.NAME`,
/// the rest `key=value`. On error returns nullopt with `why` naming the problem (no location).
std::optional<NcCommand> parseNcCommand(const std::vector<std::string_view> &items,
                                        std::string &why);

} // namespace lj::formats

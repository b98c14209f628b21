// The verifier's interface: ParsedProgram -> VerifiedProgram (DIALECT.md 6), dialect-neutral.
#pragma once

#include "ir/Diagnostics.h"
#include "ir/Profile.h"
#include "ir/Program.h"

#include <optional>

namespace lj {

/// Options the verifier plans with; an unset one is the program's profile's
/// (TargetProfile::defaultSliceStatements, maxStatements, maxCallDepth).
struct VerifyOptions {
  std::optional<int32_t> plc2Nvalue;    ///< PLC2 statements per tick (0 = one slice)
  std::optional<int32_t> maxStatements; ///< program size limit (DIALECT.md 6)
  std::optional<int32_t> maxCallDepth;  ///< nesting of CALL

  /// These options with every unset limit taken from `tp`.
  VerifyOptions resolved(const TargetProfile &tp) const {
    return {plc2Nvalue.value_or(tp.defaultSliceStatements),
            maxStatements.value_or(tp.maxStatements), maxCallDepth.value_or(tp.maxCallDepth)};
  }
};

/// Check every rule of DIALECT.md 6 and compute stack depths, scopes, jump/call targets, state
/// slots and PLC2 slices. Returns nothing when an error was reported.
std::optional<VerifiedProgram> verify(const ParsedProgram &parsed, const VerifyOptions &opts,
                                      Diagnostics &diags);

} // namespace lj

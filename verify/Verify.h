// The verifier's interface: ParsedProgram -> VerifiedProgram (DIALECT.md 6), dialect-neutral.
#pragma once

#include "ir/Diagnostics.h"
#include "ir/Profile.h"
#include "ir/Program.h"

#include <optional>

namespace lj {

/// Options the verifier plans with; the defaults are the target profile's.
struct VerifyOptions {
  /// PLC2 statements per tick (0 = one slice)
  int32_t plc2Nvalue = targetProfile().defaultSliceStatements;
  int32_t maxStatements = targetProfile().maxStatements; ///< program size limit (DIALECT.md 6)
  int32_t maxCallDepth = targetProfile().maxCallDepth;   ///< nesting of CALL
};

/// Check every rule of DIALECT.md 6 and compute stack depths, scopes, jump/call targets, state
/// slots and PLC2 slices. Returns nothing when an error was reported.
std::optional<VerifiedProgram> verify(const ParsedProgram &parsed, const VerifyOptions &opts,
                                      Diagnostics &diags);

} // namespace lj

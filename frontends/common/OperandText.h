// The operand formatter core: an IR operand in the syntax of a profile-laid dialect, area name,
// element number and `.bit` (HNC-8 `X1.0`, `D5`, `L3`; FANUC `R100.3`, `P10`). IEC IL writes
// its objects otherwise (frontends/iec/Objects.h) and uses only the constant form.
#pragma once

#include "ir/Profile.h"
#include "ir/Program.h"

#include <string>

namespace lj::frontend {

/// A constant as every dialect writes it: the decimal value.
std::string constantText(int32_t value);

/// `op` as `tp` names its areas: "" for no operand, the constant in decimal, the area's name,
/// the element number and, for a bit, `.bit`.
std::string operandText(const TargetProfile &tp, const Operand &op);

} // namespace lj::frontend

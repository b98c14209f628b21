// Whole-state comparison of two lj_state values, naming the first differing field.
#pragma once

#include "ladderjit/abi.h"

#include <cstddef>
#include <optional>
#include <string>

namespace lj::test {

/// Byte offset of the first difference (memcmp order), or nothing when identical.
std::optional<size_t> firstDifference(const lj_state &a, const lj_state &b);

/// Human name of the field holding byte `offset`: `img.D[3] (byte 1)`, `T[130].start_ms`,
/// `edge[17]`, `fault_divzero`, ...
std::string fieldAt(size_t offset);

/// Empty when identical; otherwise "first difference at <field> (offset N): a=... b=...".
std::string describeDifference(const lj_state &a, const lj_state &b, const char *nameA,
                               const char *nameB);

} // namespace lj::test

// The complete lj_state as JSON (`ladderjit run --dump`): every area, timer, counter, edge bit,
// PLS/PLF/ALT state, fault counter and the tick bookkeeping.
#pragma once

#include "ir/Profile.h"
#include "ladderjit/abi.h"

#include <nlohmann/json.hpp>

#include <string>
#include <string_view>

namespace lj::formats {

/// The one way the project writes JSON text that may hold user bytes (paths, diagnostics
/// quoting a file, plc.dit fields): a string that is not valid UTF-8 is written with U+FFFD
/// in place of the bad bytes instead of throwing nlohmann::json's type_error 316.
std::string dumpJson(const nlohmann::json &j, int indent = -1);
std::string dumpJson(const nlohmann::ordered_json &j, int indent = -1);

/// Whether `s` is well-formed UTF-8 (RFC 3629: no overlongs, surrogates or code points above
/// U+10FFFF).
bool isUtf8(std::string_view s);

/// The state as a JSON object:
/// `{"abi_version", "now_ms", "plc2_next_slice", "max_backward_steps", "steps", "last_fault",
///   "faults": {"watchdog", "index", "divzero"},
///   "areas": {"X": [...], ..., "P": [...]}       (values by the area's read rule)
///   "timers": [{"n", "elapsed_ms", "start_ms", "out", "running"}, ...]  (T0..T127, T300..T427)
///   "counters": [{"n", "value", "out", "prev"}, ...]
///   "pls_prev", "plf_prev", "alt_prev", "alt_state": [512 x 0/1], "edge": [16384 x 0/1]}`.
nlohmann::ordered_json stateToJson(const lj_state &s);

/// The state of a program of target `tp`: as above for a target on HNC-8's image; for a target
/// laid out in lj_state.mem (FANUC, IEC) "areas" holds each of its areas by its own name, one
/// value per element (bytes for FANUC; both ranges, in number order, with "<name>@<lo>" for an
/// upper range such as "T@9000"), and "mem_nonzero" the count of non-zero bytes of lj_state.mem.
nlohmann::ordered_json stateToJson(const lj_state &s, const TargetProfile &tp);

} // namespace lj::formats

// A deterministic lj_host (runtime_abi abi.h) for tests and the differential fuzzer: serves CNC
// variables, tool pockets and handwheel deltas from maps, and records every call it receives.
#pragma once

#include "ladderjit/abi.h"

#include <cstdint>
#include <deque>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace lj::hosts {

/// One callback invocation as the host saw it: the callback name (the lj_host member), its
/// value arguments, the values it returned through pointers and its return value (0 for void).
struct HostCall {
  std::string name;
  std::vector<int32_t> args;
  std::vector<int32_t> out;
  int32_t result = 0;
  friend bool operator==(const HostCall &, const HostCall &) = default;
  /// `name(a, b) -> result [out...]`, for failure messages.
  std::string str() const;
};

/// A recording NC host. Each engine under test gets its own instance with the same content, so
/// two engines are equal only if their states AND their call logs are equal.
///
/// Behaviour of the callbacks (documented so tests can derive expected values):
/// - var_get / var_set: a variable (type, offset) exists when the offset is inside the type's
///   range of hnc8-functions-2.md section 3 with 4 channels, 32 axes and 100 tools (type 5:
///   0..7999, 6: 0..3999, 7: 0..3199, 8: 0..1599, 9: 0..19999). Values are doubles in `vars`
///   (missing = 0, or a seeded value). Float types (0, 1, 4, 6, 9) read as trunc(v * 10^exp)
///   and store value / 10^exp; integer types (2, 3, 5, 7, 8) read and store the value as is
///   (a 64-bit value keeps its low 32 bits). Results outside int32 keep their low 32 bits.
/// - mpg_delta(mpg): the next entry of `mpgDeltas[mpg]` (consumed), then 0 (or seeded values).
/// - tool_select(spindle, cmd): found when `pockets` maps cmd -> pocket: *pocket = pocket,
///   returns 1. Otherwise *error = `toolError` (default 7) and returns 0.
/// - spindle_da(ch, sp, rpm, gear, pbase): rpm / 10 + 1000 * gear + 100 * sp + 10 * ch + pbase
///   (int64, low 32 bits), a formula every argument shows up in.
/// - nixie_encode(value, width): BCD of the low 2 (width 0) or 4 (width 1) decimal digits of
///   |value|.
/// - notifications (mpg_input, temp_input, event, save_data, tool_in_use, tool_vector,
///   slave_home) only record the call.
class TestHost {
public:
  /// Empty content: no stored variables (all zero), no pockets, deltas 0.
  TestHost();
  /// Deterministic pseudo-random content from `seed` (0 = empty content): variable values,
  /// handwheel deltas and a few pockets, for the fuzzer.
  explicit TestHost(uint64_t seed);
  TestHost(const TestHost &) = delete;
  TestHost &operator=(const TestHost &) = delete;

  /// The callback table (ctx = this). Install it with `attach`.
  const lj_host *host() const { return &host_; }
  /// s.host := this host.
  void attach(lj_state &s) const { s.host = &host_; }
  /// Set one member of the table to NULL (by its lj_host member name, e.g. "var_get"), to test
  /// the documented defaults. Returns false for an unknown name.
  bool disable(std::string_view callback);

  /// Every call so far, in order.
  const std::vector<HostCall> &calls() const { return calls_; }
  void clearCalls() { calls_.clear(); }
  /// The calls as text, one per line.
  std::string callText() const;

  // ---- content (tests preset these) ----
  /// CNC variables by (type, offset).
  std::map<std::pair<int32_t, int32_t>, double> vars;
  /// Handwheel pulse deltas to serve, per handwheel, front first.
  std::map<int32_t, std::deque<int32_t>> mpgDeltas;
  /// Tool number -> pocket number.
  std::map<int32_t, int32_t> pockets;
  /// Error code tool_select reports for a tool with no pocket.
  int32_t toolError = 7;

  /// Whether variable (type, offset) exists (see the class comment).
  static bool varExists(int32_t type, int32_t offset);
  /// Whether `type` holds floating-point values (types 0, 1, 4, 6, 9).
  static bool isFloatType(int32_t type);

private:
  friend struct TestHostCallbacks;
  void record(const char *name, std::vector<int32_t> args, std::vector<int32_t> out,
              int32_t result);
  double varValue(int32_t type, int32_t offset) const;

  lj_host host_{};
  uint64_t seed_ = 0;
  std::map<int32_t, uint32_t> mpgCalls_; ///< seeded deltas: calls so far per handwheel
  std::vector<HostCall> calls_;
};

} // namespace lj::hosts

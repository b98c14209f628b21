// The signal trace of `ladderjit serve` (docs/trace.md): up to 64 addresses sampled at the end
// of every tick into a ring of pre-trigger ticks, a trigger (an edge of a bit, a comparison of a
// word with a constant, a manual request, or at once), then the post-trigger ticks; a complete
// capture is handed to readers through a triple buffer. In the scan thread a sample is a copy of
// the chosen bytes at precomputed offsets into lj_state: no allocation, no lock, no system call.
#pragma once

#include "formats/Address.h"
#include "formats/Vcd.h"
#include "ladderjit/abi.h"

#include <nlohmann/json.hpp>

#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace lj::rt {

/// Limits of one trace (docs/trace.md "Limits").
constexpr size_t kTraceMaxSignals = 64;
constexpr uint32_t kTraceMaxTicks = 60000; ///< pre + 1 + post: one minute at 1 ms
/// A capture buffer holds (pre + 1 + post) * (8 + the signals' bytes) bytes; three are kept
/// (scan thread, hand-off, reader): at most 3 * 60000 * (8 + 64 * 4) bytes = 47.5 MB.
constexpr size_t kTraceSampleMaxBytes = 8 + kTraceMaxSignals * 4;

enum class TriggerKind : uint8_t {
  Manual,    ///< `monitor trace trigger` (or SignalTrace::triggerNow)
  Immediate, ///< the first tick after arming
  Rising,    ///< the bit (or element != 0) goes from 0 to 1
  Falling,   ///< from 1 to 0
  Compare,   ///< the element compared with a constant holds (and did not on the previous tick)
};
enum class CompareOp : uint8_t { Eq, Ne, Lt, Gt, Le, Ge };

/// A trace definition as written (docs/trace.md "Definition file"), addresses still text.
struct TraceDefinition {
  std::vector<std::string> signals;
  TriggerKind trigger = TriggerKind::Manual;
  std::string triggerAddress; ///< Rising / Falling / Compare
  CompareOp op = CompareOp::Eq;
  int64_t value = 0;
  uint32_t pre = 100, post = 100;
  bool repeat = false;
};

/// Parse a definition file: one item per line, `#` comments, blank lines ignored:
///   signal ADDR[, ADDR...]      (repeatable; 1..64 addresses in all)
///   trigger manual | immediate | rising ADDR | falling ADDR | ADDR OP VALUE  (OP: = <> < > <= >=)
///   pre N | post N              (ticks before / after the trigger tick; pre + 1 + post <= limit)
///   mode single | repeat
/// Errors name `file` and the line.
std::optional<TraceDefinition> parseTraceDefinition(std::string_view text, const std::string &file,
                                                    std::string &error);
/// The definition written back in that format.
std::string formatTraceDefinition(const TraceDefinition &d);

/// The address syntax of the running program (pipeline/Dialects.h parseAddress; symbols where the
/// dialect resolves them).
using AddressParser =
    std::function<std::optional<formats::CliAddress>(std::string_view text, std::string &error)>;

/// One complete capture, as a reader gets it.
struct TraceCapture {
  std::vector<formats::SignalInfo> signals;
  std::vector<uint64_t> ticks; ///< the tick number of each row
  std::vector<int64_t> values; ///< ticks.size() rows of signals.size() values (readAddress's)
  uint64_t triggerTick = 0;
  uint32_t preTicks = 0;  ///< rows before the trigger row
  uint32_t postTicks = 0; ///< rows after it
  uint64_t sequence = 0;  ///< 1, 2, ... per completed capture of this trace
  uint64_t periodNs = 1000000;

  /// The capture as a VCD (formats/Vcd.h; `splitBits`: elements as bit wires) or as CSV.
  std::string vcd(bool splitBits) const;
  std::string csv() const;
};

/// Where a trace stands (any thread).
struct TraceStatus {
  const char *state = "idle"; ///< waiting (for the trigger), recording (post), done, idle
  uint64_t samples = 0;       ///< ticks sampled since arming
  uint64_t captures = 0;      ///< completed captures
  uint64_t dropped = 0;       ///< completed captures replaced before a reader took them
};

class SignalTrace {
public:
  /// Resolve `def`'s addresses with `parse` and lay out the buffers (all allocation happens
  /// here). Null with `error` for a bad address, too many signals, a trigger address that is not
  /// traceable or depths over the limit.
  static std::unique_ptr<SignalTrace> make(const TraceDefinition &def, const AddressParser &parse,
                                           uint64_t periodNs, std::string &error);
  SignalTrace(const SignalTrace &) = delete;
  SignalTrace &operator=(const SignalTrace &) = delete;

  /// Scan thread, at the end of tick `tick` (ticks increase). No allocation, no lock.
  void sample(const lj_state &s, uint64_t tick);
  /// Any thread: fire a waiting trace at its next sample (any trigger kind).
  void triggerNow() { manual_.store(true, std::memory_order_release); }
  /// Any thread: the newest completed capture not taken yet into `out`. False when none.
  bool take(TraceCapture &out);
  TraceStatus status() const;
  const TraceDefinition &definition() const { return def_; }
  const std::vector<formats::SignalInfo> &signals() const { return info_; }

private:
  struct Source {
    uint32_t stateOffset;
    uint16_t rowOffset;
    uint8_t bytes;
    int8_t bit; ///< -1: the element; else the bit read out of it
    bool isSigned;
  };
  struct Slot {
    std::vector<unsigned char> rows; ///< rowBytes_ per row; row: tick (8 bytes), then the bytes
    uint32_t ringLen = 0, ringHead = 0, post = 0;
    uint64_t triggerTick = 0, sequence = 0;
  };
  SignalTrace() = default;
  int64_t decode(const unsigned char *row, const Source &src) const;
  int64_t readNow(const lj_state &s, const Source &src) const;
  void publish();

  TraceDefinition def_;
  std::vector<formats::SignalInfo> info_;
  std::vector<Source> sources_;
  Source trig_{};
  uint32_t rowBytes_ = 8, ringCap_ = 1, post_ = 0;
  uint64_t periodNs_ = 1000000;

  // Scan thread only.
  enum Phase : uint8_t { Waiting, Recording, Done };
  Phase phase_ = Waiting;
  bool havePrev_ = false;
  int64_t prev_ = 0;
  uint64_t sequence_ = 0;
  uint64_t sampled_ = 0;

  // Triple buffer (runtime/TraceBuffer.h's scheme): back_ the scan thread's, front_ readers'.
  Slot slots_[3];
  static constexpr uint32_t kFresh = 4;
  std::atomic<uint32_t> middle_{1};
  uint32_t back_ = 0, front_ = 2;
  std::mutex readMu_;

  std::atomic<bool> manual_{false};
  std::atomic<uint8_t> state_{Waiting};
  std::atomic<uint64_t> samples_{0}, captures_{0}, dropped_{0};
};

class Executive;

/// The trace of a running serve, as the control socket's `trace` command drives it (docs/trace.md
/// "monitor trace"): one definition, armed into the executive, stopped, its last capture saved.
/// Traces live in memory only: nothing survives a restart unless saved.
class TraceControl {
public:
  explicit TraceControl(Executive &exec) : exec_(exec) {}
  ~TraceControl(); ///< disarms (the executive must outlive it)
  TraceControl(const TraceControl &) = delete;
  TraceControl &operator=(const TraceControl &) = delete;

  /// `{"cmd":"trace","action":A,...}` with A one of
  ///   define  "text": a definition (parseTraceDefinition), "file": its name for messages;
  ///           replaces the trace (disarming the old one)
  ///   arm     start sampling (a fresh capture; the last capture stays until a new one completes)
  ///   trigger fire a waiting trace at the next tick
  ///   stop    stop sampling
  ///   status  state, definition, samples, captures, dropped
  ///   save    "format": "vcd" | "csv", "bits": true for --vcd-bits: the last capture's text
  ///   capture status plus "capture", the last capture as JSON (captureJson), unless its "id"
  ///           is "have" (the page polls with the id it holds and gets the rows only once)
  /// `parse`: the running program's address syntax; `periodNs`: the tick.
  nlohmann::json handle(const nlohmann::json &req, const AddressParser &parse, uint64_t periodNs);
  /// serve --trace FILE: define from `text` and arm. False with `error`.
  bool defineAndArm(const std::string &text, const std::string &file, const AddressParser &parse,
                    uint64_t periodNs, std::string &error);

private:
  bool define(const std::string &text, const std::string &file, const AddressParser &parse,
              uint64_t periodNs, std::string &error);
  bool arm(std::string &error);
  bool disarm(std::string &error);
  void collect(); ///< the newest completed capture of the trace into last_

  Executive &exec_;
  std::mutex mu_; // one command at a time
  std::optional<TraceDefinition> def_;
  AddressParser parse_;
  uint64_t periodNs_ = 1000000;
  std::unique_ptr<SignalTrace> trace_; ///< the current trace (armed_: in the executive)
  bool armed_ = false;
  std::optional<TraceCapture> last_;
  uint64_t lastId_ = 0; ///< 1, 2, ... per capture collected, over every trace of this server
};

/// A capture as the live page's trace panel reads it (GET /api/trace, docs/trace.md "Page"):
/// `{"id","capture","period_ns","trigger_tick","trigger_row","rows","signals":[{"name","bits"}],
/// "ticks":{"from":T0,"steps":COLUMN},"columns":[COLUMN...]}`, one column per signal. A COLUMN
/// is a plain array of values, or `{"rle":[v,n,v,n,...]}` (value v repeated n times) when that
/// is shorter: a bit that changes a few times in 60,000 rows costs a few numbers. `steps` are
/// the rows' tick differences (rows - 1 of them; 1 except after ticks that did not run).
nlohmann::json captureJson(const TraceCapture &c, uint64_t id);

} // namespace lj::rt

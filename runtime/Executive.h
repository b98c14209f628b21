// The cyclic executive of `ladderjit serve`: one dedicated scan thread sleeping to absolute
// deadlines (clock_nanosleep, CLOCK_MONOTONIC), running init at start, then per tick: pending
// writes and locks, I/O in, lj_tick, I/O out, locks, publish, after-tick hooks. Online change
// swaps the program at a tick boundary (docs/serve.md).
#pragma once

#include "formats/Address.h"
#include "ir/Engine.h"
#include "ir/Forces.h"
#include "ir/Program.h"
#include "ladderjit/abi.h"
#include "runtime/Exchange.h"
#include "runtime/Stats.h"
#include "runtime/TraceBuffer.h"

#include <atomic>
#include <chrono>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace lj::rt {

class SignalTrace;

/// One loaded program version: the verified program, its engine and the contact forces it was
/// built with (runtime state, kept here and never in `prog`: ir/Forces.h). Immutable once built;
/// the engine refers to `prog` (declared first, so it is destroyed last). Interpreter-first
/// tiering builds further versions of the same program (the same `prog`, shared) with faster
/// engines (ProgramLoader::buildTier, Executive::tierUp).
struct ProgramVersion {
  std::string path; ///< PROGRAM file it came from
  std::string hash; ///< formats::sha256Hash of the file's bytes (`sha256:...`)
  std::string so;   ///< the AOT .so the engine came from; empty for jit / interp
  std::shared_ptr<VerifiedProgram> prog;
  /// A traced build's power-flow trace (ir/Trace.h), null when untraced; outlives `engine`.
  std::unique_ptr<TraceBuffer> trace;
  std::unique_ptr<Engine> engine;
  ContactForces forces; ///< statement id -> forced conducting value (0/1)
  uint64_t id = 0;      ///< 1, 2, ... in load order (a tier of a version keeps its id)
  /// Which build of `prog` this is: a new number for every load and every rebuild with other
  /// forces or tracing (ProgramLoader::rebuild); a tier of a build keeps it. `baseVariant`: the
  /// build this one may replace at a tick boundary (Executive::switchCode): its own variant for a
  /// tier, the variant it was rebuilt from for a rebuild, 0 for a load.
  uint64_t variant = 0, baseVariant = 0;
  EngineTier tier = EngineTier::Interp; ///< which code `engine` is
  int64_t buildNs = 0;                  ///< how long building `engine` took
  // What an online change's statistics need (runtime/Stats.h ChangeRecord): set by the loader
  // (front end, build) and the controller (request, settle wait); requestedNs 0 = not a change.
  int64_t frontendNs = 0, buildCpuNs = 0, requestedNs = 0, settleNs = 0;
  uint32_t groups = 0, groupsCompiled = 0, groupsQuick = 0;
  size_t warnings = 0; ///< the verifier's warnings (serve prints their count, not each one)
};

/// I/O binding called on the scan thread around lj_tick (the simulated NC, a shared-memory
/// host). Must be cheap and never block.
class IoBinding {
public:
  virtual ~IoBinding() = default;
  /// Before the scan: inputs (X, F) into `s`; may set s.host.
  virtual void beforeTick(lj_state &s, uint64_t tick) = 0;
  /// After the scan: consume outputs (G, Y) of `s`.
  virtual void afterTick(lj_state &s, uint64_t tick) = 0;
};

struct ExecutiveOptions {
  uint64_t periodNs = 1000000;              ///< PLC1 period
  uint64_t maxBackwardSteps = 1000000;      ///< watchdog limit per tick (DIALECT.md 4)
  int rtPriority = -1;                      ///< SCHED_FIFO priority, -1 = leave the policy alone
  int cpu = -1;                             ///< pin the scan thread to this CPU, -1 = no pinning
  uint64_t maxTicks = 0;                    ///< stop after this many ticks, 0 = until requestStop
  std::vector<formats::Assignment> powerUp; ///< written after the reset, before the start hooks
  /// For the statistics only (TickStats): CLOCK_MONOTONIC ns of what serve calls its start (the
  /// start of main) and of the program being ready (read and verified); 0 = start() / unknown.
  int64_t startNs = 0, readyNs = 0;
  const char *tierMode = "direct"; ///< a static string: the `--tier` mode, for the statistics
};

class Executive {
public:
  /// Called on the scan thread after publish; keep it cheap (no syscalls, no allocation).
  using AfterTickHook = std::function<void(const lj_state &, uint64_t tick)>;
  /// Called on the scan thread with the state: start hooks after the power-up writes and
  /// before init (restore retained data), stop hooks after the last tick (final save).
  using StateHook = std::function<void(lj_state &)>;
  /// Messages (priority refused, swap applied...); called from the thread that notices.
  using Log = std::function<void(const std::string &)>;

  Executive(Exchange &ex, ExecutiveOptions opts, Log log = nullptr);
  /// Stops the scan thread (stop hooks run) and joins it.
  ~Executive();
  Executive(const Executive &) = delete;
  Executive &operator=(const Executive &) = delete;

  // Configuration: only before start().
  void addAfterTickHook(AfterTickHook h) { after_.push_back(std::move(h)); }
  void addStartHook(StateHook h) { startHooks_.push_back(std::move(h)); }
  void addStopHook(StateHook h) { stopHooks_.push_back(std::move(h)); }
  /// Bindings run in the order added (beforeTick in order, afterTick in order).
  void addIo(IoBinding *io) { io_.push_back(io); }

  /// Reset the state, apply power-up writes and start hooks, run `initial`'s init part and
  /// start ticking. Returns once init has run; false with `error` if the thread cannot start.
  bool start(std::shared_ptr<ProgramVersion> initial, std::string &error);
  /// Replace the program at the next tick boundary (edge memory, PLS/PLF/ALT and inst_word
  /// cleared, everything else kept, then the new init part). Returns when the scan thread has
  /// taken it; the old version is destroyed on the calling thread. False (with `error`) when
  /// the executive is not running or `timeout` passed first.
  bool swap(std::shared_ptr<ProgramVersion> next, std::chrono::milliseconds timeout,
            std::string &error);
  /// Interpreter-first tiering (docs/serve.md "Tiering"): run `faster`, another build of the
  /// running program (the same `prog` object), from the next tick boundary on. Nothing else
  /// happens there: no init, nothing in lj_state is touched (PLC2 continues with its next slice,
  /// edge memories, timers and counters run on), because every engine keeps all program state
  /// in lj_state. False (with `error`) when the running program is no longer `faster->prog` (an
  /// online change or a force came first; `faster` is discarded and counted), when the
  /// executive is not running or `timeout` passed. The replaced version is destroyed here.
  bool tierUp(std::shared_ptr<ProgramVersion> faster, std::chrono::milliseconds timeout,
              std::string &error);
  /// The same switch as tierUp, for any other build of the running program: `next` (built with
  /// other contact forces or traced/untraced, ProgramLoader::rebuild) runs from the next tick
  /// boundary on, on the same lj_state: no init, nothing cleared, the version id unchanged
  /// (docs/serve.md "Forcing"). Taken only while the running build is `next->baseVariant`; false
  /// (with `error`) when another build or an online change came first, when the executive is not
  /// running or `timeout` passed. Logs nothing: the caller says why it switched.
  bool switchCode(std::shared_ptr<ProgramVersion> next, std::chrono::milliseconds timeout,
                  std::string &error);
  /// The signal trace (runtime/SignalTrace.h) sampled at the end of every tick, null for none.
  /// Returns once the scan thread uses `t` and no longer the one before, which may then be
  /// destroyed (at once when the executive is not running). While none is set the scan thread
  /// pays one load and one predictable branch per tick. False (with `error`) on `timeout`.
  bool setSignalTrace(SignalTrace *t, std::chrono::milliseconds timeout, std::string &error);
  /// Ask the scan thread to stop after the current tick (async-signal-unsafe: not from a
  /// signal handler).
  void requestStop() { stop_.store(true, std::memory_order_release); }
  /// Wait for the scan thread to end (after requestStop or maxTicks).
  void join();
  bool running() const { return running_.load(std::memory_order_acquire); }
  uint64_t periodNs() const { return opts_.periodNs; }

  /// The running program version.
  std::shared_ptr<ProgramVersion> current() const;
  /// The version the scan thread runs this tick: only for after-tick hooks (scan thread).
  const ProgramVersion *scanVersion() const { return cur_; }
  /// A copy of the statistics (taken by the scan thread at a tick boundary; after the thread
  /// ended, the final ones).
  TickStats stats() const;
  /// The state; only valid to touch when the scan thread is not running (tests, after join).
  const lj_state &finalState() const { return *state_; }

private:
  void loop();
  void tickOnce(uint64_t tick);
  void takeSwap(uint64_t tick);
  bool takeTierUp(uint64_t tick);
  /// Wait until `counter` moves past `before` (or `refused` past `refusedBefore`): true when
  /// taken; false when refused, stopped or timed out, with `pending` taken back when possible.
  bool waitTaken(std::atomic<ProgramVersion *> &pending, ProgramVersion *offered,
                 const std::atomic<uint64_t> &counter, uint64_t before,
                 const std::atomic<uint64_t> *refused, uint64_t refusedBefore,
                 std::chrono::milliseconds timeout, std::string &error);

  Exchange &ex_;
  ExecutiveOptions opts_;
  Log log_;
  std::vector<AfterTickHook> after_;
  std::vector<StateHook> startHooks_, stopHooks_;
  std::vector<IoBinding *> io_;

  std::unique_ptr<lj_state> state_;
  std::thread thread_;
  std::atomic<bool> stop_{false}, running_{false};

  // Program handoff: swap() parks the next version in pending_; the scan thread takes it and
  // counts swapsTaken_; the owners (shared_ptrs) are only touched off the scan thread.
  ProgramVersion *cur_ = nullptr; // scan thread
  std::atomic<ProgramVersion *> pending_{nullptr};
  std::atomic<uint64_t> swapsTaken_{0};
  std::atomic<ProgramVersion *> pendingTier_{nullptr};
  std::atomic<uint64_t> tiersTaken_{0}, tiersRefused_{0};
  mutable std::mutex ownerMu_;
  std::shared_ptr<ProgramVersion> currentOwner_;
  std::mutex swapMu_; // one swap at a time

  // The signal trace: setSignalTrace parks it in tracePending_ and bumps traceSeq_; the scan
  // thread takes it into trace_ at the end of a tick and acknowledges with traceAck_.
  void traceTick(const lj_state &s, uint64_t tick);
  std::atomic<bool> traceWanted_{false};
  std::atomic<SignalTrace *> tracePending_{nullptr};
  std::atomic<uint64_t> traceSeq_{0}, traceAck_{0};
  SignalTrace *trace_ = nullptr; // scan thread
  std::mutex traceMu_;           // one setSignalTrace at a time

  // Statistics: owned by the scan thread, copied into shared_ on request.
  TickStats scanStats_;
  mutable std::atomic<bool> statsWanted_{false};
  mutable std::atomic<uint64_t> statsCopies_{0};
  mutable std::mutex statsMu_;
  std::unique_ptr<TickStats> shared_;
};

/// Clear what the verifier numbers per program (edge memory, PLS/PLF/ALT arrays, inst_word)
/// and restart PLC2 at its first slice: the state kept across an online change
/// (docs/dialect-notes.md "State details"). `tp`: also the PLS/PLF bytes a profile keeps in
/// lj_state.mem (TargetProfile::BlockState, the FANUC DIFU/DIFD edges).
void clearRenumberedState(lj_state &s, const TargetProfile *tp = nullptr);

} // namespace lj::rt

// The scan thread: absolute-deadline sleeping, the per-tick order of docs/serve.md, the
// catch-up policy for late wake-ups, statistics and the program handoff of online change.
#include "runtime/Executive.h"
#include "runtime/SignalTrace.h"

#include "hosts/SystemBits.h"
#include "ir/Profile.h"

#include <pthread.h>
#include <sched.h>
#include <sys/prctl.h>
#include <time.h>

#include <cerrno>
#include <cstring>
#include <future>

namespace lj::rt {

namespace {

int64_t clockNs(clockid_t clock) {
  timespec ts;
  clock_gettime(clock, &ts);
  return int64_t{ts.tv_sec} * 1000000000 + ts.tv_nsec;
}

int64_t monoNs() { return clockNs(CLOCK_MONOTONIC); }

void sleepUntil(int64_t ns) {
  timespec ts{static_cast<time_t>(ns / 1000000000), static_cast<long>(ns % 1000000000)};
  while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, nullptr) == EINTR) {
  }
}

} // namespace

void clearRenumberedState(lj_state &s, const TargetProfile *tp) {
  std::memset(s.edge, 0, sizeof s.edge);
  if (tp && tp->blockState.rise) { // as pls_prev / plf_prev, where the profile keeps them
    auto *base = reinterpret_cast<unsigned char *>(&s);
    const auto n = static_cast<size_t>(tp->pulseSlots());
    std::memset(base + tp->pulseOffset(true, 0), 0, n);
    std::memset(base + tp->pulseOffset(false, 0), 0, n);
  }
  std::memset(s.pls_prev, 0, sizeof s.pls_prev);
  std::memset(s.plf_prev, 0, sizeof s.plf_prev);
  std::memset(s.alt_prev, 0, sizeof s.alt_prev);
  std::memset(s.alt_state, 0, sizeof s.alt_state);
  std::memset(s.inst_word, 0, sizeof s.inst_word);
  s.plc2_next_slice = 0; // the new program has its own slices
}

Executive::Executive(Exchange &ex, ExecutiveOptions opts, Log log)
    : ex_(ex), opts_(std::move(opts)), log_(std::move(log)), state_(std::make_unique<lj_state>()),
      shared_(std::make_unique<TickStats>()) {
  if (opts_.periodNs == 0) opts_.periodNs = 1000000;
  lj_state_reset(state_.get());
}

Executive::~Executive() {
  requestStop();
  join();
}

void Executive::join() {
  if (thread_.joinable()) thread_.join();
}

std::shared_ptr<ProgramVersion> Executive::current() const {
  std::lock_guard<std::mutex> g(ownerMu_);
  return currentOwner_;
}

bool Executive::start(std::shared_ptr<ProgramVersion> initial, std::string &error) {
  if (thread_.joinable()) {
    error = "the executive was already started";
    return false;
  }
  if (!initial || !initial->engine) {
    error = "no program to run";
    return false;
  }
  {
    std::lock_guard<std::mutex> g(ownerMu_);
    currentOwner_ = initial;
  }
  cur_ = initial.get();
  std::promise<std::vector<std::string>> started;
  std::future<std::vector<std::string>> startedF = started.get_future();
  running_.store(true, std::memory_order_release);
  scanStats_.periodNs = opts_.periodNs;
  scanStats_.tierMode = opts_.tierMode ? opts_.tierMode : "direct";
  scanStats_.startNs = opts_.startNs ? opts_.startNs : monoNs();
  scanStats_.readyNs = opts_.readyNs;
  scanStats_.firstTier = scanStats_.tier = initial->tier;
  thread_ = std::thread([this, &started] {
    std::vector<std::string> notes;
    // The default 50 us timer slack of normal threads would be wake-up jitter of our own making.
    prctl(PR_SET_TIMERSLACK, 1UL, 0UL, 0UL, 0UL);
    // Priority and pinning are best effort: say why not, then run anyway (issue 6 item 1).
    if (opts_.rtPriority >= 0) {
      sched_param sp{};
      sp.sched_priority = opts_.rtPriority;
      if (int rc = pthread_setschedparam(pthread_self(), SCHED_FIFO, &sp); rc != 0)
        notes.push_back("--rt-priority " + std::to_string(opts_.rtPriority) +
                        ": SCHED_FIFO not permitted (" + std::strerror(rc) +
                        "); running with the normal scheduler");
      else
        notes.push_back("scan thread runs SCHED_FIFO priority " + std::to_string(opts_.rtPriority));
    }
    if (opts_.cpu >= 0) {
      cpu_set_t set;
      CPU_ZERO(&set);
      CPU_SET(opts_.cpu, &set);
      if (int rc = pthread_setaffinity_np(pthread_self(), sizeof set, &set); rc != 0)
        notes.push_back("--cpu " + std::to_string(opts_.cpu) + ": pinning not permitted (" +
                        std::strerror(rc) + "); running unpinned");
      else
        notes.push_back("scan thread pinned to CPU " + std::to_string(opts_.cpu));
    }
    lj_state &s = *state_;
    lj_state_reset(&s);
    s.max_backward_steps = opts_.maxBackwardSteps;
    for (const formats::Assignment &a : opts_.powerUp) formats::writeAddress(s, a.addr, a.value);
    for (StateHook &h : startHooks_) h(s);
    ex_.applyPending(s);
    s.now_ms = 0;
    if (uint32_t f = lj_run_init(&s, &cur_->engine->entries()); f != LJ_FAULT_NONE)
      notes.push_back("init: fault " + std::to_string(f) + " (the init part was aborted)");
    ex_.applyLocks(s);
    ex_.publish(s, 0);
    started.set_value(std::move(notes));
    loop();
    for (StateHook &h : stopHooks_) h(s);
    {
      std::lock_guard<std::mutex> g(statsMu_);
      *shared_ = scanStats_;
    }
    running_.store(false, std::memory_order_release);
  });
  for (const std::string &n : startedF.get())
    if (log_) log_(n);
  return true;
}

void Executive::loop() {
  const int64_t period = static_cast<int64_t>(opts_.periodNs);
  int64_t deadline = monoNs() + period;
  uint64_t tick = 0, executed = 0;
  bool swappedLastTick = false; // the previous tick took an online change
  while (!stop_.load(std::memory_order_acquire)) {
    sleepUntil(deadline);
    int64_t woke = monoNs();
    int64_t late = woke - deadline;
    scanStats_.jitter.add(late); // against the deadline it slept for, before any catch-up
    if (late >= period) {
      // Catch-up policy (docs/serve.md): never run a burst of ticks. The deadlines that passed
      // entirely are missed and counted; this tick runs for the latest one that has passed, so
      // tick numbers (and now_ms) keep following real time.
      int64_t m = late / period;
      scanStats_.missedDeadlines += static_cast<uint64_t>(m);
      if (swappedLastTick) scanStats_.missedAfterSwap += static_cast<uint64_t>(m);
      tick += static_cast<uint64_t>(m);
      deadline += m * period;
    }
    uint64_t swapsBefore = scanStats_.swaps;
    uint32_t tiersBefore = scanStats_.tierSwitches;
    tickOnce(tick);
    int64_t end = monoNs();
    if (scanStats_.ticks == 0) {
      scanStats_.firstTickEndNs = end;
      scanStats_.firstTickEndUnixNs = clockNs(CLOCK_REALTIME);
    }
    if (scanStats_.tierSwitches != tiersBefore &&
        scanStats_.tierSwitches <= TickStats::kMaxSwitches)
      scanStats_.switches[scanStats_.tierSwitches - 1].endNs = end;
    scanStats_.scan.add(end - woke);
    if (scanStats_.swaps != swapsBefore && uint64_t(end - woke) > scanStats_.swapTickMaxNs)
      scanStats_.swapTickMaxNs = static_cast<uint64_t>(end - woke);
    deadline += period;
    swappedLastTick = scanStats_.swaps != swapsBefore;
    if (end > deadline) {
      scanStats_.overruns++;
      if (swappedLastTick) scanStats_.swapOverruns++;
    }
    ++tick;
    ++scanStats_.ticks;
    if (statsWanted_.load(std::memory_order_acquire)) {
      std::unique_lock<std::mutex> g(statsMu_, std::try_to_lock);
      if (g.owns_lock()) {
        *shared_ = scanStats_; // fixed-size copy, no allocation
        statsWanted_.store(false, std::memory_order_relaxed);
        statsCopies_.fetch_add(1, std::memory_order_release);
      }
    }
    if (opts_.maxTicks && ++executed >= opts_.maxTicks) break;
  }
}

void Executive::takeSwap(uint64_t tick) {
  // A stop request wins over a pending online change: it is left for swap() to take back.
  if (stop_.load(std::memory_order_acquire)) return;
  ProgramVersion *next = pending_.exchange(nullptr, std::memory_order_acq_rel);
  if (!next) return;
  if (next->requestedNs) { // the new code runs from here: the change's latency ends
    const uint64_t n = scanStats_.changeCount++;
    ChangeRecord &c = scanStats_.changes[n % TickStats::kMaxChanges];
    c = ChangeRecord{};
    c.version = next->id;
    c.tick = tick;
    c.requestedNs = next->requestedNs;
    c.runningNs = monoNs();
    c.settleNs = next->settleNs;
    c.frontendNs = next->frontendNs;
    c.buildNs = next->buildNs - next->frontendNs;
    c.buildCpuNs = next->buildCpuNs;
    c.groups = next->groups;
    c.groupsCompiled = next->groupsCompiled;
    c.groupsQuick = next->groupsQuick;
    c.tier = next->tier;
    scanStats_.latencyNs[n % TickStats::kLatencies] = c.runningNs - c.requestedNs;
  }
  scanStats_.tier = next->tier;
  lj_state &s = *state_;
  cur_ = next;
  clearRenumberedState(s, cur_->prog ? cur_->prog->profile : nullptr);
  // hnc8-core.md 6.2 RESOLUTION: the new program's init part runs at the swap.
  if (lj_run_init(&s, &cur_->engine->entries()) != LJ_FAULT_NONE) scanStats_.faultTicks++;
  scanStats_.swaps++;
  swapsTaken_.fetch_add(1, std::memory_order_release);
}

bool Executive::takeTierUp(uint64_t tick) {
  if (stop_.load(std::memory_order_acquire)) return false;
  ProgramVersion *next = pendingTier_.exchange(nullptr, std::memory_order_acq_rel);
  if (!next) return false;
  // Built for a version an online change has replaced, or from a build (forces, tracing) that
  // another rebuild has replaced since: its code would undo that.
  if (next->prog != cur_->prog || next->baseVariant != cur_->variant) {
    ++scanStats_.tierRefusals;
    tiersRefused_.fetch_add(1, std::memory_order_release);
    return false;
  }
  // The whole switch: the next lj_tick calls other code on the same lj_state.
  if (next->variant != cur_->variant) {
    ++scanStats_.rebuilds; // forces or tracing changed: not a tier switch
  } else {
    if (scanStats_.tierSwitches < TickStats::kMaxSwitches) {
      TierSwitch &w = scanStats_.switches[scanStats_.tierSwitches];
      w.tick = tick;
      w.from = cur_->tier;
      w.to = next->tier;
      w.buildNs = next->buildNs;
    }
    ++scanStats_.tierSwitches;
    if (scanStats_.changeCount) { // the optimized build of the last online change
      ChangeRecord &c = scanStats_.changes[(scanStats_.changeCount - 1) % TickStats::kMaxChanges];
      if (c.version == next->id && c.tier == EngineTier::JitQuick && !c.optimizedNs)
        c.optimizedNs = monoNs();
    }
  }
  scanStats_.tier = next->tier;
  cur_ = next;
  tiersTaken_.fetch_add(1, std::memory_order_release);
  return true;
}

void Executive::tickOnce(uint64_t tick) {
  lj_state &s = *state_;
  ex_.applyPending(s);
  for (IoBinding *io : io_) io->beforeTick(s, tick);
  s.now_ms = tick * opts_.periodNs / 1000000;
  takeSwap(tick); // init of a new version sees this tick's inputs and now_ms
  takeTierUp(tick);
  // The target's system bits (FANUC R9091 clocks, R9015 first scan), as `run` writes them.
  if (cur_->prog && cur_->prog->profile) hosts::writeSystemBits(*cur_->prog->profile, s, tick);
  if (lj_tick(&s, &cur_->engine->entries()) != LJ_FAULT_NONE) scanStats_.faultTicks++;
  for (IoBinding *io : io_) io->afterTick(s, tick);
  ex_.applyLocks(s);
  ex_.publish(s, tick);
  for (AfterTickHook &h : after_) h(s, tick);
  if (traceWanted_.load(std::memory_order_acquire)) [[unlikely]]
    traceTick(s, tick);
}

void Executive::traceTick(const lj_state &s, uint64_t tick) {
  const uint64_t seq = traceSeq_.load(std::memory_order_acquire);
  if (seq != traceAck_.load(std::memory_order_relaxed)) {
    trace_ = tracePending_.load(std::memory_order_acquire);
    traceAck_.store(seq, std::memory_order_release);
  }
  if (trace_) trace_->sample(s, tick);
}

bool Executive::setSignalTrace(SignalTrace *t, std::chrono::milliseconds timeout,
                               std::string &error) {
  std::lock_guard<std::mutex> one(traceMu_);
  tracePending_.store(t, std::memory_order_release);
  const uint64_t seq = traceSeq_.fetch_add(1, std::memory_order_acq_rel) + 1;
  traceWanted_.store(true, std::memory_order_release);
  const auto until = std::chrono::steady_clock::now() + timeout;
  while (running() && traceAck_.load(std::memory_order_acquire) < seq) {
    if (std::chrono::steady_clock::now() >= until) {
      error = "the scan thread did not take the trace in time";
      return false;
    }
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  // Nothing armed: back to the one branch per tick. (Not running: the next start takes the
  // pending value, which is null.)
  if (!t) traceWanted_.store(false, std::memory_order_release);
  return true;
}

bool Executive::waitTaken(std::atomic<ProgramVersion *> &pending, ProgramVersion *offered,
                          const std::atomic<uint64_t> &counter, uint64_t before,
                          const std::atomic<uint64_t> *refused, uint64_t refusedBefore,
                          std::chrono::milliseconds timeout, std::string &error) {
  auto until = std::chrono::steady_clock::now() + timeout;
  while (counter.load(std::memory_order_acquire) == before) {
    if (refused && refused->load(std::memory_order_acquire) != refusedBefore) {
      error = "the running program changed before the new code was ready";
      return false;
    }
    if (std::chrono::steady_clock::now() >= until || !running()) {
      // Take the offer back unless the scan thread grabbed it in the meantime.
      ProgramVersion *expected = offered;
      if (pending.compare_exchange_strong(expected, nullptr)) {
        error = running() ? "the scan thread did not take the new program in time"
                          : "the scan thread is not running";
        return false;
      }
    }
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  return true;
}

bool Executive::swap(std::shared_ptr<ProgramVersion> next, std::chrono::milliseconds timeout,
                     std::string &error) {
  std::lock_guard<std::mutex> one(swapMu_);
  if (!running()) {
    error = "the scan thread is not running";
    return false;
  }
  uint64_t before = swapsTaken_.load(std::memory_order_acquire);
  pending_.store(next.get(), std::memory_order_release);
  if (!waitTaken(pending_, next.get(), swapsTaken_, before, nullptr, 0, timeout, error))
    return false;
  std::shared_ptr<ProgramVersion> old;
  {
    std::lock_guard<std::mutex> g(ownerMu_);
    old = std::move(currentOwner_);
    currentOwner_ = std::move(next);
  }
  old.reset(); // the old engine (and its JITDylib) goes away here, off the scan thread
  if (log_) log_("online change: now running version " + std::to_string(current()->id));
  return true;
}

bool Executive::tierUp(std::shared_ptr<ProgramVersion> faster, std::chrono::milliseconds timeout,
                       std::string &error) {
  if (!switchCode(faster, timeout, error)) return false;
  if (log_)
    log_(std::string("tiering: version ") + std::to_string(current()->id) + " now runs on " +
         engineTierName(current()->tier));
  return true;
}

bool Executive::switchCode(std::shared_ptr<ProgramVersion> next, std::chrono::milliseconds timeout,
                           std::string &error) {
  std::lock_guard<std::mutex> one(swapMu_); // never at the same time as an online change
  if (!running()) {
    error = "the scan thread is not running";
    return false;
  }
  if (!next || !next->engine) {
    error = "no engine to switch to";
    return false;
  }
  {
    std::lock_guard<std::mutex> g(ownerMu_);
    if (!currentOwner_ || currentOwner_->prog != next->prog ||
        currentOwner_->variant != next->baseVariant) {
      error = "the running program changed before the new code was ready";
      return false;
    }
  }
  uint64_t before = tiersTaken_.load(std::memory_order_acquire);
  uint64_t refusedBefore = tiersRefused_.load(std::memory_order_acquire);
  pendingTier_.store(next.get(), std::memory_order_release);
  if (!waitTaken(pendingTier_, next.get(), tiersTaken_, before, &tiersRefused_, refusedBefore,
                 timeout, error))
    return false;
  std::shared_ptr<ProgramVersion> old;
  {
    std::lock_guard<std::mutex> g(ownerMu_);
    old = std::move(currentOwner_);
    currentOwner_ = std::move(next);
  }
  old.reset(); // the replaced engine goes away off the scan thread; the program stays (shared)
  return true;
}

TickStats Executive::stats() const {
  if (running()) {
    uint64_t before = statsCopies_.load(std::memory_order_acquire);
    statsWanted_.store(true, std::memory_order_release);
    for (int i = 0; i < 500 && running(); ++i) {
      if (statsCopies_.load(std::memory_order_acquire) != before) break;
      std::this_thread::sleep_for(std::chrono::microseconds(200));
    }
  }
  std::lock_guard<std::mutex> g(statsMu_);
  return *shared_;
}

} // namespace lj::rt

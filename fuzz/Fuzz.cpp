// The differential fuzzing campaign behind `ladderjit fuzz`: per program a derived seed, a random
// valid program and stimulus, interpreter and JIT in lock step; mismatches minimized and printed.
#include "fuzz/Fuzz.h"

#include "fuzz/ClpFuzz.h"
#include "fuzz/Differential.h"
#include "fuzz/RoundTrip.h"
#include "gen/FanucProgram.h"

#include "gen/IlGenerator.h"
#include "gen/Rng.h"
#include "ir/Profile.h"

#include <algorithm>
#include <chrono>
#include <iomanip>
#include <ostream>

namespace lj::fuzz {

namespace {

const char *tierName(bool fast) { return fast ? "fast" : "optimizing"; }

const char *modeName(TierMode m) {
  switch (m) {
  case TierMode::Fast:
    return "fast";
  case TierMode::Optimizing:
    return "optimizing";
  default:
    return "mixed";
  }
}

/// A random switch schedule: init on a random engine, then 1..4 switches at random ticks, each
/// to an engine other than the one running.
void randomSwitches(gen::Rng &rng, uint32_t ticks, Case &c) {
  c.switched = true;
  c.first = static_cast<SwitchEngine>(rng.range(0, 2));
  SwitchEngine now = c.first;
  const int n = static_cast<int>(rng.range(1, 4));
  std::vector<uint32_t> at;
  for (int i = 0; i < n; ++i)
    at.push_back(static_cast<uint32_t>(rng.range(0, ticks > 0 ? ticks - 1 : 0)));
  std::sort(at.begin(), at.end());
  for (uint32_t t : at) {
    SwitchEngine e = static_cast<SwitchEngine>((static_cast<int>(now) + rng.range(1, 2)) % 3);
    c.switches.push_back({t, e});
    now = e;
  }
}

void countSwitches(const Case &c, FuzzStats &st) {
  SwitchEngine now = c.first;
  for (const SwitchPoint &p : c.switches) {
    if (p.tick >= c.stim.ticks()) break;
    if (now == SwitchEngine::Interp) ++st.interpToJit;
    if (p.engine == SwitchEngine::Interp) ++st.jitToInterp;
    if (now == SwitchEngine::JitFast && p.engine == SwitchEngine::JitOpt) ++st.fastToOpt;
    if (now == SwitchEngine::JitOpt && p.engine == SwitchEngine::JitFast) ++st.optToFast;
    now = p.engine;
  }
}

/// Print a case so it replays: the program, the slicing, the stimulus file.
void printCase(std::ostream &out, const Case &c) {
  out << "--- program (" << c.lines.size() << " statements; --plc2-nvalue " << c.plc2Nvalue;
  if (c.switched) {
    out << "; engine switches: init on " << switchEngineName(c.first);
    for (const SwitchPoint &p : c.switches)
      out << ", " << switchEngineName(p.engine) << " from tick " << p.tick;
  } else {
    out << ", JIT tier " << tierName(c.fastTier);
  }
  out << ") ---\n";
  for (const std::string &l : c.lines) out << l << "\n";
  out << "--- NC host: tests/support/TestHost(" << c.hostSeed << ") per engine ---\n";
  if (c.fanuc && c.stim.counterFormat == TargetProfile::kCounterBcd)
    out << "--- counter data type BCD (--params file: COUNTER = BCD) ---\n";
  out << "--- stimulus (" << c.stim.ticks() << " ticks; --stimulus file) ---\n";
  out << gen::formatStimulus(c.stim);
  out << "--- end ---\n";
}

const char *kindName(Outcome::Kind k) {
  switch (k) {
  case Outcome::Kind::Mismatch:
    return "MISMATCH";
  case Outcome::Kind::EngineError:
    return "ENGINE ERROR";
  case Outcome::Kind::NotVerified:
    return "NOT VERIFIED";
  default:
    return "same";
  }
}

std::string where(const Outcome &o) {
  return o.tick == Outcome::kInitTick ? "after init" : "at tick " + std::to_string(o.tick);
}

} // namespace

FuzzStats runWith(const FuzzOptions &opts, std::ostream &out, const EngineFactory &candidate,
                  const std::function<void(bool)> &minimizing) {
  if (opts.classicladder) return runClp(opts, out, candidate);
  using Clock = std::chrono::steady_clock;
  const auto t0 = Clock::now();
  FuzzStats st;
  uint32_t reported = 0;
  gen::Rng master(opts.seed);
  for (uint64_t i = 0; i < opts.programs; ++i) {
    // One derived seed per program: program i replays alone with the same campaign seed.
    const uint64_t pseed = master.next();
    gen::Rng rng(pseed);
    gen::RandomOptions ro;
    ro.seed = rng.fork();
    ro.statements = static_cast<int32_t>(rng.range(opts.statements / 4 + 1, opts.statements));
    Case c;
    if (opts.fanuc) {
      c.fanuc = true;
      // generateFanuc's size is a rung budget (~0.75 x n rungs of ~7 statements each), so the
      // full `statements` gave ~235 statements, 1.8x the IEC and 5x the HNC-8 generators' and
      // ~27 ms of LLVM codegen per program; half of it lands at the IEC programs' size.
      c.lines = gen::generateFanuc(ro.seed, std::max(ro.statements / 2, 1));
      c.plc2Nvalue = static_cast<int32_t>(rng.chance(30) ? 0 : rng.range(1, 40));
      c.stim = gen::generateFanucStimulus(rng.fork(), opts.ticks);
    } else if (opts.iec) {
      c.iec = true;
      gen::GenProgram gp = gen::generateIl(ro.seed, ro.statements);
      c.lines = std::move(gp.lines);
      c.plc2Nvalue = gp.plc2Nvalue;
      c.stim = gen::generateIlStimulus(rng.fork(), opts.ticks);
    } else {
      gen::GenProgram gp = gen::generateRandom(ro);
      c.lines = std::move(gp.lines);
      c.plc2Nvalue = gp.plc2Nvalue;
      c.stim = gen::generateStimulus(rng.fork(), opts.ticks);
    }
    c.fastTier = opts.tiers == TierMode::Fast || (opts.tiers == TierMode::Mixed && rng.chance(50));
    c.hostSeed = rng.next() | 1; // never 0: the host serves seeded variables, deltas, pockets
    c.trace = opts.trace;
    if (opts.switches) {
      randomSwitches(rng, opts.ticks, c);
      countSwitches(c, st);
    } else {
      ++(c.fastTier ? st.fastPrograms : st.optimizingPrograms);
    }
    ++st.programs;

    Outcome o = runCase(c, candidate);
    st.statements += o.statements;
    st.watchdogTicks += o.watchdogTicks;
    st.divZero += o.divZero;
    st.multiSlice += o.slices > 1;
    st.ticks += o.kind == Outcome::Kind::Same ? c.stim.ticks()
                                              : (o.tick == Outcome::kInitTick ? 0 : o.tick + 1);
    if (o.kind == Outcome::Kind::NotVerified) ++st.notVerified;
    if (o.kind == Outcome::Kind::Mismatch) ++st.mismatches;
    if (o.kind == Outcome::Kind::EngineError) ++st.engineErrors;
    if (opts.progress) {
      st.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
      opts.progress(st, i + 1);
    }
    if (o.kind == Outcome::Kind::Same) continue;
    if (reported >= opts.maxReports) continue;
    ++reported;
    out << kindName(o.kind) << ": program " << i << " of seed " << opts.seed << " (program seed "
        << pseed << ")";
    if (o.kind == Outcome::Kind::Mismatch) out << ' ' << where(o);
    out << "\n  " << o.detail << "\n";
    if (opts.minimize && o.kind != Outcome::Kind::NotVerified) {
      if (minimizing) minimizing(true);
      Case m = minimize(c, o.kind, candidate, opts.minimizeBudget);
      Outcome mo = runCase(m, candidate);
      if (minimizing) minimizing(false);
      out << "minimized " << c.lines.size() << " -> " << m.lines.size() << " statements, "
          << c.stim.ticks() << " -> " << m.stim.ticks() << " ticks; " << kindName(mo.kind)
          << (mo.kind == Outcome::Kind::Mismatch ? " " + where(mo) : "")
          << "\n  first difference: " << mo.detail << "\n";
      printCase(out, m);
    } else {
      printCase(out, c);
    }
  }
  st.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
  if (opts.progress) opts.progress(st, 0);

  out << "fuzz summary: seed " << opts.seed << ", programs " << st.programs << ", ticks/program "
      << opts.ticks << ", tiers "
      << (opts.switches
              ? std::string("switched (interp, fast and optimizing JIT)")
              : std::string(modeName(opts.tiers)) + " (fast " + std::to_string(st.fastPrograms) +
                    ", optimizing " + std::to_string(st.optimizingPrograms) + ")")
      << "\n"
      << "  ticks run " << st.ticks << ", statements executed " << st.statements
      << " (PLC1 + slice per tick, loops and calls counted once), watchdog ticks "
      << st.watchdogTicks << ", division-by-zero faults " << st.divZero
      << ", programs with PLC2 slices > 1 " << st.multiSlice << "\n";
  if (opts.switches)
    out << "  engine switches at random ticks: interp->jit " << st.interpToJit << ", jit->interp "
        << st.jitToInterp << ", fast->opt " << st.fastToOpt << ", opt->fast " << st.optToFast
        << " (each compared tick by tick with an unswitched interpreter run)\n";
  out << "  mismatches " << st.mismatches << ", engine errors " << st.engineErrors
      << ", programs not verified " << st.notVerified << "\n"
      << "  time " << std::fixed << std::setprecision(2) << st.seconds << " s\n";
  out << (st.failures() == 0 ? "PASS\n" : "FAIL\n");
  return st;
}

uint64_t run(const FuzzOptions &opts, std::ostream &out) {
  if (opts.roundTrip) {
    out << (opts.fanuc || opts.iec
                ? "round trip: interpreter on each program against the interpreter on its "
                  "round trip (program -> networks -> JSON -> networks -> program text in the "
                  "dialect -> front end), whose networks must hold the same statements\n"
                : "round trip: interpreter on each program against the interpreter on its ladder "
                  "round trip (STL -> networks -> JSON -> networks -> STL)\n");
    auto counts = std::make_shared<ladder::RungCounts>();
    ladder::RungCounts saved;
    FuzzStats st = runWith(opts, out, roundTripFactory(counts), [&](bool start) {
      if (start)
        saved = *counts; // the minimizer's runs are not programs of the campaign
      else
        *counts = saved;
    });
    out << "round trip rungs: ladder " << counts->ladder << ", stl " << counts->stl << ", marker "
        << counts->marker << "\n";
    if (opts.fanuc || opts.iec)
      out << "round trip: printed " << counts->printed << " of " << st.programs
          << " programs in the dialect (program text -> front end -> verified -> interpreter); "
          << counts->asWritten << " of their " << counts->statements
          << " statements printed as the instruction they were made from was written\n";
    return st.failures();
  }
  if (opts.switches)
    out << "switch mode: each program's engine switches between the interpreter and the JIT "
           "tiers at random ticks on one state, against an unswitched interpreter run\n";
  FuzzStats st = runWith(opts, out, jitFactory());
  return st.failures();
}

} // namespace lj::fuzz

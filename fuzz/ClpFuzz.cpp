// The ClassicLadder differential campaign (fuzz/ClpFuzz.h): generated projects through the
// classicladder pipeline, interpreter against the engine under test, state compared per tick.
#include "fuzz/ClpFuzz.h"

#include "fuzz/Differential.h"
#include "gen/ClpGenerator.h"
#include "gen/Rng.h"
#include "ir/Engine.h"
#include "pipeline/Compile.h"
#include "pipeline/Dialects.h"

#include <chrono>
#include <cstring>
#include <memory>
#include <ostream>

namespace lj::fuzz {

namespace {

/// The HAL inputs a generated project reads (gen::ClpGenSizes: in-NN, s32in-NN, floatin-NN).
std::vector<formats::CliAddress> inputs(const gen::ClpGenSizes &sz) {
  const pipeline::Dialect *d = pipeline::dialectNamed("classicladder");
  std::vector<formats::CliAddress> in;
  auto add = [&](const std::string &name, int n) {
    for (int i = 0; i < n; ++i) {
      std::string err;
      if (auto a = d->parseAddress(name + std::to_string(i), err)) in.push_back(*a);
    }
  };
  add("%I", sz.inputs);
  add("%IW", sz.s32in);
  add("%IF", sz.floatIn);
  return in;
}

} // namespace

FuzzStats runClp(const FuzzOptions &opts, std::ostream &out, const EngineFactory &candidate) {
  FuzzStats st;
  const auto t0 = std::chrono::steady_clock::now();
  const gen::ClpGenSizes sizes;
  const std::vector<formats::CliAddress> in = inputs(sizes);
  uint32_t reports = 0;
  for (uint64_t k = 0; k < opts.programs; ++k) {
    gen::Rng rng(opts.seed * 0x9E3779B97F4A7C15ull + k + 1);
    const uint64_t seed = opts.seed * 1000003ull + k;
    const auto rungs = static_cast<int32_t>(rng.range(2, 16));
    const std::string text = gen::generateClp(seed, rungs, sizes);
    const bool fast =
        opts.tiers == TierMode::Fast || (opts.tiers == TierMode::Mixed && rng.range(0, 1) == 0);
    ++(fast ? st.fastPrograms : st.optimizingPrograms);
    ++st.programs;
    auto report = [&](const std::string &what) {
      if (reports++ < opts.maxReports)
        out << "--- mismatch: generateClp(seed " << seed << ", " << rungs
            << " rungs) (clp_tool gen " << seed << " OUT.clp " << rungs << "): " << what << "\n";
    };
    Diagnostics diags("fuzz.clp");
    std::optional<VerifiedProgram> prog =
        pipeline::compileClp(text, "fuzz.clp", VerifyOptions{}, diags);
    if (!prog) {
      ++st.notVerified;
      report("does not compile:\n" + diags.render());
      continue;
    }
    std::string error;
    std::unique_ptr<Engine> ref = makeInterpreterEngine(*prog);
    std::unique_ptr<Engine> cand = candidate(*prog, fast, error);
    if (!ref || !cand) {
      ++st.engineErrors;
      report("engine build failed: " + error);
      continue;
    }
    auto sa = std::make_unique<lj_state>();
    auto sb = std::make_unique<lj_state>();
    lj_state_reset(sa.get());
    lj_state_reset(sb.get());
    // the thread period: mostly LinuxCNC's 1 ms servo thread, sometimes longer (timers then
    // advance by more than 1 ms a scan)
    const uint64_t period = rng.range(0, 3) ? 1 : static_cast<uint64_t>(rng.range(2, 50));
    uint32_t fa = lj_run_init(sa.get(), &ref->entries());
    uint32_t fb = lj_run_init(sb.get(), &cand->entries());
    std::vector<uint32_t> hold(in.size(), 0);
    bool same = fa == fb && std::memcmp(sa.get(), sb.get(), LJ_STATE_COMPARED_BYTES) == 0;
    uint32_t tick = 0;
    for (; same && tick < opts.ticks; ++tick) {
      for (size_t i = 0; i < in.size(); ++i) {
        if (hold[i]-- > 0) continue;
        hold[i] = static_cast<uint32_t>(rng.range(0, 60));
        const bool bit = in[i].isBit();
        const int64_t v = bit               ? rng.range(0, 1)
                          : rng.range(0, 5) ? rng.range(-20, 100)
                                            : static_cast<int32_t>(rng.next());
        formats::writeAddress(*sa, in[i], v);
        formats::writeAddress(*sb, in[i], v);
      }
      sa->now_ms = sb->now_ms = tick * period;
      fa = lj_tick(sa.get(), &ref->entries());
      fb = lj_tick(sb.get(), &cand->entries());
      ++st.ticks;
      same = fa == fb && std::memcmp(sa.get(), sb.get(), LJ_STATE_COMPARED_BYTES) == 0;
    }
    if (!same) {
      ++st.mismatches;
      report("tick " + std::to_string(tick == 0 ? 0 : tick - 1) + ", period " +
             std::to_string(period) + " ms: " +
             (fa != fb ? "fault code interp=" + std::to_string(fa) + " " + cand->name() + "=" +
                             std::to_string(fb)
                       : firstDifference(*sa, *sb, cand->name())));
    }
    st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (opts.progress) opts.progress(st, k + 1);
  }
  st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  if (opts.progress) opts.progress(st, 0);
  out << "fuzz --dialect classicladder: " << st.programs << " projects, " << st.ticks
      << " ticks, mismatches " << st.mismatches << ", not compiled " << st.notVerified
      << ", engine errors " << st.engineErrors << " (" << st.fastPrograms << " fast, "
      << st.optimizingPrograms << " optimizing), " << st.seconds << " s\n";
  return st;
}

} // namespace lj::fuzz

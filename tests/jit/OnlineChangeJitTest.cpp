// Online change through the incremental compile (docs/incremental.md, docs/serve.md "Online
// change latency"): random one-rung edits of a generated program, each compiled in one
// incremental session as serve does (the touched groups at the fast tier, JitOptions::
// quickLeaves, then the optimized build of the same program), and swapped in on a running state
// with serve's swap semantics (runtime/Executive: renumbered state cleared, the new init part,
// everything else kept). The carried state runs on, tick by tick, on three engines that must
// agree in every byte of lj_state: the interpreter of the edited program, a fresh whole-program
// JIT compile of it, and the session's quick version switched to its optimized version halfway
// (tiering's switch: nothing touched). A key that reuses a group the edit changed, a spine
// reused with the wrong cuts, or an alias naming the wrong group shows up as a state difference.
#include "engines/EngineSpec.h"
#include "frontends/hnc8/FrontEnd.h"
#include "pipeline/Compile.h"
#include "runtime/Executive.h"
#include "tests/jit/JitHarness.h"
#include "tests/support/StateDiff.h"

#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace lj::test {
namespace {

std::vector<std::string> linesOf(const std::string &text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

std::string join(const std::vector<std::string> &lines) {
  std::string s;
  for (const std::string &l : lines) s += l + "\n";
  return s;
}

/// One rung edited: a contact on a bit operand (`LD X3.2`) gets another bit, or its negation
/// (LD <-> LDI, AND <-> ANI, OR <-> ORI). Empty when `line` is no such contact.
std::string editContact(const std::string &line, std::mt19937_64 &rng) {
  const size_t sp = line.find(' ');
  if (sp == std::string::npos) return {};
  const std::string op = line.substr(0, sp);
  static const char *const kPairs[][2] = {{"LD", "LDI"}, {"AND", "ANI"}, {"OR", "ORI"}};
  const char *other = nullptr;
  for (const auto &p : kPairs) {
    if (op == p[0]) other = p[1];
    if (op == p[1]) other = p[0];
  }
  if (!other) return {};
  const size_t dot = line.find('.', sp);
  const bool bitOperand = dot != std::string::npos && dot + 1 < line.size() &&
                          line[dot + 1] >= '0' && line[dot + 1] <= '7' &&
                          (dot + 2 == line.size() || line[dot + 2] == ' ');
  if (bitOperand && rng() % 2) {
    std::string l = line;
    l[dot + 1] = static_cast<char>('0' + (l[dot + 1] - '0' + 1 + rng() % 7) % 8);
    return l;
  }
  return other + line.substr(sp);
}

/// An engine with its program (which must outlive it) and the build's times.
struct Built {
  std::unique_ptr<Engine> engine;
  jit::CompileTimes times;
};

Built inSession(jit::Session &session, const VerifiedProgram &prog, bool quick) {
  jit::JitOptions o;
  o.chunkStatements = 12; // many small groups: most edits leave most groups alone
  o.compileThreads = 2;
  o.quickLeaves = quick;
  Built b;
  std::string error;
  b.engine = session.compile(prog, o, error, &b.times);
  EXPECT_TRUE(b.engine) << error;
  return b;
}

/// serve's swap at the start of tick `tick` (runtime/Executive takeSwap, after that tick's
/// inputs and now_ms): renumbered state cleared, then the new init part.
uint32_t swapIn(lj_state &s, const Engine &e, const Scenario &sc, uint32_t tick) {
  if (sc.hostInputs) sc.hostInputs(tick, s);
  s.now_ms = static_cast<uint64_t>(tick) * sc.periodMs;
  rt::clearRenumberedState(s);
  return lj_run_init(&s, &e.entries());
}

uint32_t tickAfterSwap(lj_state &s, const Engine &e) { return lj_tick(&s, &e.entries()); }

uint32_t tickOn(lj_state &s, const Engine &e, const Scenario &sc, uint32_t tick) {
  if (sc.hostInputs) sc.hostInputs(tick, s);
  s.now_ms = static_cast<uint64_t>(tick) * sc.periodMs;
  return lj_tick(&s, &e.entries());
}

TEST(OnlineChangeJit, RandomOneRungEditsMatchInterpreterAndFreshCompile) {
  constexpr uint32_t kTicksPerVersion = 40, kEdits = 12;
  for (uint64_t seed : {301u, 302u, 303u, 304u}) {
    std::string text;
    std::optional<VerifiedProgram> first = randomProgramOrFail(seed, 500, &text);
    ASSERT_TRUE(first) << text;
    // Every version's ticks, plus the swap tick of each edit.
    Scenario sc = randomScenario(seed, (kTicksPerVersion + 1) * (kEdits + 1), 7, 3000);
    std::string error;
    std::shared_ptr<jit::Session> session = jit::Session::create(jit::Tier::Optimizing, error);
    ASSERT_TRUE(session) << error;
    session->enableIncremental();
    std::mt19937_64 rng(seed);
    std::vector<std::string> lines = linesOf(text);

    // The running program: interpreter state, JIT state (the session's versions).
    auto prog = std::make_unique<VerifiedProgram>(std::move(*first));
    Result<std::unique_ptr<Engine>> interp =
        engines::makeEngine({engines::EngineKind::Interp, {}}, *prog);
    ASSERT_TRUE(interp) << interp.status().message();
    Built jitv = inSession(*session, *prog, false);
    ASSERT_TRUE(jitv.engine);
    auto si = std::make_unique<lj_state>(), sj = std::make_unique<lj_state>();
    lj_state_reset(si.get());
    si->max_backward_steps = sc.maxBackwardSteps;
    if (sc.hostBefore) sc.hostBefore(*si);
    *sj = *si;
    ASSERT_EQ(lj_run_init(si.get(), &(*interp)->entries()),
              lj_run_init(sj.get(), &jitv.engine->entries()));
    uint32_t tick = 0, quickEdits = 0;
    std::vector<std::unique_ptr<VerifiedProgram>> keep; // programs outlive their engines
    std::unique_ptr<Engine> fresh, opt;                 // this version's other builds
    for (uint32_t edit = 0; edit <= kEdits; ++edit) {
      // kTicksPerVersion ticks on this version; the session's quick version switches to its
      // optimized build halfway, as serve's ChangeOptimizer does.
      std::unique_ptr<lj_state> sf;
      if (fresh) sf = std::make_unique<lj_state>(*si);
      for (uint32_t k = 0; k < kTicksPerVersion; ++k, ++tick) {
        if (k == kTicksPerVersion / 2 && opt) jitv.engine = std::move(opt);
        uint32_t fi = tickOn(*si, **interp, sc, tick);
        uint32_t fj = tickOn(*sj, *jitv.engine, sc, tick);
        ASSERT_EQ(fi, fj) << "seed " << seed << " edit " << edit << " tick " << tick;
        ASSERT_FALSE(firstDifference(*si, *sj))
            << "seed " << seed << " edit " << edit << " tick " << tick << ": "
            << describeDifference(*si, *sj, "interp", "incremental jit");
        if (sf) {
          uint32_t ff = tickOn(*sf, *fresh, sc, tick);
          ASSERT_EQ(fi, ff);
          ASSERT_FALSE(firstDifference(*si, *sf))
              << "seed " << seed << " edit " << edit << " tick " << tick << ": "
              << describeDifference(*si, *sf, "interp", "fresh jit");
        }
      }
      if (edit == kEdits) break;
      // One rung edited (a contact that verifies again), compiled as serve compiles it.
      std::unique_ptr<VerifiedProgram> next;
      for (int attempt = 0; attempt < 200 && !next; ++attempt) {
        const size_t at = rng() % lines.size();
        std::string l = editContact(lines[at], rng);
        if (l.empty()) continue;
        std::vector<std::string> edited = lines;
        edited[at] = l;
        Diagnostics d;
        std::optional<VerifiedProgram> v =
            pipeline::compileStl(join(edited), "edit.stl", optionsWithNvalue(prog->plc2Nvalue), d);
        if (!v) continue;
        next = std::make_unique<VerifiedProgram>(std::move(*v));
        lines = std::move(edited);
      }
      ASSERT_TRUE(next) << "seed " << seed << ": no contact to edit";
      Built quick = inSession(*session, *next, true);
      ASSERT_TRUE(quick.engine);
      EXPECT_LT(quick.times.leavesCompiled, quick.times.leaves) << "seed " << seed;
      if (quick.times.leavesQuick) ++quickEdits;
      Built o = inSession(*session, *next, false);
      ASSERT_TRUE(o.engine);
      EXPECT_EQ(o.times.leavesQuick, 0u);
      Result<std::unique_ptr<Engine>> ni =
          engines::makeEngine({engines::EngineKind::Interp, {}}, *next);
      ASSERT_TRUE(ni) << ni.status().message();
      jit::JitOptions whole; // a fresh whole-program compile of the edited program
      fresh = jit::compile(*next, whole, error);
      ASSERT_TRUE(fresh) << error;
      // The swap at the next tick: the same carried state on every engine, the new init part,
      // then that tick on the new code.
      ASSERT_EQ(swapIn(*si, **ni, sc, tick), swapIn(*sj, *quick.engine, sc, tick));
      ASSERT_FALSE(firstDifference(*si, *sj))
          << "seed " << seed << " edit " << edit << " after the swap's init: "
          << describeDifference(*si, *sj, "interp", "incremental jit");
      ASSERT_EQ(tickAfterSwap(*si, **ni), tickAfterSwap(*sj, *quick.engine));
      ++tick;
      interp = std::move(ni);
      jitv.engine = std::move(quick.engine);
      opt = std::move(o.engine);
      keep.push_back(std::move(prog));
      prog = std::move(next);
    }
    // An edit of a contact whose group was not cached runs quick first (most of them).
    EXPECT_GT(quickEdits, 0u) << "seed " << seed;
  }
}

} // namespace
} // namespace lj::test

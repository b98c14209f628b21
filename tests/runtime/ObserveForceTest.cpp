// Watching and forcing never disturb the machine (issue 28 finding 1, docs/serve.md "Forcing"):
// the live view's traced code and every force are other builds of the running program switched in
// at a tick boundary on the same lj_state, never an online change. So no init runs, no memory is
// cleared, PROGRAM is not read again and the version stays the same: a served run with pages
// opening and closing and contacts forced and restored equals, tick for tick, a run of the
// interpreter alone with the same forces from the same ticks.
#include "runtime/Controller.h"
#include "runtime/Executive.h"
#include "runtime/ProgramLoader.h"

#include "engines/EngineSpec.h"
#include "engines/LlvmBackend.h"
#include "formats/InputFiles.h"
#include "hosts/SimNc.h"
#include "hosts/SystemBits.h"
#include "ir/Profile.h"
#include "pipeline/Dialects.h"
#include "pipeline/ProgramFile.h"
#include "tests/support/EngineRegistry.h"
#include "tests/support/StateDiff.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <mutex>
#include <random>
#include <sstream>
#include <thread>

namespace lj::rt {
namespace {

std::string examplePath(const char *name) { return std::string(LJ_EXAMPLES_DIR) + "/" + name; }

std::string readText(const std::string &path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// A 64-bit digest of the whole state but the host pointer (which differs between two runs).
uint64_t digest(const lj_state &s, lj_state &scratch) {
  std::memcpy(&scratch, &s, sizeof s);
  scratch.host = nullptr;
  const auto *p = reinterpret_cast<const unsigned char *>(&scratch);
  uint64_t h = 0x9E3779B97F4A7C15ull;
  size_t i = 0;
  for (; i + 8 <= sizeof scratch; i += 8) {
    uint64_t w;
    std::memcpy(&w, p + i, 8);
    h = (h ^ w) * 0x100000001B3ull;
    h ^= h >> 29;
  }
  for (; i < sizeof scratch; ++i) h = (h ^ p[i]) * 0x100000001B3ull;
  return h;
}

// The stimulus as serve would apply it: each event before the scan of its tick (events of a tick
// number the executive skipped, a missed deadline, come with the next tick it runs).
class StimulusBinding : public IoBinding {
public:
  explicit StimulusBinding(const formats::Stimulus &st) : st_(st) {}
  void beforeTick(lj_state &s, uint64_t tick) override {
    while (next_ < st_.events.size() && st_.events[next_].tick <= tick) {
      for (const formats::Assignment &a : st_.events[next_].sets)
        formats::writeAddress(s, a.addr, a.value);
      ++next_;
    }
  }
  void afterTick(lj_state &, uint64_t) override {}

private:
  const formats::Stimulus &st_;
  size_t next_ = 0;
};

class NcBinding : public IoBinding {
public:
  hosts::SimNc nc;
  void beforeTick(lj_state &s, uint64_t tick) override { nc.beforeTick(s, tick); }
  void afterTick(lj_state &s, uint64_t tick) override { nc.afterTick(s, tick); }
};

// lathe_panel.stim, then a seeded operator session over the rest of the run: mode keys, spindle
// keys, the guard door, jog keys and the NC's mode answers, each held for 5-300 ms.
std::string sessionStimulus(uint64_t ticks) {
  std::string text = readText(examplePath("lathe_panel.stim"));
  std::mt19937 rng(28);
  const char *keys[] = {"X480.0", "X480.2", "X480.3", "X480.4", "X482.7", "X484.5",
                        "X484.6", "X484.7", "X483.0", "X484.2", "X482.1"};
  uint64_t t = 120;
  while (t + 400 < ticks) {
    const char *k = keys[rng() % (sizeof keys / sizeof *keys)];
    uint64_t hold = 5 + rng() % 296;
    text += "@" + std::to_string(t) + " " + k + "=1\n";
    if (rng() % 3 == 0)
      text += "@" + std::to_string(t + 2) + " F2560=" + std::to_string(1 + rng() % 5) + "\n";
    text += "@" + std::to_string(t + hold) + " " + k + "=0\n";
    t += hold + 1 + rng() % 400;
  }
  return text;
}

struct Recorded {
  uint64_t tick = 0;
  uint64_t variant = 0; // the build that ran the tick
  uint64_t digest = 0;
};

enum class Served { Interp, Jit, Aot };

const char *servedName(Served s) {
  return s == Served::Interp ? "interp" : s == Served::Jit ? "jit" : "aot";
}

// The build of lathe_panel.stl that an AOT server serves: `ladderjit compile`'s path (the JIT
// library's shared object, signed with the test key) into a temporary file.
std::string compileAot(const std::string &program, std::string &error) {
  pipeline::ProgramSource src;
  if (Status st = pipeline::readProgramFile(program, src, ""); !st.ok()) {
    error = st.message();
    return {};
  }
  const int32_t nvalue = pipeline::effectiveNvalue(src, 200, false);
  std::string diags;
  std::optional<VerifiedProgram> prog = pipeline::verifyProgram(src, nvalue, diags);
  if (!prog) {
    error = diags;
    return {};
  }
  const engines::LlvmBackend *llvm = engines::llvmBackend(error);
  if (!llvm) return {};
  std::string out =
      (std::filesystem::temp_directory_path() / ("ljobserve-" + std::to_string(::getpid()) + ".so"))
          .string();
  engines::AotExpect id = engines::aotExpectOf(src, nvalue);
  jit::AotOptions o;
  o.output = out;
  o.programHash = id.program;
  o.sourceHash = id.source;
  o.plc2Nvalue = nvalue;
  o.signingKey = &test::testSigningKey();
  if (!llvm->compileSharedObject(*prog, o, error)) return {};
  return out;
}

class ObserveForce : public ::testing::TestWithParam<Served> {};

// The acceptance run of issue 28 finding 1: LJ_OBSERVE_SECONDS (default 60) of serve's scan at
// 1 ms with the stimulus, 20 pages opening and closing (the live view's traced builds, first on the
// interpreter and then the JIT, as ServeHttp does) and contacts forced on, off and restored, on the
// served engine; then the interpreter alone replays the same ticks with the same forces from the
// tick each took effect, and every tick's complete state and every NC call must be equal.
TEST_P(ObserveForce, ServedRunEqualsInterpreterWithTheSameForces) {
  const Served served = GetParam();
  const char *env = std::getenv("LJ_OBSERVE_SECONDS");
  const uint64_t seconds = env ? std::strtoull(env, nullptr, 10) : 60;
  const uint64_t ticks = seconds * 1000;
  const std::string program = examplePath("lathe_panel.stl");
  std::string err;
  std::optional<formats::Stimulus> stim = formats::parseStimulus(
      sessionStimulus(ticks), "session.stim", err, pipeline::defaultDialect().parseAssignment);
  ASSERT_TRUE(stim) << err;

  std::string so;
  if (served == Served::Aot) {
    so = compileAot(program, err);
    ASSERT_FALSE(so.empty()) << err;
  }
  struct Unlink {
    std::string p;
    ~Unlink() {
      if (!p.empty()) std::remove(p.c_str());
    }
  } unlinkSo{so};
  ProgramLoader loader(servedName(served), -1);
  if (served == Served::Aot) loader.setAotTrust(test::testTrust());
  std::shared_ptr<ProgramVersion> first = loader.load(program, {}, err, nullptr, so);
  ASSERT_TRUE(first) << err;
  const uint64_t version = first->id;
  std::shared_ptr<VerifiedProgram> prog = first->prog;

  // The contacts forced: every contact of PLC1 and the subroutines (lathe_panel: ~40).
  std::vector<StmtId> contacts;
  for (const Stmt &st : prog->stmts)
    if (isContact(st.op)) contacts.push_back(st.id);
  ASSERT_GE(contacts.size(), 10u);

  Exchange ex;
  ExecutiveOptions eo;
  eo.periodNs = 1000000;
  eo.maxTicks = ticks;
  std::vector<std::string> logs;
  std::mutex logMu;
  auto log = [&](const std::string &l) {
    std::lock_guard<std::mutex> g(logMu);
    logs.push_back(l);
  };
  Executive exec(ex, eo, log);
  StimulusBinding stimBinding(*stim);
  NcBinding ncBinding;
  exec.addIo(&stimBinding);
  exec.addIo(&ncBinding);
  exec.addStartHook([&](lj_state &s) { ncBinding.nc.powerUp(s); });
  std::vector<Recorded> rec;
  rec.reserve(ticks + 16);
  auto scratch = std::make_unique<lj_state>();
  exec.addAfterTickHook([&](const lj_state &s, uint64_t tick) {
    const ProgramVersion *v = exec.scanVersion();
    if (rec.size() < rec.capacity()) rec.push_back({tick, v->variant, digest(s, *scratch)});
  });
  // Which forces each build carries (the test thread notes every build it sees).
  std::map<uint64_t, ContactForces> forcesOf;
  forcesOf[first->variant] = first->forces;
  ASSERT_TRUE(exec.start(first, err)) << err;
  first.reset();
  Controller ctl(ex, exec, loader, program, log, so);
  auto note = [&] {
    std::shared_ptr<ProgramVersion> cur = exec.current();
    forcesOf[cur->variant] = cur->forces;
    EXPECT_EQ(cur->id, version) << "the program version changed";
  };

  std::mt19937 rng(1028);
  const auto t0 = std::chrono::steady_clock::now();
  const auto until = t0 + std::chrono::seconds(seconds) - std::chrono::milliseconds(800);
  int pages = 0, forceActions = 0;
  bool traced = false;
  while (exec.running() && std::chrono::steady_clock::now() < until) {
    // About 150 actions over the run (60 s: one every 200-600 ms).
    const uint64_t pace = std::max<uint64_t>(20, seconds * 1000 / 150);
    std::this_thread::sleep_for(std::chrono::milliseconds(pace / 2 + rng() % pace));
    const bool pageAction = rng() % 2 == 0;
    if (pageAction && pages < 40 && served == Served::Aot) {
      // An AOT .so is never traced: the page is refused its power flow, and nothing changes.
      EXPECT_FALSE(ctl.setTraced(true, err, true));
      EXPECT_FALSE(ctl.setTraced(true, err));
      EXPECT_TRUE(ctl.setTraced(false, err)) << err;
      ++pages;
    } else if (pageAction && pages < 40) { // 20 opens and 20 closes
      if (!traced) {
        ASSERT_TRUE(ctl.setTraced(true, err, true)) << err; // interim traced interpreter
        note();
        ASSERT_TRUE(ctl.setTraced(true, err)) << err; // then the traced JIT build
      } else {
        ASSERT_TRUE(ctl.setTraced(false, err)) << err;
      }
      traced = !traced;
      ++pages;
    } else {
      const StmtId id = contacts[rng() % contacts.size()];
      const char *modes[] = {"on", "off", "restore"};
      nlohmann::json r = ctl.handle({{"cmd", "force"}, {"id", id}, {"mode", modes[rng() % 3]}});
      if (r["ok"].get<bool>())
        ++forceActions;
      else
        EXPECT_NE(r["error"].get<std::string>().find("is not forced"), std::string::npos)
            << r.dump();
    }
    note();
  }
  // Everything restored and the pages closed before the end: the served engine runs its own
  // untraced code again (an AOT server its .so).
  const ContactForces left = exec.current()->forces;
  for (const auto &[id, v] : left) {
    nlohmann::json r = ctl.handle({{"cmd", "force"}, {"id", id}, {"mode", "restore"}});
    EXPECT_TRUE(r["ok"].get<bool>()) << r.dump();
    note();
  }
  if (traced) {
    ASSERT_TRUE(ctl.setTraced(false, err)) << err;
  }
  note();
  // Wait for a background optimized build (ChangeOptimizer) to end before the state is read.
  while (ctl.busy()) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  note();
  exec.join();
  ctl.shutdown();
  EXPECT_GE(pages, 20) << "fewer page opens and closes than asked";
  EXPECT_GE(forceActions, 20);
  TickStats st = exec.stats();
  EXPECT_EQ(st.swaps, 0u) << "an online change happened";
  EXPECT_GT(st.rebuilds, 20u);
  EXPECT_EQ(exec.current()->id, version);
  if (served == Served::Aot) {
    EXPECT_EQ(exec.current()->tier, EngineTier::Aot) << "the .so is not served again";
  }
  ASSERT_EQ(rec.size(), ticks);
  {
    std::lock_guard<std::mutex> g(logMu);
    for (const std::string &l : logs) {
      EXPECT_EQ(l.find("online change"), std::string::npos) << l;
    }
  }

  // The replay: the interpreter alone, the same bindings' rules, the forces of the build that ran
  // each tick in the served run.
  std::map<uint64_t, std::unique_ptr<Engine>> interp;
  for (const auto &[variant, forces] : forcesOf) {
    engines::EngineOptions o;
    o.forces = forces;
    Result<std::unique_ptr<Engine>> e =
        engines::makeEngine(engines::EngineSpec{engines::EngineKind::Interp, {}}, *prog, o);
    ASSERT_TRUE(e) << e.status().message();
    interp[variant] = std::move(e).value();
  }
  auto s = std::make_unique<lj_state>();
  lj_state_reset(s.get());
  s->max_backward_steps = eo.maxBackwardSteps;
  StimulusBinding stim2(*stim);
  NcBinding nc2;
  nc2.nc.powerUp(*s);
  s->now_ms = 0;
  ASSERT_TRUE(interp.count(rec[0].variant));
  lj_run_init(s.get(), &interp.at(rec[0].variant)->entries());
  for (const Recorded &r : rec) {
    auto it = interp.find(r.variant);
    ASSERT_NE(it, interp.end()) << "tick " << r.tick << " ran a build the test never saw";
    stim2.beforeTick(*s, r.tick);
    nc2.beforeTick(*s, r.tick);
    s->now_ms = r.tick * eo.periodNs / 1000000;
    if (prog->profile) hosts::writeSystemBits(*prog->profile, *s, r.tick);
    lj_tick(s.get(), &it->second->entries());
    nc2.afterTick(*s, r.tick);
    ASSERT_EQ(digest(*s, *scratch), r.digest)
        << servedName(served) << ": the state differs after tick " << r.tick << " (build "
        << r.variant << ")";
  }
  EXPECT_EQ(nc2.nc.calls(), ncBinding.nc.calls()) << "the NC calls differ";
  EXPECT_EQ(nc2.nc.events(), ncBinding.nc.events()) << "the NC events differ";
  const lj_state &fin = exec.finalState();
  EXPECT_FALSE(test::firstDifference(fin, *s))
      << test::describeDifference(fin, *s, "served", "interpreter");
}

INSTANTIATE_TEST_SUITE_P(Engines, ObserveForce,
                         ::testing::Values(Served::Interp, Served::Jit, Served::Aot),
                         [](const auto &info) { return std::string(servedName(info.param)); });

// The reproduction of the finding, quickly: a page opening (traced code) and a force after the
// operator chose auto mode leave the mode latches alone (init would set R0.2 = manual again) and
// the edge memory and the counter of ticks run on.
TEST(ObserveForce, OpeningAPageOrForcingRunsNoInit) {
  // Line 12 is LD X2.0. Init: manual mode (R0.2) and D10 = 100; PLC1 counts ticks in D10 and
  // rising edges of X1.0 in D12 (DIALECT.md 5: a block runs while its input is 1).
  const char *kProgram = R"(
LDT
OUT R0.2
MOV 100 D10
IEND
LDT
ADD D10 1 D10
LDP X1.0
SET R0.0
RST R0.2
ADD D12 1 D12
LD X2.0
OUT Y1.0
1END
2END
)";
  std::string path = (std::filesystem::temp_directory_path() /
                      ("ljobserve-" + std::to_string(::getpid()) + ".stl"))
                         .string();
  std::ofstream(path) << kProgram;
  for (const char *engine : {"interp", "jit"}) {
    SCOPED_TRACE(engine);
    ProgramLoader loader(engine, -1);
    std::string err;
    auto v = loader.load(path, {}, err);
    ASSERT_TRUE(v) << err;
    Exchange ex;
    Executive exec(ex, ExecutiveOptions{});
    ASSERT_TRUE(exec.start(v, err)) << err;
    Controller ctl(ex, exec, loader, path, nullptr);
    auto tickOnce = [&] { ASSERT_TRUE(ex.waitApplied(ex.post({}), std::chrono::seconds(30))); };
    std::optional<formats::Assignment> press =
        pipeline::defaultDialect().parseAssignment("X1.0=1", err);
    ASSERT_TRUE(press) << err;
    ex.post({*press});
    tickOnce();
    tickOnce();
    // The file on disk changes: neither the view nor a force may read it.
    std::ofstream(path, std::ios::trunc) << "LDT\nOUT Y9.0\n1END\n2END\n";
    auto s = std::make_unique<lj_state>();
    ASSERT_TRUE(ex.snapshot(*s));
    ASSERT_EQ(s->img.R[0] & 0x05, 0x01); // auto latched, manual reset
    ASSERT_EQ(s->img.D[12], 1);          // one rising edge of X1.0 (held at 1 from now on)
    const int32_t d10 = s->img.D[10];
    ASSERT_GT(d10, 100);
    ASSERT_TRUE(ctl.setTraced(true, err, true)) << err;
    ASSERT_TRUE(ctl.setTraced(true, err)) << err;
    nlohmann::json r = ctl.handle({{"cmd", "force"}, {"line", 12}, {"mode", "on"}});
    ASSERT_TRUE(r["ok"].get<bool>()) << r.dump();
    tickOnce();
    tickOnce();
    ASSERT_TRUE(ex.snapshot(*s));
    EXPECT_EQ(s->img.R[0] & 0x05, 0x01) << "init ran again (R0.2 set)";
    EXPECT_GE(s->img.D[10], d10 + 2) << "init ran again (D10 = 100 + ticks since)";
    EXPECT_EQ(s->img.D[12], 1) << "the edge memory was cleared: held X1.0 seen as a new edge";
    EXPECT_EQ(s->img.Y[1] & 1, 1) << "the force did not take effect";
    EXPECT_EQ(s->img.Y[9] & 1, 0) << "the changed file went live";
    ASSERT_TRUE(ctl.setTraced(false, err)) << err;
    EXPECT_EQ(exec.current()->id, v->id);
    EXPECT_EQ(exec.stats().swaps, 0u);
    std::ofstream(path, std::ios::trunc) << kProgram;
    exec.requestStop();
    exec.join();
    ctl.shutdown();
  }
  std::remove(path.c_str());
}

} // namespace
} // namespace lj::rt

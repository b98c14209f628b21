// The cyclic executive (docs/serve.md): now_ms per tick, init at start, online change keeping
// state and running the new init, a failed compile keeping the old program, statistics. No
// timing assertions: only what the executive must do whatever the machine load.
#include "runtime/Executive.h"
#include "runtime/Controller.h"
#include "runtime/ProgramLoader.h"

#include "ir/Profile.h"
#include "profiles/fanuc/FanucProfile.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <mutex>
#include <thread>

namespace lj::rt {
namespace {

// A temporary STL file.
class TempProgram {
public:
  explicit TempProgram(const std::string &text, const std::string &ext = ".stl") {
    path_ = (std::filesystem::temp_directory_path() /
             ("ljrt-" + std::to_string(::getpid()) + "-" + std::to_string(counter_++) + ext))
                .string();
    write(text);
  }
  ~TempProgram() { std::remove(path_.c_str()); }
  void write(const std::string &text) { std::ofstream(path_, std::ios::trunc) << text; }
  const std::string &path() const { return path_; }

private:
  static inline int counter_ = 0;
  std::string path_;
};

// DIALECT.md 4: init once, PLC1 every tick; D1 counts PLC1 executions.
const char *kCounting = R"(
LDT
MOV 7 D10
IEND
LDT
ADD D1 1 D1
LD X1.0
OUT Y1.0
1END
2END
)";

formats::Assignment assign(const std::string &text) {
  std::string err;
  std::optional<formats::Assignment> a = formats::parseAssignment(text, err);
  EXPECT_TRUE(a) << err;
  return a.value_or(formats::Assignment{});
}

// Post a no-op write and wait until a tick has applied and published it: a tick boundary
// passed, without any assumption on how long that takes.
void waitTicks(Exchange &ex, int n) {
  for (int i = 0; i < n; ++i) ASSERT_TRUE(ex.waitApplied(ex.post({}), std::chrono::seconds(30)));
}

TEST(Executive, TicksCarryNowMsAndInitRunsFirst) {
  TempProgram p(kCounting);
  ProgramLoader loader("interp", -1);
  std::string err;
  auto v = loader.load(p.path(), {}, err);
  ASSERT_TRUE(v) << err;
  Exchange ex;
  ExecutiveOptions o;
  o.periodNs = 2000000; // 2 ms: now_ms = tick * 2 (CLI.md `--period-ms`)
  o.maxTicks = 30;
  Executive exec(ex, o);
  std::mutex mu;
  std::vector<std::pair<uint64_t, uint64_t>> seen; // (tick, now_ms)
  std::vector<int32_t> d1;
  exec.addAfterTickHook([&](const lj_state &s, uint64_t tick) {
    std::lock_guard<std::mutex> g(mu);
    seen.emplace_back(tick, s.now_ms);
    d1.push_back(s.img.D[1]);
  });
  ASSERT_TRUE(exec.start(v, err)) << err;
  exec.join();
  ASSERT_EQ(seen.size(), 30u);
  for (size_t i = 0; i < seen.size(); ++i) {
    EXPECT_EQ(seen[i].second, seen[i].first * 2) << "tick " << seen[i].first;
    if (i) {
      EXPECT_GT(seen[i].first, seen[i - 1].first);
    }
    EXPECT_EQ(d1[i], static_cast<int32_t>(i + 1)); // one PLC1 run per executed tick
  }
  EXPECT_EQ(exec.finalState().img.D[10], 7); // the init part ran
  TickStats st = exec.stats();
  EXPECT_EQ(st.ticks, 30u);
  EXPECT_EQ(st.scan.count(), 30u);
  EXPECT_EQ(st.jitter.count(), 30u);
  // Every deadline is either ticked or counted as missed: the last tick number tells how many.
  EXPECT_EQ(st.ticks + st.missedDeadlines, seen.back().first + 1);
}

TEST(Executive, OnlineChangeKeepsStateAndRunsTheNewInit) {
  TempProgram p(kCounting);
  // Version 2: another init value, PLC1 counts in D2, and an edge contact of its own.
  TempProgram p2(R"(
LDT
MOV 9 D10
IEND
LDT
ADD D2 1 D2
LDP X1.0
OUT Y1.1
1END
2END
)");
  ProgramLoader loader("interp", -1);
  std::string err;
  auto v = loader.load(p.path(), {}, err);
  ASSERT_TRUE(v) << err;
  Exchange ex;
  Executive exec(ex, ExecutiveOptions{});
  ASSERT_TRUE(exec.start(v, err)) << err;
  // State that must survive: a B register, a counter value written by the host, D1.
  ex.post({assign("B5=1234"), assign("X1.0=1")});
  waitTicks(ex, 3);
  Controller ctl(ex, exec, loader, p.path(), nullptr);
  ASSERT_TRUE(ctl.change(p2.path(), {}, err)) << err;
  waitTicks(ex, 2);
  auto s = std::make_unique<lj_state>();
  ASSERT_TRUE(ex.snapshot(*s));
  EXPECT_EQ(exec.current()->id, 2u);
  EXPECT_EQ(s->img.D[10], 9);   // hnc8-core.md 6.2 RESOLUTION: the new init ran
  EXPECT_EQ(s->img.B[5], 1234); // the image is kept
  EXPECT_GE(s->img.D[1], 3);    // D1 kept the count of version 1 (no longer incremented)
  EXPECT_GE(s->img.D[2], 1);    // version 2 runs
  // X1.0 has been 1 since before the swap; the edge memory was cleared at the swap
  // (docs/dialect-notes.md "State details"), so LDP saw one rising edge in its first tick and
  // none after: Y1.1 is 0 now, and the memory holds 1.
  EXPECT_EQ(s->img.Y[1] & 2, 0);
  exec.requestStop();
  exec.join();
  EXPECT_EQ(exec.stats().swaps, 1u);
}

// Interpreter-first tiering (docs/serve.md "Tiering"): the interpreter runs from the start,
// the JIT build of the same program is switched in at a tick boundary. Nothing else happens:
// the init part ran once (D11 counts init runs), D1 counts every PLC1 run across the switch,
// the edge memory of LDP X1.0 is kept (X1.0 = 1 since before the switch: one rising edge in
// all, so Y1.1 stays 0 after the first tick), and the statistics name the switch.
TEST(Executive, TierUpSwitchesCodeOnly) {
  TempProgram p(R"(
LDT
MOV 7 D10
ADD D11 1 D11
IEND
LDT
ADD D1 1 D1
LDP X1.0
OUT Y1.1
1END
2END
)");
  ProgramLoader loader("jit", -1);
  std::string err;
  int64_t ready = 0;
  auto v = loader.loadInterpreted(p.path(), err, nullptr, &ready);
  ASSERT_TRUE(v) << err;
  EXPECT_EQ(v->tier, EngineTier::Interp);
  EXPECT_GT(ready, 0);
  Exchange ex;
  ExecutiveOptions o;
  o.tierMode = "interp-first";
  Executive exec(ex, o);
  std::atomic<int> risingTicks{0}; // ticks that ended with Y1.1 = 1
  exec.addAfterTickHook([&](const lj_state &st, uint64_t) {
    if (st.img.Y[1] & 2) risingTicks.fetch_add(1);
  });
  ASSERT_TRUE(exec.start(v, err)) << err;
  ASSERT_TRUE(ex.waitApplied(ex.post({assign("X1.0=1")}), std::chrono::seconds(30)));
  waitTicks(ex, 3);
  auto fast = loader.buildTier(*v, EngineTier::JitOpt, err);
  ASSERT_TRUE(fast) << err;
  EXPECT_EQ(fast->prog, v->prog); // the same verified program
  EXPECT_EQ(fast->id, v->id);
  ASSERT_TRUE(exec.tierUp(fast, std::chrono::seconds(30), err)) << err;
  EXPECT_EQ(exec.current()->tier, EngineTier::JitOpt);
  waitTicks(ex, 3);
  exec.requestStop();
  exec.join();
  const lj_state &s = exec.finalState();
  TickStats st = exec.stats();
  EXPECT_EQ(s.img.D[11], 1); // init ran once, not again at the switch
  EXPECT_EQ(s.img.D[10], 7);
  EXPECT_EQ(s.img.D[1], static_cast<int32_t>(st.ticks)); // one PLC1 run per tick, none lost
  EXPECT_EQ(s.img.Y[1] & 2, 0);                          // no second rising edge
  EXPECT_EQ(s.edge[0], 1);                               // the memory holds X1.0's level
  EXPECT_EQ(st.swaps, 0u);                               // a tier switch is no online change
  ASSERT_EQ(st.tierSwitches, 1u);
  EXPECT_EQ(st.switches[0].from, EngineTier::Interp);
  EXPECT_EQ(st.switches[0].to, EngineTier::JitOpt);
  EXPECT_GT(st.switches[0].tick, 0u);
  EXPECT_GT(st.switches[0].buildNs, 0);
  EXPECT_GE(st.switches[0].endNs, st.firstTickEndNs);
  EXPECT_EQ(st.firstTier, EngineTier::Interp);
  EXPECT_EQ(st.tier, EngineTier::JitOpt);
  nlohmann::json j = st.toJson()["startup"];
  EXPECT_EQ(j["tiering"]["mode"], "interp-first");
  EXPECT_EQ(j["tiering"]["switches"][0]["from"], "interp");
  EXPECT_EQ(j["tiering"]["switches"][0]["to"], "jit-opt");
  EXPECT_EQ(j["tiering"]["switches"][0]["tick"], st.switches[0].tick);
  EXPECT_GT(j["first_tick_ms"].get<double>(), 0.0);
}

// A faster build of a program an online change has replaced is never switched in.
TEST(Executive, TierUpAfterOnlineChangeIsRefused) {
  TempProgram p(kCounting);
  TempProgram p2("LDT\nMOV 9 D10\nIEND\nLDT\nADD D2 1 D2\n1END\n2END\n");
  ProgramLoader loader("jit", -1);
  std::string err;
  auto v = loader.loadInterpreted(p.path(), err);
  ASSERT_TRUE(v) << err;
  Exchange ex;
  Executive exec(ex, ExecutiveOptions{});
  ASSERT_TRUE(exec.start(v, err)) << err;
  auto fast = loader.buildTier(*v, EngineTier::JitFast, err);
  ASSERT_TRUE(fast) << err;
  auto v2 = loader.load(p2.path(), {}, err);
  ASSERT_TRUE(v2) << err;
  ASSERT_TRUE(exec.swap(v2, std::chrono::seconds(30), err)) << err;
  EXPECT_FALSE(exec.tierUp(fast, std::chrono::seconds(30), err));
  EXPECT_NE(err.find("running program changed"), std::string::npos) << err;
  EXPECT_EQ(exec.current()->id, v2->id);
  waitTicks(ex, 2);
  auto s = std::make_unique<lj_state>();
  ASSERT_TRUE(ex.snapshot(*s));
  EXPECT_EQ(s->img.D[10], 9); // version 2 runs
  exec.requestStop();
  exec.join();
  EXPECT_EQ(exec.stats().tierSwitches, 0u);
}

TEST(Executive, FailedCompileKeepsTheOldProgram) {
  TempProgram p(kCounting);
  TempProgram bad("LD X1.0\nOUT\n"); // OUT without its operand: a verifier error
  ProgramLoader loader("interp", -1);
  std::string err;
  auto v = loader.load(p.path(), {}, err);
  ASSERT_TRUE(v) << err;
  Exchange ex;
  Executive exec(ex, ExecutiveOptions{});
  ASSERT_TRUE(exec.start(v, err)) << err;
  std::vector<std::string> logs;
  std::mutex mu;
  Controller ctl(ex, exec, loader, p.path(), [&](const std::string &l) {
    std::lock_guard<std::mutex> g(mu);
    logs.push_back(l);
  });
  EXPECT_FALSE(ctl.change(bad.path(), {}, err));
  EXPECT_NE(err.find(bad.path()), std::string::npos) << err; // located diagnostic
  EXPECT_EQ(exec.current()->id, 1u);
  waitTicks(ex, 2);
  auto s = std::make_unique<lj_state>();
  ASSERT_TRUE(ex.snapshot(*s));
  EXPECT_GE(s->img.D[1], 2); // still ticking version 1
  // The same reason went to the log.
  std::lock_guard<std::mutex> g(mu);
  ASSERT_FALSE(logs.empty());
  EXPECT_NE(logs.back().find("old program keeps running"), std::string::npos);
}

/// A program file loaded by `engine` and running under a controller (the force tests).
struct Running {
  Running(const std::string &path, const char *engine) : loader(engine, -1) {
    auto v = loader.load(path, {}, error);
    if (v && exec.start(v, error))
      ctl = std::make_unique<Controller>(ex, exec, loader, path, nullptr);
  }
  ProgramLoader loader;
  Exchange ex;
  Executive exec{ex, ExecutiveOptions{}};
  std::string error;
  std::unique_ptr<Controller> ctl; ///< null: it did not load or start (`error` says why)
};

TEST(Executive, ForcingRecompilesAndRejectsNonContacts) {
  TempProgram p(kCounting); // line 7 = LD X1.0, line 8 = OUT Y1.0
  Running run(p.path(), "interp");
  ASSERT_TRUE(run.ctl) << run.error;
  Exchange &ex = run.ex;
  Controller &ctl = *run.ctl;
  nlohmann::json r = ctl.handle({{"cmd", "force"}, {"line", 7}, {"mode", "on"}});
  ASSERT_TRUE(r["ok"].get<bool>()) << r.dump();
  waitTicks(ex, 2);
  auto s = std::make_unique<lj_state>();
  ASSERT_TRUE(ex.snapshot(*s));
  EXPECT_EQ(s->img.Y[1] & 1, 1); // 允许: X1.0 is 0 but the contact conducts
  r = ctl.handle({{"cmd", "force"}, {"line", 8}, {"mode", "on"}});
  EXPECT_FALSE(r["ok"].get<bool>());
  EXPECT_NE(r["error"].get<std::string>().find("not a contact"), std::string::npos);
  r = ctl.handle({{"cmd", "force"}, {"line", 7}, {"mode", "restore"}});
  ASSERT_TRUE(r["ok"].get<bool>()) << r.dump();
  waitTicks(ex, 2);
  ASSERT_TRUE(ex.snapshot(*s));
  EXPECT_EQ(s->img.Y[1] & 1, 0); // 恢复: the real X1.0 = 0 again
}

/// The id of the statement on source line `line` of the running version (-1: none).
StmtId idOnLine(const Executive &exec, int32_t line) {
  for (const Stmt &st : exec.current()->prog->stmts)
    if (st.loc.line == line) return st.id;
  return -1;
}

// Forces are keyed by statement id and live in the runtime: an online change to a text where
// that id is still a contact keeps the force (the contact moved to another line), one where the
// id became a coil drops it and says so in the log. The verified program carries no force.
TEST(Executive, ForceByIdSurvivesOnlineChange) {
  TempProgram p(kCounting); // line 7 = LD X1.0, line 8 = OUT Y1.0
  // Same statements, a comment line in front of LD X1.0: it is on line 8 now, same id.
  TempProgram moved("\nLDT\nMOV 7 D10\nIEND\nLDT\nADD D1 1 D1\n; moved down\nLD X1.0\nOUT "
                    "Y1.0\n1END\n2END\n");
  // The LDT / ADD rung gone: the id LD X1.0 had now names OUT Y1.1.
  TempProgram shifted(
      "\nLDT\nMOV 7 D10\nIEND\nLD X1.0\nOUT Y1.0\nOUT Y1.1\nOUT Y1.2\n1END\n2END\n");
  ProgramLoader loader("interp", -1);
  std::string err;
  auto v = loader.load(p.path(), {}, err);
  ASSERT_TRUE(v) << err;
  Exchange ex;
  Executive exec(ex, ExecutiveOptions{});
  ASSERT_TRUE(exec.start(v, err)) << err;
  std::vector<std::string> logs;
  std::mutex mu;
  Controller ctl(ex, exec, loader, p.path(), [&](const std::string &l) {
    std::lock_guard<std::mutex> g(mu);
    logs.push_back(l);
  });
  const StmtId ld = idOnLine(exec, 7);
  ASSERT_GE(ld, 0);
  nlohmann::json r = ctl.handle({{"cmd", "force"}, {"id", ld}, {"mode", "on"}});
  ASSERT_TRUE(r["ok"].get<bool>()) << r.dump();
  ASSERT_EQ(r["forces"].size(), 1u);
  EXPECT_EQ(r["forces"][0]["id"], ld);
  EXPECT_EQ(r["forces"][0]["line"], 7);
  waitTicks(ex, 2);
  auto s = std::make_unique<lj_state>();
  ASSERT_TRUE(ex.snapshot(*s));
  EXPECT_EQ(s->img.Y[1] & 1, 1); // 允许: X1.0 is 0 but the contact conducts
  for (const Stmt &st : exec.current()->prog->stmts) EXPECT_EQ(st.id == ld, st.loc.line == 7);

  ASSERT_TRUE(ctl.change(moved.path(), {}, err)) << err;
  EXPECT_EQ(idOnLine(exec, 8), ld);
  EXPECT_EQ(exec.current()->forces, (ContactForces{{ld, 1}}));
  waitTicks(ex, 2);
  ASSERT_TRUE(ex.snapshot(*s));
  EXPECT_EQ(s->img.Y[1] & 1, 1); // still forced after the online change

  ASSERT_TRUE(ctl.change(shifted.path(), {}, err)) << err;
  EXPECT_TRUE(exec.current()->forces.empty());
  waitTicks(ex, 2);
  ASSERT_TRUE(ex.snapshot(*s));
  EXPECT_EQ(s->img.Y[1] & 1, 0); // the force is gone: the real X1.0 = 0
  std::lock_guard<std::mutex> g(mu);
  bool logged = false;
  for (const std::string &l : logs)
    logged |= l.find("force dropped") != std::string::npos &&
              l.find("statement id " + std::to_string(ld) + " is 'OUT', not a contact") !=
                  std::string::npos;
  EXPECT_TRUE(logged);
}

// Forcing an id that is not a contact, or that does not exist, is refused with the reason;
// nothing is recompiled.
TEST(Executive, ForceOnANonContactIdIsRefused) {
  TempProgram p(kCounting);
  Running run(p.path(), "jit");
  ASSERT_TRUE(run.ctl) << run.error;
  Executive &exec = run.exec;
  Controller &ctl = *run.ctl;
  const StmtId out = idOnLine(exec, 8);
  ASSERT_GE(out, 0);
  nlohmann::json r = ctl.handle({{"cmd", "force"}, {"id", out}, {"mode", "off"}});
  EXPECT_FALSE(r["ok"].get<bool>());
  EXPECT_NE(r["error"].get<std::string>().find(":8: statement id " + std::to_string(out) +
                                               " is 'OUT', not a contact"),
            std::string::npos)
      << r.dump();
  // The contacts that can be forced, named in the dialect's words (DIALECT.md 2.1).
  EXPECT_NE(r["error"].get<std::string>().find(
                "(only LD LDI LDP LDF AND ANI OR ORI ANDP ANDF ORP ORF can be forced)"),
            std::string::npos)
      << r.dump();
  r = ctl.handle({{"cmd", "force"}, {"id", 4000}, {"mode", "on"}});
  EXPECT_FALSE(r["ok"].get<bool>());
  EXPECT_NE(r["error"].get<std::string>().find("statement id 4000 does not exist"),
            std::string::npos)
      << r.dump();
  r = ctl.handle({{"cmd", "force"}, {"id", 1}, {"line", 7}, {"mode", "on"}});
  EXPECT_FALSE(r["ok"].get<bool>()); // one of the two, not both
  EXPECT_EQ(exec.current()->id, 1u);
}

// A FANUC program's refusal names FANUC's contacts (fanuc-pmc.md 5: RD, RD.NOT, AND, AND.NOT,
// OR, OR.NOT; RD.STK pushes as RD does), not HNC-8's LD / LDI it once listed for every dialect.
TEST(Executive, ForceRefusalInTheDialectsWords) {
  TempProgram p("RD X0.0\nWRT Y0.0\nEND1\nEND2\nEND\n", ".pmc");
  Running run(p.path(), "jit");
  ASSERT_TRUE(run.ctl) << run.error;
  const StmtId wrt = idOnLine(run.exec, 2);
  ASSERT_GE(wrt, 0);
  nlohmann::json r = run.ctl->handle({{"cmd", "force"}, {"id", wrt}, {"mode", "on"}});
  EXPECT_FALSE(r["ok"].get<bool>());
  const std::string e = r.value("error", "");
  EXPECT_NE(e.find("is 'WRT', not a contact (only RD RD.NOT AND AND.NOT OR OR.NOT"),
            std::string::npos)
      << e;
  EXPECT_EQ(e.find("LDI"), std::string::npos) << e;
}

// Online change latency (docs/serve.md): after the session's first optimized build, a change
// runs the groups it touched at the fast tier (jit-quick) and the ChangeOptimizer switches the
// optimized build in later, without init; the statistics time the change from its request to
// the new code running and record when the optimized build came.
TEST(Executive, QuickOnlineChangeIsOptimizedLaterAndTimed) {
  TempProgram p(kCounting);
  TempProgram p2(R"(
LDT
MOV 9 D10
IEND
LDT
ADD D1 1 D1
LD X1.1
OUT Y1.0
1END
2END
)");
  ProgramLoader loader("jit", -1);
  std::string err;
  auto v = loader.load(p.path(), {}, err);
  ASSERT_TRUE(v) << err;
  EXPECT_EQ(v->tier, EngineTier::JitOpt); // the first build is optimized throughout
  Exchange ex;
  Executive exec(ex, ExecutiveOptions{});
  ASSERT_TRUE(exec.start(v, err)) << err;
  ex.post({assign("B5=1234")});
  waitTicks(ex, 3);
  {
    Controller ctl(ex, exec, loader, p.path(), nullptr);
    ASSERT_TRUE(ctl.change(p2.path(), {}, err)) << err;
    // The optimized build of version 2 replaces its quick one (bounded wait, no timing check).
    for (int i = 0; i < 3000 && exec.current()->tier != EngineTier::JitOpt; ++i)
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    EXPECT_EQ(exec.current()->tier, EngineTier::JitOpt);
    EXPECT_EQ(exec.current()->id, 2u);
  }
  ex.post({assign("X1.1=1")});
  waitTicks(ex, 2);
  auto s = std::make_unique<lj_state>();
  ASSERT_TRUE(ex.snapshot(*s));
  EXPECT_EQ(s->img.D[10], 9);    // the change's init ran (once: the optimized switch runs none)
  EXPECT_EQ(s->img.B[5], 1234);  // the image is kept
  EXPECT_EQ(s->img.Y[1] & 1, 1); // the edited contact (X1.1) drives Y1.0
  exec.requestStop();
  exec.join();
  TickStats st = exec.stats();
  EXPECT_EQ(st.swaps, 1u);
  ASSERT_EQ(st.changeCount, 1u);
  const ChangeRecord &c = st.changes[0];
  EXPECT_EQ(c.version, 2u);
  EXPECT_EQ(c.tier, EngineTier::JitQuick);
  EXPECT_GE(c.groupsQuick, 1u);
  EXPECT_LT(c.groupsCompiled, c.groups); // the other groups came from the cache
  EXPECT_GT(c.runningNs, c.requestedNs);
  EXPECT_GE(c.optimizedNs, c.runningNs);
  EXPECT_GT(c.frontendNs, 0);
  EXPECT_GT(c.buildNs, 0);
  nlohmann::json j = st.toJson()["online_changes"];
  EXPECT_EQ(j["count"], 1);
  EXPECT_EQ(j["recent"][0]["engine"], "jit-quick");
  EXPECT_DOUBLE_EQ(j["latency_ms"]["median"].get<double>(),
                   static_cast<double>(c.runningNs - c.requestedNs) / 1e6);
}

TEST(Exchange, LocksWinOverPostedWritesAndProgramWrites) {
  // hnc8-core.md 6.1 RESOLUTION (b): the locked value is what the image holds.
  Exchange ex;
  auto s = std::make_unique<lj_state>();
  lj_state_reset(s.get());
  ex.lock(assign("D3=42"));
  uint64_t seq = ex.post({assign("D3=5"), assign("D4=6")});
  ex.applyPending(*s);
  EXPECT_EQ(s->img.D[3], 42);
  EXPECT_EQ(s->img.D[4], 6);
  s->img.D[3] = -1; // the program writes it during the scan
  ex.applyLocks(*s);
  EXPECT_EQ(s->img.D[3], 42);
  EXPECT_FALSE(ex.waitApplied(seq, std::chrono::milliseconds(0))); // not published yet
  ex.publish(*s, 0);
  EXPECT_TRUE(ex.waitApplied(seq, std::chrono::milliseconds(0)));
  std::string err;
  ASSERT_EQ(ex.locks().size(), 1u);
  EXPECT_TRUE(ex.unlock(formats::parseAddress("D3", err).value()));
  EXPECT_FALSE(ex.unlock(formats::parseAddress("D3", err).value()));
  auto snap = std::make_unique<lj_state>();
  uint64_t tick = 99;
  ASSERT_TRUE(ex.snapshot(*snap, &tick));
  EXPECT_EQ(tick, 0u);
  EXPECT_EQ(snap->img.D[3], 42);
}

TEST(Stats, HistogramPercentiles) {
  Histogram h;
  for (int us = 1; us <= 1000; ++us) h.add(int64_t{us} * 1000);
  EXPECT_EQ(h.count(), 1000u);
  EXPECT_EQ(h.minNs(), 1000);
  EXPECT_EQ(h.maxNs(), 1000000);
  EXPECT_DOUBLE_EQ(h.meanNs(), 500.5 * 1000);
  // The 990th of 1000 sorted values is 990 us; buckets are 1 us wide.
  EXPECT_GE(h.percentileNs(0.99), 990000);
  EXPECT_LE(h.percentileNs(0.99), 991000);
  EXPECT_GE(h.percentileNs(0.999), 999000);
  EXPECT_LE(h.percentileNs(0.999), 1000000);
  h.add(int64_t{50} * 1000000); // beyond the buckets: reported through max
  EXPECT_EQ(h.percentileNs(1.0), 50000000);
}

// docs/dialect-notes.md "What online change keeps": PLS/PLF memory is cleared at a swap, also
// where a profile keeps it in lj_state.mem (FANUC DIFU/DIFD 1..1000); the areas are kept.
TEST(Executive, OnlineChangeClearsProfileEdgeBytes) {
  auto s = std::make_unique<lj_state>();
  lj_state_reset(s.get());
  const TargetProfile &tp = fanuc::profile();
  auto *b = reinterpret_cast<unsigned char *>(s.get());
  b[tp.pulseOffset(true, 1000)] = 1;
  b[tp.pulseOffset(false, 999)] = 1;
  b[tp.elementOffset(Area::KeepRelay, 5)] = 7;
  s->pls_prev[3] = 1;
  clearRenumberedState(*s, &tp);
  EXPECT_EQ(b[tp.pulseOffset(true, 1000)], 0);
  EXPECT_EQ(b[tp.pulseOffset(false, 999)], 0);
  EXPECT_EQ(b[tp.elementOffset(Area::KeepRelay, 5)], 7);
  EXPECT_EQ(s->pls_prev[3], 0);
}

} // namespace
} // namespace lj::rt

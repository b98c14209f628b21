// The signal trace (runtime/SignalTrace.h, docs/trace.md): the definition file, captures driven
// tick by tick on a hand-made lj_state with expected rows worked out by hand (tick numbers,
// trigger position, pre/post counts, repeated capture, the triple buffer's drop count), the
// values against formats::readAddress, and the trace in a running Executive.
#include "runtime/SignalTrace.h"

#include "pipeline/Dialects.h"
#include "profiles/Profiles.h"
#include "runtime/Controller.h"
#include "runtime/Executive.h"
#include "runtime/ProgramLoader.h"

#include <gtest/gtest.h>

#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <thread>

namespace lj::rt {
namespace {

std::optional<formats::CliAddress> hnc8(std::string_view text, std::string &error) {
  return formats::parseAddress(text, error);
}

std::unique_ptr<SignalTrace> makeTrace(const std::string &text, std::string &error,
                                       AddressParser parse = hnc8) {
  std::optional<TraceDefinition> d = parseTraceDefinition(text, "t.trace", error);
  if (!d) return nullptr;
  return SignalTrace::make(*d, parse, 1000000, error);
}

void set(lj_state &s, const char *addr, int64_t v) {
  std::string err;
  std::optional<formats::CliAddress> a = formats::parseAddress(addr, err);
  ASSERT_TRUE(a) << err;
  formats::writeAddress(s, *a, v);
}

// D5 = 3 * tick on every tick; X0.0 as `x0(tick)` says.
template <class F> void drive(SignalTrace &t, lj_state &s, uint64_t from, uint64_t to, F x0) {
  for (uint64_t k = from; k < to; ++k) {
    set(s, "D5", static_cast<int64_t>(3 * k));
    set(s, "X0.0", x0(k));
    t.sample(s, k);
  }
}

TEST(TraceDefinition, ParsesEveryItem) {
  std::string err;
  std::optional<TraceDefinition> d = parseTraceDefinition("# a tool change\n"
                                                          "signal X0.0, D5\n"
                                                          "signals Y1.0   # more\n"
                                                          "trigger D5 >= -12\n"
                                                          "pre 7\npost 9\nmode repeat\n",
                                                          "f", err);
  ASSERT_TRUE(d) << err;
  EXPECT_EQ(d->signals, (std::vector<std::string>{"X0.0", "D5", "Y1.0"}));
  EXPECT_EQ(d->trigger, TriggerKind::Compare);
  EXPECT_EQ(d->triggerAddress, "D5");
  EXPECT_EQ(d->op, CompareOp::Ge);
  EXPECT_EQ(d->value, -12);
  EXPECT_EQ(d->pre, 7u);
  EXPECT_EQ(d->post, 9u);
  EXPECT_TRUE(d->repeat);
  // Written back and read again: the same definition.
  std::optional<TraceDefinition> again = parseTraceDefinition(formatTraceDefinition(*d), "g", err);
  ASSERT_TRUE(again) << err;
  EXPECT_EQ(formatTraceDefinition(*again), formatTraceDefinition(*d));
  for (const char *t :
       {"trigger rising X0.1", "trigger falling X0.1", "trigger manual", "trigger immediate",
        "trigger D5<>0", "trigger D5=3", "trigger D5 < 3", "trigger D5 > 3", "trigger D5 <= 3"}) {
    EXPECT_TRUE(parseTraceDefinition(std::string("signal X0.0\n") + t, "f", err)) << t << err;
  }
}

TEST(TraceDefinition, ErrorsNameTheLine) {
  std::string err;
  EXPECT_FALSE(parseTraceDefinition("signal X0.0\nwhatever 3\n", "f.trace", err));
  EXPECT_NE(err.find("f.trace:2: unknown item 'whatever'"), std::string::npos) << err;
  EXPECT_FALSE(parseTraceDefinition("signal X0.0\ntrigger D5 ~ 3\n", "f", err));
  EXPECT_NE(err.find("f:2: trigger:"), std::string::npos) << err;
  EXPECT_FALSE(parseTraceDefinition("pre 3\n", "f", err));
  EXPECT_NE(err.find("no signal"), std::string::npos) << err;
  EXPECT_FALSE(parseTraceDefinition("signal X0.0\npre 40000\npost 30000\n", "f", err));
  EXPECT_NE(err.find("more than the 60000"), std::string::npos) << err;
  EXPECT_FALSE(parseTraceDefinition("signal X0.0\nmode twice\n", "f", err));
  std::string many = "signal X0.0";
  for (int i = 1; i <= 64; ++i) many += ", R" + std::to_string(i);
  EXPECT_FALSE(parseTraceDefinition(many + "\n", "f", err));
  EXPECT_NE(err.find("more than 64 signals"), std::string::npos) << err;
  // 64 are fine; a bad address is found when the trace is made, in the dialect's words.
  many = "signal X0.0";
  for (int i = 1; i < 64; ++i) many += ", R" + std::to_string(i);
  EXPECT_TRUE(makeTrace(many + "\n", err)) << err;
  EXPECT_FALSE(makeTrace("signal X0.0, Z9\n", err));
  EXPECT_NE(err.find("bad address 'Z9'"), std::string::npos) << err;
  EXPECT_FALSE(makeTrace("signal X0.0\ntrigger rising Q1\n", err));
  EXPECT_NE(err.find("trigger: bad address 'Q1'"), std::string::npos) << err;
}

TEST(SignalTrace, RisingEdgeWithPreAndPost) {
  std::string err;
  auto t = makeTrace("signal X0.0, D5\ntrigger rising X0.0\npre 3\npost 2\n", err);
  ASSERT_TRUE(t) << err;
  auto s = std::make_unique<lj_state>();
  std::memset(s.get(), 0, sizeof(lj_state));
  TraceCapture c;
  drive(*t, *s, 0, 12, [](uint64_t k) { return k >= 10 ? 1 : 0; });
  EXPECT_STREQ(t->status().state, "recording"); // the trigger at 10, one post tick of 2 so far
  EXPECT_FALSE(t->take(c));
  drive(*t, *s, 12, 20, [](uint64_t) { return 1; });
  EXPECT_STREQ(t->status().state, "done");
  EXPECT_EQ(t->status().samples, 13u) << "ticks 0..12; nothing after the capture";
  ASSERT_TRUE(t->take(c));
  // Rising edge at 10: 3 ticks before (7, 8, 9), the trigger tick, 2 after (11, 12).
  EXPECT_EQ(c.ticks, (std::vector<uint64_t>{7, 8, 9, 10, 11, 12}));
  EXPECT_EQ(c.triggerTick, 10u);
  EXPECT_EQ(c.preTicks, 3u);
  EXPECT_EQ(c.postTicks, 2u);
  EXPECT_EQ(c.values, (std::vector<int64_t>{0, 21, 0, 24, 0, 27, 1, 30, 1, 33, 1, 36}));
  EXPECT_EQ(c.sequence, 1u);
  EXPECT_FALSE(t->take(c)) << "taken once";
}

TEST(SignalTrace, EarlyTriggerHasFewerPreTicks) {
  std::string err;
  auto t = makeTrace("signal D5\ntrigger D5 = 6\npre 5\npost 1\n", err);
  ASSERT_TRUE(t) << err;
  auto s = std::make_unique<lj_state>();
  std::memset(s.get(), 0, sizeof(lj_state));
  drive(*t, *s, 0, 10, [](uint64_t) { return 0; });
  TraceCapture c;
  ASSERT_TRUE(t->take(c));
  // D5 = 6 at tick 2: only ticks 0 and 1 came before it.
  EXPECT_EQ(c.ticks, (std::vector<uint64_t>{0, 1, 2, 3}));
  EXPECT_EQ(c.preTicks, 2u);
  EXPECT_EQ(c.values, (std::vector<int64_t>{0, 3, 6, 9}));
}

TEST(SignalTrace, FallingEdgeAndComparisonFireOnTheChange) {
  std::string err;
  // Falling: X0.0 is 1 from the start (no edge at arming), falls at 4.
  auto t = makeTrace("signal X0.0\ntrigger falling X0.0\npre 1\npost 0\n", err);
  ASSERT_TRUE(t) << err;
  auto s = std::make_unique<lj_state>();
  std::memset(s.get(), 0, sizeof(lj_state));
  drive(*t, *s, 0, 8, [](uint64_t k) { return k < 4 ? 1 : 0; });
  TraceCapture c;
  ASSERT_TRUE(t->take(c));
  EXPECT_EQ(c.ticks, (std::vector<uint64_t>{3, 4}));
  EXPECT_EQ(c.values, (std::vector<int64_t>{1, 0}));
  // Repeated comparison D5 > 10: true from tick 4 on (D5 = 12), never false again: one capture.
  t = makeTrace("signal D5\ntrigger D5 > 10\npre 0\npost 0\nmode repeat\n", err);
  ASSERT_TRUE(t) << err;
  drive(*t, *s, 0, 20, [](uint64_t) { return 0; });
  ASSERT_TRUE(t->take(c));
  EXPECT_EQ(c.ticks, (std::vector<uint64_t>{4}));
  EXPECT_EQ(t->status().captures, 1u);
  EXPECT_STREQ(t->status().state, "waiting");
}

TEST(SignalTrace, RepeatedCaptureAndTheHandOff) {
  std::string err;
  auto t = makeTrace("signal X0.0, D5\ntrigger rising X0.0\npre 1\npost 1\nmode repeat\n", err);
  ASSERT_TRUE(t) << err;
  auto s = std::make_unique<lj_state>();
  std::memset(s.get(), 0, sizeof(lj_state));
  // Pulses at 10, 20 and 30 (one tick each).
  auto pulses = [](uint64_t k) { return k == 10 || k == 20 || k == 30 ? 1 : 0; };
  drive(*t, *s, 0, 15, pulses);
  TraceCapture c;
  ASSERT_TRUE(t->take(c));
  EXPECT_EQ(c.ticks, (std::vector<uint64_t>{9, 10, 11}));
  EXPECT_EQ(c.sequence, 1u);
  // Two more captures before the reader looks again: the newest wins, one is counted dropped.
  drive(*t, *s, 15, 35, pulses);
  EXPECT_EQ(t->status().captures, 3u);
  EXPECT_EQ(t->status().dropped, 1u);
  ASSERT_TRUE(t->take(c));
  EXPECT_EQ(c.ticks, (std::vector<uint64_t>{29, 30, 31}));
  EXPECT_EQ(c.values, (std::vector<int64_t>{0, 87, 1, 90, 0, 93}));
  EXPECT_EQ(c.sequence, 3u);
  EXPECT_FALSE(t->take(c));
}

TEST(SignalTrace, ManualAndImmediateRepeatRecordEveryTick) {
  std::string err;
  auto t = makeTrace("signal D5\ntrigger manual\npre 2\npost 2\n", err);
  ASSERT_TRUE(t) << err;
  auto s = std::make_unique<lj_state>();
  std::memset(s.get(), 0, sizeof(lj_state));
  drive(*t, *s, 0, 6, [](uint64_t) { return 0; });
  EXPECT_STREQ(t->status().state, "waiting") << "no trigger without the request";
  t->triggerNow();
  drive(*t, *s, 6, 12, [](uint64_t) { return 0; });
  TraceCapture c;
  ASSERT_TRUE(t->take(c));
  EXPECT_EQ(c.ticks, (std::vector<uint64_t>{4, 5, 6, 7, 8}));
  EXPECT_EQ(c.triggerTick, 6u);
  // immediate + repeat: back-to-back captures of 1 + post ticks; a reader taking each in time
  // sees every tick exactly once.
  t = makeTrace("signal D5\ntrigger immediate\npre 0\npost 3\nmode repeat\n", err);
  ASSERT_TRUE(t) << err;
  std::vector<uint64_t> seen;
  for (uint64_t k = 100; k < 140; ++k) {
    drive(*t, *s, k, k + 1, [](uint64_t) { return 0; });
    if (t->take(c)) seen.insert(seen.end(), c.ticks.begin(), c.ticks.end());
  }
  ASSERT_EQ(seen.size(), 40u);
  for (size_t i = 0; i < seen.size(); ++i) EXPECT_EQ(seen[i], 100 + i);
  EXPECT_EQ(t->status().dropped, 0u);
}

TEST(SignalTrace, ValuesAreReadAddressValues) {
  // Every kind of HNC-8 address, and a FANUC signed word: each sampled value must be what
  // formats::readAddress reads from the same state (the watch table's values).
  const char *hnc[] = {"X0.0", "X3", "Y1.7", "F2616", "G2616.15", "R5", "D5",
                       "B2",   "T3", "T3.0", "C1",    "C1.0",     "W0"};
  std::string def = "signal ";
  for (const char *a : hnc) def += std::string(a) + ",";
  def.pop_back();
  std::string err;
  auto t = makeTrace(def + "\ntrigger immediate\npre 0\npost 0\n", err);
  ASSERT_TRUE(t) << err;
  auto s = std::make_unique<lj_state>();
  std::memset(s.get(), 0, sizeof(lj_state));
  set(*s, "X0.0", 1);
  set(*s, "X3", 0xA5);
  set(*s, "Y1.7", 1);
  set(*s, "F2616", -2);
  set(*s, "G2616", 0x8000);
  set(*s, "R5", 200);
  set(*s, "D5", -123456);
  set(*s, "B2", 77);
  set(*s, "C1", 41);
  set(*s, "C1.0", 1);
  set(*s, "W0", 0x1234);
  const int slot = profileNamed("hnc8")->tcSlot(Area::Timer, 3);
  ASSERT_GE(slot, 0);
  s->T[slot].elapsed_ms = 1500;
  s->T[slot].out = 1;
  t->sample(*s, 0);
  TraceCapture c;
  ASSERT_TRUE(t->take(c));
  ASSERT_EQ(c.values.size(), std::size(hnc));
  for (size_t i = 0; i < std::size(hnc); ++i) {
    std::optional<formats::CliAddress> a = formats::parseAddress(hnc[i], err);
    ASSERT_TRUE(a);
    EXPECT_EQ(c.values[i], formats::readAddress(*s, *a)) << hnc[i];
  }
  EXPECT_EQ(c.values[3], -2);
  EXPECT_EQ(c.values[4], 1);
  EXPECT_EQ(c.values[6], -123456);
  EXPECT_EQ(c.values[8], 1500);
  // FANUC: D100:2 a signed word laid in lj_state.mem, R0.3 a bit.
  const pipeline::Dialect *fanuc = pipeline::dialectNamed("fanuc");
  ASSERT_TRUE(fanuc);
  t = makeTrace(
      "signal D100:2, R0.3\ntrigger immediate\npre 0\npost 0\n", err,
      [fanuc](std::string_view text, std::string &e) { return fanuc->parseAddress(text, e); });
  ASSERT_TRUE(t) << err;
  std::optional<formats::CliAddress> d100 = fanuc->parseAddress("D100:2", err);
  std::optional<formats::CliAddress> r03 = fanuc->parseAddress("R0.3", err);
  ASSERT_TRUE(d100 && r03);
  formats::writeAddress(*s, *d100, -300);
  formats::writeAddress(*s, *r03, 1);
  t->sample(*s, 5);
  ASSERT_TRUE(t->take(c));
  EXPECT_EQ(c.values, (std::vector<int64_t>{-300, 1}));
  EXPECT_EQ(c.signals[0].bits, 16);
  EXPECT_EQ(c.signals[1].bits, 1);
}

TEST(SignalTrace, CaptureAsVcdAndCsv) {
  std::string err;
  auto t = makeTrace("signal X0.0, D5\ntrigger rising X0.0\npre 1\npost 1\n", err);
  ASSERT_TRUE(t) << err;
  auto s = std::make_unique<lj_state>();
  std::memset(s.get(), 0, sizeof(lj_state));
  drive(*t, *s, 0, 5, [](uint64_t k) { return k >= 2 ? 1 : 0; });
  TraceCapture c;
  ASSERT_TRUE(t->take(c));
  EXPECT_EQ(c.csv(), "tick,ms,X0.0,D5,trigger\n1,1,0,3,0\n2,2,1,6,1\n3,3,1,9,0\n");
  EXPECT_EQ(c.vcd(false), "$version ladderjit $end\n"
                          "$comment trigger at tick 2, 1 ticks before, 1 after; capture 1 $end\n"
                          "$timescale 1ms $end\n"
                          "$scope module ladderjit $end\n"
                          "$var wire 1 ! X0.0 $end\n"
                          "$var wire 32 \" D5 $end\n"
                          "$upscope $end\n"
                          "$enddefinitions $end\n"
                          "#1\n0!\nb11 \"\n#2\n1!\nb110 \"\n#3\nb1001 \"\n#4\n");
}

TEST(SignalTrace, InARunningExecutive) {
  // D1 counts PLC1 executions: consecutive samples must differ by exactly 1 (no tick lost or
  // sampled twice), whatever ticks a loaded machine skips.
  const std::string path =
      (std::filesystem::temp_directory_path() / ("ljtrace-" + std::to_string(::getpid()) + ".stl"))
          .string();
  std::ofstream(path) << "LDT\nADD D1 1 D1\n1END\n2END\n";
  ProgramLoader loader("interp", -1);
  std::string err;
  auto v = loader.load(path, {}, err);
  std::remove(path.c_str());
  ASSERT_TRUE(v) << err;
  Exchange ex;
  ExecutiveOptions o;
  Executive exec(ex, o);
  auto t = makeTrace("signal D1\ntrigger immediate\npre 0\npost 299\n", err);
  ASSERT_TRUE(t) << err;
  ASSERT_TRUE(exec.start(v, err)) << err;
  ASSERT_TRUE(exec.setSignalTrace(t.get(), std::chrono::seconds(30), err)) << err;
  TraceCapture c;
  for (int i = 0; i < 3000 && !t->take(c); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  ASSERT_TRUE(exec.setSignalTrace(nullptr, std::chrono::seconds(30), err)) << err;
  t.reset(); // no longer used by the scan thread
  exec.requestStop();
  exec.join();
  ASSERT_EQ(c.ticks.size(), 300u);
  for (size_t i = 1; i < c.ticks.size(); ++i) {
    EXPECT_GT(c.ticks[i], c.ticks[i - 1]);
    EXPECT_EQ(c.values[i], c.values[i - 1] + 1) << "row " << i;
  }
  if (exec.stats().missedDeadlines == 0) {
    EXPECT_EQ(c.ticks.back() - c.ticks.front(), 299u) << "contiguous tick numbers";
  }
}

} // namespace
} // namespace lj::rt

namespace lj::rt {
namespace {

// Issue 32 item 6: a user's force and a view switch are logged as what they are, naming the
// element forced, never as "online change: now running version N".
TEST(ServeLog, ForceAndViewSwitchSayWhatHappened) {
  const std::string path =
      (std::filesystem::temp_directory_path() / ("ljforce-" + std::to_string(::getpid()) + ".stl"))
          .string();
  std::ofstream(path) << "LDT\nADD D1 1 D1\nLD X483.0\nOUT Y1.0\n1END\n2END\n";
  ProgramLoader loader("interp", -1);
  std::string err;
  auto v = loader.load(path, {}, err);
  ASSERT_TRUE(v) << err;
  Exchange ex;
  Executive exec(ex, ExecutiveOptions{});
  ASSERT_TRUE(exec.start(v, err)) << err;
  std::vector<std::string> logs;
  std::mutex mu;
  Controller ctl(ex, exec, loader, path, [&](const std::string &l) {
    std::lock_guard<std::mutex> g(mu);
    logs.push_back(l);
  });
  nlohmann::json r = ctl.handle({{"cmd", "force"}, {"line", 3}, {"mode", "off"}});
  ASSERT_TRUE(r["ok"].get<bool>()) << r.dump();
  ASSERT_TRUE(ctl.setTraced(true, err)) << err;
  std::remove(path.c_str());
  std::lock_guard<std::mutex> g(mu);
  bool forced = false, switched = false;
  for (const std::string &l : logs) {
    EXPECT_EQ(l.find("online change"), std::string::npos) << l;
    forced |= l.find("force: LD X483.0 (line 3, id ") != std::string::npos &&
              l.find("forced off") != std::string::npos;
    switched |= l.find("live view: switching to the traced code") != std::string::npos;
  }
  EXPECT_TRUE(forced) << "no force line naming LD X483.0";
  EXPECT_TRUE(switched);
}

} // namespace
} // namespace lj::rt

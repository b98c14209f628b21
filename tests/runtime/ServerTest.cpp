// serve as a library (runtime/Server.h): an embedder starts a Server without the CLI, runs
// ticks, talks to it through the exchange, stops it, and reads its statistics.
#include "runtime/Server.h"

#include "formats/Address.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

namespace lj::rt {
namespace {

namespace fs = std::filesystem;

// A private directory for the program, the control socket and the statistics file.
class TempDir {
public:
  TempDir() {
    path_ = fs::temp_directory_path() /
            ("lj-server-test-" + std::to_string(::getpid()) + "-" + std::to_string(counter_++));
    fs::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  std::string file(const std::string &name, const std::string &text = {}) const {
    std::string p = (path_ / name).string();
    if (!text.empty()) std::ofstream(p) << text;
    return p;
  }

private:
  static inline int counter_ = 0;
  fs::path path_;
};

// DIALECT.md 4: init once, PLC1 every tick; D1 counts PLC1 runs, Y1.0 follows X1.0.
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

ServerOptions optionsFor(const TempDir &dir, const std::string &program) {
  ServerOptions o;
  o.program = program;
  o.engine = "interp";
  o.periodMs = 2;
  o.control = dir.file("serve.sock");
  o.log = [](const std::string &) {};
  o.say = [](const std::string &) {};
  return o;
}

formats::Assignment assign(const std::string &text) {
  std::string err;
  std::optional<formats::Assignment> a = formats::parseAssignment(text, err);
  EXPECT_TRUE(a) << err;
  return a.value_or(formats::Assignment{});
}

int64_t read(Exchange &ex, const std::string &addr) {
  std::string err;
  std::optional<formats::CliAddress> a = formats::parseAddress(addr, err);
  EXPECT_TRUE(a) << err;
  lj_state s;
  EXPECT_TRUE(ex.snapshot(s));
  return a ? formats::readAddress(s, *a) : -1;
}

TEST(Server, AnEmbedderRunsTheExampleAndStopsIt) {
  TempDir dir;
  ServerOptions o = optionsFor(dir, LJ_EXAMPLES_DIR "/coolant_lube.stl");
  o.stats = dir.file("stats.json");
  std::string said;
  o.say = [&said](const std::string &t) { said += t; };
  Server server(o);
  Status s = server.load();
  ASSERT_TRUE(s.ok()) << s.message();
  s = server.start();
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_NE(said.find("ladderjit serve: running '" LJ_EXAMPLES_DIR "/coolant_lube.stl' (engine "
                      "interp, tier direct, period 2 ms"),
            std::string::npos)
      << said;
  EXPECT_NE(said.find("control socket " + dir.file("serve.sock")), std::string::npos) << said;
  EXPECT_TRUE(fs::exists(server.controlPath()));
  EXPECT_EQ(server.httpPort(), -1);
  EXPECT_EQ(server.modbusPort(), -1);
  // Ticks run: each posted write is applied at a tick boundary and published.
  for (int i = 0; i < 5; ++i)
    ASSERT_TRUE(
        server.exchange().waitApplied(server.exchange().post({}), std::chrono::seconds(30)));
  EXPECT_GE(server.exchange().lastTick(), 4u);
  EXPECT_TRUE(server.executive().running());

  std::thread stopper([&server] { server.requestStop("embedder"); });
  const std::string why = server.waitForStop();
  stopper.join();
  EXPECT_EQ(why, "embedder");
  s = server.shutdown(why);
  ASSERT_TRUE(s.ok()) << s.message();
  EXPECT_FALSE(server.mustExitFast());
  EXPECT_FALSE(server.executive().running());
  EXPECT_NE(said.find("ladderjit serve: embedder; "), std::string::npos) << said;
  std::ifstream in(o.stats);
  nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_EQ(j["stop_reason"], "embedder");
  EXPECT_EQ(j["engine"], "interp");
  EXPECT_GE(j["ticks"].get<uint64_t>(), 5u);
}

TEST(Server, WritesReachTheProgramAndDurationEndsIt) {
  TempDir dir;
  ServerOptions o = optionsFor(dir, dir.file("count.stl", kCounting));
  o.duration = 1;
  o.sets = {"X1.0=1"};
  Server server(o);
  Status s = server.load();
  ASSERT_TRUE(s.ok()) << s.message();
  s = server.start();
  ASSERT_TRUE(s.ok()) << s.message();
  Exchange &ex = server.exchange();
  ASSERT_TRUE(ex.waitApplied(ex.post({}), std::chrono::seconds(30)));
  EXPECT_EQ(read(ex, "D10"), 7);  // init ran
  EXPECT_EQ(read(ex, "Y1.0"), 1); // --set X1.0=1 at power-up
  ASSERT_TRUE(ex.waitApplied(ex.post({assign("X1.0=0")}), std::chrono::seconds(30)));
  ASSERT_TRUE(ex.waitApplied(ex.post({}), std::chrono::seconds(30)));
  EXPECT_EQ(read(ex, "Y1.0"), 0);
  EXPECT_GT(read(ex, "D1"), 0);
  EXPECT_EQ(server.waitForStop(), "--duration");
  EXPECT_TRUE(server.shutdown("--duration").ok());
}

TEST(Server, BadOptionsAndBadProgramsAreDifferentErrors) {
  TempDir dir;
  ServerOptions o = optionsFor(dir, dir.file("count.stl", kCounting));
  o.periodMs = 0;
  Status s = Server(o).load();
  EXPECT_EQ(s.code(), ErrorCode::InvalidArgument);
  EXPECT_EQ(s.message(), "--period-ms: expected 1..1000, got 0");

  o = optionsFor(dir, dir.file("bad.stl", "LD X1.0\nOUT Y1.0\nFOO D1\n"));
  s = Server(o).load();
  EXPECT_EQ(s.code(), ErrorCode::Rejected); // the program's diagnostics: the CLI's exit 1
  EXPECT_NE(s.message().find("bad.stl:3:"), std::string::npos) << s.message();

  o = optionsFor(dir, dir.file("missing.stl"));
  s = Server(o).load();
  EXPECT_EQ(s.code(), ErrorCode::InvalidArgument) << s.message();
}

} // namespace
} // namespace lj::rt

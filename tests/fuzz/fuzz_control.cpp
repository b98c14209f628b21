// libFuzzer target for the serve control protocol: request lines as a control connection
// receives them, and `load` files (the body written to a file and loaded online), against a
// Controller over a running interpreter executive. Every answer must be one well-formed JSON
// object with "ok", whatever the bytes (issue 11 finding 3: no request may abort the server).
#include "runtime/ControlSocket.h"
#include "runtime/Controller.h"

#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <string>
#include <string_view>

namespace {

const char *kInitial = "LDT\nMOV 7 D10\nIEND\nLD X1.0\nOUT Y1.0\n1END\n2END\n";

struct Server {
  std::string dir, program, loaded;
  lj::rt::Exchange ex;
  lj::rt::Executive exec{ex, {}, [](const std::string &) {}};
  lj::rt::ProgramLoader loader{"interp", -1};
  std::unique_ptr<lj::rt::Controller> ctl;
  lj::rt::ControlSocket::Handler handler;

  Server() {
    char tmpl[] = "/tmp/lj-fuzz-control-XXXXXX";
    if (!::mkdtemp(tmpl)) std::abort();
    dir = tmpl;
    program = dir + "/served.stl";
    loaded = dir + "/loaded.stl";
    std::ofstream(program) << kInitial;
    std::string err;
    std::shared_ptr<lj::rt::ProgramVersion> first = loader.load(program, {}, err);
    if (!first || !exec.start(first, err)) std::abort();
    ctl =
        std::make_unique<lj::rt::Controller>(ex, exec, loader, program, [](const std::string &) {});
    handler = [this](const nlohmann::json &r) { return ctl->handle(r); };
  }
};

Server &server() {
  static Server *s = new Server; // never destroyed: the scan thread runs until exit
  return *s;
}

// The answer must be exactly one JSON object line with a boolean "ok".
void checkAnswer(const std::string &a) {
  if (a.empty() || a.back() != '\n' || a.find('\n') != a.size() - 1) __builtin_trap();
  nlohmann::json j = nlohmann::json::parse(a, nullptr, false);
  if (j.is_discarded() || !j.is_object() || !j.contains("ok") || !j["ok"].is_boolean())
    __builtin_trap();
}

std::string ask(Server &s, std::string_view line) {
  std::string a = lj::rt::ControlSocket::answer(s.handler, line);
  checkAnswer(a);
  return a;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  if (size == 0) return 0;
  Server &s = server();
  std::string_view rest(reinterpret_cast<const char *>(data) + 1, size - 1);
  if ((data[0] & 1) == 0) {
    // Request lines. A "load" may only name our own file (the reading of arbitrary paths is
    // bounded elsewhere); everything else goes to the controller as it came.
    size_t pos = 0;
    while (pos <= rest.size()) {
      size_t nl = rest.find('\n', pos);
      std::string_view line =
          rest.substr(pos, nl == std::string_view::npos ? rest.size() - pos : nl - pos);
      nlohmann::json j = nlohmann::json::parse(line, nullptr, false);
      if (j.is_object() && j.contains("cmd") && j["cmd"] == "load") {
        j["program"] = s.loaded;
        j.erase("so");
        ask(s, j.dump());
      } else { // "stop" only sets the flag serve's main loop reads
        ask(s, line);
      }
      if (nl == std::string_view::npos) break;
      pos = nl + 1;
    }
  } else {
    // A `load` file: the rest is its body (STL or plc.dit), loaded online, then stats.
    std::ofstream(s.loaded, std::ios::binary | std::ios::trunc)
        .write(rest.data(), std::streamsize(rest.size()));
    ask(s, R"({"cmd":"load","program":")" + s.loaded + "\"}");
    ask(s, R"({"cmd":"stats"})");
    ask(s, R"({"cmd":"read","addrs":["D10","Y1.0"]})");
  }
  return 0;
}

// `ladderjit monitor`: the client of a running `ladderjit serve` (docs/serve.md "Control"):
// read/write addresses, force contacts, the lock list, online change, stats, stop. Every
// problem (bad arguments, no server, a refused request) exits 2 with a message.
#include "tools/ladderjit/Commands.h"

#include "pipeline/Dialects.h"

#include "formats/Address.h"
#include "formats/InputFiles.h"
#include "formats/OutputFile.h"
#include "formats/StateJson.h"
#include "runtime/ControlPath.h"
#include "runtime/ControlSocket.h"

#include <charconv>
#include <climits>
#include <cstdio>
#include <filesystem>

namespace lj::cli {

namespace {

using nlohmann::json;

// --control (a socket owned by us or root), or the only live server in our private runtime
// directory (runtime/ControlPath.h); never a socket found by globbing /tmp.
bool findControl(const std::string &given, std::string &path, std::string &error) {
  if (given.empty()) return rt::findControlSocket(path, error);
  path = given;
  return rt::checkControlSocket(path, error);
}

// Check the addresses / assignments locally, so a typo never reaches the server: an item must
// be valid in some dialect of this build (the server checks it against the running program's).
// An address shaped like a name goes to the server, which reads it as a symbol of the running
// program (`monitor read COOLANT`).
bool checkItems(const std::vector<std::string> &items, bool assignments, std::string &error) {
  for (const std::string &it : items) {
    const std::string_view addr =
        std::string_view(it).substr(0, assignments ? it.find('=') : it.npos);
    if (SymbolTable::isNameShaped(addr) && (!assignments || addr.size() < it.size())) continue;
    std::string first;
    bool ok = false;
    for (const pipeline::Dialect *d : pipeline::allDialects()) {
      std::string why;
      if (assignments) {
        std::optional<formats::Assignment> as = d->parseAssignment(it, why);
        ok = as && formats::checkWritable(as->addr, as->value, why);
      } else {
        ok = d->parseAddress(it, why).has_value();
      }
      if (ok) break;
      if (first.empty()) first = why; // HNC-8's message (the default dialect comes first)
    }
    if (!ok) {
      error = first;
      return false;
    }
  }
  return true;
}

// The request for `args` (command first); false with `error` on a usage problem.
bool buildRequest(const std::vector<std::string> &args, bool allowShrink, json &req,
                  std::string &error) {
  const std::string &cmd = args[0];
  std::vector<std::string> rest(args.begin() + 1, args.end());
  auto want = [&](size_t n, const char *usage) {
    if (rest.size() == n) return true;
    error = std::string("usage: ladderjit monitor ") + usage;
    return false;
  };
  if (cmd == "read" || cmd == "write") {
    if (rest.empty()) {
      error = cmd == "read" ? "usage: ladderjit monitor read ADDR..."
                            : "usage: ladderjit monitor write ADDR=VALUE...";
      return false;
    }
    if (!checkItems(rest, cmd == "write", error)) return false;
    req = {{"cmd", cmd}, {cmd == "read" ? "addrs" : "writes", rest}};
    return true;
  }
  if (cmd == "force") {
    if (!want(2, "force ID|id:ID|line:LINE on|off|restore")) return false;
    // ID (or id:ID) is a statement id (`ladderjit ladder` shows them); line:LINE the statements
    // on a source line of the running version (the older way, kept as an alias).
    std::string_view t = rest[0];
    const bool byLine = t.substr(0, 5) == "line:";
    if (byLine)
      t.remove_prefix(5);
    else if (t.substr(0, 3) == "id:")
      t.remove_prefix(3);
    int64_t n = -1;
    auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), n);
    if (t.empty() || ec != std::errc() || end != t.data() + t.size() || n < (byLine ? 1 : 0) ||
        n > INT32_MAX) {
      error = byLine ? "force: line:LINE needs a source line number >= 1, got '" + rest[0] + "'"
                     : "force: expected a statement id >= 0 (or line:LINE), got '" + rest[0] + "'";
      return false;
    }
    if (rest[1] != "on" && rest[1] != "off" && rest[1] != "restore") {
      error = "force: expected on, off or restore, got '" + rest[1] + "'";
      return false;
    }
    req = {{"cmd", "force"}, {byLine ? "line" : "id", n}, {"mode", rest[1]}};
    return true;
  }
  if (cmd == "lock") {
    if (!want(1, "lock ADDR=VALUE") || !checkItems(rest, true, error)) return false;
    req = {{"cmd", "lock"}, {"item", rest[0]}};
    return true;
  }
  if (cmd == "unlock") {
    if (!want(1, "unlock ADDR") || !checkItems(rest, false, error)) return false;
    req = {{"cmd", "unlock"}, {"addr", rest[0]}};
    return true;
  }
  if (cmd == "load") {
    // load PROGRAM (jit / interp servers), load PROGRAM PATH.so or load PATH.so (AOT servers;
    // the latter for the served PROGRAM). Paths go absolute: the server's cwd differs.
    if (rest.empty() || rest.size() > 2) {
      error = "usage: ladderjit monitor load PROGRAM [PATH.so] | load PATH.so";
      return false;
    }
    auto isSo = [](const std::string &p) {
      return p.size() > 3 && p.compare(p.size() - 3, 3, ".so") == 0;
    };
    if (rest.size() == 2 && !isSo(rest[1])) {
      error = "load: the second argument must be a .so built by `ladderjit compile`, got '" +
              rest[1] + "'";
      return false;
    }
    req = {{"cmd", "load"}};
    for (size_t i = 0; i < rest.size(); ++i) {
      std::error_code ec;
      std::filesystem::path p = std::filesystem::absolute(rest[i], ec);
      if (ec || !std::filesystem::exists(p)) {
        error = "load: cannot read '" + rest[i] + "'";
        return false;
      }
      if (!formats::isUtf8(p.string())) { // the control protocol is JSON: UTF-8 text only
        error = "load: the path '" + rest[i] +
                "' is not valid UTF-8; rename the file (the control protocol carries UTF-8)";
        return false;
      }
      req[isSo(rest[i]) && (i == 1 || rest.size() == 1) ? "so" : "program"] = p.string();
    }
    if (allowShrink) req["allow_shrink"] = true;
    return true;
  }
  if (cmd == "trace") {
    // trace define FILE | arm | trigger | stop | status | save FILE [--vcd|--csv] [--bits]
    // (docs/trace.md "monitor trace"): the client reads and writes the files, never the server.
    const char *usage = "usage: ladderjit monitor trace define FILE | arm | trigger | stop | "
                        "status | save FILE [--vcd|--csv] [--bits]";
    if (rest.empty()) {
      error = usage;
      return false;
    }
    const std::string &action = rest[0];
    req = {{"cmd", "trace"}, {"action", action}};
    if (action == "define") {
      std::string text;
      if (rest.size() != 2) {
        error = usage;
        return false;
      }
      if (!formats::readFile(rest[1], text, error)) return false;
      if (!formats::isUtf8(text)) {
        error = "trace define: '" + rest[1] + "' is not UTF-8 text";
        return false;
      }
      req["text"] = text;
      req["file"] = formats::isUtf8(rest[1]) ? rest[1] : std::string("definition");
      return true;
    }
    if (action == "save") {
      if (rest.size() < 2) {
        error = usage;
        return false;
      }
      std::string format = "vcd";
      bool bits = false;
      for (size_t i = 2; i < rest.size(); ++i) {
        if (rest[i] == "--vcd" || rest[i] == "--csv") {
          format = rest[i].substr(2);
        } else if (rest[i] == "--bits") {
          bits = true;
        } else {
          error = usage;
          return false;
        }
      }
      if (bits && format != "vcd") {
        error = "trace save: --bits is for --vcd";
        return false;
      }
      if (!formats::checkOutputPath(rest[1], error)) return false;
      req["format"] = format;
      req["bits"] = bits;
      return true;
    }
    if (action == "arm" || action == "trigger" || action == "stop" || action == "status") {
      if (rest.size() != 1) {
        error = usage;
        return false;
      }
      return true;
    }
    error = "trace: unknown action '" + action + "' (define, arm, trigger, stop, status, save)";
    return false;
  }
  if (cmd == "locks" || cmd == "stats" || cmd == "stop") {
    if (!want(0, cmd.c_str())) return false;
    req = {{"cmd", cmd}};
    return true;
  }
  error = "monitor: unknown command '" + cmd +
          "' (read, write, force, lock, unlock, locks, load, stats, trace, stop)";
  return false;
}

} // namespace

static int monitorOnce(const MonitorArgs &a);

int runMonitor(const MonitorArgs &a) {
  try {
    return monitorOnce(a);
  } catch (const std::exception &e) { // an answer of an unexpected shape
    return usageError(std::string("monitor: unexpected answer from the server: ") + e.what());
  }
}

static int monitorOnce(const MonitorArgs &a) {
  if (a.args.empty()) return usageError("monitor: missing command");
  json req, resp;
  std::string error, path;
  if (!buildRequest(a.args, a.allowShrink, req, error)) return usageError(error);
  if (!findControl(a.control, path, error)) return usageError(error);
  if (!rt::controlRequest(path, req, resp, error)) return usageError(error);
  if (!resp.value("ok", false)) return usageError(resp.value("error", std::string("refused")));
  const std::string &cmd = a.args[0];
  if (cmd == "read") {
    const json &vals = resp["values"];
    for (size_t i = 0; i < vals.size() && i + 1 < a.args.size(); ++i)
      std::printf("%s=%lld\n", a.args[i + 1].c_str(), vals[i].get<long long>());
  } else if (cmd == "force") {
    if (resp["forces"].empty()) std::printf("no forced contacts\n");
    for (const json &f : resp["forces"])
      std::printf("id %d line %d forced %s\n", f["id"].get<int>(), f["line"].get<int>(),
                  f["value"].get<int>() ? "on" : "off");
  } else if (cmd == "lock" || cmd == "unlock" || cmd == "locks") {
    for (const json &l : resp["locks"]) std::printf("%s\n", l.get<std::string>().c_str());
  } else if (cmd == "load") {
    std::printf("running version %llu\n", resp["version"].get<unsigned long long>());
  } else if (cmd == "stats") {
    std::printf("%s\n", formats::dumpJson(resp["stats"], 2).c_str());
  } else if (cmd == "trace" && a.args[1] == "save") {
    if (!formats::writeOutputFile(a.args[2], resp["data"].get<std::string>(), error))
      return usageError("trace save: " + error);
    std::printf("capture %llu: %llu ticks, trigger at tick %llu -> %s\n",
                resp["capture"].get<unsigned long long>(), resp["ticks"].get<unsigned long long>(),
                resp["trigger_tick"].get<unsigned long long>(), a.args[2].c_str());
  } else if (cmd == "trace") {
    json st = resp;
    st.erase("ok");
    std::printf("%s\n", formats::dumpJson(st, 2).c_str());
  }
  return kOk;
}

} // namespace lj::cli

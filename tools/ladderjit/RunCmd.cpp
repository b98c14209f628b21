// `ladderjit run` (PROGRAM an STL file or a plc.dit): validate every input first (usage errors
// exit 2 before anything runs), build the chosen engine, simulate, stream the watch table,
// optionally dump the final state.
#include "tools/ladderjit/Commands.h"

#include "engines/EngineSpec.h"
#include "formats/StateJson.h"
#include "hosts/Simulation.h"
#include "ir/Engine.h"
#include "jit/ObjectCache.h"

#include <charconv>
#include <cstdio>
#include <fstream>
#include <memory>

namespace lj::cli {

namespace {

constexpr size_t kRunNcLogLimit = 10000;

// Every user input of `run`, parsed and checked.
bool parseInputs(const RunArgs &a, const io::Dialect &d, io::SimOptions &sim, std::string &error) {
  sim.ticks = a.ticks;
  sim.periodMs = a.periodMs;
  for (const std::string &item : a.sets) {
    std::optional<io::Assignment> as = d.parseAssignment(item, error);
    if (!as) {
      error = "--set: " + error;
      return false;
    }
    sim.sets.push_back(std::move(*as));
  }
  for (const std::string &list : a.watch) {
    size_t pos = 0;
    while (true) {
      size_t comma = list.find(',', pos);
      std::string item = list.substr(pos, comma == std::string::npos ? comma : comma - pos);
      if (item.empty()) {
        error = "--watch: empty address in '" + list + "'";
        return false;
      }
      std::optional<io::CliAddress> addr = d.parseAddress(item, error);
      if (!addr) {
        error = "--watch: " + error;
        return false;
      }
      sim.watch.push_back(std::move(*addr));
      if (comma == std::string::npos) break;
      pos = comma + 1;
    }
  }
  std::string text;
  if (!a.stimulus.empty()) {
    if (!io::readFile(a.stimulus, text, error)) return false;
    std::optional<io::Stimulus> st = io::parseStimulus(text, a.stimulus, error, d.parseAssignment);
    if (!st) return false;
    sim.stimulus = std::move(*st);
  }
  if (!a.params.empty()) {
    if (!io::readFile(a.params, text, error)) return false;
    std::optional<std::vector<io::Assignment>> ps = io::parseParams(text, a.params, error);
    if (!ps) return false;
    sim.params = std::move(*ps);
  }
  return true;
}

// Buffered writer of the watch table: rows can number in the millions.
class TableWriter {
public:
  TableWriter(const std::vector<io::CliAddress> &watch, bool jsonl) : jsonl_(jsonl) {
    if (jsonl_) {
      for (const io::CliAddress &a : watch) keys_.push_back(nlohmann::json(a.text).dump());
    } else {
      buf_ += "tick";
      for (const io::CliAddress &a : watch) buf_ += "," + a.text;
      buf_ += '\n';
    }
  }
  ~TableWriter() { flush(); }

  void row(const io::WatchRow &r) {
    if (jsonl_) buf_ += "{\"tick\":";
    number(static_cast<int64_t>(r.tick));
    for (size_t i = 0; i < r.values.size(); ++i) {
      if (jsonl_) {
        buf_ += ',';
        buf_ += keys_[i];
        buf_ += ':';
      } else {
        buf_ += ',';
      }
      number(r.values[i]);
    }
    if (jsonl_) buf_ += '}';
    buf_ += '\n';
    if (buf_.size() > (1u << 16)) flush();
  }

  void flush() {
    std::fwrite(buf_.data(), 1, buf_.size(), stdout);
    std::fflush(stdout);
    buf_.clear();
  }

private:
  void number(int64_t v) {
    char tmp[24];
    auto res = std::to_chars(tmp, tmp + sizeof tmp, v);
    buf_.append(tmp, res.ptr);
  }
  bool jsonl_;
  std::vector<std::string> keys_;
  std::string buf_;
};

// Where --dump goes: opened before the run so an unwritable path is a usage error up front.
class DumpTarget {
public:
  bool open(const std::string &path, std::string &error) {
    path_ = path;
    if (path.empty() || path == "-") return true;
    file_.open(path, std::ios::binary | std::ios::trunc);
    if (!file_) error = "--dump: cannot write '" + path + "'";
    return static_cast<bool>(file_);
  }
  bool write(const lj_state &s, const io::SimNc &nc, const TargetProfile &tp, std::string &error) {
    if (path_.empty()) return true;
    nlohmann::ordered_json j = io::stateToJson(s, tp);
    j["nc"] = nc.toJson(); // the simulated NC (docs/simulated-nc.md "Dump")
    std::string text = j.dump() + "\n";
    if (path_ == "-") {
      std::fwrite(text.data(), 1, text.size(), stdout);
      return true;
    }
    if (!(file_ << text) || !file_.flush()) {
      error = "--dump: cannot write '" + path_ + "'";
      return false;
    }
    return true;
  }

private:
  std::string path_;
  std::ofstream file_;
};

} // namespace

int runRun(const RunArgs &a) {
  if (a.format != "csv" && a.format != "jsonl")
    return usageError("--format: expected csv or jsonl, got '" + a.format + "'");
  Result<engines::EngineSpec> spec = engines::parseEngineSpec(a.engine);
  if (!spec) return usageError(spec.status().message());
  if (a.periodMs > (uint64_t{1} << 40))
    return usageError("--period-ms: too large (at most 2^40 ms)");

  io::SimOptions sim;
  std::string error;
  int code = kOk;
  ProgramSource src;
  if (!readProgram(a.program, src, code, a.dialect)) return code;
  // Addresses (--set, --watch, the stimulus) are written in the program's dialect.
  if (!parseInputs(a, *src.dialect, sim, error)) return usageError(error);
  if (src.dit) {
    // A container's parameters are defaults: its P values go first so --params and --set
    // override them; its period counts unless --period-ms was given (docs/plc-dit.md "run").
    sim.params.insert(sim.params.begin(), src.dit->params.begin(), src.dit->params.end());
    if (!a.periodMsGiven) sim.periodMs = src.dit->periodMs;
  }
  const int32_t nvalue = effectiveNvalue(src, a.plc2Nvalue, a.plc2NvalueGiven);
  std::optional<VerifiedProgram> prog = loadProgram(src, nvalue, code);
  if (!prog) return code;
  sim.profile = prog->profile;

  engines::EngineOptions eo;
  io::TrustedKeys trust;
  if (spec->kind == engines::EngineKind::Jit)
    eo.cache = jit::ObjectCache::fromEnvironment(); // docs/aot.md "Object cache"
  if (spec->kind == engines::EngineKind::Aot) {
    // The signers `--trust-key` names (none: the default public key), docs/aot.md "Trust".
    if (!io::loadTrustedKeys(a.trustKeys, trust, error))
      return usageError("--engine aot: " + error);
    eo.aotExpect = io::aotExpectOf(src, nvalue);
    eo.aotTrust = &trust;
  }
  Result<std::unique_ptr<Engine>> made = engines::makeEngine(*spec, *prog, eo);
  if (!made)
    return usageError((spec->kind == engines::EngineKind::Aot ? "--engine aot: " : "jit: ") +
                      made.status().message());
  std::unique_ptr<Engine> engine = std::move(made).value();

  DumpTarget dump; // opened only once the program is known to run
  if (!dump.open(a.dump, error)) return usageError(error);

  for (const io::StimulusEvent &ev : sim.stimulus.events) {
    if (ev.tick >= a.ticks) {
      std::fprintf(stderr, "ladderjit: warning: %s:%d: tick %llu is never reached (--ticks %llu)\n",
                   a.stimulus.c_str(), ev.line, static_cast<unsigned long long>(ev.tick),
                   static_cast<unsigned long long>(a.ticks));
      break; // ticks are sorted: one warning covers the rest
    }
  }

  sim.maxBackwardSteps = a.maxBackwardSteps;
  auto state = std::make_unique<lj_state>();
  // Every engine runs against the simulated NC (docs/simulated-nc.md). Its log keeps the last
  // kRunNcLogLimit host calls and events (the --dump says how many were dropped): a run of
  // millions of ticks of a SAVEDATA / EVENT-heavy program must not keep them all.
  io::SimNcConfig ncConfig;
  ncConfig.logLimit = kRunNcLogLimit;
  auto nc = std::make_unique<io::SimNc>(ncConfig);
  io::Simulation run(engine->entries(), *state, sim, nc.get());
  if (uint32_t f = run.powerUp(); f != LJ_FAULT_NONE)
    std::fprintf(stderr, "ladderjit: init: fault: %s (the init part was aborted)\n",
                 io::faultName(f));
  std::optional<TableWriter> table;
  if (!sim.watch.empty()) table.emplace(sim.watch, a.format == "jsonl");
  io::WatchRow row;
  while (!run.done()) {
    if (uint32_t f = run.step(row); f != LJ_FAULT_NONE) {
      if (table) table->flush(); // keep stdout and stderr in tick order on a terminal
      std::fprintf(stderr, "ladderjit: tick %llu: fault: %s (the tick was aborted)\n",
                   static_cast<unsigned long long>(row.tick), io::faultName(f));
    }
    if (table) table->row(row);
  }
  if (table) table->flush();
  if (!dump.write(*state, *nc, *prog->profile, error)) return usageError(error);
  return kOk;
}

} // namespace lj::cli

// `ladderjit run` (PROGRAM an STL file or a plc.dit): validate every input first (usage errors
// exit 2 before anything runs), build the chosen engine, simulate, stream the watch table,
// optionally dump the final state.
#include "tools/ladderjit/Commands.h"

#include "engines/EngineSpec.h"
#include "formats/OutputFile.h"
#include "formats/StateJson.h"
#include "formats/Vcd.h"
#include "hosts/Simulation.h"
#include "ir/Engine.h"
#include "runtime/TierUp.h"

#include <charconv>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <mutex>
#include <thread>

namespace lj::cli {

namespace {

constexpr size_t kRunNcLogLimit = 10000;

// The addressed inputs of `run` (--set, --watch, --stimulus), parsed and checked. Addresses
// may be symbols of the program (`--watch COOLANT`): `symbols` are its symbols; with
// `namesLater` (before the program is read) an item shaped like a name passes, to be read again
// with the symbols once they are known.
bool parseAddressed(const RunArgs &a, const pipeline::Dialect &d, std::span<const Symbol> symbols,
                    bool namesLater, hosts::SimOptions &sim, std::string &error) {
  sim.sets.clear();
  sim.watch.clear();
  sim.stimulus = {};
  auto later = [&](std::string_view item) {
    return namesLater && SymbolTable::isNameShaped(item.substr(0, item.find('=')));
  };
  auto assign = [&](std::string_view item, std::string &why) -> std::optional<formats::Assignment> {
    if (later(item)) return formats::Assignment{};
    return formats::parseAssignmentIn(d.parseAddress, d.parseAssignment, symbols, item, why);
  };
  for (const std::string &item : a.sets) {
    std::optional<formats::Assignment> as = assign(item, error);
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
      std::optional<formats::CliAddress> addr =
          later(item) ? formats::CliAddress{}
                      : formats::parseAddressIn(d.parseAddress, symbols, item, error);
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
    if (!formats::readFile(a.stimulus, text, error)) return false;
    std::optional<formats::Stimulus> st = formats::parseStimulus(text, a.stimulus, error, assign);
    if (!st) return false;
    sim.stimulus = std::move(*st);
  }
  return true;
}

// Every user input of `run`, parsed and checked (names among the addresses: parseAddressed).
bool parseInputs(const RunArgs &a, const pipeline::Dialect &d, hosts::SimOptions &sim,
                 std::string &error) {
  sim.ticks = a.ticks;
  sim.periodMs = a.periodMs;
  if (!parseAddressed(a, d, {}, true, sim, error)) return false;
  std::string text;
  if (!a.params.empty()) {
    if (!formats::readFile(a.params, text, error)) return false;
    std::optional<std::vector<formats::Assignment>> ps =
        formats::parseParams(text, a.params, error, d.profile);
    if (!ps) return false;
    sim.params = std::move(*ps);
  }
  return true;
}

// Buffered writer of the watch table: rows can number in the millions.
class TableWriter {
public:
  TableWriter(const std::vector<formats::CliAddress> &watch, bool jsonl) : jsonl_(jsonl) {
    if (jsonl_) {
      for (const formats::CliAddress &a : watch) keys_.push_back(nlohmann::json(a.text).dump());
    } else {
      buf_ += "tick";
      for (const formats::CliAddress &a : watch) buf_ += "," + a.text;
      buf_ += '\n';
    }
  }
  ~TableWriter() { flush(); }

  void row(const hosts::WatchRow &r) {
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
    if (formats::checkOutputPath(path, error)) return true;
    error = "--dump: " + error;
    return false;
  }
  bool write(const lj_state &s, const hosts::SimNc &nc, const TargetProfile &tp,
             std::string &error) {
    if (path_.empty()) return true;
    nlohmann::ordered_json j = formats::stateToJson(s, tp);
    j["nc"] = nc.toJson(); // the simulated NC (docs/simulated-nc.md "Dump")
    std::string text = j.dump() + "\n";
    if (path_ == "-") {
      std::fwrite(text.data(), 1, text.size(), stdout);
      return true;
    }
    if (formats::writeOutputFile(path_, text, error)) return true;
    error = "--dump: " + error;
    return false;
  }

private:
  std::string path_;
};

// Where --vcd goes (docs/trace.md "run --vcd"): the value change dump of the --watch addresses,
// streamed through a private temporary file and renamed over FILE at the end, so a run that
// fails leaves no half file.
class VcdTarget {
public:
  ~VcdTarget() {
    if (f_) std::fclose(f_);
  }
  bool open(const std::string &path, const std::vector<formats::CliAddress> &watch,
            uint64_t periodMs, bool splitBits, const std::string &program, std::string &error) {
    if (path == "-") {
      error = "--vcd: standard output carries the watch table; give a file name";
      return false;
    }
    if (watch.empty()) {
      error = "--vcd: records the --watch addresses; give --watch ADDR[,ADDR...]";
      return false;
    }
    if (!file_.open(path, error) || !(f_ = std::fopen(file_.tempPath().c_str(), "w"))) {
      if (error.empty()) error = "cannot write '" + path + "'";
      error = "--vcd: " + error;
      return false;
    }
    std::vector<formats::SignalInfo> sigs;
    for (const formats::CliAddress &a : watch) sigs.push_back({a.text, formats::signalBits(a)});
    writer_.emplace(std::move(sigs), periodMs * 1000000, splitBits,
                    "ladderjit run " + formats::vcdName(program));
    buf_ = writer_->header();
    return true;
  }
  void row(const hosts::WatchRow &r) {
    if (!f_) return;
    writer_->row(r.tick, r.values.data(), buf_);
    last_ = r.tick;
    any_ = true;
    if (buf_.size() > (1u << 16)) flush();
  }
  bool close(std::string &error) {
    if (!f_) return true;
    if (any_) writer_->finish(last_, buf_);
    flush();
    const bool ok = !std::ferror(f_);
    std::fclose(f_);
    f_ = nullptr;
    if (!ok || !file_.commit(error)) {
      error = "--vcd: " + (error.empty() ? std::string("write failed") : error);
      return false;
    }
    return true;
  }

private:
  void flush() {
    std::fwrite(buf_.data(), 1, buf_.size(), f_);
    buf_.clear();
  }
  formats::OutputFile file_;
  std::FILE *f_ = nullptr;
  std::optional<formats::VcdWriter> writer_;
  std::string buf_;
  uint64_t last_ = 0;
  bool any_ = false;
};

// TIER: the JIT tiers of `run --tier` (docs/serve.md "Tiering"), built one after another on a
// background thread while the interpreter runs the first ticks.
class BackgroundJit {
public:
  BackgroundJit(const VerifiedProgram &prog, std::vector<rt::EngineTier> tiers)
      : tiers_(std::move(tiers)) {
    built_.resize(tiers_.size());
    thread_ = std::thread([this, &prog] {
      for (size_t i = 0; i < tiers_.size(); ++i) {
        engines::EngineOptions eo;
        eo.fastTier = tiers_[i] == rt::EngineTier::JitFast;
        eo.cacheFromEnvironment = true; // docs/aot.md "Object cache"
        Result<std::unique_ptr<Engine>> made =
            engines::makeEngine(engines::EngineSpec{engines::EngineKind::Jit, {}}, prog, eo);
        std::lock_guard<std::mutex> g(mu_);
        if (!made) {
          error_ = std::string(rt::engineTierName(tiers_[i])) + ": " + made.status().message();
          failed_ = true;
          break;
        }
        built_[i] = std::move(made).value();
        done_ = i + 1;
        cv_.notify_all();
      }
      std::lock_guard<std::mutex> g(mu_);
      finished_ = true;
      cv_.notify_all();
    });
  }
  ~BackgroundJit() {
    if (thread_.joinable()) thread_.join();
  }
  size_t count() const { return tiers_.size(); }
  rt::EngineTier tier(size_t i) const { return tiers_[i]; }
  /// Tier i's engine once built; null before (or, with `wait`, only when the build failed:
  /// `error` says why).
  Engine *get(size_t i, bool wait, std::string &error) {
    std::unique_lock<std::mutex> g(mu_);
    if (wait) cv_.wait(g, [&] { return done_ > i || failed_; });
    if (done_ > i) return built_[i].get();
    if (failed_) error = error_;
    return nullptr;
  }
  bool failed() {
    std::lock_guard<std::mutex> g(mu_);
    return failed_;
  }
  bool finished() {
    std::lock_guard<std::mutex> g(mu_);
    return finished_;
  }
  /// Let a compile still running end with the process.
  void detach() { thread_.detach(); }

private:
  std::vector<rt::EngineTier> tiers_;
  std::mutex mu_;
  std::condition_variable cv_;
  std::vector<std::unique_ptr<Engine>> built_;
  size_t done_ = 0;
  bool failed_ = false, finished_ = false;
  std::string error_;
  std::thread thread_;
};

// --tier-switch-tick N[,M]: one tick per background tier, in order, not decreasing.
bool parseSwitchTicks(const std::string &text, size_t tiers, std::vector<uint64_t> &out,
                      std::string &error) {
  size_t pos = 0;
  while (pos <= text.size() && !text.empty()) {
    size_t comma = text.find(',', pos);
    std::string item = text.substr(pos, comma == std::string::npos ? comma : comma - pos);
    uint64_t v = 0;
    auto [end, ec] = std::from_chars(item.data(), item.data() + item.size(), v);
    if (item.empty() || ec != std::errc() || end != item.data() + item.size()) {
      error = "--tier-switch-tick: expected tick numbers N[,M], got '" + text + "'";
      return false;
    }
    if (!out.empty() && v < out.back()) {
      error = "--tier-switch-tick: the ticks must not decrease, got '" + text + "'";
      return false;
    }
    out.push_back(v);
    if (comma == std::string::npos) break;
    pos = comma + 1;
  }
  if (out.size() > tiers) {
    error = "--tier-switch-tick: " + std::to_string(out.size()) +
            " ticks, but the tier plan "
            "switches " +
            std::to_string(tiers) + " time(s)";
    return false;
  }
  return true;
}

} // namespace

int runRun(const RunArgs &a) {
  if (a.format != "csv" && a.format != "jsonl")
    return usageError("--format: expected csv or jsonl, got '" + a.format + "'");
  Result<engines::EngineSpec> spec = engines::parseEngineSpec(a.engine);
  if (!spec) return usageError(spec.status().message());
  // 0 would stop time (now_ms = tick * period): no timer would ever run out.
  if (a.periodMs < 1 || a.periodMs > (uint64_t{1} << 40))
    return usageError("--period-ms: expected 1..2^40, got " + std::to_string(a.periodMs));
  std::string tierError;
  std::optional<rt::TierPlan> plan = rt::parseTierPlan(a.tier, tierError);
  if (!plan) return usageError(tierError);
  const std::vector<rt::EngineTier> tiers = rt::backgroundTiers(*plan);
  if (!tiers.empty() && spec->kind != engines::EngineKind::Jit)
    return usageError("--tier " + a.tier +
                      " needs --engine jit (it switches from the interpreter to the JIT)");
  std::vector<uint64_t> switchTicks;
  if (!a.tierSwitchTicks.empty()) {
    if (tiers.empty())
      return usageError("--tier-switch-tick needs --tier interp-first or "
                        "interp-fast-opt");
    if (!parseSwitchTicks(a.tierSwitchTicks, tiers.size(), switchTicks, tierError))
      return usageError(tierError);
  }

  hosts::SimOptions sim;
  std::string error;
  int code = kOk;
  ProgramSource src;
  if (!readProgram(a.program, src, code, a.dialect)) return code;
  // Addresses (--set, --watch, the stimulus) are written in the program's dialect; names among
  // them are read once the program (and so its symbols) is.
  if (!parseInputs(a, *src.dialect, sim, error)) return usageError(error);
  if (src.dit) {
    // A container's parameters are defaults: its P values go first so --params and --set
    // override them; its period counts unless --period-ms was given (docs/plc-dit.md "run").
    sim.params.insert(sim.params.begin(), src.dit->params.begin(), src.dit->params.end());
    if (!a.periodMsGiven) sim.periodMs = src.dit->periodMs;
  }
  const int32_t nvalue = effectiveNvalue(src, a.plc2Nvalue, a.plc2NvalueGiven);
  std::optional<VerifiedProgram> prog = loadProgram(
      src, nvalue, code, a.quiet ? WarningReport::None : WarningReport::Summary, a.dialect);
  if (!prog) return code;
  if (!parseAddressed(a, *src.dialect, prog->symbols, false, sim, error)) return usageError(error);
  sim.profile = prog->profile;

  engines::EngineOptions eo;
  signing::TrustedKeys trust;
  if (spec->kind == engines::EngineKind::Jit)
    eo.cacheFromEnvironment = true; // docs/aot.md "Object cache"
  if (spec->kind == engines::EngineKind::Aot) {
    // The signers `--trust-key` names (none: the default public key), docs/aot.md "Trust".
    if (!signing::loadTrustedKeys(a.trustKeys, trust, error))
      return usageError("--engine aot: " + error);
    eo.aotExpect = engines::aotExpectOf(src, nvalue);
    eo.aotTrust = &trust;
  }
  // TIER: interpreter-first, the interpreter runs at once, the JIT is built in the background.
  Result<std::unique_ptr<Engine>> made =
      tiers.empty()
          ? engines::makeEngine(*spec, *prog, eo)
          : engines::makeEngine(engines::EngineSpec{engines::EngineKind::Interp, {}}, *prog, eo);
  if (!made)
    return usageError((spec->kind == engines::EngineKind::Aot ? "--engine aot: " : "jit: ") +
                      made.status().message());
  std::unique_ptr<Engine> engine = std::move(made).value();

  DumpTarget dump; // opened only once the program is known to run
  if (!dump.open(a.dump, error)) return usageError(error);
  VcdTarget vcd;
  if (!a.vcd.empty() && !vcd.open(a.vcd, sim.watch, sim.periodMs, a.vcdBits, a.program, error))
    return usageError(error);
  if (a.vcd.empty() && a.vcdBits) return usageError("--vcd-bits needs --vcd FILE");

  for (const formats::StimulusEvent &ev : sim.stimulus.events) {
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
  hosts::SimNcConfig ncConfig;
  ncConfig.logLimit = kRunNcLogLimit;
  auto nc = std::make_unique<hosts::SimNc>(ncConfig);
  hosts::Simulation run(engine->entries(), *state, sim, nc.get());
  std::unique_ptr<BackgroundJit> background;
  if (!tiers.empty()) background = std::make_unique<BackgroundJit>(*prog, tiers);
  size_t nextTier = 0;
  // Before each tick: switch to every tier that is due (its --tier-switch-tick reached, waiting
  // for its build) or, without a given tick, already built. Only the code changes.
  auto tierUp = [&] {
    while (background && nextTier < background->count()) {
      const bool pinned = nextTier < switchTicks.size();
      if (pinned && run.nextTick() < switchTicks[nextTier]) return;
      std::string err;
      Engine *e = background->get(nextTier, pinned, err);
      if (!e) {
        if (background->failed()) {
          std::fprintf(stderr, "ladderjit: warning: %s (the run goes on with the engine it has)\n",
                       err.empty() ? "the background JIT build failed" : err.c_str());
          nextTier = background->count();
        }
        return;
      }
      run.setEntries(e->entries());
      std::fprintf(stderr, "ladderjit: tiering: %s from tick %llu\n",
                   rt::engineTierName(background->tier(nextTier)),
                   static_cast<unsigned long long>(run.nextTick()));
      ++nextTier;
    }
  };
  if (uint32_t f = run.powerUp(); f != LJ_FAULT_NONE)
    std::fprintf(stderr, "ladderjit: init: fault: %s (the init part was aborted)\n",
                 hosts::faultName(f));
  std::optional<TableWriter> table;
  if (!sim.watch.empty()) table.emplace(sim.watch, a.format == "jsonl");
  hosts::WatchRow row;
  while (!run.done()) {
    tierUp();
    if (uint32_t f = run.step(row); f != LJ_FAULT_NONE) {
      if (table) table->flush(); // keep stdout and stderr in tick order on a terminal
      std::fprintf(stderr, "ladderjit: tick %llu: fault: %s (the tick was aborted)\n",
                   static_cast<unsigned long long>(row.tick), hosts::faultName(f));
    }
    if (table) table->row(row);
    vcd.row(row);
  }
  if (table) table->flush();
  if (!vcd.close(error)) return usageError(error);
  if (!dump.write(*state, *nc, *prog->profile, error)) return usageError(error);
  if (background && !background->finished()) {
    // TIER: the result is complete; a compile still running ends with the process.
    background->detach();
    int code = checkStdout(kOk);
    std::fflush(stderr);
    std::_Exit(code);
  }
  return kOk;
}

} // namespace lj::cli

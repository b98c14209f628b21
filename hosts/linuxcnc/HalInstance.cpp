// Loading one program for the HAL component and its real-time tick.
#include "hosts/linuxcnc/HalInstance.h"

#include "engines/AotLoader.h"
#include "formats/InputFiles.h"
#include "hosts/SystemBits.h"
#include "ir/Diagnostics.h"
#include "pipeline/ProgramFile.h"
#include "services/RetainStore.h"
#include "signing/AotTrust.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdlib>
#include <new>
#include <sys/stat.h>
#include <thread>

namespace lj::hal {

namespace {

bool exists(const std::string &p) {
  struct stat st {};
  return stat(p.c_str(), &st) == 0;
}

std::vector<std::string> splitComma(const std::string &s) {
  std::vector<std::string> out;
  size_t start = 0;
  while (start <= s.size()) {
    size_t comma = s.find(',', start);
    std::string part =
        s.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    if (!part.empty()) out.push_back(part);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
}

/// names=: empty (classicladder_rt's prefix), or a HAL name short enough that its function's
/// `.refresh.tmax` and every pin fit HAL_NAME_LEN (checkPins checks the pins exactly).
bool validClassicName(const std::string &n) {
  if (n.empty()) return true;
  if (n.size() > 32 || n.front() == '.' || n.back() == '.') return false;
  return std::all_of(n.begin(), n.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.';
  });
}

} // namespace

bool loadProgram(const Options &opt, const std::string &sourcePath, const std::string &prefix,
                 Loaded &out, std::string &error) {
  // A bad parameter is an error naming it, never silently the default (issue 28 finding 10).
  const bool nvalueGiven = opt.plc2Nvalue != Options::kNvalueUnset;
  if (nvalueGiven && opt.plc2Nvalue < 0) {
    error = "plc2_nvalue: expected 0..2147483647, got " + std::to_string(opt.plc2Nvalue);
    return false;
  }
  const std::vector<std::string> trustFiles = splitComma(opt.trust);
  if (!opt.trust.empty() &&
      trustFiles.size() !=
          static_cast<size_t>(std::count(opt.trust.begin(), opt.trust.end(), ',')) + 1) {
    error = "trust: an empty key file name in '" + printable(opt.trust) +
            "' (expected KEY.pub[,KEY.pub...])";
    return false;
  }
  if (!validClassicName(opt.classicName)) {
    error = "names=" + printable(opt.classicName) +
            ": expected 1-32 letters, digits, '_', '-' or '.' (not at either end), a HAL name";
    return false;
  }
  pipeline::ProgramSource src;
  if (Status st = pipeline::readProgramFile(sourcePath, src); !st.ok()) {
    error = st.message();
    return false;
  }
  int32_t nvalue = pipeline::effectiveNvalue(src, nvalueGiven ? opt.plc2Nvalue : 200, nvalueGiven);
  std::string diags;
  std::optional<VerifiedProgram> prog = pipeline::verifyProgram(src, nvalue, diags);
  if (!prog) {
    size_t nl = diags.find('\n');
    error = "'" + sourcePath + "' has errors: " + diags.substr(0, nl);
    return false;
  }
  signing::TrustedKeys keys;
  if (!signing::loadTrustedKeys(trustFiles, keys, error)) {
    error = "trusted keys: " + error;
    return false;
  }
  engines::AotExpect expect = engines::aotExpectOf(src, nvalue);
  out.hash = expect.program;
  out.engine = engines::loadAot(opt.program, expect, keys, error);
  if (!out.engine) return false;
  out.entries = out.engine->entries();
  out.profile = prog->profile;
  // A ClassicLadder project gets classicladder_rt's pins (docs/linuxcnc.md "ClassicLadder
  // drop-in"), so its HAL file keeps its nets; other programs their X / Y bits.
  out.classic = src.dialect == pipeline::dialectNamed("classicladder");
  if (out.classic) {
    if (!classicLadderPins(opt.classic, *src.dialect, out.pins, error)) return false;
  } else {
    out.pins = defaultPins(*prog, *src.dialect);
  }
  if (!opt.map.empty()) {
    std::string text;
    if (!formats::readFile(opt.map, text, error)) return false;
    if (!applyMap(text, opt.map, out.pins, error, *src.dialect)) return false;
  }
  if (!out.classic && !opt.classicName.empty()) {
    error = "names=" + printable(opt.classicName) +
            ": only a ClassicLadder source (.clp) takes names= (its pins are named by " +
            "classicladder_rt's convention); this program's pins are '" + prefix + ".*'";
    return false;
  }
  return checkPins(out.pins, out.classic ? classicPrefix(opt) : prefix, error);
}

std::string classicPrefix(const Options &opt) {
  return opt.classicName.empty() ? std::string(kClassicPrefix) : opt.classicName;
}

std::string sourceBeside(const std::string &soPath) {
  std::string base = soPath;
  if (base.size() > 3 && base.compare(base.size() - 3, 3, ".so") == 0) base.resize(base.size() - 3);
  for (const char *ext : {".dit", ".stl", ".json", ".pmc", ".il", ".clp"})
    if (exists(base + ext)) return base + ext;
  return {};
}

Instance *Instance::create(const Options &opt, const std::string &prefix, std::string &error) {
  if (opt.program.empty()) {
    error = "no program: give program=PATH.so (built by `ladderjit compile`)";
    return nullptr;
  }
  std::unique_ptr<Instance> inst(new Instance());
  inst->soPath_ = opt.program;
  inst->sourcePath_ = opt.source.empty() ? sourceBeside(opt.program) : opt.source;
  if (inst->sourcePath_.empty()) {
    error = "'" + opt.program +
            "': no program source beside it (.dit, .stl, .json, .pmc or .il of the same "
            "name); give source=PROGRAM (the file it was compiled from)";
    return nullptr;
  }
  inst->opt_ = opt;
  inst->prefix_ = prefix;
  Loaded first;
  if (!loadProgram(opt, inst->sourcePath_, prefix, first, error)) return nullptr;
  inst->engine_ = std::move(first.engine);
  inst->entries_ = first.entries;
  inst->pins_ = std::move(first.pins);
  for (PinSpec &p : inst->pins_) p.at = formats::resolveAddress(p.addr);
  inst->classic_ = first.classic;
  inst->profile_ = first.profile;
  inst->programHash_ = first.hash;

  inst->state_ = new (std::nothrow) lj_state;
  if (!inst->state_) {
    error = "out of memory for the program state";
    return nullptr;
  }
  lj_state_reset(inst->state_);
  inst->state_->host = nullptr; // no NC services in HAL: map F/G words to pins instead
  if (!opt.params.empty()) {
    std::string text;
    if (!formats::readFile(opt.params, text, error)) return nullptr;
    auto list = formats::parseParams(text, opt.params, error, inst->profile_);
    if (!list) return nullptr;
    for (const formats::Assignment &a : *list)
      formats::writeAddress(*inst->state_, a.addr, a.value);
  }
  if (!opt.retain.empty()) {
    services::RetainConfig cfg;
    cfg.path = opt.retain;
    cfg.programHash = inst->programHash_;
    cfg.profile = inst->profile_; // what the target retains (docs/retain.md)
    cfg.log = opt.log;
    inst->retain_ = std::make_unique<services::RetainStore>(cfg);
    if (!inst->retain_->prepare(error)) {
      error = "retain store '" + opt.retain + "': " + error;
      return nullptr;
    }
    services::RestoreReport rep = inst->retain_->restore(*inst->state_, 0);
    if (rep.status == services::RestoreStatus::LayoutMismatch ||
        rep.status == services::RestoreStatus::DamagedNotKept) {
      error = "retain store '" + opt.retain + "': " + rep.message;
      return nullptr;
    }
  }
  return inst.release();
}

Instance::~Instance() {
  stopLoader();
  delete pending_.exchange(nullptr);
  delete retired_.exchange(nullptr);
  retain_.reset();
  engine_.reset();
  delete state_;
}

bool Instance::takePending() {
  if (!pending_.load(std::memory_order_acquire) || retired_.load(std::memory_order_acquire))
    return false;
  Loaded *next = pending_.exchange(nullptr, std::memory_order_acq_rel);
  // Swap the code, keep the state (and with it every retained value): `next` now holds the
  // old engine, which the loader thread frees (no free() on the real-time thread).
  std::swap(engine_, next->engine);
  std::swap(entries_, next->entries);
  programHash_.swap(next->hash);
  retired_.store(next, std::memory_order_release);
  reloads_.fetch_add(1, std::memory_order_relaxed);
  return true;
}

uint32_t Instance::tick(uint64_t periodNs) {
  state_->now_ms = elapsedNs_ / 1000000u;
  // Online change at the thread boundary (docs/linuxcnc.md): the new program's init runs on
  // the kept state, before this tick, as `serve` does.
  if (takePending()) inited_ = false;
  if (!inited_) {
    inited_ = true;
    lj_run_init(state_, &entries_);
  }
  // The target's system bits (FANUC R9091 constants and clocks, R9015 first scan) before every
  // tick, after init, as `run` and `serve` write them (hosts/SystemBits.h).
  if (profile_) hosts::writeSystemBits(*profile_, *state_, ticks_);
  uint32_t fault = lj_tick(state_, &entries_);
  if (retain_) retain_->afterTick(*state_, ticks_);
  elapsedNs_ += periodNs;
  ++ticks_;
  return fault;
}

void Instance::startRetain() {
  if (retain_ && !retainStarted_) {
    retain_->start();
    retainStarted_ = true;
  }
}

void Instance::stopRetain() {
  if (retain_ && retainStarted_) {
    retain_->stop(*state_, ticks_ ? ticks_ - 1 : 0);
    retainStarted_ = false;
  }
}

void Instance::requestReload() { reloadRequested_.store(true, std::memory_order_release); }

void Instance::startLoader() {
  if (loader_.joinable()) return;
  loader_ = std::thread([this] { loaderLoop(); });
}

void Instance::stopLoader() {
  stopLoader_.store(true, std::memory_order_release);
  if (loader_.joinable()) loader_.join();
}

void Instance::loaderLoop() {
  while (!stopLoader_.load(std::memory_order_acquire)) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    delete retired_.exchange(nullptr, std::memory_order_acq_rel); // the old engine, swapped out
    if (pending_.load(std::memory_order_acquire) ||
        !reloadRequested_.exchange(false, std::memory_order_acq_rel))
      continue;
    auto next = std::make_unique<Loaded>();
    std::string error;
    bool ok = loadProgram(opt_, sourcePath_, prefix_, *next, error);
    if (ok && next->profile != profile_) {
      ok = false;
      error = "the new program is for another target (" + std::string(next->profile->name) +
              ", running " + profile_->name + ")";
    }
    if (ok && !samePins(next->pins, pins_)) {
      ok = false;
      error = "the new program needs other pins than the running one (HAL pins cannot change "
              "while the component runs: unload and load it instead)";
    }
    if (!ok) {
      reloadFailures_.fetch_add(1, std::memory_order_relaxed);
      if (opt_.log) opt_.log("online change refused, the old program keeps running: " + error);
      continue;
    }
    if (opt_.log)
      opt_.log("online change: " + next->hash + " ready, swapped in at the next refresh");
    pending_.store(next.release(), std::memory_order_release);
  }
}

bool samePins(const std::vector<PinSpec> &a, const std::vector<PinSpec> &b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (a[i].name != b[i].name || a[i].type != b[i].type || a[i].out != b[i].out ||
        a[i].addr.text != b[i].addr.text || a[i].scale != b[i].scale)
      return false;
  return true;
}

std::string Instance::summary() const {
  size_t in = 0, out = 0;
  for (const PinSpec &p : pins_) (p.out ? out : in)++;
  return "'" + soPath_ + "' (" + programHash_ + ", source '" + sourcePath_ +
         "'): " + std::to_string(in) + " input and " + std::to_string(out) + " output pins" +
         (retain_ ? ", retain store on" : "");
}

} // namespace lj::hal

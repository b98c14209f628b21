// Loading one program for the HAL component and its real-time tick.
#include "hosts/linuxcnc/HalInstance.h"

#include "engines/AotLoader.h"
#include "engines/AotTrust.h"
#include "formats/InputFiles.h"
#include "formats/ProgramFile.h"
#include "hosts/SystemBits.h"
#include "services/RetainStore.h"

#include <cstdlib>
#include <new>
#include <sys/stat.h>

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

} // namespace

std::string sourceBeside(const std::string &soPath) {
  std::string base = soPath;
  if (base.size() > 3 && base.compare(base.size() - 3, 3, ".so") == 0) base.resize(base.size() - 3);
  for (const char *ext : {".dit", ".stl", ".json", ".pmc", ".il"})
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
  io::ProgramSource src;
  if (!io::readProgramFile(inst->sourcePath_, src, error)) return nullptr;
  int32_t nvalue =
      io::effectiveNvalue(src, opt.plc2Nvalue < 0 ? 200 : opt.plc2Nvalue, opt.plc2Nvalue >= 0);
  std::string diags;
  std::optional<VerifiedProgram> prog = io::verifyProgram(src, nvalue, diags);
  if (!prog) {
    size_t nl = diags.find('\n');
    error = "'" + inst->sourcePath_ + "' has errors: " + diags.substr(0, nl);
    return nullptr;
  }
  io::TrustedKeys keys;
  if (!io::loadTrustedKeys(splitComma(opt.trust), keys, error)) {
    error = "trusted keys: " + error;
    return nullptr;
  }
  io::AotExpect expect = io::aotExpectOf(src, nvalue);
  inst->programHash_ = expect.program;
  inst->engine_ = io::loadAot(opt.program, expect, keys, error);
  if (!inst->engine_) return nullptr;
  inst->entries_ = inst->engine_->entries();

  inst->profile_ = prog->profile;
  inst->pins_ = defaultPins(*prog, *src.dialect);
  if (!opt.map.empty()) {
    std::string text;
    if (!io::readFile(opt.map, text, error)) return nullptr;
    if (!applyMap(text, opt.map, inst->pins_, error, *src.dialect)) return nullptr;
  }
  if (!checkPins(inst->pins_, prefix, error)) return nullptr;

  inst->state_ = new (std::nothrow) lj_state;
  if (!inst->state_) {
    error = "out of memory for the program state";
    return nullptr;
  }
  lj_state_reset(inst->state_);
  inst->state_->host = nullptr; // no NC services in HAL: map F/G words to pins instead
  if (!opt.params.empty()) {
    std::string text;
    if (!io::readFile(opt.params, text, error)) return nullptr;
    auto list = io::parseParams(text, opt.params, error);
    if (!list) return nullptr;
    for (const io::Assignment &a : *list) io::writeAddress(*inst->state_, a.addr, a.value);
  }
  if (!opt.retain.empty()) {
    io::RetainConfig cfg;
    cfg.path = opt.retain;
    cfg.programHash = inst->programHash_;
    cfg.profile = prog->profile; // what the target retains (docs/retain.md)
    cfg.log = opt.log;
    inst->retain_ = std::make_unique<io::RetainStore>(cfg);
    if (!inst->retain_->prepare(error)) {
      error = "retain store '" + opt.retain + "': " + error;
      return nullptr;
    }
    io::RestoreReport rep = inst->retain_->restore(*inst->state_, 0);
    if (rep.status == io::RestoreStatus::LayoutMismatch) {
      error = "retain store '" + opt.retain + "': " + rep.message;
      return nullptr;
    }
  }
  return inst.release();
}

Instance::~Instance() {
  retain_.reset();
  engine_.reset();
  delete state_;
}

uint32_t Instance::tick(uint64_t periodNs) {
  state_->now_ms = elapsedNs_ / 1000000u;
  if (!inited_) {
    inited_ = true;
    lj_run_init(state_, &entries_);
  }
  // The target's system bits (FANUC R9091 constants and clocks, R9015 first scan) before every
  // tick, after init, as `run` and `serve` write them (hosts/SystemBits.h).
  if (profile_) io::writeSystemBits(*profile_, *state_, ticks_);
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

std::string Instance::summary() const {
  size_t in = 0, out = 0;
  for (const PinSpec &p : pins_) (p.out ? out : in)++;
  return "'" + soPath_ + "' (" + programHash_ + ", source '" + sourcePath_ +
         "'): " + std::to_string(in) + " input and " + std::to_string(out) + " output pins" +
         (retain_ ? ", retain store on" : "");
}

} // namespace lj::hal

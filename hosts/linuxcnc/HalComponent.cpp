// The LinuxCNC HAL real-time component `ladderjit` (docs/linuxcnc.md):
//   loadrt ladderjit program=PATH.so [source=PROGRAM] [map=FILE] [trust=KEY.pub[,KEY.pub]]
//                    [params=FILE] [retain=FILE] [plc2_nvalue=N] [numPhysInputs=N ...]
//                    [names=PREFIX]
// A ClassicLadder source (.clp) exports classicladder_rt's pins and `classicladder.0.refresh`
// (the drop-in, docs/linuxcnc.md), or PREFIX.* with names=PREFIX.
// rtapi_app_main (not real-time) reads and verifies the program source, loads the signed AOT
// .so through the project's trusted loader (engines/AotLoader: signer, identity, ABI, state
// size, ELF checks, sealed memfd), builds the pin plan (HalPlan.h), creates the pins and exports
// `ladderjit.refresh`. refresh (real-time) copies input pins into the image, runs one tick
// (PLC1 + the next PLC2 slice, lj_tick), copies the image to output pins: no allocation, no
// lock, no system call besides the clock read. A rising edge on `ladderjit.reload` asks the
// component's loader thread to load program= again; refresh swaps the prepared program in at
// its start (online change, state kept).
#include "hosts/linuxcnc/HalInstance.h"

#include "hal.h"
#include "rtapi.h"
#include "rtapi_app.h"

#include <cstring>
#include <exception>
#include <new>
#include <string>

extern "C" {
MODULE_AUTHOR("ladderjit");
MODULE_DESCRIPTION("ladderjit: runs a signed AOT ladder program built by `ladderjit compile`");
MODULE_LICENSE("GPL");

static char *program = nullptr;
RTAPI_MP_STRING(program, "the AOT .so built by `ladderjit compile` (required)");
static char *source = nullptr;
RTAPI_MP_STRING(source, "the program it was built from (default: PATH.so with .dit/.stl/.json)");
static char *map = nullptr;
RTAPI_MP_STRING(map, "map file: pins for other bits, registers, F/G words (docs/linuxcnc.md)");
static char *trust = nullptr;
RTAPI_MP_STRING(trust, "trusted public key file(s), comma separated (default: the user's key)");
static char *params = nullptr;
RTAPI_MP_STRING(params, "P values, one Pn=VALUE per line, applied before init");
static char *retain = nullptr;
RTAPI_MP_STRING(retain, "retentive store file (B, T300..T427, C300..C427; docs/retain.md)");
static int plc2_nvalue = lj::hal::Options::kNvalueUnset; // not given: the container's, else 200
RTAPI_MP_INT(plc2_nvalue, "PLC2 nvalue the .so was built with (default: container's, else 200)");

// The ClassicLadder drop-in (docs/linuxcnc.md "ClassicLadder drop-in"): classicladder_rt's
// loadrt parameters. The six pin sizes size the classicladder.0.* pins of a .clp source (a value
// > 0 overrides the default, as classicladder_rt reads them); the others size ClassicLadder's own
// tables, which ladderjit sizes from the program: they are accepted so that a classicladder_rt
// loadrt line can be kept as it is.
static int numPhysInputs = 0, numPhysOutputs = 0, numS32in = 0, numS32out = 0, numFloatIn = 0,
           numFloatOut = 0;
RTAPI_MP_INT(numPhysInputs, "ClassicLadder source: classicladder.0.in-NN pins (default 15)");
RTAPI_MP_INT(numPhysOutputs, "ClassicLadder source: classicladder.0.out-NN pins (default 15)");
RTAPI_MP_INT(numS32in, "ClassicLadder source: classicladder.0.s32in-NN pins (default 10)");
RTAPI_MP_INT(numS32out, "ClassicLadder source: classicladder.0.s32out-NN pins (default 10)");
RTAPI_MP_INT(numFloatIn, "ClassicLadder source: classicladder.0.floatin-NN pins (default 10)");
RTAPI_MP_INT(numFloatOut, "ClassicLadder source: classicladder.0.floatout-NN pins (default 10)");
static char *names = nullptr;
RTAPI_MP_STRING(names, "ClassicLadder source: pin and function prefix (default classicladder.0)");
static int numRungs = 0, numBits = 0, numWords = 0, numTimers = 0, numMonostables = 0,
           numCounters = 0, numTimersIec = 0, numArithmExpr = 0, numSections = 0, numSymbols = 0;
RTAPI_MP_INT(numRungs, "accepted for classicladder_rt compatibility (sized from the program)");
RTAPI_MP_INT(numBits, "accepted for classicladder_rt compatibility (sized from the program)");
RTAPI_MP_INT(numWords, "accepted for classicladder_rt compatibility (sized from the program)");
RTAPI_MP_INT(numTimers, "accepted for classicladder_rt compatibility (sized from the program)");
RTAPI_MP_INT(numMonostables,
             "accepted for classicladder_rt compatibility (sized from the program)");
RTAPI_MP_INT(numCounters, "accepted for classicladder_rt compatibility (sized from the program)");
RTAPI_MP_INT(numTimersIec, "accepted for classicladder_rt compatibility (sized from the program)");
RTAPI_MP_INT(numArithmExpr, "accepted for classicladder_rt compatibility (sized from the program)");
RTAPI_MP_INT(numSections, "accepted for classicladder_rt compatibility (sized from the program)");
RTAPI_MP_INT(numSymbols, "accepted for classicladder_rt compatibility (sized from the program)");
}

namespace {

constexpr const char *kName = "ladderjit";

int compId = -1;
lj::hal::Instance *instance = nullptr;

void logLine(const std::string &line) {
  rtapi_print_msg(RTAPI_MSG_ERR, "%s: %s\n", kName, line.c_str());
}

std::string str(const char *s) { return s ? std::string(s) : std::string(); }

/// The HAL side of one pin: where HAL keeps its pointer (hal_malloc'd, as HAL requires).
union HalPtr {
  hal_bit_t *b;
  hal_s32_t *s;
  hal_u32_t *u;
  hal_float_t *f;
};

struct Status {
  hal_u32_t *scanNs;
  hal_u32_t *scanMaxNs;
  hal_u32_t *ticks;
  hal_u32_t *fault;
  hal_u32_t *watchdog;
  hal_bit_t *resetMax;
  hal_bit_t *reload;         ///< rising edge: online change (load program= again)
  hal_u32_t *reloads;        ///< online changes swapped in
  hal_u32_t *reloadFailures; ///< online changes refused (RTAPI log says why)
  hal_bit_t *hideGui;        ///< drop-in: classicladder.0.hide_gui (no GUI here: unused)
  hal_s32_t ladderState;     ///< drop-in: the parameter classicladder.ladder-state (2 = RUN)
};

HalPtr *halPins = nullptr;
Status *status = nullptr;
bool lastReload = false; // refresh only

void refresh(void *arg, long period) {
  auto *inst = static_cast<lj::hal::Instance *>(arg);
  // Online change: the request goes to the component's loader thread; the prepared program is
  // swapped in by Instance::tick at the start of a later refresh (a thread boundary).
  const bool reload = *status->reload;
  if (reload && !lastReload) inst->requestReload();
  lastReload = reload;
  const std::vector<lj::hal::PinSpec> &pins = inst->pins();
  lj_state &s = inst->state();
  for (size_t i = 0; i < pins.size(); ++i) {
    const lj::hal::PinSpec &p = pins[i];
    if (p.out) continue;
    switch (p.type) {
    case lj::hal::PinType::Bit:
      lj::formats::writeResolved(s, p.at, p.addr, *halPins[i].b ? 1 : 0);
      break;
    case lj::hal::PinType::S32:
      lj::formats::writeResolved(s, p.at, p.addr, *halPins[i].s);
      break;
    case lj::hal::PinType::U32:
      lj::formats::writeResolved(s, p.at, p.addr, *halPins[i].u);
      break;
    case lj::hal::PinType::Float:
      lj::formats::writeResolved(s, p.at, p.addr, inst->fromFloat(i, *halPins[i].f));
      break;
    }
  }
  long long t0 = rtapi_get_time();
  uint32_t fault = inst->tick(period > 0 ? static_cast<uint64_t>(period) : 0);
  long long ns = rtapi_get_time() - t0;
  for (size_t i = 0; i < pins.size(); ++i) {
    const lj::hal::PinSpec &p = pins[i];
    if (!p.out) continue;
    int64_t v = lj::formats::readResolved(s, p.at, p.addr);
    switch (p.type) {
    case lj::hal::PinType::Bit:
      *halPins[i].b = v != 0;
      break;
    case lj::hal::PinType::S32:
      *halPins[i].s = static_cast<int32_t>(v);
      break;
    case lj::hal::PinType::U32:
      *halPins[i].u = static_cast<uint32_t>(v);
      break;
    case lj::hal::PinType::Float:
      *halPins[i].f = static_cast<double>(v) * p.scale;
      break;
    }
  }
  uint32_t scan = ns < 0 ? 0u : ns > 0xffffffffLL ? 0xffffffffu : static_cast<uint32_t>(ns);
  *status->scanNs = scan;
  if (*status->resetMax) *status->scanMaxNs = 0;
  if (scan > *status->scanMaxNs) *status->scanMaxNs = scan;
  *status->ticks = static_cast<uint32_t>(inst->ticks());
  *status->fault = fault;
  *status->watchdog = s.fault_watchdog;
  *status->reloads = inst->reloads();
  *status->reloadFailures = inst->reloadFailures();
}

/// `prefix.name`: `ladderjit.x484.5`, or classicladder_rt's `classicladder.0.in-00`.
int makePin(const lj::hal::PinSpec &p, HalPtr &ptr, const char *prefix) {
  hal_pin_dir_t dir = p.out ? HAL_OUT : HAL_IN;
  const char *n = p.name.c_str();
  switch (p.type) {
  case lj::hal::PinType::Bit:
    return hal_pin_bit_newf(dir, &ptr.b, compId, "%s.%s", prefix, n);
  case lj::hal::PinType::S32:
    return hal_pin_s32_newf(dir, &ptr.s, compId, "%s.%s", prefix, n);
  case lj::hal::PinType::U32:
    return hal_pin_u32_newf(dir, &ptr.u, compId, "%s.%s", prefix, n);
  case lj::hal::PinType::Float:
    return hal_pin_float_newf(dir, &ptr.f, compId, "%s.%s", prefix, n);
  }
  return -1;
}

int fail(const std::string &why) {
  logLine(why + "; the component is not started");
  if (compId >= 0) hal_exit(compId);
  compId = -1;
  delete instance;
  instance = nullptr;
  return -1;
}

int start() {
  lj::hal::Options opt;
  opt.program = str(program);
  opt.source = str(source);
  opt.map = str(map);
  opt.trust = str(trust);
  opt.params = str(params);
  opt.retain = str(retain);
  opt.plc2Nvalue = plc2_nvalue;
  opt.classic = {numPhysInputs, numPhysOutputs, numS32in, numS32out, numFloatIn, numFloatOut};
  opt.classicName = str(names);
  opt.log = logLine;
  std::string error;
  instance = lj::hal::Instance::create(opt, kName, error);
  if (!instance) return fail(error);

  compId = hal_init(kName);
  if (compId < 0) return fail("hal_init failed (" + std::to_string(compId) + ")");
  const std::vector<lj::hal::PinSpec> &pins = instance->pins();
  halPins =
      static_cast<HalPtr *>(hal_malloc(static_cast<long>(sizeof(HalPtr) * (pins.size() + 1))));
  status = static_cast<Status *>(hal_malloc(sizeof(Status)));
  if (!halPins || !status) return fail("hal_malloc failed (HAL shared memory full)");
  // A ClassicLadder source: classicladder_rt's pin and function names (the drop-in), or
  // names= (beside classicladder_rt in one HAL); the status pins keep ladderjit's.
  const bool classic = instance->classicLadder();
  const std::string prefix = classic ? lj::hal::classicPrefix(opt) : kName;
  for (size_t i = 0; i < pins.size(); ++i)
    if (int r = makePin(pins[i], halPins[i], prefix.c_str()); r != 0)
      return fail("cannot create pin " + prefix + "." + pins[i].name + " (" + std::to_string(r) +
                  ")");
  int r = hal_pin_u32_newf(HAL_OUT, &status->scanNs, compId, "%s.scan-time-ns", kName);
  if (!r) r = hal_pin_u32_newf(HAL_OUT, &status->scanMaxNs, compId, "%s.scan-time-max-ns", kName);
  if (!r) r = hal_pin_u32_newf(HAL_OUT, &status->ticks, compId, "%s.ticks", kName);
  if (!r) r = hal_pin_u32_newf(HAL_OUT, &status->fault, compId, "%s.fault", kName);
  if (!r) r = hal_pin_u32_newf(HAL_OUT, &status->watchdog, compId, "%s.watchdog-faults", kName);
  if (!r) r = hal_pin_bit_newf(HAL_IN, &status->resetMax, compId, "%s.scan-time-max-reset", kName);
  if (!r) r = hal_pin_bit_newf(HAL_IN, &status->reload, compId, "%s.reload", kName);
  if (!r) r = hal_pin_u32_newf(HAL_OUT, &status->reloads, compId, "%s.reloads", kName);
  if (!r)
    r = hal_pin_u32_newf(HAL_OUT, &status->reloadFailures, compId, "%s.reload-failures", kName);
  if (!r && classic) {
    r = hal_pin_bit_newf(HAL_IN, &status->hideGui, compId, "%s.hide_gui", prefix.c_str());
    if (!r)
      r = hal_param_s32_newf(HAL_RO, &status->ladderState, compId, "%s.ladder-state",
                             opt.classicName.empty() ? "classicladder" : opt.classicName.c_str());
    if (!r) status->ladderState = 2; // RUN: the program runs from the first refresh
  }
  if (r) return fail("cannot create the status pins (" + std::to_string(r) + ")");
  *status->reload = 0;
  *status->reloads = 0;
  *status->reloadFailures = 0;
  *status->scanNs = 0;
  *status->scanMaxNs = 0;
  *status->ticks = 0;
  *status->fault = 0;
  *status->watchdog = 0;
  *status->resetMax = 0;
  std::string fn = prefix + ".refresh"; // classicladder.0.refresh for the drop-in
  // uses_fp: float pins are converted; not reentrant (one state).
  if (int e = hal_export_funct(fn.c_str(), refresh, instance, 1, 0, compId); e != 0)
    return fail("cannot export " + fn + " (" + std::to_string(e) + ")");
  instance->startRetain();
  instance->startLoader();
  rtapi_print_msg(RTAPI_MSG_INFO, "%s: %s\n", kName, instance->summary().c_str());
  return hal_ready(compId);
}

} // namespace

extern "C" int rtapi_app_main(void) {
  try {
    return start();
  } catch (const std::exception &e) {
    return fail(std::string("internal error: ") + e.what());
  }
}

extern "C" void rtapi_app_exit(void) {
  // HAL has stopped calling refresh (threads stopped or the function unlinked) when a
  // component is unloaded: the retain store's final save takes the last state.
  if (instance) instance->stopLoader();
  if (instance) instance->stopRetain();
  if (compId >= 0) hal_exit(compId);
  compId = -1;
  delete instance;
  instance = nullptr;
}

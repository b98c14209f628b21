// `ladderjit bench PROGRAM` (docs/bench.md): the compile phases of the user's own program and its
// full-scan time on every engine and tier, all in one run so the ratios compare like with like.
// Every lane runs the same inputs; at the end every final state must equal the interpreter's.
#include "tools/ladderjit/BenchCmd.h"
#include "tools/ladderjit/Commands.h"

#include "ir/Trace.h"
#include "tools/ladderjit/Progress.h"

#include "engines/AotLoader.h"
#include "engines/LlvmBackend.h"
#include "formats/Address.h"
#include "formats/InputFiles.h"
#include "gen/Rng.h"
#include "ladder/Json.h"
#include "pipeline/Compile.h"
#include "signing/AotTrust.h"

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <iostream>
#include <sstream>

namespace lj::cli {

namespace {

using bench::FrontTimes;
using bench::Lane;
using bench::Phases;
using bench::Ratio;
using bench::Stats;
using Clock = std::chrono::steady_clock;

double usSince(Clock::time_point t0) {
  return std::chrono::duration<double, std::micro>(Clock::now() - t0).count();
}

inline double monoNs() {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<double>(ts.tv_sec) * 1e9 + static_cast<double>(ts.tv_nsec);
}

/// The inputs of one scan: every X byte (pseudo-random mode) or the stimulus writes of that tick.
struct ScanInputs {
  bool random = true;
  uint64_t seed = 1;
  const formats::Stimulus *stimulus = nullptr;
  size_t nextEvent = 0;
  /// Random mode for a target laid out in lj_state.mem (FANUC): where its input bytes are.
  uint32_t memInputOffset = 0, memInputBytes = 0;
};

/// Random mode: X (all 513 bytes) and 16 F words get new values each scan, from the seed and the
/// scan number, so every lane sees the same inputs.
void applyInputs(lj_state &s, const ScanInputs &in, uint64_t scan,
                 const std::vector<const formats::StimulusEvent *> &events) {
  if (in.random) {
    gen::Rng rng(in.seed * 0x9E3779B97F4A7C15ull + scan);
    for (size_t i = 0; i < LJ_X_COUNT; i += 8) {
      uint64_t v = rng.next();
      size_t n = std::min<size_t>(8, LJ_X_COUNT - i);
      std::memcpy(&s.img.X[i], &v, n);
    }
    for (int k = 0; k < 16; ++k) {
      uint64_t v = rng.next();
      s.img.F[v % LJ_F_COUNT] = static_cast<int16_t>(v >> 32);
    }
    auto *bytes = reinterpret_cast<unsigned char *>(&s);
    for (uint32_t i = 0; i < in.memInputBytes; i += 8) {
      uint64_t v = rng.next();
      std::memcpy(bytes + in.memInputOffset + i, &v, std::min<uint32_t>(8, in.memInputBytes - i));
    }
    return;
  }
  for (const formats::StimulusEvent *ev : events)
    for (const formats::Assignment &a : ev->sets) formats::writeAddress(s, a.addr, a.value);
}

/// One full scan as docs/BENCHMARKS.md defines it: PLC1, then every PLC2 slice (a PLC1 fault
/// skips the slices, as lj_tick does).
inline uint32_t fullScan(const lj_entries &e, lj_state *s) {
  s->steps = 0;
  uint32_t f = e.plc1(e.ctx, s);
  if (f != LJ_FAULT_NONE) return f;
  for (uint32_t k = 0; k < e.plc2_slice_count; ++k)
    if (uint32_t g = e.plc2_slice(e.ctx, s, k); g != LJ_FAULT_NONE) return g;
  return LJ_FAULT_NONE;
}

/// A private 0700 directory for the AOT .so and the C baseline, removed at exit.
struct TempDir {
  std::string path;
  ~TempDir() {
    if (path.empty()) return;
    std::error_code ec;
    std::filesystem::remove_all(path, ec);
  }
  bool make(std::string &error) {
    const char *tmp = std::getenv("TMPDIR");
    std::string t = std::string(tmp && *tmp ? tmp : "/tmp") + "/ladderjit-bench-XXXXXX";
    if (!::mkdtemp(t.data())) {
      error = "cannot create a temporary directory: " + std::string(std::strerror(errno));
      return false;
    }
    path = t;
    return true;
  }
};

Phases phasesOf(const jit::CompileTimes &t, double totalUs) {
  Phases p;
  p.lowerUs = t.lowerUs;
  p.optimizeUs = t.optimizeUs;
  p.linkUs = t.linkUs;
  p.cacheUs = t.cacheUs;
  p.codegenUs = std::max(0.0, t.codegenUs - t.linkUs - t.cacheUs);
  p.codeBytes = t.objectBytes;
  p.cacheHit = t.cacheHit;
  p.totalUs = totalUs;
  return p;
}

bool addJitLane(const engines::LlvmBackend &llvm, const VerifiedProgram &prog, bool fast,
                bool useCache, std::vector<Lane> &lanes, std::string &error, bool traced = false) {
  jit::JitOptions o;
  o.tier = fast ? jit::Tier::Fast : jit::Tier::Optimizing;
  if (useCache) o.cache = llvm.cacheFromEnvironment();
  // --trace: the traced build of the live view (ir/Trace.h), recording into its own buffer.
  std::shared_ptr<std::vector<int32_t>> buf;
  if (traced) {
    buf = std::make_shared<std::vector<int32_t>>(static_cast<size_t>(traceLayout(prog).words));
    o.trace = buf->data();
  }
  jit::CompileTimes t;
  auto t0 = Clock::now();
  std::unique_ptr<Engine> e = llvm.compile(prog, o, error, &t);
  if (!e) return false;
  Lane l;
  l.name = std::string(fast ? "jit-fast" : "jit-opt") + (traced ? "-traced" : "");
  l.keepAlive = buf;
  l.engine = "jit";
  l.tier = fast ? "fast" : "opt";
  l.phases = phasesOf(t, usSince(t0));
  l.entries = e->entries();
  l.engine_ = std::move(e);
  lanes.push_back(std::move(l));
  return true;
}

/// `ladderjit compile` into the private directory, signed with a throw-away key pair made for
/// this run, then loaded by the trusted loader trusting only that key (as `run --engine aot:`
/// would load it). Nothing is written to the user's key directory (issue 28 finding 10).
bool addAotLane(const engines::LlvmBackend &llvm, const VerifiedProgram &prog,
                const ProgramSource &src, int32_t nvalue, const std::string &dir,
                std::vector<Lane> &lanes, std::string &error) {
  signing::SigningKey key;
  if (!key.generate(error)) {
    error = "signing key: " + error;
    return false;
  }
  signing::TrustedKeys trust;
  trust.addRaw(key.publicRaw());
  engines::AotExpect id = engines::aotExpectOf(src, nvalue);
  jit::AotOptions o;
  o.output = dir + "/program.so";
  o.programHash = id.program;
  o.sourceHash = id.source;
  o.plc2Nvalue = nvalue;
  o.signingKey = &key;
  jit::CompileTimes t;
  o.times = &t;
  auto t0 = Clock::now();
  if (!llvm.compileSharedObject(prog, o, error)) return false;
  struct stat st {};
  uint64_t soBytes = ::stat(o.output.c_str(), &st) == 0 ? static_cast<uint64_t>(st.st_size) : 0;
  auto tl = Clock::now();
  std::unique_ptr<Engine> e = engines::loadAot(o.output, id, trust, error);
  if (!e) return false;
  Lane l;
  l.name = "aot";
  l.engine = "aot";
  l.tier = "opt";
  l.phases = phasesOf(t, usSince(t0));
  l.phases.codegenUs = t.codegenUs; // no cache, link measured apart
  l.phases.loadUs = usSince(tl);
  l.phases.codeBytes = soBytes;
  l.entries = e->entries();
  l.engine_ = std::move(e);
  lanes.push_back(std::move(l));
  return true;
}

/// Median cost of the clock reads around one scan (two back-to-back reads), subtracted from
/// every sample so a 50 ns scan is not reported as 80.
double clockOverheadNs() {
  std::vector<double> d(2001);
  for (double &x : d) {
    double t = monoNs();
    x = monoNs() - t;
  }
  std::sort(d.begin(), d.end());
  return d[d.size() / 2];
}

/// The lanes' scans, interleaved in blocks of 64 so machine noise hits every engine alike.
void runScans(std::vector<Lane> &lanes, const BenchArgs &a, const ScanInputs &in,
              Progress &progress, double overheadNs, uint64_t base = 0, size_t rotate = 0) {
  constexpr uint64_t kBlock = 64;
  std::vector<std::vector<const formats::StimulusEvent *>> events(kBlock);
  size_t nextEvent = 0;
  auto t0 = Clock::now();
  auto lastShow = t0;
  for (Lane &l : lanes) l.scanNs.reserve(a.scans);
  for (uint64_t b = 0; b < a.scans; b += kBlock) {
    const uint64_t n = std::min(kBlock, a.scans - b);
    for (uint64_t k = 0; k < n; ++k) {
      events[k].clear();
      while (in.stimulus && nextEvent < in.stimulus->events.size() &&
             in.stimulus->events[nextEvent].tick == b + k)
        events[k].push_back(&in.stimulus->events[nextEvent++]);
      while (in.stimulus && nextEvent < in.stimulus->events.size() &&
             in.stimulus->events[nextEvent].tick < b + k)
        ++nextEvent; // not reachable: ticks are sorted
    }
    for (size_t li = 0; li < lanes.size(); ++li) {
      Lane &l = lanes[(li + rotate) % lanes.size()];
      lj_state *s = l.state.get();
      for (uint64_t k = 0; k < n; ++k) {
        applyInputs(*s, in, base + b + k, events[k]);
        s->now_ms = base + b + k + 1;
        double t = monoNs();
        uint32_t f = fullScan(l.entries, s);
        l.scanNs.push_back(std::max(0.0, monoNs() - t - overheadNs));
        l.faults += f != LJ_FAULT_NONE;
      }
    }
    if (progress.enabled() &&
        std::chrono::duration<double>(Clock::now() - lastShow).count() > 0.25) {
      lastShow = Clock::now();
      double el = std::chrono::duration<double>(lastShow - t0).count();
      double done = static_cast<double>(b + n) / static_cast<double>(a.scans);
      char buf[160];
      std::snprintf(buf, sizeof buf, "bench: scans %llu/%llu, %.1f s left",
                    static_cast<unsigned long long>(b + n),
                    static_cast<unsigned long long>(a.scans), done > 0 ? el / done - el : 0.0);
      progress.show(buf);
    }
  }
}

} // namespace

namespace bench {

int measure(const BenchArgs &a, Measured &m, unsigned rounds) {
  const bool wantInterp = a.engine == "interp" || a.engine == "all";
  const bool wantJit = a.engine == "jit" || a.engine == "all";
  const bool wantAot = a.engine == "aot" || a.engine == "all";
  if (!wantInterp && !wantJit && !wantAot)
    return usageError("--engine: expected interp, jit, aot or all, got '" + a.engine + "'");
  if (a.tier != "fast" && a.tier != "opt" && a.tier != "both")
    return usageError("--tier: expected fast, opt or both, got '" + a.tier + "'");
  if (a.format != "text" && a.format != "json")
    return usageError("--format: expected text or json, got '" + a.format + "'");
  if (a.scans < 1 || a.scans > 10000000)
    return usageError("--scans: expected 1..10000000, got " + std::to_string(a.scans));
  if (a.engine == "aot" && a.tier == "fast")
    return usageError("--tier fast: aot has only the optimizing tier (use --tier opt or both)");
  if (a.cTimeoutS < 1 || a.cTimeoutS > 3600)
    return usageError("--c-timeout: expected 1..3600 seconds");

  std::string error;
  formats::Stimulus stim;
  ScanInputs in;
  in.seed = a.seed;

  Progress progress;
  int code = kOk;
  ProgramSource src;
  auto tr = Clock::now();
  if (!readProgram(a.program, src, code, a.dialect)) return code;
  if (!a.stimulus.empty()) { // addresses in the program's dialect
    std::string text;
    if (!formats::readFile(a.stimulus, text, error)) return usageError(error);
    std::optional<formats::Stimulus> st =
        formats::parseStimulus(text, a.stimulus, error, src.dialect->parseAssignment);
    if (!st) return usageError(error);
    stim = std::move(*st);
    in.random = false;
    in.stimulus = &stim;
  }
  FrontTimes &ft = m.ft;
  ft.readUs = usSince(tr);
  const int32_t nvalue = effectiveNvalue(src, a.plc2Nvalue, a.plc2NvalueGiven);
  std::optional<VerifiedProgram> &prog = m.prog;
  // Warnings as run / ladder / serve report them: one line with the count (docs/bench.md).
  prog = loadProgram(src, nvalue, code, a.quiet ? WarningReport::None : WarningReport::Summary,
                     a.dialect);
  if (!prog) return code;
  if (const AreaInfo &x = prog->profile->area(Area::Input); x.offset >= offsetof(lj_state, mem)) {
    in.memInputOffset = x.offset;
    in.memInputBytes = static_cast<uint32_t>(x.count + x.upperCount) * x.bytes;
  }
  {
    // Parse and verify apart (the program above came from the same two steps in one call).
    const SymbolTable *symbols = src.dit      ? &src.dit->symbols
                                 : src.ladder ? &src.ladder->symbols
                                              : nullptr;
    Diagnostics d(src.path);
    auto t0 = Clock::now();
    ParsedProgram parsed = pipeline::parse(*src.dialect, src.text, src.path, d, symbols);
    ft.parseUs = usSince(t0);
    VerifyOptions vo;
    vo.plc2Nvalue = nvalue;
    auto t1 = Clock::now();
    std::optional<VerifiedProgram> again = verify(parsed, vo, d);
    ft.verifyUs = usSince(t1);
  }

  std::vector<std::string> &notes = m.notes;
  std::vector<Lane> &lanes = m.lanes;
  {
    Lane l;
    l.name = "interp";
    l.engine = "interp";
    l.tier = "-";
    l.engine_ = makeInterpreterEngine(*prog);
    l.entries = l.engine_->entries();
    lanes.push_back(std::move(l));
  }
  if (!wantInterp)
    notes.push_back("the interpreter always runs: it is the reference every final "
                    "state is checked against");
  TempDir dir;
  const bool fast = a.tier != "opt", opt = a.tier != "fast";
  // The LLVM module loads before any compile is timed (engines/LlvmBackend.h).
  const engines::LlvmBackend *llvm = nullptr;
  if (wantJit || (wantAot && opt)) {
    llvm = engines::llvmBackend(error);
    if (!llvm) return usageError(std::string(wantJit ? "jit: " : "aot: ") + error);
  }
  if (wantJit && fast) {
    progress.show("bench: compiling jit-fast ...");
    if (!addJitLane(*llvm, *prog, true, a.cache, lanes, error)) return usageError("jit: " + error);
  }
  if (wantJit && opt) {
    progress.show("bench: compiling jit-opt ...");
    if (!addJitLane(*llvm, *prog, false, a.cache, lanes, error)) return usageError("jit: " + error);
  }
  if (a.trace) { // the live view's traced builds beside the untraced ones (docs/BENCHMARKS.md)
    Lane l;
    auto buf =
        std::make_shared<std::vector<int32_t>>(static_cast<size_t>(traceLayout(*prog).words));
    l.name = "interp-traced";
    l.engine = "interp";
    l.tier = "-";
    l.engine_ = makeInterpreterEngine(*prog, {}, buf->data());
    l.keepAlive = buf;
    l.entries = l.engine_->entries();
    lanes.push_back(std::move(l));
    if (wantJit && fast && !addJitLane(*llvm, *prog, true, false, lanes, error, true))
      return usageError("jit: " + error);
    if (wantJit && opt && !addJitLane(*llvm, *prog, false, false, lanes, error, true))
      return usageError("jit: " + error);
  }
  if ((wantAot && opt) || a.cBaseline)
    if (!dir.make(error)) return usageError(error);
  if (wantAot && opt) {
    progress.show("bench: building aot ...");
    if (!addAotLane(*llvm, *prog, src, nvalue, dir.path, lanes, error))
      return usageError("aot: " + error);
  } else if (wantAot) {
    notes.push_back("aot skipped: it has only the optimizing tier");
  }
  if (a.cBaseline) {
    if (!bench::cBaselineSupports(*prog, error)) return usageError("--c-baseline: " + error);
    for (const char *cc : {"gcc", "clang-19", "clang"}) {
      std::string path;
      for (std::string_view d : {"/usr/bin/", "/usr/local/bin/", "/bin/"}) {
        std::string p = std::string(d) + cc;
        if (::access(p.c_str(), X_OK) == 0) {
          path = p;
          break;
        }
      }
      if (path.empty()) {
        notes.push_back(std::string(cc) + " not installed");
        continue;
      }
      if (std::string(cc) == "clang") {
        bool have19 = false;
        for (const Lane &l : lanes) have19 |= l.name.rfind("clang-19", 0) == 0;
        if (have19) continue; // clang is clang-19 on this machine or an older one: one is enough
      }
      for (const char *lvl : {"-O1", "-O2"}) {
        progress.show(std::string("bench: C baseline ") + cc + " " + lvl + " ...");
        Lane l;
        if (!bench::buildCBaseline(*prog, {path, lvl}, dir.path, a.cTimeoutS, l, error)) {
          notes.push_back(std::string(cc) + " " + lvl + ": " + error);
          continue;
        }
        lanes.push_back(std::move(l));
      }
    }
  }

  for (Lane &l : lanes) {
    l.state = std::make_unique<lj_state>();
    lj_state_reset(l.state.get());
    if (src.dit)
      for (const formats::Assignment &p : src.dit->params)
        formats::writeAddress(*l.state, p.addr, p.value);
    lj_run_init(l.state.get(), &l.entries);
  }
  const double overheadNs = clockOverheadNs();
  m.overheadNs = overheadNs;
  // Rounds (--corpus): the same scans again, lanes started in turn; each round's median kept.
  m.roundMedians.assign(lanes.size(), {});
  for (unsigned r = 0; r < std::max(rounds, 1u); ++r) {
    for (Lane &l : lanes) l.scanNs.clear();
    runScans(lanes, a, in, progress, overheadNs, static_cast<uint64_t>(r) * a.scans, r);
    for (size_t i = 0; i < lanes.size(); ++i)
      m.roundMedians[i].push_back(statsOf(lanes[i].scanNs).medianNs);
  }
  progress.clear();

  for (size_t i = 1; i < lanes.size(); ++i)
    if (std::memcmp(lanes[i].state.get(), lanes[0].state.get(), LJ_STATE_COMPARED_BYTES) != 0 ||
        lanes[i].faults != lanes[0].faults) {
      std::fprintf(stderr,
                   "ladderjit: error: bench: the final state of %s differs from the interpreter's "
                   "after %llu scans (a miscompile: please report it with the program)\n",
                   lanes[i].name.c_str(), static_cast<unsigned long long>(a.scans));
      return kProgramErrors;
    }

  std::vector<Stats> &st = m.st;
  for (const Lane &l : lanes) st.push_back(bench::statsOf(l.scanNs));
  m.ratios = bench::ratiosOf(lanes, st);
  char ov[160];
  std::snprintf(ov, sizeof ov,
                "scan times: CLOCK_MONOTONIC around each scan, its own cost (%.0f ns, median) "
                "subtracted",
                overheadNs);
  notes.push_back(ov);
  return kOk;
}

} // namespace bench

int runBench(const BenchArgs &a) {
  if (a.corpus) return bench::runCorpus(a);
  if (a.program.empty()) return usageError("bench: PROGRAM is required (or --corpus)");
  bench::Measured m;
  if (int code = bench::measure(a, m, 1); code != kOk) return code;
  if (a.format == "json")
    bench::printJson(a, m.overheadNs, *m.prog, m.ft, m.lanes, m.st, m.ratios, m.notes);
  else
    bench::printText(a, *m.prog, m.ft, m.lanes, m.st, m.ratios, m.notes);
  return kOk;
}

} // namespace lj::cli

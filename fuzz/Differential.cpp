// Runs one case on the reference interpreter and the engine under test in lock step and names
// the first field of lj_state where they part.
#include "fuzz/Differential.h"

#include "gen/FanucProgram.h"
#include "hosts/SystemBits.h"
#include "hosts/TestHost.h"
#include "pipeline/Compile.h"

#include <cstring>
#include <memory>
#include <sstream>

namespace lj::fuzz {

namespace {

/// Timer/counter number of a slot (inverse of lj_tc_slot).
int32_t tcNumber(size_t slot) {
  return slot < 128 ? static_cast<int32_t>(slot) : static_cast<int32_t>(slot - 128 + 300);
}

struct Differ {
  const char *cand;
  std::ostringstream o;
  bool found = false;

  template <typename T> void field(const std::string &name, const T &a, const T &b) {
    if (found || a == b) return;
    found = true;
    o << name << ": interp=" << +a << ' ' << cand << '=' << +b;
  }
  template <typename T, size_t N> void array(const char *name, const T (&a)[N], const T (&b)[N]) {
    // Image areas read like addresses (`D5`), other arrays like arrays (`edge[5]`).
    bool area = std::strlen(name) == 1;
    for (size_t i = 0; i < N && !found; ++i) {
      if (a[i] == b[i]) continue;
      field(area ? name + std::to_string(i) : std::string(name) + "[" + std::to_string(i) + "]",
            a[i], b[i]);
    }
  }
};

} // namespace

std::string firstDifference(const lj_state &a, const lj_state &b, const char *candName) {
  Differ d{candName, {}, false};
  d.array("D", a.img.D, b.img.D);
  d.array("B", a.img.B, b.img.B);
  d.array("P", a.img.P, b.img.P);
  d.array("F", a.img.F, b.img.F);
  d.array("G", a.img.G, b.img.G);
  d.array("W", a.img.W, b.img.W);
  d.array("X", a.img.X, b.img.X);
  d.array("Y", a.img.Y, b.img.Y);
  d.array("R", a.img.R, b.img.R);
  for (size_t i = 0; i < LJ_TC_SLOTS && !d.found; ++i) {
    std::string t = "T" + std::to_string(tcNumber(i));
    d.field(t + ".start_ms", a.T[i].start_ms, b.T[i].start_ms);
    d.field(t + " (elapsed_ms)", a.T[i].elapsed_ms, b.T[i].elapsed_ms);
    d.field(t + ".0 (out)", a.T[i].out, b.T[i].out);
    d.field(t + ".running", a.T[i].running, b.T[i].running);
  }
  for (size_t i = 0; i < LJ_TC_SLOTS && !d.found; ++i) {
    std::string c = "C" + std::to_string(tcNumber(i));
    d.field(c + " (value)", a.C[i].value, b.C[i].value);
    d.field(c + ".0 (out)", a.C[i].out, b.C[i].out);
    d.field(c + ".prev", a.C[i].prev, b.C[i].prev);
  }
  d.array("pls_prev", a.pls_prev, b.pls_prev);
  d.array("plf_prev", a.plf_prev, b.plf_prev);
  d.array("alt_prev", a.alt_prev, b.alt_prev);
  d.array("alt_state", a.alt_state, b.alt_state);
  d.array("edge", a.edge, b.edge);
  d.field("now_ms", a.now_ms, b.now_ms);
  d.field("max_backward_steps", a.max_backward_steps, b.max_backward_steps);
  d.field("steps", a.steps, b.steps);
  d.field("plc2_next_slice", a.plc2_next_slice, b.plc2_next_slice);
  d.field("last_fault", a.last_fault, b.last_fault);
  d.field("fault_watchdog", a.fault_watchdog, b.fault_watchdog);
  d.field("fault_index", a.fault_index, b.fault_index);
  d.field("fault_divzero", a.fault_divzero, b.fault_divzero);
  d.array("inst_word", a.inst_word, b.inst_word);
  d.array("mem", a.mem, b.mem); // the profile-laid areas (FANUC: byte k of lj_state.mem)
  if (!d.found && std::memcmp(&a, &b, LJ_STATE_COMPARED_BYTES) != 0) {
    const auto *pa = reinterpret_cast<const unsigned char *>(&a);
    const auto *pb = reinterpret_cast<const unsigned char *>(&b);
    size_t off = 0;
    while (pa[off] == pb[off]) ++off;
    d.o << "padding byte at offset " << off << ": interp=" << +pa[off] << ' ' << candName << '='
        << +pb[off];
    d.found = true;
  }
  return d.o.str();
}

std::string firstCallDifference(const std::vector<hosts::HostCall> &a,
                                const std::vector<hosts::HostCall> &b, const char *candName) {
  size_t i = 0;
  while (i < a.size() && i < b.size() && a[i] == b[i]) ++i;
  auto show = [](const std::vector<hosts::HostCall> &v, size_t k) {
    return k < v.size() ? v[k].str() : std::string("(no call)");
  };
  return "host call " + std::to_string(i) + ": interp=" + show(a, i) + ' ' + candName + '=' +
         show(b, i);
}

const char *switchEngineName(SwitchEngine e) {
  switch (e) {
  case SwitchEngine::Interp:
    return "interp";
  case SwitchEngine::JitFast:
    return "jit-fast";
  case SwitchEngine::JitOpt:
    return "jit-opt";
  }
  return "interp";
}

namespace {

/// The candidate of a switch-mode case: one engine per code kind the schedule uses.
class SwitchedCandidate {
public:
  bool build(const VerifiedProgram &prog, const Case &c, const EngineFactory &factory,
             std::string &error) {
    auto need = [&](SwitchEngine e) {
      std::unique_ptr<Engine> &slot = engines_[static_cast<size_t>(e)];
      if (slot) return true;
      if (e == SwitchEngine::Interp)
        slot = makeInterpreterEngine(prog);
      else
        slot = factory(prog, e == SwitchEngine::JitFast, error);
      if (!slot && error.empty()) error = "engine build failed without a message";
      return slot != nullptr;
    };
    if (!need(c.first)) return false;
    for (const SwitchPoint &p : c.switches)
      if (!need(p.engine)) return false;
    return true;
  }
  /// The entries for tick `t` (kInitTick: init).
  const lj_entries &at(const Case &c, uint32_t t) const {
    SwitchEngine e = c.first;
    if (t != Outcome::kInitTick)
      for (const SwitchPoint &p : c.switches)
        if (p.tick <= t) e = p.engine;
    return engines_[static_cast<size_t>(e)]->entries();
  }

private:
  std::unique_ptr<Engine> engines_[3];
};

} // namespace

std::string firstTraceDifference(const VerifiedProgram &prog, const TraceLayout &tl,
                                 const std::vector<int32_t> &a, const std::vector<int32_t> &b,
                                 const char *candName) {
  size_t w = 0;
  while (w < a.size() && a[w] == b[w]) ++w;
  size_t i = 0; // the statement owning word w
  for (size_t k = 0; k < tl.at.size(); ++k)
    if (tl.at[k] >= 0 && static_cast<size_t>(tl.at[k]) <= w) i = k;
  const Stmt &st = prog.stmts[i];
  return "trace word " + std::to_string(w) + " (statement id " + std::to_string(st.id) + ", line " +
         std::to_string(st.loc.line) + ", word " + std::to_string(w - size_t(tl.at[i])) +
         "): interp=" + std::to_string(a[w]) + ' ' + candName + '=' + std::to_string(b[w]);
}

Outcome runCase(const Case &c, const EngineFactory &factory) {
  Outcome r;
  std::string text;
  for (const std::string &l : c.lines) text += l + "\n";
  Diagnostics diags(c.fanuc ? "fuzz.pmc" : c.iec ? "fuzz.il" : "fuzz.stl");
  VerifyOptions vo;
  vo.plc2Nvalue = c.plc2Nvalue;
  std::optional<VerifiedProgram> prog =
      c.fanuc ? pipeline::compilePmc(text, "fuzz.pmc", vo, diags, nullptr)
      : c.iec ? pipeline::compileIl(text, "fuzz.il", vo, diags)
              : pipeline::compileStl(text, "fuzz.stl", vo, diags);
  if (!prog) {
    r.kind = Outcome::Kind::NotVerified;
    r.detail = diags.render();
    return r;
  }
  // Traced: both engines record into their own buffer of the one layout (ir/Trace.h).
  const TraceLayout tl = c.trace ? traceLayout(*prog) : TraceLayout{};
  std::vector<int32_t> ta(static_cast<size_t>(tl.words)), tb(ta.size());
  std::unique_ptr<Engine> ref = makeInterpreterEngine(*prog, {}, c.trace ? ta.data() : nullptr);
  std::string error;
  std::unique_ptr<Engine> cand;
  SwitchedCandidate switched;
  if (c.switched ? !switched.build(*prog, c, factory, error)
                 : !(cand = c.trace ? tracedJit(*prog, c.fastTier, tb.data(), error)
                                    : factory(*prog, c.fastTier, error))) {
    r.kind = Outcome::Kind::EngineError;
    r.detail = error.empty() ? "engine build failed without a message" : error;
    return r;
  }
  const char *candName = c.switched ? "switched" : cand->name();
  // Two full states on the heap (each is ~40 KB), each with its own NC host of equal content.
  auto sa = std::make_unique<lj_state>();
  auto sb = std::make_unique<lj_state>();
  hosts::TestHost ha(c.hostSeed), hb(c.hostSeed);
  for (lj_state *s : {sa.get(), sb.get()}) {
    lj_state_reset(s);
    (s == sa.get() ? ha : hb).attach(*s);
    s->max_backward_steps = c.stim.maxBackwardSteps;
    if (c.fanuc) {
      gen::applyFanucWrites(*prog->profile, *s, c.stim.beforeInit);
      if (const uint32_t at = prog->profile->systemParams.counterFormat) // as --params does
        reinterpret_cast<unsigned char *>(s)[at] = c.stim.counterFormat;
    } else
      gen::applyWrites(*s, c.stim.beforeInit);
    s->now_ms = c.stim.initNowMs;
  }
  const lj_entries &ea = ref->entries();
  auto eb = [&](uint32_t t) -> const lj_entries & {
    return c.switched ? switched.at(c, t) : cand->entries();
  };
  r.slices = ea.plc2_slice_count;
  auto compare = [&](uint32_t fa, uint32_t fb, uint32_t tick) {
    const bool sameCalls = ha.calls() == hb.calls();
    const bool sameTrace = ta == tb;
    if (fa == fb && sameCalls && sameTrace &&
        std::memcmp(sa.get(), sb.get(), LJ_STATE_COMPARED_BYTES) == 0)
      return true;
    r.kind = Outcome::Kind::Mismatch;
    r.tick = tick;
    if (fa != fb)
      r.detail =
          "fault code: interp=" + std::to_string(fa) + ' ' + candName + '=' + std::to_string(fb);
    else if (!sameCalls)
      r.detail = firstCallDifference(ha.calls(), hb.calls(), candName);
    else if (!sameTrace)
      r.detail = firstTraceDifference(*prog, tl, ta, tb, candName);
    else
      r.detail = firstDifference(*sa, *sb, candName);
    return false;
  };
  uint32_t fa = lj_run_init(sa.get(), &ea);
  uint32_t fb = lj_run_init(sb.get(), &eb(Outcome::kInitTick));
  r.statements += static_cast<uint64_t>(prog->init.end - prog->init.begin);
  if (!compare(fa, fb, Outcome::kInitTick)) return r;
  const int32_t plc1 = prog->plc1.end - prog->plc1.begin;
  for (uint32_t t = 0; t < c.stim.ticks(); ++t) {
    uint32_t slice = sa->plc2_next_slice < prog->slices.size() ? sa->plc2_next_slice : 0;
    for (lj_state *s : {sa.get(), sb.get()}) {
      if (c.fanuc)
        gen::applyFanucWrites(*prog->profile, *s, c.stim.writes[t]);
      else
        gen::applyWrites(*s, c.stim.writes[t]);
      s->now_ms = c.stim.nowMs[t];
      hosts::writeSystemBits(*prog->profile, *s, t);
    }
    fa = lj_tick(sa.get(), &ea);
    fb = lj_tick(sb.get(), &eb(t));
    r.statements += static_cast<uint64_t>(plc1);
    if (slice < prog->slices.size())
      r.statements += static_cast<uint64_t>(prog->slices[slice].end - prog->slices[slice].begin);
    if (fa == LJ_FAULT_WATCHDOG) ++r.watchdogTicks;
    if (!compare(fa, fb, t)) return r;
  }
  r.divZero = sa->fault_divzero;
  return r;
}

} // namespace lj::fuzz

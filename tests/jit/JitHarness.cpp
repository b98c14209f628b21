// Lock-step interpreter/JIT runs with byte-exact state comparison (STYLE.md 12).
#include "tests/jit/JitHarness.h"

#include <cstddef>
#include <cstring>

namespace lj::test {

std::optional<VerifiedProgram> verifyOrFail(std::string_view text, int32_t plc2Nvalue) {
  Diagnostics diags("test.stl");
  VerifyOptions opts;
  opts.plc2Nvalue = plc2Nvalue;
  std::optional<VerifiedProgram> prog = compileFrontEnd(text, "test.stl", opts, diags);
  if (!prog) ADD_FAILURE() << "front end rejected the program:\n" << diags.render();
  return prog;
}

std::unique_ptr<Engine> jitOrFail(const VerifiedProgram &prog, jit::Tier tier,
                                  int32_t chunkStatements) {
  std::string error;
  jit::JitOptions opts;
  opts.tier = tier;
  opts.chunkStatements = chunkStatements;
  std::unique_ptr<Engine> e = jit::compile(prog, opts, error);
  if (!e) ADD_FAILURE() << "JIT compile failed: " << error;
  return e;
}

std::string fieldAt(size_t off) {
  struct Arr {
    const char *name;
    size_t begin, elem, count;
  };
  const size_t img = offsetof(lj_state, img);
  const Arr arrays[] = {
      {"img.D", img + offsetof(lj_image, D), 4, LJ_D_COUNT},
      {"img.B", img + offsetof(lj_image, B), 4, LJ_B_COUNT},
      {"img.P", img + offsetof(lj_image, P), 4, LJ_P_COUNT},
      {"img.F", img + offsetof(lj_image, F), 2, LJ_F_COUNT},
      {"img.G", img + offsetof(lj_image, G), 2, LJ_G_COUNT},
      {"img.W", img + offsetof(lj_image, W), 2, LJ_W_COUNT},
      {"img.X", img + offsetof(lj_image, X), 1, LJ_X_COUNT},
      {"img.Y", img + offsetof(lj_image, Y), 1, LJ_Y_COUNT},
      {"img.R", img + offsetof(lj_image, R), 1, LJ_R_COUNT},
      {"T", offsetof(lj_state, T), sizeof(lj_timer), LJ_TC_SLOTS},
      {"C", offsetof(lj_state, C), sizeof(lj_counter), LJ_TC_SLOTS},
      {"pls_prev", offsetof(lj_state, pls_prev), 1, LJ_BLOCK_SLOTS},
      {"plf_prev", offsetof(lj_state, plf_prev), 1, LJ_BLOCK_SLOTS},
      {"alt_prev", offsetof(lj_state, alt_prev), 1, LJ_BLOCK_SLOTS},
      {"alt_state", offsetof(lj_state, alt_state), 1, LJ_BLOCK_SLOTS},
      {"edge", offsetof(lj_state, edge), 1, LJ_EDGE_SLOTS},
  };
  for (const Arr &a : arrays) {
    if (off >= a.begin && off < a.begin + a.elem * a.count) {
      size_t i = (off - a.begin) / a.elem;
      std::string s = std::string(a.name) + "[" + std::to_string(i) + "]";
      if (a.name[0] == 'T' && a.name[1] == 0) {
        size_t f = (off - a.begin) % a.elem;
        s += f < 8 ? ".start_ms" : f < 16 ? ".elapsed_ms" : f == 16 ? ".out" : ".running";
      }
      if (a.name[0] == 'C' && a.name[1] == 0) {
        size_t f = (off - a.begin) % a.elem;
        s += f < 4 ? ".value" : f == 4 ? ".out" : ".prev";
      }
      return s;
    }
  }
  struct Field {
    const char *name;
    size_t begin, size;
  };
  const Field fields[] = {
      {"now_ms", offsetof(lj_state, now_ms), 8},
      {"max_backward_steps", offsetof(lj_state, max_backward_steps), 8},
      {"steps", offsetof(lj_state, steps), 8},
      {"plc2_next_slice", offsetof(lj_state, plc2_next_slice), 4},
      {"last_fault", offsetof(lj_state, last_fault), 4},
      {"fault_watchdog", offsetof(lj_state, fault_watchdog), 4},
      {"fault_index", offsetof(lj_state, fault_index), 4},
      {"fault_divzero", offsetof(lj_state, fault_divzero), 4},
  };
  for (const Field &f : fields)
    if (off >= f.begin && off < f.begin + f.size) return f.name;
  return "padding@" + std::to_string(off);
}

::testing::AssertionResult sameState(const lj_state &ref, const lj_state &got) {
  const auto *a = reinterpret_cast<const uint8_t *>(&ref);
  const auto *b = reinterpret_cast<const uint8_t *>(&got);
  for (size_t i = 0; i < sizeof(lj_state); ++i) {
    if (a[i] != b[i])
      return ::testing::AssertionFailure()
             << "state differs at byte " << i << " (" << fieldAt(i) << "): interpreter "
             << int(a[i]) << ", jit " << int(b[i]);
  }
  return ::testing::AssertionSuccess();
}

namespace {

std::unique_ptr<lj_state> freshState(const Drive &d) {
  auto s = std::make_unique<lj_state>();
  lj_state_reset(s.get());
  s->max_backward_steps = d.maxSteps;
  if (d.before) d.before(*s);
  return s;
}

} // namespace

::testing::AssertionResult
jitMatchesInterpreter(const VerifiedProgram &prog, jit::Tier tier, const Drive &drive,
                      const std::function<void(uint32_t, const lj_state &, uint32_t)> &check,
                      int32_t chunkStatements) {
  std::unique_ptr<Engine> ref = makeInterpreterEngine(prog);
  std::unique_ptr<Engine> jit = jitOrFail(prog, tier, chunkStatements);
  if (!ref || !jit) return ::testing::AssertionFailure() << "no engine";
  std::unique_ptr<lj_state> a = freshState(drive), b = freshState(drive);
  uint32_t fa = lj_run_init(a.get(), &ref->entries());
  uint32_t fb = lj_run_init(b.get(), &jit->entries());
  if (fa != fb)
    return ::testing::AssertionFailure() << "init fault: interpreter " << fa << ", jit " << fb;
  if (auto r = sameState(*a, *b); !r) return r << " after init";
  for (uint32_t t = 0; t < drive.ticks; ++t) {
    a->now_ms = b->now_ms = t * drive.periodMs;
    if (drive.inputs) {
      drive.inputs(t, *a);
      drive.inputs(t, *b);
    }
    fa = lj_tick(a.get(), &ref->entries());
    fb = lj_tick(b.get(), &jit->entries());
    if (fa != fb)
      return ::testing::AssertionFailure()
             << "tick " << t << " fault: interpreter " << fa << ", jit " << fb;
    if (auto r = sameState(*a, *b); !r) return r << " after tick " << t;
    if (check) check(t, *a, fa);
  }
  return ::testing::AssertionSuccess();
}

std::unique_ptr<lj_state>
runAlone(const Engine &engine, const Drive &drive,
         const std::function<void(uint32_t, const lj_state &, uint32_t)> &check) {
  std::unique_ptr<lj_state> s = freshState(drive);
  lj_run_init(s.get(), &engine.entries());
  for (uint32_t t = 0; t < drive.ticks; ++t) {
    s->now_ms = t * drive.periodMs;
    if (drive.inputs) drive.inputs(t, *s);
    uint32_t f = lj_tick(s.get(), &engine.entries());
    if (check) check(t, *s, f);
  }
  return s;
}

} // namespace lj::test

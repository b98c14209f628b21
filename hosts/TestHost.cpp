// The recording test host: lj_host trampolines into TestHost, its variable store with the
// VARGET/VARSET scaling of hnc8-functions-2.md 2.22, 2.23 and section 3, and the call log.
#include "hosts/TestHost.h"
#include "ir/Bcd.h"

#include <cmath>
#include <cstdlib>
#include <sstream>

namespace lj::hosts {

namespace {

/// splitmix64: the seeded content must be the same for every TestHost built from one seed.
uint64_t mix(uint64_t x) {
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

uint64_t hash3(uint64_t seed, uint64_t a, uint64_t b) { return mix(mix(mix(seed) ^ a) ^ b); }

/// Low 32 bits of an integer, two's complement (no UB for values outside int32).
int32_t low32(int64_t v) { return static_cast<int32_t>(static_cast<uint32_t>(v)); }

/// trunc(v) as an integer keeping the low 32 bits; NaN and infinities give 0.
int32_t truncLow32(double v) {
  if (!std::isfinite(v) || std::fabs(v) >= 9.2e18) return 0;
  return low32(static_cast<int64_t>(v));
}

} // namespace

/// The C callbacks of the table; ctx is the TestHost.
struct TestHostCallbacks {
  static TestHost &h(void *ctx) { return *static_cast<TestHost *>(ctx); }

  static int32_t varGet(void *ctx, int32_t type, int32_t offset, int32_t exp, int32_t *value) {
    TestHost &t = h(ctx);
    if (!TestHost::varExists(type, offset) || exp < 0 || exp > 9) {
      t.record("var_get", {type, offset, exp}, {}, 0);
      return 0;
    }
    double v = t.varValue(type, offset);
    int32_t r = TestHost::isFloatType(type) ? truncLow32(v * std::pow(10.0, exp))
                                            : low32(static_cast<int64_t>(v));
    *value = r;
    t.record("var_get", {type, offset, exp}, {r}, 1);
    return 1;
  }
  static int32_t varSet(void *ctx, int32_t type, int32_t offset, int32_t exp, int32_t value) {
    TestHost &t = h(ctx);
    int32_t ok = TestHost::varExists(type, offset) && exp >= 0 && exp <= 9;
    // VARSET divides (resolution 14 of hnc8-functions-2.md 6) so that it round-trips VARGET.
    if (ok)
      t.vars[{type, offset}] =
          TestHost::isFloatType(type) ? value / std::pow(10.0, exp) : static_cast<double>(value);
    t.record("var_set", {type, offset, exp, value}, {}, ok);
    return ok;
  }
  static void mpgInput(void *ctx, int32_t mpg, int32_t value) {
    h(ctx).record("mpg_input", {mpg, value}, {}, 0);
  }
  static int32_t mpgDelta(void *ctx, int32_t mpg) {
    TestHost &t = h(ctx);
    int32_t d = 0;
    auto it = t.mpgDeltas.find(mpg);
    if (it != t.mpgDeltas.end() && !it->second.empty()) {
      d = it->second.front();
      it->second.pop_front();
    } else if (t.seed_ != 0) {
      d = static_cast<int32_t>(
              hash3(t.seed_, 0x4D5047u + static_cast<uint32_t>(mpg), t.mpgCalls_[mpg]++) % 201) -
          100;
    }
    t.record("mpg_delta", {mpg}, {}, d);
    return d;
  }
  static void tempInput(void *ctx, int32_t sensor, int32_t raw, int32_t type, int32_t p0,
                        int32_t p1, int32_t p2, int32_t p3) {
    h(ctx).record("temp_input", {sensor, raw, type, p0, p1, p2, p3}, {}, 0);
  }
  static void event(void *ctx, int32_t n) { h(ctx).record("event", {n}, {}, 0); }
  static void saveData(void *ctx) { h(ctx).record("save_data", {}, {}, 0); }
  static int32_t toolSelect(void *ctx, int32_t spindleTool, int32_t cmdTool, int32_t *pocket,
                            int32_t *error) {
    TestHost &t = h(ctx);
    auto it = t.pockets.find(cmdTool);
    if (it != t.pockets.end()) {
      *pocket = it->second;
      t.record("tool_select", {spindleTool, cmdTool}, {it->second}, 1);
      return 1;
    }
    *error = t.toolError;
    t.record("tool_select", {spindleTool, cmdTool}, {t.toolError}, 0);
    return 0;
  }
  static void toolInUse(void *ctx, int32_t ch, int32_t tool) {
    h(ctx).record("tool_in_use", {ch, tool}, {}, 0);
  }
  static void toolVector(void *ctx, int32_t ch, int32_t on) {
    h(ctx).record("tool_vector", {ch, on}, {}, 0);
  }
  static void slaveHome(void *ctx, int32_t axis, int32_t on) {
    h(ctx).record("slave_home", {axis, on}, {}, 0);
  }
  static int32_t spindleDa(void *ctx, int32_t ch, int32_t sp, int32_t rpm, int32_t gear,
                           int32_t pbase) {
    int32_t r = low32(int64_t{rpm} / 10 + 1000 * int64_t{gear} + 100 * int64_t{sp} +
                      10 * int64_t{ch} + pbase);
    h(ctx).record("spindle_da", {ch, sp, rpm, gear, pbase}, {}, r);
    return r;
  }
  static int32_t nixieEncode(void *ctx, int32_t value, int32_t width) {
    const uint32_t mag =
        value < 0 ? 0u - static_cast<uint32_t>(value) : static_cast<uint32_t>(value);
    const auto r = static_cast<int32_t>(bcd::encode(mag, width == 0 ? 2 : 4));
    h(ctx).record("nixie_encode", {value, width}, {}, r);
    return r;
  }
};

std::string HostCall::str() const {
  std::ostringstream os;
  os << name << "(";
  for (size_t i = 0; i < args.size(); ++i) os << (i ? ", " : "") << args[i];
  os << ") -> " << result;
  if (!out.empty()) {
    os << " [";
    for (size_t i = 0; i < out.size(); ++i) os << (i ? ", " : "") << out[i];
    os << "]";
  }
  return os.str();
}

TestHost::TestHost() : TestHost(0) {}

TestHost::TestHost(uint64_t seed) : seed_(seed) {
  using C = TestHostCallbacks;
  host_.ctx = this;
  host_.var_get = &C::varGet;
  host_.var_set = &C::varSet;
  host_.mpg_input = &C::mpgInput;
  host_.mpg_delta = &C::mpgDelta;
  host_.temp_input = &C::tempInput;
  host_.event = &C::event;
  host_.save_data = &C::saveData;
  host_.tool_select = &C::toolSelect;
  host_.tool_in_use = &C::toolInUse;
  host_.tool_vector = &C::toolVector;
  host_.slave_home = &C::slaveHome;
  host_.spindle_da = &C::spindleDa;
  host_.nixie_encode = &C::nixieEncode;
  if (seed != 0)
    for (int32_t tool = 1; tool <= 16; ++tool) {
      uint64_t r = hash3(seed, 0x544F4F4Cu, static_cast<uint64_t>(tool));
      if (r % 4 != 0) pockets[tool] = static_cast<int32_t>(1 + (r >> 8) % 24);
    }
}

bool TestHost::disable(std::string_view callback) {
  // Every member is a function pointer; compare by name and null the one asked for.
  auto clear = [&](std::string_view n, auto &member) {
    if (callback != n) return false;
    member = nullptr;
    return true;
  };
  return clear("var_get", host_.var_get) || clear("var_set", host_.var_set) ||
         clear("mpg_input", host_.mpg_input) || clear("mpg_delta", host_.mpg_delta) ||
         clear("temp_input", host_.temp_input) || clear("event", host_.event) ||
         clear("save_data", host_.save_data) || clear("tool_select", host_.tool_select) ||
         clear("tool_in_use", host_.tool_in_use) || clear("tool_vector", host_.tool_vector) ||
         clear("slave_home", host_.slave_home) || clear("spindle_da", host_.spindle_da) ||
         clear("nixie_encode", host_.nixie_encode);
}

std::string TestHost::callText() const {
  std::string s;
  for (const HostCall &c : calls_) s += c.str() + "\n";
  return s;
}

bool TestHost::varExists(int32_t type, int32_t offset) {
  // hnc8-functions-2.md section 3, with 4 channels, 32 axes and 100 tools.
  static constexpr int32_t kCount[10] = {5000,     500,      10000,    5000,    5000,
                                         2000 * 4, 1000 * 4, 100 * 32, 50 * 32, 200 * 100};
  return type >= 0 && type <= 9 && offset >= 0 && offset < kCount[type];
}

bool TestHost::isFloatType(int32_t type) {
  return type == 0 || type == 1 || type == 4 || type == 6 || type == 9;
}

void TestHost::record(const char *name, std::vector<int32_t> args, std::vector<int32_t> out,
                      int32_t result) {
  calls_.push_back({name, std::move(args), std::move(out), result});
}

double TestHost::varValue(int32_t type, int32_t offset) const {
  auto it = vars.find({type, offset});
  if (it != vars.end()) return it->second;
  if (seed_ == 0) return 0.0;
  uint64_t r = hash3(seed_, static_cast<uint64_t>(type), static_cast<uint64_t>(offset));
  // Two decimals for float types, so the exponent changes the result.
  return isFloatType(type) ? static_cast<double>(static_cast<int64_t>(r % 200001) - 100000) / 100.0
                           : static_cast<double>(static_cast<int64_t>(r % 2000001) - 1000000);
}

} // namespace lj::hosts

// The simulated NC's lj_host callbacks (abi.h), its CNC variable store with the VARGET/VARSET
// scaling rules (hnc8-functions-2.md 2.22, 2.23, 3), and the call log every callback appends to.
#include "hosts/SimNcModel.h"
#include "ir/Bcd.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>

namespace lj::hosts {

/// The C trampolines: ctx is the SimNc. Every one appends to the call log.
struct SimNcHost {
  static SimNc &nc(void *ctx) { return *static_cast<SimNc *>(ctx); }
  // Filled in place: in a ring (SimNcConfig::logLimit) a reused slot keeps its capacity, and
  // every call name fits the small-string buffer, so a warm log records without allocating.
  static void record(SimNc &n, const char *name, std::initializer_list<int64_t> args,
                     std::initializer_list<int64_t> out, int64_t result) {
    NcCall &c = n.calls_.next();
    c.tick = n.tick_;
    c.name.assign(name);
    c.args.assign(args);
    c.out.assign(out);
    c.result = result;
  }

  static int32_t varGet(void *ctx, int32_t type, int32_t offset, int32_t exp, int32_t *value) {
    SimNc &n = nc(ctx);
    int32_t v = 0;
    int32_t ok = n.scaledGet(type, offset, exp, v);
    if (ok) *value = v;
    if (ok)
      record(n, "var_get", {type, offset, exp}, {v}, ok);
    else
      record(n, "var_get", {type, offset, exp}, {}, ok);
    return ok;
  }
  static int32_t varSet(void *ctx, int32_t type, int32_t offset, int32_t exp, int32_t value) {
    SimNc &n = nc(ctx);
    int32_t ok = n.scaledSet(type, offset, exp, value);
    record(n, "var_set", {type, offset, exp, value}, {}, ok);
    return ok;
  }
  static void mpgInput(void *ctx, int32_t mpg, int32_t value) {
    SimNc &n = nc(ctx);
    if (mpg >= 0 && mpg < ncw::kMpgs) {
      // The pulse register is a counter: its change since the last call is turned distance.
      if (n.m_->mpgRawSeen[mpg]) n.m_->mpgPending[mpg] += int64_t{value} - n.m_->mpgRaw[mpg];
      n.m_->mpgRaw[mpg] = value;
      n.m_->mpgRawSeen[mpg] = true;
    }
    record(n, "mpg_input", {mpg, value}, {}, 0);
  }
  static int32_t mpgDelta(void *ctx, int32_t mpg) {
    SimNc &n = nc(ctx);
    int32_t d = 0;
    if (mpg >= 0 && mpg < ncw::kMpgs) {
      int64_t &p = n.m_->mpgPending[mpg];
      d = static_cast<int32_t>(std::clamp<int64_t>(p, INT32_MIN, INT32_MAX));
      p -= d;
    }
    record(n, "mpg_delta", {mpg}, {}, d);
    return d;
  }
  static void tempInput(void *ctx, int32_t sensor, int32_t raw, int32_t type, int32_t p0,
                        int32_t p1, int32_t p2, int32_t p3) {
    SimNc &n = nc(ctx);
    if (sensor >= 0 && sensor < ncw::kSensors) {
      // Types 1 and 4 scale linearly from p0 (raw 0) to p1 (raw 32767, full scale); the
      // built-in models of types 0, 2, 3 are not documented: the raw value is taken as is.
      int64_t v = raw;
      if (type == 1 || type == 4) v = p0 + (int64_t{p1} - p0) * raw / 32767;
      n.m_->temp[sensor] = static_cast<int32_t>(std::clamp<int64_t>(v, INT16_MIN, INT16_MAX));
      n.m_->tempSet[sensor] = true;
    }
    record(n, "temp_input", {sensor, raw, type, p0, p1, p2, p3}, {}, 0);
  }
  static void event(void *ctx, int32_t e) { record(nc(ctx), "event", {e}, {}, 0); }
  static void saveData(void *ctx) { record(nc(ctx), "save_data", {}, {}, 0); }
  static int32_t toolSelect(void *ctx, int32_t spindleTool, int32_t cmdTool, int32_t *pocket,
                            int32_t *error) {
    SimNc &n = nc(ctx);
    int32_t p = -1, err = 0;
    if (cmdTool <= 0) {
      err = 1; // not a tool number
    } else if (cmdTool == spindleTool) {
      p = 0; // already in the spindle
    } else {
      for (int i = 1; i <= n.cfg_.pockets && p < 0; ++i)
        if (n.m_->pocket[i] == cmdTool) p = i;
      if (p < 0) err = 2; // not in the magazine
    }
    int32_t ok = p >= 0;
    if (ok)
      *pocket = p;
    else
      *error = err;
    record(n, "tool_select", {spindleTool, cmdTool}, {ok ? p : err}, ok);
    return ok;
  }
  static void toolInUse(void *ctx, int32_t ch, int32_t tool) {
    SimNc &n = nc(ctx);
    if (ch >= 0 && ch < n.cfg_.channels) n.m_->ch[ch].toolInUse = tool;
    record(n, "tool_in_use", {ch, tool}, {}, 0);
  }
  static void toolVector(void *ctx, int32_t ch, int32_t on) {
    SimNc &n = nc(ctx);
    if (ch >= 0 && ch < n.cfg_.channels) n.m_->ch[ch].toolVector = on != 0;
    record(n, "tool_vector", {ch, on}, {}, 0);
  }
  static void slaveHome(void *ctx, int32_t axis, int32_t on) {
    SimNc &n = nc(ctx);
    if (axis >= 0 && axis < n.cfg_.axes) n.m_->ax[axis].slaveHome = on != 0;
    record(n, "slave_home", {axis, on}, {}, 0);
  }
  static int32_t spindleDa(void *ctx, int32_t ch, int32_t sp, int32_t rpm, int32_t gear,
                           int32_t pbase) {
    SimNc &n = nc(ctx);
    int32_t da = n.daValue(rpm, gear, pbase);
    record(n, "spindle_da", {ch, sp, rpm, gear, pbase}, {}, da);
    return da;
  }
  static int32_t nixieEncode(void *ctx, int32_t value, int32_t width) {
    // BCD digits: two for width 0 (one byte), four for width 1 (two bytes).
    const int digits = width == 0 ? 2 : 4;
    const auto out = static_cast<int32_t>(
        bcd::encode(static_cast<uint64_t>(std::llabs(int64_t{value})), digits));
    record(nc(ctx), "nixie_encode", {value, width}, {}, out);
    return out;
  }
};

void SimNc::bindHost() {
  host_.ctx = this;
  host_.var_get = &SimNcHost::varGet;
  host_.var_set = &SimNcHost::varSet;
  host_.mpg_input = &SimNcHost::mpgInput;
  host_.mpg_delta = &SimNcHost::mpgDelta;
  host_.temp_input = &SimNcHost::tempInput;
  host_.event = &SimNcHost::event;
  host_.save_data = &SimNcHost::saveData;
  host_.tool_select = &SimNcHost::toolSelect;
  host_.tool_in_use = &SimNcHost::toolInUse;
  host_.tool_vector = &SimNcHost::toolVector;
  host_.slave_home = &SimNcHost::slaveHome;
  host_.spindle_da = &SimNcHost::spindleDa;
  host_.nixie_encode = &SimNcHost::nixieEncode;
}

// Variable types (hnc8-functions-2.md 3): 0, 1, 4, 6, 9 hold floats, the others integers.
bool SimNc::varIsFloat(int type) {
  return type == 0 || type == 1 || type == 4 || type == 6 || type == 9;
}

bool SimNc::varExists(int type, int offset) const {
  int64_t limit = 0; // number of offsets of the type
  switch (type) {
  case 0:
    limit = 5000;
    break; // #50000..#54999
  case 1:
    limit = 500;
    break; // #500..#999
  case 2:
    limit = 10000;
    break; // int32 system
  case 3:
  case 4:
    limit = 5000;
    break; // int64 / float system
  case 5:
    limit = 2000 * cfg_.channels;
    break; // int32 channel: 2000*ch + item
  case 6:
    limit = 1000 * cfg_.channels;
    break; // float channel
  case 7:
    limit = 100 * cfg_.axes;
    break; // int32 axis
  case 8:
    limit = 50 * cfg_.axes;
    break; // int64 axis
  case 9:
    limit = 200 * int64_t{cfg_.tools};
    break; // tool: 200*t + item
  default:
    return false;
  }
  return offset >= 0 && offset < limit;
}

const NcVar *SimNc::var(int type, int offset) const {
  auto it = vars_.find({type, offset});
  return it == vars_.end() ? nullptr : &it->second;
}

bool SimNc::setVar(int type, int offset, const NcVar &v) {
  if (!varExists(type, offset)) return false;
  NcVar &dst = vars_[{type, offset}];
  dst = NcVar{};
  dst.isFloat = varIsFloat(type);
  if (dst.isFloat)
    dst.f = v.isFloat ? v.f : static_cast<double>(v.i);
  else if (type == 3 || type == 8)
    dst.i = v.isFloat ? static_cast<int64_t>(v.f) : v.i;
  else
    dst.i = static_cast<int32_t>(v.isFloat ? static_cast<int64_t>(v.f) : v.i); // int32 types
  return true;
}

int32_t SimNc::scaledGet(int type, int offset, int exp, int32_t &out) const {
  if (!varExists(type, offset) || exp < 0 || exp > 4) return 0;
  const NcVar *v = var(type, offset);
  if (!varIsFloat(type)) {
    out = static_cast<int32_t>(static_cast<uint32_t>(v ? v->i : 0)); // low 32 bits
    return 1;
  }
  // 2.22: float * 10^exp, truncated toward zero; beyond int32 it saturates (NaN reads 0).
  double x = std::trunc((v ? v->f : 0.0) * std::pow(10.0, exp));
  if (std::isnan(x)) x = 0;
  out = static_cast<int32_t>(std::clamp(x, double{INT32_MIN}, double{INT32_MAX}));
  return 1;
}

int32_t SimNc::scaledSet(int type, int offset, int exp, int32_t value) {
  if (!varExists(type, offset) || exp < 0 || exp > 4) return 0;
  NcVar v;
  v.isFloat = varIsFloat(type);
  // 2.23 with resolution 14 (hnc8-functions-2.md 6): a float variable receives value / 10^exp.
  if (v.isFloat)
    v.f = value / std::pow(10.0, exp);
  else
    v.i = value;
  return setVar(type, offset, v) ? 1 : 0;
}

int32_t SimNc::daValue(int32_t rpm, int32_t gear, int32_t pbase) const {
  // P block (hnc8-cnc-interface.md 6.2 SPDLBUS1/SPDA): +0 motor max speed, +1 min speed,
  // +2 max speed, +3/+4 gear ratio numerator/denominator; one block of 5 per gear (1-based).
  int64_t pb = int64_t{pbase} + (gear >= 1 ? 5 * (int64_t{gear} - 1) : 0);
  if (!state_ || pb < 0 || pb + 4 >= LJ_P_COUNT) return 0;
  const int32_t *p = &state_->img.P[pb];
  if (p[4] == 0 || p[0] <= 0) return 0;
  int64_t motor = int64_t{rpm} * p[3] / p[4];
  if (rpm != 0 && p[2] >= p[1] && p[1] >= 0) {
    int64_t mag = std::clamp<int64_t>(std::llabs(motor), p[1], p[2]);
    motor = motor < 0 ? -mag : mag;
  }
  // 10 V (10000 mV) at the motor's maximum speed.
  return static_cast<int32_t>(std::clamp<int64_t>(motor * 10000 / p[0], -10000, 10000));
}

} // namespace lj::hosts

// HostChain (hosts/HostChain.h): one trampoline per lj_host member, from the chain's table to
// its base host, plus the layer's save_data.
#include "hosts/HostChain.h"

namespace lj::hosts {

// ctx plus the 13 callbacks: a new lj_host member needs its trampoline below.
static_assert(sizeof(lj_host) == 14 * sizeof(void *), "lj_host changed: update HostChain");

// Each trampoline is installed only where the base's member is non-null, so it may call it.
struct HostChain::Calls {
  static const lj_host &base(void *ctx) { return *static_cast<HostChain *>(ctx)->base_; }

  static int32_t varGet(void *c, int32_t type, int32_t offset, int32_t exp, int32_t *value) {
    return base(c).var_get(base(c).ctx, type, offset, exp, value);
  }
  static int32_t varSet(void *c, int32_t type, int32_t offset, int32_t exp, int32_t value) {
    return base(c).var_set(base(c).ctx, type, offset, exp, value);
  }
  static void mpgInput(void *c, int32_t mpg, int32_t value) {
    base(c).mpg_input(base(c).ctx, mpg, value);
  }
  static int32_t mpgDelta(void *c, int32_t mpg) { return base(c).mpg_delta(base(c).ctx, mpg); }
  static void tempInput(void *c, int32_t sensor, int32_t raw, int32_t type, int32_t p0, int32_t p1,
                        int32_t p2, int32_t p3) {
    base(c).temp_input(base(c).ctx, sensor, raw, type, p0, p1, p2, p3);
  }
  static void event(void *c, int32_t n) { base(c).event(base(c).ctx, n); }
  static void saveData(void *c) {
    auto *self = static_cast<HostChain *>(c);
    if (self->base_ && self->base_->save_data) self->base_->save_data(self->base_->ctx);
    if (self->onSaveData_) self->onSaveData_();
  }
  static int32_t toolSelect(void *c, int32_t spindleTool, int32_t cmdTool, int32_t *pocket,
                            int32_t *error) {
    return base(c).tool_select(base(c).ctx, spindleTool, cmdTool, pocket, error);
  }
  static void toolInUse(void *c, int32_t ch, int32_t tool) {
    base(c).tool_in_use(base(c).ctx, ch, tool);
  }
  static void toolVector(void *c, int32_t ch, int32_t on) {
    base(c).tool_vector(base(c).ctx, ch, on);
  }
  static void slaveHome(void *c, int32_t axis, int32_t on) {
    base(c).slave_home(base(c).ctx, axis, on);
  }
  static int32_t spindleDa(void *c, int32_t ch, int32_t sp, int32_t rpm, int32_t gear,
                           int32_t pbase) {
    return base(c).spindle_da(base(c).ctx, ch, sp, rpm, gear, pbase);
  }
  static int32_t nixieEncode(void *c, int32_t value, int32_t width) {
    return base(c).nixie_encode(base(c).ctx, value, width);
  }
};

void HostChain::bindOver(lj_state &s) {
  if (s.host == &table_) return;
  base_ = s.host;
  const lj_host b = base_ ? *base_ : lj_host{};
  table_ = lj_host{};
  table_.ctx = this;
  // A member the base does not serve stays null: the engines then behave as without an NC.
  if (b.var_get) table_.var_get = &Calls::varGet;
  if (b.var_set) table_.var_set = &Calls::varSet;
  if (b.mpg_input) table_.mpg_input = &Calls::mpgInput;
  if (b.mpg_delta) table_.mpg_delta = &Calls::mpgDelta;
  if (b.temp_input) table_.temp_input = &Calls::tempInput;
  if (b.event) table_.event = &Calls::event;
  table_.save_data = &Calls::saveData;
  if (b.tool_select) table_.tool_select = &Calls::toolSelect;
  if (b.tool_in_use) table_.tool_in_use = &Calls::toolInUse;
  if (b.tool_vector) table_.tool_vector = &Calls::toolVector;
  if (b.slave_home) table_.slave_home = &Calls::slaveHome;
  if (b.spindle_da) table_.spindle_da = &Calls::spindleDa;
  if (b.nixie_encode) table_.nixie_encode = &Calls::nixieEncode;
  s.host = &table_;
}

} // namespace lj::hosts

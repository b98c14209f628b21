/* The tick driver both engines share deliberately (DIALECT.md section 4): the order of PLC1,
 * the PLC2 slice and the watchdog bookkeeping must not differ between engines. */
#include "ladderjit/abi.h"

#include <string.h>

void lj_state_reset(lj_state *s) {
  memset(s, 0, sizeof *s);
  s->max_backward_steps = 1000000u;
}

uint32_t lj_run_init(lj_state *s, const lj_entries *e) {
  s->steps = 0;
  uint32_t fault = e->init(e->ctx, s);
  s->last_fault = fault;
  if (fault == LJ_FAULT_WATCHDOG) s->fault_watchdog++;
  return fault;
}

uint32_t lj_tick(lj_state *s, const lj_entries *e) {
  s->steps = 0;
  uint32_t fault = e->plc1(e->ctx, s);
  if (fault == LJ_FAULT_NONE) {
    uint32_t count = e->plc2_slice_count ? e->plc2_slice_count : 1u;
    uint32_t k = s->plc2_next_slice < count ? s->plc2_next_slice : 0u;
    s->plc2_next_slice = (k + 1u) % count;
    fault = e->plc2_slice(e->ctx, s, k);
  }
  s->last_fault = fault;
  if (fault == LJ_FAULT_WATCHDOG) s->fault_watchdog++;
  return fault;
}

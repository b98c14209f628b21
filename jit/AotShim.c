/* The exported ABI of an AOT shared object (runtime_abi/include/ladderjit/program.h), linked
 * next to the compiled program object and runtime_abi/tick.c by `ladderjit compile`. The tick
 * driver is tick.c itself, so AOT ticks exactly like the interpreter and the JIT. Compiled with
 * -DLJPROG_HASH_VALUE="sha256:..." -DLJPROG_SLICES=N and -fvisibility=hidden. */
#include "ladderjit/program.h"

/* The entries of the program object (lowering/Lower.h kInitSymbol etc.), hidden there. */
uint32_t lj_init(void *ctx, lj_state *s);
uint32_t lj_plc1(void *ctx, lj_state *s);
uint32_t lj_plc2(void *ctx, lj_state *s, uint32_t slice);

static const lj_entries kEntries = {0, lj_init, lj_plc1, lj_plc2, LJPROG_SLICES};

uint32_t ljprog_abi_version(void) { return LJPROG_ABI_VERSION; }
const char *ljprog_hash(void) { return LJPROG_HASH_VALUE; }
uint32_t ljprog_slice_count(void) { return LJPROG_SLICES; }
size_t ljprog_state_size(void) { return sizeof(lj_state); }
void ljprog_state_reset(lj_state *s) { lj_state_reset(s); }
uint32_t ljprog_init(lj_state *s) { return lj_run_init(s, &kEntries); }
uint32_t ljprog_tick(lj_state *s) { return lj_tick(s, &kEntries); }
void ljprog_entries(lj_entries *out) { *out = kEntries; }

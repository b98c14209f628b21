/* ladderjit runtime ABI v3: the process image, per-instance state, fault counters and the
 * scan-entry signatures shared by the interpreter, the JIT and AOT shared objects.
 *
 * Everything a program touches lives in one host-owned `lj_state`, so code can be swapped at a
 * tick boundary without moving state. The layout is pinned with static asserts below; the
 * lowering builds its matching llvm::StructType from the same offsets (lowering/AbiTypes.cpp).
 * Plain C so a controller host can include it without C++. */
#ifndef LADDERJIT_ABI_H
#define LADDERJIT_ABI_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define LJ_ABI_VERSION 3u

/* Element counts of every area (DIALECT.md section 1). */
#define LJ_X_COUNT 513
#define LJ_Y_COUNT 513
#define LJ_F_COUNT 3120
#define LJ_G_COUNT 3120
#define LJ_R_COUNT 400
#define LJ_W_COUNT 200
#define LJ_D_COUNT 100
#define LJ_B_COUNT 50
#define LJ_P_COUNT 200
/* Timers T0..T127 and T300..T427 (likewise counters) live in 256 slots:
 * slot = n for n < 128, slot = n - 300 + 128 for n >= 300. */
#define LJ_TC_SLOTS 256
/* Instance numbers of PLS / PLF / ALT blocks: 0..511 (docs/dialect-notes.md). */
#define LJ_BLOCK_SLOTS 512
/* Edge-memory bits of edge contacts (LDP...ORF) and CTR instances, one byte per instance. */
#define LJ_EDGE_SLOTS 16384

/* Per-instance words of stateful CNC blocks (TOOLLIFE install counters), indices assigned by the
 * verifier like edge slots. */
#define LJ_INST_WORDS 1024

/* Bytes of the profile-laid region lj_state.mem (ABI v3): the areas of targets whose memory is
 * not HNC-8's lj_image (FANUC PMC byte-addressed areas, IEC objects) and their hidden state, at
 * offsets the target profile gives (ir/Profile.h TargetProfile::elementOffset). HNC-8 programs
 * do not use it. */
#define LJ_MEM_BYTES 65536

/* Fault codes returned by scan entries and recorded in lj_state.last_fault. */
#define LJ_FAULT_NONE 0
#define LJ_FAULT_WATCHDOG 1 /* more than max_backward_steps backward jumps/loop iterations */

/** The process image: every area at its exact width, little-endian. */
typedef struct lj_image {
  int32_t D[LJ_D_COUNT];
  int32_t B[LJ_B_COUNT];
  int32_t P[LJ_P_COUNT];
  int16_t F[LJ_F_COUNT];
  int16_t G[LJ_G_COUNT];
  int16_t W[LJ_W_COUNT];
  uint8_t X[LJ_X_COUNT];
  uint8_t Y[LJ_Y_COUNT];
  uint8_t R[LJ_R_COUNT];
  uint8_t pad_[6];
} lj_image;

/** One timer (TMRB on-delay or STMR off-delay). */
typedef struct lj_timer {
  int64_t start_ms;   /* now_ms when the current timing started */
  int64_t elapsed_ms; /* current value in ms, capped at the preset (read as `Tn`) */
  uint8_t out;        /* output bit (read as `Tn.0`) */
  uint8_t running;    /* TMRB: input on and timing; STMR: off-delay in progress */
  uint8_t pad_[6];
} lj_timer;

/** One counter (CTRC / CTUD state; CTR keeps its value in a user register). */
typedef struct lj_counter {
  int32_t value; /* current count (read as `Cn`) */
  uint8_t out;   /* "count reached" bit (read as `Cn.0`) */
  uint8_t prev;  /* last level of the count input (rising-edge detection) */
  uint8_t pad_[2];
} lj_counter;

/** Complete per-instance state of one running program. Zero-initialise before init. */
typedef struct lj_state {
  lj_image img;
  lj_timer T[LJ_TC_SLOTS];
  lj_counter C[LJ_TC_SLOTS];
  uint8_t pls_prev[LJ_BLOCK_SLOTS];
  uint8_t plf_prev[LJ_BLOCK_SLOTS];
  uint8_t alt_prev[LJ_BLOCK_SLOTS];
  uint8_t alt_state[LJ_BLOCK_SLOTS];
  uint8_t edge[LJ_EDGE_SLOTS]; /* per-instance edge memory, indices assigned by the verifier */
  uint64_t now_ms;             /* written by the host before every tick */
  uint64_t max_backward_steps; /* watchdog limit per tick (default 1,000,000) */
  uint64_t steps;              /* backward steps taken in the current tick */
  uint32_t plc2_next_slice;    /* slice the next tick runs */
  uint32_t last_fault;         /* fault code of the last tick, LJ_FAULT_* */
  uint32_t fault_watchdog;     /* ticks aborted by the watchdog */
  uint32_t fault_index;        /* indirect accesses out of range */
  uint32_t fault_divzero;      /* divisions by zero (harmless, counted) */
  uint32_t pad_;
  /* ---- ABI v2 additions (after every v1 field, so v1 offsets are unchanged) ---- */
  int32_t inst_word[LJ_INST_WORDS]; /* per-instance words (TOOLLIFE counters) */
  /* ---- ABI v3 addition ---- */
  uint8_t mem[LJ_MEM_BYTES]; /* profile-laid byte region (see LJ_MEM_BYTES), little-endian */
  /* The NC host the CNC blocks call (see lj_host). Set by the host after lj_state_reset; NULL
   * (or a NULL callback) gives the documented default. Not program state: engines compare
   * states over the first LJ_STATE_COMPARED_BYTES bytes only. */
  const struct lj_host *host;
} lj_state;

/** Services of the NC that CNC function blocks need beyond the F/G words (DIALECT.md 5,
 * hnc8-cnc-interface.md 3.3). Every callback receives `ctx` first and only int32 values, so
 * compiled code calls them through plain pointers. A NULL `lj_state.host` or a NULL member means
 * "no NC service": getters report "not available" (nothing is written), notifications do
 * nothing, NIXIE shows the raw value. Both engines call them at the same points, in the same
 * order, with the same arguments. */
typedef struct lj_host {
  void *ctx;
  /* VARGET: the variable (type 0..9, offset) scaled by 10^exp (floats, truncated toward zero)
   * into *value; returns 1, or 0 when it does not exist (nothing is written). */
  int32_t (*var_get)(void *ctx, int32_t type, int32_t offset, int32_t exp, int32_t *value);
  /* VARSET: store `value` (floats: value / 10^exp); returns 1, or 0 when it does not exist. */
  int32_t (*var_set)(void *ctx, int32_t type, int32_t offset, int32_t exp, int32_t value);
  /* RTOMPG: handwheel `mpg` receives the pulse register's raw value. */
  void (*mpg_input)(void *ctx, int32_t mpg, int32_t value);
  /* MPGSET: pulse delta of handwheel `mpg` since the last call. */
  int32_t (*mpg_delta)(void *ctx, int32_t mpg);
  /* TEMPSEN: sensor `sensor` (0..19) read `raw` from its X group; board `type` (0..4) with the
   * four P parameters p0..p3 starting at the block's P operand. */
  void (*temp_input)(void *ctx, int32_t sensor, int32_t raw, int32_t type, int32_t p0, int32_t p1,
                     int32_t p2, int32_t p3);
  /* EVENT: event `n` raised (rising edge of the block's input). */
  void (*event)(void *ctx, int32_t n);
  /* SAVEDATA: save the retentive data now (rising edge of the block's input). */
  void (*save_data)(void *ctx);
  /* TOOL: find the pocket for commanded tool `cmd_tool` (spindle holds `spindle_tool`);
   * returns 1 and sets *pocket, or 0 and sets *error. */
  int32_t (*tool_select)(void *ctx, int32_t spindle_tool, int32_t cmd_tool, int32_t *pocket,
                         int32_t *error);
  /* TOOLUSE: channel `ch` shows tool `tool` in use. */
  void (*tool_in_use)(void *ctx, int32_t ch, int32_t tool);
  /* TOOLSET / TOOLCLR: tool-vector direction of channel `ch` on (1) or off (0). */
  void (*tool_vector)(void *ctx, int32_t ch, int32_t on);
  /* SUBAXEN: slave-axis homing of `axis` allowed (1) or not (0). */
  void (*slave_home)(void *ctx, int32_t axis, int32_t on);
  /* SPDA: DA output value for spindle `sp` of channel `ch` at commanded speed `rpm`, gear
   * `gear`, parameter block P[pbase..pbase+4]. */
  int32_t (*spindle_da)(void *ctx, int32_t ch, int32_t sp, int32_t rpm, int32_t gear,
                        int32_t pbase);
  /* NIXIE: panel-display encoding of `value` for `width` 0 (one byte) or 1 (two bytes). */
  int32_t (*nixie_encode)(void *ctx, int32_t value, int32_t width);
} lj_host;

/* Bytes of lj_state that are program state (everything before `host`). */
#define LJ_STATE_COMPARED_BYTES offsetof(lj_state, host)

/** Scan entries. Each returns LJ_FAULT_NONE or a fault code (the part stopped there). `ctx` is
 * the engine's own context (the interpreter's instance); compiled code ignores it. */
typedef uint32_t (*lj_part_fn)(void *ctx, lj_state *s);
typedef uint32_t (*lj_slice_fn)(void *ctx, lj_state *s, uint32_t slice);

/** The entry points of one compiled program, as the JIT returns them and an AOT .so exports. */
typedef struct lj_entries {
  void *ctx;
  lj_part_fn init;
  lj_part_fn plc1;
  lj_slice_fn plc2_slice;
  uint32_t plc2_slice_count; /* >= 1 */
} lj_entries;

/** HNC-8 timer / counter slot of number n, or -1 when n is not a valid T/C number. Engines take
 * the slot from the program's profile (TargetProfile::tcSlot), which for HNC-8 is this. */
static inline int lj_tc_slot(int32_t n) {
  if (n >= 0 && n < 128) return (int)n;
  if (n >= 300 && n < 428) return (int)(n - 300 + 128);
  return -1;
}

/** Reset a state to power-up (everything zero) with the default watchdog limit. */
void lj_state_reset(lj_state *s);

/** Run the init part: clears the per-tick step counter, then init. */
uint32_t lj_run_init(lj_state *s, const lj_entries *e);

/** One tick (DIALECT.md section 4): PLC1 completely, then the next PLC2 slice. The host writes
 * inputs and now_ms before calling. A watchdog abort in PLC1 skips the slice; the slice index
 * advances whatever the slice returned. Returns the tick's fault code (also in last_fault). */
uint32_t lj_tick(lj_state *s, const lj_entries *e);

#ifdef __cplusplus
} /* extern "C" */
#endif

/* Layout pins. Changing any of these is an ABI change: bump LJ_ABI_VERSION. */
#ifdef __cplusplus
#define LJ_STATIC_ASSERT static_assert
#else
#define LJ_STATIC_ASSERT _Static_assert
#endif
LJ_STATIC_ASSERT(offsetof(lj_image, D) == 0, "image D");
LJ_STATIC_ASSERT(offsetof(lj_image, B) == 400, "image B");
LJ_STATIC_ASSERT(offsetof(lj_image, P) == 600, "image P");
LJ_STATIC_ASSERT(offsetof(lj_image, F) == 1400, "image F");
LJ_STATIC_ASSERT(offsetof(lj_image, G) == 7640, "image G");
LJ_STATIC_ASSERT(offsetof(lj_image, W) == 13880, "image W");
LJ_STATIC_ASSERT(offsetof(lj_image, X) == 14280, "image X");
LJ_STATIC_ASSERT(offsetof(lj_image, Y) == 14793, "image Y");
LJ_STATIC_ASSERT(offsetof(lj_image, R) == 15306, "image R");
LJ_STATIC_ASSERT(sizeof(lj_image) == 15712, "image size");
LJ_STATIC_ASSERT(sizeof(lj_timer) == 24, "timer size");
LJ_STATIC_ASSERT(sizeof(lj_counter) == 8, "counter size");
LJ_STATIC_ASSERT(offsetof(lj_state, T) == 15712, "state T");
LJ_STATIC_ASSERT(offsetof(lj_state, C) == 15712 + 256 * 24, "state C");
LJ_STATIC_ASSERT(offsetof(lj_state, pls_prev) == 15712 + 256 * 24 + 256 * 8, "state pls");
LJ_STATIC_ASSERT(offsetof(lj_state, edge) == 15712 + 256 * 24 + 256 * 8 + 4 * 512, "state edge");
LJ_STATIC_ASSERT(offsetof(lj_state, now_ms) == 15712 + 256 * 24 + 256 * 8 + 4 * 512 + 16384,
                 "state now_ms");
LJ_STATIC_ASSERT(offsetof(lj_state, inst_word) == 15712 + 256 * 24 + 256 * 8 + 4 * 512 + 16384 + 48,
                 "state inst_word");
LJ_STATIC_ASSERT(offsetof(lj_state, mem) ==
                     15712 + 256 * 24 + 256 * 8 + 4 * 512 + 16384 + 48 + 4 * LJ_INST_WORDS,
                 "state mem");
LJ_STATIC_ASSERT(offsetof(lj_state, mem) % 16 == 0, "mem is 16-byte aligned");
LJ_STATIC_ASSERT(offsetof(lj_state, host) == 15712 + 256 * 24 + 256 * 8 + 4 * 512 + 16384 + 48 +
                                                 4 * LJ_INST_WORDS + LJ_MEM_BYTES,
                 "state host");
LJ_STATIC_ASSERT(sizeof(lj_state) == 15712 + 256 * 24 + 256 * 8 + 4 * 512 + 16384 + 48 +
                                         4 * LJ_INST_WORDS + LJ_MEM_BYTES + 8,
                 "state size");

#endif /* LADDERJIT_ABI_H */

/* ladderjit AOT program ABI v1: the C functions a shared object built by `ladderjit compile`
 * exports (docs/aot.md). A host dlopens the .so, checks ljprog_abi_version() and ljprog_hash(),
 * allocates an lj_state (abi.h) and drives it with ljprog_init / ljprog_tick, or with the raw
 * entry table from ljprog_entries and its own scheduler.
 *
 * These are the only dynamic symbols of the .so, all at symbol version LJPROG_1. Everything
 * else (the compiled scan code, the tick driver) is internal. Plain C, no LLVM needed. */
#ifndef LADDERJIT_PROGRAM_H
#define LADDERJIT_PROGRAM_H

#include "ladderjit/abi.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Version of this interface AND of the lj_state layout it was built against (LJ_ABI_VERSION).
 * Any incompatible change to program.h or to abi.h's layout bumps it. */
#define LJPROG_ABI_VERSION 2u

/* The symbol version node every export carries (GNU symbol versioning). */
#define LJPROG_SYMBOL_VERSION "LJPROG_1"

/* Length of the string ljprog_hash() returns: "sha256:" + 64 lowercase hex digits. */
#define LJPROG_HASH_LEN 71

/* Integrity trailer `ladderjit compile` appends after the ELF image (the dynamic loader ignores
 * it): LJPROG_TRAILER_MAGIC, 64 lowercase hex digits of SHA-256 over every byte before the
 * trailer, then "\n". ladderjit's loader refuses a .so whose trailer is missing or wrong before
 * it calls dlopen, so a damaged file is an error, never a crash in the dynamic loader. */
#define LJPROG_TRAILER_MAGIC "LJPROG1-SHA256:"
#define LJPROG_TRAILER_SIZE 80 /* 15 + 64 + 1 */

#if defined(__GNUC__)
#define LJPROG_EXPORT __attribute__((visibility("default")))
#else
#define LJPROG_EXPORT
#endif

/* Function types of the exports, for dlsym casts. */
typedef uint32_t (*ljprog_u32_fn)(void);
typedef const char *(*ljprog_hash_fn)(void);
typedef size_t (*ljprog_size_fn)(void);
typedef void (*ljprog_reset_fn)(lj_state *s);
typedef uint32_t (*ljprog_run_fn)(lj_state *s);
typedef void (*ljprog_entries_fn)(lj_entries *out);

/** LJPROG_ABI_VERSION of the .so. A host refuses any other value before calling anything else. */
LJPROG_EXPORT uint32_t ljprog_abi_version(void);

/** The program's content hash, "sha256:<64 hex>" (docs/aot.md "Program hash"): the plc.dit
 * hash line for a container built with its own plc2_nvalue. Static storage, NUL-terminated. */
LJPROG_EXPORT const char *ljprog_hash(void);

/** Number of PLC2 slices (>= 1): one tick runs PLC1 and one slice. */
LJPROG_EXPORT uint32_t ljprog_slice_count(void);

/** sizeof(lj_state) the code was built for; a host checks it against its own sizeof. */
LJPROG_EXPORT size_t ljprog_state_size(void);

/** Power-up state: everything zero, watchdog limit 1,000,000 (same as lj_state_reset). The host
 * allocates the state (malloc(sizeof(lj_state)) or static storage); then it sets P values. */
LJPROG_EXPORT void ljprog_state_reset(lj_state *s);

/** Run the init part once after power-up (same as lj_run_init). Returns LJ_FAULT_*. */
LJPROG_EXPORT uint32_t ljprog_init(lj_state *s);

/** One tick (same as lj_tick, DIALECT.md 4): the host writes inputs and now_ms first, then
 * reads outputs. Returns the tick's fault code (also in s->last_fault). */
LJPROG_EXPORT uint32_t ljprog_tick(lj_state *s);

/** Fill `out` with the raw scan entries (ctx NULL, init, plc1, plc2_slice, slice count) for a
 * host that schedules parts itself (it then owns the bookkeeping lj_tick does). */
LJPROG_EXPORT void ljprog_entries(lj_entries *out);

#ifdef __cplusplus
} /* extern "C" */
#endif

#endif /* LADDERJIT_PROGRAM_H */

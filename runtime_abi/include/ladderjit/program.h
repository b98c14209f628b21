/* ladderjit AOT program ABI v5: the C functions a shared object built by `ladderjit compile`
 * exports (docs/aot.md). A host verifies the signed trailer (below) first, dlopens the verified
 * bytes, allocates an lj_state (abi.h) and drives it with ljprog_init / ljprog_tick, or with the
 * raw entry table from ljprog_entries and its own scheduler.
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
 * Any incompatible change to program.h, to abi.h's layout or to the trailer bumps it (3: the
 * signed trailer replaced the unkeyed checksum; 4: lj_state gained the v3 byte region mem; 5: the
 * FANUC profile keeps TMRB/TMRBF and DIFU/DIFD state in mem, not in lj_state.T / pls_prev /
 * plf_prev, so a v4 FANUC .so would not share it with this build's interpreter and JIT). */
#define LJPROG_ABI_VERSION 5u

/* The symbol version node every export carries (GNU symbol versioning). */
#define LJPROG_SYMBOL_VERSION "LJPROG_1"

/* Length of the string ljprog_hash() returns: "sha256:" + 64 lowercase hex digits. */
#define LJPROG_HASH_LEN 71

/* Signed trailer `ladderjit compile` appends after the ELF image (the dynamic loader ignores
 * it; docs/aot.md "Trust"). The file is IMAGE | META | FOOTER | SIGNATURE:
 *   META       text lines, LJPROG_META_MAGIC then `key = value` lines (abi, program, source,
 *              plc2_nvalue, slices, state_size, image_size, key), at most LJPROG_META_MAX bytes;
 *   FOOTER     LJPROG_FOOTER_MAGIC, 8 lowercase hex digits = the length of META, "\n";
 *   SIGNATURE  Ed25519 (64 bytes) over every byte before it (IMAGE | META | FOOTER), by the key
 *              META names.
 * A loader verifies the signature with a key it trusts BEFORE any byte is mapped, and takes the
 * program hash, ABI version and nvalue from META, never from the .so's functions. */
#define LJPROG_META_MAGIC "ladderjit-aot-meta 3\n"
#define LJPROG_META_MAX 4096
#define LJPROG_FOOTER_MAGIC "LJPROG3-ED25519 "
#define LJPROG_FOOTER_SIZE 25 /* 16 + 8 + 1 */
#define LJPROG_SIG_SIZE 64
#define LJPROG_TRAILER_MIN (LJPROG_FOOTER_SIZE + LJPROG_SIG_SIZE)

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

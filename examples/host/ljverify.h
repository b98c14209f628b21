/* Verify and open an AOT .so the way ladderjit's own loader does (docs/aot.md "Trust"), for a C
 * host: read the file once, check its Ed25519 signature against a trusted public key, and
 * dlopen exactly the verified bytes from a sealed memfd. Needs OpenSSL libcrypto (-lcrypto)
 * and -ldl; copy ljverify.{h,c} into a host. */
#ifndef LADDERJIT_LJVERIFY_H
#define LADDERJIT_LJVERIFY_H

#include <stddef.h>
#include <stdint.h>

/* What the signed trailer states (all of it covered by the signature). */
typedef struct {
  uint32_t abi;        /* LJPROG_ABI_VERSION of the build */
  char program[72];    /* program hash, "sha256:" + 64 hex */
  int32_t plc2_nvalue; /* PLC2 nvalue the code was built with */
  uint32_t slices;     /* PLC2 slices */
  uint64_t state_size; /* sizeof(lj_state) of the build */
} ljverify_meta;

/* Open `path` if its trailer is signed by the Ed25519 public key PEM file `pubkey_path`. Returns
 * the dlopen handle (keep it; dlclose when done) and fills `meta`; NULL with a message in `err`
 * on any problem, before any byte of the file is mapped. The caller still checks meta->abi,
 * meta->state_size and meta->program against what it expects. */
void *ljverify_open(const char *path, const char *pubkey_path, ljverify_meta *meta, char *err,
                    size_t errlen);

#endif /* LADDERJIT_LJVERIFY_H */

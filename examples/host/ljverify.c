/* Signature check and sealed-memfd dlopen of an AOT .so for C hosts (ljverify.h; the trailer
 * layout is program.h's LJPROG_*, the same checks as ladderjit's signing/AotSigned.cpp). */
#define _GNU_SOURCE
#include "ljverify.h"

#include "ladderjit/program.h"

#include <dlfcn.h>
#include <errno.h>
#include <fcntl.h>
#include <openssl/evp.h>
#include <openssl/pem.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#define MAX_SO_SIZE ((size_t)256 << 20)

static void *fail(char *err, size_t n, const char *what, const char *path) {
  snprintf(err, n, "'%s': %s", path, what);
  return NULL;
}

/* The value of `key = value` in META (NUL-terminated copy `meta`), or NULL. */
static const char *field(const char *meta, const char *key, char *out, size_t outlen) {
  size_t klen = strlen(key);
  for (const char *line = meta; line && *line;
       line = strchr(line, '\n') ? strchr(line, '\n') + 1 : NULL) {
    if (strncmp(line, key, klen) == 0 && strncmp(line + klen, " = ", 3) == 0) {
      const char *v = line + klen + 3, *end = strchr(v, '\n');
      size_t len = end ? (size_t)(end - v) : strlen(v);
      if (len >= outlen) return NULL;
      memcpy(out, v, len);
      out[len] = '\0';
      return out;
    }
  }
  return NULL;
}

static int read_file(const char *path, unsigned char **data, size_t *size) {
  int fd = open(path, O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY);
  struct stat st;
  if (fd < 0) return 0;
  if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode) || (size_t)st.st_size > MAX_SO_SIZE) {
    close(fd);
    return 0;
  }
  *size = (size_t)st.st_size;
  *data = malloc(*size ? *size : 1);
  size_t got = 0;
  while (*data && got < *size) {
    ssize_t r = read(fd, *data + got, *size - got);
    if (r < 0 && errno == EINTR) continue;
    if (r <= 0) break;
    got += (size_t)r;
  }
  close(fd);
  return *data && got == *size;
}

static int trusted_raw(const char *pubkey_path, unsigned char raw[32]) {
  FILE *f = fopen(pubkey_path, "r");
  if (!f) return 0;
  EVP_PKEY *k = PEM_read_PUBKEY(f, NULL, NULL, NULL);
  fclose(f);
  size_t n = 32;
  int ok = k && EVP_PKEY_get_id(k) == EVP_PKEY_ED25519 &&
           EVP_PKEY_get_raw_public_key(k, raw, &n) == 1 && n == 32;
  EVP_PKEY_free(k);
  return ok;
}

static int verify(const unsigned char raw[32], const unsigned char *msg, size_t len,
                  const unsigned char *sig) {
  EVP_PKEY *k = EVP_PKEY_new_raw_public_key(EVP_PKEY_ED25519, NULL, raw, 32);
  EVP_MD_CTX *ctx = EVP_MD_CTX_new();
  int ok = k && ctx && EVP_DigestVerifyInit(ctx, NULL, NULL, NULL, k) == 1 &&
           EVP_DigestVerify(ctx, sig, LJPROG_SIG_SIZE, msg, len) == 1;
  EVP_MD_CTX_free(ctx);
  EVP_PKEY_free(k);
  return ok;
}

static void *open_sealed(const unsigned char *data, size_t size) {
  int fd = memfd_create("ljprog", MFD_CLOEXEC | MFD_ALLOW_SEALING);
  if (fd < 0) return NULL;
  size_t done = 0;
  while (done < size) {
    ssize_t w = write(fd, data + done, size - done);
    if (w <= 0) break;
    done += (size_t)w;
  }
  char name[64];
  snprintf(name, sizeof name, "/proc/self/fd/%d", fd);
  /* A loaded object of the same name would be handed back instead: refuse then. */
  void *old = dlopen(name, RTLD_LAZY | RTLD_NOLOAD);
  if (done != size || old ||
      fcntl(fd, F_ADD_SEALS, F_SEAL_SHRINK | F_SEAL_GROW | F_SEAL_WRITE | F_SEAL_SEAL) != 0) {
    if (old) dlclose(old);
    close(fd);
    return NULL;
  }
  return dlopen(name, RTLD_NOW | RTLD_LOCAL); /* fd stays open while the object is loaded */
}

void *ljverify_open(const char *path, const char *pubkey_path, ljverify_meta *m, char *err,
                    size_t errlen) {
  unsigned char *data = NULL, raw[32];
  size_t size = 0;
  char meta[LJPROG_META_MAX + 1], v[160];
  void *h = NULL;
  const size_t magic = sizeof(LJPROG_FOOTER_MAGIC) - 1;
  if (!trusted_raw(pubkey_path, raw))
    return fail(err, errlen, "not an Ed25519 public key PEM", pubkey_path);
  if (!read_file(path, &data, &size)) {
    free(data);
    return fail(err, errlen, "cannot read (not a regular file, or too large)", path);
  }
  size_t mlen = 0, image = 0;
  if (size < LJPROG_TRAILER_MIN) {
    fail(err, errlen, "no ladderjit signature at the end", path);
    goto done;
  }
  const unsigned char *footer = data + size - LJPROG_TRAILER_MIN;
  if (memcmp(footer, LJPROG_FOOTER_MAGIC, magic) != 0 ||
      sscanf((const char *)footer + magic, "%8zx", &mlen) != 1 || mlen > LJPROG_META_MAX ||
      mlen > size - LJPROG_TRAILER_MIN) {
    fail(err, errlen, "no ladderjit signature at the end", path);
    goto done;
  }
  image = size - LJPROG_TRAILER_MIN - mlen;
  memcpy(meta, data + image, mlen);
  meta[mlen] = '\0';
  if (strncmp(meta, LJPROG_META_MAGIC, sizeof(LJPROG_META_MAGIC) - 1) != 0 ||
      !field(meta, "key", v, sizeof v) || strlen(v) != 8 + 64 || strncmp(v, "ed25519:", 8) != 0) {
    fail(err, errlen, "bad signed trailer", path);
    goto done;
  }
  for (int i = 0; i < 32; ++i) {
    unsigned b = 0;
    if (sscanf(v + 8 + 2 * i, "%2x", &b) != 1 || b != raw[i]) {
      fail(err, errlen, "signed by a key that is not the trusted one", path);
      goto done;
    }
  }
  if (!verify(raw, data, size - LJPROG_SIG_SIZE, data + size - LJPROG_SIG_SIZE)) {
    fail(err, errlen, "bad signature: modified after `ladderjit compile` signed it", path);
    goto done;
  }
  /* Signed from here on. */
  char prog[80];
  unsigned long long image_size = 0;
  if (!field(meta, "abi", v, sizeof v) || sscanf(v, "%u", &m->abi) != 1 ||
      !field(meta, "plc2_nvalue", v, sizeof v) || sscanf(v, "%d", &m->plc2_nvalue) != 1 ||
      !field(meta, "slices", v, sizeof v) || sscanf(v, "%u", &m->slices) != 1 ||
      !field(meta, "state_size", v, sizeof v) || sscanf(v, "%llu", &image_size) != 1 ||
      !(m->state_size = image_size, field(meta, "image_size", v, sizeof v)) ||
      sscanf(v, "%llu", &image_size) != 1 || image_size != image ||
      !field(meta, "program", prog, sizeof prog) || strlen(prog) != 71) {
    fail(err, errlen, "bad signed trailer values", path);
    goto done;
  }
  memcpy(m->program, prog, 72);
  h = open_sealed(data, size);
  if (!h) fail(err, errlen, "cannot load the verified copy", path);
done:
  free(data);
  return h;
}

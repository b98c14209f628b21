#!/usr/bin/env python3
"""Issue 11 finding 1 through the CLI: `ladderjit run --engine aot:` must refuse every .so that a
trusted `ladderjit compile` did not sign, before any of its bytes are mapped (docs/aot.md "Trust").

  aot_attacks.py LADDERJIT SOURCE_DIR [--mutants N] [--seed S]

1. a foreign .so whose ELF constructor writes a marker file and which exports every ljprog_*
   symbol with the right program hash, with the trailers an attacker can make (none, the old
   unkeyed SHA-256 trailer, the genuine trailer of a real .so, the signed trailer of a real .so
   with its image swapped): refused, exit 2, and the marker must not exist afterwards;
2. N mutants of a real signed .so (seeded; 1-4 random bytes of the image changed, then every
   unkeyed part recomputed: the old SHA-256 trailer for an old-format .so; a signature cannot
   be recomputed): none may run (exit 0) or crash (signal), each is refused with exit 2;
3. the genuine .so still runs and prints what --engine interp prints.

The script also runs against an old ladderjit (unsigned trailer) to show the attacks worked
there: then it reports what ran and exits 1. Exit 0 = every attack refused."""
import hashlib
import os
import random
import subprocess
import sys
import tempfile

FAIL = []


def check(ok, what):
    if not ok:
        FAIL.append(what)
        print("FAIL:", what)


def main():
    args = sys.argv[1:]
    lj, src = args[0], args[1]
    mutants = int(args[args.index("--mutants") + 1]) if "--mutants" in args else 60
    seed = int(args[args.index("--seed") + 1]) if "--seed" in args else 11
    tmp = tempfile.mkdtemp(prefix="ljaotattack-")
    env = dict(os.environ, LADDERJIT_KEY_DIR=os.path.join(tmp, "keys"), LADDERJIT_CACHE="off")
    prog = os.path.join(src, "examples", "part_counter.stl")

    def run(*a, timeout=120):
        try:
            r = subprocess.run([lj, *a], capture_output=True, env=env, timeout=timeout)
        except subprocess.TimeoutExpired:
            return None, "", "timed out"  # a hang (the old loader ran mutated code that looped)
        return r.returncode, r.stdout.decode(errors="replace"), r.stderr.decode(errors="replace")

    good = os.path.join(tmp, "good.so")
    rc, _, err = run("compile", prog, "-o", good)
    check(rc == 0, "compile: " + err)
    data = open(good, "rb").read()
    old_format = data[-80:-65] == b"LJPROG1-SHA256:"
    if old_format:
        image, trailer = data[:-80], data[-80:]
    else:
        meta_len = int(data[-89 + 16:-89 + 24], 16)
        image, trailer = data[:-89 - meta_len], data[-89 - meta_len:]
    print(f"format: {'old unsigned (LJPROG1-SHA256)' if old_format else 'signed (LJPROG3)'}")

    def sha_trailer(img):  # the old format's unkeyed checksum, which anyone can recompute
        return b"LJPROG1-SHA256:" + hashlib.sha256(img).hexdigest().encode() + b"\n"

    def retrailer(img):  # everything unkeyed recomputed; a signature stays what it was
        return img + (sha_trailer(img) if old_format else trailer)

    tail = ["--ticks", "60", "--stimulus", os.path.join(src, "examples", "part_counter.stim"),
            "--watch", "G2579,Y481,B0,D41"]
    rc_i, interp, _ = run("run", prog, "--engine", "interp", *tail)
    rc_a, aot, err = run("run", prog, "--engine", "aot:" + good, *tail)
    check(rc_i == 0 and rc_a == 0 and aot == interp, "the genuine .so runs like interp: " + err)

    # 1. The constructor .so with the right hash.
    text = open(prog, "rb").read().replace(b"\r\n", b"\n")
    if text and not text.endswith(b"\n"):
        text += b"\n"
    phash = "sha256:" + hashlib.sha256(
        b"ladderjit-program 1\nplc2_nvalue = 200\n[program]\n" + text).hexdigest()
    marker = os.path.join(tmp, "constructor-ran")
    csrc = os.path.join(tmp, "evil.c")
    with open(csrc, "w") as f:
        f.write(f"""#include <stdio.h>
#include <stddef.h>
#include <string.h>
__attribute__((constructor)) static void evil(void) {{
  FILE *f = fopen("{marker}", "w"); if (f) {{ fputs("ran\\n", f); fclose(f); }}
}}
static unsigned z(void *s, void *t, unsigned u) {{ (void)s; (void)t; (void)u; return 0; }}
typedef struct {{ void *ctx; void *init, *plc1, *plc2; unsigned n; }} ent;
unsigned ljprog_abi_version(void) {{ return {5 if not old_format else 2}; }}
const char *ljprog_hash(void) {{ return "{phash}"; }}
unsigned ljprog_slice_count(void) {{ return 1; }}
size_t ljprog_state_size(void);
void ljprog_state_reset(void *s) {{ (void)s; }}
unsigned ljprog_init(void *s) {{ (void)s; return 0; }}
unsigned ljprog_tick(void *s) {{ (void)s; return 0; }}
void ljprog_entries(ent *e) {{ memset(e, 0, sizeof *e); e->init = e->plc1 = e->plc2 = (void *)z; e->n = 1; }}
""")
    # the state size the loader expects, from the public header
    inc = os.path.join(src, "runtime_abi", "include")
    with open(csrc, "a") as f:
        f.write('#include "ladderjit/abi.h"\nsize_t ljprog_state_size(void) { return sizeof(lj_state); }\n')
    evil = os.path.join(tmp, "evil-image.so")
    cc = subprocess.run(["cc", "-shared", "-fPIC", "-I", inc, "-o", evil, csrc],
                        capture_output=True)
    check(cc.returncode == 0, "cc evil.c: " + cc.stderr.decode())
    evil_img = open(evil, "rb").read()
    for name, body in [("no trailer", evil_img), ("unkeyed SHA-256 trailer",
                                                   evil_img + sha_trailer(evil_img)),
                       ("the genuine .so's trailer", evil_img + trailer)]:
        path = os.path.join(tmp, "evil.so")
        open(path, "wb").write(body)
        if os.path.exists(marker):
            os.remove(marker)
        rc, _, err = run("run", prog, "--engine", "aot:" + path, "--ticks", "1")
        ran = os.path.exists(marker)
        check(rc == 2 and "error" in err and not ran,
              f"constructor .so with {name}: exit {rc}, constructor ran: {ran}: {err.strip()}")
        print(f"constructor .so, {name}: exit {rc}, constructor ran: {ran}")

    # 2. Mutants of the genuine .so.
    rnd = random.Random(seed)
    accepted = crashed = hung = refused = 0
    path = os.path.join(tmp, "mut.so")
    for i in range(mutants):
        img = bytearray(image)
        for _ in range(rnd.randint(1, 4)):
            img[rnd.randrange(len(img))] = rnd.randrange(256)
        open(path, "wb").write(retrailer(bytes(img)))
        rc, _, err = run("run", prog, "--engine", "aot:" + path, "--ticks", "5", timeout=20)
        if rc is None:
            hung += 1
        elif rc == 0:
            accepted += 1
        elif rc < 0 or rc >= 128:
            crashed += 1
        elif rc == 2 and "ladderjit: error: --engine aot:" in err:
            refused += 1
        else:
            check(False, f"mutant {i}: exit {rc}: {err.strip()[:200]}")
    print(f"mutants: {mutants}, ran: {accepted}, crashed: {crashed}, hung: {hung}, "
          f"refused: {refused}")
    check(accepted == 0 and crashed == 0 and hung == 0 and refused == mutants,
          f"mutants must all be refused ({accepted} ran, {crashed} crashed, {hung} hung)")

    if FAIL:
        print(f"{len(FAIL)} attack(s) not refused")
        return 1
    print("every attack refused")
    return 0


if __name__ == "__main__":
    sys.exit(main())

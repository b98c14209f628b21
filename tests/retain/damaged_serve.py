#!/usr/bin/python3
"""A damaged retain file is moved aside before serve's first save (issue 28, finding 7).

Expected behaviour (docs/retain.md "Restore"): a retain file that cannot be used because it is
damaged (checksum mismatch, truncation, bad magic) is renamed to FILE.damaged-TIME (FILE.prev
to FILE.prev.damaged-TIME) before the first save, and the restore log line names the new file.
The machine data in the damaged file is never overwritten: after serve has run and saved
several times, each damaged copy still exists byte for byte.

Cases:
  both:    one flipped bit in FILE and in FILE.prev -> both moved aside, zeros, log says where;
  no-prev: FILE damaged, no FILE.prev -> FILE moved aside;
  prev:    FILE damaged, FILE.prev good -> FILE.prev restored, FILE moved aside.
Exit status 0 = pass.
"""
import glob
import os
import shutil
import subprocess
import sys
import tempfile

PROGRAM = """; retain damaged-file test program (tests/retain/damaged_serve.py)
LD R0.0
MOV D0 B0
1END
"""
B5_OFFSET = 144 + 5 * 4  # docs/retain.md "File format (format 1)": B0..B49 (int32) from 144
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
import serveutil  # noqa: E402
from serveutil import FAILURES, check  # noqa: E402,F401


def serve(lj, workdir, retain, duration, *extra):
    r = subprocess.run([lj, "serve", os.path.join(workdir, "p.stl"), "--engine", "interp",
                        "--retain", retain, "--retain-period-ms", "10", "--duration", duration,
                        *extra], capture_output=True, text=True, timeout=60)
    return r.returncode, r.stderr


def read(path):
    with open(path, "rb") as f:
        return f.read()


def flip(path, offset):
    data = bytearray(read(path))
    data[offset] ^= 0x01
    with open(path, "wb") as f:
        f.write(bytes(data))
    return bytes(data)


def make_store(lj, workdir, retain, with_prev):
    """Two runs: FILE (and FILE.prev) hold B5 = 4471."""
    for _ in range(2 if with_prev else 1):
        rc, err = serve(lj, workdir, retain, "1", "--set", "B5=4471")
        check(rc == 0, "serve exits 0: " + err)
    if not with_prev and os.path.exists(retain + ".prev"):
        os.unlink(retain + ".prev")


def run_case(lj, workdir, name, damage_prev, with_prev):
    d = os.path.join(workdir, name)
    os.mkdir(d)
    retain = os.path.join(d, "store.ret")
    make_store(lj, workdir, retain, with_prev)
    damaged_main = flip(retain, B5_OFFSET)
    damaged_prev = flip(retain + ".prev", B5_OFFSET + 1) if damage_prev else None
    # Runs long enough for several periodic saves (period 10 ms) and the shutdown save.
    rc, err = serve(lj, workdir, retain, "2")
    check(rc == 0, name + ": serve exits 0 with a damaged store: " + err)
    kept = sorted(glob.glob(retain + ".damaged-*"))
    check(len(kept) == 1, name + ": FILE moved aside to FILE.damaged-TIME, found %s" % kept)
    if kept:
        check(read(kept[0]) == damaged_main, name + ": the damaged FILE is kept byte for byte")
        check(kept[0] in err, name + ": the log names " + kept[0] + ": " + err)
    kept_prev = sorted(glob.glob(retain + ".prev.damaged-*"))
    if damage_prev:
        check(len(kept_prev) == 1,
              name + ": FILE.prev moved aside to FILE.prev.damaged-TIME, found %s" % kept_prev)
        if kept_prev:
            check(read(kept_prev[0]) == damaged_prev,
                  name + ": the damaged FILE.prev is kept byte for byte")
            check(kept_prev[0] in err, name + ": the log names " + kept_prev[0] + ": " + err)
        check("starting with zeros" in err, name + ": the log says it starts with zeros: " + err)
    else:
        check(not kept_prev, name + ": no FILE.prev.damaged-* without damage: %s" % kept_prev)
    if with_prev and not damage_prev:
        check("restored " + retain + ".prev" in err, name + ": FILE.prev is restored: " + err)
    # A second run with the now good store must not touch the kept copies.
    rc, err = serve(lj, workdir, retain, "1")
    check(rc == 0 and "restored " + retain in err, name + ": the new store restores: " + err)
    check(sorted(glob.glob(retain + ".damaged-*")) == kept, name + ": kept copies stay")


def main():
    lj = sys.argv[1]
    workdir = tempfile.mkdtemp(prefix="lj-retain-damaged-")
    try:
        with open(os.path.join(workdir, "p.stl"), "w") as f:
            f.write(PROGRAM)
        run_case(lj, workdir, "both", damage_prev=True, with_prev=True)
        run_case(lj, workdir, "no-prev", damage_prev=False, with_prev=False)
        run_case(lj, workdir, "prev", damage_prev=False, with_prev=True)
    finally:
        shutil.rmtree(workdir, ignore_errors=True)
    if FAILURES:
        print("%d failure(s)" % len(FAILURES))
        return 1
    print("PASS")
    return 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
"""Issue 28 finding 8: every command writes its output files the same safe way.

Expected (docs/security.md "Output files"; CLI.md: a usage error exits 2): `serve --stats`,
`ladder -o`, `dit -o`, `run --dump` and `compile -o` refuse an output path that is a symbolic
link (exit 2, "not a regular file (a symbolic link)") and never write through it, also in a
sticky world-writable directory (like /tmp) where another user plants links; the link and its
target are left unchanged. An existing regular file is replaced by a new one (a hard link to
another file is not written through), a new path is written, and no temporary file is left
beside the output."""
import os
import shutil
import tempfile

from sec_util import PROGRAM, check, finish, run, write


def writers(prog, out):
    """Each command that writes one output file, writing `out`."""
    return {
        "serve --stats": ["serve", prog, "--engine", "interp", "--duration", "1", "--stats",
                          out, "--control", os.path.join(os.path.dirname(out), "c.sock")],
        "ladder -o": ["ladder", prog, "-o", out],
        "dit -o": ["dit", prog, "-o", out],
        "run --dump": ["run", prog, "--engine", "interp", "--ticks", "2", "--dump", out],
        "compile -o": ["compile", prog, "-o", out],
    }


def main():
    tmp = tempfile.mkdtemp(prefix="ljsec-outlink-")
    prog = os.path.join(tmp, "p.stl")
    write(prog, PROGRAM)
    shared = os.path.join(tmp, "shared")  # like /tmp: sticky, world-writable
    os.mkdir(shared)
    os.chmod(shared, 0o1777)
    victim = os.path.join(tmp, "victim")

    for name in writers(prog, "x"):
        write(victim, "precious\n")
        out = os.path.join(shared, "out")
        os.symlink(victim, out)
        rc, _, err = run(*writers(prog, out)[name], timeout=120)
        check(rc == 2 and "not a regular file (a symbolic link)" in err,
              f"{name} through a planted symlink: exit 2, refused: rc={rc} {err.strip()}")
        with open(victim) as f:
            check(f.read() == "precious\n", f"{name}: the symlink's target is unchanged")
        check(os.path.islink(out), f"{name}: the symlink is left alone")
        if os.path.lexists(out):
            os.unlink(out)

        # a hard link to another file at OUT: OUT is replaced, the other file is not written
        os.link(victim, out)
        rc, _, err = run(*writers(prog, out)[name], timeout=120)
        check(rc == 0, f"{name} over an existing regular file works: {err.strip()}")
        with open(victim) as f:
            check(f.read() == "precious\n", f"{name}: a hard-linked file is not written through")
        check(os.path.isfile(out) and os.path.getsize(out) > 0, f"{name}: OUT was written")
        if os.path.lexists(out):
            os.unlink(out)

        rc, _, err = run(*writers(prog, out)[name], timeout=120)
        check(rc == 0 and os.path.isfile(out), f"{name} to a new path works: {err.strip()}")
        left = sorted(f for f in os.listdir(shared) if f not in ("out", "c.sock"))
        check(left == [], f"{name}: no temporary file is left beside OUT: {left}")
        if os.path.lexists(out):
            os.unlink(out)
    shutil.rmtree(tmp, ignore_errors=True)
    return finish("output_symlinks")


if __name__ == "__main__":
    raise SystemExit(main())

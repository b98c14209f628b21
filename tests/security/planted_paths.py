#!/usr/bin/env python3
"""Issue 11 item 8: planted paths around serve's shared memory and retentive store.

Expected (docs/serve.md "Shared-memory image", docs/retain.md "Location"):
- --shm never reuses an existing object: one of ours (a crash's leftover, here with mode 0666
  and kept open by the "attacker") is replaced by a new 0600 object; one of another user is
  refused (exit 2). Needs root to plant another user's object: without root this test FAILS.
- the retain temp file never follows a planted symlink (FILE.tmp -> victim stays unchanged);
- two servers cannot share a retain file (the second exits 2 naming the lock);
- --retain in a missing directory, or a FIFO in the file's place, exits 2 at start with one
  message, at once."""
import os
import shutil
import stat
import tempfile
import time

from sec_util import PROGRAM, Server, check, finish, run, write

NOBODY = 65534


def main():
    tmp = tempfile.mkdtemp(prefix="ljsec-pp-")
    prog = os.path.join(tmp, "p.stl")
    write(prog, PROGRAM, age=10)
    check(os.geteuid() == 0, "runs as root (needed to plant another user's shm object)")

    # --- shm: our own planted 0666 object, kept open, must not be the one serve uses ---
    name = f"ljsec-{os.getpid()}"
    path = "/dev/shm/" + name
    fd = os.open(path, os.O_RDWR | os.O_CREAT | os.O_EXCL, 0o666)
    os.fchmod(fd, 0o666)
    planted_ino = os.fstat(fd).st_ino
    sock = os.path.join(tmp, "c.sock")
    srv = Server(prog, "--control", sock, "--shm", name, "--duration", "30")
    check(srv.started(), "serve --shm starts over a stale object of ours")
    st = os.stat(path) if os.path.exists(path) else None
    check(st is not None and st.st_ino != planted_ino, "the planted object was replaced")
    check(st is not None and stat.S_IMODE(st.st_mode) == 0o600, "the new object has mode 0600")
    srv.stop()
    os.close(fd)
    # another user's object: refused
    fd = os.open(path, os.O_RDWR | os.O_CREAT | os.O_EXCL, 0o666)
    os.fchmod(fd, 0o666)
    os.fchown(fd, NOBODY, NOBODY)
    rc, _, err = run("serve", prog, "--control", sock, "--shm", name, "--duration", "1",
                     timeout=20)
    check(rc == 2 and "belongs to uid" in err, "another user's shm object is refused: " + err)
    os.close(fd)
    if os.path.exists(path):
        os.unlink(path)

    # --- retain: a planted FILE.tmp symlink is never followed ---
    victim = os.path.join(tmp, "victim")
    write(victim, "precious\n")
    store = os.path.join(tmp, "r.dat")
    os.symlink(victim, store + ".tmp")
    srv = Server(prog, "--control", sock, "--retain", store, "--duration", "30")
    check(srv.started(), "serve --retain starts")
    srv.monitor("write", "B5=1234")
    time.sleep(0.5)
    srv.stop()
    with open(victim, "rb") as f:
        check(f.read() == b"precious\n", "the symlink target of FILE.tmp is unchanged")
    check(os.path.isfile(store) and not os.path.islink(store), "the store itself was written")

    # --- two servers on one store ---
    a = Server(prog, "--control", sock, "--retain", store, "--duration", "30")
    check(a.started(), "the first server holds the store")
    rc, _, err = run("serve", prog, "--control", os.path.join(tmp, "d.sock"), "--retain", store,
                     "--duration", "2", timeout=20)
    check(rc == 2 and "in use" in err, "a second server on the same store is refused: " + err)
    a.stop()

    # --- missing directory and a FIFO at the store's path: refused at start, once ---
    t0 = time.time()
    rc, _, err = run("serve", prog, "--control", sock, "--retain", "/nonexistent-dir/r.dat",
                     "--duration", "2", timeout=20)
    check(rc == 2 and "nonexistent-dir" in err and len(err.strip().splitlines()) == 1
          and time.time() - t0 < 1.8,
          "--retain in a missing directory: exit 2 at start, one message: " + err)
    fifo = os.path.join(tmp, "fifo.dat")
    os.mkfifo(fifo)
    rc, _, err = run("serve", prog, "--control", sock, "--retain", fifo, "--duration", "2",
                     timeout=10)
    check(rc == 2 and "not a regular file" in err, "a FIFO as the retain file: exit 2: " + err)
    shutil.rmtree(tmp, ignore_errors=True)
    return finish("planted_paths")


if __name__ == "__main__":
    raise SystemExit(main())

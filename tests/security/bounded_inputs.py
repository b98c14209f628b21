#!/usr/bin/env python3
"""Issue 11 item 4: every PROGRAM / stimulus / params / plc.dit reader is bounded.

Expected (docs/serve.md "Online change", io/InputFiles.h): regular files only, refused at once
(a FIFO never blocks); at most 16 MiB; a read error (/proc/self/mem) is an error, not an empty
program; parsing stops at the 10,000-statement limit (DIALECT.md 6) and after 100 errors; a
file that is not a program gets one error that echoes none of its lines; and a FIFO handed to
`monitor load` is refused without wedging serve. Children run under a 2 GiB address-space limit
so the old code fails these checks instead of exhausting the machine."""
import os
import resource
import shutil
import signal
import subprocess
import tempfile
import time

from sec_util import LJ, PROGRAM, Server, check, finish, write

LIMIT = 2 << 30


def limited():
    resource.setrlimit(resource.RLIMIT_AS, (LIMIT, LIMIT))


def lj(*args, timeout=10):
    """Run ladderjit: (exit code or None on timeout, stderr, max RSS in MiB)."""
    p = subprocess.Popen([LJ, *args], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                         text=True, preexec_fn=limited)
    try:
        _, err = p.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        p.kill()
        p.communicate()
        return None, "timed out", 0
    ru = resource.getrusage(resource.RUSAGE_CHILDREN)
    return p.returncode, err, ru.ru_maxrss / 1024


def main():
    tmp = tempfile.mkdtemp(prefix="ljsec-in-")
    prog = os.path.join(tmp, "p.stl")
    write(prog, PROGRAM, age=10)
    fifo = os.path.join(tmp, "f.stl")
    os.mkfifo(fifo)

    # Measured first: RUSAGE_CHILDREN keeps the maximum over every child so far.
    many = os.path.join(tmp, "many.stl")
    write(many, "LDT\n" + "OUT Y0.0\nLDT\n" * 150000 + "2END\n")
    rc, err, rss = lj("check", many, timeout=30)
    check(rc == 1 and "statements, more than the limit of 10000" in err,
          "300,001 statements: exit 1 at the limit: " + err[-200:])
    check(err.count("\n") < 50, f"and parsing stopped there ({err.count(chr(10))} lines of output)")
    check(rss < 130, f"memory stays small while refusing it ({rss:.0f} MiB max RSS, bound 130)")

    rc, err, _ = lj("check", fifo, timeout=5)
    check(rc == 2 and "not a regular file" in err, "check FIFO: refused at once: " + err)
    rc, err, _ = lj("run", prog, "--stimulus", fifo, timeout=5)
    check(rc == 2 and "not a regular file" in err, "run --stimulus FIFO: refused: " + err)
    rc, err, _ = lj("run", prog, "--params", fifo, timeout=5)
    check(rc == 2 and "not a regular file" in err, "run --params FIFO: refused: " + err)
    rc, err, _ = lj("serve", prog, "--params", fifo, "--duration", "1", timeout=5)
    check(rc == 2 and "not a regular file" in err, "serve --params FIFO: refused: " + err)
    dfifo = os.path.join(tmp, "f.dit")
    os.mkfifo(dfifo)
    rc, err, _ = lj("check", dfifo, timeout=5)
    check(rc == 2 and "not a regular file" in err, "check FIFO.dit: refused: " + err)
    rc, err, _ = lj("check", "/dev/zero", timeout=10)
    check(rc == 2 and "not a regular file" in err, "check /dev/zero: refused: " + err[-200:])
    big = os.path.join(tmp, "big.stl")
    with open(big, "wb") as f:
        f.truncate(100 << 20)
    rc, err, _ = lj("check", big, timeout=20)
    check(rc == 2 and "limit" in err, "a 100 MB file: refused by its size: " + err[-200:])
    rc, err, _ = lj("check", "/proc/self/mem", timeout=10)
    check(rc == 2 and "cannot read" in err, "/proc/self/mem is a read error: " + err[-200:])

    errs = os.path.join(tmp, "errs.stl")
    write(errs, "LDT\n" + "OUT\n" * 5000)
    rc, err, _ = lj("check", errs, timeout=20)
    check(rc == 1 and err.count("error:") <= 101 and "too many errors" in err,
          f"5,000 bad lines: at most 101 errors ({err.count('error:')})")
    anb = os.path.join(tmp, "anb.stl")
    write(anb, "LDT\n" + "ANB\n" * 3000 + "1END\n2END\n")
    rc, err, _ = lj("check", anb, timeout=20)
    check(rc == 1 and err.count("\n") == 201 and "2800 more diagnostic lines not shown" in err,
          f"3,000 verifier errors: 200 lines and a count ({err.count(chr(10))} lines)")
    secret = os.path.join(tmp, "shadow")
    write(secret, "".join(f"user{i}:$6$SECRETSALT{i}:19000:0:99999:7:::\n" for i in range(50)))
    rc, err, _ = lj("check", secret, timeout=10)
    check(rc == 1 and "SECRETSALT" not in err and err.count("error:") == 1,
          "a file that is not a program: one error, none of its lines echoed: " + err[:300])

    # serve: `monitor load` of a FIFO in the load directory must not wedge the server.
    sock = os.path.join(tmp, "c.sock")
    srv = Server(prog, "--control", sock, "--duration", "60")
    check(srv.started(), "serve starts")
    rc, _, err = srv.monitor("load", fifo, timeout=8)
    check(rc == 2 and "not a regular file" in err, "monitor load FIFO: refused at once: " + err)
    mem = os.path.join(tmp, "mem.stl")
    os.symlink("/proc/self/mem", mem)
    rc, _, err = srv.monitor("load", mem, timeout=8)
    check(rc == 2, "monitor load of a symlink to /proc/self/mem: refused: " + err)
    check(srv.read("D10") == 7, "the old program keeps running")
    t0 = time.time()
    srv.p.send_signal(signal.SIGTERM)
    try:
        srv.p.wait(timeout=5)
        check(time.time() - t0 < 3, "SIGTERM still stops serve promptly")
    except subprocess.TimeoutExpired:
        srv.p.kill()
        srv.p.wait()
        check(False, "SIGTERM still stops serve promptly (it hung)")
    shutil.rmtree(tmp, ignore_errors=True)
    return finish("bounded_inputs")


if __name__ == "__main__":
    raise SystemExit(main())

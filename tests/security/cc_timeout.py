#!/usr/bin/env python3
"""Issue 28 finding 9: `compile` bounds the C compiler's time and leaves no temporary file.

Expected (docs/aot.md "Time bound"; CLI.md: usage errors exit 2):
- the C compiler ($LADDERJIT_CC) may take 120 s by default (`compile --help` says so);
  `--cc-timeout S` or LADDERJIT_CC_TIMEOUT=S changes it; after it the compiler's whole process
  group is killed (a hung driver and the program it started) and compile exits 2 naming the
  bound; nothing is left beside OUT;
- a bad bound (0, not a number) is a usage error (exit 2) naming the option;
- SIGTERM or SIGINT to `ladderjit compile` while the compiler runs: ladderjit dies of it at
  once, the compiler's group is killed, and no OUT.XXXXXX is left beside OUT."""
import os
import shutil
import signal
import subprocess
import tempfile
import time

from sec_util import LJ, PROGRAM, check, finish, run, write


def alive(pid):
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    # a zombie is dead too (its parent, the killed driver, may not have been reaped yet)
    try:
        with open(f"/proc/{pid}/stat") as f:
            return f.read().split(")")[-1].split()[0] != "Z"
    except OSError:
        return False


def read_pid(path, seconds=20):
    end = time.time() + seconds
    while time.time() < end:
        try:
            with open(path) as f:
                text = f.read().strip()
            if text:
                return int(text)
        except OSError:
            pass
        time.sleep(0.02)
    return None


def main():
    tmp = tempfile.mkdtemp(prefix="ljsec-cc-")
    prog = os.path.join(tmp, "p.stl")
    write(prog, PROGRAM)
    outdir = os.path.join(tmp, "out")
    os.mkdir(outdir)
    out = os.path.join(outdir, "p.so")
    pidfile = os.path.join(tmp, "cc.pid")
    hung = os.path.join(tmp, "hung-cc")
    # A driver that hangs in a program it started (as cc waits for cc1 or ld).
    write(hung, f"#!/bin/sh\nsleep 1000 &\necho $! > {pidfile}\nwait\n")
    os.chmod(hung, 0o755)
    env = dict(os.environ, LADDERJIT_CC=hung)
    env.pop("LADDERJIT_CC_TIMEOUT", None)

    rc, help_text, _ = run("compile", "--help")
    check("--cc-timeout" in help_text and "120" in help_text,
          "compile --help names --cc-timeout and its default of 120 s")

    for how, extra, env_extra in (("--cc-timeout 2", ["--cc-timeout", "2"], {}),
                                  ("LADDERJIT_CC_TIMEOUT=2", [], {"LADDERJIT_CC_TIMEOUT": "2"})):
        if os.path.exists(pidfile):
            os.unlink(pidfile)
        t0 = time.time()
        rc, _, err = run("compile", prog, "-o", out, *extra, env={**env, **env_extra}, timeout=60)
        took = time.time() - t0
        check(rc == 2 and "did not finish within 2 s" in err,
              f"{how}: a hung C compiler is killed, exit 2: rc={rc} {err.strip()}")
        check(rc is not None and took < 30, f"{how}: compile returns soon after 2 s ({took:.1f} s)")
        pid = read_pid(pidfile, 1)
        time.sleep(0.2)
        check(pid is not None and not alive(pid),
              f"{how}: the program the compiler started is killed too (pid {pid})")
        check(os.listdir(outdir) == [], f"{how}: nothing is left beside OUT: {os.listdir(outdir)}")
        if pid is not None and alive(pid):
            os.kill(pid, signal.SIGKILL)

    for bad in ("0", "abc", "-5"):
        rc, _, err = run("compile", prog, "-o", out, "--cc-timeout", bad, env=env, timeout=60)
        check(rc == 2 and "--cc-timeout" in err, f"--cc-timeout {bad}: exit 2: {err.strip()}")
        rc, _, err = run("compile", prog, "-o", out, env={**env, "LADDERJIT_CC_TIMEOUT": bad},
                         timeout=60)
        check(rc == 2 and "LADDERJIT_CC_TIMEOUT" in err,
              f"LADDERJIT_CC_TIMEOUT={bad}: exit 2: {err.strip()}")
    check(os.listdir(outdir) == [], f"nothing is left beside OUT: {os.listdir(outdir)}")

    for sig in (signal.SIGTERM, signal.SIGINT):
        if os.path.exists(pidfile):
            os.unlink(pidfile)
        p = subprocess.Popen([LJ, "compile", prog, "-o", out], env=env,
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        pid = read_pid(pidfile)
        check(pid is not None, f"{sig.name}: the hung compiler runs")
        p.send_signal(sig)
        try:
            p.wait(timeout=10)
            stopped = True
        except subprocess.TimeoutExpired:
            stopped = False
            p.kill()
            p.wait()
        check(stopped and p.returncode != 0, f"{sig.name}: compile stops at once "
              f"(returncode {p.returncode})")
        time.sleep(0.2)
        check(pid is not None and not alive(pid), f"{sig.name}: the compiler's group is killed")
        check(os.listdir(outdir) == [],
              f"{sig.name}: no OUT.XXXXXX is left beside OUT: {os.listdir(outdir)}")
        if pid is not None and alive(pid):
            os.kill(pid, signal.SIGKILL)
    shutil.rmtree(tmp, ignore_errors=True)
    return finish("cc_timeout")


if __name__ == "__main__":
    raise SystemExit(main())

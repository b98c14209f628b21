"""Shared by the Python tests that start `ladderjit serve` and drive it with `ladderjit monitor`
(through tests/runtime/serve_client.py, tests/security/sec_util.py and
tests/security/ctl/ctl_common.py): the HNC-8 test programs, failure collection, running the
binary with a bound, and values read through `monitor`. Every wait is bounded, so a regression
shows as a failure, never as a hang; values are polled until they show up (the tests assert what
the server must do, never how fast)."""
import subprocess
import time

FAILURES = []

# Line numbers matter: `force line:N` addresses source lines (line 4 is LD X1.0).
PROGRAM = """\
LDT
MOV 7 D10
IEND
LD X1.0
OUT Y1.0
LDT
MOV 1 D20
1END
LDT
ADD D30 1 D30
2END
"""
LINE_LD_X10 = 4  # LD X1.0 in PROGRAM

# PROGRAM with the two parts' bodies swapped: D30 counts in PLC1, every scan.
PROGRAM_COUNT_IN_PLC1 = PROGRAM.replace("MOV 1 D20\n1END\nLDT\nADD D30 1 D30\n2END",
                                        "ADD D30 1 D30\n1END\nLDT\nMOV 1 D20\n2END")


def check(cond, what):
    """Record `what` as a failure unless `cond`; print the outcome. Returns `cond`."""
    print(("ok:   " if cond else "FAIL: ") + what, flush=True)
    if not cond:
        FAILURES.append(what)
    return cond


def finish(name=""):
    """The exit status of a test: 1 when a check failed."""
    head = name + ": " if name else ""
    if FAILURES:
        print(f"{head}{len(FAILURES)} failure(s)", flush=True)
        return 1
    print(f"{head}all checks passed", flush=True)
    return 0


def run(lj, *args, timeout=60, env=None):
    """`lj ARGS...`: (exit status, stdout, stderr), text decoded with errors replaced; the status is
    None when it did not finish within `timeout` seconds."""
    try:
        r = subprocess.run([lj, *args], capture_output=True, timeout=timeout, env=env)
    except subprocess.TimeoutExpired:
        return None, "", f"timed out after {timeout} s"
    return r.returncode, r.stdout.decode(errors="replace"), r.stderr.decode(errors="replace")


def monitor(lj, sock, *args, timeout=60, env=None):
    """`ladderjit monitor --control SOCK ARGS...` (run's result)."""
    return run(lj, "monitor", "--control", sock, *args, timeout=timeout, env=env)


def read(lj, sock, addr, timeout=60):
    """The value of `addr` through `monitor read`, or None when that failed."""
    rc, out, _ = monitor(lj, sock, "read", addr, timeout=timeout)
    return int(out.strip().split("=")[1]) if rc == 0 else None


def wait_value(lj, sock, addr, want, seconds=10):
    """Poll `addr` until it is `want` (True) or `seconds` passed (False, the last value printed)."""
    end = time.time() + seconds
    v = None
    while time.time() < end:
        v = read(lj, sock, addr)
        if v == want:
            return True
        time.sleep(0.02)
    print(f"  {addr} = {v}, wanted {want}", flush=True)
    return False

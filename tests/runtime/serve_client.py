"""Shared by the serve end-to-end tests (serve_monitor.py, serve_aot.py): the test program, the
`ladderjit` binary from argv[1], and helpers that drive `ladderjit monitor` and collect failures.
Values are polled until they show up (bounded by a generous deadline): the tests assert what the
server must do, never how fast."""
import subprocess
import sys
import time

LJ = sys.argv[1]
FAILURES = []

# Line numbers matter: `force line:N` addresses source lines.
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
LINE_LD_X10 = 4  # LD X1.0


def check(cond, what):
    if not cond:
        FAILURES.append(what)
        print("FAIL:", what, flush=True)


def run(*args):
    r = subprocess.run([LJ, *args], capture_output=True, text=True, timeout=300)
    return r.returncode, r.stdout, r.stderr


def monitor(sock, *args):
    return run("monitor", "--control", sock, *args)


def read(sock, addr):
    rc, out, _ = monitor(sock, "read", addr)
    return int(out.strip().split("=")[1]) if rc == 0 else None


def wait_value(sock, addr, want, seconds=30):
    end = time.time() + seconds
    v = None
    while time.time() < end:
        v = read(sock, addr)
        if v == want:
            return True
        time.sleep(0.02)
    print(f"  {addr} = {v}, wanted {want}", flush=True)
    return False

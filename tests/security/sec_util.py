"""Shared by the security regression tests (issue 11): the `ladderjit` binary from argv[1], a
serve process whose stderr log is collected, and checks that fail loudly. Every wait is bounded
so a regression shows as a failure, never as a hang."""
import os
import subprocess
import sys
import threading
import time

LJ = sys.argv[1]
FAILURES = []

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


def check(cond, what):
    print(("ok:   " if cond else "FAIL: ") + what, flush=True)
    if not cond:
        FAILURES.append(what)


def finish(name):
    if FAILURES:
        print(f"{name}: {len(FAILURES)} failure(s)")
        return 1
    print(f"{name}: all checks passed")
    return 0


def run(*args, timeout=60, **kw):
    try:
        r = subprocess.run([LJ, *args], capture_output=True, text=True, timeout=timeout, **kw)
        return r.returncode, r.stdout, r.stderr
    except subprocess.TimeoutExpired:
        return None, "", f"timed out after {timeout} s"


def write(path, text, age=None):
    with open(path, "w") as f:
        f.write(text)
    if age is not None:  # make the file look settled (older than serve's settle interval)
        t = time.time() - age
        os.utime(path, (t, t))


def serve_has(option):
    """Whether this ladderjit's serve knows `option` (the old code lacks the new ones)."""
    return option in run("serve", "--help")[1]


class Server:
    """`ladderjit serve` with its stderr log collected on a thread."""

    def __init__(self, *args):
        self.sock = None
        for i, a in enumerate(args):
            if a == "--control":
                self.sock = args[i + 1]
        self.p = subprocess.Popen([LJ, "serve", *args], stdout=subprocess.PIPE,
                                  stderr=subprocess.PIPE, text=True)
        self.log = []
        self.out = []
        threading.Thread(target=self._drain, args=(self.p.stderr, self.log), daemon=True).start()
        threading.Thread(target=self._drain, args=(self.p.stdout, self.out), daemon=True).start()

    @staticmethod
    def _drain(stream, into):
        for line in stream:
            into.append(line)

    def started(self, seconds=20):
        end = time.time() + seconds
        while time.time() < end:
            if any("control socket" in l for l in self.out):
                return True
            if self.p.poll() is not None:
                return False
            time.sleep(0.02)
        return False

    def monitor(self, *args, timeout=60):
        return run("monitor", "--control", self.sock, *args, timeout=timeout)

    def read(self, addr):
        rc, out, _ = self.monitor("read", addr)
        return int(out.strip().split("=")[1]) if rc == 0 else None

    def wait_value(self, addr, want, seconds=10):
        end = time.time() + seconds
        while time.time() < end:
            if self.read(addr) == want:
                return True
            time.sleep(0.02)
        return False

    def text(self):
        return "".join(self.log)

    def stop(self, seconds=10):
        if self.p.poll() is None:
            self.monitor("stop", timeout=seconds)
        try:
            self.p.wait(timeout=seconds)
        except subprocess.TimeoutExpired:
            self.p.kill()
            self.p.wait()
            return None
        time.sleep(0.05)  # let the drain threads take the last lines
        return self.p.returncode

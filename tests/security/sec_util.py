"""Shared by the security regression tests (issue 11): the `ladderjit` binary from argv[1], a
serve process whose stderr log is collected, and checks that fail loudly (tests/support/
serveutil.py). Every wait is bounded so a regression shows as a failure, never as a hang."""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
import subprocess
import threading
import time

import serveutil  # noqa: E402
from serveutil import FAILURES, PROGRAM, check, finish  # noqa: E402,F401

LJ = sys.argv[1]


def run(*args, timeout=60, env=None):
    return serveutil.run(LJ, *args, timeout=timeout, env=env)


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
        return serveutil.monitor(LJ, self.sock, *args, timeout=timeout)

    def read(self, addr):
        return serveutil.read(LJ, self.sock, addr)

    def wait_value(self, addr, want, seconds=10):
        return serveutil.wait_value(LJ, self.sock, addr, want, seconds)

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

#!/usr/bin/python3
"""SAVEDATA inside a running `ladderjit serve --retain` makes a durable retain save (end to end).

Expected behaviour, from the spec and the docs:
  * SAVEDATA calls the host's save_data on the rising edge of its input (hnc8-cnc-interface.md
    section 2 #62; docs/dialect-notes.md "NC services").
  * In serve that call asks the retentive store for a save outside the rate limit; periodic saves
    happen at most once per --retain-period-ms; SIGKILL gives no clean-shutdown save
    (docs/retain.md "When it saves").
  * B0..B49 are retained and restored at start, logged as "retain: restored FILE (save #n, ...)";
    the file keeps B0 as an int32 LE at offset 144 (docs/retain.md "File format", "Restore").
  * Function blocks are level-triggered: MOV runs only while its input is 1 (DIALECT.md 5).

With --retain-period-ms 60000 the only periodic save in a run is the first one (the start state,
B0 = 0), so after it B0 reaches the file only through SAVEDATA. Per engine (jit, interp):
  positive: B0 := 4242, X0.0 rises -> the file holds 4242; then B0 := 5555 with X0.0 held at 1
            (no new edge) -> the file keeps 4242; SIGKILL; a restart restores B0 = 4242.
  negative: B0 := 4242 without an X0.0 edge; SIGKILL; a restart restores B0 = 0.
Exit status 0 = pass.
"""
import os
import shutil
import signal
import struct
import subprocess
import sys
import tempfile
import time

# X0.1 gates the MOV so that after a restart (X and D start at 0) the program leaves the restored
# B0 alone and `monitor read B0` shows what was restored.
PROGRAM = """; SAVEDATA end-to-end test program (tests/retain/savedata_serve.py)
LD X0.1
MOV D0 B0
LD X0.0
SAVEDATA
1END
"""
B0_OFFSET = 144  # docs/retain.md "File format (format 1)": B0..B49 (int32) at offset 144
SETTLE = 0.5  # s to wait before asserting that no save happened (a SAVEDATA save takes ms)
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
import serveutil  # noqa: E402
from serveutil import FAILURES, check  # noqa: E402,F401


class Server:
    """One `ladderjit serve` process with its own control socket and log files."""

    def __init__(self, lj, workdir, engine, retain, name):
        self.lj = lj
        self.sock = os.path.join(workdir, name + ".sock")
        self.out = open(os.path.join(workdir, name + ".out"), "w+")
        self.err = open(os.path.join(workdir, name + ".err"), "w+")
        self.proc = subprocess.Popen(
            [lj, "serve", os.path.join(workdir, "p.stl"), "--engine", engine, "--retain", retain,
             "--retain-period-ms", "60000", "--control", self.sock, "--duration", "60"],
            stdout=self.out, stderr=self.err)
        deadline = time.time() + 30
        while time.time() < deadline:
            self.out.seek(0)
            if "control socket " + self.sock in self.out.read():
                return
            if self.proc.poll() is not None:
                break
            time.sleep(0.01)
        self.proc.kill()
        sys.exit("FAIL: serve did not start: " + self.log())

    def log(self):
        self.err.seek(0)
        return self.err.read()

    def monitor(self, *args):
        return serveutil.monitor(self.lj, self.sock, *args, timeout=30)

    def write(self, *assignments):
        rc, _, err = self.monitor("write", *assignments)
        check(rc == 0, "monitor write %s accepted: %s" % (" ".join(assignments), err))

    def read(self, addr):
        return serveutil.read(self.lj, self.sock, addr, timeout=30)

    def wait_value(self, addr, want, seconds=10):
        return serveutil.wait_value(self.lj, self.sock, addr, want, seconds)

    def kill9(self):
        self.proc.send_signal(signal.SIGKILL)
        self.proc.wait(timeout=30)
        check(self.proc.returncode == -signal.SIGKILL, "serve died of SIGKILL")


def file_b0(path):
    """B0 in the retain file, or None while it does not exist (it is replaced by rename)."""
    try:
        with open(path, "rb") as f:
            data = f.read()
    except FileNotFoundError:
        return None
    return struct.unpack_from("<i", data, B0_OFFSET)[0] if len(data) >= B0_OFFSET + 4 else None


def wait_file_b0(path, want, seconds=10):
    end = time.time() + seconds
    v = None
    while time.time() < end:
        v = file_b0(path)
        if v == want:
            return True
        time.sleep(0.005)
    print("  %s: B0 = %s, wanted %s" % (path, v, want), flush=True)
    return False


def start_and_set_b0(lj, workdir, engine, retain, tag):
    """Fresh store: start serve, wait for the start save (B0 = 0), then make B0 = 4242."""
    srv = Server(lj, workdir, engine, retain, tag + "-1")
    check("does not exist yet" in srv.log(), tag + ": a fresh store starts with zeros: " + srv.log())
    check(wait_file_b0(retain, 0), tag + ": the start state (B0 = 0) is saved once")
    srv.write("D0=4242", "X0.1=1")
    check(srv.wait_value("B0", 4242), tag + ": B0 follows D0 while X0.1 = 1")
    time.sleep(SETTLE)
    check(file_b0(retain) == 0, tag + ": no periodic save within --retain-period-ms 60000")
    return srv


def restart_b0(lj, workdir, engine, retain, tag):
    """Restart serve on the store after a SIGKILL; the restored B0 (None if unreadable)."""
    srv = Server(lj, workdir, engine, retain, tag + "-2")
    log = srv.log()
    check("retain: restored " + retain + " (save #" in log and "WARNING" not in log,
          tag + ": the restart restores the main file: " + log)
    b0 = srv.read("B0")
    srv.kill9()
    return b0


def positive(lj, workdir, engine):
    tag = engine + "-savedata"
    retain = os.path.join(workdir, tag + ".retain")
    srv = start_and_set_b0(lj, workdir, engine, retain, tag)
    srv.write("X0.0=1")  # rising edge of SAVEDATA's input
    check(wait_file_b0(retain, 4242), tag + ": the SAVEDATA edge saves B0 = 4242")
    # X0.0 stays 1: no new edge, so a new B0 is not saved (rising edge only, dialect-notes).
    srv.write("D0=5555")
    check(srv.wait_value("B0", 5555), tag + ": B0 follows D0 = 5555")
    time.sleep(SETTLE)
    check(file_b0(retain) == 4242, tag + ": X0.0 held at 1 saves nothing more")
    srv.kill9()
    b0 = restart_b0(lj, workdir, engine, retain, tag)
    check(b0 == 4242, tag + ": after SIGKILL the restart restores B0 = 4242 (got %s)" % b0)


def negative(lj, workdir, engine):
    tag = engine + "-no-edge"
    retain = os.path.join(workdir, tag + ".retain")
    srv = start_and_set_b0(lj, workdir, engine, retain, tag)
    srv.kill9()
    b0 = restart_b0(lj, workdir, engine, retain, tag)
    check(b0 == 0, tag + ": without SAVEDATA the restart restores the start save B0 = 0 (got %s)"
          % b0)


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: savedata_serve.py LADDERJIT")
    lj = sys.argv[1]
    if not os.access(lj, os.X_OK):
        sys.exit("FAIL: no ladderjit binary at " + lj)
    workdir = tempfile.mkdtemp(prefix="lj-savedata-")
    with open(os.path.join(workdir, "p.stl"), "w") as f:
        f.write(PROGRAM)
    started = time.time()
    for engine in ("jit", "interp"):
        positive(lj, workdir, engine)
        negative(lj, workdir, engine)
    print("savedata_serve: %d failure(s) in %.1f s" % (len(FAILURES), time.time() - started))
    if FAILURES:
        print("logs kept in " + workdir)
        return 1
    shutil.rmtree(workdir, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())

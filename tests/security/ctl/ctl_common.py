"""Shared by the control-socket security tests (tests/security/ctl/): start `ladderjit serve`,
run commands as another user, raw control-socket and Modbus clients, and failure collection
(tests/support/serveutil.py). A part that needs a second user and cannot get one FAILS (never
skips)."""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "support"))
import re
import socket
import subprocess
import time

import serveutil  # noqa: E402
from serveutil import FAILURES, check  # noqa: E402,F401
from serveutil import PROGRAM_COUNT_IN_PLC1 as PROGRAM  # noqa: E402,F401

LJ = sys.argv[1]


def finish():
    return serveutil.finish()


def run(*args, env=None, timeout=60):
    return serveutil.run(LJ, *args, timeout=timeout, env=env)


def start_serve(args, env=None, umask=None, out_path=None):
    """Start serve; return (process, control socket path from its banner, output file)."""
    out = open(out_path, "w+b")
    pre = (lambda: os.umask(umask)) if umask is not None else None
    proc = subprocess.Popen([LJ, "serve", *args], stdout=out, stderr=subprocess.STDOUT, env=env,
                            preexec_fn=pre)
    end = time.time() + 60
    sock = None
    while time.time() < end and proc.poll() is None:
        out.seek(0)
        m = re.search(rb"control socket (\S+)\n", out.read())
        if m:
            sock = m.group(1).decode(errors="surrogateescape")
            break
        time.sleep(0.02)
    return proc, sock, out


def output(out):
    out.seek(0)
    return out.read().decode(errors="replace")


def stop_serve(proc, sock):
    if proc.poll() is None and sock:
        run("monitor", "--control", sock, "stop")
    try:
        return proc.wait(timeout=30)
    except subprocess.TimeoutExpired:
        proc.kill()
        return proc.wait()


def control(sock, line, timeout=10):
    """One raw request line on a fresh connection; the answer line, or the error text."""
    s = socket.socket(socket.AF_UNIX)
    s.settimeout(timeout)
    try:
        s.connect(sock)
        s.sendall(line)
        buf = b""
        while not buf.endswith(b"\n"):
            b = s.recv(65536)
            if not b:
                break
            buf += b
        return buf
    finally:
        s.close()


def as_nobody(code, timeout=30):
    """Run python code as uid nobody; returns (rc, stdout). None when it cannot be done."""
    cmd = ["setpriv", "--reuid=nobody", "--regid=nogroup", "--clear-groups", sys.executable, "-c",
           code]
    try:
        r = subprocess.run(cmd, capture_output=True, text=True, timeout=timeout)
    except (OSError, subprocess.TimeoutExpired) as e:
        return None, str(e)
    return r.returncode, r.stdout + r.stderr


def nobody_available():
    rc, out = as_nobody("import os; print(os.geteuid())")
    ok = rc == 0 and out.strip() == "65534"
    check(ok, "a second user is available (setpriv to nobody; tests run as root): " + out.strip())
    return ok

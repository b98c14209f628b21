"""Shared by the control-socket security tests (tests/security/ctl/): start `ladderjit serve`,
run commands as another user, raw control-socket and Modbus clients, and failure collection.
A part that needs a second user and cannot get one FAILS (never skips)."""
import os
import re
import socket
import subprocess
import sys
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
ADD D30 1 D30
1END
LDT
MOV 1 D20
2END
"""


def check(cond, what):
    print(("ok:   " if cond else "FAIL: ") + what, flush=True)
    if not cond:
        FAILURES.append(what)


def finish():
    print("%d failures" % len(FAILURES), flush=True)
    return 1 if FAILURES else 0


def run(*args, env=None, timeout=60):
    r = subprocess.run([LJ, *args], capture_output=True, timeout=timeout, env=env)
    return r.returncode, r.stdout.decode(errors="replace"), r.stderr.decode(errors="replace")


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

"""Issue 11 finding 7: the control socket has real access control. serve started under umask 000
makes a private 0700 runtime directory and a 0600 socket; another local user (nobody) can neither
write nor stop the PLC, not even when the modes are loosened (SO_PEERCRED); `monitor` refuses a
socket, or a server, of another user and never picks a /tmp/ladderjit-*.sock; a planted runtime
directory (another owner, a symlink) stops serve with an error instead of being used."""
import json
import os
import shutil
import socket
import stat
import sys
import tempfile
import time

from ctl_common import (PROGRAM, as_nobody, check, control, finish, nobody_available, output,
                        run, start_serve, stop_serve)

NOBODY = 65534

NOBODY_CLIENT = """
import json, socket, sys
for req in ({"cmd": "write", "writes": ["D5=77"]}, {"cmd": "stop"}):
    s = socket.socket(socket.AF_UNIX)
    s.settimeout(5)
    try:
        s.connect(sys.argv[1] if len(sys.argv) > 1 else %r)
        s.sendall((json.dumps(req) + "\\n").encode())
        ans = s.recv(4096)
        print("answer", req["cmd"], ans.decode(errors="replace").strip())
    except OSError as e:
        print("refused", req["cmd"], type(e).__name__)
    finally:
        s.close()
"""

FAKE_SERVER = """
import os, socket, sys
path, log = %r, %r
s = socket.socket(socket.AF_UNIX)
s.bind(path)
s.listen(4)
s.settimeout(20)
while True:
    try:
        c, _ = s.accept()
    except OSError:
        break
    c.settimeout(2)
    try:
        data = c.recv(4096)
    except OSError:
        data = b""
    with open(log, "ab") as f:
        f.write(data)
    try:
        c.sendall(b'{"ok":true,"tick":1,"values":[1234]}\\n')
    except OSError:
        pass
    c.close()
"""


def env_with(runtime_dir):
    e = dict(os.environ)
    e["LADDERJIT_RUNTIME_DIR"] = runtime_dir
    return e


def wait_for(path, seconds=10):
    end = time.time() + seconds
    while time.time() < end and not os.path.exists(path):
        time.sleep(0.05)
    return os.path.exists(path)


def nobody_attacks(proc, sock, what):
    rc, out = as_nobody(NOBODY_CLIENT % sock)
    lines = out.strip().splitlines()
    refused = rc == 0 and len(lines) == 2 and all(
        l.startswith("refused") or ('"ok":false' in l and "permission denied" in l) for l in lines)
    check(refused, what + ": nobody's write and stop are refused: " + out.strip())
    time.sleep(0.3)
    rc, val, _ = run("monitor", "--control", sock, "read", "D5", "D10")
    check(proc.poll() is None and val.split() == ["D5=0", "D10=7"],
          what + ": the PLC keeps running and D5 was not written: %r" % val)


def main():
    if not nobody_available():
        return finish()
    tmp = tempfile.mkdtemp(prefix="lj-ctl-acc-")
    os.chmod(tmp, 0o711)  # nobody may traverse it; the runtime dir inside is serve's own
    prog = os.path.join(tmp, "p.stl")
    with open(prog, "w") as f:
        f.write(PROGRAM)
    os.chmod(prog, 0o644)
    rundir = os.path.join(tmp, "run")

    # 1. umask 000, default socket path: a private directory and a 0600 socket.
    proc, sock, out = start_serve([prog, "--duration", "120"], env=env_with(rundir), umask=0,
                                  out_path=os.path.join(tmp, "serve.out"))
    check(sock is not None and os.path.dirname(sock) == rundir,
          "the default socket is in the private runtime directory: %s" % sock)
    if sock is None:
        print(output(out))
        proc.kill()
        return finish()
    st, dt = os.lstat(sock), os.lstat(os.path.dirname(sock))
    check(stat.S_ISSOCK(st.st_mode) and stat.S_IMODE(st.st_mode) == 0o600 and st.st_uid == 0,
          "socket mode 0600 owned by root under umask 000: %o" % stat.S_IMODE(st.st_mode))
    check(stat.S_ISDIR(dt.st_mode) and stat.S_IMODE(dt.st_mode) == 0o700 and dt.st_uid == 0,
          "runtime directory mode 0700 owned by root: %o" % stat.S_IMODE(dt.st_mode))
    end = time.time() + 30
    while time.time() < end and run("monitor", "--control", sock, "read", "D10")[1].strip() != "D10=7":
        time.sleep(0.05)
    rc, val, err = run("monitor", "read", "D10", env=env_with(rundir))
    check(rc == 0 and val.strip() == "D10=7",
          "monitor without --control finds the server in the runtime directory: %r %s" % (val, err))
    nobody_attacks(proc, sock, "modes as created")

    # 2. Modes loosened (an operator's chmod): SO_PEERCRED still refuses nobody.
    os.chmod(rundir, 0o755)
    os.chmod(sock, 0o666)
    nobody_attacks(proc, sock, "socket 0666 in a 0755 directory")
    os.chmod(rundir, 0o700)

    # 3. A fake server of another user: refused before any request is sent.
    fake_dir = os.path.join(tmp, "fake")
    os.mkdir(fake_dir)
    os.chown(fake_dir, NOBODY, NOBODY)
    fake, log = os.path.join(fake_dir, "f.sock"), os.path.join(fake_dir, "got")
    import subprocess
    srv = subprocess.Popen(["setpriv", "--reuid=nobody", "--regid=nogroup", "--clear-groups",
                            sys.executable, "-c", FAKE_SERVER % (fake, log)])
    check(wait_for(fake), "nobody's fake server is up")
    rc, o, err = run("monitor", "--control", fake, "write", "D5=1")
    check(rc == 2 and "refusing" in err, "monitor refuses a socket of another user: " + err.strip())
    rc, o, err = run("monitor", "--control", fake, "read", "D5")
    check(rc == 2 and "D5=1234" not in o, "no forged value is read from it: %r %s" % (o, err))
    # The same fake at the old predictable path: monitor never globs /tmp.
    old_style = "/tmp/ladderjit-%d.sock" % (900000 + os.getpid() % 90000)
    srv2 = subprocess.Popen(["setpriv", "--reuid=nobody", "--regid=nogroup", "--clear-groups",
                             sys.executable, "-c", FAKE_SERVER % (old_style, log)])
    check(wait_for(old_style), "nobody's fake server at %s is up" % old_style)
    rc, o, err = run("monitor", "write", "D5=1", env=env_with(os.path.join(tmp, "none")))
    check(rc == 2 and "no running server" in err,
          "monitor without --control ignores /tmp/ladderjit-*.sock: rc %s %s" % (rc, err.strip()))
    got = open(log, "rb").read() if os.path.exists(log) else b""
    check(got == b"", "the fake servers received nothing: %r" % got[:200])

    # 4. A root-owned socket file served by a process of another user: SO_PEERCRED on the
    #    client side refuses it (the file check alone would pass).
    trap_dir = os.path.join(tmp, "trap")
    os.mkdir(trap_dir, 0o700)
    trap = os.path.join(trap_dir, "t.sock")
    ls = socket.socket(socket.AF_UNIX)
    ls.bind(trap)
    pid = os.fork()
    if pid == 0:  # the listener drops to nobody before listen(): its credentials are nobody's
        try:
            os.setgid(NOBODY)
            os.setuid(NOBODY)
            ls.listen(4)
            ls.settimeout(10)
            c, _ = ls.accept()
            c.settimeout(5)
            data = c.recv(4096)
            os._exit(3 if data else 4)
        except BaseException:
            os._exit(5)
    ls.close()
    time.sleep(0.3)
    rc, o, err = run("monitor", "--control", trap, "write", "D5=1")
    check(rc == 2 and "runs as uid 65534" in err,
          "monitor refuses a server process of another user (SO_PEERCRED): " + err.strip())
    _, status = os.waitpid(pid, 0)
    check(os.WEXITSTATUS(status) == 4, "that server received no request (exit %d)"
          % os.WEXITSTATUS(status))

    # 5. Planted runtime directories stop serve with an error naming them.
    pub = os.path.join(tmp, "pub")
    os.mkdir(pub)
    os.chmod(pub, 0o1777)
    planted = os.path.join(pub, "planted")
    as_nobody("import os; os.mkdir(%r, 0o777); os.chmod(%r, 0o777)" % (planted, planted))
    rc, o, err = run("serve", prog, "--duration", "1", env=env_with(planted))
    check(rc == 2 and "belongs to uid 65534" in err,
          "a runtime directory of another user is refused: rc %s %s" % (rc, err.strip()))
    real = os.path.join(tmp, "real")
    os.mkdir(real, 0o700)
    link = os.path.join(tmp, "link")
    os.symlink(real, link)
    rc, o, err = run("serve", prog, "--duration", "1", env=env_with(link))
    check(rc == 2 and "symlink" in err, "a symlinked runtime directory is refused: rc %s %s"
          % (rc, err.strip()))

    rc = stop_serve(proc, sock)
    check(rc == 0 and "monitor stop" in output(out), "root's monitor stop still works (rc %s)" % rc)
    for p in (srv, srv2):
        p.kill()
        p.wait()
    for p in (old_style,):
        if os.path.exists(p):
            os.unlink(p)
    shutil.rmtree(tmp)
    return finish()


if __name__ == "__main__":
    sys.exit(main())

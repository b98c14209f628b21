#!/usr/bin/env python3
"""Issue 28 finding 10: small ones, each a clear error.

Expected (the issue's rule "bad input never crashes: a clear error naming the problem";
CLI.md: usage errors exit 2, program errors exit 1 as `file:line:col: error: text`):
- a value quoted in an error of --set, --stimulus, --params, --watch, --modbus-map or
  `monitor write` never echoes a raw control byte: it is written as \\xNN;
- `run --period-ms 0` is a usage error (PLC1 needs a period of at least 1 ms);
- X0.99999999999999999999 is "bit number out of range", never "bit number 1099511627776";
- a program whose lines end with a CR alone gets an error saying so, not "LD takes 1 operand,
  got 3";
- `--plc2-nvalue 4294967296` names the accepted range, not a bare "Could not convert";
- `monitor` on a socket it may not open (EACCES) does not ask "is serve running?";
- a control request with a key given twice is refused;
- a Modbus request with function code >= 0x80 is answered with exception 01 and fc | 0x80, not
  `03 01` (which reads as an FC3 reply);
- an edit of the symbol table of a FANUC ladder JSON is refused (exit 1), not ignored;
- `bench` does not create a signing key pair in the user's key directory."""
import json
import os
import shutil
import socket
import struct
import subprocess
import tempfile
import time

from sec_util import LJ, PROGRAM, Server, check, finish, run, write

ESC = "\x1b[2J\x07"  # clear-screen sequence and a bell


def clean(err):
    """No raw control byte other than the line ends, and the escape shown as \\x1B."""
    raw = [c for c in err if ord(c) < 0x20 and c not in "\n"]
    return not raw and "\\x1B" in err


def free_port():
    s = socket.socket()
    s.bind(("127.0.0.1", 0))
    port = s.getsockname()[1]
    s.close()
    return port


def main():
    tmp = tempfile.mkdtemp(prefix="ljsec-small-")
    os.chmod(tmp, 0o755)
    prog = os.path.join(tmp, "p.stl")
    write(prog, PROGRAM, age=10)

    # --- escape bytes in value errors ---
    rc, _, err = run("run", prog, "--engine", "interp", "--set", "D0=1" + ESC)
    check(rc == 2 and clean(err), "--set: exit 2, control bytes escaped: " + repr(err))
    rc, _, err = run("run", prog, "--engine", "interp", "--watch", "D0" + ESC)
    check(rc == 2 and clean(err), "--watch: exit 2, control bytes escaped: " + repr(err))
    stim = os.path.join(tmp, "bad.stim")
    write(stim, "@0 D0=" + ESC + "\n")
    rc, _, err = run("run", prog, "--engine", "interp", "--stimulus", stim)
    check(rc == 2 and clean(err), "--stimulus: exit 2, control bytes escaped: " + repr(err))
    params = os.path.join(tmp, "bad.params")
    write(params, "P1=" + ESC + "\n")
    rc, _, err = run("run", prog, "--engine", "interp", "--params", params)
    check(rc == 2 and clean(err), "--params: exit 2, control bytes escaped: " + repr(err))
    mbmap = os.path.join(tmp, "bad.map")
    write(mbmap, "holding 0 D0" + ESC + "\n")
    rc, _, err = run("serve", prog, "--engine", "interp", "--modbus", str(free_port()),
                     "--modbus-map", mbmap, "--control", os.path.join(tmp, "m.sock"),
                     "--duration", "1", timeout=30)
    check(rc == 2 and clean(err), "--modbus-map: exit 2, control bytes escaped: " + repr(err))

    # --- numbers and line ends ---
    rc, _, err = run("run", prog, "--engine", "interp", "--period-ms", "0")
    check(rc == 2 and "--period-ms" in err, "run --period-ms 0: exit 2 naming it: " + err)
    big = os.path.join(tmp, "bigbit.stl")
    write(big, "LD X0.99999999999999999999\nOUT Y0.0\n1END\n2END\n")
    rc, _, err = run("check", big)
    check(rc == 1 and "bit number out of range" in err and "1099511627776" not in err,
          "X0.99999999999999999999: bit number out of range, no 2^40: " + err)
    cr = os.path.join(tmp, "cr.stl")
    write(cr, "LD X0.0\rOUT Y0.0\r1END\r2END\r")
    rc, _, err = run("check", cr)
    check(rc == 1 and "carriage return" in err and "takes 1 operand" not in err
          and err.startswith(cr + ":1:8: error:"), "CR-only lines: a clear error: " + err)
    rc, _, err = run("run", prog, "--engine", "interp", "--plc2-nvalue", "4294967296")
    check(rc == 2 and "2147483647" in err and "4294967296" in err,
          "--plc2-nvalue 4294967296: exit 2 naming the range: " + err)

    # --- monitor on a socket it may not open ---
    sockdir = os.path.join(tmp, "sockdir")
    os.mkdir(sockdir, 0o755)
    spath = os.path.join(sockdir, "c.sock")
    s = socket.socket(socket.AF_UNIX)
    s.bind(spath)
    s.listen(1)
    os.chmod(spath, 0o600)
    try:
        r = subprocess.run([LJ, "monitor", "--control", spath, "stats"], capture_output=True,
                           text=True, timeout=30,
                           preexec_fn=lambda: (os.setgid(65534), os.setuid(65534)))
        check(r.returncode == 2 and "Permission denied" in r.stderr
              and "serve` running" not in r.stderr,
              "monitor on EACCES does not ask whether serve runs: " + r.stderr)
    finally:
        s.close()

    # --- a live server: duplicate keys, monitor write, Modbus fc >= 0x80 ---
    port = free_port()
    sock = os.path.join(tmp, "c.sock")
    srv = Server(prog, "--engine", "interp", "--control", sock, "--modbus", f"127.0.0.1:{port}",
                 "--duration", "60")
    check(srv.started(), "serve starts")
    c = socket.socket(socket.AF_UNIX)
    c.settimeout(10)
    c.connect(sock)
    c.sendall(b'{"cmd":"write","writes":["D50=1"],"writes":["D50=2"]}\n')
    buf = b""
    while not buf.endswith(b"\n"):
        chunk = c.recv(4096)
        if not chunk:
            break
        buf += chunk
    c.close()
    resp = json.loads(buf or b"{}")
    check(resp.get("ok") is False and "more than once" in resp.get("error", ""),
          "a request with a key twice is refused: " + buf.decode(errors="replace").strip())
    rc, _, err = srv.monitor("write", "D0=1" + ESC)
    check(rc == 2 and clean(err), "monitor write: exit 2, control bytes escaped: " + repr(err))
    m = socket.create_connection(("127.0.0.1", port), timeout=10)
    for fc in (0x83, 0xFF):
        m.sendall(struct.pack(">HHHBB", 0x1234, 0, 6, 1, fc) + b"\x00\x00\x00\x01")
        rsp = b""
        end = time.time() + 5
        while len(rsp) < 9 and time.time() < end:
            chunk = m.recv(64)
            if not chunk:
                break
            rsp += chunk
        check(rsp == struct.pack(">HHHBBB", 0x1234, 0, 3, 1, fc, 1),
              f"Modbus fc 0x{fc:02X}: exception 01 with fc 0x{fc:02X}, got {rsp.hex(' ')}")
    m.close()
    srv.stop()

    # --- the symbol table of a FANUC ladder JSON ---
    pmc = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "examples",
                       "fanuc_coolant.pmc")
    rc, out, err = run("ladder", pmc, "--format", "json")
    check(rc == 0, "ladder --format json of a FANUC program: " + err)
    if rc == 0:
        j = json.loads(out)
        j["symbols"][0]["address"] = "X0.7"
        edited = os.path.join(tmp, "edited.json")
        write(edited, json.dumps(j))
        rc, _, err = run("check", edited)
        check(rc == 1 and "symbols[0]" in err and "X0.7" in err,
              "an edited symbol table of a FANUC ladder JSON is refused: " + err)

    # --- bench and the user's key directory ---
    home = os.path.join(tmp, "home")
    os.mkdir(home)
    env = {k: v for k, v in os.environ.items() if k not in ("LADDERJIT_KEY_DIR",
                                                             "XDG_CONFIG_HOME")}
    env["HOME"] = home
    r = subprocess.run([LJ, "bench", prog, "--engine", "aot", "--scans", "5"],
                       capture_output=True, text=True, timeout=300, env=env)
    check(r.returncode == 0, "bench --engine aot runs: " + r.stderr[-300:])
    check(not os.path.exists(os.path.join(home, ".config", "ladderjit")),
          "bench created no key pair in ~/.config/ladderjit: " + str(os.listdir(home)))
    shutil.rmtree(tmp, ignore_errors=True)
    return finish("small_errors")


if __name__ == "__main__":
    raise SystemExit(main())

"""Issue 11 finding 3: no request may abort `ladderjit serve`. User bytes that are not UTF-8 (the
served program's path in `monitor stats`, a loaded file whose first line or tokens are not
UTF-8, raw request lines) must give JSON answers, and the server keeps running."""
import json
import os
import shutil
import sys
import tempfile
import time

from ctl_common import (LJ, PROGRAM, check, control, finish, output, run, start_serve,
                        stop_serve)


def alive(proc, sock, what):
    rc, out, _ = run("monitor", "--control", sock, "read", "D10")
    check(proc.poll() is None and rc == 0 and out.strip() == "D10=7",
          what + ": serve still runs and answers (D10=7): rc %s %r" % (rc, out))


def main():
    tmp = tempfile.mkdtemp(prefix="lj-ctl-json-")
    prog = os.path.join(tmp.encode(), b"prog\xff\xfe.stl")  # a path that is not UTF-8
    with open(prog, "w") as f:
        f.write(PROGRAM)
    sock = os.path.join(tmp, "c.sock")
    stats = os.path.join(tmp, "stats.json")
    proc, got, out = start_serve([prog, "--control", sock, "--duration", "120", "--stats", stats],
                                 out_path=os.path.join(tmp, "serve.out"))
    check(got == sock, "serve started: " + output(out))
    if got != sock:
        proc.kill()
        return finish()
    end = time.time() + 30
    while time.time() < end and run("monitor", "--control", sock, "read", "D10")[1].strip() != "D10=7":
        time.sleep(0.05)

    rc, text, err = run("monitor", "--control", sock, "stats")
    check(rc == 0 and "prog\ufffd\ufffd.stl" in text,
          "monitor stats with a non-UTF-8 program path answers (U+FFFD for the bad bytes): rc %s %s"
          % (rc, err.strip()))
    alive(proc, sock, "after stats")

    # Files whose bytes are not UTF-8, loaded online: refused with an error, never fatal.
    bodies = {
        "bad_first_line.dit": b"ladderjit-plc-dit \xff\xfe\nhash = sha256:00\n",
        "bad_magic.dit": b"ladderjit-plc-dit 1\xc3\n",
        "bad_token.stl": b"\xff\xfe\xfd X0.0\nOUT Y0.0\n",
        "bad_symbol.stl": b"LD X0.0\nOUT \xe4\xb8\n",
        "bad_comment.stl": b"LDT ; \xc0\xaf overlong\nMOV 7 D10\nIEND\n\x80\n",
    }
    for name, body in bodies.items():
        p = os.path.join(tmp, name)
        with open(p, "wb") as f:
            f.write(body)
        rc, _, err = run("monitor", "--control", sock, "load", p)
        check(rc == 2 and "error" in err, "load %s is refused with an error: %s" % (name, err.strip()))
        alive(proc, sock, "after load " + name)

    # monitor itself refuses a load path it cannot put into JSON, instead of aborting.
    bad = os.path.join(tmp.encode(), b"v\xff.stl")
    with open(bad, "w") as f:
        f.write(PROGRAM)
    rc, _, err = run("monitor", "--control", sock, "load", bad)
    check(rc == 2 and "not valid UTF-8" in err, "monitor load of a non-UTF-8 path: exit 2: %s"
          % err.strip())

    # Raw request lines: invalid UTF-8, wrong types, deep nesting; each gets a JSON answer.
    for line in [b'{"cmd":"read","addrs":["\xff"]}\n', b"\xff\xfe\n", b'{"cmd":5}\n',
                 b'{"cmd":"force","line":1e400,"mode":"on"}\n', b'{"cmd":"lock","item":7}\n',
                 b'{"cmd":"load","program":["x"]}\n', b"[" * 100000 + b"\n",
                 b'{"cmd":"write","writes":["D5=99999999999999999999"]}\n']:
        ans = control(sock, line)
        try:
            j = json.loads(ans)
        except ValueError:
            j = None
        check(isinstance(j, dict) and j.get("ok") is False,
              "raw request %r answered with an error: %r" % (line[:40], ans[:120]))
    alive(proc, sock, "after raw requests")

    rc = stop_serve(proc, sock)
    check(rc == 0, "serve exits 0 after monitor stop (rc %s): %s" % (rc, output(out)[-400:]))
    try:
        with open(stats, encoding="utf-8") as f:
            j = json.load(f)
        ok = j.get("program", "").endswith("prog\ufffd\ufffd.stl")
    except (OSError, ValueError) as e:
        ok = False
        print(e)
    check(ok, "--stats is written as valid UTF-8 JSON with U+FFFD in the program path")
    shutil.rmtree(tmp)
    return finish()


if __name__ == "__main__":
    sys.exit(main())

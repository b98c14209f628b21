#!/usr/bin/env python3
"""End-to-end test of `ladderjit serve PROGRAM --engine aot:PATH.so` (docs/serve.md "AOT"): the
.so must be built from PROGRAM (io/AotLoader), forcing is refused (it needs recompilation),
online change by `monitor load PROGRAM PATH.so` / `load PATH.so` and by a rebuilt .so on disk
(hnc8-core.md 6.2 RESOLUTION: init runs again, state kept), and a bad .so leaves the old
program running. The .so files are built here with `ladderjit compile`.

Values are polled until they show up (bounded by a generous deadline)."""
import json, os
import shutil
import subprocess
import sys
import tempfile
import time

from serve_client import FAILURES, LINE_LD_X10, LJ, PROGRAM, check, monitor, read, run, wait_value


def version(d10):
    return PROGRAM.replace("MOV 7 D10", f"MOV {d10} D10")


def write(path, text):
    with open(path, "w") as f:
        f.write(text)


def compile_so(stl, so):
    rc, _, err = run("compile", stl, "-o", so)
    check(rc == 0, f"ladderjit compile {stl}: {err}")


def main():
    tmp = tempfile.mkdtemp(prefix="ljserveaot-")
    # compile's default signing key pair, trusted by serve (docs/aot.md "Trust"): never ~/.config
    os.environ["LADDERJIT_KEY_DIR"] = os.path.join(tmp, "keys")
    p = os.path.join(tmp, "p.stl")
    v2 = os.path.join(tmp, "v2.stl")
    write(p, version(7))
    write(v2, version(9))
    p_so, v2_so = os.path.join(tmp, "p.so"), os.path.join(tmp, "v2.so")
    compile_so(p, p_so)
    compile_so(v2, v2_so)
    damaged = os.path.join(tmp, "damaged.so")
    with open(v2_so, "rb") as f:
        data = bytearray(f.read())
    data[len(data) // 2] ^= 0xFF  # one flipped byte: the signature no longer matches
    with open(damaged, "wb") as f:
        f.write(data)
    sock = os.path.join(tmp, "c.sock")
    # A .so of the right program signed by a key serve does not trust (docs/aot.md "Trust").
    other = os.path.join(tmp, "other")
    rc, _, err = run("keygen", "-o", other)
    check(rc == 0, "keygen: " + err)
    untrusted_so = os.path.join(tmp, "untrusted.so")
    rc, _, err = run("compile", v2, "-o", untrusted_so, "--sign-key", other + ".key")
    check(rc == 0, "compile --sign-key: " + err)

    # Start-up problems are usage errors (exit 2) before anything runs.
    rc, _, err = run("serve", p, "--engine", "aot:" + v2_so, "--duration", "1")
    check(rc == 2 and "another program" in err, "a .so of another program is refused: " + err)
    rc, _, err = run("serve", p, "--engine", "aot:" + p_so, "--trust-key", other + ".pub",
                     "--duration", "1")
    check(rc == 2 and "not a trusted key" in err, "a .so of an untrusted signer is refused: " + err)
    rc, _, err = run("serve", p, "--engine", "aot:", "--duration", "1")
    check(rc == 2 and "needs a path" in err, "--engine aot: without a path: " + err)
    rc, _, err = run("serve", p, "--engine", "aot:" + os.path.join(tmp, "none.so"))
    check(rc == 2 and "none.so" in err, "a missing .so is named: " + err)

    srv = subprocess.Popen([LJ, "serve", p, "--engine", "aot:" + p_so, "--control", sock,
                            "--duration", "240", "--watch-file"], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                           text=True)
    head = srv.stdout.readline()
    check("engine aot:" in head, "serve announces the AOT engine: " + head)

    check(wait_value(sock, "D10", 7), "init ran at start (D10 = 7)")
    rc, _, _ = monitor(sock, "write", "X1.0=1", "B5=1234")
    check(rc == 0, "write accepted")
    check(wait_value(sock, "Y1.0", 1), "the .so's PLC1 runs: Y1.0 follows X1.0")

    # A force on an AOT server runs forced JIT code of the same program until the last force is
    # restored, then the .so again; neither switch runs init (D10 was set to 7 by init: write 8).
    rc, _, _ = monitor(sock, "write", "D10=8")
    check(rc == 0, "write D10=8")
    rc, out, err = monitor(sock, "force", f"line:{LINE_LD_X10}", "off")
    check(rc == 0 and "forced off" in out, "force on an AOT server: " + out + err)
    check(wait_value(sock, "Y1.0", 0), "the forced contact is off: Y1.0 = 0 with X1.0 = 1")
    rc, out, err = monitor(sock, "force", f"line:{LINE_LD_X10}", "restore")
    check(rc == 0, "restore: " + out + err)
    check(wait_value(sock, "Y1.0", 1), "restored: Y1.0 follows X1.0 again")
    check(read(sock, "D10") == 8, "no init ran for the force or the restore (D10 = 8)")
    rc, out, _ = monitor(sock, "stats")
    st = json.loads(out)
    check(rc == 0 and st["swaps"] == 0 and st["rebuilds"] == 2 and st["program"]["version"] == 1,
          "force and restore are rebuilds of version 1, not online changes: swaps %s rebuilds %s"
          % (st.get("swaps"), st.get("rebuilds")))
    rc, _, _ = monitor(sock, "write", "D10=7")

    rc, _, err = monitor(sock, "load", v2)
    check(rc == 2 and ".so" in err, "load without a .so is refused: " + err)
    rc, _, err = monitor(sock, "load", v2, p_so)
    check(rc == 2 and "another program" in err, "a .so of another program is refused: " + err)
    rc, _, err = monitor(sock, "load", v2, damaged)
    check(rc == 2 and "bad signature" in err, "a damaged .so is refused: " + err)
    rc, _, err = monitor(sock, "load", v2, untrusted_so)
    check(rc == 2 and "not a trusted key" in err, "monitor load of an untrusted .so: " + err)
    check(read(sock, "D10") == 7, "the old program keeps running (D10 = 7)")

    rc, out, err = monitor(sock, "load", v2, v2_so)
    check(rc == 0 and "running version 2" in out, "load PROGRAM PATH.so: " + out + err)
    check(wait_value(sock, "D10", 9), "the new init part ran (D10 = 9)")
    check(read(sock, "B5") == 1234, "B5 kept across the online change")
    check(wait_value(sock, "Y1.0", 1), "inputs kept: Y1.0 = X1.0 = 1")

    # `load PATH.so` pairs the .so with the served PROGRAM (now v2.stl): p.so does not fit it.
    rc, _, err = monitor(sock, "load", p_so)
    check(rc == 2 and "another program" in err, "load PATH.so checks the served PROGRAM: " + err)

    # A file change: editing v2.stl alone makes v2.so stale (refused, logged, old one runs);
    # rebuilding v2.so then swaps the new version in.
    time.sleep(1.1)  # a different mtime even on coarse-timestamp file systems
    write(v2, version(11))
    time.sleep(2.5)  # the server polls once a second
    check(read(sock, "D10") == 9, "a PROGRAM edit without a rebuilt .so changes nothing")
    compile_so(v2, v2_so)
    check(wait_value(sock, "D10", 11, seconds=60), "a rebuilt .so on disk is swapped in")

    write(v2, version(13))  # mtime differs from the last look (>1 s after the edit above)
    v13_so = os.path.join(tmp, "v13.so")
    compile_so(v2, v13_so)
    rc, out, err = monitor(sock, "load", v13_so)
    check(rc == 0, "load PATH.so for the served PROGRAM: " + out + err)
    check(wait_value(sock, "D10", 13), "its init part ran (D10 = 13)")

    rc, _, _ = monitor(sock, "stop")
    check(rc == 0, "stop accepted")
    try:
        out, err = srv.communicate(timeout=60)
    except subprocess.TimeoutExpired:
        srv.kill()
        out, err = srv.communicate()
        check(False, "serve did not stop")
    check(srv.returncode == 0, f"serve exits 0 (got {srv.returncode}): {err}")
    check("refused" in err and "damaged" in err, "refusals are logged: " + err[-400:])

    shutil.rmtree(tmp, ignore_errors=True)
    if FAILURES:
        print(f"{len(FAILURES)} failure(s)")
        return 1
    print("serve --engine aot end-to-end: all checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())

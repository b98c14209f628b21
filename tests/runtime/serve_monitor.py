#!/usr/bin/env python3
"""End-to-end test of `ladderjit serve` and `ladderjit monitor` (docs/serve.md): reads, writes,
forcing (hnc8-core.md 6.1 RESOLUTION (a)), the lock list (RESOLUTION (b)), online change by
command and by file change (6.2 RESOLUTION: init runs again, state kept), a refused program,
usage errors (exit 2) and a clean stop with the statistics file.

Values are polled until they show up (bounded by a generous deadline): the test asserts what
the server must do, never how fast."""
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time

from serve_client import FAILURES, LINE_LD_X10, LJ, PROGRAM, check, monitor, read, wait_value

LINE_OUT = 5  # OUT Y1.0: not a contact
V2 = PROGRAM.replace("MOV 7 D10", "MOV 9 D10")
V3 = PROGRAM.replace("MOV 7 D10", "MOV 11 D10")


def main():
    tmp = tempfile.mkdtemp(prefix="ljserve-")
    prog = os.path.join(tmp, "p.stl")
    with open(prog, "w") as f:
        f.write(PROGRAM)
    v2 = os.path.join(tmp, "v2.stl")
    with open(v2, "w") as f:
        f.write(V2)
    bad = os.path.join(tmp, "bad.stl")
    with open(bad, "w") as f:
        f.write("LD X1.0\nOUT\n")
    sock = os.path.join(tmp, "c.sock")
    stats = os.path.join(tmp, "stats.json")

    srv = subprocess.Popen([LJ, "serve", prog, "--control", sock, "--duration", "240", "--stats",
                            stats, "--watch-file"], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    line = srv.stdout.readline() + srv.stdout.readline()
    check("control socket " + sock in line, "serve announces its control socket: " + line)

    check(wait_value(sock, "D10", 7), "init ran at start (D10 = 7)")
    check(wait_value(sock, "D20", 1), "PLC1 runs (D20 = 1)")

    rc, _, _ = monitor(sock, "write", "X1.0=1", "B5=1234")
    check(rc == 0, "write accepted")
    check(wait_value(sock, "Y1.0", 1), "Y1.0 follows X1.0 = 1")

    # A force is not an online change (issue 28 finding 1): init (D10 = 7) never runs for one.
    rc, _, _ = monitor(sock, "write", "D10=8")
    check(rc == 0, "write D10=8")
    # line:N is the alias of the older LINE form; the answer names the statement id.
    rc, out, _ = monitor(sock, "force", f"line:{LINE_LD_X10}", "off")
    check(rc == 0 and f"line {LINE_LD_X10} forced off" in out, "force off accepted: " + out)
    check(wait_value(sock, "Y1.0", 0), "forced off (禁止): Y1.0 = 0 although X1.0 = 1")
    rc, _, err = monitor(sock, "force", f"line:{LINE_OUT}", "on")
    check(rc == 2 and "not a contact" in err, "forcing a coil is refused: " + err)
    rc, _, err = monitor(sock, "force", "line:1000", "on")
    check(rc == 2 and "no statement" in err, "forcing an empty line is refused: " + err)
    rc, _, err = monitor(sock, "force", "1000", "on")
    check(rc == 2 and "statement id 1000 does not exist" in err, "unknown id refused: " + err)
    ids = [w for w in out.split() if w.isdigit()]
    stmt_id = ids[0] if ids else "?"
    rc, out, _ = monitor(sock, "force", stmt_id, "restore")  # by statement id
    check(rc == 0 and "no forced contacts" in out, "restore by id accepted: " + out)
    check(wait_value(sock, "Y1.0", 1), "restored (恢复): Y1.0 = X1.0 = 1 again")
    rc, out, _ = monitor(sock, "force", f"id:{stmt_id}", "off")
    check(rc == 0 and f"id {stmt_id} line {LINE_LD_X10} forced off" in out, "force by id: " + out)
    check(wait_value(sock, "Y1.0", 0), "forced off by id")
    rc, out, _ = monitor(sock, "force", f"line:{LINE_LD_X10}", "restore")
    check(rc == 0 and "no forced contacts" in out, "restore by line accepted: " + out)
    check(wait_value(sock, "Y1.0", 1), "restored again")
    check(read(sock, "D10") == 8, "four forces and restores ran no init (D10 = 8, not 7)")
    rc, _, _ = monitor(sock, "write", "D10=7")

    rc, out, _ = monitor(sock, "lock", "D20=55")
    check(rc == 0 and "D20=55" in out, "lock accepted")
    check(wait_value(sock, "D20", 55), "locked D20 reads 55 although the program writes 1")
    rc, out, _ = monitor(sock, "locks")
    check(rc == 0 and out.strip() == "D20=55", "locks lists D20=55: " + out)
    rc, _, _ = monitor(sock, "unlock", "D20")
    check(rc == 0, "unlock accepted")
    check(wait_value(sock, "D20", 1), "unlocked D20 is the program's 1 again")
    rc, _, err = monitor(sock, "unlock", "D20")
    check(rc == 2 and "not locked" in err, "unlocking twice is an error: " + err)

    rc, _, err = monitor(sock, "load", bad)
    check(rc == 2 and "bad.stl:2" in err, "a program with errors is refused, located: " + err)
    check(wait_value(sock, "D10", 7), "the old program keeps running")

    fake_so = os.path.join(tmp, "v2.so")
    with open(fake_so, "w") as f:
        f.write("not looked at")
    rc, _, err = monitor(sock, "load", v2, fake_so)
    check(rc == 2 and "aot" in err, "a JIT server refuses a .so (it compiles PROGRAM): " + err)

    rc, out, _ = monitor(sock, "load", v2)
    check(rc == 0 and "running version" in out, "online change by command: " + out)
    check(wait_value(sock, "D10", 9), "the new init part ran (D10 = 9)")
    check(read(sock, "B5") == 1234, "B5 kept across the online change")
    check(wait_value(sock, "Y1.0", 1), "inputs kept: Y1.0 = X1.0 = 1")

    # The watched file is the one given to `load` last (v2.stl); change it on disk.
    time.sleep(1.1)  # a different mtime even on coarse-timestamp file systems
    with open(v2, "w") as f:
        f.write(V3)
    check(wait_value(sock, "D10", 11, seconds=60), "online change on file change (D10 = 11)")

    rc, _, err = monitor(sock, "read", "Q1")
    check(rc == 2 and "Q1" in err, "bad address: exit 2 naming it: " + err)
    rc, _, err = monitor(sock, "write", "T5=3")
    check(rc == 2, "timers are read-only: " + err)
    rc, _, err = monitor(sock, "frobnicate")
    check(rc == 2 and "unknown command" in err, "unknown command: " + err)
    r = subprocess.run([LJ, "monitor", "--control", os.path.join(tmp, "none.sock"), "stats"],
                       capture_output=True, text=True, timeout=60)
    check(r.returncode == 2 and "cannot connect" in r.stderr, "no server: exit 2: " + r.stderr)

    rc, out, _ = monitor(sock, "stats")
    st = json.loads(out) if rc == 0 else {}
    # Two online changes (load v2, the file change); the four forces and restores are rebuilds.
    check(st.get("swaps") == 2 and st.get("rebuilds") == 4,
          "stats count the online changes and the rebuilds apart: " + out[:300])

    rc, _, _ = monitor(sock, "stop")
    check(rc == 0, "stop accepted")
    try:
        out, err = srv.communicate(timeout=60)
    except subprocess.TimeoutExpired:
        srv.kill()
        out, err = srv.communicate()
        check(False, "serve did not stop")
    check(srv.returncode == 0, f"serve exits 0 (got {srv.returncode}): {err}")
    check("monitor stop" in out and "missed deadlines" in out, "summary printed: " + out)
    check(not os.path.exists(sock), "the socket file is removed")
    with open(stats) as f:
        js = json.load(f)
    for key in ("ticks", "overruns", "missed_deadlines", "scan", "jitter"):
        check(key in js, "stats file has " + key)
    check(js.get("ticks", 0) > 0, "ticks were counted")
    check(js["scan"]["count"] == js["ticks"], "one scan sample per tick")

    # Usage errors before anything runs.
    r = subprocess.run([LJ, "serve", prog, "--engine", "aot"], capture_output=True, text=True)
    check(r.returncode == 2, "serve --engine aot is a usage error")
    r = subprocess.run([LJ, "serve", bad, "--duration", "1"], capture_output=True, text=True)
    check(r.returncode == 1 and "bad.stl:2" in r.stderr, "serve of a bad program: exit 1")

    shutil.rmtree(tmp, ignore_errors=True)
    if FAILURES:
        print(f"{len(FAILURES)} failure(s)")
        return 1
    print("serve/monitor end-to-end: all checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
"""The signal trace of a real `ladderjit serve` driven by `ladderjit monitor trace`
(docs/trace.md): serve --trace FILE arms a rising-edge trigger on X1.0; `monitor write X1.0=1`
fires it; the saved CSV must hold pre + 1 + post rows around the trigger tick, one row per tick
that ran (D1 counts PLC1 executions: +1 per row), Y1.0 following X1.0; the saved VCD (--bits)
read back by sigrok-cli must hold the same values. Errors: a bad definition names its line,
save before any capture is refused, define/arm/trigger/stop change what status says.

usage: serve_trace.py LADDERJIT WORK_DIR
"""
import json
import os
import shutil
import subprocess
import sys
import time

PROGRAM = "LDT\nADD D1 1 D1\nLD X1.0\nOUT Y1.0\n1END\n2END\n"
DEFINITION = "signal D1, Y1.0, X1.0\ntrigger rising X1.0\npre 5\npost 20\n"


def main():
    ladderjit, work = sys.argv[1:3]
    sigrok = shutil.which("sigrok-cli")
    if not sigrok:
        print("FAIL: sigrok-cli is not installed (scripts/setup-test.sh)", file=sys.stderr)
        return 1
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(work)
    prog = os.path.join(work, "p.stl")
    open(prog, "w").write(PROGRAM)
    dfile = os.path.join(work, "t.trace")
    open(dfile, "w").write(DEFINITION)
    sock = os.path.join(work, "s.sock")
    serve = subprocess.Popen([ladderjit, "serve", prog, "--engine", "interp", "--control", sock,
                              "--trace", dfile, "--duration", "60"],
                             stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    failures = []

    def mon(*args, ok=True):
        p = subprocess.run([ladderjit, "monitor", "--control", sock] + list(args),
                           capture_output=True, text=True)
        if ok and p.returncode != 0:
            raise RuntimeError("monitor %s: %s" % (" ".join(args), p.stderr))
        return p

    def check(cond, msg):
        if not cond:
            failures.append(msg)
            print("FAIL: " + msg, file=sys.stderr)

    try:
        for _ in range(300):
            if os.path.exists(sock) and mon("trace", "status", ok=False).returncode == 0:
                break
            time.sleep(0.05)
        st = json.loads(mon("trace", "status").stdout)
        check(st["armed"] and st["state"] == "waiting", "armed by --trace: %s" % st)
        p = mon("trace", "save", os.path.join(work, "none.csv"), "--csv", ok=False)
        check(p.returncode == 2 and "no capture yet (waiting)" in p.stderr, p.stderr)
        time.sleep(0.1)
        mon("write", "X1.0=1")
        for _ in range(200):
            st = json.loads(mon("trace", "status").stdout)
            if st["captures"] == 1:
                break
            time.sleep(0.05)
        check(st["state"] == "done" and st["captures"] == 1, "one capture: %s" % st)
        csv = os.path.join(work, "c.csv")
        vcd = os.path.join(work, "c.vcd")
        out = mon("trace", "save", csv, "--csv").stdout
        check("26 ticks" in out, out)
        mon("trace", "save", vcd, "--bits")
        lines = open(csv).read().strip().split("\n")
        check(lines[0] == "tick,ms,D1,Y1.0,X1.0,trigger", lines[0])
        rows = [[int(x) for x in l.split(",")] for l in lines[1:]]
        check(len(rows) == 26, "pre 5 + trigger + post 20 rows, got %d" % len(rows))
        trig = [i for i, r in enumerate(rows) if r[5] == 1]
        check(trig == [5], "the trigger row is the 6th: %s" % trig)
        for i, r in enumerate(rows):
            check(r[4] == (1 if i >= 5 else 0), "X1.0 row %d: %s" % (i, r))
            check(r[3] == r[4], "Y1.0 follows X1.0, row %d: %s" % (i, r))
            check(r[1] == r[0], "ms = tick at 1 ms, row %d" % i)
            if i:
                check(r[0] > rows[i - 1][0], "tick numbers increase, row %d" % i)
                check(r[2] == rows[i - 1][2] + 1, "one row per tick that ran, row %d" % i)
        # sigrok-cli: samples from the first row's tick on, one per ms; a tick that did not run
        # (a missed deadline) keeps the previous row's value.
        s = subprocess.run([sigrok, "-i", vcd, "-O", "csv:label=channel:header=false:dedup=false"],
                           capture_output=True, text=True, check=True).stdout
        data = [l for l in s.split("\n") if l and not l.startswith((";", "META"))]
        header = data[0].split(",")
        samples = data[1:]
        first = rows[0][0]
        check(len(samples) == rows[-1][0] + 1 - first, "sigrok samples %d" % len(samples))
        for r in rows:
            cells = samples[r[0] - first].split(",")
            d1 = sum(int(cells[header.index("D1[%d]" % b)]) << b for b in range(32))
            check(d1 == r[2] and int(cells[header.index("X1.0")]) == r[4],
                  "sigrok at tick %d: D1 %d X1.0 %s, csv %s" % (r[0], d1,
                                                                cells[header.index("X1.0")], r))
        # A bad definition names its line; the old trace stays.
        bad = os.path.join(work, "bad.trace")
        open(bad, "w").write("signal D1\ntrigger D1 ~ 3\n")
        p = mon("trace", "define", bad, ok=False)
        check(p.returncode == 2 and "bad.trace:2: trigger:" in p.stderr, p.stderr)
        p = mon("trace", "define", os.path.join(work, "t.trace"))
        st = json.loads(mon("trace", "arm").stdout)
        check(st["armed"] and st["state"] == "waiting" and st["last_capture"]["capture"] == 1,
              "re-armed, last capture kept: %s" % st)
        mon("trace", "trigger")
        time.sleep(0.3)
        st = json.loads(mon("trace", "stop").stdout)
        check(not st["armed"] and st["state"] == "stopped" and st["captures"] == 1,
              "manual trigger captured, stopped: %s" % st)
        mon("stop")
        serve.wait(timeout=30)
        err = serve.stderr.read()
        check(serve.returncode == 0, "serve exit %s: %s" % (serve.returncode, err))
    finally:
        if serve.poll() is None:
            serve.kill()
            serve.wait()
    if failures:
        print("%d failure(s)" % len(failures), file=sys.stderr)
        return 1
    print("serve trace: capture of %d rows around tick %d checked" % (len(rows), rows[5][0]))
    return 0


if __name__ == "__main__":
    sys.exit(main())

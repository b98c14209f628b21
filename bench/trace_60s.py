#!/usr/bin/env python3
"""The signal trace's 60 s acceptance run (issue 32, docs/BENCHMARKS.md "Signal trace: 60 s of
serve"): serve the realistic 10k program at 1 ms for SECONDS (+ a start margin) twice in one
sitting, alternating, once without a trace and once with `serve --trace` of 64 addresses
(bits, bytes and words, `trigger immediate`, `pre 0`, `post SECONDS*1000-1`,
`mode single`: one capture of every tick of SECONDS). The capture is saved as CSV through
`monitor trace save` and checked: its tick numbers strictly increase (none twice), and the
ticks without a row (a deadline that passed entirely is never run, so it has no row,
docs/trace.md) are printed beside the missed deadlines serve counted in the window; then the scan's overruns and missed deadlines of both runs, which
the trace must not raise. Not a CTest test (timing; the ctests of runtime/SignalTrace check the
rows). Usage: bench/trace_60s.py BUILD_DIR WORK_DIR [SECONDS] [PAIRS]"""
import csv
import json
import os
import re
import subprocess
import sys
import time

build, work = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
seconds = int(sys.argv[3]) if len(sys.argv) > 3 else 60
pairs = int(sys.argv[4]) if len(sys.argv) > 4 else 1
lj = os.path.join(build, "tools", "ladderjit")
os.makedirs(work, exist_ok=True)
prog = os.path.join(work, "p10k.stl")
subprocess.run([os.path.join(build, "bench", "gen_realistic"), "10000", prog], check=True,
               stdout=subprocess.DEVNULL)
signals = (["X%d.%d" % (i // 8, i % 8) for i in range(16)] + ["Y%d.%d" % (i // 8, i % 8)
                                                               for i in range(16)] +
           ["R%d" % i for i in range(16)] + ["D%d" % i for i in range(16)])
assert len(signals) == 64
tdef = os.path.join(work, "t.trace")
with open(tdef, "w") as f:
    f.write("signal %s\ntrigger immediate\npre 0\npost %d\nmode single\n" %
            (", ".join(signals), seconds * 1000 - 1))


def monitor(sock, *args):
    return subprocess.run([lj, "monitor", "--control", sock, *args], capture_output=True,
                          text=True, timeout=120)


def stats(sock):
    return json.loads(monitor(sock, "stats").stdout)


def one(traced, n):
    sock = os.path.join(work, "c%d%s.sock" % (n, "t" if traced else ""))
    if os.path.exists(sock):
        os.unlink(sock)
    cmd = [lj, "serve", prog, "--control", sock, "--duration", str(seconds + 30), "--quiet"]
    if traced:
        cmd += ["--trace", tdef]
    err = open(os.path.join(work, "serve%d%s.err" % (n, "t" if traced else "")), "w")
    srv = subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=err)
    while not os.path.exists(sock):
        if srv.poll() is not None:
            sys.exit("serve ended: see " + err.name)
        time.sleep(0.05)
    while True:  # the window starts once the optimizing tier runs, as in production
        try:
            if stats(sock)["startup"]["tiering"]["engine"] == "jit-opt":
                break
        except (ValueError, KeyError):
            pass
        time.sleep(0.2)
    if traced:  # the capture starts at the tick after arming: re-armed here, on jit-opt
        assert monitor(sock, "trace", "arm").returncode == 0
    s0 = stats(sock)
    time.sleep(seconds + 2)
    s1 = stats(sock)
    row = {"traced": traced,
           "ticks": s1["ticks"] - s0["ticks"],
           "overruns": s1["overruns"] - s0["overruns"],
           "missed": s1["missed_deadlines"] - s0["missed_deadlines"],
           "load": open("/proc/loadavg").read().split()[0]}
    if traced:
        out = os.path.join(work, "capture%d.csv" % n)
        r = monitor(sock, "trace", "save", out, "--csv")
        st = json.loads(monitor(sock, "trace", "status").stdout)
        assert r.returncode == 0, r.stderr
        ticks = [int(line["tick"]) for line in csv.DictReader(open(out))]
        gaps = sum(b - a - 1 for a, b in zip(ticks, ticks[1:]) if b - a > 1)
        row.update({"rows": len(ticks), "first": ticks[0], "last": ticks[-1],
                    "duplicated": sum(1 for a, b in zip(ticks, ticks[1:]) if b <= a),
                    "ticks_without_row": gaps, "columns": len(open(out).readline().split(",")),
                    "dropped": st.get("dropped")})
    monitor(sock, "stop")
    srv.wait(timeout=60)
    return row


rows = []
for n in range(pairs):
    rows.append(one(False, n))
    rows.append(one(True, n))
for r in rows:
    print(json.dumps(r))

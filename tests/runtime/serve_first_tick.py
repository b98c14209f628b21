#!/usr/bin/env python3
"""Time to first tick and time to JIT speed of `ladderjit serve` (docs/serve.md "Time to first
tick", docs/BENCHMARKS.md "Tiering"): runs serve N times on PROGRAM with --stats and prints, per
run and as medians, the numbers serve reports (from the start of main: ready_ms, first_tick_ms,
time_to_jit_ms) and the time from just before exec() to the end of the first tick, computed
from the stats' first_tick_unix_ns against CLOCK_REALTIME taken by this script before it starts
the process (so it includes fork/exec, the dynamic loader and static constructors).

usage: serve_first_tick.py LADDERJIT PROGRAM [RUNS] [-- extra serve options]
"""
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time


def main():
    if len(sys.argv) < 3:
        print(__doc__)
        return 2
    ladderjit, program = sys.argv[1], sys.argv[2]
    rest = sys.argv[3:]
    runs = 10
    if rest and rest[0] != "--":
        runs = int(rest[0])
        rest = rest[1:]
    extra = rest[1:] if rest and rest[0] == "--" else []
    rows = []
    with tempfile.TemporaryDirectory() as d:
        for i in range(runs):
            stats = os.path.join(d, "s%d.json" % i)
            ctl = os.path.join(d, "c%d.sock" % i)
            cmd = [ladderjit, "serve", program, "--duration", "4", "--stats", stats,
                   "--control", ctl] + extra
            t0 = time.time_ns()
            subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=True)
            s = json.load(open(stats))["startup"]
            rows.append({
                "exec_to_first_tick_ms": (s["first_tick_unix_ns"] - t0) / 1e6,
                "ready_ms": s["ready_ms"],
                "first_tick_ms": s["first_tick_ms"],
                "time_to_jit_ms": s["tiering"]["time_to_jit_ms"],
                "switches": " ".join("%s@%d" % (w["to"], w["tick"])
                                     for w in s["tiering"]["switches"]),
            })
            r = rows[-1]
            print("run %2d: exec->first tick %6.1f ms | main->ready %5.1f ms, main->first tick "
                  "%5.1f ms, main->JIT %7.1f ms [%s]" % (
                      i, r["exec_to_first_tick_ms"], r["ready_ms"], r["first_tick_ms"],
                      r["time_to_jit_ms"], r["switches"]))
    def med(k):
        return statistics.median(r[k] for r in rows)
    print("median of %d: exec->first tick %.1f ms, main->ready %.1f ms, main->first tick %.1f ms, "
          "main->JIT speed %.1f ms" % (runs, med("exec_to_first_tick_ms"), med("ready_ms"),
                                       med("first_tick_ms"), med("time_to_jit_ms")))
    return 0


if __name__ == "__main__":
    sys.exit(main())

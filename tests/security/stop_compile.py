#!/usr/bin/env python3
"""Issue 11 item 5 (second half): a stop request wins over a compile in progress.

`monitor load` of a program that takes the JIT seconds to compile (LDT + 9,990 x
`BMOV D0 D1 99`: over 100 s before compile time was made linear), then SIGTERM while it
compiles. Expected (docs/serve.md "Online change"): serve exits promptly (bound: 2 s, all of it
slack for a loaded machine; serve itself waits at most 0.3 s for control clients) and the new
version is never swapped in: the --stats file counts 0 swaps, and the log has no swap."""
import json
import os
import shutil
import signal
import subprocess
import tempfile
import time

from sec_util import LJ, PROGRAM, Server, check, finish, write


def main():
    tmp = tempfile.mkdtemp(prefix="ljsec-stop-")
    prog = os.path.join(tmp, "p.stl")
    write(prog, PROGRAM, age=10)
    big = os.path.join(tmp, "big.stl")
    # Distinct statements: serve compiles incrementally, and a program of one statement repeated
    # is one rung group compiled once (equal groups share their code), which takes no time.
    body = "".join(f"BMOV D{i % 41} D{50 + i % 37} {1 + i % 9}\n" for i in range(9990))
    write(big, "LDT\n" + body + "1END\n2END\n", age=10)
    sock = os.path.join(tmp, "c.sock")
    stats = os.path.join(tmp, "stats.json")
    srv = Server(prog, "--control", sock, "--stats", stats, "--duration", "120")
    check(srv.started(), "serve starts")
    check(srv.wait_value("D10", 7), "init ran (D10 = 7)")
    load = subprocess.Popen([LJ, "monitor", "--control", sock, "load", big],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    # The load is reading, verifying or compiling now. Since online changes compile the changed
    # rung groups at the fast tier first (docs/serve.md "Online change latency"), this load takes
    # about 0.5 s on an idle machine, so SIGTERM follows soon after it starts.
    time.sleep(0.15)
    check(load.poll() is None, "the load is still in progress when SIGTERM is sent")
    t0 = time.time()
    srv.p.send_signal(signal.SIGTERM)
    try:
        srv.p.wait(timeout=10)
        took = time.time() - t0
    except subprocess.TimeoutExpired:
        took = None
        srv.p.kill()
        srv.p.wait()
    check(took is not None and took < 2.0,
          f"serve exits within 2 s of SIGTERM (took {took if took is None else round(took, 2)} s)")
    time.sleep(0.1)
    try:
        load.wait(timeout=10)
    except subprocess.TimeoutExpired:
        load.kill()
    try:
        with open(stats) as f:
            js = json.load(f)
    except (OSError, ValueError):
        js = {}
    check(js.get("stop_reason") == "SIGTERM", "the stats file was written: " + str(js)[:120])
    check(js.get("swaps", -1) == 0, "the compiled version was not swapped in (swaps = 0)")
    check("swapped in" not in srv.text() and "now running version" not in srv.text(),
          "the log shows no swap: " + srv.text()[-300:])
    shutil.rmtree(tmp, ignore_errors=True)
    return finish("stop_compile")


if __name__ == "__main__":
    raise SystemExit(main())

#!/usr/bin/env python3
"""Issue 11 item 5 (second half): a stop request wins over a compile in progress.

`monitor load` of a 10,000-statement program (the same parts as the running one, so the
shrink guard takes it) while serve is starved of CPU, so its compile takes seconds, then SIGTERM
while it compiles. Expected (docs/serve.md "Online change"): serve exits promptly (bound: 2 s, all of it
slack for a loaded machine; serve itself waits at most 0.3 s for control clients) and the new
version is never swapped in: the --stats file counts 0 swaps, and the log has no swap."""
import json
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time

from sec_util import LJ, PROGRAM, Server, check, finish, write


def starve(pid, cpu):
    """Every thread of process `pid` to CPU `cpu` at nice 19 (threads it starts later inherit)."""
    for tid in os.listdir(f"/proc/{pid}/task"):
        try:
            os.sched_setaffinity(int(tid), {cpu})
            os.setpriority(os.PRIO_PROCESS, int(tid), 19)
        except ProcessLookupError:
            pass


def main():
    tmp = tempfile.mkdtemp(prefix="ljsec-stop-")
    prog = os.path.join(tmp, "p.stl")
    write(prog, PROGRAM, age=10)
    big = os.path.join(tmp, "big.stl")
    # Distinct statements: serve compiles incrementally, and a program of one statement repeated
    # is one rung group compiled once (equal groups share their code), which takes no time.
    body = "".join(f"BMOV D{i % 41} D{50 + i % 37} {1 + i % 9}\n" for i in range(9990))
    # The same parts as PROGRAM (init, PLC1, PLC2): a program lacking one is refused by the
    # online change's shrink guard at once, and nothing would be compiling when SIGTERM comes.
    write(big, "LDT\nMOV 7 D10\nIEND\nLDT\n" + body + "1END\nLDT\nADD D30 1 D30\n2END\n", age=10)
    sock = os.path.join(tmp, "c.sock")
    stats = os.path.join(tmp, "stats.json")
    srv = Server(prog, "--control", sock, "--stats", stats, "--duration", "120")
    check(srv.started(), "serve starts")
    check(srv.wait_value("D10", 7), "init ran (D10 = 7)")
    # A compile at the fast tier takes this program about 0.1 s (docs/serve.md "Online change
    # latency"), too short to send a signal into reliably. So serve is starved while it compiles:
    # all its threads are moved to one CPU at nice 19 beside a busy loop at nice 0 there, which
    # leaves serve about 1.5 % of that CPU (CFS weights 15 against 1024), and the compile some
    # seconds. The busy loop ends just before SIGTERM, so serve's exit is not slowed by it.
    cpu = min(os.sched_getaffinity(0))
    hog = subprocess.Popen([sys.executable, "-c", "while True: pass"])
    os.sched_setaffinity(hog.pid, {cpu})
    starve(srv.p.pid, cpu)
    load = subprocess.Popen([LJ, "monitor", "--control", sock, "load", big],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    time.sleep(1.0)
    still = load.poll() is None
    hog.kill()
    hog.wait()
    check(still, "the load is still in progress when SIGTERM is sent")
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
    # Its only possible refusal is the stop's: a refusal for any other reason (a program lacking a
    # part of the running one, a verify error) would mean nothing was compiling at SIGTERM.
    refusals = [l for l in srv.log if "refused" in l]
    check(all("the server is stopping" in l for l in refusals),
          "the load was refused for the stop only, if at all: " + "".join(refusals)[-300:])
    check("swapped in" not in srv.text() and "now running version" not in srv.text(),
          "the log shows no swap: " + srv.text()[-300:])
    shutil.rmtree(tmp, ignore_errors=True)
    return finish("stop_compile")


if __name__ == "__main__":
    raise SystemExit(main())

#!/usr/bin/env python3
"""Issue 11 item 2 (and the `load` allow-list of item 4): an online change never swaps in an
empty, half-written or shrunken program, and `monitor load` reads only below --load-dir.

Expected behaviour (docs/serve.md "Online change"): a truncated PROGRAM seen by the file watch is
refused and logged, and the old program keeps controlling Y1.0; a file still being written is
taken only once it stopped changing; a program without a part the running one has is refused
unless `monitor load --allow-shrink`; a path outside the load directories (also through a
symlink) is refused. Every refusal is in the log and counted in `monitor stats`."""
import json
import os
import shutil
import tempfile
import threading
import time

from sec_util import PROGRAM, Server, check, finish, serve_has, write


def main():
    tmp = tempfile.mkdtemp(prefix="ljsec-oc-")
    other = tempfile.mkdtemp(prefix="ljsec-other-")
    prog = os.path.join(tmp, "p.stl")
    write(prog, PROGRAM, age=10)
    sock = os.path.join(tmp, "c.sock")
    stats = os.path.join(tmp, "stats.json")
    args = [prog, "--control", sock, "--duration", "60", "--stats", stats]
    if serve_has("--watch-file"):
        args.append("--watch-file")  # the watch is opt-in now; the old code always watched
    srv = Server(*args)
    check(srv.started(), "serve starts")
    check(srv.wait_value("D10", 7), "init ran (D10 = 7)")
    srv.monitor("write", "X1.0=1")
    check(srv.wait_value("Y1.0", 1), "Y1.0 (the spindle) follows X1.0 = 1")

    # `: > p.stl` while served: the watch must refuse the empty program.
    write(prog, "")
    time.sleep(2.5)  # > one poll (1 s) + the settle interval
    check("refused" in srv.text() and "empty" in srv.text(),
          "the truncated PROGRAM is refused with a logged reason: " + srv.text()[-300:])
    srv.monitor("write", "X1.0=0")
    check(srv.wait_value("Y1.0", 0, seconds=3), "the old program still switches Y1.0 off")
    rc, out, _ = srv.monitor("stats")
    st = json.loads(out) if rc == 0 else {}
    check(st.get("program", {}).get("version") == 1, "still version 1: " + out[:300])
    check(st.get("online_change_refusals", 0) >= 1, "monitor stats counts the refusal")

    # A program that lost its PLC2 part: refused, unless the operator asks for it.
    shrink = os.path.join(tmp, "shrink.stl")
    write(shrink, "LDT\nMOV 8 D10\nIEND\nLD X1.0\nOUT Y1.0\n1END\n2END\n", age=10)
    rc, _, err = srv.monitor("load", shrink)
    check(rc == 2 and "lacks PLC2" in err, "a program without PLC2 is refused: " + err)
    rc, _, err = srv.monitor("load", "--allow-shrink", shrink)
    check(rc == 0, "monitor load --allow-shrink takes it: " + err)
    check(srv.wait_value("D10", 8), "the shrunken version runs (D10 = 8)")

    # A file still being written: the partial text (valid on its own) must never run.
    hw = os.path.join(tmp, "hw.stl")
    partial = PROGRAM.replace("MOV 7 D10", "MOV 5 D10")
    final = PROGRAM.replace("MOV 7 D10", "MOV 9 D10")
    write(hw, partial)

    def finish_writing():
        time.sleep(0.3)
        write(hw, final)

    t = threading.Thread(target=finish_writing)
    t.start()
    rc, _, err = srv.monitor("load", hw)
    t.join()
    check(rc == 0, "the finished file is loaded: " + err)
    check(srv.read("D10") == 9, "the version swapped in is the finished file (D10 = 9, not 5)")

    # Only below the load directory (default: PROGRAM's), symlinks resolved.
    outside = os.path.join(other, "o.stl")
    write(outside, PROGRAM.replace("MOV 7 D10", "MOV 3 D10"), age=10)
    rc, _, err = srv.monitor("load", outside)
    check(rc == 2 and "outside" in err, "a program outside the load directory is refused: " + err)
    link = os.path.join(tmp, "link.stl")
    os.symlink(outside, link)
    rc, _, err = srv.monitor("load", link)
    check(rc == 2 and "outside" in err, "a symlink leading outside is refused: " + err)
    check(srv.read("D10") == 9, "the refused loads changed nothing (D10 = 9)")

    rc = srv.stop()
    check(rc == 0, f"serve stops cleanly (exit {rc})")
    try:
        with open(stats) as f:
            js = json.load(f)
    except (OSError, ValueError):
        js = {}
    check(js.get("online_change_refusals", 0) >= 4, "--stats counts every refusal: " + str(js)[:200])
    shutil.rmtree(tmp, ignore_errors=True)
    shutil.rmtree(other, ignore_errors=True)
    return finish("online_change")


if __name__ == "__main__":
    raise SystemExit(main())

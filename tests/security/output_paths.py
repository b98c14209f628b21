#!/usr/bin/env python3
"""Issue 11 items 9 and 10: output paths and the run log.

Expected (docs/aot.md, CLI.md exit codes, docs/simulated-nc.md "Dump"):
- `compile -o OUT` refuses an OUT that exists and is not a regular file (exit 2; here a
  character device node like /dev/full, made in a temp dir, and a FIFO) and leaves it alone;
- `check --print`, `run --watch` and `emit-llvm` exit 2 with a message when stdout cannot be
  written (`> /dev/full`);
- `run` keeps the last 10,000 simulated-NC host calls, and the dump counts the dropped ones:
  a SAVEDATA on every second tick for 50,000 ticks makes 25,000 calls, 15,000 dropped."""
import json
import os
import shutil
import stat
import subprocess
import tempfile

from sec_util import LJ, PROGRAM, check, finish, run, write


def to_full(*args):
    with open("/dev/full", "w") as full:
        r = subprocess.run([LJ, *args], stdout=full, stderr=subprocess.PIPE, text=True,
                           timeout=120)
    return r.returncode, r.stderr


def main():
    tmp = tempfile.mkdtemp(prefix="ljsec-out-")
    prog = os.path.join(tmp, "p.stl")
    write(prog, PROGRAM)

    node = os.path.join(tmp, "full")
    os.mknod(node, 0o666 | stat.S_IFCHR, os.makedev(1, 7))  # the /dev/full device
    rc, _, err = run("compile", prog, "-o", node, timeout=120)
    check(rc == 2 and "not a regular file" in err, "compile -o DEVICE: refused: " + err)
    check(stat.S_ISCHR(os.lstat(node).st_mode), "the device node is still a device node")
    fifo = os.path.join(tmp, "fifo.so")
    os.mkfifo(fifo)
    rc, _, err = run("compile", prog, "-o", fifo, timeout=120)
    check(rc == 2 and stat.S_ISFIFO(os.lstat(fifo).st_mode), "compile -o FIFO: refused: " + err)
    so = os.path.join(tmp, "p.so")
    rc, _, err = run("compile", prog, "-o", so, timeout=120)
    with open(so, "rb") if os.path.exists(so) else open(os.devnull, "rb") as f:
        check(rc == 0 and f.read(4) == b"\x7fELF", "compile -o a new path still works: " + err)
    check(sorted(os.listdir(tmp)) == ["fifo.so", "full", "p.so", "p.stl"],
          "no temp file is left beside the outputs: " + str(os.listdir(tmp)))

    for args in (["check", "--print", prog], ["run", prog, "--ticks", "3", "--watch", "D10"],
                 ["emit-llvm", prog]):
        rc, err = to_full(*args)
        check(rc == 2 and "standard output" in err, " ".join(args[:2]) + " > /dev/full: exit 2: "
              + err)

    sd = os.path.join(tmp, "sd.stl")
    write(sd, "LDI R0.0\nOUT R0.0\nLD R0.0\nSAVEDATA\n1END\n2END\n")
    rc, out, err = run("run", sd, "--ticks", "50000", "--engine", "interp", "--dump", "-",
                       timeout=120)
    nc = json.loads(out).get("nc", {}) if rc == 0 else {}
    calls = nc.get("calls", [])
    check(len(calls) == 10000, f"run keeps the last 10,000 host calls ({len(calls)})")
    check(nc.get("log_dropped", {}).get("calls") == 15000, "the dump counts the 15,000 dropped")
    check(bool(calls) and calls[-1].get("tick") == 49998 and calls[-1].get("name") == "save_data",
          "the kept ones are the newest (last: tick 49998 save_data)")
    shutil.rmtree(tmp, ignore_errors=True)
    return finish("output_paths")


if __name__ == "__main__":
    raise SystemExit(main())

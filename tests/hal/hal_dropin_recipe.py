#!/usr/bin/env python3
"""The ClassicLadder drop-in recipe on a real LinuxCNC configuration (issue 31 scope 2;
docs/linuxcnc.md "ClassicLadder drop-in"), under halrun.

The configuration: LinuxCNC's configs/by_interface/parport/classicladder/cl-estop (read from
../shared/realprograms/classicladder/linuxcnc/, never copied into the repository): its
custom.hal loads classicladder_rt, adds classicladder.0.refresh to the servo thread and loads
estop.clp with `loadusr classicladder --nogui`. The recipe changes exactly two lines:

    loadrt classicladder_rt ...            ->  loadrt ladderjit program=estop.so source=estop.clp ...
    loadusr classicladder --nogui estop.clp ->  (removed)

(estop.so: `ladderjit compile estop.clp -o estop.so`; `trust=` names the signing key when it is
not the user's default). Both files run under halrun after one stand-in line for what stepconf's
main HAL file provides (`loadrt threads name1=servo-thread period1=1000000`), with the same input
steps on classicladder.0.in-00..in-03 appended, each held 100 ms (100 periods). Checked:
- the recipe's file changes only those two lines of custom.hal;
- ladderjit exports the pins of classicladder_rt for this configuration: the same names, types
  and directions (`show pin classicladder.0`), and the function classicladder.0.refresh (the
  unchanged addf line works);
- after every step the 15 output pins are the same under both.
Usage: hal_dropin_recipe.py LADDERJIT MODULE REALPROGRAMS_ROOT"""
import os
import random
import re
import shutil
import sys

sys.dont_write_bytecode = True
from halrig import Rig, RigError, gets_values  # noqa: E402

CONFIG = "linuxcnc/configs/by_interface/parport/classicladder/cl-estop"
STEPS = 24
HOLD_S = 0.1


def recipe(text, so, clp, key):
    """custom.hal with the recipe applied: the loadrt line replaced, the loader line removed."""
    out = []
    for line in text.splitlines():
        m = re.match(r"\s*loadrt\s+classicladder_rt\b(.*)$", line)
        if m:
            out.append(f"loadrt ladderjit program={so} source={clp} trust={key}{m.group(1)}")
        elif re.match(r"\s*loadusr\s+(-w\s+)?classicladder\b", line):
            continue
        else:
            out.append(line)
    return "\n".join(out) + "\n"


def run(rig, name, hal_text, seq):
    lines = ["loadrt threads name1=servo-thread period1=1000000", hal_text.rstrip("\n"),
             "start", "loadusr -w sleep 0.5", "show pin classicladder.0", "show funct"]
    for step in seq:
        lines += [f"setp classicladder.0.in-{i:02d} {v}" for i, v in enumerate(step)]
        lines.append(f"loadusr -w sleep {HOLD_S}")
        lines += [f"getp classicladder.0.out-{o:02d}" for o in range(15)]
    lines.append("stop")
    r = rig.halfile(name, "\n".join(lines) + "\n", timeout=120)
    pins = sorted((m.group(1), m.group(2), m.group(3)) for m in re.finditer(
        r"^\s*\d+\s+(bit|s32|u32|float)\s+(IN|OUT|I/O)\s+\S+\s+(classicladder\.0\.\S+)",
        r.stdout, re.M))
    functs = re.findall(r"classicladder\.0\.refresh", r.stdout)
    vals = gets_values(r.stdout)
    return pins, functs, vals, r.stdout + r.stderr


def main():
    ladderjit, module, root = sys.argv[1], sys.argv[2], sys.argv[3]
    failures = []

    def check(ok, what):
        print(("ok   " if ok else "FAIL ") + what, flush=True)
        if not ok:
            failures.append(what)

    try:
        rig = Rig(ladderjit, module)
    except RigError as e:
        print(f"FAIL {e}")
        return 1
    try:
        src = os.path.join(root, CONFIG)
        for f in ("custom.hal", "estop.clp"):
            shutil.copyfile(os.path.join(src, f), rig.path(f))
            os.chmod(rig.path(f), 0o644)
        clp = rig.path("estop.clp")
        so = rig.compile(clp, rig.path("estop.so"))
        with open(rig.path("custom.hal")) as f:
            original = f.read()
        # classicladder's loader resolves estop.clp against halrun's folder: name it in full
        cl_text = original.replace("--nogui estop.clp", f"--nogui {clp}")
        dropin = recipe(original, so, clp, rig.trust_key())
        changed = [(a, b) for a, b in zip(original.splitlines(), dropin.splitlines() + [""]) if a != b]
        check(len(original.splitlines()) - len(dropin.splitlines()) == 1 and len(changed) >= 1 and
              changed[0][0].startswith("loadrt classicladder_rt"),
              "the recipe changes custom.hal's loadrt line and removes the loader line: " +
              " | ".join(l for l in dropin.splitlines() if l.startswith("loadrt")))
        rng = random.Random(31)
        seq = [[rng.randint(0, 1) for _ in range(4)] for _ in range(STEPS)]
        cl_pins, cl_funct, cl_vals, cl_log = run(rig, "classicladder.hal", cl_text, seq)
        lj_pins, lj_funct, lj_vals, lj_log = run(rig, "ladderjit.hal", dropin, seq)
        check(len(cl_pins) > 0 and cl_pins == lj_pins,
              f"ladderjit exports classicladder_rt's {len(cl_pins)} classicladder.0 pins, names, "
              f"types and directions equal" + ("" if cl_pins == lj_pins else
                                               f": only classicladder_rt {sorted(set(cl_pins) - set(lj_pins))[:5]}, "
                                               f"only ladderjit {sorted(set(lj_pins) - set(cl_pins))[:5]}"))
        check(len(lj_funct) >= 1, "ladderjit exports classicladder.0.refresh (the addf line is unchanged)")
        want = STEPS * 15
        check(len(cl_vals) == want and len(lj_vals) == want,
              f"{want} output values from each run ({len(cl_vals)}, {len(lj_vals)})" +
              ("" if len(lj_vals) == want else "\n" + lj_log[-1500:]))
        diffs = [(k // 15, k % 15, a, b) for k, (a, b) in enumerate(zip(cl_vals, lj_vals)) if a != b]
        changes = sum(1 for k in range(15, len(cl_vals)) if cl_vals[k] != cl_vals[k - 15])
        check(not diffs and len(cl_vals) == want,
              f"the 15 outputs after each of {STEPS} input steps are equal ({changes} output changes "
              f"under classicladder_rt)" + (f": first differences (step, out, CL, ladderjit) {diffs[:5]}"
                                            if diffs else ""))
    except RigError as e:
        check(False, str(e))
    finally:
        rig.halrun(["-U"], timeout=30, check=False)
        rig.cleanup()
    print(f"{len(failures)} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())

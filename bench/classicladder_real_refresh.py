#!/usr/bin/env python3
"""Refresh time of classicladder_rt and of ladderjit's drop-in on the same real ClassicLadder
projects, in the same HAL thread (issue 31 scope 4; docs/BENCHMARKS.md "ClassicLadder refresh
time on real projects").

For each project (every .clp under ROOT, or the `--real` ones), one `halrun`:
  1. loads classicladder_rt with the project's sizes (what `clp_tool info` says the
     `loadrt classicladder_rt` line needs) and the project with `classicladder --nogui`, and
     ladderjit's HAL component on the same project (`ladderjit compile`, signed with the run's own
     key) with `names=lj`, so both export their pins and refresh function in one HAL;
  2. adds both refresh functions to one 1 ms thread and nets every input pin of both to one
     signal (in-NN, s32in-NN, floatin-NN);
  3. STEPS times: stops the thread, reads every output pin of both (they must be equal), sets new
     random inputs (each pin changes with probability 1/3), starts the thread, and while it runs
     for about HOLD ms reads both functions' `*.refresh.time` (HAL's own per-function time, in
     rtapi_get_clocks() units) SAMPLES times;
  4. half way through swaps the two functions' order in the thread (`delf`/`addf`), so neither
     always runs first (with the caches the other one warmed).
Both run the same inputs in the same period: the outputs read with the thread stopped are those
of the same scan. The refresh times include each function's pin copies.

Usage: classicladder_real_refresh.py CLP_TOOL LADDERJIT MODULE ROOT [--real REL...]
       [--steps 40] [--samples 5] [--hold-ms 100] [--seed 1] [--format md|json]
A project ladderjit refuses (`ladderjit compile` fails) is listed with the reason and not timed;
the exit status is 1 when any timed project's outputs differ or a run fails."""
import argparse
import json
import os
import random
import shutil
import statistics
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "tests", "hal"))
sys.path.insert(0, os.path.join(HERE, "..", "tests", "classicladder"))
from halrig import Rig, RigError, gets_values  # noqa: E402
from clharness import pins, project_info  # noqa: E402

PERIOD_NS = 1000000  # 1 ms: one scan per period for both (classicladder.md 4.1)
LJ = "lj"           # names= of the ladderjit component (classicladder_rt keeps classicladder.0)
CL = "classicladder.0"
SIZE_KEYS = ("numPhysInputs", "numPhysOutputs", "numS32in", "numS32out", "numFloatIn",
             "numFloatOut")


def value(pin, rng):
    if pin.startswith("in-"):
        return rng.randint(0, 1)
    if pin.startswith("s32in-"):
        return rng.randint(-3, 20) if rng.random() < 0.9 else rng.randint(-2**31, 2**31 - 1)
    return round(rng.uniform(-12.0, 12.0), 3)


def hal_lines(clp, so, key, loadrt, ins, outs, a, rng):
    """The HAL file of one project, and how many values each step's and the tail's commands
    print (steps x (2 x outputs + 2 x samples), then 4 tmax values and the ladder state)."""
    args = " ".join(f"{k}={v}" for k, v in loadrt.items())
    sizes = " ".join(f"{k}={loadrt[k]}" for k in SIZE_KEYS if k in loadrt)
    lines = [f"loadrt classicladder_rt {args}",
             f"loadrt ladderjit program={so} source={clp} trust={key} names={LJ} {sizes}",
             f"loadrt threads name1=plc period1={PERIOD_NS} fp1=1",
             f"addf {CL}.refresh plc", f"addf {LJ}.refresh plc"]
    lines += [f"net i-{p} {CL}.{p} {LJ}.{p}" for p in ins]
    lines.append(f"loadusr -w classicladder --nogui {clp}")
    current = {p: value(p, rng) for p in ins}
    lines += [f"sets i-{p} {v}" for p, v in current.items()]
    for step in range(a.steps):
        if step == a.steps // 2:  # the other order for the second half
            lines += [f"delf {CL}.refresh plc", f"delf {LJ}.refresh plc",
                      f"addf {LJ}.refresh plc", f"addf {CL}.refresh plc"]
        lines.append("start")
        for _ in range(a.samples):
            lines += [f"loadusr -w sleep {a.hold_ms / 1000 / a.samples:.3f}",
                      f"getp {CL}.refresh.time", f"getp {LJ}.refresh.time"]
        lines.append("stop")
        lines += [f"getp {CL}.{p}" for p in outs] + [f"getp {LJ}.{p}" for p in outs]
        for p in ins:
            if rng.random() < 1 / 3:
                current[p] = value(p, rng)
                lines.append(f"sets i-{p} {current[p]}")
    lines += [f"getp {CL}.refresh.tmax", f"getp {LJ}.refresh.tmax", "getp ladderjit.ticks",
              "getp classicladder.ladder-state"]
    return lines


def run_project(rig, clp_tool, path, rel, a, seed):
    info = project_info(clp_tool, path)
    if not info["ok"] or info.get("upstream"):
        return dict(project=rel, refused="not a LinuxCNC project: " +
                    info.get("error", "an upstream 0.9 .clprj"))
    loadrt = info["loadrt"]
    ins, outs = pins(loadrt)
    name = rel.replace("/", "__")
    clp = rig.path(name)
    shutil.copyfile(path, clp)
    os.chmod(clp, 0o644)
    so = rig.path(name[:-4] + ".so")
    r = rig.run([rig.ladderjit, "compile", clp, "-o", so], check=False, timeout=300)
    if r.returncode != 0:
        why = (r.stdout + r.stderr).strip().splitlines()
        return dict(project=rel, refused=why[0] if why else f"compile failed ({r.returncode})")
    os.chmod(so, 0o644)
    os.chmod(rig.path("keys"), 0o755)
    rng = random.Random(seed)
    lines = hal_lines(clp, so, rig.trust_key(), loadrt, ins, outs, a, rng)
    timeout = 120 + a.steps * (a.hold_ms / 1000 + 1)
    res = rig.halfile(name[:-4] + ".hal", "\n".join(lines) + "\n", timeout=timeout, check=False)
    vals = gets_values(res.stdout)
    per_step = 2 * a.samples + 2 * len(outs)
    want = a.steps * per_step + 4
    if res.returncode != 0 or len(vals) != want:
        tail = (res.stdout + res.stderr)[-1500:]
        raise RigError(f"{rel}: halrun gave {len(vals)} values of {want} "
                       f"(rc {res.returncode}):\n{tail}")
    cl_t, lj_t, cl_first, lj_first = [], [], [], []
    mism, pos = 0, 0
    for step in range(a.steps):
        for _ in range(a.samples):
            c, j = int(vals[pos]), int(vals[pos + 1])
            pos += 2
            if c <= 0 or j <= 0:  # not run yet in this start (the first period after start)
                continue
            cl_t.append(c)
            lj_t.append(j)
            (cl_first if step < a.steps // 2 else lj_first).append(c / j)
        cl_out = vals[pos:pos + len(outs)]
        lj_out = vals[pos + len(outs):pos + 2 * len(outs)]
        pos += 2 * len(outs)
        mism += sum(1 for x, y in zip(cl_out, lj_out) if norm(x) != norm(y))
    cl_max, lj_max, ticks, state = (int(v, 0) for v in vals[pos:pos + 4])
    if state != 2:
        raise RigError(f"{rel}: classicladder.ladder-state {state} (2 = RUN)")
    return dict(project=rel, ins=len(ins), outs=len(outs), samples=len(cl_t),
                cl=statistics.median(cl_t), lj=statistics.median(lj_t),
                ratio_cl_first=statistics.median(cl_first) if cl_first else None,
                ratio_lj_first=statistics.median(lj_first) if lj_first else None,
                cl_max=cl_max, lj_max=lj_max, ticks=ticks, mismatches=mism,
                compared=a.steps * len(outs))


def norm(v):
    if v in ("TRUE", "FALSE"):
        return v == "TRUE"
    return round(float(v), 4)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("clp_tool")
    ap.add_argument("ladderjit")
    ap.add_argument("module")
    ap.add_argument("root")
    ap.add_argument("--real", nargs="*", default=[], help="projects relative to ROOT (default all)")
    ap.add_argument("--steps", type=int, default=40)
    ap.add_argument("--samples", type=int, default=5)
    ap.add_argument("--hold-ms", type=int, default=100)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--format", choices=("md", "json"), default="md")
    a = ap.parse_args()
    if a.steps < 2 or a.samples < 1:
        ap.error("--steps must be at least 2 and --samples at least 1")
    rel = a.real or sorted(os.path.relpath(os.path.join(d, f), a.root)
                           for d, _, fs in os.walk(a.root) for f in fs if f.endswith(".clp"))
    try:
        rig = Rig(a.ladderjit, a.module)
    except RigError as e:
        print(f"error: {e}")
        return 1
    rows, failed = [], 0
    try:
        for i, r in enumerate(rel):
            try:
                rows.append(run_project(rig, a.clp_tool, os.path.join(a.root, r), r, a,
                                        a.seed + i))
            except RigError as e:
                print(f"error: {e}", file=sys.stderr)
                rows.append(dict(project=r, error=str(e).splitlines()[0]))
                failed += 1
                rig.halrun(["-U"], timeout=30, check=False)
            row = rows[-1]
            if "cl" in row:
                failed += row["mismatches"] != 0
                print(f"{r}: refresh.time median CL {row['cl']:.0f}, ladderjit {row['lj']:.0f} "
                      f"clocks ({row['cl'] / row['lj']:.1f}x); outputs unequal "
                      f"{row['mismatches']}/{row['compared']}", file=sys.stderr, flush=True)
    finally:
        rig.halrun(["-U"], timeout=30, check=False)
        rig.cleanup()
    if a.format == "json":
        print(json.dumps(rows, indent=1))
        return 1 if failed else 0
    print("| project | in / out pins | classicladder.0.refresh.time | lj.refresh.time | "
          "CL / ladderjit | (CL first / ladderjit first) | tmax CL / ladderjit | outputs equal |")
    print("|---|---:|---:|---:|---:|---|---:|---:|")
    timed = [r for r in rows if "cl" in r]
    for r in rows:
        if "refused" in r or "error" in r:
            print(f"| {r['project']} | | | | | {r.get('refused') or r['error']} | | |")
            continue
        print(f"| {r['project']} | {r['ins']} / {r['outs']} | {r['cl']:,.0f} | {r['lj']:,.0f} | "
              f"{r['cl'] / r['lj']:.1f}x | {r['ratio_cl_first']:.1f}x / "
              f"{r['ratio_lj_first']:.1f}x | {r['cl_max']:,} / {r['lj_max']:,} | "
              f"{r['compared'] - r['mismatches']}/{r['compared']} |")
    if timed:
        ratios = [r["cl"] / r["lj"] for r in timed]
        print(f"\n{len(timed)} projects timed: CL / ladderjit median {statistics.median(ratios):.1f}x, "
              f"range {min(ratios):.1f}x - {max(ratios):.1f}x; "
              f"{len(rows) - len(timed)} not timed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())

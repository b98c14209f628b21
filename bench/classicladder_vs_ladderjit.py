#!/usr/bin/env python3
"""ClassicLadder (classicladder_rt) against the ladderjit HAL component in one HAL thread.

For each size N (default 100, 1000, 3000, 5000 rungs) this generates an equivalent program twice,
a ClassicLadder project (.clp) and a ladderjit program (FANUC PMC by default, `--dialect hnc8`
for HNC-8 STL), then under one `halrun`:
  1. loads classicladder_rt (sized for N rungs) and the program with `classicladder --nogui`,
     and the ladderjit component with the compiled, signed .so;
  2. adds both refresh functions to the same HAL thread, connects the same 16 input signals to
     both and shows equivalence: STEPS random input vectors, each held for many periods, all 16
     outputs of both read with `gets` and compared;
  3. samples both functions' `*.refresh.time` pins (HAL's own per-function measurement, in
     rtapi_get_clocks() units) SAMPLES times, and ladderjit's scan-time-ns pin.

The program limits are 24,000 statements for FANUC (profiles/fanuc) and 10,000 for HNC-8
(DIALECT.md), which `ladderjit compile` enforces; a rung is 3 statements, so HNC-8 stops at
3,332 rungs (larger sizes then run ClassicLadder alone, its outputs checked against the rung
definition) and FANUC at 7,999.

Rung k (0-based): contact in[k mod 16] AND NOT coil[k-1] (rung 0: NOT in[1]) -> coil[k];
the last 16 rungs' coils are the outputs, the others memory bits.
  ClassicLadder: %I(k mod 16), %B(k) / %Q(j), one row of the 10x6 grid per rung.
  FANUC:         X0.0..X1.7, R(k/8).(k%8) / Y0.0..Y1.7: RD, AND.NOT, WRT per rung.
  HNC-8:         X0.0..X1.7, G(k/16).(k%16) / Y0.0..Y1.7: LD, ANI, OUT per rung.
Usage: classicladder_vs_ladderjit.py LADDERJIT MODULE [--sizes 100,1000,3000,5000]
       [--steps 40] [--samples 100] [--period-ns 10000000] [--dialect fanuc|hnc8]
"""
import argparse
import os
import random
import statistics
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "hal"))
from halrig import Rig, RigError, gets_values  # noqa: E402

NIN = 16
NOUT = 16
STMT_LIMIT = {"hnc8": 10000, "fanuc": 24000}  # statements of one program; a rung here is 3
DIALECT = "fanuc"  # --dialect
VAR_MEM_BIT, VAR_PHYS_INPUT, VAR_PHYS_OUTPUT = 0, 50, 60  # ClassicLadder classicladder.h
ELE_FREE, ELE_INPUT, ELE_INPUT_NOT, ELE_CONNECTION, ELE_OUTPUT = 0, 1, 2, 9, 50


def coil(n, k):
    """(ClassicLadder var type, offset), ladderjit address of rung k's coil."""
    if k >= n - NOUT:
        j = k - (n - NOUT)
        return (VAR_PHYS_OUTPUT, j), f"Y{j // 8}.{j % 8}"
    if DIALECT == "fanuc":
        return (VAR_MEM_BIT, k), f"R{k // 8}.{k % 8}"
    return (VAR_MEM_BIT, k), f"G{k // 16}.{k % 16}"


def xin(i):
    return f"X{i // 8}.{i % 8}"


def make_stl(n):
    lines = [f"; {n} rungs: in[k mod 16] AND NOT coil[k-1] -> coil[k] "
             "(bench/classicladder_vs_ladderjit.py)"]
    for k in range(n):
        prev = xin(1) if k == 0 else coil(n, k - 1)[1]
        lines += [f"LD {xin(k % NIN)}", f"ANI {prev}", f"OUT {coil(n, k)[1]}"]
    lines += ["1END", "2END"]
    return "\n".join(lines) + "\n"


def make_pmc(n):
    lines = [f"; {n} rungs: in[k mod 16] AND NOT coil[k-1] -> coil[k] "
             "(bench/classicladder_vs_ladderjit.py)"]
    for k in range(n):
        prev = xin(1) if k == 0 else coil(n, k - 1)[1]
        lines += [f"RD {xin(k % NIN)}", f"AND.NOT {prev}", f"WRT {coil(n, k)[1]}"]
    lines += ["END1", "END2", "END"]
    return "\n".join(lines) + "\n"


def cell(t, vt=0, vo=0, top=0):
    return f"{t}-{top}-{vt}/{vo}"


def make_clp(n):
    out = ["_FILES_CLASSICLADDER", "_FILE-sections.csv", "#VER=1.0", "#NAME000=Prog1",
           f"000,0,-1,0,{n - 1},0", "_/FILE-sections.csv"]
    for k in range(n):
        prev = (VAR_PHYS_INPUT, 1) if k == 0 else coil(n, k - 1)[0]
        row0 = [cell(ELE_INPUT, VAR_PHYS_INPUT, k % NIN), cell(ELE_INPUT_NOT, *prev)]
        row0 += [cell(ELE_CONNECTION)] * 7 + [cell(ELE_OUTPUT, *coil(n, k)[0])]
        empty = " , ".join([cell(ELE_FREE)] * 10)
        out += [f"_FILE-rung_{k}.csv", "#VER=2.0", f"#LABEL=R{k}", "#COMMENT=",
                f"#PREVRUNG={k - 1 if k else -1}", f"#NEXTRUNG={k + 1 if k + 1 < n else -1}",
                " , ".join(row0)] + [empty] * 5 + [f"_/FILE-rung_{k}.csv"]
    out += ["_FILE-general.txt", "PERIODIC_REFRESH=1", f"SIZE_NBR_RUNGS={n}",
            f"SIZE_NBR_BITS={n}", "SIZE_NBR_WORDS=4", "SIZE_NBR_TIMERS=1",
            "SIZE_NBR_MONOSTABLES=1", "SIZE_NBR_COUNTERS=1", "SIZE_NBR_TIMERS_IEC=1",
            f"SIZE_NBR_PHYS_INPUTS={NIN}", f"SIZE_NBR_PHYS_OUTPUTS={NOUT}",
            "SIZE_NBR_ARITHM_EXPR=4", "SIZE_NBR_SECTIONS=1", "_/FILE-general.txt"]
    return "\n".join(out) + "\n"


def expected(n, inputs):
    """The outputs the rung definition gives (for the report; the check is CL == ladderjit)."""
    prev = not inputs[1]
    outs = []
    for k in range(n):
        v = inputs[k % NIN] and (prev if k == 0 else not prev)
        prev = v
        if k >= n - NOUT:
            outs.append(v)
    return outs


def fits(n):
    return 3 * n + 3 <= STMT_LIMIT[DIALECT]


def run_size(rig, n, steps, samples, period_ns):
    """Both engines; beyond the HNC-8 statement limit ClassicLadder alone (with_lj False)."""
    with_lj = fits(n)
    clp = rig.write(f"bench{n}.clp", make_clp(n))
    if with_lj:
        ext, text = (".pmc", make_pmc(n)) if DIALECT == "fanuc" else (".stl", make_stl(n))
        src = rig.write(f"bench{n}{ext}", text)
        so = rig.compile(src, rig.path(f"bench{n}.so"))
    rng = random.Random(n)
    vectors = [[rng.randint(0, 1) for _ in range(NIN)] for _ in range(steps)]
    hal = [f"loadrt classicladder_rt numRungs={n} numBits={n} numWords=4 numTimers=1 "
           f"numMonostables=1 numCounters=1 numTimersIec=1 numPhysInputs={NIN} "
           f"numPhysOutputs={NOUT} numArithmExpr=4 numSections=1",
           f"loadrt threads name1=plc period1={period_ns}",
           "addf classicladder.0.refresh plc",
           f"loadusr -w classicladder --nogui {clp}"]
    if with_lj:
        hal[1:1] = [f"loadrt ladderjit program={so} trust={rig.trust_key()}"]
        hal.insert(4, "addf ladderjit.refresh plc")
    for i in range(NIN):
        hal.append(f"net in{i} classicladder.0.in-{i:02d}" +
                   (f" ladderjit.{xin(i).lower()}" if with_lj else ""))
    for j in range(NOUT):
        hal.append(f"net cl{j} classicladder.0.out-{j:02d}")
        if with_lj:
            hal.append(f"net lj{j} ladderjit.y{j // 8}.{j % 8}")
    hal += ["start", "loadusr -w sleep 0.2"]
    for vec in vectors:
        hal += [f"sets in{i} {v}" for i, v in enumerate(vec)]
        hal.append("loadusr -w sleep 0.05")
        hal += [f"gets cl{j}" for j in range(NOUT)]
        hal += [f"gets lj{j}" if with_lj else f"gets cl{j}" for j in range(NOUT)]
    for _ in range(samples):
        hal += ["getp classicladder.0.refresh.time",
                "getp ladderjit.refresh.time" if with_lj else "getp classicladder.0.refresh.time",
                "getp ladderjit.scan-time-ns" if with_lj else "getp classicladder.0.refresh.time",
                "loadusr -w sleep 0.01"]
    hal += ["getp classicladder.0.refresh.tmax",
            "getp ladderjit.refresh.tmax" if with_lj else "getp classicladder.0.refresh.tmax",
            "getp ladderjit.ticks" if with_lj else "getp plc.time", "stop"]
    r = rig.halfile(f"bench{n}.hal", "\n".join(hal) + "\n", timeout=120 + steps + samples)
    vals = gets_values(r.stdout)
    want = steps * 2 * NOUT + samples * 3 + 3
    if len(vals) != want:
        raise RigError(f"{n} rungs: expected {want} values, got {len(vals)}:\n"
                       f"{r.stdout[-3000:]}{r.stderr[-3000:]}")
    mism = 0
    ref_mism = 0
    pos = 0
    for vec in vectors:
        cl = [v == "TRUE" for v in vals[pos:pos + NOUT]]
        lj = [v == "TRUE" for v in vals[pos + NOUT:pos + 2 * NOUT]]
        pos += 2 * NOUT
        mism += cl != lj
        ref_mism += cl != expected(n, [bool(v) for v in vec])
    cl_t, lj_t, lj_ns = [], [], []
    for _ in range(samples):
        cl_t.append(int(vals[pos]))
        lj_t.append(int(vals[pos + 1]))
        lj_ns.append(int(vals[pos + 2], 0))
        pos += 3
    cl_max, lj_max, ticks = int(vals[pos]), int(vals[pos + 1]), int(vals[pos + 2], 0)
    return dict(n=n, steps=steps, lj=None if not with_lj else statistics.median(lj_t), mism=mism, ref_mism=ref_mism,
                cl=statistics.median(cl_t),
                lj_ns=statistics.median(lj_ns), cl_max=cl_max, lj_max=lj_max, ticks=ticks)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    ap.add_argument("ladderjit")
    ap.add_argument("module")
    ap.add_argument("--sizes", default="100,1000,3000,5000")
    ap.add_argument("--steps", type=int, default=40)
    ap.add_argument("--samples", type=int, default=100)
    ap.add_argument("--period-ns", type=int, default=10000000)
    ap.add_argument("--dialect", choices=("fanuc", "hnc8"), default="fanuc")
    a = ap.parse_args()
    global DIALECT
    DIALECT = a.dialect
    try:
        rig = Rig(a.ladderjit, a.module)
    except RigError as e:
        print(f"error: {e}")
        return 1
    rows = []
    try:
        for n in (int(s) for s in a.sizes.split(",")):
            rows.append(run_size(rig, n, a.steps, a.samples, a.period_ns))
            r = rows[-1]
            if r["lj"] is None:
                print(f"{n} rungs: ClassicLadder only ({3 * n + 3} statements exceed the "
                      f"{DIALECT} limit of {STMT_LIMIT[DIALECT]}); outputs vs the rung definition mismatching in "
                      f"{r['ref_mism']}/{r['steps']} steps; median refresh.time "
                      f"{r['cl']:.0f}, tmax {r['cl_max']}", flush=True)
                continue
            print(f"{n} rungs: outputs CL vs ladderjit mismatching in {r['mism']}/{r['steps']} "
                  f"steps (CL vs the rung definition: {r['ref_mism']}); "
                  f"median refresh.time CL {r['cl']:.0f}, ladderjit {r['lj']:.0f} "
                  f"(ladderjit scan {r['lj_ns']:.0f} ns); tmax CL {r['cl_max']}, "
                  f"ladderjit {r['lj_max']}", flush=True)
    except RigError as e:
        print(f"error: {e}")
        return 1
    finally:
        rig.halrun(["-U"], timeout=30, check=False)
        rig.cleanup()
    print()
    print("| rungs | equal outputs (steps) | classicladder.0.refresh.time | ladderjit.refresh.time "
          "| ratio | ladderjit scan-time-ns | tmax CL / ladderjit |")
    print("|---|---|---|---|---|---|---|")
    for r in rows:
        if r["lj"] is None:
            print(f"| {r['n']:,} | CL only: {r['steps'] - r['ref_mism']}/{r['steps']} as defined "
                  f"| {r['cl']:,.0f} | over the {STMT_LIMIT[DIALECT]:,}-statement limit | | | "
                  f"{r['cl_max']:,} / - |")
            continue
        print(f"| {r['n']:,} | {r['steps'] - r['mism']}/{r['steps']} | {r['cl']:,.0f} | "
              f"{r['lj']:,.0f} | {r['cl'] / max(r['lj'], 1):.1f}x | {r['lj_ns']:,.0f} | "
              f"{r['cl_max']:,} / {r['lj_max']:,} |")
    return 0 if all(r["mism"] == 0 and r["ref_mism"] == 0 for r in rows) else 1


if __name__ == "__main__":
    sys.exit(main())

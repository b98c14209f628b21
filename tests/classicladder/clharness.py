#!/usr/bin/env python3
"""ClassicLadder as the oracle (issue 31; docs/classicladder.md "The oracle harness").

One `halrun` per project runs LinuxCNC's own ClassicLadder (`classicladder_rt`, the project
loaded by `classicladder --nogui`) period by period in one HAL thread, deterministically:

    streamer.N -> bitslice.K -> classicladder.0.refresh -> wsum (process_wsums) -> sampler.N

`streamer` plays a seeded random stimulus prepared in full before the thread starts (every
`in-NN` bit, 32 to a u32 unpacked by `bitslice`; every `s32in-NN`; every `floatin-NN`), one row
per period; `sampler` records every `out-NN` (31 to an s32 packed by `weighted_sum`), every
`s32out-NN` and `floatout-NN` in the same period. A 1 ms thread gives exactly one scan per call
(classicladder.md 4.1), so row k of the trace is the outputs after the k-th scan, whatever the
machine's load. The traces are CSV (`period,out-00,...,s32out-00,...,floatout-00,...`).

"The other side" is any command (phase 2: ladderjit) given as a template with {project},
{stimulus} (the CSV of inputs, `period,in-00,...,s32in-00,...,floatin-00,...`), {trace} (the CSV
it must write, same columns as ClassicLadder's) and {periods}; `compare` runs both and reports
every period and pin that differ.

Usage:
  clharness.py record  CLP_TOOL PROJECT OUTDIR [--periods N] [--seed S]
  clharness.py compare CLP_TOOL PROJECT OUTDIR --other 'CMD {project} {stimulus} {trace}'
  clharness.py real    CLP_TOOL ROOT OUTDIR [--periods N]     every .clp under ROOT, a table
  clharness.py gen     CLP_TOOL OUTDIR [--count N] [--periods N] [--seed S] [--rungs R]
  clharness.py dropin  CLP_TOOL LADDERJIT MODULE ROOT OUTDIR --real REL... --gen N
                       ClassicLadder against ladderjit's HAL drop-in (loadrt ladderjit with
                       the .clp) in the same HAL file, period by period
  clharness.py suite   CLP_TOOL ROOT OUTDIR --real REL... --gen N [--other CMD]
                       ClassicLadder against the other side (default: `clp_tool ref`, the
                       reference scan of oracle/classicladder) on real and generated projects
CLP_TOOL is build/tests/classicladder/clp_tool (project sizes, the generator)."""
import argparse
import csv
import json
import os
import random
import re
import shlex
import shutil
import subprocess
import sys
import tempfile
import time

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "hal"))
from halrig import RigError, install_module  # noqa: E402

PERIOD_NS = 1000000  # 1 ms: one scan per call (classicladder.md 4.1)
ITEMS = 20           # items per streamer/sampler channel (the components take at most 21)
IN_BITS = 32         # input bits a u32 item carries (bitslice: 32 outputs)
OUT_BITS = 31        # output bits an s32 item carries (weighted_sum; 2^31 would not fit)


class Hal:
    """A world-readable work directory and bounded halrun runs (tests/hal/halrig.py's set-up,
    without the ladderjit component)."""

    def __init__(self, workdir):
        for tool in ("halrun", "halcmd", "rtapi_app", "classicladder", "halstreamer",
                     "halsampler"):
            if shutil.which(tool) is None:
                raise RigError(f"'{tool}' not found: install linuxcnc-uspace")
        self.dir = workdir
        os.makedirs(self.dir, exist_ok=True)
        os.chmod(self.dir, 0o755)
        fifo = os.path.join(self.dir, "fifo")
        os.makedirs(fifo, exist_ok=True)
        os.chmod(fifo, 0o1777)
        self.env = dict(os.environ)
        if os.geteuid() == 0:
            self.env.setdefault("RTAPI_UID", "65534")
            self.env["RTAPI_FIFO_PATH"] = os.path.join(fifo, "rtapi_fifo")
        self.halrun(["-U"], timeout=30)

    def halrun(self, args, timeout):
        try:
            return subprocess.run(["halrun", *args], env=self.env, capture_output=True,
                                  text=True, timeout=timeout)
        except subprocess.TimeoutExpired:
            subprocess.run(["halrun", "-U"], env=self.env, capture_output=True, timeout=30)
            raise RigError(f"halrun {' '.join(args)} did not finish in {timeout} s")

    def write(self, name, text):
        p = os.path.join(self.dir, name)
        with open(p, "w") as f:
            f.write(text)
        os.chmod(p, 0o644)
        return p


def project_info(clp_tool, project):
    r = subprocess.run([clp_tool, "info", project], capture_output=True, text=True, timeout=60)
    if r.returncode != 0:
        raise RigError(f"clp_tool info {project} failed: {r.stderr}")
    return json.loads(r.stdout)


def pins(loadrt):
    """Input and output pin names of classicladder_rt loaded with these sizes."""
    ins = [f"in-{i:02d}" for i in range(loadrt["numPhysInputs"])]
    ins += [f"s32in-{i:02d}" for i in range(loadrt["numS32in"])]
    ins += [f"floatin-{i:02d}" for i in range(loadrt["numFloatIn"])]
    outs = [f"out-{i:02d}" for i in range(loadrt["numPhysOutputs"])]
    outs += [f"s32out-{i:02d}" for i in range(loadrt["numS32out"])]
    outs += [f"floatout-{i:02d}" for i in range(loadrt["numFloatOut"])]
    return ins, outs


def stimulus(ins, periods, seed):
    """Rows of input values: each pin keeps a value for a random number of periods (1 to a few
    thousand, so timers and counters run out), then changes."""
    rng = random.Random(seed)
    holds = (1, 3, 20, 200, 1500, 4000)
    value, left = {}, {}

    def fresh(p):
        if p.startswith("in-"):
            return 1 - value.get(p, rng.randint(0, 1))
        if p.startswith("s32in-"):
            return rng.randint(-3, 20) if rng.random() < 0.85 else rng.randint(-2**31, 2**31 - 1)
        return round(rng.uniform(-12.0, 12.0), 3)

    rows = []
    for _ in range(periods):
        row = []
        for p in ins:
            if left.get(p, 0) <= 0:
                value[p] = fresh(p)
                left[p] = rng.randint(1, rng.choice(holds))
            left[p] -= 1
            row.append(value[p])
        rows.append(row)
    return rows


def chunks(items):
    return [items[i:i + ITEMS] for i in range(0, len(items), ITEMS)] or [[]]


def hal_file(hal, project, loadrt, ins, outs, periods, stream_path, sample_paths, dropin=None):
    """The HAL commands of one oracle run, and the channel layouts. `dropin` (the .so and the
    trusted key): the same HAL file run on ladderjit's drop-in instead (docs/linuxcnc.md
    "ClassicLadder drop-in": the loadrt line replaced, the loader line gone)."""
    nbits_in = sum(p.startswith("in-") for p in ins)
    nbits_out = sum(p.startswith("out-") for p in outs)
    in_words = (nbits_in + IN_BITS - 1) // IN_BITS
    out_words = (nbits_out + OUT_BITS - 1) // OUT_BITS
    # streamer items: packed input words, then s32in, then floatin
    # the period number travels from the streamer to the sampler beside the pins: the sampled
    # index of row k must be k, which proves no row was lost, repeated (an underrun) or shifted
    s_items = [("u", "idx")] + [("u", f"w{k}") for k in range(in_words)]
    s_items += [("s", p) for p in ins if p.startswith("s32in-")]
    s_items += [("f", p) for p in ins if p.startswith("floatin-")]
    o_items = [("s", f"w{k}") for k in range(out_words)]
    o_items += [("s", p) for p in outs if p.startswith("s32out-")]
    o_items += [("f", p) for p in outs if p.startswith("floatout-")]
    s_ch = chunks(s_items)
    # every sampler channel records the period number too
    o_ch = [[("u", "idx")] + c for c in chunks(o_items)]
    if len(s_ch) > 8 or len(o_ch) > 8 or in_words > 8 or out_words > 8:
        raise RigError("more pins than 8 streamer/sampler channels, bitslices or weighted sums "
                       "carry")
    depth = periods + 64
    args = " ".join(f"{k}={v}" for k, v in loadrt.items())
    first = (f"loadrt ladderjit program={dropin['so']} source={project} trust={dropin['key']} "
             f"{args}" if dropin else f"loadrt classicladder_rt {args}")
    lines = [first,
             f"loadrt streamer depth={','.join([str(depth)] * len(s_ch))} "
             f"cfg={','.join(''.join(t for t, _ in c) for c in s_ch)}",
             f"loadrt sampler depth={','.join([str(depth)] * len(o_ch))} "
             f"cfg={','.join(''.join(t for t, _ in c) for c in o_ch)}"]
    if in_words:
        lines.append(f"loadrt bitslice count={in_words} "
                     f"personality={','.join([str(IN_BITS)] * in_words)}")
    if out_words:
        lines.append(f"loadrt weighted_sum wsum_sizes={','.join([str(OUT_BITS)] * out_words)}")
    lines.append(f"loadrt threads name1=plc period1={PERIOD_NS} fp1=1")
    lines += [f"addf streamer.{c} plc" for c in range(len(s_ch))]
    lines += [f"addf bitslice.{k} plc" for k in range(in_words)]
    lines.append("addf classicladder.0.refresh plc")
    if out_words:
        lines.append("addf process_wsums plc")
    lines += [f"addf sampler.{c} plc" for c in range(len(o_ch))]
    for c, chan in enumerate(s_ch):
        for i, (_, name) in enumerate(chan):
            src = f"streamer.{c}.pin.{i}"
            if name == "idx":
                lines.append(f"net s-idx {src}")
            elif name.startswith("w"):
                lines.append(f"net sw{name[1:]} {src} bitslice.{name[1:]}.in")
            else:
                lines.append(f"net s-{name} {src} classicladder.0.{name}")
    for b in range(nbits_in):
        lines.append(f"net s-in-{b:02d} bitslice.{b // IN_BITS}.out-{b % IN_BITS:02d} "
                     f"classicladder.0.in-{b:02d}")
    for b in range(nbits_out):
        lines.append(f"net s-out-{b:02d} classicladder.0.out-{b:02d} "
                     f"wsum.{b // OUT_BITS}.bit.{b % OUT_BITS}.in")
    for c, chan in enumerate(o_ch):
        for i, (_, name) in enumerate(chan):
            dst = f"sampler.{c}.pin.{i}"
            if name == "idx":
                lines.append(f"net s-idx {dst}")
            elif name.startswith("w"):
                lines.append(f"net ow{name[1:]} wsum.{name[1:]}.sum {dst}")
            else:
                lines.append(f"net s-{name} classicladder.0.{name} {dst}")
    if not dropin:
        lines.append(f"loadusr -w classicladder --nogui {project}")
    for c in range(len(s_ch)):
        lines.append(f"loadusr -w halstreamer -c {c} {stream_path[c]}")
    lines.append("start")
    for c in range(len(o_ch)):
        lines.append(f"loadusr -w halsampler -c {c} -n {periods} {sample_paths[c]}")
    lines.append("stop")
    # published by the refresh function while the thread runs (2 = RUN)
    lines.append("getp classicladder.ladder-state")
    # (a sampler channel read after another one overruns once its FIFO is full, which drops
    # samples after the first `depth`: the period numbers in every row prove the first ones)
    return lines, s_ch, o_ch


def write_csv(path, header, rows, periods_from=1):
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["period", *header])
        for k, row in enumerate(rows):
            w.writerow([k + periods_from, *row])


def fmt(v):
    return f"{v:.6f}" if isinstance(v, float) else str(v)


def record(clp_tool, project, outdir, periods, seed, hal=None, ladderjit=None):
    """ClassicLadder's trace of `project`: returns dict(ok, reason, stimulus, trace, seconds).
    With `ladderjit` (the driver): the same run on ladderjit's HAL drop-in, the project compiled
    with `ladderjit compile` and signed with a key of the run's own (trace ladderjit-hal.csv)."""
    os.makedirs(outdir, exist_ok=True)
    info = project_info(clp_tool, project)
    if not info["ok"]:
        return dict(ok=False, reason="ladderjit's reader refuses it: " + info["error"])
    if info.get("upstream"):
        return dict(ok=False, reason="an upstream 0.9 .clprj: LinuxCNC does not load it")
    loadrt = info["loadrt"]
    ins, outs = pins(loadrt)
    rows = stimulus(ins, periods, seed)
    hal = hal or Hal(tempfile.mkdtemp(prefix="clharness-"))
    proj = os.path.join(hal.dir, "project.clp")
    shutil.copyfile(project, proj)
    os.chmod(proj, 0o644)
    dropin = None
    if ladderjit:
        keys = os.path.join(hal.dir, "keys")
        so = os.path.join(hal.dir, "project.so")
        env = dict(hal.env, LADDERJIT_KEY_DIR=keys, LADDERJIT_CACHE="off")
        r = subprocess.run([ladderjit, "compile", proj, "-o", so], env=env, capture_output=True,
                           text=True, timeout=300)
        if r.returncode != 0:
            return dict(ok=False, reason="ladderjit compile failed: " + (r.stdout + r.stderr)[-800:])
        os.chmod(so, 0o644)
        os.chmod(keys, 0o755)  # rtapi_app reads the public key as its fallback user
        dropin = dict(so=so, key=os.path.join(keys, "aot-signing.pub"))
    # streamer files, one per channel, in channel item order
    lines, s_ch, o_ch = hal_file(hal, proj, loadrt, ins, outs, periods,
                                 [os.path.join(hal.dir, f"stream{c}.txt") for c in range(8)],
                                 [os.path.join(hal.dir, f"sample{c}.txt") for c in range(8)],
                                 dropin)
    col = {p: i for i, p in enumerate(ins)}
    for c, chan in enumerate(s_ch):
        out = []
        for row in rows:
            vals = []
            for t, name in chan:
                if name == "idx":
                    vals.append(str(len(out) + 1))
                elif name.startswith("w"):
                    k = int(name[1:])
                    word = 0
                    for b in range(IN_BITS):
                        p = f"in-{k * IN_BITS + b:02d}"
                        if p in col and row[col[p]]:
                            word |= 1 << b
                    vals.append(str(word))
                else:
                    vals.append(fmt(row[col[name]]))
            out.append(" ".join(vals))
        hal.write(f"stream{c}.txt", "\n".join(out) + "\n")
    for c in range(len(o_ch)):
        p = os.path.join(hal.dir, f"sample{c}.txt")
        if os.path.exists(p):
            os.remove(p)
    t0 = time.time()
    r = hal.halrun(["-f", hal.write("oracle.hal", "\n".join(lines) + "\n")],
                   timeout=120 + periods * PERIOD_NS * 20 // 10**9)
    seconds = time.time() - t0
    log = r.stdout + r.stderr
    if r.returncode != 0:
        tail = "\n".join(l for l in log.splitlines() if "fallback_uid" not in l)[-1500:]
        return dict(ok=False, reason=f"halrun failed ({r.returncode}):\n{tail}")
    nums = [l.strip() for l in r.stdout.splitlines() if re.fullmatch(r"-?\d+", l.strip())]
    if not nums:
        return dict(ok=False, reason=f"unexpected halrun output:\n{log[-1500:]}")
    state = int(nums[-1])
    if state != 2:
        return dict(ok=False, reason=f"ladder-state {state} after loading (2 = RUN):\n"
                                     f"{log[-800:]}")
    # unpack the samples into the trace
    per_chan = []
    for c, chan in enumerate(o_ch):
        with open(os.path.join(hal.dir, f"sample{c}.txt")) as f:
            got = [l.split() for l in f.read().splitlines() if l.strip()]
        if len(got) != periods or any(len(g) != len(chan) for g in got):
            return dict(ok=False, reason=f"sampler channel {c}: {len(got)} rows")
        per_chan.append(got)
    trace = []
    for k in range(periods):
        named = {}
        for c, chan in enumerate(o_ch):
            for i, (t, name) in enumerate(chan):
                v = per_chan[c][k][i]
                if name == "idx":
                    if int(v) != k + 1:
                        return dict(ok=False, reason=f"period {k + 1} sampled the stimulus row "
                                                     f"{v}: the run was not in step")
                elif name.startswith("w"):
                    w = int(v)
                    for b in range(OUT_BITS):
                        named[f"out-{int(name[1:]) * OUT_BITS + b:02d}"] = (w >> b) & 1
                else:
                    named[name] = float(v) if t == "f" else int(v)
        trace.append([fmt(named[p]) for p in outs])
    stim_csv = os.path.join(outdir, "stimulus.csv")
    trace_csv = os.path.join(outdir, "ladderjit-hal.csv" if ladderjit else "classicladder.csv")
    write_csv(stim_csv, ins, [[fmt(v) for v in row] for row in rows])
    write_csv(trace_csv, outs, trace)
    return dict(ok=True, stimulus=stim_csv, trace=trace_csv, seconds=seconds, outs=outs,
                ins=ins, warnings=info["warnings"], hal=hal)


def read_csv(path):
    with open(path) as f:
        rows = list(csv.reader(f))
    return rows[0], rows[1:]


def diff(trace_a, trace_b, limit=20):
    """Every (period, pin, a, b) where the traces differ (numbers compared as numbers)."""
    ha, ra = read_csv(trace_a)
    hb, rb = read_csv(trace_b)
    if ha != hb:
        return [("header", "", " ".join(ha), " ".join(hb))], 1
    out, n = [], 0
    if len(ra) != len(rb):
        out.append(("rows", "", str(len(ra)), str(len(rb))))
        n += 1
    for a, b in zip(ra, rb):
        for name, x, y in zip(ha[1:], a[1:], b[1:]):
            if float(x) != float(y):
                n += 1
                if len(out) < limit:
                    out.append((a[0], name, x, y))
    return out, n


def cmd_compare(a):
    rec = record(a.clp_tool, a.project, a.outdir, a.periods, a.seed)
    if not rec["ok"]:
        print(f"ClassicLadder did not run {a.project}: {rec['reason']}")
        return 1
    other = os.path.join(a.outdir, "other.csv")
    cmd = a.other.format(project=shlex.quote(a.project), stimulus=shlex.quote(rec["stimulus"]),
                         trace=shlex.quote(other), periods=a.periods)
    r = subprocess.run(cmd, shell=True, capture_output=True, text=True, timeout=3600)
    if r.returncode != 0:
        print(f"the other side failed ({r.returncode}): {r.stdout}{r.stderr}")
        return 1
    diffs, n = diff(rec["trace"], other)
    print(f"{a.project}: {a.periods} periods x {len(rec['outs'])} output pins, "
          f"{n} differences")
    for d in diffs:
        print("  period {} {}: ClassicLadder {} other {}".format(*d))
    return 0 if n == 0 else 1


def compare_one(clp_tool, project, outdir, periods, seed, other, hal):
    """ClassicLadder against `other` on one project: the number of differences (None: not run)."""
    rec = record(clp_tool, project, outdir, periods, seed, hal)
    if not rec["ok"]:
        print(f"{project}: ClassicLadder did not run it: {rec['reason']}")
        return None
    trace = os.path.join(outdir, "other.csv")
    cmd = other.format(project=shlex.quote(project), stimulus=shlex.quote(rec["stimulus"]),
                       trace=shlex.quote(trace), periods=periods)
    r = subprocess.run(cmd, shell=True, capture_output=True, text=True, timeout=3600)
    if r.returncode != 0:
        print(f"{project}: the other side failed ({r.returncode}): {r.stdout}{r.stderr}")
        return -1
    diffs, n = diff(rec["trace"], trace)
    changed, changes = activity(rec["trace"])
    print(f"{project}: {periods} periods x {len(rec['outs'])} output pins ({changed} changing, "
          f"{changes} changes): {n} differences", flush=True)
    for d in diffs:
        print("  period {} {}: ClassicLadder {} other {}".format(*d))
    return n


def generate(clp_tool, outdir, seed, rungs=8):
    """A generated project `outdir/gen<seed>.clp` (clp_tool gen), its path."""
    clp = os.path.join(outdir, f"gen{seed}.clp")
    os.makedirs(outdir, exist_ok=True)
    subprocess.run([clp_tool, "gen", str(seed), clp, str(rungs)], check=True, timeout=60)
    return clp


def selected_projects(a):
    """(path, name, seed, trace folder) of `--real` projects under ROOT (seed 1 + index) and of
    `--gen` generated ones (seeds from `--seed`); a trace folder is never a project's own name."""
    projects = [(os.path.join(a.root, rel), rel, 1 + i) for i, rel in enumerate(a.real)]
    for k in range(a.gen):
        seed = a.seed + k
        projects.append((generate(a.clp_tool, a.outdir, seed), f"gen{seed}.clp", seed))
    return [(path, rel, seed,
             os.path.join(a.outdir, re.sub(r"\.clp$", "", rel.replace("/", "__"))))
            for path, rel, seed in projects]


def add_selection(s):
    """The project selection `suite` and `dropin` share (selected_projects)."""
    s.add_argument("root")
    s.add_argument("outdir")
    s.add_argument("--real", nargs="*", default=[], help="projects relative to ROOT")
    s.add_argument("--gen", type=int, default=0)
    s.add_argument("--periods", type=int, default=2000)
    s.add_argument("--seed", type=int, default=1)


def cmd_suite(a):
    """The CI-sized check: the listed real projects and `--gen` generated ones, ClassicLadder
    against the other side (default: clp_tool's reference scan); fails on any difference."""
    other = a.other or f"{shlex.quote(a.clp_tool)} ref {{project}} {{stimulus}} {{trace}}"
    projects = selected_projects(a)
    hal = Hal(tempfile.mkdtemp(prefix="clharness-"))
    bad = 0
    try:
        for path, _rel, seed, out in projects:
            bad += compare_one(a.clp_tool, path, out, a.periods, seed, other, hal) != 0
    finally:
        shutil.rmtree(hal.dir, ignore_errors=True)
    print(f"{len(projects)} projects, {bad} with differences or not run")
    return 1 if bad else 0


def cmd_dropin(a):
    """ClassicLadder against ladderjit's HAL drop-in, both in the same kind of HAL thread with
    the same streamed inputs, period by period: real projects under ROOT and generated ones.
    Fails on any difference or any project that does not run."""
    install_module(a.module)
    projects = selected_projects(a)
    hal = Hal(tempfile.mkdtemp(prefix="cldropin-"))
    bad = 0
    try:
        for path, rel, seed, out in projects:
            cl = record(a.clp_tool, path, out, a.periods, seed, hal)
            lj = record(a.clp_tool, path, out, a.periods, seed, hal, ladderjit=a.ladderjit) \
                if cl["ok"] else cl
            if not cl["ok"] or not lj["ok"]:
                bad += 1
                side = "ClassicLadder" if not cl["ok"] else "ladderjit's drop-in"
                print(f"{rel}: {side} did not run it: {(cl if not cl['ok'] else lj)['reason']}")
                continue
            diffs, n = diff(cl["trace"], lj["trace"])
            changed, changes = activity(cl["trace"])
            print(f"{rel}: {a.periods} periods x {len(cl['outs'])} output pins ({changed} changing, "
                  f"{changes} changes): {n} differences (classicladder_rt {cl['seconds']:.1f} s, "
                  f"ladderjit {lj['seconds']:.1f} s)", flush=True)
            for d in diffs:
                print("  period {} {}: ClassicLadder {} ladderjit {}".format(*d))
            bad += n != 0
    finally:
        shutil.rmtree(hal.dir, ignore_errors=True)
    print(f"{len(projects)} projects, {bad} with differences or not run")
    return 1 if bad else 0


def cmd_record(a):
    rec = record(a.clp_tool, a.project, a.outdir, a.periods, a.seed)
    if not rec["ok"]:
        print(f"{a.project}: not run: {rec['reason']}")
        return 1
    print(f"{a.project}: {a.periods} periods recorded in {rec['seconds']:.1f} s -> {rec['trace']}")
    return 0


def activity(trace):
    """How many output pins change at least once, and the number of changes."""
    h, rows = read_csv(trace)
    pins_changed, changes = 0, 0
    for j in range(1, len(h)):
        c = sum(1 for k in range(1, len(rows)) if rows[k][j] != rows[k - 1][j])
        changes += c
        pins_changed += c > 0
    return pins_changed, changes


def cmd_real(a):
    projects = []
    for root, _, files in os.walk(a.root):
        projects += [os.path.join(root, f) for f in files if f.endswith(".clp")]
    projects.sort()
    failures = 0
    hal = Hal(tempfile.mkdtemp(prefix="clharness-"))
    print("| project | result | periods | output pins (changing) | output changes | seconds |")
    print("|---|---|---|---|---|---|")
    for i, p in enumerate(projects):
        rel = os.path.relpath(p, a.root)
        out = os.path.join(a.outdir, rel.replace("/", "__"))
        rec = record(a.clp_tool, p, out, a.periods, a.seed + i, hal)
        if not rec["ok"]:
            failures += 1
            reason = rec["reason"].strip().splitlines()
            print(f"| {rel} | not run: {reason[0][:200]} | | | | |", flush=True)
            for l in reason[1:6]:
                print(f"|   | {l[:200]} | | | | |", flush=True)
            continue
        changed, changes = activity(rec["trace"])
        print(f"| {rel} | recorded | {a.periods} | {len(rec['outs'])} ({changed}) | {changes} | "
              f"{rec['seconds']:.1f} |", flush=True)
    shutil.rmtree(hal.dir, ignore_errors=True)
    return 0 if failures == 0 or a.allow_failures else 1


def cmd_gen(a):
    hal = Hal(tempfile.mkdtemp(prefix="clharness-"))
    loaded = 0
    for k in range(a.count):
        seed = a.seed + k
        clp = generate(a.clp_tool, a.outdir, seed, a.rungs)
        rec = record(a.clp_tool, clp, os.path.join(a.outdir, f"gen{seed}"), a.periods, seed, hal)
        if rec["ok"]:
            loaded += 1
            changed, changes = activity(rec["trace"])
            print(f"seed {seed}: loaded and ran {a.periods} periods; {changed} of "
                  f"{len(rec['outs'])} outputs change ({changes} changes)", flush=True)
        else:
            print(f"seed {seed}: NOT loaded: {rec['reason']}", flush=True)
    shutil.rmtree(hal.dir, ignore_errors=True)
    print(f"{loaded} of {a.count} generated projects loaded and ran in ClassicLadder")
    return 0 if loaded == a.count else 1


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawTextHelpFormatter)
    sub = ap.add_subparsers(dest="cmd", required=True)
    for name in ("record", "compare"):
        s = sub.add_parser(name)
        s.add_argument("clp_tool")
        s.add_argument("project")
        s.add_argument("outdir")
        s.add_argument("--periods", type=int, default=10000)
        s.add_argument("--seed", type=int, default=1)
        if name == "compare":
            s.add_argument("--other", required=True,
                           help="command template: {project} {stimulus} {trace} {periods}")
    s = sub.add_parser("real")
    s.add_argument("clp_tool")
    s.add_argument("root")
    s.add_argument("outdir")
    s.add_argument("--periods", type=int, default=10000)
    s.add_argument("--seed", type=int, default=1)
    s.add_argument("--allow-failures", action="store_true")
    s = sub.add_parser("suite")
    s.add_argument("clp_tool")
    add_selection(s)
    s.add_argument("--other", default="")
    s = sub.add_parser("dropin")
    s.add_argument("clp_tool")
    s.add_argument("ladderjit")
    s.add_argument("module", help="the built HAL component (ladderjit.so)")
    add_selection(s)
    s = sub.add_parser("gen")
    s.add_argument("clp_tool")
    s.add_argument("outdir")
    s.add_argument("--count", type=int, default=50)
    s.add_argument("--periods", type=int, default=2000)
    s.add_argument("--seed", type=int, default=1)
    s.add_argument("--rungs", type=int, default=8)
    a = ap.parse_args()
    try:
        return {"record": cmd_record, "compare": cmd_compare, "real": cmd_real,
                "gen": cmd_gen, "suite": cmd_suite, "dropin": cmd_dropin}[a.cmd](a)
    except RigError as e:
        print(f"error: {e}")
        return 1


if __name__ == "__main__":
    sys.exit(main())

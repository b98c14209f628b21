#!/usr/bin/env python3
"""`run --vcd` of every example in examples/ (HNC-8, FANUC, IEC) read back by other programs
and compared, value by value and tick by tick, with the same run's `--watch` table
(docs/trace.md "run --vcd"; issue 32 scope 3).

For each example:
  1. `run ... --watch LIST` prints the watch table (the reference);
  2. `run ... --watch LIST --vcd A.vcd --vcd-bits` is read back by `sigrok-cli -i A.vcd -O csv`
     (Debian's libsigrok 0.5 reads 1-bit wires only, hence --vcd-bits); each element is put
     together again from its bit columns NAME[0].. and compared with the table;
  3. `run ... --watch LIST --vcd B.vcd` (one vector per byte/word, what GTKWave shows) is read
     by the small IEEE 1364 reader below and compared with the table as well.
A value is compared as the two's complement bits of its width (a signed -1 of a 16-bit word
is 0xFFFF in a VCD). sigrok-cli missing is a FAILURE (install it with scripts/setup-test.sh).

usage: vcd_sigrok.py LADDERJIT SOURCE_DIR WORK_DIR
"""
import os
import shutil
import subprocess
import sys

# program, run options, watch list (bits and elements of every width the example has)
EXAMPLES = [
    ("lathe_panel.stl", ["--ticks", "100", "--stimulus", "lathe_panel.stim"],
     "R0,G2620,G2564,Y480.0,Y480.2,Y480.3,Y0.0,Y0.1,G2622.0,Y0.2"),
    ("lathe_panel.dit", ["--ticks", "100", "--stimulus", "lathe_panel.stim"],
     "R0,G2620,Y480.2,Y0.0,Y0.1"),
    ("coolant_lube.stl", ["--ticks", "100", "--period-ms", "10", "--params", "coolant_lube.params",
                          "--stimulus", "coolant_lube.stim"],
     "R10.0,Y0.3,T2,Y481.5,Y0.4,R20.2,T11,Y481.6,G3010.0,D10,D11,D12"),
    ("part_counter.stl", ["--ticks", "100", "--params", "part_counter.params",
                          "--stimulus", "part_counter.stim"],
     "R32.0,R30.0,B0,G2579,C5,C6,Y481.2,Y481.3,D40,D41,Y481.5"),
    ("mcode_handshake.stl", ["--ticks", "25", "--stimulus", "mcode_handshake.stim"],
     "F2608,G2608,F2609,G2609,R0.0,G2570,F402.14,F402.15,Y0.0,Y0.1"),
    ("tool_change.stl", ["--ticks", "55", "--stimulus", "tool_change.stim"],
     "F2616,G2616,D5,D7,D6,R6.1,R6.2,C1,Y1.0"),
    ("catalogue.stl", ["--ticks", "40", "--stimulus", "catalogue.stim"],
     "X1,X3,F2608,F2616,D0,D1,D2,B3,R27,R0,Y0,Y1"),
    ("fanuc_coolant.pmc", ["--ticks", "1300", "--period-ms", "8", "--stimulus",
                           "fanuc_coolant.stim"],
     "Y0.0,Y0.1,Y0.2,G4.3,Y0"),
    ("fanuc_tool_change.pmc", ["--ticks", "1000", "--period-ms", "8", "--set", "D14:2=255",
                               "--stimulus", "fanuc_tool_change.stim"],
     "Y1.0,Y1.1,G4.3,A0.0,R20,D12:2,D14:2"),
    ("fanuc_magazine.pmc", ["--ticks", "52", "--period-ms", "8", "--stimulus",
                            "fanuc_magazine.stim"],
     "R41,R42,R30.1,Y2.0,Y2.1,Y2.2,G4.3,A0.1"),
    ("conveyor.il", ["--ticks", "18", "--stimulus", "conveyor.stim"],
     "%Q0.0,%Q0.1,%Q0.2,%MW0"),
    ("filler.il", ["--ticks", "37", "--period-ms", "100", "--stimulus", "filler.stim"],
     "%Q0.0,%Q0.1,%Q0.2,%TM0.V,%C0.V"),
    ("pump_station.il", ["--ticks", "20", "--stimulus", "pump_station.stim"],
     "%M1,%M2,%Q0.0,%Q0.1,%Q0.2,%Q0.3,%MW1,%MW2"),
]

PROGRAM_EXTENSIONS = (".stl", ".dit", ".pmc", ".il")
UNITS_NS = {"s": 10**9, "ms": 10**6, "us": 10**3, "ns": 1}

failures = []


def fail(msg):
    failures.append(msg)
    print("FAIL: " + msg, file=sys.stderr)


def run(cmd):
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != 0:
        raise RuntimeError("%s exited %d: %s" % (" ".join(cmd), p.returncode, p.stderr))
    return p.stdout


def watch_table(text):
    lines = text.strip().split("\n")
    names = lines[0].split(",")[1:]
    rows = []
    for i, line in enumerate(lines[1:]):
        cells = line.split(",")
        assert int(cells[0]) == i, "tick column"
        rows.append([int(c) for c in cells[1:]])
    return names, rows


def parse_vcd(text):
    """A reader of the IEEE 1364 subset: header sections, #time, scalar and b-vector changes."""
    tokens = text.split()
    i = 0
    timescale = None
    var_of = {}  # id -> (name, width)
    order = []
    while i < len(tokens):
        t = tokens[i]
        if t == "$enddefinitions":
            i += 2
            break
        if t == "$timescale":
            j = tokens.index("$end", i)
            timescale = "".join(tokens[i + 1:j])
            i = j + 1
        elif t == "$var":
            j = tokens.index("$end", i)
            _, width, ident, name = tokens[i + 1:i + 5]
            var_of[ident] = (name, int(width))
            order.append(ident)
            i = j + 1
        elif t.startswith("$"):
            i = tokens.index("$end", i) + 1
        else:
            raise ValueError("unexpected header token " + t)
    changes = []  # (time, id, value)
    now = None
    while i < len(tokens):
        t = tokens[i]
        if t.startswith("#"):
            now = int(t[1:])
            i += 1
        elif t[0] in "bB":
            changes.append((now, tokens[i + 1], int(t[1:], 2)))
            i += 2
        elif t[0] in "01":
            changes.append((now, t[1:], int(t[0])))
            i += 1
        else:
            raise ValueError("unexpected value token " + t)
    return timescale, var_of, order, changes, now


def unit_ns(timescale):
    for suffix in ("ms", "us", "ns", "s"):
        if timescale.endswith(suffix):
            return int(timescale[:-len(suffix)]) * UNITS_NS[suffix]
    raise ValueError("timescale " + timescale)


def check_vector_vcd(label, path, names, widths, rows, period_ns):
    timescale, var_of, order, changes, end = parse_vcd(open(path).read())
    per_tick = period_ns // unit_ns(timescale)
    if per_tick * unit_ns(timescale) != period_ns:
        fail("%s: timescale %s does not divide the period %d ns" % (label, timescale, period_ns))
        return
    got_names = [var_of[i][0] for i in order]
    if got_names != names:
        fail("%s: VCD variables %s, watch columns %s" % (label, got_names, names))
        return
    for ident, w in zip(order, widths):
        if var_of[ident][1] != w:
            fail("%s: %s declared %d bits, expected %d" % (label, var_of[ident][0],
                                                          var_of[ident][1], w))
    if end != len(rows) * per_tick:
        fail("%s: VCD ends at %s, expected %d" % (label, end, len(rows) * per_tick))
    value = {}
    ci = 0
    for tick, row in enumerate(rows):
        while ci < len(changes) and changes[ci][0] <= tick * per_tick:
            if changes[ci][0] % per_tick != 0:
                fail("%s: change at %d, between ticks" % (label, changes[ci][0]))
            value[changes[ci][1]] = changes[ci][2]
            ci += 1
        for col, ident in enumerate(order):
            want = row[col] & ((1 << widths[col]) - 1)
            if value.get(ident) != want:
                fail("%s: tick %d %s: VCD %s, watch %d" % (label, tick, names[col],
                                                          value.get(ident), row[col]))
                return


def check_sigrok(label, sigrok, path, names, widths, rows, period_ns, timescale_ns):
    per_tick = period_ns // timescale_ns
    out = run([sigrok, "-i", path, "-O", "csv:label=channel:header=false:dedup=false"])
    lines = [l for l in out.split("\n") if l and not l.startswith(";")
             and not l.startswith("META")]
    header = lines[0].split(",")
    data = lines[1:]
    if len(data) != len(rows) * per_tick:
        fail("%s: sigrok-cli gave %d samples, expected %d ticks x %d" % (label, len(data),
                                                                        len(rows), per_tick))
        return
    column = {}
    for k, name in enumerate(header):
        column[name] = k
    for col, (name, w) in enumerate(zip(names, widths)):
        want_cols = [name] if w == 1 else ["%s[%d]" % (name, b) for b in range(w)]
        missing = [c for c in want_cols if c not in column]
        if missing:
            fail("%s: sigrok-cli has no channel %s (channels: %s)" % (label, missing[0],
                                                                    ",".join(header)))
            return
    for tick, row in enumerate(rows):
        for sample in range(per_tick):  # every sample of the tick holds the tick's value
            cells = data[tick * per_tick + sample].split(",")
            for col, (name, w) in enumerate(zip(names, widths)):
                if w == 1:
                    got = int(cells[column[name]])
                else:
                    got = 0
                    for b in range(w):
                        got |= int(cells[column["%s[%d]" % (name, b)]]) << b
                want = row[col] & ((1 << w) - 1)
                if got != want:
                    fail("%s: tick %d (sample %d) %s: sigrok-cli %d, watch %d" %
                         (label, tick, sample, name, got, row[col]))
                    return


def main():
    ladderjit, src, work = sys.argv[1:4]
    sigrok = shutil.which("sigrok-cli")
    if not sigrok:
        print("FAIL: sigrok-cli is not installed; the VCD round trip needs it "
              "(scripts/setup-test.sh installs the Debian package sigrok-cli)", file=sys.stderr)
        return 1
    os.makedirs(work, exist_ok=True)
    examples = os.path.join(src, "examples")
    listed = {e[0] for e in EXAMPLES}
    for f in sorted(os.listdir(examples)):
        if f.endswith(PROGRAM_EXTENSIONS) and f not in listed:
            fail("examples/%s has no entry in EXAMPLES: every example is checked" % f)
    dialects = set()
    for program, opts, watch in EXAMPLES:
        opts = [os.path.join(examples, o) if os.path.exists(os.path.join(examples, o)) else o
                for o in opts]
        base = [ladderjit, "run", os.path.join(examples, program), "--engine", "interp"] + opts
        names, rows = watch_table(run(base + ["--watch", watch]))
        period_ms = int(opts[opts.index("--period-ms") + 1]) if "--period-ms" in opts else 1
        period_ns = period_ms * 10**6
        # The widths the VCD declares, from the addresses' areas (docs/trace.md): here read from
        # the vector file's declarations and checked against the table's columns.
        vec = os.path.join(work, program + ".vcd")
        bits = os.path.join(work, program + ".bits.vcd")
        for path, extra in ((vec, []), (bits, ["--vcd-bits"])):
            table = run(base + ["--watch", watch, "--vcd", path] + extra)
            if watch_table(table) != (names, rows):
                fail("%s: --vcd changed the watch table" % program)
        timescale, var_of, order, _, _ = parse_vcd(open(vec).read())
        widths = [var_of[i][1] for i in order]
        for name, w in zip(names, widths):
            if w not in (1, 8, 16, 32):
                fail("%s: %s has width %d" % (program, name, w))
            if not name.startswith("%") and ("." in name) != (w == 1):  # HNC-8, FANUC
                fail("%s: %s: a bit must be a 1-bit wire, an element a vector (%d)" %
                     (program, name, w))
        check_vector_vcd(program, vec, names, widths, rows, period_ns)
        check_sigrok(program, sigrok, bits, names, widths, rows, period_ns, unit_ns(timescale))
        dialects.add(os.path.splitext(program)[1])
        print("%s: %d ticks x %d signals agree (timescale %s)" % (program, len(rows),
                                                                  len(names), timescale))
    if not {".stl", ".pmc", ".il"} <= dialects:
        fail("not every dialect was checked")
    if failures:
        print("%d failure(s)" % len(failures), file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())

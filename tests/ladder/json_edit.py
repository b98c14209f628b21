#!/usr/bin/env python3
"""A FANUC and an IEC network JSON with edited rungs run their edits (docs/ladder-json.md "Other
dialects"): `ladderjit ladder --format json` of a small program, the JSON edited as an editor would
(an operand of a contact, the instruction of a coil, in the dialect's words), then `ladderjit run`
of the JSON on interp and jit. The expected outputs are the manuals' meaning of the edited rungs
(FANUC WRT.NOT writes the inverted result, fanuc-pmc.md 5; IL STN likewise, modicon-neza.md 2),
and the unedited JSON must run as its program. Usage: json_edit.py LADDERJIT WORK_DIR"""
import json, pathlib, subprocess, sys

exe, work = sys.argv[1], pathlib.Path(sys.argv[2])
work.mkdir(parents=True, exist_ok=True)

CASES = {
    # X0.0 = 1, X0.1 = 0, X0.2 = 1. Rung 1: Y0.0 := X0.0 AND X0.1 (0), edited to X0.2 (1).
    # Rung 2: Y0.1 := X0.0 (1), edited to WRT.NOT (0).
    "fanuc": {
        "file": "edit.pmc",
        "text": "; rung 1\nRD X0.0\nAND X0.1\nWRT Y0.0\n; rung 2\nRD X0.0\nWRT Y0.1   ; lamp\n"
                "END1\nEND2\nEND\n",
        "set": ["X0.0=1", "X0.2=1"],
        "watch": "Y0.0,Y0.1",
        "contact": ("X0.1", "X0.2"), "coil": ("Y0.1", "WRT", "WRT.NOT"),
        "before": [0, 1], "after": [1, 0],
    },
    # %I0.0 = 1, %I0.1 = 0, %I0.2 = 1: the same two rungs in IL.
    "iec": {
        "file": "edit.il",
        "text": "(* rung 1 *)\n000 LD %I0.0\n001 AND %I0.1\n002 ST %Q0.0\n(* rung 2 *)\n"
                "003 LD %I0.0\n004 ST %Q0.1 (* lamp *)\n",
        "set": ["%I0.0=1", "%I0.2=1"],
        "watch": "%Q0.0,%Q0.1",
        "contact": ("%I0.1", "%I0.2"), "coil": ("%Q0.1", "ST", "STN"),
        "before": [0, 1], "after": [1, 0],
    },
}

def walk(node):
    if isinstance(node, dict):
        yield node
        for v in node.values(): yield from walk(v)
    elif isinstance(node, list):
        for v in node: yield from walk(v)

def run(prog, case, engine):
    args = [exe, "run", str(prog), "--engine", engine, "--ticks", "3", "--watch", case["watch"]]
    for s in case["set"]: args += ["--set", s]
    r = subprocess.run(args, capture_output=True, text=True)
    if r.returncode != 0:
        raise SystemExit(f"FAIL: {' '.join(args)}: exit {r.returncode}\n{r.stdout}{r.stderr}")
    last = [l for l in r.stdout.splitlines() if l.strip()][-1].split(",")
    return [int(v) for v in last[-2:]], r.stdout

failed = 0
for dialect, case in CASES.items():
    src = work / case["file"]
    src.write_text(case["text"])
    js = work / (case["file"] + ".json")
    subprocess.run([exe, "ladder", str(src), "--format", "json", "-o", str(js)], check=True)
    doc = json.loads(js.read_text())
    edited = 0
    for n in walk(doc["parts"]):
        ops = n.get("operands") or []
        if n.get("type") == "contact" and ops and ops[0]["text"] == case["contact"][0]:
            ops[0]["text"] = case["contact"][1]
            edited += 1
        if n.get("type") == "coil" and ops and ops[0]["text"] == case["coil"][0]:
            if n["instr"] != case["coil"][1]:
                print(f"FAIL {dialect}: coil named {n['instr']!r}, not the dialect's {case['coil'][1]!r}")
                failed += 1
            n["instr"] = case["coil"][2]
            edited += 1
    if edited != 2:
        print(f"FAIL {dialect}: {edited} places edited, expected 2")
        failed += 1
    ed = work / (case["file"] + ".edited.json")
    ed.write_text(json.dumps(doc, indent=1))
    for engine in ("interp", "jit"):
        for prog, want in ((src, case["before"]), (js, case["before"]), (ed, case["after"])):
            got, out = run(prog, case, engine)
            if got != want:
                print(f"FAIL {dialect} {engine} {prog.name}: {case['watch']} = {got}, expected {want}\n{out}")
                failed += 1
print(f"json edit: {len(CASES)} dialects, {failed} failed")
sys.exit(1 if failed else 0)

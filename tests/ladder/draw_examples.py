#!/usr/bin/env python3
"""Every example drawn (ladderjit ladder --format layout|html|svg): per part the same rungs as the
verified program's networks (--format json), every statement id of the networks placed in the
layout (as a cell's stmt, among the statements a cell drawn as written covers, or hidden as the
front end's own) and every cell's stmt present as data-stmt in the HTML; HNC-8, IEC and FANUC
examples. Prints 'N passed, N failed'."""
import json, re, subprocess, sys, pathlib

exe, examples = sys.argv[1], pathlib.Path(sys.argv[2])
passed = failed = 0

def ids(node, out):
    if isinstance(node, dict):
        if isinstance(node.get("id"), int): out.add(node["id"])
        if isinstance(node.get("link"), dict) and isinstance(node["link"].get("id"), int):
            out.add(node["link"]["id"])
        for v in node.values(): ids(v, out)
    elif isinstance(node, list):
        for v in node: ids(v, out)

files = sorted(examples.glob("*.stl")) + sorted(examples.glob("*.il")) + sorted(examples.glob("*.pmc"))
for stl in files:
    run = lambda fmt: subprocess.run([exe, "ladder", str(stl), "--format", fmt], check=True,
                                     capture_output=True, text=True).stdout
    nets, lay, html = json.loads(run("json")), json.loads(run("layout")), run("html")
    errs = []
    for pn, pl in zip(nets["parts"], lay["parts"]):
        if len(pn["rungs"]) != len(pl["rungs"]):
            errs.append(f"{pn['name']}: {len(pn['rungs'])} rungs, drawn {len(pl['rungs'])}")
    if len(nets["parts"]) != len(lay["parts"]): errs.append("part count differs")
    want = set(); ids(nets["parts"], want)
    cells = [c for p in lay["parts"] for r in p["rungs"] for c in r["cells"]]
    drawn = {c["stmt"] for c in cells if "stmt" in c}
    placed = drawn | {i for c in cells for i in c.get("covers", [])} | \
        {i for p in lay["parts"] for r in p["rungs"] for i in r.get("hidden", [])}
    if want - placed: errs.append(f"statements not placed: {sorted(want - placed)[:10]}")
    in_html = {int(x) for x in re.findall(r'data-stmt="(\d+)"', html)}
    if drawn - in_html: errs.append(f"statements not in html: {sorted(drawn - in_html)[:10]}")
    rungs = sum(len(p["rungs"]) for p in lay["parts"])
    if errs:
        failed += 1; print(f"FAIL {stl.name}: " + "; ".join(errs))
    else:
        passed += 1; print(f"ok {stl.name}: {rungs} rungs, {len(want)} statements drawn")
print(f"{passed} passed, {failed} failed")
sys.exit(1 if failed else 0)

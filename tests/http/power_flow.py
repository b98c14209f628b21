#!/usr/bin/python3
"""Power flow you can follow (issue 32, page item 1; docs/ladder-view.md "Power flow"), in
headless Chromium: wires, links and element stubs are green only where power reaches them, and a
contact that conducts with no power reaching it is marked apart (class `cnp`) from the live path.

On examples/lathe_panel.stl (hnc8-core.md: LDP/OR/ANI/OUT as a latch):
  rung 10  LDP X484.5 / OR R1.0 / ANI X484.6 / ANI X483.0 / OUT R1.0   (spindle CW latch)
  rung 11  LDP X484.7 / ANI R1.0 / OR R1.1 / ANI X484.6 / ANI X483.0 / OUT R1.1  (CCW)
- before any input: X484.6 and X483.0 are 0, so their normally closed contacts conduct, but no
  power reaches them (the rising-edge contact and the latch contact are open): both `cnp`, the
  wire to the coil is not powered, the coils are off;
- after a rising edge on X484.5 (written over Modbus, coil 10000 + 8 * 484 + 5), R1.0 latches:
  in rung 10 the R1.0 contact, its links, X484.6, X483.0 and the wire to the coil are powered and
  coil R1.0 is on; in rung 11 the normally closed R1.0 is open, so X484.6 and X483.0 still
  conduct without power and the wire to R1.1 stays dark;
- in every frame, for every output of every ladder rung of the program (all parts, drawn or
  not), the power the page computes at its input equals its traced input (the engine's ST0):
  the drawing's power flow is the program's. The same check on the FANUC and IEC examples, and
  on a ClassicLadder project drawn on its own grid while its inputs change.
Usage: power_flow.py LADDERJIT EXAMPLES OUTDIR"""
import os, subprocess, sys, time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import liveutil  # noqa: E402

exe, examples, out = sys.argv[1], sys.argv[2], sys.argv[3]
os.makedirs(out, exist_ok=True)
check = liveutil.check

# For every output of every ladder rung, computed input power against the traced one, over the
# frame the page has now: [compared, mismatches (first 5), rungs skipped as not scanned].
CONSISTENT = """
var L = window.ladder, n = 0, bad = [], ns = 0;
L.layout.parts.forEach(function (p, pi) { p.rungs.forEach(function (r, ri) {
  if (r.kind !== 'ladder') return;
  var f = L.flowOf(pi, ri);
  if (!f) return;
  if (f.ns) { ns++; return; }
  Object.keys(f.el).forEach(function (id) {
    var e = f.el[id];
    if (!e.sink) return;
    n++;
    if (e.i !== (e.v === 1) && bad.length < 5) bad.push(p.name + ' rung ' + r.number + ' id ' + id);
  });
}); });
return [n, bad, ns];"""


def live(driver, seconds=15):
    t0 = time.time()
    while time.time() - t0 < seconds:
        st = driver.execute_script("var m=window.ladder.live.last;return m&&m.traced&&!!m.w")
        if st:
            return True
        time.sleep(0.05)
    return False


def consistent(driver, name, frames=10):
    """The consistency check over `frames` frames 100 ms apart; the outputs compared in all."""
    total = 0
    for _ in range(frames):
        n, bad, ns = driver.execute_script(CONSISTENT)
        total += n
        if bad:
            check(False, "%s: computed power at an output differs from its traced input: %s" % (name, bad))
            return total
        time.sleep(0.1)
    check(total > 0, "%s: power computed at every output equals its traced input (%d output "
          "frames compared, 0 differ)" % (name, total))
    return total


def classes(driver, stmt):
    return driver.execute_script(
        "var g=document.querySelector('g.el[data-stmt=\"%d\"]');return g?g.getAttribute('class'):''" % stmt).split()


def wire_powered(driver, part, rung, at):
    return driver.execute_script(
        "var d=window.ladder.rungDiv(%d,%d),e=d&&d.querySelector('[data-at=\"%s\"]');return e?e.classList.contains('p'):null"
        % (part, rung, at))


def stubs(driver, stmt):
    return driver.execute_script(
        "return Array.from(document.querySelectorAll('g.el[data-stmt=\"%d\"] line.w')).map(function(l){"
        "return l.classList.contains('p')})" % stmt)


def lathe():
    serve, driver, _, _, _, mport = liveutil.open_page(exe, os.path.join(examples, "lathe_panel.stl"), out,
                                                       "lathe", 90, modbus=True)
    try:
        check(live(driver), "lathe_panel: the page receives traced frames")
        ids, where = driver.execute_script(
            "var ids={},w={};window.ladder.layout.parts.forEach(function(p,pi){p.rungs.forEach(function(r,ri){"
            "r.cells.forEach(function(c){if(c.stmt>=0&&c.text){ids[p.name+' '+r.number+' '+c.kind+' '+c.text]=c.stmt;"
            "w[p.name+' '+r.number]=[pi,ri]}})})});return [ids,w]")
        cw = lambda k: ids["PLC1 10 " + k]
        ccw = lambda k: ids["PLC1 11 " + k]
        pi, ri10 = where["PLC1 10"]
        ri11 = where["PLC1 11"][1]
        driver.execute_script("window.ladder.goTo(%d)" % ccw("coil R1.1"))
        time.sleep(0.5)
        for name, stmt in (("X484.6", ccw("contact-nc X484.6")), ("X483.0", ccw("contact-nc X483.0"))):
            c = classes(driver, stmt)
            check("on" in c and "cnp" in c and "pwi" not in c,
                  "rung 11 before any input: %s conducts with no power reaching it (%s)" % (name, " ".join(c)))
        check(wire_powered(driver, pi, ri11, "0,4") is False, "rung 11: the wire to coil R1.1 is not powered")
        check("on" not in classes(driver, ccw("coil R1.1")), "rung 11: coil R1.1 off")
        check("cnp" in classes(driver, cw("contact-nc X484.6")),
              "rung 10 before any input: X484.6 conducts with no power reaching it")
        consistent(driver, "lathe_panel before the input")
        liveutil.modbus_write_coil(mport, 10000 + 8 * 484 + 5, True)  # X484.5: spindle CW
        t0 = time.time()
        while time.time() - t0 < 3 and "on" not in classes(driver, cw("coil R1.0")):
            time.sleep(0.02)
        time.sleep(0.3)
        r10 = classes(driver, cw("contact-no R1.0"))
        check("on" in r10 and "pwi" in r10 and "cnp" not in r10,
              "rung 10 after X484.5: the latch contact R1.0 is in the live path (%s)" % " ".join(r10))
        for name in ("contact-nc X484.6", "contact-nc X483.0"):
            c = classes(driver, cw(name))
            check("on" in c and "pwi" in c and "cnp" not in c and stubs(driver, cw(name)) == [True, True],
                  "rung 10: %s live, both stubs powered (%s)" % (name.split()[1], " ".join(c)))
        coil = classes(driver, cw("coil R1.0"))
        check("on" in coil and "pwi" in coil and stubs(driver, cw("coil R1.0")) == [True, True],
              "rung 10: coil R1.0 on, its stubs powered")
        check(wire_powered(driver, pi, ri10, "0,4") is True, "rung 10: the wire to coil R1.0 is powered")
        links = driver.execute_script(
            "return Array.from(window.ladder.rungDiv(%d,%d).querySelectorAll('g.vlink')).map(function(g){"
            "return g.classList.contains('p')})" % (pi, ri10))
        check(links and all(links), "rung 10: its links are powered (%s)" % links)
        nc = classes(driver, ccw("contact-nc R1.0"))
        check("on" not in nc and "pwi" not in nc, "rung 11: the normally closed R1.0 is open (%s)" % " ".join(nc))
        for name in ("contact-nc X484.6", "contact-nc X483.0"):
            c = classes(driver, ccw(name))
            check("on" in c and "cnp" in c and stubs(driver, ccw(name)) == [False, False],
                  "rung 11 after X484.5: %s conducts, no power, stubs dark (%s)" % (name.split()[1], " ".join(c)))
        check(wire_powered(driver, pi, ri11, "0,4") is False, "rung 11: the wire to coil R1.1 stays dark")
        consistent(driver, "lathe_panel with R1.0 latched")
        d = driver.execute_script("return window.ladder.rungDiv(%d,%d)" % (pi, ri10))
        driver.execute_script("arguments[0].scrollIntoView({block:'center'})", d)
        time.sleep(0.5)
        shot = os.path.join(out, "power-flow.png")
        driver.save_screenshot(shot)
        check(os.path.getsize(shot) > 10000, "screenshot " + shot)
    finally:
        liveutil.stop(driver, serve)


def other(name):
    serve, driver, _, _, _, _ = liveutil.open_page(exe, os.path.join(examples, name), out, name)
    try:
        check(live(driver), name + ": the page receives traced frames")
        consistent(driver, name)
    finally:
        liveutil.stop(driver, serve)


def cell_rows(rows):
    """A rung's 6 rows of 10 cells (`type-top-vartype/num`, missing cells empty)."""
    out = []
    for y in range(6):
        r = rows[y] if y < len(rows) else {}
        out.append(" , ".join(r.get(x, "0-0-0/0") for x in range(10)))
    return "\n".join(out)


def classic():
    """A ClassicLadder project drawn on its own grid (docs/classicladder.md "Ladder view"): NO and
    NC contacts, a parallel branch through vertical wires, an edge contact, a compare block, an
    IEC timer and set/reset coils; the page's power flow equals the traced inputs of every output
    in every frame, while the inputs change."""
    def wired(a, b, cells):
        r = {x: "9-0-0/0" for x in range(a, b)}
        r.update(cells)
        return r
    r0 = [wired(2, 9, {0: "1-0-50/0", 1: "2-0-50/1", 9: "50-0-60/0"}),
          wired(1, 2, {0: "1-0-50/2", 2: "9-1-0/0"}),
          wired(4, 9, {0: "3-0-50/3", 1: "9-0-0/0", 2: "99-0-0/0", 3: "13-0-0/0", 9: "52-0-60/1"}),
          {2: "99-0-0/0", 3: "99-0-0/0"},
          wired(3, 9, {0: "99-0-0/0", 1: "99-0-0/0", 2: "20-0-0/0", 9: "53-0-60/1"})]
    clp = ("_FILES_CLASSICLADDER\n_FILE-sections.csv\n#VER=1.0\n#NAME000=Main\n000,0,-1,0,0,0\n"
           "_/FILE-sections.csv\n_FILE-rung_0.csv\n#VER=2.0\n#LABEL=R0\n#COMMENT=flow\n#NEXTRUNG=-1\n"
           + cell_rows(r0) + "\n_/FILE-rung_0.csv\n_FILE-timers_iec.csv\n1,5,0\n_/FILE-timers_iec.csv\n"
           "_FILE-arithmetic_expressions.csv\n0000,@270/0@>5\n_/FILE-arithmetic_expressions.csv\n"
           "_/FILES_CLASSICLADDER\n")
    path = os.path.join(out, "flow.clp")
    with open(path, "w") as f:
        f.write(clp)
    serve, driver, _, _, sock, _ = liveutil.open_page(exe, path, out, "classicladder")
    try:
        check(live(driver), "flow.clp: the page receives traced frames")
        kinds = driver.execute_script(
            "return window.ladder.layout.parts[0].rungs[0].cells.map(function(c){return c.kind})")
        check(all(k in kinds for k in ("contact-no", "contact-nc", "contact-rise", "box", "compare",
                                       "vlink", "set", "rst")),
              "flow.clp: the rung is drawn on its grid, every kind of cell: %s" % sorted(set(kinds)))
        total = consistent(driver, "flow.clp, inputs 0", frames=4)
        for step in (["%I0=1"], ["%I2=1"], ["%I1=1"], ["%I3=1", "%IW0=9"], ["%I0=0", "%I3=0"]):
            subprocess.run([exe, "monitor", "--control", sock, "write", *step], capture_output=True,
                           timeout=10)
            time.sleep(0.3)
            total += consistent(driver, "flow.clp after " + " ".join(step), frames=3)
        shot = os.path.join(out, "power-flow-classicladder.png")
        driver.save_screenshot(shot)
        check(os.path.getsize(shot) > 10000, "screenshot " + shot)
    finally:
        liveutil.stop(driver, serve)


lathe()
classic()
for prog in ("catalogue.stl", "tool_change.stl", "fanuc_coolant.pmc", "fanuc_tool_change.pmc",
             "fanuc_magazine.pmc", "conveyor.il", "pump_station.il", "filler.il"):
    other(prog)
print("%d failed" % len(liveutil.failures))
sys.exit(1 if liveutil.failures else 0)

#!/usr/bin/python3
"""Box values that say what they are (issue 32, page item 3; docs/ladder-view.md "Box values"),
in headless Chromium. A box's register operands carry their value on their own operand line
("W0 = 2"), constants carry none (a constant is not a reading), and a timer's elapsed time or a
counter's count is on the box's values line with its label. Each value is checked against
`monitor read` of the same address (they may differ only while it changes: read until equal).

- examples/lathe_panel.stl rung `WAND F2560 15 W0`: F2560 and W0 labelled with their values, the
  constant 15 without one, nothing unlabelled on the values line.
- examples/coolant_lube.stl (--params coolant_lube.params: P10 = 100, P11 = 250, so D10 = 100 and
  D11 = 250 from its init): `TMRB 11 0 D10` shows "D10 = 100" on D10's line, no value on the
  constants 11 and 0, and "elapsed ms = N" on the values line with 0 <= N.
Usage: box_values.py LADDERJIT EXAMPLES OUTDIR"""
import os, re, sys, time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import liveutil  # noqa: E402

exe, examples, out = sys.argv[1], sys.argv[2], sys.argv[3]
os.makedirs(out, exist_ok=True)
check = liveutil.check

BOX = """
var L = window.ladder, want = arguments[0], id = null;
L.layout.parts.forEach(function (p) { p.rungs.forEach(function (r) { r.cells.forEach(function (c) {
  if (c.kind === 'box' && c.text + ' ' + (c.operands || []).join(' ') === want) id = c.stmt; }); }); });
if (id === null) return null;
L.goTo(id);
var g = document.querySelector('g.el[data-stmt="' + id + '"]');
if (!g) return {id: id};
var v = g.querySelector('text.val');
return {id: id, ops: Array.from(g.querySelectorAll('text.op')).map(function (t) { return t.textContent; }),
        val: v ? v.textContent : null};"""


def box(driver, want, seconds=10):
    t0 = time.time()
    while time.time() - t0 < seconds:
        b = driver.execute_script(BOX, want)
        if b and b.get("ops") is not None and b.get("val") is not None:
            return b
        time.sleep(0.1)
    return driver.execute_script(BOX, want)


def read(sock, addr):
    return liveutil.monitor_read(exe, sock, addr)


def agrees(driver, sock, want, addr, seconds=5):
    """The value drawn on `addr`'s operand line and monitor read agree (within `seconds`)."""
    t0 = time.time()
    line = None
    while time.time() - t0 < seconds:
        b = box(driver, want)
        line = [o for o in b["ops"] if o.startswith(addr + " = ")]
        if line and read(sock, addr) == int(line[0].split(" = ")[1]):
            return True, line[0]
        time.sleep(0.1)
    return False, line


def serve(program, name, *extra):
    srv, driver, _, _, sock, _ = liveutil.open_page(exe, program, out, name, extra=list(extra))
    return srv, driver, sock


srv, driver, sock = serve(os.path.join(examples, "lathe_panel.stl"), "lathe")
try:
    want = "WAND F2560 15 W0"
    b = box(driver, want)
    check(b is not None and b.get("ops") is not None, "lathe_panel: the box %s is drawn (%s)" % (want, b))
    for addr in ("F2560", "W0"):
        ok, line = agrees(driver, sock, want, addr)
        check(ok, "lathe_panel %s: %s's line carries its value, equal to monitor read (%s)" % (want, addr, line))
    b = box(driver, want)
    check("15" in b["ops"], "lathe_panel %s: the constant 15 carries no value (%s)" % (want, b["ops"]))
    check(b["val"] == "", "lathe_panel %s: nothing unlabelled on the values line (%r)" % (want, b["val"]))
    shot = os.path.join(out, "box-values-lathe.png")
    driver.save_screenshot(shot)
finally:
    liveutil.stop(driver, srv)

srv, driver, sock = serve(os.path.join(examples, "coolant_lube.stl"), "coolant", "--params",
                          os.path.join(examples, "coolant_lube.params"))
try:
    want = "TMRB 11 0 D10"
    ok, line = agrees(driver, sock, want, "D10")
    check(ok and line == "D10 = 100", "coolant_lube %s: D10's line shows 100 (P10), as monitor read (%s)" % (want, line))
    b = box(driver, want)
    check("11" in b["ops"] and "0" in b["ops"], "coolant_lube %s: the constants 11 and 0 carry no value (%s)"
          % (want, b["ops"]))
    m = re.fullmatch(r"elapsed ms = (\d+)", b["val"] or "")
    check(m is not None, "coolant_lube %s: the values line is the labelled elapsed time (%r)" % (want, b["val"]))
    shot = os.path.join(out, "box-values-timer.png")
    driver.save_screenshot(shot)
    check(os.path.getsize(shot) > 10000, "screenshot " + shot)
finally:
    liveutil.stop(driver, srv)
print("%d failed" % len(liveutil.failures))
sys.exit(1 if liveutil.failures else 0)

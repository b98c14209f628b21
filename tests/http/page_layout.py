#!/usr/bin/python3
"""The live page's layout (issue 32, page item 5; docs/ladder-view.md "Live view"), in headless
Chromium on examples/lathe_panel.stl:
- the page opens on PLC1 (the first level), not on the init part that comes first in the file;
- one grid per program: PLC2's rung ending in the 2-cell box `WAND F2560 15 W0` and its coil
  rungs share one right rail;
- trailing comments are shown right of the right rail, on their element's row, as the HNC-8
  editor does (`AND X484.2 ; +X` in rung 9: "; +X" right of the rail at X484.2's row);
- a force mark on a contact standing on the left rail (R0.2 at column 0 of rung 9) lies right of
  the rail and clear of the address above the contact;
- the status line names the element as a technician does ("R0.2 (PLC1 rung 9) forced OFF"), not
  its statement id, and fades after a few seconds (class `old`).
Usage: page_layout.py LADDERJIT EXAMPLES OUTDIR"""
import os, sys, time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import liveutil  # noqa: E402

exe, examples, out = sys.argv[1], sys.argv[2], sys.argv[3]
os.makedirs(out, exist_ok=True)
check = liveutil.check

serve, driver, _, _, _, _ = liveutil.open_page(exe, os.path.join(examples, "lathe_panel.stl"), out, "lathe")
try:
    parts = driver.execute_script("return window.ladder.layout.parts.map(function(p){return p.name})")
    sel = driver.execute_script("var s=document.querySelector('section.part.sel');return s&&s.dataset.part")
    check(parts[0] == "init" and sel == "PLC1", "the page opens on PLC1 (parts %s, shown %s)" % (parts, sel))
    # one grid per program: PLC2's WAND rung (a 2-cell box at the rail) and its coil rungs share
    # one right rail
    driver.execute_script("document.querySelectorAll('.tab')[2].click()")
    time.sleep(0.5)
    rails = driver.execute_script(
        "return Array.from(document.querySelectorAll('section.part.sel g.rung')).map(function(g){"
        "var r=g.querySelectorAll('line.rail');return r.length>1?+r[1].getAttribute('x1'):null})"
        ".filter(function(x){return x!==null})")
    check(len(rails) >= 7 and len(set(rails)) == 1, "PLC2: one right rail for box and coil rungs (%s)" % rails)
    driver.execute_script("document.querySelectorAll('.tab')[1].click()")
    # rung 9 of PLC1: its R0.2 contact (column 0) and X484.2 with its trailing comment
    ids = driver.execute_script(
        "var r={};window.ladder.layout.parts[1].rungs.forEach(function(g){if(g.number===9)g.cells.forEach("
        "function(c){if(c.text)r[c.text]=[c.stmt,c.row,c.col]})});return r")
    r02, x842 = ids["R0.2"], ids["X484.2"]
    check(r02[2] == 0, "R0.2 stands on the left rail (column %d)" % r02[2])
    driver.execute_script("window.ladder.goTo(%d)" % x842[0])
    time.sleep(0.5)
    tc = driver.execute_script(
        "var g=document.querySelector('g.rung[data-part=\"PLC1\"][data-rung=\"9\"]');"
        "var rails=g.querySelectorAll('line.rail'),rx=+rails[1].getAttribute('x1');"
        "return Array.from(g.querySelectorAll('text.tc')).map(function(t){var b=t.getBBox();"
        "return [t.textContent,b.x-rx,b.y+b.height/2]})")
    el = driver.execute_script(
        "var b=document.querySelector('g.el[data-stmt=\"%d\"] line.sym').getBBox();return b.y+b.height/2" % x842[0])
    plus_x = [t for t in tc if t[0] == "; +X"]
    check(len(plus_x) == 1 and plus_x[0][1] > 0 and abs(plus_x[0][2] - el) < 15,
          "rung 9: '; +X' right of the right rail on X484.2's row (comments %s, row centre %.0f)" % (tc, el))
    # force R0.2 off from the page: the mark right of the rail, clear of the address
    res = driver.execute_async_script("var d=arguments[0];window.ladder.force(%d,'off').then(d)" % r02[0])
    check(res["status"] == 200, "force off R0.2 from the page (%s)" % res)
    t0 = time.time()
    box = None
    while time.time() - t0 < 10 and not box:
        box = driver.execute_script(
            "var g=document.querySelector('g.el[data-stmt=\"%d\"]'),t=g&&g.querySelector('text.fmark');"
            "if(!t)return null;var b=t.getBBox(),a=g.querySelector('text.addr').getBBox(),"
            "rail=+g.closest('g.rung').querySelector('line.rail').getAttribute('x1');"
            "return {text:t.textContent,x:b.x,y:b.y,w:b.width,h:b.height,ax:a.x,ay:a.y,aw:a.width,ah:a.height,rail:rail}"
            % r02[0])
        time.sleep(0.05)
    check(box is not None and box["text"] == "F-OFF", "R0.2 drawn with its F-OFF mark (%s)" % box)
    if box:
        overlap = not (box["x"] >= box["ax"] + box["aw"] or box["x"] + box["w"] <= box["ax"] or
                       box["y"] >= box["ay"] + box["ah"] or box["y"] + box["h"] <= box["ay"])
        check(box["x"] > box["rail"] + 2 and not overlap,
              "the F-OFF mark is right of the left rail (x %.0f > %d) and clear of the address" % (box["x"], box["rail"]))
    msg = driver.execute_script("return document.getElementById('msg').textContent")
    check(msg.startswith("R0.2 (PLC1 rung 9) forced OFF") and "id" not in msg.split(),
          "the status line names the element: %r" % msg)
    driver.save_screenshot(os.path.join(out, "page-layout.png"))
    time.sleep(7)
    old = driver.execute_script("return document.getElementById('msg').classList.contains('old')")
    check(old, "the status line has faded after 7 s")
    res = driver.execute_async_script("var d=arguments[0];window.ladder.force(%d,'restore').then(d)" % r02[0])
    check(res["status"] == 200, "restore R0.2")
finally:
    liveutil.stop(driver, serve)
print("%d failed" % len(liveutil.failures))
sys.exit(1 if liveutil.failures else 0)

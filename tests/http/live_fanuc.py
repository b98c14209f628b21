#!/usr/bin/python3
"""The live ladder view of a FANUC PMC program in a real browser (headless Chromium through
python3-selenium and chromedriver): `serve --http` on examples/fanuc_coolant.pmc (a LADDER-III
mnemonic file with %@2-E symbols). The page draws FANUC words (EQB, DIFU, TMRBF, TMRB, END2; no
HNC-8 or IR name), the symbol names under the addresses, and runs live: the 1 s clock R9091.6
(CLOCK_1S, written by the runtime, ON:OFF = 1:1, fanuc-pmc.md 2) is drawn on and off in turn on
the level-2 tab, and a full one-row box gets its values line below its operands. Keeps a
screenshot. Usage: live_fanuc.py LADDERJIT EXAMPLES_DIR OUTDIR"""
import json, os, sys, time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import liveutil  # noqa: E402

from selenium.webdriver.common.by import By

exe, examples, out = sys.argv[1], sys.argv[2], sys.argv[3]
os.makedirs(out, exist_ok=True)
program = os.path.join(examples, "fanuc_coolant.pmc")
sock = os.path.join(out, "serve.sock")
check = liveutil.check

serve, url, token, _ = liveutil.start_serve(exe, program, sock, os.path.join(out, "serve.err"), 60,
                                           modbus=False)
driver = liveutil.chrome()
driver.set_script_timeout(10)
try:
    driver.get(url + "?token=" + token)
    layout = json.loads(driver.find_element(By.ID, "ladder-layout").get_attribute("textContent"))
    parts = [(p["name"], len(p["rungs"])) for p in layout["parts"]]
    # Level 1: the E-stop rung and END1; level 2: eight rungs and END2 (the program's own text).
    check(parts == [("PLC1", 2), ("PLC2", 9)], "parts and rungs %s" % parts)
    cells = [c for p in layout["parts"] for r in p["rungs"] for c in r["cells"]]
    words = {c.get("text") for c in cells if c["kind"] in ("box", "marker")}
    for w in ("EQB", "DIFU", "TMRBF", "TMRB", "END1", "END2"):
        check(w in words, "FANUC word %s drawn (boxes and markers: %s)" % (w, sorted(words)))
    for w in ("CompareEq", "2END", "1END", "OnDelayTimer"):
        check(w not in words, "no HNC-8 or IR name %s" % w)
    symbols = {c.get("text"): c.get("symbol") for c in cells if c.get("symbol")}
    check(symbols.get("R9091.6") == "CLOCK_1S" and symbols.get("X0.1") == "COOL_KEY",
          "symbols under the addresses: R9091.6 %s, X0.1 %s" %
          (symbols.get("R9091.6"), symbols.get("X0.1")))
    clock = next(c["stmt"] for c in cells if c.get("text") == "R9091.6")
    driver.find_element(By.CSS_SELECTOR, 'button.tab[data-for="part-1"]').click()
    on = ("var g=document.querySelector('g.el[data-stmt=\"%d\"]');"
          "return g?g.classList.contains('on'):null" % clock)
    # The 1 s clock: seen on and seen off within 3 s of live snapshots on the level-2 tab.
    seen = set()
    t0 = time.time()
    while time.time() - t0 < 3 and len(seen) < 2:
        v = driver.execute_script(on)
        if v is not None:
            seen.add(v)
        time.sleep(0.02)
    check(seen == {True, False}, "R9091.6 (CLOCK_1S) drawn on and off: %s" % sorted(seen))
    # The EQB F10 8 box of rung 1 is one row with two operand lines: its values line (written by
    # the page) lies below its last operand line, not over it (11 px text needs 11 px).
    eqb = next(c["stmt"] for c in layout["parts"][1]["rungs"][0]["cells"] if c["kind"] == "box")
    gap = driver.execute_script(
        "var g=document.querySelector('g.el[data-stmt=\"%d\"]'),v=g&&g.querySelector('text.val'),"
        "o=g&&g.querySelectorAll('text.op');return v&&o.length?+v.getAttribute('y')-"
        "+o[o.length-1].getAttribute('y'):null" % eqb)
    check(gap is not None and gap >= 11, "EQB box: values line %s px below its last operand" % gap)
    texts = driver.execute_script("return document.querySelector('section.part.sel').textContent")
    check("CLOCK_1S" in texts and "KEY_PULSE" in texts, "symbol names on the level-2 tab")
    driver.save_screenshot(os.path.join(out, "live_fanuc.png"))
    check(os.path.getsize(os.path.join(out, "live_fanuc.png")) > 10000,
          "screenshot " + os.path.join(out, "live_fanuc.png"))
finally:
    liveutil.stop(driver, serve)
print("%d failed" % len(liveutil.failures))
sys.exit(1 if liveutil.failures else 0)

#!/usr/bin/python3
"""The live page of a 10,000-statement program in headless Chromium (docs/ladder-view.md "Large
programs"): `serve --http` runs the realistic generator's 10k program at 1 ms; the page draws only
the rungs near the view, so the test checks that it is live (a contact on an input follows a
Modbus write, drawn on then off again), that every part's last rung is drawn when scrolled to and
that a search for an address of the last rung draws and marks it, and that the page did not draw
every rung. The load time is printed, not asserted (bench/live_page_load.py measures it).
Usage: live_10k.py LADDERJIT GEN_REALISTIC OUTDIR"""
import json, os, re, subprocess, sys, time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import liveutil  # noqa: E402

from selenium.webdriver.common.by import By

exe, gen, out = sys.argv[1], sys.argv[2], sys.argv[3]
os.makedirs(out, exist_ok=True)
program = os.path.join(out, "realistic10k.stl")
subprocess.run([gen, "10000", program], check=True, timeout=60)
sock = os.path.join(out, "serve.sock")
failures = liveutil.failures
check, modbus_write_coil = liveutil.check, liveutil.modbus_write_coil


def wait_for(fn, limit):
    t0 = time.time()
    while time.time() - t0 < limit:
        v = fn()
        if v:
            return v, time.time() - t0
        time.sleep(0.02)
    return None, limit


serve, url, token, mport = liveutil.start_serve(exe, program, sock, os.path.join(out, "serve.err"), 90, 30)
driver = liveutil.chrome()
driver.set_script_timeout(20)
driver.set_page_load_timeout(30)
try:
    t0 = time.time()
    driver.get(url + "?token=" + token)
    live, _ = wait_for(lambda: driver.execute_script(
        "var L=window.ladder;return L&&L.live&&L.live.last&&L.live.last.w&&L.drawn()>0"), 30)
    print("page loaded and live after %.2f s (not asserted; see bench/live_page_load.py)" %
          (time.time() - t0))
    check(bool(live), "the page receives traced snapshots and draws rungs")
    layout = driver.execute_script("return window.ladder.layout")
    total = sum(len(p["rungs"]) for p in layout["parts"])
    stmts = sum(1 for p in layout["parts"] for r in p["rungs"] for c in r["cells"] if "stmt" in c)
    check(stmts >= 10000 and total > 1000, "the layout has %d rungs, %d placed statements" % (total, stmts))
    drawn = driver.execute_script("return window.ladder.drawn()")
    check(0 < drawn < total // 4, "rungs in the DOM at load: %d of %d (only those near the view)" %
          (drawn, total))
    # Live: a normally open contact on an input of PLC1 (scanned every tick) follows the input.
    cands = [(c["stmt"], c["text"]) for p in layout["parts"] if p["name"] == "PLC1"
             for r in p["rungs"] for c in r["cells"]
             if c["kind"] == "contact-no" and re.fullmatch(r"X\d+\.\d", c.get("text", ""))]
    state = ("var g=document.querySelector('g.el[data-stmt=\"%d\"]');if(!g)return null;"
             "return g.classList.contains('on')?'on':g.classList.contains('ns')?'ns':"
             "g.classList.contains('off')?'off':null")
    followed = None
    for stmt, addr in cands[:8]:
        driver.execute_script("window.ladder.goTo(%d)" % stmt)
        st, _ = wait_for(lambda: driver.execute_script(state % stmt), 3)
        if st != "off":
            continue  # skipped by a jump in this program, or the input is on: try the next one
        byte, bit = map(int, addr[1:].split("."))
        modbus_write_coil(mport, 10000 + 8 * byte + bit, True)
        on, t_on = wait_for(lambda: driver.execute_script(state % stmt) == "on", 3)
        modbus_write_coil(mport, 10000 + 8 * byte + bit, False)
        off, t_off = wait_for(lambda: driver.execute_script(state % stmt) == "off", 3)
        followed = (addr, bool(on), t_on, bool(off), t_off)
        break
    check(followed is not None and followed[1] and followed[3],
          "a contact on an input follows Modbus writes: %s" %
          ("%s drawn on after %.0f ms, off again after %.0f ms" %
           (followed[0], followed[2] * 1000, followed[4] * 1000) if followed else "no candidate"))
    # Every rung reachable: each part's last rung is drawn once scrolled into view.
    for i, p in enumerate(layout["parts"]):
        last = len(p["rungs"]) - 1
        driver.execute_script(
            "document.querySelectorAll('.tab')[%d].click();"
            "document.querySelector('div.rg[data-p=\"%d\"][data-r=\"%d\"]').scrollIntoView()" % (i, i, last))
        ok, _ = wait_for(lambda: driver.execute_script(
            "var d=document.querySelector('div.rg[data-p=\"%d\"][data-r=\"%d\"]');"
            "return !!d.querySelector('g.rung')" % (i, last)), 5)
        check(bool(ok), "%s: its last rung (%d) is drawn when scrolled to" % (p["name"], last + 1))
    # Search for an address of the last ladder rung of the largest part: drawn and marked.
    big = max(range(len(layout["parts"])), key=lambda i: len(layout["parts"][i]["rungs"]))
    target = None
    for r in reversed(layout["parts"][big]["rungs"]):
        for c in r["cells"]:
            if c["kind"].startswith("contact") and c.get("text") and "stmt" in c:
                target = c
        if target:
            break
    driver.execute_script("document.querySelectorAll('.tab')[0].click();window.scrollTo(0,0)")
    time.sleep(0.3)
    q = driver.find_element(By.ID, "q")
    q.clear()
    q.send_keys(target["text"])
    hit = None
    for _ in range(40):  # Enter steps through the hits; stop at the one of that rung
        driver.execute_script("document.getElementById('q').dispatchEvent(new KeyboardEvent('keydown',{key:'Enter'}))")
        hit = driver.execute_script(
            "var g=document.querySelector('g.el.hit');return g&&+g.dataset.stmt")
        if hit == target["stmt"]:
            break
    check(hit == target["stmt"], "search %s reaches the element %d of %s's last ladder rung (marked %s)" %
          (target["text"], target["stmt"], layout["parts"][big]["name"], hit))
    drawn = driver.execute_script("return window.ladder.drawn()")
    check(drawn < total // 2, "rungs in the DOM after the walk: %d of %d" % (drawn, total))
    driver.save_screenshot(os.path.join(out, "live10k.png"))
finally:
    liveutil.stop(driver, serve)
print("%d failed" % len(failures))
sys.exit(1 if failures else 0)

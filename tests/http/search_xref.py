#!/usr/bin/python3
"""Search and cross-reference like the HNC-8 screen (issue 32, page item 4; docs/ladder-view.md
"Search" and "Cross-reference"), in headless Chromium with real keys and clicks.

examples/lathe_panel.stl:
- `R0.2` + Enter: hit 1 of N; Enter: 2/N; Shift+Enter: back to 1/N; ▲: N/N (wraps, 向上查找);
- the cross-reference of R0.2 lists its own uses and, as overlapping in memory, `WAND R0 0xE0 R0`
  (S1 rung 1, which reads and writes R0), and shows R0.2's current value equal to `monitor read R0.2`;
- `WAND` (an instruction) finds the program's two WAND boxes; `guard door` (comment text) finds
  the rungs whose comments say it;
- `#12` with PLC1 shown highlights its rung 12; `PLC2#3` switches to PLC2 and rung 3.
tests/http/xref.stl: the double coil Y0.0 is marked on both coils ("2× 双线圈").
Usage: search_xref.py LADDERJIT EXAMPLES OUTDIR"""
import os, re, sys, time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import liveutil  # noqa: E402

from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys

exe, examples, out = sys.argv[1], sys.argv[2], sys.argv[3]
os.makedirs(out, exist_ok=True)
check = liveutil.check
here = os.path.dirname(os.path.abspath(__file__))


def mread(sock, addr):
    return liveutil.monitor_read(exe, sock, addr)


def query(driver, text, keys=Keys.ENTER):
    """Type `text` into the search box (None: keep what is there) and press `keys`."""
    q = driver.find_element(By.ID, "q")
    if text is not None:
        q.clear()
    q.send_keys((text or "") + keys)
    time.sleep(0.4)
    return driver.find_element(By.ID, "qres").text


def hit_rung(driver):
    return driver.execute_script(
        "var g=document.querySelector('g.hit');g=g&&g.closest('g.rung');"
        "return g?[g.dataset.part,+g.dataset.rung]:null")


def lathe():
    serve, driver, _, _, sock, _ = liveutil.open_page(exe, os.path.join(examples, "lathe_panel.stl"),
                                                            out, "lathe")
    try:
        time.sleep(1.5)
        r1 = query(driver, "R0.2")
        n = int(r1.split("/")[1]) if "/" in r1 else 0
        check(r1 == "1/%d" % n and n >= 2, "R0.2: first hit %s" % r1)
        r2 = query(driver, None, Keys.ENTER)
        check(r2 == "2/%d" % n, "Enter: next hit %s" % r2)
        r3 = query(driver, None, Keys.SHIFT + Keys.ENTER)
        check(r3 == "1/%d" % n, "Shift+Enter: previous hit %s" % r3)
        driver.find_element(By.ID, "qup").click()
        time.sleep(0.4)
        r4 = driver.find_element(By.ID, "qres").text
        check(r4 == "%d/%d" % (n, n), "▲ from the first hit wraps to the last (向上查找): %s" % r4)
        time.sleep(0.6)
        x = driver.find_element(By.ID, "xref").text
        check("overlapping in memory" in x and re.search(r"reads and writes R0 = 0x[0-9A-F]{2} in WAND R0 (0xE0|224) R0", x) is not None,
              "the cross-reference of R0.2 lists WAND R0 0xE0 R0 writing R0: %r" % x)
        m = re.search(r"R0\.2 = (\d+)", x)
        check(m is not None and int(m.group(1)) == mread(sock, "R0.2"),
              "and shows R0.2's current value (%s, monitor read %s)" % (m and m.group(1), mread(sock, "R0.2")))
        w = query(driver, "WAND")
        check(w == "1/2", "WAND finds the two WAND boxes: %s" % w)
        g = query(driver, "guard door")
        check(g.endswith("/2") or g.endswith("/3"), "'guard door' found in comments: %s" % g)
        driver.find_elements(By.CSS_SELECTOR, ".tab")[1].click()  # PLC1
        rr = query(driver, "#12")
        check(rr == "rung 12" and hit_rung(driver) == ["PLC1", 12], "#12: PLC1 rung 12 (%s, %s)" % (rr, hit_rung(driver)))
        rr = query(driver, "PLC2#3")
        sel = driver.execute_script("return document.querySelector('section.part.sel').dataset.part")
        check(sel == "PLC2" and hit_rung(driver) == ["PLC2", 3], "PLC2#3: PLC2 shown, rung 3 (%s)" % hit_rung(driver))
        driver.save_screenshot(os.path.join(out, "search.png"))
    finally:
        liveutil.stop(driver, serve)


def double_coil():
    serve, driver, _, _, _, _ = liveutil.open_page(exe, os.path.join(here, "xref.stl"), out, "x")
    try:
        time.sleep(1.5)
        marks = driver.execute_script(
            "return Array.from(document.querySelectorAll('g.el.coil')).map(function(g){"
            "var t=g.querySelector('text.dblm');return [g.querySelector('text.addr').textContent,"
            "g.classList.contains('dbl'),t?t.textContent:'']})")
        y0 = [m for m in marks if m[0] == "Y0.0"]
        y2 = [m for m in marks if m[0] == "Y0.2"]
        check(len(y0) == 2 and all(m[1] and m[2] == "2× 双线圈" for m in y0), "both coils of Y0.0 marked: %s" % y0)
        check(y2 and not y2[0][1], "Y0.2 (one coil) not marked: %s" % y2)
        driver.save_screenshot(os.path.join(out, "double-coil.png"))
    finally:
        liveutil.stop(driver, serve)


lathe()
double_coil()
print("%d failed" % len(liveutil.failures))
sys.exit(1 if liveutil.failures else 0)

#!/usr/bin/python3
"""The watch table (诊断→状态显示; issue 32 page item 2; docs/ladder-view.md "Watch table"), in
headless Chromium with real clicks and keys:
- lathe_panel.stl: W0 typed in and added; R1.0 picked from the drawing (right-click the coil,
  "watch R1.0"); both values equal `monitor read`; W0 shown in hex ("0x0002" for 2: W is a 16-bit
  register, so four digits) and binary; D60 written from the table as BCD 1234, which
  `monitor read D60` reads as 0x1234 = 4660; a bit written with its 1 button; an address that
  does not exist is refused with the server's reason and not added; the rows survive a reload
  (kept in the browser per program);
- fanuc_coolant.pmc: a symbol (M08_ON, R0001.0) is watched by its name;
- under --http-read-only the table reads but shows no write control, and POST /api/write is
  refused with 403; GET /api/read without the token is refused with 401.
Usage: watch_table.py LADDERJIT EXAMPLES OUTDIR"""
import json, os, re, sys, time, urllib.request, urllib.error

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import liveutil  # noqa: E402

from selenium.webdriver.common.action_chains import ActionChains
from selenium.webdriver.common.by import By
from selenium.webdriver.common.keys import Keys

exe, examples, out = sys.argv[1], sys.argv[2], sys.argv[3]
os.makedirs(out, exist_ok=True)
check = liveutil.check


def mread(sock, addr):
    return liveutil.monitor_read(exe, sock, addr)


def rows(driver):
    return driver.execute_script(
        "return Array.from(document.querySelectorAll('#watch tr[data-i]')).map(function(tr){"
        "return [tr.cells[0].textContent, tr.cells[1].textContent]})")


def row_value(driver, name, seconds=5, want=None):
    t0 = time.time()
    v = None
    while time.time() - t0 < seconds:
        for a, val in rows(driver):
            if a == name:
                v = val
        if v is not None and (want is None or v == want):
            return v
        time.sleep(0.1)
    return v


def add(driver, text):
    box = driver.find_element(By.ID, "wadd")
    box.clear()
    box.send_keys(text + Keys.ENTER)
    time.sleep(0.6)


def row_of(driver, name):
    for tr in driver.find_elements(By.CSS_SELECTOR, "#watch tr[data-i]"):
        if tr.find_elements(By.TAG_NAME, "td")[0].text == name:
            return tr
    return None


def fmt(driver, name, f):
    tr = row_of(driver, name)
    sel = tr.find_element(By.TAG_NAME, "select")
    sel.click()
    sel.find_element(By.XPATH, "option[text()='%s']" % f).click()
    time.sleep(0.4)


def http(url, path, token=None, body=None):
    req = urllib.request.Request(url.rstrip("/") + path, data=json.dumps(body).encode() if body is not None else None,
                                 method="POST" if body is not None else "GET")
    if token:
        req.add_header("Authorization", "Bearer " + token)
    if body is not None:
        req.add_header("Content-Type", "application/json")
    try:
        with urllib.request.urlopen(req, timeout=5) as r:
            return r.status, json.loads(r.read() or b"{}")
    except urllib.error.HTTPError as e:
        return e.code, json.loads(e.read() or b"{}")


def lathe():
    serve, driver, url, token, sock, _ = liveutil.open_page(exe, os.path.join(examples, "lathe_panel.stl"),
                                                            out, "lathe", 90)
    try:
        driver.execute_script("localStorage.clear()")
        driver.get(url)
        time.sleep(1)
        add(driver, "W0")
        w0 = row_value(driver, "W0")
        check(w0 is not None and mread(sock, "W0") == int(w0), "W0 added: %s, monitor read %s" % (w0, mread(sock, "W0")))
        # pick R1.0 from the drawing: right-click its coil in PLC1 rung 10
        stmt = driver.execute_script(
            "var s=null;window.ladder.layout.parts[1].rungs.forEach(function(r){r.cells.forEach(function(c){"
            "if(c.kind==='coil'&&c.text==='R1.0')s=c.stmt})});window.ladder.goTo(s);return s")
        time.sleep(0.5)
        g = driver.find_element(By.CSS_SELECTOR, 'g.el[data-stmt="%d"]' % stmt)
        ActionChains(driver).context_click(g).perform()
        driver.find_element(By.CSS_SELECTOR, '#menu div[data-w="R1.0"]').click()
        r10 = row_value(driver, "R1.0")
        check(r10 is not None and int(r10) == mread(sock, "R1.0"), "R1.0 picked from the drawing: %s" % r10)
        fmt(driver, "W0", "hex")
        hx = row_value(driver, "W0")
        check(hx == "0x%04X" % mread(sock, "W0"), "W0 in hex: %s (a 16-bit register, four digits)" % hx)
        fmt(driver, "W0", "bin")
        bn = row_value(driver, "W0")
        check(bn == " ".join(re.findall("....", format(mread(sock, "W0") & 0xFFFF, "016b"))), "W0 in binary: %s" % bn)
        # write D60 as BCD 1234 from the table
        add(driver, "D60")
        fmt(driver, "D60", "BCD")
        tr = row_of(driver, "D60")
        inp = tr.find_element(By.CSS_SELECTOR, "input.wi")
        inp.send_keys("1234" + Keys.ENTER)
        time.sleep(0.8)
        check(mread(sock, "D60") == 0x1234, "D60 written as BCD 1234: monitor read %s (0x1234 = 4660)" % mread(sock, "D60"))
        check(row_value(driver, "D60", want="1234") == "1234", "D60 shown as BCD 1234")
        # a bit by its 1 button: R5.3 is not written by the program
        add(driver, "R5.3")
        row_of(driver, "R5.3").find_element(By.CSS_SELECTOR, 'button[data-b="1"]').click()
        time.sleep(0.8)
        check(mread(sock, "R5.3") == 1, "R5.3 set by its 1 button: monitor read %s" % mread(sock, "R5.3"))
        n = len(rows(driver))
        add(driver, "Q7")
        err = driver.find_element(By.ID, "werr").text
        check(len(rows(driver)) == n and "Q7" in err, "Q7 refused with the server's reason: %r" % err)
        driver.save_screenshot(os.path.join(out, "watch-table.png"))
        driver.refresh()
        time.sleep(1.5)
        names = [a for a, _ in rows(driver)]
        check(names == ["W0", "R1.0", "D60", "R5.3"], "the rows survive a reload: %s" % names)
        check(row_value(driver, "W0", want=bn) == bn, "and W0 keeps its format (binary)")
        st, js = http(url, "/api/read?a=W0")
        check(st == 401, "GET /api/read without the token: %d %s" % (st, js.get("error", "")))
        st, js = http(url, "/api/read?a=W0,R1.0", token)
        check(st == 200 and js.get("bits") == [16, 1], "GET /api/read with the token: %d %s" % (st, js))
        st, js = http(url, "/api/write", None, {"writes": ["D61=5"]})
        check(st == 401 and mread(sock, "D61") == 0, "POST /api/write without the token: %d, D61 unchanged" % st)
    finally:
        liveutil.stop(driver, serve)


def fanuc_symbol():
    serve, driver, _, _, sock, _ = liveutil.open_page(exe, os.path.join(examples, "fanuc_coolant.pmc"),
                                                      out, "fanuc")
    try:
        time.sleep(1)
        add(driver, "M08_ON")
        v = row_value(driver, "M08_ON")
        check(v is not None and int(v) == mread(sock, "R0001.0"), "fanuc_coolant: the symbol M08_ON watched: %s" % v)
    finally:
        liveutil.stop(driver, serve)


def read_only():
    serve, driver, url, token, sock, _ = liveutil.open_page(exe, os.path.join(examples, "lathe_panel.stl"),
                                                            out, "ro", extra=["--http-read-only"])
    try:
        time.sleep(1)
        add(driver, "W0")
        v = row_value(driver, "W0")
        controls = driver.execute_script("return document.querySelectorAll('#watch input.wi,#watch button[data-b=\"w\"]').length")
        check(v is not None and controls == 0, "read-only: W0 read (%s), no write control (%d)" % (v, controls))
        st, js = http(url, "/api/write", token, {"writes": ["D60=5"]})
        check(st == 403 and mread(sock, "D60") == 0, "read-only: POST /api/write refused with 403 (%d), D60 unchanged" % st)
    finally:
        liveutil.stop(driver, serve)


lathe()
fanuc_symbol()
read_only()
print("%d failed" % len(liveutil.failures))
sys.exit(1 if liveutil.failures else 0)

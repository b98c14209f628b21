#!/usr/bin/python3
"""Load time of the live ladder page for a large program (docs/BENCHMARKS.md "Live view"):
`serve --http` runs PROGRAM; the first page is opened at once and the time from serve's start to
its first live frame with power flow is printed; then, once the traced build is in (an SSE client sees traced words), headless
Chromium opens the page RUNS times, each in a fresh tab, and reports per load, from navigation
start (performance.now()): DOMContentLoaded, the load event, the first rung drawn, and the first
live frame painted. The static page of `ladderjit ladder --format html` (every rung in the DOM)
is loaded the same way for comparison. Usage: live_page_load.py LADDERJIT PROGRAM [RUNS]"""
import os, re, subprocess, sys, tempfile, threading, time, urllib.request

from selenium import webdriver
from selenium.webdriver.chrome.service import Service

exe, program = sys.argv[1], sys.argv[2]
runs = int(sys.argv[3]) if len(sys.argv) > 3 else 5
tmp = tempfile.mkdtemp(prefix="ljload")
static = os.path.join(tmp, "static.html")
subprocess.run([exe, "ladder", program, "--format", "html", "-o", static], check=True,
               stderr=subprocess.DEVNULL, timeout=120)
opts = webdriver.ChromeOptions()
opts.binary_location = "/usr/bin/chromium"
for a in ["--headless=new", "--no-sandbox", "--disable-gpu", "--window-size=1400,900",
          "--user-data-dir=" + os.path.join(tmp, "profile")]:
    opts.add_argument(a)
driver = webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=opts)
driver.set_page_load_timeout(120)
t_start = time.time()
serve = subprocess.Popen([exe, "serve", program, "--http", "127.0.0.1:0", "--duration", "600"],
                         stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True)
url = None
while url is None:
    line = serve.stdout.readline()
    if not line:
        sys.exit("serve ended before printing the live view")
    m = re.search(r"live view (http://\S+) \(token in (\S+)\)", line)
    if m:  # every request needs the token (issue 28): Bearer here, ?token= for a browser
        TOKEN = open(m.group(2)).read().strip()
        AUTH = {"Authorization": "Bearer " + TOKEN}
    url = m.group(1) if m else None
# The first page of the run: opened as soon as serve prints its URL; from serve's start to the
# first frame with power flow (trace words) painted. Its traced build is requested by this page.
driver.get(url + "?token=" + TOKEN)
first = 0
while not first and time.time() - t_start < 120:
    first = driver.execute_script(
        "var L=window.ladder;return L&&L.drawn()>0&&L.live.last&&L.live.last.w?1:0")
    if not first:
        time.sleep(0.01)
print("first page: serve start -> first live frame with power flow %.2f s" % (time.time() - t_start))
# Wait for the traced build (the first watcher asks for it; a compile off the scan thread), and
# keep that watcher open: between two page loads no page watches, and serve would put the
# untraced build back 10 s after the last one left (the next page would wait for a rebuild).
t0 = time.time()
es = urllib.request.urlopen(urllib.request.Request(url + "api/events", headers=AUTH), timeout=120)
for raw in es:
    if raw.startswith(b"data:") and b'"w":' in raw:
        break
print("traced build in after %.1f s (first watcher)" % (time.time() - t0))
threading.Thread(target=lambda: [None for _ in es], daemon=True).start()
page_bytes = len(urllib.request.urlopen(urllib.request.Request(url, headers=AUTH)).read())
print("live page %d bytes, static page %d bytes" % (page_bytes, os.path.getsize(static)))



def measure(target, live):
    driver.get("about:blank")
    driver.get(target)
    cond = ("var L=window.ladder;return L&&L.drawn()>0&&L.live.last&&L.live.last.w?performance.now():0"
            if live else "return document.querySelectorAll('g.rung').length?performance.now():0")
    end = 0
    t = time.time()
    while not end and time.time() - t < 60:
        end = driver.execute_script(cond)
        if not end:
            time.sleep(0.01)
    nav = driver.execute_script(
        "var n=performance.getEntriesByType('navigation')[0];return [n.domContentLoadedEventEnd,n.loadEventEnd]")
    return nav[0], nav[1], end


try:
    for name, target, live in [("live page (lazy)", url + "?token=" + TOKEN, True), ("static page (every rung)", "file://" + static, False)]:
        rows = [measure(target, live) for _ in range(runs)]
        for d, l, e in rows:
            print("%-26s DOMContentLoaded %6.0f ms  load %6.0f ms  %s %6.0f ms" %
                  (name, d, l, "live frame painted" if live else "rungs in the DOM  ", e))
        med = sorted(r[2] for r in rows)[len(rows) // 2]
        print("%-26s median %.0f ms over %d loads" % (name, med, runs))
finally:
    driver.quit()
    serve.terminate()
    serve.wait(timeout=10)
print("load average %s" % open("/proc/loadavg").read().strip())

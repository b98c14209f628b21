#!/usr/bin/python3
"""Does watching delay a tick? (docs/BENCHMARKS.md "Live view"): `serve PROGRAM --period-ms 1
--rt-priority 50 --http 127.0.0.1:0 --duration SECONDS` with PAGES watchers on the live view from
the moment it is up (the first one makes serve put the traced build in). Prints serve's end-of-run
line (ticks, overruns, missed deadlines), what each watcher received, and the load average.

MODE sse (the default): PAGES Server-Sent-Events clients on /api/events (Python threads), each
reading and JSON-parsing every frame, as a page does.
MODE chromium: PAGES real pages, tabs of headless Chromium (Debian /usr/bin/chromium with
chromedriver and python3-selenium), PER_BROWSER tabs per browser, each browser with a fresh
--user-data-dir; started before serve, so their start-up is not in the run. Each tab loads the live page as soon as serve prints its URL and draws every
frame (background-tab throttling is off, so all PAGES tabs paint as a foreground one would). Each
tab is checked twice, a third into the run and just before its end; it is live when at the second
check its newest frame carries trace words (power flow), its tick advanced since the first check
and rungs are drawn.
Usage: live_watchers.py LADDERJIT PROGRAM PAGES SECONDS [sse|chromium]"""
import json, re, shutil, subprocess, sys, tempfile, threading, time, urllib.request

exe, program, pages, secs = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4])
mode = sys.argv[5] if len(sys.argv) > 5 else "sse"
# A browser keeps at most 6 HTTP/1.1 connections per server, and each live tab holds one (its
# event stream): a 7th tab of one browser would wait for a free connection, never live. So the
# pages are spread over browsers of PER_BROWSER tabs each.
PER_BROWSER = 5
if mode not in ("sse", "chromium"):
    sys.exit("MODE is sse or chromium")

drivers, profiles, tabs = [], [], []  # tabs: (driver, window handle)
if mode == "chromium" and pages:
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service

    for b in range((pages + PER_BROWSER - 1) // PER_BROWSER):
        profiles.append(tempfile.mkdtemp(prefix="ljwatch"))
        opts = webdriver.ChromeOptions()
        opts.binary_location = "/usr/bin/chromium"
        opts.page_load_strategy = "none"  # navigate all tabs at once; liveness is checked below
        for a in ["--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
                  "--disable-background-networking", "--disable-component-update", "--disable-sync",
                  "--user-data-dir=" + profiles[-1], "--window-size=1400,900",
                  "--disable-background-timer-throttling", "--disable-renderer-backgrounding",
                  "--disable-backgrounding-occluded-windows"]:
            opts.add_argument(a)
        d = webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=opts)
        drivers.append(d)
        for k in range(min(PER_BROWSER, pages - b * PER_BROWSER)):
            if k:
                d.switch_to.new_window("tab")
            tabs.append((d, d.current_window_handle))

print("load average before: %s" % open("/proc/loadavg").read().strip(), flush=True)
serve = subprocess.Popen([exe, "serve", program, "--period-ms", "1", "--rt-priority", "50",
                          "--http", "127.0.0.1:0", "--duration", str(secs)],
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
start = time.time()
url = None
lines = []
while url is None:
    line = serve.stdout.readline()
    if not line:
        sys.exit("serve ended before printing the live view")
    lines.append(line.rstrip())
    m = re.search(r"live view (http://\S+) \(token in (\S+)\)", line)
    if m:  # every request needs the token (issue 28): Bearer here, ?token= for a browser
        TOKEN = open(m.group(2)).read().strip()
        AUTH = {"Authorization": "Bearer " + TOKEN}
    url = m.group(1) if m else None
end = start + secs
frames = [0] * pages
traced = [0] * pages
errors = []


def watch(i):
    try:
        with urllib.request.urlopen(urllib.request.Request(url + "api/events", headers=AUTH), timeout=30) as es:
            for raw in es:
                if raw.startswith(b"data:"):
                    m = json.loads(raw[5:])
                    frames[i] += 1
                    traced[i] += 1 if "w" in m else 0
    except Exception as e:  # serve ended: the stream closes (or resets)
        if time.time() < end - 1:
            errors.append("client %d: %s" % (i, e))


reader = threading.Thread(target=lambda: lines.extend(l.rstrip() for l in serve.stdout), daemon=True)
reader.start()
checks = []
if mode == "sse":
    threads = [threading.Thread(target=watch, args=(i,), daemon=True) for i in range(pages)]
    for t in threads:
        t.start()
elif pages:
    for d, h in tabs:
        d.switch_to.window(h)
        d.get(url + "?token=" + TOKEN)
    probe = ("var L=window.ladder,m=L&&L.live&&L.live.last;return [document.visibilityState,"
             "m?m.tick:-1,!!(m&&m.w),L&&L.drawn?L.drawn():0]")
    for at in (secs / 3.0, secs - 4.0):
        time.sleep(max(0.0, start + at - time.time()))
        t = time.time() - start
        row = []
        for d, h in tabs:
            d.switch_to.window(h)
            try:
                row.append(d.execute_script(probe))
            except Exception as e:
                row.append(["error: %s" % e, -1, False, 0])
        checks.append((t, row))
reader.join(timeout=secs + 120)
serve.wait()
if mode == "sse":
    for t in threads:
        t.join(timeout=5)
for d in drivers:
    d.quit()
for p in profiles:
    shutil.rmtree(p, ignore_errors=True)
print("\n".join(l for l in lines if "warning" not in l and
                re.search(r"--duration|SIGTERM|scan |jitter|tiering|traced|live view|online change", l)))
if mode == "sse" and pages:
    print("frames parsed per client: min %d max %d (traced: min %d)" % (min(frames), max(frames), min(traced)))
if checks:
    (t1, a), (t2, b) = checks
    live = [y[2] and y[1] > x[1] and y[3] > 0 for x, y in zip(a, b)]
    print("chromium: %d browsers, %d tabs, visibility %s; checks at %.1f s and %.1f s: live in %d of %d tabs "
          "(traced frame, tick advanced, rungs drawn); traced already at the 1st: %d" %
          (len(drivers), pages, sorted(set(str(x[0]) for x in a + b)), t1, t2, sum(live), pages, sum(bool(x[2]) for x in a)))
    print("  ticks seen per tab at the 2nd check: min %d max %d; rungs drawn per tab: min %d max %d" %
          (min(y[1] for y in b), max(y[1] for y in b), min(y[3] for y in b), max(y[3] for y in b)))
    for i, (x, y) in enumerate(zip(a, b)):
        if not live[i]:
            print("  tab %d NOT live: %s -> %s" % (i, x, y))
print("client errors: %s" % (errors or "none"))
print("load average after: %s" % open("/proc/loadavg").read().strip())

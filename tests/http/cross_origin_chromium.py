#!/usr/bin/python3
"""Issue 28 finding 1, the cross-origin case, in headless Chromium: a page of ANOTHER origin (a
python3 http.server on another loopback port) that embeds <img src=".../api/events">, frames the
live page and fetch()es the API, in a browser that holds the live view's cookie, gets nothing and
does not make `serve` build a traced version. examples/lathe_panel.stl with --engine interp
--http-read-only: the Auto key (X480.0 1 then 0) leaves R0.2 = 0 and G2620 = 1; after the visit
they are still 0 and 1, the running version and the swap count are unchanged, serve's log shows
no traced build, and the page's fetches failed. Usage: cross_origin_chromium.py LADDERJIT EXAMPLES OUTDIR"""
import http.server, json, os, re, socketserver, subprocess, sys, threading, time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import liveutil  # noqa: E402

exe, examples, out = sys.argv[1], sys.argv[2], sys.argv[3]
os.makedirs(out, exist_ok=True)
check = liveutil.check
sock = os.path.join(out, "serve.sock")
errpath = os.path.join(out, "serve.err")
serve = subprocess.Popen([exe, "serve", os.path.join(examples, "lathe_panel.stl"), "--engine", "interp",
                          "--http", "127.0.0.1:0", "--http-read-only", "--control", sock, "--duration", "90"],
                         stdout=subprocess.PIPE, stderr=open(errpath, "w"), text=True)
url = token = None
t0 = time.time()
while time.time() - t0 < 30 and url is None:
    line = serve.stdout.readline()
    if not line:
        break
    m = re.search(r"live view (http://\S+?)/? \(token in (\S+)\)", line)
    if m:
        url, token = m.group(1), liveutil.read_token(m.group(2))
    m = re.search(r"live view (http://\S+?)/? \(token (\w+)\)", line)
    if m:
        url, token = m.group(1), m.group(2)
if not url:
    serve.kill()
    sys.exit("serve did not print its live view line")
port = int(url.rsplit(":", 1)[1])


def monitor(*args):
    r = subprocess.run([exe, "monitor", "--control", sock] + list(args), capture_output=True, text=True, timeout=20)
    return r.stdout


def values():
    text = monitor("read", "R0.2", "G2620")
    r = re.search(r"R0\.2\D+(\d+)", text)
    g = re.search(r"G2620\D+(\d+)", text)
    return (int(r.group(1)) if r else None, int(g.group(1)) if g else None), text.strip()


def stats():
    try:
        return json.loads(monitor("stats"))
    except ValueError:
        return {}


# The attacker's page, on another origin.
evil = os.path.join(out, "evil")
os.makedirs(evil, exist_ok=True)
with open(os.path.join(evil, "index.html"), "w") as f:
    f.write("""<!DOCTYPE html><html><body>
<img src="http://127.0.0.1:%(p)d/api/events"><img src="http://localhost:%(p)d/api/events">
<iframe id="fr" src="http://127.0.0.1:%(p)d/"></iframe>
<script>
window.results = [];
function tryit(u, o) { return fetch(u, o).then(function (r) { return r.text().then(function (t) {
  window.results.push(u + ' READ ' + r.status + ' ' + t.slice(0, 80)); }); },
  function (e) { window.results.push(u + ' failed'); }); }
tryit('http://127.0.0.1:%(p)d/api/model', {credentials: 'include'});
tryit('http://127.0.0.1:%(p)d/api/state', {credentials: 'include'});
tryit('http://127.0.0.1:%(p)d/api/events', {credentials: 'include', mode: 'no-cors'});
try { new EventSource('http://127.0.0.1:%(p)d/api/events', {withCredentials: true}); } catch (e) {}
</script></body></html>""" % {"p": port})


class Quiet(http.server.SimpleHTTPRequestHandler):
    def __init__(self, *a, **k):
        super().__init__(*a, directory=evil, **k)

    def log_message(self, *a):
        pass


httpd = socketserver.TCPServer(("127.0.0.1", 0), Quiet)
threading.Thread(target=httpd.serve_forever, daemon=True).start()
evil_url = "http://127.0.0.1:%d/" % httpd.server_address[1]

driver = liveutil.chrome()
try:
    time.sleep(1.0)
    monitor("write", "X480.0=1")
    time.sleep(0.3)
    monitor("write", "X480.0=0")
    time.sleep(0.3)
    v0, text = values()
    check(v0 == (0, 1), "after the Auto key: R0.2, G2620 = %s (want 0, 1): %s" % (v0, text))
    s0 = stats()
    ver0 = s0.get("program", {}).get("version")
    swaps0 = s0.get("swaps")
    # The browser holds the live view's credential: the cookie the page sets (a 404 page of the
    # server first, so the cookie's domain is the server's; no live page is opened).
    driver.get(url + "/favicon.ico")
    driver.add_cookie({"name": "ljtoken_%d" % port, "value": token, "path": "/", "httpOnly": True,
                       "sameSite": "Strict"})
    driver.get(evil_url)
    time.sleep(8)  # the traced build would be in within a second or two
    results = driver.execute_script("return window.results")
    # Each fetch failed, or (no-cors) came back opaque: status 0, no byte readable.
    check(results is not None and len(results) >= 3 and all(r.endswith("failed") or r.endswith(" READ 0 ") for r in results),
          "the other origin's fetches got nothing: %s" % results)
    v1, text = values()
    s1 = stats()
    check(v1 == (0, 1), "after the cross-origin page: R0.2, G2620 = %s (want 0, 1): %s" % (v1, text))
    check(s1.get("program", {}).get("version") == ver0 and s1.get("swaps") == swaps0,
          "version %s -> %s, swaps %s -> %s (unchanged)" % (ver0, s1.get("program", {}).get("version"),
                                                             swaps0, s1.get("swaps")))
    log = open(errpath).read()
    check("traced" not in log.lower(), "serve's log shows no traced build: %r" % log[-600:])
finally:
    driver.quit()
    httpd.shutdown()
    serve.terminate()
    try:
        serve.wait(timeout=15)
    except subprocess.TimeoutExpired:
        serve.kill()
print("%d failed" % len(liveutil.failures))
sys.exit(1 if liveutil.failures else 0)

#!/usr/bin/python3
"""Does watching delay a tick? (docs/BENCHMARKS.md "Live view"): `serve PROGRAM --period-ms 1
--rt-priority 50 --http 127.0.0.1:0 --duration SECONDS` with PAGES Server-Sent-Events clients on
/api/events from the moment the live view is up (the first one makes serve put the traced build
in). Each client reads and JSON-parses every frame, as a page does. Prints serve's end-of-run
line (ticks, overruns, missed deadlines), the frames each client parsed, and the load average.
Usage: live_watchers.py LADDERJIT PROGRAM PAGES SECONDS"""
import json, re, subprocess, sys, threading, time, urllib.request

exe, program, pages, secs = sys.argv[1], sys.argv[2], int(sys.argv[3]), int(sys.argv[4])
print("load average before: %s" % open("/proc/loadavg").read().strip(), flush=True)
serve = subprocess.Popen([exe, "serve", program, "--period-ms", "1", "--rt-priority", "50",
                          "--http", "127.0.0.1:0", "--duration", str(secs)],
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
url = None
lines = []
while url is None:
    line = serve.stdout.readline()
    if not line:
        sys.exit("serve ended before printing the live view")
    m = re.search(r"live view (http://\S+) ", line)
    url = m.group(1) if m else None
frames = [0] * pages
traced = [0] * pages
errors = []


def watch(i):
    try:
        with urllib.request.urlopen(url + "api/events", timeout=30) as es:
            for raw in es:
                if raw.startswith(b"data:"):
                    m = json.loads(raw[5:])
                    frames[i] += 1
                    traced[i] += 1 if "w" in m else 0
    except Exception as e:  # serve ended: the stream closes (or resets)
        if time.time() < end - 1:
            errors.append("client %d: %s" % (i, e))


end = time.time() + secs
threads = [threading.Thread(target=watch, args=(i,), daemon=True) for i in range(pages)]
for t in threads:
    t.start()
for line in serve.stdout:
    if "warning" not in line:
        lines.append(line.rstrip())
serve.wait()
for t in threads:
    t.join(timeout=5)
print("\n".join(l for l in lines if re.search(r"--duration|scan |jitter|tiering|traced|live view", l)))
if pages:
    print("frames parsed per client: min %d max %d (traced: min %d)" % (min(frames), max(frames), min(traced)))
print("client errors: %s" % (errors or "none"))
print("load average after: %s" % open("/proc/loadavg").read().strip())

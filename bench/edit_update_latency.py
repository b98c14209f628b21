#!/usr/bin/env python3
"""Update latency of the ladder editor (issue 30, docs/BENCHMARKS.md "Ladder editor: update
latency"): serve the realistic 10k program with --http, wait for the optimizing JIT, then CHANGES
times do what the page does for a one-rung edit: GET /api/edit (the running networks and hash),
change one contact's address in one rung (a different rung each time), POST the draft, and time
POST /api/edit/update (更新修改) from the request to its answer, which comes once the new version
runs (docs/ladder-edit.md, step 4: the online change has swapped it in). Serve's own statistics
give the online change's latency (requested -> new code running) and the scan's overruns and
missed deadlines around the swaps, which must not grow. Not a CTest test (timing).
Usage: bench/edit_update_latency.py BUILD_DIR WORK_DIR [CHANGES] [SERVE_OPTIONS]
(SERVE_OPTIONS: one argument, e.g. "--rt-priority 50 --cpu 1", added to serve's command line)"""
import http.client
import json
import os
import re
import statistics
import subprocess
import sys
import time

build, work = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2])
changes = int(sys.argv[3]) if len(sys.argv) > 3 else 20
extra = sys.argv[4].split() if len(sys.argv) > 4 else []
lj = os.path.join(build, "tools", "ladderjit")
os.makedirs(work, exist_ok=True)
prog = os.path.join(work, "p10k.stl")
subprocess.run([os.path.join(build, "bench", "gen_realistic"), "10000", prog], check=True,
               stdout=subprocess.DEVNULL)
for old in os.listdir(work):  # a previous run's history and audit log
    if old.startswith("p10k.stl."):
        subprocess.run(["rm", "-rf", os.path.join(work, old)], check=True)
sock = os.path.join(work, "c.sock")
if os.path.exists(sock):
    os.unlink(sock)
serve = subprocess.Popen([lj, "serve", prog, "--http", "127.0.0.1:0", "--control", sock,
                          "--duration", "900"] + extra, stdout=subprocess.PIPE,
                         stderr=open(os.path.join(work, "serve.err"), "w"), text=True)
port = token = None
deadline = time.time() + 60
while time.time() < deadline and port is None:
    line = serve.stdout.readline()
    m = re.search(r"live view http://127\.0\.0\.1:(\d+)/\S* \(token in (\S+)\)", line)
    if m:
        port, token = int(m.group(1)), open(m.group(2)).read().strip()
if port is None:
    serve.kill()
    sys.exit("serve did not print its live view address")


def call(path, body=None):
    c = http.client.HTTPConnection("127.0.0.1", port, timeout=120)
    headers = {"Authorization": "Bearer " + token}
    data = None
    if body is not None:
        data = json.dumps(body).encode()
        headers["Content-Type"] = "application/json"
    c.request("GET" if body is None else "POST", path, data, headers)
    r = c.getresponse()
    text = r.read()
    c.close()
    return r.status, json.loads(text) if text else {}


def stats():
    out = subprocess.run([lj, "monitor", "--control", sock, "stats"], capture_output=True,
                         text=True, check=True).stdout
    return json.loads(out)


while stats()["startup"]["tiering"]["engine"] != "jit-opt":
    time.sleep(0.5)
before = stats()
print("serving on jit-opt; load average: %s" % " ".join(open("/proc/loadavg").read().split()[:3]))


def contacts(node, out):
    """Every contact on an X bit address in `node` (dicts of the network JSON), in order."""
    if isinstance(node, dict):
        if node.get("type") == "contact":
            ops = node.get("operands", [])
            if ops and re.fullmatch(r"X\d+\.[0-7]", ops[0].get("text", "")):
                out.append(node)
        for v in node.values():
            contacts(v, out)
    elif isinstance(node, list):
        for v in node:
            contacts(v, out)
    return out


walls = []
for c in range(1, changes + 1):
    st, cur = call("/api/edit")
    assert st == 200, cur
    nets = cur["running"]["networks"]
    rungs = [r for p in nets["parts"] for r in p["rungs"] if contacts(r.get("network"), [])]
    rung = rungs[(c * 7919) % len(rungs)]
    op = contacts(rung["network"], [])[0]["operands"][0]
    byte, bit = op["text"].split(".")
    op["text"] = "%s.%d" % (byte, (int(bit) + 1) % 8)
    op.pop("symbol", None)
    nets["base"] = cur["running"]["hash"]
    st, ans = call("/api/edit/draft", nets)
    assert st == 200, ans
    t0 = time.perf_counter()
    st, ans = call("/api/edit/update", {})
    walls.append((time.perf_counter() - t0) * 1000.0)
    assert st == 200, ans
    time.sleep(1)
after = stats()
print("load average: %s" % " ".join(open("/proc/loadavg").read().split()[:3]))
oc = after["online_changes"]
lat = oc["latency_ms"]
print("updates %d: POST /api/edit/update -> answered with the new version running: "
      "min %.2f / median %.2f / max %.2f ms" % (len(walls), min(walls), statistics.median(walls),
                                                max(walls)))
print("serve's online changes %d: latency (requested -> new code running) min %.2f / median %.2f "
      "/ max %.2f ms (last %d)" % (oc["count"], lat["min"], lat["median"], lat["max"],
                                    lat["of_last"]))


def scan(j):
    return {k: j.get(k) for k in ("overruns", "missed_deadlines", "swap_overruns",
                                  "missed_after_swap", "swap_tick_max_us")}


print("scan before the updates: %s" % json.dumps(scan(before)))
print("scan after the updates:  %s" % json.dumps(scan(after)))
subprocess.run([lj, "monitor", "--control", sock, "stop"], capture_output=True)
serve.wait(timeout=60)

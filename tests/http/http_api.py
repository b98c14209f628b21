#!/usr/bin/env python3
"""The live view's HTTP API against a running `serve --http` (docs/serve.md "Live view"): a
request without the token is 401 with a reason (and logged with its origin), a wrong token 403,
bad bodies and unknown fields 400, GET on a POST route 405, an unknown path 404, malformed HTTP
never crashes the server, the SSE stream sends state events; with --http-read-only even the right
token is refused. Usage: http_api.py LADDERJIT OUTDIR"""
import json, os, re, socket, subprocess, sys, time, urllib.error, urllib.request

exe, out = sys.argv[1], sys.argv[2]
os.makedirs(out, exist_ok=True)
program = os.path.join(os.path.dirname(os.path.abspath(__file__)), "live.stl")
failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what, flush=True)
    if not ok:
        failures.append(what)


def start(extra, name):
    err = open(os.path.join(out, name + ".err"), "w+")
    p = subprocess.Popen([exe, "serve", program, "--http", "127.0.0.1:0", "--control",
                          os.path.join(out, name + ".sock"), "--duration", "30"] + extra,
                         stdout=subprocess.PIPE, stderr=err, text=True)
    while True:
        line = p.stdout.readline()
        if not line:
            raise SystemExit("serve ended before printing the live view line")
        m = re.search(r"live view (http://\S+)/ \(token in (\S+)\)", line)
        if m:
            return p, err, m.group(1), open(m.group(2)).read().strip()


def call(url, method="GET", body=None, token=None):
    req = urllib.request.Request(url, method=method, data=body.encode() if body is not None else None)
    if token:
        req.add_header("Authorization", "Bearer " + token)
    try:
        with urllib.request.urlopen(req, timeout=10) as r:
            return r.status, r.read().decode()
    except urllib.error.HTTPError as e:
        return e.code, e.read().decode()


def error_of(text):
    try:
        return json.loads(text).get("error", "")
    except ValueError:
        return ""


serve, err, base, token = start([], "rw")
try:
    st, body = call(base + "/", token=token)
    check(st == 200 and "ladder-layout" in body and "EventSource" in body, "GET / serves the live page")
    st, body = call(base + "/api/force", "POST", '{"id":2,"mode":"on"}')
    check(st == 401 and "missing token" in error_of(body), "force without a token: %d %s" % (st, error_of(body)))
    st, body = call(base + "/api/force", "POST", '{"id":2,"mode":"on"}', token="x" * len(token))
    check(st == 403 and error_of(body) == "wrong token", "force with a wrong token: %d %s" % (st, error_of(body)))
    st, body = call(base + "/api/force", "POST", "{not json", token=token)
    check(st == 400 and "JSON object" in error_of(body), "a body that is not JSON: %d" % st)
    st, body = call(base + "/api/force", "POST", '{"id":2,"mode":"on","x":1}', token=token)
    check(st == 400 and "unknown field 'x'" in error_of(body), "an unknown field: %d %s" % (st, error_of(body)))
    st, body = call(base + "/api/force", "POST", '{"id":2,"mode":"sideways"}', token=token)
    check(st == 400 and "mode must be" in error_of(body), "a bad mode: %d %s" % (st, error_of(body)))
    st, body = call(base + "/api/force", "POST", '{"id":99999,"mode":"on"}', token=token)
    check(st == 400 and "does not exist" in error_of(body), "an id that does not exist: %d" % st)
    st, body = call(base + "/api/force", token=token)
    check(st == 405, "GET on a POST route: %d" % st)
    st, body = call(base + "/nothing/here")
    check(st == 404 and "no such page" in error_of(body), "unknown path: %d" % st)
    # Malformed HTTP on a raw socket: an answer or a closed connection, and the server lives on.
    for junk in [b"\x00\xff garbage\r\n\r\n", b"GET / HTTP/1.1\r\nContent-Length: -5\r\n\r\n",
                 b"POST /api/force HTTP/1.1\r\nHost: x\r\nContent-Length: 99999999\r\n\r\n{"]:
        host, port = base[7:].split(":")
        with socket.create_connection((host, int(port)), timeout=5) as s:
            s.sendall(junk)
            try:
                s.recv(200)
            except socket.timeout:
                pass
    st, body = call(base + "/api/model", token=token)
    check(st == 200 and json.loads(body).get("version", 0) >= 1, "still serving after malformed requests")
    # SSE: state events with the version and, once the traced build is in, the trace words.
    events, traced = 0, False
    req = urllib.request.Request(base + "/api/events", headers={"Authorization": "Bearer " + token})
    with urllib.request.urlopen(req, timeout=10) as r:
        t0 = time.time()
        while time.time() - t0 < 8 and not (events >= 3 and traced):
            line = r.readline().decode()
            if line.startswith("data: "):
                m = json.loads(line[6:])
                events += 1
                traced = traced or (m.get("traced") and "w" in m)
    check(events >= 3 and traced, "SSE: %d state events, traced words seen: %s" % (events, traced))
    st, body = call(base + "/api/force", "POST", '{"id":2,"mode":"on"}', token=token)
    check(st == 200 and json.loads(body)["forces"][0]["id"] == 2, "force with the token: %d" % st)
    err.flush()
    log = open(err.name).read()
    check(re.search(r"http: refused POST /api/force from 127\.0\.0\.1:\d+ \(Origin: none\): missing token", log)
          is not None, "the refusal is logged with its origin")
    check(re.search(r'http: POST /api/force \{"id":2,"mode":"on"\} from 127\.0\.0\.1:\d+.*: ok', log) is not None,
          "the force is logged with its origin")
finally:
    serve.terminate()
    serve.wait(timeout=15)
check(serve.returncode == 0, "serve ended cleanly (exit %s)" % serve.returncode)

tokfile = os.path.join(out, "token")
with open(tokfile, "w") as f:
    f.write("s3cret-token-0123\n")
os.chmod(tokfile, 0o600)
serve, err, base, _ = start(["--http-read-only", "--http-token-file", tokfile], "ro")
try:
    st, body = call(base + "/api/force", "POST", '{"id":2,"mode":"on"}', token="s3cret-token-0123")
    check(st == 403 and "read-only" in error_of(body), "read-only: force refused even with the token: %d" % st)
    st, body = call(base + "/api/lock", "POST", '{"item":"D5=3"}', token="s3cret-token-0123")
    check(st == 403, "read-only: lock refused: %d" % st)
    st, body = call(base + "/api/locks", token="s3cret-token-0123")
    check(st == 200 and json.loads(body)["locks"] == [], "read-only: the lock list reads")
finally:
    serve.terminate()
    serve.wait(timeout=15)
print("%d failed" % len(failures))
sys.exit(1 if failures else 0)

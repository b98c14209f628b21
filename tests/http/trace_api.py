#!/usr/bin/env python3
"""The signal trace's HTTP routes against a running `serve --http` (docs/trace.md "Page",
docs/security.md "The live view's HTTP port"): GET /api/trace (status and the last capture) and
POST /api/trace (define, arm, trigger, stop: the requests of `monitor trace`, answered by the
same TraceControl), /dygraph.min.js and /dygraph.min.css (Debian's libjs-dygraphs).

- No token: 401; a wrong token: 403; a foreign Origin: 403; a body that is not JSON, an unknown
  field, an action the page may not send, a define without text or with a bad address, a bad
  `have`: 400 with a message naming the fault; a body over the limit: 413.
- A trace defined and armed through POST is the one `monitor trace status` shows; `monitor write
  X1.0=1` fires it; the capture GET /api/trace sends is the one `monitor trace save --csv` writes,
  row by row, and what the program makes (D1 counts the ticks, Y1.0 follows X1.0, pre 5 + 1 + post
  20 rows, X1.0 0 before the trigger row and 1 from it); its constant and two-valued columns are
  run-length coded; `have=ID` leaves it out.
- Every POST is logged with its body and its answer.
- dygraph.min.js is the Debian file byte for byte (with the page's cookie or the token; none:
  401); with LADDERJIT_DYGRAPHS_DIR on an empty folder it is a 404 naming libjs-dygraphs.
- Under --http-read-only, GET /api/trace answers (read_only true) and every POST is 403.

Usage: trace_api.py LADDERJIT OUTDIR"""
import json, os, re, shutil, subprocess, sys, time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import httputil  # noqa: E402
from httputil import call, check, get  # noqa: E402

exe, out = sys.argv[1], sys.argv[2]
shutil.rmtree(out, ignore_errors=True)
os.makedirs(out)
PROGRAM = "LDT\nADD D1 1 D1\nLD X1.0\nOUT Y1.0\n1END\n2END\n"
DEFINITION = "signal D1, Y1.0, X1.0\ntrigger rising X1.0\npre 5\npost 20\n"
DYGRAPHS = "/usr/share/javascript/dygraphs"
prog = os.path.join(out, "p.stl")
open(prog, "w").write(PROGRAM)


def mon(srv, *args):
    p = subprocess.run([exe, "monitor", "--control", srv.sock] + list(args), capture_output=True,
                       text=True, timeout=30)
    return p.returncode, p.stdout, p.stderr


def column(c, rows):
    if isinstance(c, list):
        return c
    v = []
    for i in range(0, len(c["rle"]), 2):
        v += [c["rle"][i]] * c["rle"][i + 1]
    check(len(v) == rows, "a run-length column holds %d rows: %d" % (rows, len(v)))
    return v


def raw_post(srv, body, extra=()):
    lines = ["POST /api/trace HTTP/1.1", "Host: 127.0.0.1:%d" % srv.port, "Connection: close",
             "Authorization: Bearer " + srv.token, "Content-Type: application/json",
             "Content-Length: %d" % len(body)] + list(extra)
    st, _, rest = httputil.request(srv.port, "\r\n".join(lines), body, timeout=20)
    try:
        return st, json.loads(rest)
    except ValueError:
        return st, {"raw": rest.decode(errors="replace")}


srv = httputil.Serve(exe, prog, out, "rw", extra=["--engine", "interp"], duration=100)
try:
    st, ans = call(srv, "/api/trace", token=None)
    check(st == 401 and "missing token" in ans.get("error", ""), "GET without the token: %s %s" % (st, ans))
    st, ans = call(srv, "/api/trace", {"action": "arm"}, token=None)
    check(st == 401 and "missing token" in ans.get("error", ""), "POST without the token: %s %s" % (st, ans))
    st, ans = call(srv, "/api/trace", {"action": "arm"}, token="x" * len(srv.token))
    check(st == 403 and ans.get("error") == "wrong token", "POST with a wrong token: %s %s" % (st, ans))
    st, ans = call(srv, "/api/trace", {"action": "arm"}, origin="http://evil.example")
    check(st == 403 and "cross-origin" in ans.get("error", ""), "POST from another origin: %s %s" % (st, ans))
    st, ans = call(srv, "/api/trace")
    check(st == 200 and ans.get("state") == "idle" and ans.get("read_only") is False and "capture" not in ans
          and ans.get("period_ns") == 1000000, "GET: idle, not read-only, 1 ms, no capture: %s" % ans)
    st, ans = raw_post(srv, b"action=arm")
    check(st == 400 and "must be a JSON object" in ans.get("error", ""), "a body that is not JSON: %s %s" % (st, ans))
    for body in ({}, {"action": "save"}, {"action": "status"}, {"action": 3}):
        st, ans = call(srv, "/api/trace", body)
        check(st == 400 and "POST /api/trace needs \"action\": define" in ans.get("error", ""),
              "POST %s: 400 naming the actions: %s %s" % (json.dumps(body), st, ans.get("error")))
    st, ans = call(srv, "/api/trace", {"action": "arm", "what": 1})
    check(st == 400 and "unknown field 'what'" in ans.get("error", ""), "an unknown field: %s %s" % (st, ans))
    st, ans = call(srv, "/api/trace", {"action": "define"})
    check(st == 400 and "define needs \"text\"" in ans.get("error", ""), "define without text: %s %s" % (st, ans))
    st, ans = call(srv, "/api/trace", {"action": "define", "text": "signal D1, Q9\n"})
    check(st == 400 and "bad address 'Q9'" in ans.get("error", ""), "a bad address: %s %s" % (st, ans))
    st, ans = call(srv, "/api/trace", {"action": "define", "text": "signal D1\ntrigger D1 ~ 3\n", "file": "page"})
    check(st == 400 and "page:2: trigger:" in ans.get("error", ""), "a bad trigger names its line: %s %s" % (st, ans))
    st, ans = call(srv, "/api/trace", {"action": "arm"})
    check(st == 400 and "no trace defined" in ans.get("error", ""), "arm before define: %s %s" % (st, ans))
    st, ans = raw_post(srv, json.dumps({"action": "define", "text": "#" * 70000}).encode())
    check(st == 413, "a body over 64 KiB: %s" % st)
    st, _, body = get(srv, "/api/trace?have=abc", srv.token)
    check(st == 400 and b"have must be a capture id" in body, "have=abc: %s %s" % (st, body[:100]))

    # A capture through the routes, the same as monitor trace's.
    st, ans = call(srv, "/api/trace", {"action": "define", "text": DEFINITION, "file": "page"})
    check(st == 200 and ans.get("state") == "stopped", "define: %s %s" % (st, ans))
    st, ans = call(srv, "/api/trace", {"action": "arm"})
    check(st == 200 and ans.get("armed") and ans.get("state") == "waiting", "arm: %s %s" % (st, ans))
    rc, o, _ = mon(srv, "trace", "status")
    check(rc == 0 and json.loads(o).get("definition", "").startswith(DEFINITION) and json.loads(o)["armed"],
          "monitor trace status shows the page's trace, armed: %s" % o[:200])
    time.sleep(0.2)
    mon(srv, "write", "X1.0=1")
    cap = None
    for _ in range(100):
        st, ans = call(srv, "/api/trace")
        if ans.get("capture"):
            cap = ans["capture"]
            break
        time.sleep(0.05)
    check(cap is not None, "GET /api/trace brings the capture")
    if cap:
        rows = cap["rows"]
        check(rows == 26 and cap["trigger_row"] == 5, "pre 5 + 1 + post 20 rows, trigger row 5: %d %d" % (rows, cap["trigger_row"]))
        check([s["name"] for s in cap["signals"]] == ["D1", "Y1.0", "X1.0"] and
              [s["bits"] for s in cap["signals"]] == [32, 1, 1], "signals with their widths: %s" % cap["signals"])
        check(cap["columns"][2] == {"rle": [0, 5, 1, 21]} and cap["columns"][1] == {"rle": [0, 5, 1, 21]},
              "X1.0 and Y1.0 run-length coded, 5 x 0 then 21 x 1: %s %s" % (cap["columns"][2], cap["columns"][1]))
        steps = column(cap["ticks"]["steps"], rows - 1)
        ticks = [cap["ticks"]["from"]]
        for s in steps:
            ticks.append(ticks[-1] + s)
        cols = [column(c, rows) for c in cap["columns"]]
        check(ticks[5] == cap["trigger_tick"], "the trigger row's tick is the trigger tick %s" % cap["trigger_tick"])
        check(all(cols[0][r] == cols[0][r - 1] + 1 for r in range(1, rows)), "D1 counts one per row (tick that ran)")
        csv = os.path.join(out, "c.csv")
        rc, o, e = mon(srv, "trace", "save", csv, "--csv")
        check(rc == 0, "monitor trace save: %s" % e)
        lines = open(csv).read().strip().split("\n")[1:] if rc == 0 else []
        want = ["%d,%d,%d,%d,%d,%d" % (ticks[r], ticks[r], cols[0][r], cols[1][r], cols[2][r], 1 if r == 5 else 0)
                for r in range(rows)]
        check(lines == want, "the page's capture is monitor trace save's, row by row (%d rows)" % len(lines))
        st, ans = call(srv, "/api/trace?have=%d" % cap["id"])
        check(st == 200 and "capture" not in ans and ans["last_capture"]["id"] == cap["id"],
              "have=%d: no rows sent again" % cap["id"])
        st, ans = call(srv, "/api/trace?have=0")
        check(st == 200 and ans.get("capture", {}).get("id") == cap["id"], "have=0: the capture")
    st, ans = call(srv, "/api/trace", {"action": "stop"})
    check(st == 200 and not ans.get("armed") and ans.get("state") == "stopped", "stop: %s %s" % (st, ans))
    st, ans = call(srv, "/api/trace", {"action": "trigger"})
    check(st == 400 and "not armed" in ans.get("error", ""), "trigger when stopped: %s %s" % (st, ans))
    # dygraphs from Debian's folder.
    st, hd, body = get(srv, "/dygraph.min.js", srv.token)
    check(st == 200 and body == open(DYGRAPHS + "/dygraph.min.js", "rb").read() and
          hd.get("content-type", [""])[0].startswith("text/javascript"), "dygraph.min.js is Debian's file: %s %s" % (st, hd.get("content-type")))
    st, hd, body = get(srv, "/dygraph.min.css", srv.token)
    check(st == 200 and body == open(DYGRAPHS + "/dygraph.min.css", "rb").read() and
          hd.get("content-type", [""])[0].startswith("text/css"), "dygraph.min.css is Debian's file: %s" % st)
    st, _, _ = get(srv, "/dygraph.min.js")
    check(st == 401, "dygraph.min.js without the token: %s" % st)
    log = srv.log().decode(errors="replace")
    check(re.search(r'http: POST /api/trace \{"action":"arm"\} from 127\.0\.0\.1:\d+: ok', log) is not None,
          "the log has POST /api/trace arm from ADDR: ok")
    check(re.search(r'http: POST /api/trace \{"action":"define","text":"signal D1, Q9\\x5cn"\} from \S+: '
                    r"refused: trace: bad address 'Q9'", log) is not None,
          "the log has the refused define, its body escaped, with the reason")
finally:
    srv.stop()

# Read-only, and dygraphs not installed.
empty = os.path.join(out, "no-dygraphs")
os.makedirs(empty)
os.environ["LADDERJIT_DYGRAPHS_DIR"] = empty
with open(os.path.join(out, "t.trace"), "w") as f:
    f.write(DEFINITION)
ro = httputil.Serve(exe, prog, out, "ro", extra=["--engine", "interp", "--http-read-only",
                                                  "--trace", os.path.join(out, "t.trace")], duration=60)
try:
    st, ans = call(ro, "/api/trace")
    check(st == 200 and ans.get("read_only") is True and ans.get("armed") and ans.get("state") == "waiting",
          "read-only: GET shows the trace serve --trace armed: %s %s" % (st, ans))
    for body in ({"action": "arm"}, {"action": "stop"}, {"action": "define", "text": DEFINITION}):
        st, ans = call(ro, "/api/trace", body)
        check(st == 403 and "read-only" in ans.get("error", ""), "read-only: POST %s refused: %s %s" % (body["action"], st, ans))
    st, ans = call(ro, "/api/trace")
    check(ans.get("armed") is True, "read-only: the trace is still armed")
    st, _, body = get(ro, "/dygraph.min.js", ro.token)
    check(st == 404 and b"libjs-dygraphs" in body and empty.encode() in body,
          "dygraphs absent: 404 naming the package: %s %s" % (st, body[:160]))
finally:
    ro.stop()
httputil.finish()

#!/usr/bin/env python3
"""Issue 28 finding 4 against a real `serve --http`: the operator is not locked out of the view.
(a) 100 event-stream clients with the token: at most 20 streams of one client address are served
(docs/security.md), every other one is answered 503 and its connection closed at once, and a
fresh authenticated GET /api/state is answered within 1 s while they are open.
(b) 60 slowloris connections (one header line every 3 s): a fresh authenticated request is
answered within 1 s throughout, and the server closes them once their headers are not complete
10 s after they connected (the header deadline).
Prints the numbers (time to answer, the scan's overruns) for docs/security.md.
Usage: http_lockout.py LADDERJIT OUTDIR"""
import os, select, socket, sys, time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from httputil import Serve, check, finish, overruns, timed_state  # noqa: E402

exe, out = sys.argv[1], sys.argv[2]
os.makedirs(out, exist_ok=True)
program = os.path.join(os.path.dirname(os.path.abspath(__file__)), "live.stl")
PER_CLIENT = 20  # docs/security.md: event streams of one client address at once
DEADLINE = 10  # docs/security.md: a request's headers and body complete within 10 s


def ms(t):
    return "%.0f ms" % (t * 1000) if t is not None else "no answer within 5 s"


srv = Serve(exe, program, out, "lockout")
socks = []
try:
    P, T = srv.port, srv.token
    # ---- (a) 100 event streams ----
    before = overruns(srv.stats())
    for i in range(100):
        s = socket.create_connection(("127.0.0.1", P), timeout=5)
        s.sendall(("GET /api/events HTTP/1.1\r\nHost: 127.0.0.1:%d\r\nAuthorization: Bearer %s\r\n"
                   "Accept: text/event-stream\r\n\r\n" % (P, T)).encode())
        socks.append(s)
    t0 = time.time()
    buf, status, eof = {s: b"" for s in socks}, {}, set()
    while time.time() - t0 < 5:
        wait = [s for s in socks if status.get(s) != 200 and s not in eof]
        if not wait:
            break
        r, _, _ = select.select(wait, [], [], 0.2)
        for s in r:
            try:
                b = s.recv(4096)
            except OSError:
                b = b""
            if not b:
                eof.add(s)
                continue
            buf[s] += b
            if s not in status and b"\r\n" in buf[s]:
                status[s] = int(buf[s].split(b" ")[1]) if buf[s].startswith(b"HTTP/") else None
    closed = sum(1 for s in socks if status.get(s) == 503 and s in eof)
    served = sum(1 for v in status.values() if v == 200)
    refused = sum(1 for v in status.values() if v == 503)
    t_ans = timed_state(srv)
    after = overruns(srv.stats())
    print("100 streams: %d served, %d answered 503, %d of those closed within 5 s; fresh request %s; "
          "overruns+missed %s -> %s" % (served, refused, closed, ms(t_ans), before, after), flush=True)
    check(1 <= served <= PER_CLIENT, "streams served to one client: %d (1..%d)" % (served, PER_CLIENT))
    check(refused == 100 - served, "the other %d answered 503: %d" % (100 - served, refused))
    check(closed >= refused, "the refused streams' connections closed at once: %d of %d" % (closed, refused))
    check(t_ans is not None and t_ans < 1.0, "a fresh authenticated request with 100 streams open: %s" % ms(t_ans))
    for s in socks:
        s.close()
    socks = []
    time.sleep(0.5)
    # ---- (b) 60 slowloris connections ----
    before = overruns(srv.stats())
    for i in range(60):
        s = socket.create_connection(("127.0.0.1", P), timeout=5)
        s.sendall(("GET /api/state HTTP/1.1\r\nHost: 127.0.0.1:%d\r\n" % P).encode())
        socks.append(s)
    t0 = time.time()
    worst, n, dead_at = 0.0, 0, {}
    while time.time() - t0 < DEADLINE + 4:
        for i, s in enumerate(socks):
            if s in dead_at:
                continue
            try:
                s.sendall(b"X-Slow-%d: 1\r\n" % n)
            except OSError:
                dead_at[s] = time.time() - t0
        n += 1
        for _ in range(3):  # a fresh request three times per 3 s round
            t = timed_state(srv)
            worst = max(worst, t if t is not None else 99)
            time.sleep(0.8)
    # Closed by the server: a read sees the end (or an error).
    for s in socks:
        if s in dead_at:
            continue
        r, _, _ = select.select([s], [], [], 0)
        if r:
            try:
                b = s.recv(4096)
            except OSError:
                b = b""
            if not b or b.startswith(b"HTTP/"):
                dead_at[s] = time.time() - t0
    after = overruns(srv.stats())
    print("60 slowloris: worst fresh request %s; %d of 60 closed by the server within %d s; "
          "overruns+missed %s -> %s" % (ms(worst if worst < 99 else None), len(dead_at), DEADLINE + 4,
                                        before, after), flush=True)
    check(worst < 1.0, "a fresh authenticated request under 60 slowloris connections: worst %s" %
          ms(worst if worst < 99 else None))
    check(len(dead_at) == 60, "the slowloris connections closed after the header deadline: %d of 60" % len(dead_at))
    check(srv.proc.poll() is None, "serve still runs")
finally:
    for s in socks:
        s.close()
    srv.stop()
finish()

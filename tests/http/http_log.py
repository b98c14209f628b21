#!/usr/bin/env python3
"""Issue 28 finding 5 against a real `serve --http`: refused requests cannot grow serve's log
without bound nor write control bytes into it. 2,000 POSTs without the token, each with a
4 KiB Origin holding terminal escapes (ESC ] title BEL, ESC [ 2J, the C1 CSI U+009B),
over 20 connections: serve's stderr must stay under 16 KiB, hold no control byte but the line
end and no raw C1 character, and say how many were refused in a summary line.
Usage: http_log.py LADDERJIT OUTDIR"""
import os, re, socket, sys, threading, time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from httputil import Serve, check, finish, timed_state  # noqa: E402

exe, out = sys.argv[1], sys.argv[2]
os.makedirs(out, exist_ok=True)
program = os.path.join(os.path.dirname(os.path.abspath(__file__)), "live.stl")
N, CONNS = 2000, 20

srv = Serve(exe, program, out, "log")
try:
    P = srv.port
    start = len(srv.log())
    origin = b"http://\x1b]0;pwned\x07\x1b[2J\xc2\x9b31m" + b"o" * 4096
    body = b'{"id":2,"mode":"on"}'
    req = (b"POST /api/force HTTP/1.1\r\nHost: 127.0.0.1:" + str(P).encode() +
           b"\r\nOrigin: " + origin + b"\r\nContent-Type: application/json\r\nContent-Length: " +
           str(len(body)).encode() + b"\r\nConnection: close\r\n\r\n" + body)
    done = [0]

    def worker(n):
        for _ in range(n):
            try:
                with socket.create_connection(("127.0.0.1", P), timeout=5) as s:
                    s.sendall(req)
                    while s.recv(65536):
                        pass
                done[0] += 1
            except OSError:
                pass

    t0 = time.time()
    ts = [threading.Thread(target=worker, args=(N // CONNS,)) for _ in range(CONNS)]
    for t in ts:
        t.start()
    for t in ts:
        t.join()
    dt = time.time() - t0
    answer = timed_state(srv)
    time.sleep(11)  # one summary window (10 s) and a little
    log = srv.log()[start:]
    print("%d refused POSTs in %.1f s: %d bytes of log; fresh request %s" %
          (done[0], dt, len(log), "%.0f ms" % (answer * 1000) if answer else "none"), flush=True)
    print(log.decode(errors="replace")[:1500])
    check(done[0] >= N * 9 // 10, "%d of %d requests sent and answered" % (done[0], N))
    check(len(log) < 16384, "serve's log grew by %d bytes for %d refusals (limit 16 KiB)" % (len(log), done[0]))
    bad = [b for b in log if (b < 0x20 and b not in (0x0a,)) or b == 0x7f]
    check(not bad, "no control byte in the log (found %d: %s)" % (len(bad), sorted(set(bad))[:8]))
    check(re.search(rb"[\xc2][\x80-\x9f]", log) is None, "no raw C1 character in the log")
    m = re.search(rb"refused (\d+) more request", log)
    check(m is not None and int(m.group(1)) >= done[0] // 2,
          "a summary line counts the refusals: %r" % (m.group(0) if m else None))
    check(re.search(rb"\\x1b", log) is not None, "the escape byte is written as \\x1b in the logged refusal")
finally:
    srv.stop()
finish()

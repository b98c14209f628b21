#!/usr/bin/env python3
"""Issue 28 finding 2 against a real `serve --http`: what one client sends cannot grow serve's
memory. Three attacks of 256 MiB each over loopback: header lines without end, a chunked POST
without the token, a chunked POST with the token (over the 64 KiB body limit). Each must leave
VmRSS within +64 MiB of idle (sampled every 10 ms during the attack), be cut off by the server
(connection closed or refused) before all of it is read, and a fresh authenticated request
must be answered within 1 s afterwards. Prints the numbers (RSS, seconds, the scan's overruns)
for docs/security.md. Usage: http_limits.py LADDERJIT OUTDIR"""
import os, socket, sys, threading, time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from httputil import Serve, check, finish, get, overruns, rss_kib, timed_state  # noqa: E402

exe, out = sys.argv[1], sys.argv[2]
os.makedirs(out, exist_ok=True)
program = os.path.join(os.path.dirname(os.path.abspath(__file__)), "live.stl")
TOTAL = 256 << 20  # bytes an attack sends at most
LIMIT_KIB = 64 << 10  # +64 MiB over idle
SECONDS = 40  # an attack ends after this at the latest


class Peak:
    def __init__(self, pid):
        self.pid, self.peak, self.stop = pid, 0, False
        self.t = threading.Thread(target=self.run, daemon=True)
        self.t.start()

    def run(self):
        while not self.stop:
            try:
                self.peak = max(self.peak, rss_kib(self.pid))
            except OSError:
                return
            time.sleep(0.01)

    def end(self):
        self.stop = True
        self.t.join()
        return self.peak


def flood(port, head, piece):
    """Send `head` then `piece` again and again until TOTAL bytes, SECONDS, or the server closes
    the connection; (bytes sent, seconds, cut off by the server)."""
    s = socket.create_connection(("127.0.0.1", port), timeout=10)
    sent, t0, cut = 0, time.time(), False
    try:
        s.sendall(head)
        while sent < TOTAL and time.time() - t0 < SECONDS:
            s.sendall(piece)
            sent += len(piece)
    except (BrokenPipeError, ConnectionResetError, socket.timeout):
        cut = True
    dt = time.time() - t0
    s.close()
    return sent, dt, cut


srv = Serve(exe, program, out, "limits")
rows = []
try:
    P, T = srv.port, srv.token
    host = "Host: 127.0.0.1:%d\r\n" % P
    get(srv, "/?token=" + T, None, timeout=10)
    get(srv, "/api/state", T, timeout=5)
    time.sleep(1.5)
    idle = rss_kib(srv.pid)
    line = b"X-Pad: " + b"a" * 1017 + b"\r\n"  # 1 KiB header lines
    attacks = [
        ("header lines without end", ("GET /api/state HTTP/1.1\r\n" + host).encode(), line * 1024),
        ("chunked POST, no token", ("POST /api/force HTTP/1.1\r\n" + host +
                                    "Content-Type: application/json\r\nTransfer-Encoding: chunked\r\n\r\n").encode(),
         b"100000\r\n" + b"7" * 0x100000 + b"\r\n"),
        ("chunked POST with the token", ("POST /api/force HTTP/1.1\r\n" + host + "Authorization: Bearer " + T +
                                         "\r\nContent-Type: application/json\r\nTransfer-Encoding: chunked\r\n\r\n").encode(),
         b"100000\r\n" + b"7" * 0x100000 + b"\r\n"),
    ]
    for name, head, piece in attacks:
        before = overruns(srv.stats())
        base = rss_kib(srv.pid)
        peak = Peak(srv.pid)
        sent, dt, cut = flood(P, head, piece)
        time.sleep(0.3)
        top = peak.end()
        answer = timed_state(srv, timeout=5)
        after = overruns(srv.stats())
        rows.append((name, base, top, sent, dt, answer, before, after))
        print("%s: idle %d KiB, RSS before %d KiB, peak %d KiB (+%d KiB), %d MiB sent in %.1f s, cut off: %s, "
              "fresh request %s, overruns+missed %s -> %s" %
              (name, idle, base, top, top - idle, sent >> 20, dt, cut,
               "%.0f ms" % (answer * 1000) if answer is not None else "none", before, after), flush=True)
        check(top - idle <= LIMIT_KIB, "%s: peak RSS +%d MiB over idle (limit +64 MiB)" % (name, (top - idle) >> 10))
        check(cut and sent < TOTAL, "%s: the server cut the client off after %d MiB" % (name, sent >> 20))
        check(answer is not None and answer < 1.0, "%s: a fresh authenticated request answered in %s" %
              (name, "%.0f ms" % (answer * 1000) if answer is not None else "no time"))
    check(srv.proc.poll() is None, "serve still runs")
finally:
    srv.stop()
finish()

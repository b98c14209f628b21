#!/usr/bin/env python3
"""Issue 28 finding 3 against a real `serve --http` (docs/security.md "The live view's HTTP
port"): a Host that is not the server's is refused (DNS rebinding) on the page and every API
path; every answer, reads too, needs the token (Bearer, or the HttpOnly SameSite=Strict cookie
set by opening the page with ?token=, which then redirects the token out of the address bar,
plus the page's key for the API); a foreign Origin is refused; the token never appears in what
serve prints, only the path of its 0600 file; a token file readable by group or others is
refused; --http-host adds a name; the page carries a CSP with frame-ancestors 'none'.
Usage: http_auth.py LADDERJIT OUTDIR"""
import json, os, re, stat, subprocess, sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from httputil import Serve, check, finish, get, request  # noqa: E402

exe, out = sys.argv[1], sys.argv[2]
os.makedirs(out, exist_ok=True)
program = os.path.join(os.path.dirname(os.path.abspath(__file__)), "live.stl")
def post(port, head, body):
    try:
        return request(port, head, body)
    except OSError as e:
        return None, {}, str(e).encode()


API = ["/api/model", "/api/state", "/api/locks", "/api/events"]
EVIL = "rebind.evil.example"

srv = Serve(exe, program, out, "auth")
try:
    T, P = srv.token, srv.port
    # The token is not printed; its file is this user's alone.
    check(T.encode() not in srv.stdout and T.encode() not in srv.log(),
          "the token is not in serve's output: %r" % srv.stdout.decode(errors="replace").strip()[-160:])
    check(srv.tokenfile is not None and os.path.exists(srv.tokenfile) and
          stat.S_IMODE(os.stat(srv.tokenfile).st_mode) == 0o600,
          "serve names its token file, mode 0600 (%s)" % srv.tokenfile)
    # DNS rebinding: the right token with a foreign Host is refused on every path.
    for path in ["/"] + API:
        st, _, body = get(srv, path, T, host=EVIL + ":%d" % P, timeout=5)
        check(st in (403, 421), "Host %s on %s: %s (want 421 or 403)" % (EVIL, path, st))
    st, _, _ = get(srv, "/api/model", T, host=EVIL, timeout=5)
    check(st in (403, 421), "Host %s (no port) on /api/model: %s" % (EVIL, st))
    # No credential: nothing reads.
    for path in ["/"] + API:
        st, _, body = get(srv, path, None, timeout=5)
        check(st in (401, 403) and b"ladder-layout" not in body and b'"stmts"' not in body,
              "%s without the token: %s (want 401)" % (path, st))
    st, _, _ = get(srv, "/api/model", "x" * len(T), timeout=5)
    check(st in (401, 403), "/api/model with a wrong token: %s" % st)
    # The right token reads.
    st, _, body = get(srv, "/api/model", T, timeout=5)
    check(st == 200 and json.loads(body).get("version", 0) >= 1, "/api/model with the token: %s" % st)
    st, _, body = get(srv, "/api/model", T, host="localhost:%d" % P, timeout=5)
    check(st == 200, "/api/model with Host localhost:%d: %s" % (P, st))
    # A foreign Origin is refused even with the token, on reads and on changes.
    st, _, _ = get(srv, "/api/model", T, extra=["Origin: http://evil.example"], timeout=5)
    check(st == 403, "GET /api/model with Origin http://evil.example: %s (want 403)" % st)
    st, _, _ = get(srv, "/api/model", T, extra=["Origin: http://127.0.0.1:%d" % (P + 1)], timeout=5)
    check(st == 403, "GET /api/model with Origin of another loopback port: %s (want 403)" % st)
    st, _, _ = get(srv, "/api/model", T, extra=["Origin: http://127.0.0.1:%d" % P], timeout=5)
    check(st == 200, "GET /api/model with its own Origin: %s" % st)
    body = b'{"id":2,"mode":"on"}'
    st, _, _ = post(P, "POST /api/force HTTP/1.1\r\nHost: 127.0.0.1:%d\r\nAuthorization: Bearer %s\r\n"
                          "Origin: http://evil.example\r\nContent-Type: application/json\r\n"
                          "Content-Length: %d\r\nConnection: close" % (P, T, len(body)), body)
    check(st == 403, "POST /api/force with a foreign Origin and the token: %s (want 403)" % st)
    # The page: ?token= sets an HttpOnly SameSite=Strict cookie and redirects to /.
    st, h, _ = get(srv, "/?token=" + T, None, timeout=5)
    cookie = (h.get("set-cookie") or [""])[0]
    check(st in (302, 303) and (h.get("location") or [""])[0] == "/" and T in cookie and
          "HttpOnly" in cookie and "SameSite=Strict" in cookie,
          "/?token= answers %s, Location %s, cookie %r" % (st, h.get("location"), cookie.replace(T, "T")))
    st, _, _ = get(srv, "/?token=" + "y" * len(T), None, timeout=5)
    check(st in (401, 403), "/?token=WRONG: %s" % st)
    pair = cookie.split(";")[0]
    st, h, page = get(srv, "/", None, extra=["Cookie: " + pair], timeout=10)
    csp = (h.get("content-security-policy") or [""])[0]
    check(st == 200 and b"ladder-layout" in page, "the page with the cookie: %s" % st)
    check("frame-ancestors 'none'" in csp and (h.get("x-frame-options") or [""])[0] == "DENY" and
          (h.get("x-content-type-options") or [""])[0] == "nosniff",
          "the page's CSP %r, X-Frame-Options %s" % (csp, h.get("x-frame-options")))
    # The API with the cookie needs the page's key too (a cross-site request cannot send it).
    m = re.search(rb'LJ_KEY="(\w+)"', page)
    check(m is not None, "the page carries its key")
    st, _, _ = get(srv, "/api/model", None, extra=["Cookie: " + pair], timeout=5)
    check(st in (401, 403), "/api/model with the cookie and no key: %s (want 401/403)" % st)
    if m:
        st, _, _ = get(srv, "/api/model", None, extra=["Cookie: " + pair, "X-Ladderjit-Key: " + m.group(1).decode()],
                       timeout=5)
        check(st == 200, "/api/model with the cookie and the page's key: %s" % st)
    log = srv.log()
    check(T.encode() not in log, "the token is not in serve's log")
finally:
    srv.stop()

# A token file readable by group or others is refused, like a private key.
tokfile = os.path.join(out, "token.loose")
with open(tokfile, "w") as f:
    f.write("s3cret-token-0123\n")
os.chmod(tokfile, 0o644)
r = subprocess.run([exe, "serve", program, "--http", "127.0.0.1:0", "--http-token-file", tokfile,
                    "--control", os.path.join(out, "loose.sock"), "--duration", "5"],
                   capture_output=True, text=True, timeout=30)
check(r.returncode != 0 and "group or others" in r.stderr,
      "a 0644 token file is refused: exit %d, %r" % (r.returncode, r.stderr.strip()[-200:]))
os.chmod(tokfile, 0o600)
# --http-host NAME: that name is this server too.
srv = Serve(exe, program, out, "named", ["--http-token-file", tokfile, "--http-host", "plc.example"])
try:
    st, _, _ = get(srv, "/api/model", "s3cret-token-0123", host="plc.example:%d" % srv.port, timeout=5)
    check(st == 200, "--http-host plc.example: Host plc.example:%d answers %s" % (srv.port, st))
    st, _, _ = get(srv, "/api/model", "s3cret-token-0123", host="other.example:%d" % srv.port, timeout=5)
    check(st in (403, 421), "--http-host plc.example: Host other.example refused: %s" % st)
    check(b"s3cret-token-0123" not in srv.stdout, "a --http-token-file token is not printed either")
finally:
    srv.stop()
finish()

"""Shared by the HTTP attack and access tests (issue 28): `serve --http` started on a free
loopback port with its address and token read from what it prints (the token from the file it
names; before issue 28 it printed the token itself), raw HTTP over a socket, VmRSS of a process,
`monitor stats` of a control socket. Loopback only; every test bounds its own counts and time."""
import json, os, re, socket, subprocess, sys, time

failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what, flush=True)
    if not ok:
        failures.append(what)


def finish():
    print("%d failed" % len(failures))
    sys.exit(1 if failures else 0)


class Serve:
    """`serve PROGRAM --http 127.0.0.1:0 --control SOCK ...`, stopped by stop()."""

    def __init__(self, exe, program, out, name, extra=(), duration=120, wait=30):
        self.exe = exe
        self.sock = os.path.join(out, name + ".sock")
        self.errpath = os.path.join(out, name + ".err")
        self.outpath = os.path.join(out, name + ".out")
        self.err = open(self.errpath, "wb")
        self.proc = subprocess.Popen([exe, "serve", program, "--http", "127.0.0.1:0", "--control",
                                      self.sock, "--duration", str(duration)] + list(extra),
                                     stdout=subprocess.PIPE, stderr=self.err)
        self.stdout = b""
        self.url = self.token = self.tokenfile = None
        deadline = time.time() + wait
        while time.time() < deadline:
            line = self.proc.stdout.readline()
            if not line:
                break
            self.stdout += line
            text = line.decode(errors="replace")
            m = re.search(r"live view (http://\S+?)/? \(token in (\S+)\)", text)
            if m:
                self.url, self.tokenfile = m.group(1), m.group(2)
                with open(self.tokenfile) as f:
                    self.token = f.read().strip()
                break
            m = re.search(r"live view (http://\S+?)/? \((?:token (\w+))?", text)
            if m:
                self.url, self.token = m.group(1), m.group(2)
                break
        if not self.url:
            self.proc.kill()
            raise SystemExit("serve did not print its live view line; stderr:\n" +
                             open(self.errpath, errors="replace").read())
        hp = self.url[len("http://"):]
        self.host, self.port = hp.rsplit(":", 1)[0], int(hp.rsplit(":", 1)[1])
        self.pid = self.proc.pid

    def rss_kib(self):
        return rss_kib(self.pid)

    def stats(self):
        r = subprocess.run([self.exe, "monitor", "--control", self.sock, "stats"],
                           capture_output=True, text=True, timeout=20)
        try:
            return json.loads(r.stdout)
        except ValueError:
            return {}

    def log(self):
        self.err.flush()
        with open(self.errpath, "rb") as f:
            return f.read()

    def stop(self):
        if self.proc.poll() is None:
            self.proc.terminate()
            try:
                self.proc.wait(timeout=20)
            except subprocess.TimeoutExpired:
                self.proc.kill()
                self.proc.wait()
        try:
            self.stdout += self.proc.stdout.read()
        except (OSError, ValueError):
            pass
        self.err.close()


def rss_kib(pid):
    with open("/proc/%d/status" % pid) as f:
        for line in f:
            if line.startswith("VmRSS:"):
                return int(line.split()[1])
    return 0


def request(port, head, body=b"", timeout=5.0):
    """One raw request (`head` without the final blank line); (status or None, headers, body)."""
    with socket.create_connection(("127.0.0.1", port), timeout=timeout) as s:
        s.sendall(head.encode() + b"\r\n\r\n" + body)
        data = b""
        try:
            while True:
                b = s.recv(65536)
                if not b:
                    break
                data += b
                if b"\r\n\r\n" in data:
                    h, _, rest = data.partition(b"\r\n\r\n")
                    m = re.search(rb"(?i)content-length:\s*(\d+)", h)
                    if m and len(rest) >= int(m.group(1)):
                        break
        except socket.timeout:
            pass
    h, _, rest = data.partition(b"\r\n\r\n")
    m = re.match(rb"HTTP/1\.\d (\d+)", h)
    headers = {}
    for line in h.split(b"\r\n")[1:]:
        k, _, v = line.partition(b":")
        headers.setdefault(k.strip().lower().decode(errors="replace"), []).append(v.strip().decode(errors="replace"))
    return (int(m.group(1)) if m else None), headers, rest


def get(srv, path, token=None, host=None, extra=(), timeout=5.0):
    """GET `path` from `srv` with the token (Bearer) unless None; (status, headers, body)."""
    lines = ["GET %s HTTP/1.1" % path, "Host: %s" % (host or "127.0.0.1:%d" % srv.port),
             "Connection: close"]
    if token:
        lines.append("Authorization: Bearer " + token)
    lines += list(extra)
    try:
        return request(srv.port, "\r\n".join(lines), timeout=timeout)
    except OSError as e:  # refused or reset: no answer (the check that reads it fails)
        return None, {}, str(e).encode()


def timed_state(srv, timeout=5.0):
    """Seconds a fresh authenticated GET /api/state took (None: no 200 within `timeout`)."""
    t0 = time.time()
    try:
        st, _, body = get(srv, "/api/state", srv.token, timeout=timeout)
    except OSError:
        return None
    dt = time.time() - t0
    return dt if st == 200 else None


def overruns(stats):
    return stats.get("overruns", 0), stats.get("missed_deadlines", 0)


def call(srv, path, body=None, token=True, origin=None, host=None):
    """GET (body None) or POST `path` with a JSON body; (status, JSON answer or {})."""
    data = b"" if body is None else json.dumps(body).encode()
    lines = ["%s %s HTTP/1.1" % ("GET" if body is None else "POST", path),
             "Host: %s" % (host or "127.0.0.1:%d" % srv.port), "Connection: close"]
    if token:
        lines.append("Authorization: Bearer " + (srv.token if token is True else token))
    if origin:
        lines.append("Origin: " + origin)
    if body is not None:
        lines += ["Content-Type: application/json", "Content-Length: %d" % len(data)]
    st, _, rest = request(srv.port, "\r\n".join(lines), data, timeout=60)
    try:
        return st, json.loads(rest)
    except ValueError:
        return st, {}


def chrome(width=1400, prefix="ljpage"):
    """Headless Chromium through selenium with a fresh profile (background network, sync and
    update off) and a 20 s script timeout; selenium is imported here, so the HTTP-only tests
    do not need it."""
    import tempfile
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service
    opts = webdriver.ChromeOptions()
    opts.binary_location = "/usr/bin/chromium"
    for a in ["--headless=new", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
              "--disable-component-update", "--disable-sync", "--no-first-run",
              "--window-size=%d,1000" % width, "--user-data-dir=" + tempfile.mkdtemp(prefix=prefix)]:
        opts.add_argument(a)
    d = webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=opts)
    d.set_script_timeout(20)
    return d


def wait(what, fn, seconds=30):
    """fn() until truthy (its value) or None after `seconds`."""
    end = time.time() + seconds
    while time.time() < end:
        try:
            v = fn()
        except Exception:  # noqa: BLE001 - an element between two renders
            v = None
        if v:
            return v
        time.sleep(0.1)
    print("     (waited %d s for %s)" % (seconds, what))
    return None

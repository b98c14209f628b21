"""Shared by the live-view browser tests (live_page.py, live_10k.py): checks, a Modbus coil
write written out by hand (no client library), `serve` started with its live view and Modbus
server and their addresses read from its output (the token from the file serve names), and
headless Chromium through selenium."""
import os, re, socket, struct, subprocess, sys

from selenium import webdriver
from selenium.webdriver.chrome.service import Service

failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what, flush=True)
    if not ok:
        failures.append(what)


def modbus_write_coil(port, addr, on):
    """Modbus TCP function 5 (write single coil)."""
    with socket.create_connection(("127.0.0.1", port), timeout=5) as s:
        s.sendall(struct.pack(">HHHBBHH", 1, 0, 6, 1, 5, addr, 0xFF00 if on else 0))
        ans = s.recv(64)
        assert len(ans) >= 12 and ans[7] == 5, "modbus answer %r" % ans


def read_token(path):
    """The token of the file serve names (`live view URL (token in FILE)`)."""
    with open(path) as f:
        return f.read().strip()


def start_serve(exe, program, sock, errfile, duration, wait=20, modbus=True, extra=()):
    """serve PROGRAM --http 127.0.0.1:0 --modbus 0 --modbus-write-inputs (without the Modbus
    options when `modbus` is false); (proc, url, token, modbus port or None), or exit 1 when it
    did not print the addresses within `wait` seconds. `extra`: more serve options."""
    import time
    mb = ["--modbus", "0", "--modbus-write-inputs"] if modbus else []
    serve = subprocess.Popen([exe, "serve", program, "--http", "127.0.0.1:0"] + mb +
                             ["--control", sock, "--duration", str(duration)] + list(extra),
                             stdout=subprocess.PIPE, stderr=open(errfile, "w"), text=True)
    url = token = mport = None
    deadline = time.time() + wait
    while time.time() < deadline and (url is None or (modbus and mport is None)):
        line = serve.stdout.readline()
        if not line:
            break
        m = re.search(r"live view (http://\S+) \(token in (\S+)\)", line)
        if m:
            url, token = m.group(1), read_token(m.group(2))
        m = re.search(r"live view (http://\S+) \(token (\w+)\)", line)  # before issue 28
        if m:
            url, token = m.group(1), m.group(2)
        m = re.search(r"modbus TCP on [\d.]+:(\d+)", line)
        if m:
            mport = int(m.group(1))
    if not url or (modbus and not mport):
        print("serve did not print the live view and modbus lines", file=sys.stderr)
        serve.kill()
        sys.exit(1)
    return serve, url, token, mport


def chrome():
    opts = webdriver.ChromeOptions()
    opts.binary_location = "/usr/bin/chromium"
    for a in ["--headless=new", "--no-sandbox", "--disable-gpu", "--window-size=1400,900"]:
        opts.add_argument(a)
    return webdriver.Chrome(service=Service("/usr/bin/chromedriver"), options=opts)


def stop(driver, serve):
    driver.quit()
    serve.terminate()
    try:
        serve.wait(timeout=10)
    except subprocess.TimeoutExpired:
        serve.kill()


def open_page(exe, program, out, name, duration=60, modbus=False, extra=()):
    """serve PROGRAM with its live view (start_serve; control socket and log named after `name`
    in `out`) and headless Chromium on its page, the token taken: (serve, driver, url, token,
    control socket, Modbus port or None)."""
    sock = os.path.join(out, name + ".sock")
    serve, url, token, mport = start_serve(exe, program, sock, os.path.join(out, name + ".err"),
                                           duration, modbus=modbus, extra=extra)
    driver = chrome()
    driver.get(url + "?token=" + token)
    return serve, driver, url, token, sock, mport


def monitor_read(exe, sock, addr):
    """`ladderjit monitor read ADDR`'s value, or None."""
    r = subprocess.run([exe, "monitor", "--control", sock, "read", addr], capture_output=True,
                       text=True, timeout=10)
    m = re.search(r"=\s*(-?\d+)\s*$", r.stdout.strip())
    return int(m.group(1)) if m else None

"""Issue 11 finding 6: client slots cannot be starved. With 16 idle connections and a client
dripping one byte every 0.4 s, a new control client (`monitor read`, `monitor stop`) and a new
Modbus client are still served within a bound; the dripping client is closed by the whole-request
deadline (2 s default) and an idle one by --client-idle-s."""
import os
import re
import shutil
import socket
import struct
import sys
import tempfile
import threading
import time

from ctl_common import PROGRAM, check, finish, output, run, start_serve, stop_serve


def modbus_port(out):
    end = time.time() + 30
    while time.time() < end:
        m = re.search(r"modbus TCP on 127\.0\.0\.1:(\d+)", output(out))
        if m:
            return int(m.group(1))
        time.sleep(0.02)
    return None


def read_w5(port, timeout=5):
    """A fresh Modbus client reads holding register 5 (W5); the value, or None."""
    try:
        s = socket.create_connection(("127.0.0.1", port), timeout=timeout)
        s.sendall(struct.pack(">HHHBBHH", 1, 0, 6, 1, 3, 5, 1))
        r = s.recv(64)
        s.close()
        return struct.unpack(">H", r[9:11])[0] if len(r) == 11 and r[7] == 3 else None
    except OSError:
        return None


def drip(make, data, result):
    """Send `data` one byte every 0.4 s; record how long until the server closed on us."""
    t0 = time.time()
    s = make()
    try:
        for b in data:
            s.sendall(bytes([b]))
            time.sleep(0.4)
        s.settimeout(1)
        while s.recv(4096):
            pass
    except OSError:
        pass
    result.append(time.time() - t0)
    s.close()


def closed_within(s, seconds):
    """Whether the server closes the idle connection `s` within `seconds`."""
    s.settimeout(seconds)
    t0 = time.time()
    try:
        while s.recv(4096):
            pass
        return time.time() - t0 <= seconds
    except socket.timeout:
        return False
    except OSError:
        return True


def main():
    tmp = tempfile.mkdtemp(prefix="lj-ctl-slots-")
    prog = os.path.join(tmp, "p.stl")
    with open(prog, "w") as f:
        f.write(PROGRAM)
    sock = os.path.join(tmp, "c.sock")
    proc, got, out = start_serve([prog, "--control", sock, "--modbus", "127.0.0.1:0",
                                  "--duration", "120", "--set", "W5=1234"],
                                 out_path=os.path.join(tmp, "serve.out"))
    port = modbus_port(out)
    check(got == sock and port, "serve started with Modbus: " + output(out))
    if not port:
        proc.kill()
        return finish()
    check(read_w5(port) == 1234, "a Modbus client reads W5 = 1234 before the flood")

    # Modbus: 16 idle connections and one writing 16 registers a byte every 0.4 s (18 s).
    idle_tcp = [socket.create_connection(("127.0.0.1", port)) for _ in range(16)]
    frame = struct.pack(">HHHBBHHB", 9, 0, 7 + 32, 1, 16, 0, 16, 32) + bytes(32)
    tcp_drip = []
    t = threading.Thread(target=drip, args=(
        lambda: socket.create_connection(("127.0.0.1", port)), frame, tcp_drip))
    t.start()
    time.sleep(0.5)
    t0 = time.time()
    v = read_w5(port)
    dt = time.time() - t0
    check(v == 1234 and dt < 3, "with 16 idle Modbus clients and a dripping one, a new client "
          "reads W5 = 1234 (in %.2f s): %s" % (dt, v))
    t.join(timeout=30)
    check(tcp_drip and tcp_drip[0] < 5, "the dripping Modbus client is closed by the 2 s request "
          "deadline (after %s s, its frame would take 18 s)" % tcp_drip)

    # Control: 16 idle connections and one dripping a request line.
    idle_ctl = []
    for _ in range(16):
        s = socket.socket(socket.AF_UNIX)
        s.connect(sock)
        idle_ctl.append(s)
    ctl_drip = []

    def unix():
        s = socket.socket(socket.AF_UNIX)
        s.connect(sock)
        return s
    t = threading.Thread(target=drip, args=(unix, b'{"cmd":"read","addrs":["D10"]}\n', ctl_drip))
    t.start()
    time.sleep(0.5)
    t0 = time.time()
    rc, val, err = run("monitor", "--control", sock, "read", "D10")
    dt = time.time() - t0
    check(rc == 0 and val.strip() == "D10=7" and dt < 3,
          "with 16 idle control connections and a dripping one, monitor read works (%.2f s): %r %s"
          % (dt, val, err.strip()))
    t.join(timeout=30)
    check(ctl_drip and ctl_drip[0] < 5, "the dripping control client is closed by the 2 s request "
          "deadline (after %s s, its line would take 12 s)" % ctl_drip)
    for _ in range(16):  # top up: 16 idle again, then stop must get in
        s = socket.socket(socket.AF_UNIX)
        s.connect(sock)
        idle_ctl.append(s)
    t0 = time.time()
    rc, _, err = run("monitor", "--control", sock, "stop")
    check(rc == 0, "monitor stop works with 16 idle control connections: " + err.strip())
    try:
        rc = proc.wait(timeout=10)
    except Exception:
        rc = None
    check(rc == 0 and time.time() - t0 < 10, "serve stopped cleanly (rc %s)" % rc)
    if proc.poll() is None:
        proc.kill()
    for s in idle_tcp + idle_ctl:
        s.close()

    # Idle deadline: --client-idle-s 1 closes idle control and Modbus connections.
    sock2 = os.path.join(tmp, "c2.sock")
    proc, got, out = start_serve([prog, "--control", sock2, "--modbus", "127.0.0.1:0",
                                  "--duration", "60", "--client-idle-s", "1"],
                                 out_path=os.path.join(tmp, "serve2.out"))
    port = modbus_port(out)
    if port:
        s = socket.socket(socket.AF_UNIX)
        s.connect(sock2)
        check(closed_within(s, 3), "an idle control connection is closed after --client-idle-s 1")
        s.close()
        s = socket.create_connection(("127.0.0.1", port))
        check(closed_within(s, 3), "an idle Modbus connection is closed after --client-idle-s 1")
        s.close()
    else:
        check(False, "second serve started: " + output(out))
    check(stop_serve(proc, sock2) == 0, "second serve stops cleanly")
    shutil.rmtree(tmp)
    return finish()


if __name__ == "__main__":
    sys.exit(main())

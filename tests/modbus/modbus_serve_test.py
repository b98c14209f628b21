#!/usr/bin/python3
"""Modbus TCP against a running `ladderjit serve` (issue 6 item 4).

Part 1: Debian's mbpoll, a client we did not write, reads and writes through the documented map
(docs/modbus-map.md). Part 2: raw sockets send malformed frames (garbage, a truncated MBAP header,
an unknown function, bad quantities and values); the server answers with a Modbus exception or
closes that connection, and keeps serving other clients, many at once. A missing mbpoll FAILS
(no skip). Exit status 0 = pass.
"""
import argparse
import os
import re
import shutil
import signal
import socket
import struct
import subprocess
import sys
import tempfile
import threading
import time

# R0.0 -> Y1.0, W4 -> W5, B2 -> D3, G10 -> W6: each write's effect is visible after one tick
# (DIALECT.md 3 OUT / function blocks MOV).
PROGRAM = """; modbus map test program (tests/modbus/modbus_serve_test.py)
LD R0.0
OUT Y1.0
LDT
MOV W4 W5
LDT
MOV B2 D3
LDT
MOV G10 W6
1END
"""

failures = []


def check(cond, what):
    print(("ok    " if cond else "FAIL  ") + what)
    if not cond:
        failures.append(what)


def mbpoll(args, port, *opts):
    """Run mbpoll once (-0: PDU addresses as in docs/modbus-map.md); (rc, output, values)."""
    cmd = [args.mbpoll, "-m", "tcp", "-p", str(port), "-0", "-1", "-o", "2"] + list(opts)
    p = subprocess.run(cmd, capture_output=True, text=True, timeout=30)
    out = p.stdout + p.stderr
    values = [int(v) for v in re.findall(r"^\[\d+\]:\s+(-?\d+)", p.stdout, re.M)]
    return p.returncode, out, values


def frame(tid, pdu, proto=0, length=None):
    length = len(pdu) + 1 if length is None else length
    return struct.pack(">HHHB", tid, proto, length, 1) + pdu


def exchange(port, data, timeout=3.0):
    """Send raw bytes on a fresh connection; return the reply bytes (b'' = closed)."""
    s = socket.create_connection(("127.0.0.1", port), timeout=timeout)
    try:
        s.sendall(data)
        return s.recv(260)
    except socket.timeout:
        return None
    except ConnectionResetError:  # closed with unread bytes left: the kernel sends RST
        return b""
    finally:
        s.close()


def part1(args, port):
    host = "127.0.0.1"
    # Coils: R0.0 is coil 5000; the program copies it to Y1.0 = coil 8*1+0 = 8.
    rc, out, _ = mbpoll(args, port, "-t", "0", "-r", "5000", host, "1")
    check(rc == 0, "mbpoll writes coil 5000 (R0.0)")
    rc, out, v = mbpoll(args, port, "-t", "0", "-r", "8", host)
    check(rc == 0 and v == [1], "coil 8 (Y1.0) reads 1 after R0.0 was set: %s" % v)
    # Holding registers: W4 = 4, written 16-bit; the program copies it to W5.
    rc, out, _ = mbpoll(args, port, "-t", "4", "-r", "4", host, "1234")
    rc, out, v = mbpoll(args, port, "-t", "4", "-r", "5", host)
    check(rc == 0 and v == [1234], "register 5 (W5) = 1234 after writing register 4: %s" % v)
    # 32-bit: B2 = registers 2004/2005, low word first (mbpoll's default 32-bit word order).
    rc, out, _ = mbpoll(args, port, "-t", "4:int", "-r", "2004", host, "--", "-100000")
    check(rc == 0, "mbpoll writes B2 = -100000 as registers 2004/2005")
    rc, out, v = mbpoll(args, port, "-t", "4:int", "-r", "1006", host)
    check(rc == 0 and v == [-100000], "D3 (registers 1006/1007) = -100000: %s" % v)
    rc, out, v = mbpoll(args, port, "-t", "4", "-r", "2004", "-c", "2", host)
    check(v == [(-100000) & 0xFFFF, ((-100000) >> 16) & 0xFFFF],
          "B2 low word at 2004, high word at 2005: %s" % v)
    # G10 = register 3010.
    rc, out, _ = mbpoll(args, port, "-t", "4", "-r", "3010", host, "77")
    rc, out, v = mbpoll(args, port, "-t", "4", "-r", "6", host)
    check(v == [77], "W6 = 77 after writing G10 (register 3010): %s" % v)
    # Discrete inputs: X2.3 (--set X2.3=1) is input 19; input registers: P7 (--set) at 5014.
    rc, out, v = mbpoll(args, port, "-t", "1", "-r", "19", host)
    check(v == [1], "discrete input 19 (X2.3) = 1: %s" % v)
    rc, out, v = mbpoll(args, port, "-t", "3:int", "-r", "5014", host)
    check(v == [70000], "input registers 5014/5015 (P7) = 70000: %s" % v)
    # Writes where the PLC may not be written, and unmapped addresses: ILLEGAL DATA ADDRESS.
    for what, opts in [("coil 10000 (X0.0, no simulation flag)", ["-t", "0", "-r", "10000"]),
                       ("register 10000 (F0)", ["-t", "4", "-r", "10000"]),
                       ("register 200 (unmapped)", ["-t", "4", "-r", "200"])]:
        rc, out, _ = mbpoll(args, port, *opts, host, "1")
        check(rc != 0 and "Illegal data address" in out, "write to %s refused" % what)
    rc, out, _ = mbpoll(args, port, "-t", "4", "-r", "2004", host, "1")
    check(rc != 0 and "Illegal data address" in out, "half of a 32-bit B register refused")
    rc, out, _ = mbpoll(args, port, "-t", "3", "-r", "9000", host)
    check(rc != 0 and "Illegal data address" in out, "read of unmapped input register refused")


def part2(args, port):
    r = exchange(port, frame(1, bytes([0x41, 0xAA])))
    check(r is not None and r[7:9] == bytes([0xC1, 0x01]), "unknown function 0x41: exception 01")
    r = exchange(port, frame(2, struct.pack(">BHH", 3, 0, 126)))
    check(r is not None and r[7:9] == bytes([0x83, 0x03]), "read 126 registers: exception 03")
    r = exchange(port, frame(3, struct.pack(">BHH", 5, 8, 0x1234)))
    check(r is not None and r[7:9] == bytes([0x85, 0x03]), "coil value 0x1234: exception 03")
    r = exchange(port, frame(4, struct.pack(">BHH", 1, 60000, 8)))
    check(r is not None and r[7:9] == bytes([0x81, 0x02]), "read coils at 60000: exception 02")
    r = exchange(port, b"hello, this is not modbus\r\n")
    check(r == b"", "garbage (protocol id != 0): connection closed")
    r = exchange(port, b"\x00\x01\x00")
    check(r == b"", "truncated MBAP header: connection closed by the request deadline")
    r = exchange(port, frame(5, struct.pack(">BHH", 3, 0, 1), length=200)[:12])
    check(r == b"", "MBAP length longer than the frame: connection closed")
    # Many clients at once, while one connection idles half-way through a frame.
    idle = socket.create_connection(("127.0.0.1", port))
    idle.sendall(b"\x00\x09\x00\x00")
    results = []

    def reader(i):
        try:
            s = socket.create_connection(("127.0.0.1", port), timeout=5)
            for k in range(20):
                s.sendall(frame(k, struct.pack(">BHH", 3, 5, 1)))
                rsp = s.recv(64)
                results.append(rsp[7:11] == bytes([3, 2]) + struct.pack(">H", 1234))
            s.close()
        except OSError:
            results.append(False)

    threads = [threading.Thread(target=reader, args=(i,)) for i in range(10)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    idle.close()
    check(len(results) == 200 and all(results), "10 clients x 20 reads of W5 = 1234 at once")
    rc, out, v = mbpoll(args, port, "-t", "4", "-r", "5", "127.0.0.1")
    check(v == [1234], "mbpoll still served after the malformed frames: %s" % v)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--ladderjit", required=True)
    ap.add_argument("--mbpoll", default="")
    args = ap.parse_args()
    if not args.mbpoll or not shutil.which(args.mbpoll):
        print("FAIL: mbpoll not found (install Debian's mbpoll: scripts/setup.sh)")
        return 1
    work = tempfile.mkdtemp(prefix="lj-modbus-")
    prog = os.path.join(work, "map.stl")
    with open(prog, "w") as f:
        f.write(PROGRAM)
    out = open(os.path.join(work, "serve.out"), "w+")
    proc = subprocess.Popen(
        [args.ladderjit, "serve", prog, "--modbus", "127.0.0.1:0", "--duration", "120",
         "--set", "P7=70000", "--set", "X2.3=1", "--control", os.path.join(work, "ctl.sock")],
        stdout=out, stderr=subprocess.STDOUT)
    port = None
    deadline = time.time() + 60
    while port is None and time.time() < deadline and proc.poll() is None:
        out.seek(0)
        m = re.search(r"modbus TCP on 127\.0\.0\.1:(\d+)", out.read())
        port = int(m.group(1)) if m else None
        time.sleep(0.02)
    if port is None:
        out.seek(0)
        print("FAIL: serve did not start:\n" + out.read())
        proc.kill()
        return 1
    try:
        part1(args, port)
        part2(args, port)
    finally:
        proc.send_signal(signal.SIGTERM)
        rc = proc.wait(timeout=30)
    check(rc == 0, "serve exits 0 on SIGTERM")
    shutil.rmtree(work)
    print("%d failures" % len(failures))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())

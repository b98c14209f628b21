#!/usr/bin/python3
"""Retain soak test (issue 6 acceptance, docs/retain.md "Soak test").

Repeatedly: start `ladderjit serve PROGRAM --retain FILE --modbus 127.0.0.1:0`, check what it
restored, let a Modbus client write B0 = k, k+1, ... (recording which writes were acknowledged),
SIGKILL the server at a random moment, and on the next start check that
  * the restore never fell back (not to FILE.prev, not to zeros): the file is always readable;
  * the restored B0 is a state that was acknowledged: last acknowledged <= B0 <= last sent
    (docs/retain.md "Acknowledgement": a B write is answered only after a durable save).
The Modbus client here is a minimal one of our own (speed); the map itself is tested with
Debian's mbpoll in tests/modbus. Exit status 0 = pass; the numbers are printed either way.
"""
import argparse
import os
import random
import re
import signal
import socket
import struct
import subprocess
import sys
import tempfile
import threading
import time

# B1 changes every tick, so periodic (rate-limited) saves run all the time and the kills also
# land in the middle of those; counter C300 (retained) counts R0.0, toggled every tick by ALT.
PROGRAM = """; retain soak program (tests/retain/soak.py)
LDT
ADD B1 1 B1
LDT
ALT 0
OUT R0.0
LD R0.0
LDI R0.1
CTRC 300 1000000
OUT R0.2
1END
"""


class ModbusClient:
    """Just enough Modbus TCP (FC3 read, FC16 write) for the soak loop."""

    def __init__(self, port):
        self.sock = socket.create_connection(("127.0.0.1", port), timeout=5)
        self.tid = 0

    def _call(self, pdu):
        self.tid = (self.tid + 1) & 0xFFFF
        self.sock.sendall(struct.pack(">HHHB", self.tid, 0, len(pdu) + 1, 1) + pdu)
        head = self._recv(7)
        tid, proto, length, _unit = struct.unpack(">HHHB", head)
        body = self._recv(length - 1)
        if tid != self.tid or proto != 0:
            raise RuntimeError("bad response header")
        if body[0] & 0x80:
            raise RuntimeError("modbus exception %d" % body[1])
        return body

    def _recv(self, n):
        data = b""
        while len(data) < n:
            chunk = self.sock.recv(n - len(data))
            if not chunk:
                raise ConnectionError("closed")
            data += chunk
        return data

    def write_b(self, index, value):
        lo, hi = value & 0xFFFF, (value >> 16) & 0xFFFF  # low word first (docs/modbus-map.md)
        self._call(struct.pack(">BHHBHH", 16, 2000 + 2 * index, 2, 4, lo, hi))

    def read_b(self, index):
        body = self._call(struct.pack(">BHH", 3, 2000 + 2 * index, 2))
        lo, hi = struct.unpack(">HH", body[2:6])
        return struct.unpack("<i", struct.pack("<HH", lo, hi))[0]

    def close(self):
        self.sock.close()


def start(args, workdir, retain):
    out = open(os.path.join(workdir, "serve.out"), "w+")
    err = open(os.path.join(workdir, "serve.err"), "w+")
    proc = subprocess.Popen(
        [args.ladderjit, "serve", os.path.join(workdir, "soak.stl"), "--engine", "interp",
         "--retain", retain, "--modbus", "127.0.0.1:0", "--duration", "60",
         "--control", os.path.join(workdir, "ctl.sock")],
        stdout=out, stderr=err)
    deadline = time.time() + 30
    while time.time() < deadline:
        out.seek(0)
        m = re.search(r"modbus TCP on 127\.0\.0\.1:(\d+)", out.read())
        if m:
            return proc, int(m.group(1)), err
        if proc.poll() is not None:
            break
        time.sleep(0.005)
    proc.kill()
    err.seek(0)
    sys.exit("FAIL: serve did not start: " + err.read())


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--ladderjit", required=True)
    ap.add_argument("--kills", type=int, default=200)
    ap.add_argument("--max-run-ms", type=int, default=250)
    ap.add_argument("--seed", type=int, default=1)
    args = ap.parse_args()
    rng = random.Random(args.seed)
    workdir = tempfile.mkdtemp(prefix="lj-soak-")
    with open(os.path.join(workdir, "soak.stl"), "w") as f:
        f.write(PROGRAM)
    retain = os.path.join(workdir, "plc.retain")

    last_acked = 0  # B0 value of the newest acknowledged write (0 = the power-up value)
    last_sent = 0   # B0 value of the newest write sent (acknowledged or not)
    acked_total = 0
    unacked_at_kill = 0
    restored_equal_acked = 0
    started = time.time()
    failures = []
    for run in range(args.kills + 1):
        proc, port, err = start(args, workdir, retain)
        client = ModbusClient(port)
        b0 = client.read_b(0)
        err.seek(0)
        log = err.read()
        expect = "does not exist yet" if run == 0 else "retain: restored " + retain + " ("
        if expect not in log or "WARNING" in log or "ERROR" in log:
            failures.append("run %d: unexpected restore log: %s" % (run, log.strip()))
        if not last_acked <= b0 <= last_sent:
            failures.append("run %d: restored B0 = %d, acknowledged %d, sent %d"
                            % (run, b0, last_acked, last_sent))
        restored_equal_acked += b0 == last_acked
        if run == args.kills:
            proc.send_signal(signal.SIGTERM)
            proc.wait(timeout=30)
            client.close()
            break
        # Kill at a random moment while the client writes B0 = k, k+1, ...
        delay = rng.uniform(0.0, args.max_run_ms / 1000.0)
        killer = threading.Timer(delay, proc.send_signal, (signal.SIGKILL,))
        killer.start()
        try:
            while True:
                last_sent += 1
                client.write_b(0, last_sent)
                last_acked = last_sent
                acked_total += 1
        except (ConnectionError, OSError, RuntimeError):
            unacked_at_kill += last_sent != last_acked
        killer.join()
        proc.wait(timeout=30)
        client.close()
        if len(failures) > 5:
            break
    elapsed = time.time() - started
    print("soak: %d kills in %.1f s, %d acknowledged B0 writes, %d writes in flight at a kill, "
          "restored == last acknowledged %d times, failures %d"
          % (run, elapsed, acked_total, unacked_at_kill, restored_equal_acked, len(failures)))
    for f in failures:
        print("FAIL: " + f)
    if not failures:
        subprocess.run(["rm", "-rf", workdir])
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/python3
"""Retain store and Modbus map files of FANUC and IEC programs through `ladderjit serve` (CLI).

Expected behaviour, from the references and the docs:
  * FANUC keeps K, D and the T / C data tables across power-off; R is cleared ("With an R
    register the accumulated count is 0 at power-on"; fanuc-pmc.md 1.3 "Retentive memory").
  * IEC (Neza) keeps the first 64 %M bits through a power failure (modicon-neza.md 1.1, L542).
  * A Modbus write to a retained element is acknowledged only once a save holding it is durable;
    periodic saves run every --retain-period-ms (docs/retain.md "Acknowledgement", "When").
  * A map file names the program's addresses (docs/modbus-map.md "Map files"); registers of a
    2-byte FANUC word (D100:2) and IEC words (%MW10) are one register each, coils are bits.
  * SET keeps its coil set (fanuc-pmc.md SET; IEC S), so the restored bit stays after a restart.
Per target: write retained and volatile elements over Modbus and through inputs, SIGKILL serve,
restart it, and read everything back with `monitor read` and Modbus. Then: the other target's
file is refused (exit 2); bad map lines and a missing map are usage errors naming the problem.
Exit status 0 = pass.
"""
import os
import shutil
import signal
import socket
import struct
import subprocess
import sys
import tempfile
import time

FANUC = """; tests/retain/profile_serve.py
RD X0.0
SET K0.1
RD X0.1
SET R0.0
END1
END2
END
"""
FANUC_MAP = """# tests/retain/profile_serve.py
holding 0 D100:2 4     # D100, D102, D104, D106 (retained)
holding 10 R100 2      # bytes (volatile)
holding 20 T0:2 1      # a TMR preset (retained)
coils 0 K0.0 8         # keep relays (retained)
coils 100 Y0.0 8
"""
IEC = """(* tests/retain/profile_serve.py *)
000 LD %I0.0
001 S %M3
002 LD %I0.1
003 S %M70
"""
IEC_MAP = """coils 0 %M0 64
coils 64 %M64 64
holding 0 %MW10 4
"""
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "support"))
import serveutil  # noqa: E402
from serveutil import FAILURES, check  # noqa: E402,F401


class Modbus:
    def __init__(self, port):
        self.s = socket.create_connection(("127.0.0.1", port), timeout=10)
        self.tid = 0

    def call(self, pdu):
        self.tid += 1
        self.s.sendall(struct.pack(">HHHB", self.tid, 0, len(pdu) + 1, 1) + pdu)
        head = self._recv(7)
        _, _, length, _ = struct.unpack(">HHHB", head)
        return self._recv(length - 1)

    def _recv(self, n):
        b = b""
        while len(b) < n:
            chunk = self.s.recv(n - len(b))
            if not chunk:
                raise IOError("modbus connection closed")
            b += chunk
        return b

    def write_regs(self, addr, values):
        pdu = struct.pack(">BHHB", 16, addr, len(values), 2 * len(values))
        pdu += b"".join(struct.pack(">H", v & 0xFFFF) for v in values)
        return self.call(pdu)[0] == 16

    def write_coil(self, addr, on):
        return self.call(struct.pack(">BHH", 5, addr, 0xFF00 if on else 0))[0] == 5

    def read_regs(self, addr, count):
        r = self.call(struct.pack(">BHH", 3, addr, count))
        if r[0] != 3:
            return None
        return list(struct.unpack(">%dH" % count, r[2:2 + 2 * count]))

    def read_coils(self, addr, count):
        r = self.call(struct.pack(">BHH", 1, addr, count))
        if r[0] != 1:
            return None
        return [(r[2 + i // 8] >> (i % 8)) & 1 for i in range(count)]


SHM_MEM = 64 + 15712  # docs/serve.md "Shared-memory image": header, lj_image, then lj_state.mem
FANUC_K_IN_MEM = 21648  # profiles/fanuc/Areas.cpp: K0 at mem + 21648


def shm_region(name):
    """The published lj_state.mem of a serve --shm NAME (read without the seqlock: a test)."""
    with open("/dev/shm/" + name, "rb") as f:
        data = f.read()
    mem_size = struct.unpack_from("<I", data, 56)[0]
    return mem_size, data[SHM_MEM:SHM_MEM + mem_size]


class Server:
    def __init__(self, lj, workdir, program, mapfile, retain, name, extra=()):
        self.lj = lj
        self.sock = os.path.join(workdir, name + ".sock")
        self.out = open(os.path.join(workdir, name + ".out"), "w+")
        self.err = open(os.path.join(workdir, name + ".err"), "w+")
        self.proc = subprocess.Popen(
            [lj, "serve", program, "--engine", "interp", "--retain", retain,
             "--retain-period-ms", "50", "--modbus", "0", "--modbus-map", mapfile,
             "--control", self.sock, "--duration", "60", *extra],
            stdout=self.out, stderr=self.err)
        self.port = None
        deadline = time.time() + 30
        while time.time() < deadline:
            self.out.seek(0)
            text = self.out.read()
            if "modbus TCP on 127.0.0.1:" in text:
                self.port = int(text.split("modbus TCP on 127.0.0.1:")[1].split()[0])
                self.mb = Modbus(self.port)
                return
            if self.proc.poll() is not None:
                break
            time.sleep(0.01)
        self.proc.kill()
        sys.exit("FAIL: serve did not start: " + self.log())

    def log(self):
        self.err.seek(0)
        return self.err.read()

    def monitor(self, *args):
        return serveutil.monitor(self.lj, self.sock, *args, timeout=30)

    def write(self, *assignments):
        rc, _, err = self.monitor("write", *assignments)
        check(rc == 0, "monitor write %s: %s" % (" ".join(assignments), err))

    def read(self, addr):
        rc, out, err = self.monitor("read", addr)
        if not check(rc == 0, "monitor read %s: %s" % (addr, err)):
            return None
        return int(out.strip().split("=")[1])

    def kill9(self):
        self.proc.send_signal(signal.SIGKILL)
        self.proc.wait(timeout=30)
        check(self.proc.returncode == -signal.SIGKILL, "serve died of SIGKILL")


def run_target(lj, workdir, tag, src, mapping, before, after):
    program = os.path.join(workdir, tag + (".pmc" if tag == "fanuc" else ".il"))
    mapfile = os.path.join(workdir, tag + ".map")
    with open(program, "w") as f:
        f.write(src)
    with open(mapfile, "w") as f:
        f.write(mapping)
    retain = os.path.join(workdir, tag + ".retain")
    srv = Server(lj, workdir, program, mapfile, retain, tag + "-1")
    check("does not exist yet" in srv.log(), tag + ": a fresh store starts with zeros")
    before(srv)
    time.sleep(0.5)  # ten periodic save periods: the inputs' SET bits reach the file
    srv.kill9()
    shm = "ljprof%d" % os.getpid()
    srv = Server(lj, workdir, program, mapfile, retain, tag + "-2", ("--shm", shm))
    srv.shm = shm
    log = srv.log()
    check("retain: restored " + retain + " (save #" in log and "WARNING" not in log,
          tag + ": the restart restores the main file: " + log)
    after(srv)
    srv.kill9()
    return program, retain


def fanuc_before(srv):
    check(srv.mb.write_regs(0, [1234, 0xFFFE]), "fanuc: Modbus write D100:2, D102:2")
    check(srv.mb.write_regs(10, [77]), "fanuc: Modbus write R100")
    check(srv.mb.write_regs(20, [5000]), "fanuc: Modbus write T0:2")
    check(srv.mb.write_coil(5, 1), "fanuc: Modbus write K0.5")
    srv.write("X0.0=1", "X0.1=1")


def fanuc_after(srv):
    # Retained (K, D, T): as written; volatile (R): zero.
    check(srv.read("D100:2") == 1234, "fanuc: D100:2 = 1234 after the restart")
    check(srv.read("D102:2") == -2, "fanuc: D102:2 = -2 after the restart")
    check(srv.read("T0:2") == 5000, "fanuc: T0:2 (TMR preset) = 5000 after the restart")
    check(srv.read("K0.5") == 1, "fanuc: K0.5 (Modbus coil) = 1 after the restart")
    check(srv.read("K0.1") == 1, "fanuc: K0.1 (SET by the program) = 1 after the restart")
    check(srv.read("R100") == 0, "fanuc: R100 is volatile: 0 after the restart")
    check(srv.read("R0.0") == 0, "fanuc: R0.0 is volatile: 0 after the restart")
    check(srv.mb.read_regs(0, 2) == [1234, 0xFFFE], "fanuc: Modbus reads D100:2, D102:2 back")
    check(srv.mb.read_coils(0, 8) == [0, 1, 0, 0, 0, 1, 0, 0], "fanuc: Modbus reads K0.0..K0.7")
    size, region = shm_region(srv.shm)
    check(size == 65536 and region[FANUC_K_IN_MEM] == 0x22,
          "fanuc: the shm image publishes K0 = 0x22 in the region (size %d, K0 %s)"
          % (size, region[FANUC_K_IN_MEM] if len(region) > FANUC_K_IN_MEM else None))


def iec_before(srv):
    check(srv.mb.write_coil(10, 1), "iec: Modbus write %M10")
    check(srv.mb.write_coil(64 + 10, 1), "iec: Modbus write %M74")
    check(srv.mb.write_regs(0, [42]), "iec: Modbus write %MW10")
    srv.write("%I0.0=1", "%I0.1=1")


def iec_after(srv):
    check(srv.read("%M3") == 1, "iec: %M3 (S by the program) retained")
    check(srv.read("%M10") == 1, "iec: %M10 (Modbus coil) retained")
    check(srv.read("%M70") == 0, "iec: %M70 is not retained (only %M0..%M63)")
    check(srv.read("%M74") == 0, "iec: %M74 is not retained")
    check(srv.read("%MW10") == 0, "iec: %MW10 is not retained")
    check(srv.mb.read_coils(0, 11) == [0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 1], "iec: Modbus %M0..%M10")


def usage_errors(lj, workdir, fanuc_prog, iec_retain):
    def serve(*args):
        r = subprocess.run([lj, "serve", fanuc_prog, "--engine", "interp", "--duration", "1",
                            "--control", os.path.join(workdir, "u.sock"), *args],
                           capture_output=True, text=True, timeout=30)
        return r.returncode, r.stderr

    rc, err = serve("--retain", iec_retain)
    check(rc == 2 and "another layout" in err and "profile iec" in err,
          "a FANUC program refuses the IEC program's retain file: %d %s" % (rc, err))
    rc, err = serve("--modbus", "0")
    check(rc == 2 and "needs --modbus-map" in err, "FANUC --modbus without a map: %s" % err)
    bad = os.path.join(workdir, "bad.map")
    for text, want in (("holding 0 D9999:2\n", "bad.map:1: bad address 'D9999:2'"),
                       ("coils 0 %M3\n", "bad.map:1: bad address"),
                       ("holding 0 X0.0\n", "holding take element addresses"),
                       ("coils 0 K0.0 8\ncoils 4 K1.0\n", "bad.map:2: coils 4..4 overlap line 1")):
        with open(bad, "w") as f:
            f.write(text)
        rc, err = serve("--modbus", "0", "--modbus-map", bad)
        check(rc == 2 and want in err, "bad map %r: %d %s" % (text, rc, err))


def main():
    if len(sys.argv) != 2:
        sys.exit("usage: profile_serve.py LADDERJIT")
    lj = sys.argv[1]
    workdir = tempfile.mkdtemp(prefix="lj-retain-profile-")
    started = time.time()
    fanuc_prog, _ = run_target(lj, workdir, "fanuc", FANUC, FANUC_MAP, fanuc_before, fanuc_after)
    _, iec_retain = run_target(lj, workdir, "iec", IEC, IEC_MAP, iec_before, iec_after)
    usage_errors(lj, workdir, fanuc_prog, iec_retain)
    try:
        os.unlink("/dev/shm/ljprof%d" % os.getpid())  # left by the SIGKILLed server
    except FileNotFoundError:
        pass
    print("profile_serve: %d failure(s) in %.1f s" % (len(FAILURES), time.time() - started))
    if FAILURES:
        print("logs kept in " + workdir)
        return 1
    shutil.rmtree(workdir, ignore_errors=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())

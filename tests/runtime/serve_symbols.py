#!/usr/bin/env python3
"""`ladderjit monitor` with symbols of the running program (formats/Address.h parseAddressIn):
read, write, lock and unlock take a name the program defines, as the address it stands for.
HNC-8: examples/lathe_panel.dit ([symbols]: GUARD_OPEN X483.0, CCW_KEY X484.7); FANUC:
examples/fanuc_coolant.pmc (%@2-E: ESP_OK X0.0, LUBE Y0.1: the lube pump runs while the E-stop
chain is closed). A name the program does not define is refused with the address message."""
import os
import shutil
import subprocess
import sys
import tempfile

from serve_client import FAILURES, LJ, check, monitor, read, wait_value

EXAMPLES = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "examples")


def serve(program, sock):
    srv = subprocess.Popen([LJ, "serve", program, "--control", sock, "--duration", "120"],
                           stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    line = srv.stdout.readline() + srv.stdout.readline()
    check("control socket " + sock in line, "serve announces its control socket: " + line)
    return srv


def write_seen(sock, item, addr, want, what):
    """`monitor write ITEM`, then `addr` reads `want`."""
    rc, _, err = monitor(sock, "write", item)
    check(rc == 0, what + ": write accepted: " + err)
    check(wait_value(sock, addr, want), what)


def stop(srv):
    srv.terminate()
    try:
        srv.wait(timeout=30)
    except subprocess.TimeoutExpired:
        srv.kill()
        srv.wait()


def main():
    tmp = tempfile.mkdtemp(prefix="ljsym-")
    try:
        sock = os.path.join(tmp, "h.sock")
        srv = serve(os.path.join(EXAMPLES, "lathe_panel.dit"), sock)
        check(wait_value(sock, "GUARD_OPEN", 0), "read by symbol: GUARD_OPEN = 0")
        write_seen(sock, "GUARD_OPEN=1", "X483.0", 1, "the symbol's address X483.0 was written")
        check(read(sock, "guard_open") == 1, "names are case-insensitive")
        rc, out, err = monitor(sock, "lock", "CCW_KEY=0")
        check(rc == 0 and "CCW_KEY=0" in out, "lock by symbol: " + out + err)
        rc, out, err = monitor(sock, "unlock", "CCW_KEY")
        check(rc == 0 and "CCW_KEY" not in out, "unlock by symbol: " + out + err)
        rc, _, err = monitor(sock, "read", "NO_SUCH_NAME")
        check(rc != 0 and "bad address 'NO_SUCH_NAME'" in err, "unknown name refused: " + err)
        stop(srv)

        sock = os.path.join(tmp, "f.sock")
        srv = serve(os.path.join(EXAMPLES, "fanuc_coolant.pmc"), sock)
        check(wait_value(sock, "LUBE", 0), "FANUC: lube pump off while the E-stop chain is open")
        write_seen(sock, "ESP_OK=1", "LUBE", 1, "FANUC: LUBE (Y0.1) runs with the chain closed")
        check(read(sock, "Y0.1") == 1, "FANUC: LUBE is Y0.1")
        stop(srv)
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    if FAILURES:
        print(f"{len(FAILURES)} failure(s)")
        sys.exit(1)
    print("ok")


if __name__ == "__main__":
    main()
